/* fig4.c - the geometry of the paper's Fig. 4: eight 3D pairs (ellipsoids,
 * superquadrics, boxes, cylinders, parallelepipeds) on 50 x 50 grids, each
 * with the bodies' surfaces and B2 placed on the sum (see demos.h). */
#include "demos_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Fig. 4: general superquadrics (reference demo: B1 a ~ 1 + 10 U, B2
 * a ~ 1 + 5 U, eps ~ U(0.1, 1.9), drawn at random). */
static const double mkFig4Sq1[5] = { 7.5, 5.0, 4.0, 0.4, 1.4 };   /* a, b, c, eps1, eps2 */
static const double mkFig4Sq2[5] = { 3.5, 2.2, 1.6, 1.6, 0.3 };
/* Rotations of every rotated 3D body (quaternions w, x, y, z, normalised by
 * the SPEC parser); the reference code draws quat2rotm(rand(1,4)). */
static const double mkQuat1[4] = { 0.86, 0.22, 0.38, 0.26 };
static const double mkQuat2[4] = { 0.42, 0.71, 0.13, 0.55 };
/* Primitive sizes (edge lengths of the cubes, l x w x h; cylinder
 * cross-section semi-axes and height) from the reference demo script. */
static const double mkBox1[3] = { 5.2, 3.3, 2.87 };
static const double mkBox2[3] = { 4.3, 2.8, 1.254 };
static const double mkCyl1[3] = { 6.24, 3.6, 10.0 };
static const double mkCyl2[3] = { 3.58, 2.52, 5.0 };
/* The reference demo's "ellipsoids" are spheres of radius 8.6 and 3.56; the
 * paper's caption says ellipsoids, so the largest semi-axes keep those
 * radii and the other two are chosen here. */
static const double mkEll1[3] = { 8.6, 5.5, 3.5 };
static const double mkEll2[3] = { 3.56, 2.4, 1.6 };
/* The parallelepipeds' maps (paper, Sec. 5.2.3). */
static const double mkShear1[9] = { 1, 0, 0.5, 0, 1, 0.2, 0, 0, 1 };
static const double mkShear2[9] = { 1, 0, 0.47, 0, 1, 0.14, 0, 0, 1 };
/* B2 is placed at the sum point whose B1 surface normal is closest to this
 * direction: to the right of B1 as the 3D plots look at it (gnuplot's view
 * 60, 30 has the screen's right along (cos 30, sin 30, 0)), a little
 * raised, so that B2 does not hide B1. */
static const double mkPlaceDir[3] = { 0.85, 0.45, 0.3 };
#define MK_FIG4_GRID 50

/* ---- Fig. 4: 3D pairs on 50 x 50 grids ------------------------------------ */

static void mkSpecQuat(char *buf, size_t len, const double q[4])
{
	if (q)
		snprintf(buf, len, " quat=%s,%s,%s,%s", mkDemo_Fmt(q[0]).s, mkDemo_Fmt(q[1]).s, mkDemo_Fmt(q[2]).s, mkDemo_Fmt(q[3]).s);
	else
		buf[0] = '\0';
}

/* A superquadric SPEC with a = s[0..2], eps = e1, e2 and either a rotation
 * (q, may be NULL) or the map R(q) S (S row-major, not NULL). */
