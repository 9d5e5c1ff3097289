/* paper.c - the paper's published numbers (see mink_exp/paper.h). */
#include "mink_exp/paper.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#define MK_N(a) ((int)(sizeof(a) / sizeof((a)[0])))

const mkPaperValidation mkPaper_Validation[] = {
	{ 2, "e_implicit", "e_implicit_mean", "5.9194e-16", 5.9194e-16, "published_e_implicit_2d" },
	{ 2, "e_gradient", "e_gradient_mean", "6.1839e-7", 6.1839e-7, "published_e_gradient_2d" },
	{ 3, "e_implicit", "e_implicit_mean", "1.8303e-9", 1.8303e-9, "published_e_implicit_3d" },
	{ 3, "e_gradient", "e_gradient_mean", "4.0654e-7", 4.0654e-7, "published_e_gradient_3d" },
};
const int mkPaper_ValidationCount = MK_N(mkPaper_Validation);

const mkPaperFitting mkPaper_Fitting[] = {
	{ 1, "case 1: superquadric fitted to a random polyhedron, e_volume", "polyhedron", "superquadric", "",
		0, 0, "0.2095", 0.2095, "published_case1_e_volume" },
	{ 1, "case 1: same fits, e_implicit", "polyhedron", "superquadric", "", 0, 1, "0.5808", 0.5808,
		"published_case1_e_implicit" },
	{ 2, "case 2: polyhedron of 16 superquadric points, e_volume", "superquadric", "polyhedron", "paper",
		16, 0, "0.6573", 0.6573, "published_case2_16" },
	{ 2, "case 2: polyhedron of 81 points, e_volume", "superquadric", "polyhedron", "paper", 81, 0,
		"0.094", 0.094, "published_case2_81" },
	{ 2, "case 2: polyhedron of 400 points, e_volume", "superquadric", "polyhedron", "paper", 400, 0,
		"0.0171", 0.0171, "published_case2_400" },
	{ 3, "case 3: cube as superquadric ε = (0.1, 0.1)", "cube", "superquadric", "", 0, 0, "0.0112",
		0.0112, "published_case3_cube_superquadric" },
	{ 3, "case 3: ellipsoid as 9 × 9-grid polyhedron", "ellipsoid", "polyhedron", "paper", 0, 0, "0.1340",
		0.1340, "published_case3_ellipsoid_polyhedron" },
	{ 3, "case 3: elliptic cylinder as superquadric ε = (0.1, 1)", "cylinder", "superquadric", "", 0, 0,
		"0.0074", 0.0074, "published_case3_cylinder_superquadric" },
	{ 3, "case 3: elliptic cylinder as 2 × 30-point polyhedron", "cylinder", "polyhedron", "paper", 0, 0,
		"0.0078", 0.0078, "published_case3_cylinder_polyhedron" },
};
const int mkPaper_FittingCount = MK_N(mkPaper_Fitting);

const mkPaperTable2 mkPaper_Table2[] = {
	{ 2, 50, 50, 50, "0.36", "2.860", 0.36, 2.860 },
	{ 2, 1000, 50, 50, "6.41", "2.563", 6.41, 2.563 },
	{ 2, 10000, 50, 50, "64.26", "2.570", 64.26, 2.570 },
	{ 3, 50, 100, 3600, "95.54", "5.308", 95.54, 5.308 },
	{ 3, 200, 100, 3600, "375.02", "5.209", 375.02, 5.209 },
	{ 3, 1000, 100, 3600, "1907.85", "5.299", 1907.85, 5.299 },
};
const int mkPaper_Table2Count = MK_N(mkPaper_Table2);

void mkPaper_Record(mkMeta *meta, const char *experiment)
{
	if (strcmp(experiment, "validation") == 0)
		for (int i = 0; i < mkPaper_ValidationCount; ++i)
			mkMeta_SetDouble(meta, mkPaper_Validation[i].key, mkPaper_Validation[i].value);
	if (strcmp(experiment, "fitting") == 0)
		for (int i = 0; i < mkPaper_FittingCount; ++i)
			mkMeta_SetDouble(meta, mkPaper_Fitting[i].key, mkPaper_Fitting[i].value);
}

const mkPaperTable2 *mkPaper_FindTable2(int dim, long obstacles, long points, long orientations)
{
	for (int i = 0; i < mkPaper_Table2Count; ++i) {
		const mkPaperTable2 *p = &mkPaper_Table2[i];
		if (p->dim == dim && p->obstacles == obstacles && p->points == points && p->orientations == orientations)
			return p;
	}
	return NULL;
}

const mkPaperTable3 mkPaper_Table3[] = {
	{ "GJK", "18.4", "18.3", 18.4, 18.3 },
	{ "ASC", "0.133", "—", 0.133, NAN },
	{ "Implicit", "27.0", "42.3", 27.0, 42.3 },
	{ "Common Normal", "4.1", "7.1", 4.1, 7.1 },
	{ "MinkSum (Ray)", "3.5", "5.2", 3.5, 5.2 },
	{ "MinkSum (Normal)", "3.5", "5.1", 3.5, 5.1 },
};
const int mkPaper_Table3Count = MK_N(mkPaper_Table3);
