/* mink/registry.h - every way of computing a Minkowski-sum boundary, in one
 * table: the core's closed forms and the baselines of the paper's Table 1.
 *
 * Each entry is an mkMethod (mink/method.h). The experiments loop over the
 * table; `mink methods` prints it; `mink sum --method NAME` runs one entry.
 *
 *   name             dims  exact  sampled  accepts
 *   closed-normal    2D 3D  yes            any pair (Theorem 1)
 *   closed-gradient  2D 3D  yes            any pair (Theorem 2)
 *   closed-normal-f32   2D 3D  approx 1e-6  any pair (Theorem 1, single precision)
 *   closed-gradient-f32 2D 3D  approx 1e-6  any pair (Theorem 2, single precision)
 *   closed-paper     2D 3D                 any pair (Theorem 2 as printed;
 *                                          reference only, see mink/sum.h)
 *   geometric        2D 3D  yes            body2 an ellipse / ellipsoid
 *   hull-cgal-epick  2D 3D         yes     any pair
 *   hull-cgal-epeck  2D 3D         yes     any pair
 *   hull-qhull       2D 3D         yes     any pair
 *   edge-sort        2D            yes     any pair
 *
 * Conventions every entry keeps, so that the referee (mink/referee.h) can
 * check any of them:
 *  - A method that is not MK_METHOD_SAMPLED declares in its table line how
 *    its points are indexed (mkMethodIndexing below): point k at body 1's
 *    surface parameter u_k of mkSample2_Angles(n) (2D) or mkSample3_Grid(n)
 *    (3D, n*n points), so that its outward normal is body 1's normal at u_k
 *    (MK_INDEX_PARAMETER, the closed forms); or point k where the sum's
 *    outward normal is u_k itself (MK_INDEX_NORMAL); or in no particular
 *    order (MK_INDEX_UNORDERED). The referee takes each point's normal from
 *    this; it cannot judge unordered boundary points (it says so), which
 *    the error measure (mink/error.h, `mink score`) measures all the same.
 *  - A MK_METHOD_SAMPLED method samples each body at the same parameters
 *    (n per body; 3D an n x n grid per body) as mkSampled2_Bodies /
 *    mkSampled3_Bodies (mink/baselines.h) do, and returns the vertices of
 *    the convex hull of the pairwise sums of those samples: counter-clockwise
 *    in 2D, in no particular order in 3D.
 *  - The contact set B1 (+) (-B2) is where B2's centre may go: its samples
 *    are p - (q - t2) for p on B1 and q on B2, so B2's translation does not
 *    enter it (as in mink/sum.h); the plus set adds p + q.
 *
 * Adding a method: write one file baselines/src/method_<name>.c that
 * defines a `const mkMethod` (name, summary, reference, flags, accepts and
 * run functions; mkAcceptAny2/3 and mkRefuse below help), and add its line
 * to the table in baselines/src/registry.def (the fields are documented
 * there: indexing, range of n in 2D and 3D, stated accuracy). The build
 * compiles every baselines/src/method_*.c; nothing else changes. (The
 * built-in entries are defined in registry.c, because most are members of
 * a family - one closed form, one hull library - whose run functions only
 * bind the family's parameter.) The referee tests (test_referee2,
 * test_referee3), the registry test, `mink verify` and the experiments
 * loop over the table, so the new entry is put through the referee on
 * random and extreme pairs, timed and measured without a test of its own. */
#ifndef MINK_REGISTRY_H
#define MINK_REGISTRY_H

#include <stddef.h>
#include <mink/mink.h>

MK_EXTERN_C_BEGIN

/* Make room in a method's point set (mink/method.h) for `count` points of
 * dimension dim (2 or 3) and set set->count = count. Keeps the allocation
 * when it is large enough. Returns MK_ERR_ARGUMENT on a bad dim or
 * count < 0, MK_ERR_MEMORY on failure (the set is then emptied). */
MK_API mkResult mkPointSet_Resize(mkPointSet *set, int dim, int count);
/* Release a point set's arrays and leave it empty (safe on an empty set). */
MK_API void mkPointSet_Free(mkPointSet *set);

/* Number of registered methods, the i-th (NULL when i is out of range), and
 * the method of a given name (NULL if unknown). The table's entries come
 * first, then the external methods registered so far (mink/external.h): a
 * name "exec:COMMAND" or "exec:NAME=COMMAND" given to mkRegistry_Find
 * registers one. The pointers stay valid for the life of the program. */
MK_API int mkRegistry_Count(void);
MK_API const mkMethod *mkRegistry_At(int i);
MK_API const mkMethod *mkRegistry_Find(const char *name);
/* The names of the first `max` entries, in registry order, into names[];
 * returns how many were written. */
MK_API int mkRegistry_Names(const char **names, int max);

