/* mink/cobstacle.h - configuration-space obstacles of a scene, certified to a
 * tolerance, on every core.
 *
 * For a robot R at orientation o (map R_o M) and an obstacle O, the
 * C-obstacle is the contact space K = O (+) (-R_o): the places of the robot's
 * centre where it touches or overlaps O. Theorem 1 gives K's boundary point
 * with outward normal n in closed form, x(n) (mkSum2_Batch/mkSum3_Batch with
 * MK_FORM_NORMAL and MK_PARAM_NORMAL), hence its support function
 * h_K(n) = <n, x(n)>. From these alone this module builds, per obstacle and
 * orientation,
 *  - an inner boundary: a polygon (2D, counter-clockwise) or a closed
 *    triangulated surface (3D) whose vertices lie on the boundary of K, so
 *    their convex hull P is inside K;
 *  - on request an outer boundary: the polygon (polytope) cut out by the
 *    tangent lines (planes) at the same kind of normals, which contains K;
 * and a certified bound on the Hausdorff distance of each to K. In the
 * adaptive mode normals are placed until the certified bound is at most the
 * sampling tolerance (2D: a walk around the circle of normals, each vertex
 * at about the farthest normal step its arc's bound allows; 3D: refinement
 * of the octahedron), so points go where the curvature needs them. The
 * certificates and their conditions are proved in docs/scene.md.
 *
 * Bodies that are boxes or cylinders are modelled first (mink/scene.h); the
 * tolerance T then covers the model error too: each modelled body gets a
 * model budget of T/4 and the sampling gets T minus the model errors, so the
 * reported error (model + sampling) bounds the distance to the C-obstacle of
 * the declared shapes.
 *
 * Use: mkCSpace_Create prepares a scene once (each body's model, its name
 * and error, the robot's model, the tolerance); mkCSpace_Run computes any
 * range of orientations into an mkCSpaceResult; mkCSpaceResult_Boundary
 * reads one boundary in the layout the options chose (one array per
 * coordinate, or interleaved); mkCSpace_Stream hands each boundary to the
 * caller as it is finished instead of keeping them, and mkCSpace_Estimate
 * says beforehand about how many points a run will make.
 *
 * Names: one prefix, mkCSpace, for scene runs and single boundaries alike
 * (mkCSpace2_Adaptive, ...): the library is libmink_cspace, and a
 * C-obstacle is a part of the C-space; mkCObstacle names the driver of
 * the paper's C-obstacle experiment.
 *
 * Threads: the (orientation, obstacle) pairs are independent tasks, shared
 * out to `threads` POSIX threads; every task is computed the same way
 * whichever thread runs it, so the result does not depend on the thread
 * count.
 *
 * Memory: mkCSpace_Create allocates the prepared scene (mkCSpace_Destroy
 * releases it), mkCSpace_Run the result (mkCSpaceResult_Free),
 * mkCSpace_Stream only what its threads hold (released before it returns),
 * the single-boundary functions grow the caller's buffers. */
#ifndef MINK_COBSTACLE_H
#define MINK_COBSTACLE_H

#include "scene.h"
#include "sum.h"

MK_EXTERN_C_BEGIN

typedef enum mkCSpaceMode {
	/* normals placed until the certified error is at most the tolerance */
	MK_CSPACE_ADAPTIVE = 0,
	/* a fixed set of normals, the same for every boundary, certified: 2D
	 * `uniform` normals 2 pi k / uniform; 3D the octahedron's 8 faces split
	 * uniformly `uniform` times (8 4^uniform triangles). The tolerance only
	 * chooses the models of boxes and cylinders. */
	MK_CSPACE_UNIFORM = 1,
	/* the paper's sampling, not certified (error NaN), inner only: B1's
	 * surface parameters (mkSample2_Angles(uniform) or mkSample3_Grid(uniform))
	 * with the options' form and kernel, the points bit for bit those of
	 * one mkSum*_Batch call per obstacle and orientation (the obstacle's
	 * half computed once for many orientations); Table 2's timing. No
	 * faces in 3D. */
	MK_CSPACE_PAPER = 2
} mkCSpaceMode;

