/* work.h - what the files of libmink_cspace share: the scratch space of one
 * thread (mkCSpaceWork), growable arrays, the edge hash, the contact space's
 * boundary points by batch, the boundary computations of each file and the
 * prepared scene (mkCSpace). Internal to the library. */
#ifndef MINK_CSPACE_WORK_H
#define MINK_CSPACE_WORK_H

#include <math.h>
#include <stdint.h>

#include "mink/cobstacle.h"

#define MK_CSPACE_ROUND_REL 1e-13  /* rounding allowance per unit of coordinate size */
#define MK_CSPACE_MIN_ANGLE 1e-12  /* normals closer than this (radians) are not split */
#define MK_CSPACE_MAX_SPLITS 10    /* uniform 3D: 8 * 4^10 triangles */

/* ---- growable arrays (work.c): 1, or 0 when out of memory ---- */
int mkGrow_Doubles(double **p, int *cap, int need);
int mkGrow_Ints(int **p, int *cap, int need);

/* ---- edge hash (edgehash.c): open addressing from 64-bit keys to
 * non-negative ints; a value -1 marks an empty slot, -2 a removed entry ---- */
typedef struct mkEdgeHash { uint64_t *key; int *val; int cap, count; } mkEdgeHash;

uint64_t mkEdgeHash_Undirected(int a, int b);
uint64_t mkEdgeHash_Directed(int a, int b);
void mkEdgeHash_Clear(mkEdgeHash *h);
int mkEdgeHash_Slot(const mkEdgeHash *h, uint64_t k);   /* -1 when absent */
int mkEdgeHash_Find(const mkEdgeHash *h, uint64_t k);   /* -1 when absent */
int mkEdgeHash_Put(mkEdgeHash *h, uint64_t k, int v);   /* 0 when out of memory */
void mkEdgeHash_Remove(mkEdgeHash *h, uint64_t k);      /* k must be present */
void mkEdgeHash_Free(mkEdgeHash *h);

/* ---- the scratch space of one thread, reused from boundary to boundary ---- */
typedef struct mkCSpaceWork {
	/* vertices: normal n and point p */
	double *n[3], *p[3];
	int vcap[6];
	int *next, ncap;           /* 2D walks: a node's counter-clockwise successor */
	double *m[3], *q[3];       /* batch normals and their points */
	int mcap[6];
	int *tri, tcap, *tri2, t2cap, *leaf, lcap; /* 3D triangles, 3 ints each */
	mkEdgeHash edges;          /* 3D: undirected edge -> midpoint vertex */
	mkEdgeHash dedges;         /* 3D: directed edge a -> b -> its triangle */
	int *poly, pcap;
	double *o[3]; int ocap[3]; /* 3D outer vertices */
	int *fin, fcap;            /* 3D final (conforming) triangles */
	double *pb; int pbcap;     /* paper mode: B1's half, the poses' directions, their points */
	double *err2; int ecap;    /* 2D: the error of the arc from node i to the next */
	double *cp; int cpcap;     /* 2D adaptive: the chosen walk's vertices */
	void *scratch; size_t scap; /* any task's block (mkCSpaceWork_Scratch) */
} mkCSpaceWork;

void mkCSpaceWork_Free(mkCSpaceWork *w);
int mkCSpaceWork_Verts(mkCSpaceWork *w, int need, int dim);   /* n and p */
int mkCSpaceWork_Batch(mkCSpaceWork *w, int need, int dim);   /* m and q */
/* A block of at least `need` bytes kept from task to task of the thread
 * (NULL when out of memory), so that a task of a many-pose run allocates
 * nothing: a block allocated and freed by every task could move the
 * heap's top back and forth (a system call each time). */
void *mkCSpaceWork_Scratch(mkCSpaceWork *w, size_t need);

/* cos and sin, exact on the axes (as mkSample2_Angles). */
void mkSinCosExact(double t, double *c, double *s);

/* Points x(u) of the contact space's boundary at unit normals u. */
mkResult mkContact2_Points(mkBody2 b1, mkBody2 b2, mkImpl impl, const double *ux, const double *uy, int n,
	double *x, double *y);
mkResult mkContact3_Points(mkBody3 b1, mkBody3 b2, mkImpl impl, const double *ux, const double *uy,
	const double *uz, int n, double *x, double *y, double *z);

/* ---- 2D (boundary2.c, walk2.c) ---- */
mkVec2 mkBoundary2_SplitNormal(mkVec2 ni, mkVec2 nj, mkVec2 pi, mkVec2 pj);
/* The corner of the tangent lines at (ni, pi) and (nj, pj): a vertex of the
 * outer boundary (arc2.c). */
