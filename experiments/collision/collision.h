/* collision.h - the collision-detection benchmark of the paper (Sec. 7.2,
 * Table 3).
 *
 * One trial is one random pair of bodies; every applicable query of
 * mink/collide.h runs on it, each timed alone (the wall clock of
 * mink_exp/clock.h around the query call only, one thread), and one raw row
 * per trial and algorithm is written. A referee independent of all six (the
 * minimum over unit n of h1(n) + h2(-n), support functions only) decides
 * the true answer; trials whose |min g| is within the margin are too close
 * to call and get an empty `agrees` (they are kept and counted, never
 * dropped).
 *
 * Draws (paper Sec. 7.2, the reference code's distributions; mink_exp/draw.h):
 *  B1: semi-axes ~ U(1,11)^3, eps1, eps2 ~ U(0.1,1.9), centre ~ U(-5,5)^3;
 *  B2: semi-axes ~ U(1,6)^3, same exponents, centre ~ U(5,15)^3;
 *  ellipsoid pairs have eps = (1,1) and draw no exponents. Rotations by
 *  mkDraw_Rotation3 (the reference code's normalised quaternion, or
 *  uniform on SO(3)).
 * Each trial draws from its own stream (pair << 32) | trial of the run's
 * seed (pair 0 ellipsoids, 1 superquadrics), body 1 then body 2, each in
 * the order semi-axes, exponents, centre, rotation.
 *
 * GJK runs on the 10 x 10 grid vertex sets of both bodies (100 vertices
 * each); the vertex sets are built before its timer starts, as the
 * reference code builds its surfaces outside the timed call. */
#ifndef MINK_EXP_COLLISION_H
#define MINK_EXP_COLLISION_H

#include <mink/collide.h>
#include <mink/mink.h>
#include <mink_exp/exp.h>

#define MK_COLLISION_SCHEMA 1

/* The CSV's columns, ended by NULL. */
extern const char *const mkCollision_Columns[];
/* "ellipsoids", "superquadrics": the pair kinds, 0 and 1. */
extern const char *const mkCollision_PairNames[2];

typedef struct mkCollisionOptions {
	uint64_t seed;
	mkRotDraw rotations;
	double margin;   /* the referee's: |min g| <= margin is too close to call */
} mkCollisionOptions;

/* The sidecar keys of a run (pairs, draws, referee, solvers, versions). */
void mkCollision_Meta(mkMeta *meta, const mkCollisionOptions *o, int ellipsoids, int superquadrics);

/* One trial of one pair kind: draw, referee, every query, its rows.
 * Returns 0, or -1 after printing an error. */
int mkCollision_Trial(const mkCollisionOptions *o, int pair, long trial, mkCsv *csv);

/* The section of the tables: <dir>/collision.csv beside the paper's
 * Table 3, and the reproduction's own figures per algorithm. */
void mkCollision_Summary(mkDoc *d, const char *dir, mkTally *tally);

#endif