static int mkSpec3(char *buf, size_t len, const char *kind, const double s[3], double e1, double e2,
	const double q[4], const double S[9])
{
	char pose[512];
	if (S) {
		int ok = 0;
		mkMat3 R = mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
		ok = mkMat3_IsFinite(R);
		mkMat3 Sm;
		for (int i = 0; i < 9; ++i)
			Sm.m[i / 3][i % 3] = S[i];
		mkMat3 M = mkMat3_Mul(R, Sm);
		snprintf(pose, sizeof pose, " M=%s,%s,%s,%s,%s,%s,%s,%s,%s",
			mkDemo_Fmt(M.m[0][0]).s, mkDemo_Fmt(M.m[0][1]).s, mkDemo_Fmt(M.m[0][2]).s, mkDemo_Fmt(M.m[1][0]).s, mkDemo_Fmt(M.m[1][1]).s,
			mkDemo_Fmt(M.m[1][2]).s, mkDemo_Fmt(M.m[2][0]).s, mkDemo_Fmt(M.m[2][1]).s, mkDemo_Fmt(M.m[2][2]).s);
		if (!ok)
			return -1;
	} else {
		mkSpecQuat(pose, sizeof pose, q);
	}
	if (strcmp(kind, "ellipsoid") == 0)
		snprintf(buf, len, "ellipsoid a=%s b=%s c=%s%s", mkDemo_Fmt(s[0]).s, mkDemo_Fmt(s[1]).s, mkDemo_Fmt(s[2]).s, pose);
	else
		snprintf(buf, len, "superquadric a=%s b=%s c=%s eps1=%s eps2=%s%s",
			mkDemo_Fmt(s[0]).s, mkDemo_Fmt(s[1]).s, mkDemo_Fmt(s[2]).s, mkDemo_Fmt(e1).s, mkDemo_Fmt(e2).s, pose);
	return 0;
}

/* One surface on the grid: rows i (eta) from the south pole (i = 0) to the
 * north pole (i = n - 1; mkSample3_Grid gives the poles exactly), columns
 * j = 0..n with j = n repeating j = 0 so that the surface closes around the
 * axis; a blank line after each row, two after the surface. */
static void mkWriteSurface(mkCsv *csv, const char *name, int n, const double *x, const double *y, const double *z)
{
	for (int i = 0; i < n; ++i) {
		for (int j = 0; j <= n; ++j) {
			int idx = i * n + (j % n);
			mkCsv_Str(csv, name);
			mkCsv_Int(csv, i);
			mkCsv_Int(csv, j);
			mkCsv_Double(csv, x[idx]);
			mkCsv_Double(csv, y[idx]);
			mkCsv_Double(csv, z[idx]);
			mkCsv_EndRow(csv);
		}
		fputc('\n', csv->file.fp);
	}
	fputc('\n', csv->file.fp);
}

typedef struct mkPanel3 {
	const char *panel;     /* a..h */
	const char *title;
	char spec1[512], spec2[512];
} mkPanel3;

/* The bodies of Fig. 4 and its panels: which pair, rotated (B1 by
 * mkQuat1, B2 by mkQuat2) or not, and which of the two are parallelepipeds
 * (bit 0: B1 mapped by R mkShear1, bit 1: B2 by R mkShear2). */
enum { MK_SQ1, MK_SQ2, MK_CUBE1, MK_CUBE2, MK_CYL1, MK_CYL2, MK_ELL1, MK_ELL2 };
static const struct {
	const char *panel, *title;
	int body1, body2, rotated, sheared;
} mkFig4Panels[8] = {
	{ "a", "two general superquadrics, canonical", MK_SQ1, MK_SQ2, 0, 0 },
	{ "b", "two general superquadrics, rotated", MK_SQ1, MK_SQ2, 1, 0 },
	{ "c", "two cubes", MK_CUBE1, MK_CUBE2, 1, 0 },
	{ "d", "cube and elliptic cylinder", MK_CUBE1, MK_CYL2, 1, 0 },
	{ "e", "two parallelepipeds", MK_CUBE1, MK_CUBE2, 1, 3 },
	{ "f", "parallelepiped and elliptic cylinder", MK_CUBE1, MK_CYL2, 1, 1 },
	{ "g", "two elliptic cylinders", MK_CYL1, MK_CYL2, 1, 0 },
	{ "h", "two ellipsoids", MK_ELL1, MK_ELL2, 1, 0 },
};

/* The eight panels' SPEC texts; -1 on a zero quaternion (a program
 * error). */