typedef struct mkCSpaceOptions {
	double tol;         /* T > 0, in the scene's length unit */
	int outer;          /* 1: also the outer boundary */
	mkCSpaceMode mode;
	int uniform;        /* UNIFORM: 2D >= 4 normals, 3D 0..10 splits; PAPER: points / grid side */
	int threads;        /* >= 1 */
	int store;          /* 1: keep points and faces; 0: counts, errors, checksums only */
	int max_points;     /* cap per boundary (adaptive); reaching it leaves the error above T */
	mkForm form;        /* PAPER only (MK_FORM_NORMAL or MK_FORM_GRADIENT) */
	mkImpl impl;        /* the kernel of every batch call */
	int interleaved;    /* store = 1: 1 keeps each boundary's points as x, y[, z] per point; 0 as one array per coordinate */
} mkCSpaceOptions;

/* tol 1e-3, inner only, adaptive, 1 thread, store, max_points 1000000,
 * gradient form (paper mode), AUTO kernel, one array per coordinate. */
MK_API mkCSpaceOptions mkCSpaceOptions_Default(void);

/* A scene prepared for runs: its options and the models of its bodies. */
typedef struct mkCSpace mkCSpace;

/* Prepare the scene for runs with these options (copied): every body is
 * modelled once for the tolerance. The scene must stay alive and unchanged
 * until mkCSpace_Destroy. Fails with MK_ERR_ARGUMENT on bad options (message
 * says which), MK_ERR_RANGE when a model cannot meet the tolerance (e.g. T
 * too small for a box; message "robot: ...", "part J: ..." or "obstacle I: ..."),
 * MK_ERR_UNSUPPORTED also for a robot of several parts in paper mode;
 * MK_ERR_UNSUPPORTED (outer bounds in paper mode, a kernel not built),
 * MK_ERR_MEMORY. On failure *out is NULL. */
MK_API mkResult mkCSpace_Create(const mkScene *scene, const mkCSpaceOptions *opt, mkCSpace **out,
	char *msg, size_t msglen);
MK_API void mkCSpace_Destroy(mkCSpace *cs);
MK_API const mkCSpaceOptions *mkCSpace_Options(const mkCSpace *cs);
/* The model of a body as text for reports: body -1 the robot (its part 0),
 * -1 - j its part j, 0 .. obstacles - 1 an obstacle. A SMOOTH body is its kind ("ellipse"); a box
 * or cylinder its model ("superellipse eps=0.0834"), as "inner M1; outer
 * M2" when the options ask for outer bounds. */
MK_API const char *mkCSpace_ModelName(const mkCSpace *cs, int body);

/* The boundaries of a run, (orientation o, obstacle i, robot part j, bound
 * k) at index (((o - orientation_begin) * obstacles + i) * parts + j) *
 * bounds + k; bounds is 1 (inner) or 2 (inner, outer), parts the robot's
 * (1 for a robot of one body). The C-obstacle of obstacle i is the union
 * over j of its parts' boundaries. Read them with mkCSpaceResult_Boundary
 * or mkCSpaceResult_PartBoundary. */
typedef struct mkCSpaceResult {
	int dim, obstacles, orientations, bounds, parts;
	int orientation_begin;   /* the scene orientation of the run's first */
	double tol;              /* the options' tolerance */
	int *count;              /* points of each boundary */
	double *error;           /* certified Hausdorff bound incl. model error (NaN: paper mode) */
	double *model_error;     /* the model part of it (robot's + obstacle's) */
	double *seconds;         /* wall time of each (orientation, obstacle) task, on its bound 0 entry
	                          * (paper mode: a task's time shared equally by its orientations) */
	double *checksum;        /* sum of every coordinate of the boundary (also with store = 0) */
	/* store = 1: each boundary's points (layout: interleaved) and 3D faces */
	int interleaved;
	double **points;
	int **faces;
	int *face_count;
} mkCSpaceResult;

/* One boundary of a result: point j is (x[j * stride], y[j * stride][,
 * z[j * stride]]); stride is 1 for one array per coordinate, dim for the
 * interleaved layout (then x is the whole x, y[, z] array). No points
 * (NULL) when the run did not store them. */