/* How a method's points are indexed (mink/registry.h, above). */
typedef enum mkMethodIndexing {
	MK_INDEX_PARAMETER = 0, /* point k at body 1's surface parameter u_k */
	MK_INDEX_NORMAL = 1,    /* point k where the sum's outward unit normal is u_k */
	MK_INDEX_UNORDERED = 2  /* no particular order (every sampled method) */
} mkMethodIndexing;

/* The indexing method m declares in the table; for a method not in the
 * table, MK_INDEX_UNORDERED when it is MK_METHOD_SAMPLED or external
 * (mink/external.h) and MK_INDEX_PARAMETER otherwise. */
MK_API mkMethodIndexing mkMethod_Indexing(const mkMethod *m);

/* Accept every valid pair: the accept function of a method that takes any
 * pair (the bodies are validated by the caller). */
MK_API int mkAcceptAny2(mkBody2 b1, mkBody2 b2, mkSet set, char *msg, size_t msglen);
MK_API int mkAcceptAny3(mkBody3 b1, mkBody3 b2, mkSet set, char *msg, size_t msglen);

/* Write a one-line message into msg (when msg is not NULL and msglen > 0),
 * printf-style, and return 0: the answer of an accept function that
 * refuses a pair, e.g.
 *   return mkRefuse(msg, msglen, "body2.eps = %g: needs an ellipse", eps); */
#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
MK_API int mkRefuse(char *msg, size_t msglen, const char *format, ...);

/* A --methods list as drivers take it ("all", or comma-separated names,
 * where an item "exec:COMMAND" or "exec:NAME=COMMAND" names an external
 * method, mink/external.h, and an item "@FILE" names a methods file: one
 * NAME=COMMAND per line, lines starting with # and blank lines skipped)
 * rewritten into out with every external item registered and replaced by
 * its name, so that the list holds registry names only. Returns 1, or 0 and
 * a message naming the item (an external method that cannot be registered,
 * or out too small; for a file, the file, the line and the field). */
MK_API int mkRegistry_Resolve(const char *list, char *out, size_t outlen, char *msg, size_t msglen);

/* Resolution limits. Closed forms: n >= 1 in 2D, n >= 2 in 3D (an n x n
 * grid with both poles). Sampled methods need n >= 3 per body (fewer samples
 * span no area or volume). The hull methods hold all n^2 (2D) or n^4 (3D)
 * pairwise sums in memory, so n is capped to keep that below about 400 MB;
 * edge sorting is linear and only the int range caps it. */
#define MK_CLOSED3_N_MAX 46340  /* n*n fits an int */
#define MK_SAMPLED_N_MIN 3
#define MK_HULL2_N_MAX 4096     /* 16.8 M sums of 2 doubles */
#define MK_HULL3_N_MAX 64       /* 16.8 M sums of 3 doubles */
#define MK_EDGESORT_N_MAX 100000000

/* 1 when method m runs in dimension dim with resolution n; otherwise 0 and a
 * one-line message naming the method, n and the allowed range. The run
 * functions return MK_ERR_RANGE for such n. */
MK_API int mkMethod_CheckN(const mkMethod *m, int dim, int n, char *msg, size_t msglen);

/* The accuracy a method states for its points, relative to the sum's
 * size (mkSum2_Size): MK_F32_TOL (1e-6) for the single-precision tier (MK_METHOD_APPROX);
 * 0 for every other method, which means "exact up to rounding" for
 * MK_METHOD_EXACT ones (the referee's rounding allowance) and nothing for
 * the rest. 0 also for NULL or an unregistered method. */
MK_API double mkMethod_Tolerance(const mkMethod *m);

/* m->accepts2/3 with the dimension checked first: 0 and a message when the
 * method does not run in this dimension or does not take this pair. */
MK_API int mkMethod2_Accepts(const mkMethod *m, mkBody2 b1, mkBody2 b2, mkSet set, char *msg, size_t msglen);
MK_API int mkMethod3_Accepts(const mkMethod *m, mkBody3 b1, mkBody3 b2, mkSet set, char *msg, size_t msglen);

/* The entries themselves, for code that wants one without a name lookup. */
MK_API extern const mkMethod mkMethod_ClosedNormal;
MK_API extern const mkMethod mkMethod_ClosedGradient;
MK_API extern const mkMethod mkMethod_ClosedNormalF32;
MK_API extern const mkMethod mkMethod_ClosedGradientF32;
MK_API extern const mkMethod mkMethod_ClosedPaper;
MK_API extern const mkMethod mkMethod_Geometric;
MK_API extern const mkMethod mkMethod_HullCgalEpick;
MK_API extern const mkMethod mkMethod_HullCgalEpeck;
MK_API extern const mkMethod mkMethod_HullQhull;
MK_API extern const mkMethod mkMethod_EdgeSort;

MK_EXTERN_C_END

#endif
