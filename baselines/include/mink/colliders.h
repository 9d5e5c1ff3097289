/* mink/colliders.h - the registry of collision and distance algorithms for
 * two placed superquadrics: the core's closed-form queries (mink/collision.h)
 * and every peer (libccd, FCL, Ipopt, cminpack, ASC), each behind the same
 * entry, so that the experiment, the `mink collide` command and the tests
 * loop over one table:
 *
 *     mkColliderScratch scratch;
 *     for (int i = 0; i < mkColliders_Count(); ++i) {
 *         const mkCollider *c = mkColliders_At(i);
 *         if (!mkCollider_Accepts(c, b1, b2, NULL, 0)) continue;
 *         mkCollision3 out;
 *         mkResult r = mkCollider_Run(c, b1, b2, &scratch, &out);
 *         ...
 *     }
 *
 * Every entry fills an mkCollision3 (mink/collision.h): status always (when
 * it answers), the signed distance only when the entry gives it (see
 * `gives`), witnesses likewise; fields it does not produce are NaN / -1.
 * A run returns MK_OK with a verdict, or MK_ERR_CONVERGENCE (the solver did
 * not converge: status MK_CONTACT_UNKNOWN, no verdict), or another error.
 *
 * To add an algorithm: define its mkCollider in a file of its own under
 * baselines/collision/ and add one line to the table in colliders.c. */
#ifndef MINK_COLLIDERS_H
#define MINK_COLLIDERS_H

#include <stddef.h>
#include <mink/mink.h>

MK_EXTERN_C_BEGIN

/* What an entry returns. */
typedef enum mkColliderGives {
	MK_GIVES_STATUS = 1,       /* separated / touching / overlapping */
	MK_GIVES_DISTANCE = 2,     /* distance of separated bodies */
	MK_GIVES_PENETRATION = 4,  /* penetration depth of overlapping bodies */
	MK_GIVES_WITNESS = 8       /* witness points p1, p2 */
} mkColliderGives;

/* Which pairs an entry takes. */
typedef enum mkColliderPairs {
	MK_PAIRS_ELLIPSOIDS = 1,   /* both bodies ellipsoids (eps1 = eps2 = 1) */
	MK_PAIRS_SUPERQUADRICS = 2 /* any superquadrics */
} mkColliderPairs;

/* Room for an entry's untimed preparation (the vertex sets of the polytope
 * GJK). Caller-owned; one per thread. */
#define MK_COLLIDER_SCRATCH_DOUBLES 1024
typedef struct mkColliderScratch { double d[MK_COLLIDER_SCRATCH_DOUBLES]; } mkColliderScratch;

typedef struct mkCollider {
	const char *name;      /* unique, lower case: "minksum-normal" */
	const char *summary;   /* one line for --help */
	const char *params;    /* its parameters as text, for a result sidecar */
	unsigned gives;        /* mkColliderGives */
	unsigned pairs;        /* mkColliderPairs */
	int referee;           /* 1 for the referee (slow; the truth of a run). Its
	                          answer: distance = bound = a certified lower
	                          bound of sd; separated: gap = the width of its
	                          certified bracket [bound, bound + gap];
	                          residual = gap / scale (separated), 0 for a
	                          certified overlap, NaN when not certified, so a
	                          pair is certain iff residual <= the width asked */
	/* Work done before the timed call for this pair (NULL: none). */
	mkResult (*prepare)(mkBody3 b1, mkBody3 b2, mkColliderScratch *scratch);
	/* The query; bodies valid and accepted, scratch prepared. */
	mkResult (*run)(mkBody3 b1, mkBody3 b2, mkColliderScratch *scratch, mkCollision3 *out);
	/* The version of the library it runs on, or NULL (the core's own). */
	const char *(*version)(void);
} mkCollider;

MK_API int mkColliders_Count(void);
/* The i-th entry, NULL when i is out of range. */
MK_API const mkCollider *mkColliders_At(int i);
/* By name; NULL when unknown. */
MK_API const mkCollider *mkColliders_Find(const char *name);

/* 1 when the entry takes this pair; otherwise 0 and a one-line reason in msg
 * (which body, why) when msg is not NULL. */
MK_API int mkCollider_Accepts(const mkCollider *c, mkBody3 b1, mkBody3 b2, char *msg, size_t msglen);

/* prepare (if any), then run. MK_ERR_ARGUMENT on a NULL argument,
 * MK_ERR_UNSUPPORTED when the entry does not take the pair; else the run's
 * result. out is always cleared first. */
MK_API mkResult mkCollider_Run(const mkCollider *c, mkBody3 b1, mkBody3 b2, mkColliderScratch *scratch,
	mkCollision3 *out);

MK_EXTERN_C_END

#endif