typedef struct mkCSpaceBoundary {
	int count, stride;
	const double *x, *y, *z;   /* z: 3D */
	int face_count;            /* 3D: triangles, three vertex numbers each (0-based within the */
	const int *faces;          /* boundary), counter-clockwise seen from outside */
	double error, model_error, seconds, checksum;
	int within_tol;            /* error <= tol: certified within the tolerance */
} mkCSpaceBoundary;

/* Compute the orientations [begin, end) of the prepared scene for every
 * obstacle. Fails with MK_ERR_ARGUMENT on a bad range (message says which)
 * or MK_ERR_MEMORY; then *out is empty. A boundary whose error exceeds T
 * (max_points reached, or normals closer than 1e-12 rad) is not a failure:
 * see mkCSpaceBoundary.within_tol and mkCSpaceResult_OverTolerance. */
MK_API mkResult mkCSpace_Run(const mkCSpace *cs, int begin, int end, mkCSpaceResult *out, char *msg, size_t msglen);

/* The boundary of scene orientation o (orientation_begin <= o <
 * orientation_begin + orientations), obstacle i and bound k. */
MK_API mkCSpaceBoundary mkCSpaceResult_Boundary(const mkCSpaceResult *r, int o, int i, mkBound k);
/* The same for robot part j (0 <= j < parts): the C-obstacle of obstacle i
 * against part j alone, O (+) (-R M_j B_j) - R t_j (mink/scene.h). */
MK_API mkCSpaceBoundary mkCSpaceResult_PartBoundary(const mkCSpaceResult *r, int o, int i, int j, mkBound k);
/* Largest error of the result (NaN if any is NaN). */
MK_API double mkCSpaceResult_MaxError(const mkCSpaceResult *r);
/* How many boundaries are not certified within the tolerance. */
MK_API long mkCSpaceResult_OverTolerance(const mkCSpaceResult *r);
MK_API void mkCSpaceResult_Free(mkCSpaceResult *r);

/* ---- streaming: each boundary handed over as it is finished ----------------
 * The caller's sink receives boundary (orientation o, obstacle i, bound k)
 * as a view valid during the call only. A nonzero return stops the run. */
typedef int mkCSpaceSink(void *user, int o, int i, int part, mkBound k, const mkCSpaceBoundary *b);

/* Compute the orientations [begin, end) as mkCSpace_Run does, with the same
 * points, faces, errors and checksums, but hand each boundary to sink in
 * mkCSpace_Run's index order (orientation, then obstacle, then bound) as
 * soon as it and every boundary before it are finished, instead of keeping
 * them: the calls are never concurrent, come from any of the run's threads,
 * and the memory held is the threads' scratch space plus the boundaries of
 * at most MK_CSPACE_WINDOW * threads (orientation, obstacle) tasks that are
 * finished but still waiting for an earlier one. Needs store = 1 and the
 * adaptive or uniform mode (MK_ERR_UNSUPPORTED otherwise). Fails as
 * mkCSpace_Run, or with MK_ERR_ARGUMENT ("stopped by the caller") when the
 * sink returned nonzero; the boundaries handed over until then stay
 * handed over. */
#define MK_CSPACE_WINDOW 4
MK_API mkResult mkCSpace_Stream(const mkCSpace *cs, int begin, int end, mkCSpaceSink *sink, void *user,
	char *msg, size_t msglen);

/* A run's size, estimated before it starts (mkCSpace_Estimate). */
typedef struct mkCSpaceEstimate {
	double points;          /* points of all boundaries of the run */
	double faces;           /* 3D: their triangles (2 per point, less 4 per boundary); 2D: 0 */
	double largest;         /* points of the largest boundary */
	long sampled;           /* boundaries computed for the estimate */
} mkCSpaceEstimate;