static int mkFigure4_Panels(mkPanel3 P[8])
{
	memset(P, 0, 8 * sizeof *P);
	double cube1[3], cube2[3];
	for (int i = 0; i < 3; ++i) {
		cube1[i] = mkBox1[i] / 2.0;
		cube2[i] = mkBox2[i] / 2.0;
	}
	const double cyl1[3] = { mkCyl1[0], mkCyl1[1], mkCyl1[2] / 2.0 };
	const double cyl2[3] = { mkCyl2[0], mkCyl2[1], mkCyl2[2] / 2.0 };
	const struct { const char *kind; const double *a; double e1, e2; } body[8] = {
		{ "superquadric", mkFig4Sq1, mkFig4Sq1[3], mkFig4Sq1[4] },
		{ "superquadric", mkFig4Sq2, mkFig4Sq2[3], mkFig4Sq2[4] },
		{ "superquadric", cube1, 0.1, 0.1 }, { "superquadric", cube2, 0.1, 0.1 },
		{ "superquadric", cyl1, 0.1, 1.0 }, { "superquadric", cyl2, 0.1, 1.0 },
		{ "ellipsoid", mkEll1, 1.0, 1.0 }, { "ellipsoid", mkEll2, 1.0, 1.0 },
	};
	const double *quat[2] = { mkQuat1, mkQuat2 }, *shear[2] = { mkShear1, mkShear2 };
	int bad = 0;
	for (int p = 0; p < 8; ++p) {
		P[p].panel = mkFig4Panels[p].panel;
		P[p].title = mkFig4Panels[p].title;
		for (int k = 0; k < 2; ++k) {
			int which = k == 0 ? mkFig4Panels[p].body1 : mkFig4Panels[p].body2;
			bad |= mkSpec3(k == 0 ? P[p].spec1 : P[p].spec2, sizeof P[p].spec1, body[which].kind, body[which].a,
				body[which].e1, body[which].e2, mkFig4Panels[p].rotated ? quat[k] : NULL,
				(mkFig4Panels[p].sheared >> k) & 1 ? shear[k] : NULL);
		}
	}
	return bad ? -1 : 0;
}

/* Where B2 goes: the grid index whose B1 normal is closest to the
 * placement direction. */
static int mkFigure4_Place(mkBody3 b1, const mkDemoPts *pt, int N)
{
	double dn = sqrt(mkPlaceDir[0] * mkPlaceDir[0] + mkPlaceDir[1] * mkPlaceDir[1] + mkPlaceDir[2] * mkPlaceDir[2]);
	int best = 0;
	double bestdot = -2.0;
	for (int k = 0; k < N; ++k) {
		mkVec3 u = { pt->ux[k], pt->uy[k], pt->uz[k] };
		mkVec3 x1 = mkBody3_Point(b1, u);
		mkVec3 g = mkBody3_Gradient(b1, x1);
		double gn = sqrt(g.x * g.x + g.y * g.y + g.z * g.z);
		double dot = (g.x * mkPlaceDir[0] + g.y * mkPlaceDir[1] + g.z * mkPlaceDir[2]) / (gn * dn);
		if (gn > 0.0 && dot > bestdot) {
			bestdot = dot;
			best = k;
		}
	}
	return best;
}

/* One panel: the sum on the grid, B2 placed on it, the file and its index
 * row. pt holds the grid; b1p and b2p are room for the bodies' surfaces. */
