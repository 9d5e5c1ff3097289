/* mink_exp/paper.h - the paper's published numbers, in one place.
 *
 * Ruan & Chirikjian, "Closed-Form Minkowski Sums of Convex Bodies with
 * Smooth Positively Curved Boundaries", Computer-Aided Design, 2022:
 * Sec. 6.1 (validation means), Sec. 6.2 (fitting means), Sec. 7.1
 * (Table 2, C-obstacle times, MATLAB on one core) and Sec. 7.2 (Table 3,
 * collision query times). Each number is kept as printed (`text`) and as a
 * value. The experiments' summaries and drivers read them from here; the
 * drivers copy the ones their figures show into their sidecars
 * ("published_..." keys), which is where the gnuplot scripts read them. No
 * other file holds a published number. */
#ifndef MINK_EXP_PAPER_H
#define MINK_EXP_PAPER_H

#include "meta.h"

/* Sec. 6.1: the mean validation metrics of the published code. */
typedef struct mkPaperValidation {
	int dim;
	const char *metric, *column, *text;
	double value;
	const char *key;   /* the sidecar key the driver records it under */
} mkPaperValidation;
extern const mkPaperValidation mkPaper_Validation[];
extern const int mkPaper_ValidationCount;

/* Sec. 6.2: one published fitting mean and the rows it is the mean of
 * (an empty truth/model/sampling matches anything; level 0 any level;
 * implicit selects e_implicit instead of e_volume). */
typedef struct mkPaperFitting {
	int fit_case;
	const char *what, *truth, *model, *sampling;
	int level;
	int implicit;
	const char *text;
	double value;
	const char *key;   /* the sidecar key the driver records it under */
} mkPaperFitting;
extern const mkPaperFitting mkPaper_Fitting[];
extern const int mkPaper_FittingCount;

/* Record the published numbers of `experiment` ("validation", "fitting")
 * in its sidecar under their keys, for its figure. */
void mkPaper_Record(mkMeta *meta, const char *experiment);

/* Sec. 7.1, Table 2: total seconds and microseconds per point. */
typedef struct mkPaperTable2 {
	int dim;
	long obstacles, points, orientations;
	const char *total_text, *per_point_text;
	double total_s, us_per_point;
} mkPaperTable2;
extern const mkPaperTable2 mkPaper_Table2[];
extern const int mkPaper_Table2Count;
/* The row of this level, or NULL when the paper lists none. */
const mkPaperTable2 *mkPaper_FindTable2(int dim, long obstacles, long points, long orientations);

/* Sec. 7.2, Table 3: mean milliseconds per query on ellipsoids and
 * superquadrics (NaN and "—" where the paper gives none). */
typedef struct mkPaperTable3 {
	const char *algorithm, *ellipsoids_text, *superquadrics_text;
	double ellipsoids_ms, superquadrics_ms;
} mkPaperTable3;
extern const mkPaperTable3 mkPaper_Table3[];
extern const int mkPaper_Table3Count;

#endif