/* Estimate the size of mkCSpace_Run(cs, begin, end): the boundaries of the
 * first orientation for up to 32 obstacles spread evenly over the scene
 * (all when fewer), each computed with at most 2000 points; a boundary
 * finished within T counts as it is, one stopped by that cap with error e
 * as 2000 (e / T) points in 3D, 2000 (e / T)^(1/2) in 2D (the adaptive
 * sampling's rate: triangles' errors fall as their area, polygon edges' as
 * their length squared), at most max_points; the sample stands for all
 * obstacles and orientations. An estimate: within a factor of 4 of the run
 * in the tests, over rather than under in 3D (2.9 to 3.3 times there); it takes the time of the sample (milliseconds). Fails
 * as mkCSpace_Run. */
MK_API mkResult mkCSpace_Estimate(const mkCSpace *cs, int begin, int end, mkCSpaceEstimate *out, char *msg,
	size_t msglen);

/* ---- single boundaries, for callers with their own bodies ----------------
 * K = b1 (+) (-b2) (the contact space of mink/sum.h). Adaptive inner (outer)
 * boundary with sampling tolerance tol into a buffer the function grows with
 * realloc (*x, *y, *cap: the caller owns and frees them; start with NULL, 0).
 * Writes the count and the certified bound (plus a rounding allowance of
 * 1e-13 times the coordinates' size). Returns MK_ERR_MEMORY or
 * MK_ERR_ARGUMENT (tol <= 0). */
MK_API mkResult mkCSpace2_Adaptive(mkBody2 b1, mkBody2 b2, mkBound bound, double tol, int max_points,
	mkImpl impl, double **x, double **y, int *cap, int *count, double *error);
/* 3D: points and triangles (3 ints each, *faces grown likewise; faces may
 * be NULL when only the points are wanted), inner
 * (a closed surface through boundary points of K) or outer (the polytope of
 * the tangent planes, see Proof 5 of docs/scene.md). */
MK_API mkResult mkCSpace3_Adaptive(mkBody3 b1, mkBody3 b2, mkBound bound, double tol, int max_points, mkImpl impl,
	double **x, double **y, double **z, int *cap, int **faces, int *face_cap, int *count, int *face_count,
	double *error);
/* The same with a fixed set of normals (mode UNIFORM): n normals (2D, n >= 4)
 * or `splits` uniform splits of the octahedron (3D, 0..10). 2D n >= 4 keeps
 * every normal step at most 90 degrees, which the certificate needs. */
MK_API mkResult mkCSpace2_Uniform(mkBody2 b1, mkBody2 b2, mkBound bound, int n, mkImpl impl,
	double **x, double **y, int *cap, int *count, double *error);
/* Certify given normals (any nonzero vectors, n >= 3, in counter-clockwise
 * order around the circle): the polygon of their points (inner) or tangent
 * lines (outer) and its certified bound, as the uniform mode does. Steps over
 * 90 degrees get the weaker bound of Proof 3, steps of 180 degrees or more
 * an infinite one. Used to certify another sampling, e.g. the paper's (the
 * normals of an obstacle's surface samples). */
MK_API mkResult mkCSpace2_Certify(mkBody2 b1, mkBody2 b2, mkBound bound, const double *nx, const double *ny, int n,
	mkImpl impl, double **x, double **y, int *cap, int *count, double *error);
/* Certify given normals in 3D: n normals (any nonzero vectors) and ntri
 * triangles of them (3 indices each, counter-clockwise from outside) that
 * partition the sphere; *error is Proof 4's bound for the convex hull of
 * their points (inner) and for the intersection of their tangent
 * half-spaces (outer), or +inf when some triangle is not positively
 * oriented or the triangles' areas do not sum to 4 pi (not a partition).
 * Used to certify another sampling, e.g. the paper's grid. */
MK_API mkResult mkCSpace3_Certify(mkBody3 b1, mkBody3 b2, const double *nx, const double *ny, const double *nz, int n,
	const int *tris, int ntri, mkImpl impl, double *error);
MK_API mkResult mkCSpace3_Uniform(mkBody3 b1, mkBody3 b2, mkBound bound, int splits, mkImpl impl,
	double **x, double **y, double **z, int *cap, int **faces, int *face_cap, int *count, int *face_count,
	double *error);

MK_EXTERN_C_END

#endif