static void mkFigure4_Panel(mkDemoRun *run, const mkPanel3 *P, mkDemoPts *pt, mkDemoPts *b1p, mkDemoPts *b2p)
{
	const mkDemosOptions *o = run->o;
	const int G = MK_FIG4_GRID, N = G * G;
	mkSumOptions opt = mkDemo_Options(o, MK_FORM_GRADIENT, MK_PARAM_SURFACE);
	static const char *const cols[] = { "surface", "i", "j", "x", "y", "z" };
	mkBody3 b1, b2;
	if (mkDemo_ParseBody(P->spec1, 3, "fig4.body1", &b1) || mkDemo_ParseBody(P->spec2, 3, "fig4.body2", &b2)) {
		run->failed = 1;
		return;
	}
	mkResult rc = mkSum3_Batch(b1, b2, &opt, pt->ux, pt->uy, pt->uz, N, pt->x, pt->y, pt->z, pt->kx, pt->ky, pt->kz);
	if (rc != MK_OK) {
		fprintf(stderr, "demos: fig. 4(%s): the closed form failed: %s\n", P->panel, mkResult_Name(rc));
		run->failed = 1;
		return;
	}
	int best = mkFigure4_Place(b1, pt, N);
	mkBody3 placed = b2;
	placed.t.x = pt->x[best];
	placed.t.y = pt->y[best];
	placed.t.z = pt->z[best];
	for (int k = 0; k < N; ++k) {
		mkVec3 u = { pt->ux[k], pt->uy[k], pt->uz[k] };
		mkVec3 a = mkBody3_Point(b1, u), b = mkBody3_Point(placed, u);
		b1p->x[k] = a.x;
		b1p->y[k] = a.y;
		b1p->z[k] = a.z;
		b2p->x[k] = b.x;
		b2p->y[k] = b.y;
		b2p->z[k] = b.z;
	}
	int finite = 1;
	for (int k = 0; k < N; ++k)
		finite = finite && isfinite(pt->x[k]) && isfinite(pt->y[k]) && isfinite(pt->z[k]);
	if (!finite) {
		fprintf(stderr, "demos: fig. 4(%s): a point of the sum is not finite\n", P->panel);
		run->failed = 1;
		return;
	}
	char file[64], content[512], note[512];
	snprintf(file, sizeof file, "fig4-%s.csv", P->panel);
	mkCsv csv;
	if (mkDemoRun_Open(run, file, cols, 6, &csv) != 0)
		return;
	mkWriteSurface(&csv, "b1", G, b1p->x, b1p->y, b1p->z);
	mkWriteSurface(&csv, "sum", G, pt->x, pt->y, pt->z);
	mkWriteSurface(&csv, "b2", G, b2p->x, b2p->y, b2p->z);
	snprintf(content, sizeof content, "%s: surfaces b1 (data block 0), sum (1) and b2 placed on the sum (2) "
		"on the 50 x 50 grid of B1's surface angles (eta_i, omega_j; i = 0 and 49 the exact poles; "
		"j = 50 repeats j = 0)",
		P->title);
	snprintf(note, sizeof note, "B2 centred at the sum point of grid index (i, j) = (%d, %d), "
		"at %.17g,%.17g,%.17g, where B1's normal is closest to (%g, %g, %g)",
		best / G, best % G, placed.t.x, placed.t.y, placed.t.z, mkPlaceDir[0], mkPlaceDir[1], mkPlaceDir[2]);
	mkDemoEntry e = { 4, P->panel, file, content, P->spec1, P->spec2,
		mkForm_Name(opt.form), mkParam_Name(opt.param), G, note };
	mkDemoRun_Commit(run, &csv, &e);
}

void mkFigure4(mkDemoRun *run)
{
	const int G = MK_FIG4_GRID, N = G * G;
	mkPanel3 P[8];
	int bad = mkFigure4_Panels(P) != 0;
	mkDemoPts pt, b1p, b2p;
	if (bad || mkDemoPts_Alloc(&pt, N) || mkDemoPts_Alloc(&b1p, N) || mkDemoPts_Alloc(&b2p, N)) {
		if (bad)
			fprintf(stderr, "demos: fig. 4: a zero quaternion (program error)\n");
		run->failed = 1;
		return;
	}
	mkSample3_Grid(G, pt.ux, pt.uy, pt.uz);
	for (int p = 0; p < 8 && !run->failed; ++p)
		mkFigure4_Panel(run, &P[p], &pt, &b1p, &b2p);
	mkDemoPts_Free(&pt);
	mkDemoPts_Free(&b1p);
	mkDemoPts_Free(&b2p);
}