mkVec2 mkBoundary2_TangentVertex(mkVec2 ni, mkVec2 pi, mkVec2 nj, mkVec2 pj);
double mkBoundary2_EdgeError(mkBound bound, mkVec2 ni, mkVec2 nj, mkVec2 pi, mkVec2 pj, mkVec2 m, mkVec2 xm);
/* The adaptive walk (walk2.c): nodes 0 .. count - 1 of w counter-clockwise,
 * w->err2[i] the error of the arc from node i to node i + 1 (mod count). */
mkResult mkBoundary2_Walk(mkCSpaceWork *w, mkBody2 b1, mkBody2 b2, mkImpl impl, mkBound bound, double tol,
	int max_points, int *count, double *error);
/* Adaptive (uniform_n == 0, no given normals) or fixed normals, results as
 * mkBoundary2_Walk's. */
mkResult mkBoundary2_Run(mkCSpaceWork *w, mkBody2 b1, mkBody2 b2, mkImpl impl, mkBound bound, double tol,
	int max_points, int uniform_n, const double *given_x, const double *given_y, int *count, double *error);
/* The boundary of mkBoundary2_Run (inner: points; outer: tangent vertices). */
void mkBoundary2_Emit(const mkCSpaceWork *w, mkBound bound, int count, double *ox, double *oy);

/* ---- 3D (boundary3.c, outer3.c, hull3.c) ---- */
static inline mkVec3 mkWork_Normal3(const mkCSpaceWork *w, int i)
{
	return mkVec3_Make(w->n[0][i], w->n[1][i], w->n[2][i]);
}
static inline mkVec3 mkWork_Point3(const mkCSpaceWork *w, int i)
{
	return mkVec3_Make(w->p[0][i], w->p[1][i], w->p[2][i]);
}
static inline double mkVec3_Size1(mkVec3 a) { return fabs(a.x) + fabs(a.y) + fabs(a.z); }
static inline double mkVec3_Det(mkVec3 a, mkVec3 b, mkVec3 c) { return mkVec3_Dot(a, mkVec3_Cross(b, c)); }
/* Proof 4's bound for the spherical triangle of normals (a, b, c). */
double mkBoundary3_TriangleBound(const mkCSpaceWork *w, int a, int b, int c);
/* One 3D boundary into w: inner (points w->p, faces of their hull) or outer
 * (points w->o, faces of the tangent planes' polytope) into *faces. */
mkResult mkBoundary3_Compute(mkCSpaceWork *w, mkBody3 b1, mkBody3 b2, mkImpl impl, mkBound bound, double tol,
	int max_points, int splits, int want_faces, int *count, int *nfaces, int **faces, int *fcap, double *error);
/* The outer polytope of the final triangles w->fin (outer3.c): faces count or -1. */
int mkBoundary3_Outer(mkCSpaceWork *w, int nv, int nfin, int **faces, int *fcap, double *excess);
/* The convex hull of the points w->p[0..n) (hull3.c): faces count or -1. */
int mkHull3_Build(mkCSpaceWork *w, int n, int **faces, int *fcap);

/* ---- the prepared scene (cspace.c) and its runs (run.c, pool.c) ---- */
struct mkCSpace {
	const mkScene *scene;
	mkCSpaceOptions opt;
	int dim, nob, bounds, parts;
	/* models: [bound] for the robot (part 0), [j * 2 + bound] for part j,
	 * [i * 2 + bound] for obstacles */
	mkBody2 robot2[2], *obs2, *part2;
	mkBody3 robot3[2], *obs3, *part3;
	double robot_err[2], *obs_err, *part_err;
	char robot_name[128];
	char (*part_name)[128];   /* per part */
	const mkSceneBody *part_body;  /* the scene's parts, or its robot when part_count is 0 */
	char (*model_name)[128];  /* per obstacle */
	double *paper_u[3];       /* paper mode: B1's surface parameters */
	int paper_n;
};

/* Run tasks 0 .. ntasks - 1 on `threads` threads, each with its own
 * mkCSpaceWork; the first failure stops the rest and is returned. */
typedef mkResult mkCSpaceTaskFn(void *ctx, mkCSpaceWork *w, long task);
mkResult mkCSpacePool_Run(mkCSpaceTaskFn *fn, void *ctx, long ntasks, int threads);
/* As mkCSpacePool_Run, and each finished task t is handed to emit(ctx, w,
 * t) in task order, never two at once; a task is started only when fewer
 * than `window` tasks before it are still to be emitted (window >= 1). */
mkResult mkCSpacePool_RunOrdered(mkCSpaceTaskFn *fn, mkCSpaceTaskFn *emit, void *ctx, long ntasks, int threads,
	long window);
/* Boundary b (the result's index) as a view (cspace.c). */
mkCSpaceBoundary mkCSpaceResult_At(const mkCSpaceResult *r, long b);

#endif
