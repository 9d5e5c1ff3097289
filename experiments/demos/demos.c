/* demos.c - the geometry of the paper's demonstration figures 1-4 (see
 * demos.h): the fixed choices, the SPEC texts, one writer per figure. */
#include "demos.h"
#include "demos_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the choices where the paper is silent ------------------------------- */

/* Fig. 3: one superellipse pair in four poses (the reference demo draws
 * a ~ 1 + 5 U(0,1), eps ~ U(0.1, 1.9), angles 2 pi U, shears U(-2, 2) at
 * random; these are fixed values from those ranges). */
static const double mkFig3A1[3] = { 5.2, 3.1, 0.45 };   /* a, b, eps */
static const double mkFig3A2[3] = { 2.6, 1.5, 1.55 };
static const double mkFig3Angle[2] = { MK_PI / 5.0, -2.0 * MK_PI / 7.0 };
static const double mkFig3Shear[2] = { 0.8, -0.6 };
#define MK_NO_FIELD (-1000000L)
#define MK_FIG3_N 100
#define MK_FIG3_PLACES 10


/* Two blank lines: gnuplot's separator of data blocks (curves, surfaces). */
static void mkEndBlock(mkCsv *csv)
{
	fputs("\n\n", csv->file.fp);
}

/* ---- bodies from SPEC text ---------------------------------------------- */

static void mkSpec2(char *buf, size_t len, const double s[3], double angle, double shear)
{
	snprintf(buf, len, "superellipse a=%s b=%s eps=%s rot=%s shear=%s",
		mkDemo_Fmt(s[0]).s, mkDemo_Fmt(s[1]).s, mkDemo_Fmt(s[2]).s, mkDemo_Fmt(angle).s, mkDemo_Fmt(shear).s);
}

/* Up to three leading fields of a row: lead1, lead2 (NULL: none), lead3
 * (MK_NO_FIELD: none). */
static void mkWriteLeads(mkCsv *csv, const char *lead1, const char *lead2, long lead3)
{
	if (lead1)
		mkCsv_Str(csv, lead1);
	if (lead2)
		mkCsv_Str(csv, lead2);
	if (lead3 != MK_NO_FIELD)
		mkCsv_Int(csv, lead3);
}

/* A closed outline of a 2D body: n samples and the first repeated, after
 * up to three leading fields (NULL / MK_NO_FIELD: none); with_kiss adds two
 * empty kissing-point fields. */
static void mkWriteOutline2(mkCsv *csv, const char *lead1, const char *lead2, long lead3,
	mkBody2 b, const mkDemoPts *u, int with_kiss)
{
	for (int k = 0; k <= u->n; ++k) {
		int kk = k % u->n;
		mkVec2 uv = { u->ux[kk], u->uy[kk] };
		mkVec2 p = mkBody2_Point(b, uv);
		mkWriteLeads(csv, lead1, lead2, lead3);
		mkCsv_Int(csv, k);
		mkCsv_Double(csv, p.x);
		mkCsv_Double(csv, p.y);
		if (with_kiss) {
			mkCsv_Empty(csv);
			mkCsv_Empty(csv);
		}
		mkCsv_EndRow(csv);
	}
	mkEndBlock(csv);
}

/* A closed-form sum curve: for k = 0..n (k = n repeats k = 0) the lead
 * fields (as in mkWriteOutline2), k, the parameter's angle when
 * with_angle, the sum point and the kissing point; then a block end. */
static void mkWriteSum2(mkCsv *csv, const char *lead1, const char *lead2, long lead3, const mkDemoPts *pt,
	int with_angle)
{
	for (int k = 0; k <= pt->n; ++k) {
		int kk = k % pt->n;
		mkWriteLeads(csv, lead1, lead2, lead3);
		mkCsv_Int(csv, k);
		if (with_angle)
			mkCsv_Double(csv, atan2(pt->uy[kk], pt->ux[kk]));
		mkCsv_Double(csv, pt->x[kk]);
		mkCsv_Double(csv, pt->y[kk]);
		mkCsv_Double(csv, pt->kx[kk]);
		mkCsv_Double(csv, pt->ky[kk]);
		mkCsv_EndRow(csv);
	}
	mkEndBlock(csv);
}

/* ---- Fig. 1: definition vs closed form ------------------------------------ */

static void mkFigure1(mkDemoRun *run)
{
	const mkDemosOptions *o = run->o;
	const int N = 50;
	char s1[256], s2[256];
	const double p1[3] = { 10.0, 8.6, 0.36 }, p2[3] = { 9.4, 6.8, 1.28 };
	mkSpec2(s1, sizeof s1, p1, MK_PI / 8.0, 1.32);
	mkSpec2(s2, sizeof s2, p2, -MK_PI / 5.0, 1.6);
	mkBody2 b1, b2;
	mkDemoPts pt;
	if (mkDemo_ParseBody(s1, 2, "fig1.body1", &b1) || mkDemo_ParseBody(s2, 2, "fig1.body2", &b2) || mkDemoPts_Alloc(&pt, N)) {
		run->failed = 1;
		return;
	}
	mkSample2_Angles(N, pt.ux, pt.uy);

	/* The samples of B1 and of -B2 (closed outlines through them). */
	static const char *const bcols[] = { "body", "k", "theta", "x", "y" };
	mkCsv csv;
	if (mkDemoRun_Open(run, "fig1-bodies.csv", bcols, 5, &csv) == 0) {
		for (int body = 0; body < 2; ++body) {
			for (int k = 0; k <= N; ++k) {
				int kk = k % N;
				mkVec2 u = { pt.ux[kk], pt.uy[kk] };
				mkVec2 p = body == 0 ? mkBody2_Point(b1, u) : mkBody2_Point(b2, u);
				mkCsv_Str(&csv, body == 0 ? "b1" : "minus_b2");
				mkCsv_Int(&csv, k);
				mkCsv_Double(&csv, atan2(u.y, u.x));
				mkCsv_Double(&csv, body == 0 ? p.x : -p.x);
				mkCsv_Double(&csv, body == 0 ? p.y : -p.y);
				mkCsv_EndRow(&csv);
			}
			mkEndBlock(&csv);
		}
		mkDemoEntry e = { 1, "a", "fig1-bodies.csv",
			"samples x1(theta_k) of B1 and -x2(theta_k) of -B2, theta_k = -pi + 2 pi k / 50; k = 50 repeats k = 0",
			s1, s2, "", "", N, "bodies centred at the origin" };
		mkDemoRun_Commit(run, &csv, &e);
	}

	/* The definition: every difference of a B1 sample and a B2 sample. */
	static const char *const pcols[] = { "i", "j", "x", "y" };
	if (!run->failed && mkDemoRun_Open(run, "fig1-pairwise.csv", pcols, 4, &csv) == 0) {
		for (int i = 0; i < N; ++i) {
			mkVec2 ui = { pt.ux[i], pt.uy[i] };
			mkVec2 x1 = mkBody2_Point(b1, ui);
			for (int j = 0; j < N; ++j) {
				mkVec2 uj = { pt.ux[j], pt.uy[j] };
				mkVec2 x2 = mkBody2_Point(b2, uj);
				mkCsv_Int(&csv, i);
				mkCsv_Int(&csv, j);
				mkCsv_Double(&csv, x1.x - x2.x);
				mkCsv_Double(&csv, x1.y - x2.y);
				mkCsv_EndRow(&csv);
			}
		}
		mkDemoEntry e = { 1, "a", "fig1-pairwise.csv",
			"the definition: all 2500 differences x1_i - x2_j of the 50 samples of each body", s1, s2,
			"", "", N, "their convex hull approximates the boundary of B1 (+) (-B2)" };
		mkDemoRun_Commit(run, &csv, &e);
	}

	/* The closed form at B1's 50 surface parameters, with B1's point at the
	 * same parameter (the kissing point). */
	mkSumOptions opt = mkDemo_Options(o, MK_FORM_GRADIENT, MK_PARAM_SURFACE);
	mkResult rc = run->failed ? MK_OK
		: mkSum2_Batch(b1, b2, &opt, pt.ux, pt.uy, N, pt.x, pt.y, pt.kx, pt.ky);
	if (rc != MK_OK) {
		fprintf(stderr, "demos: fig. 1: the closed form failed: %s\n", mkResult_Name(rc));
		run->failed = 1;
	}
	static const char *const ccols[] = { "k", "theta", "x", "y", "x1", "y1" };
	if (!run->failed && mkDemoRun_Open(run, "fig1-closed.csv", ccols, 6, &csv) == 0) {
		mkWriteSum2(&csv, NULL, NULL, MK_NO_FIELD, &pt, 1);
		mkDemoEntry e = { 1, "b", "fig1-closed.csv",
			"the closed form x(theta_k) at B1's 50 surface parameters, with B1's point x1(theta_k) at the same parameter; k = 50 repeats k = 0",
			s1, s2, mkForm_Name(opt.form), mkParam_Name(opt.param), N, "" };
		mkDemoRun_Commit(run, &csv, &e);
	}
	mkDemoPts_Free(&pt);
}

/* ---- Fig. 2: the two theorems --------------------------------------------- */

/* The pair of Fig. 2 and its contact at B1's surface parameter K0. */
typedef struct mkFig2 {
	char s1[256], s2[256];
	mkBody2 b1, b2;
	mkVec2 u0, n1;
	mkVec2 kiss[2], xs[2];   /* theorem 1, theorem 2 */
} mkFig2;

#define MK_FIG2_N 100
#define MK_FIG2_K0 24

/* Curves: Theorem 1 at 100 normal angles, Theorem 2 at B1's 100 surface
 * angles. */
static void mkFigure2_Curves(mkDemoRun *run, const mkFig2 *f, mkDemoPts *pt)
{
	const mkDemosOptions *o = run->o;
	const int N = MK_FIG2_N;
	const char *s1 = f->s1, *s2 = f->s2;
	mkBody2 b1 = f->b1, b2 = f->b2;
	static const char *const ccols[] = { "theorem", "k", "param_angle", "x", "y", "kx", "ky" };
	mkCsv csv;
	if (mkDemoRun_Open(run, "fig2-curves.csv", ccols, 7, &csv) == 0) {
		for (int th = 1; th <= 2 && !run->failed; ++th) {
			mkSumOptions opt = th == 1 ? mkDemo_Options(o, MK_FORM_NORMAL, MK_PARAM_NORMAL)
				: mkDemo_Options(o, MK_FORM_GRADIENT, MK_PARAM_SURFACE);
			mkResult rc = mkSum2_Batch(b1, b2, &opt, pt->ux, pt->uy, N, pt->x, pt->y, pt->kx, pt->ky);
			if (rc != MK_OK) {
				fprintf(stderr, "demos: fig. 2: the closed form failed: %s\n", mkResult_Name(rc));
				run->failed = 1;
				break;
			}
			mkWriteSum2(&csv, NULL, NULL, th, pt, 1);
		}
		if (run->failed) {
			mkCsv_Discard(&csv);
		} else {
			mkDemoEntry e = { 2, "a,b", "fig2-curves.csv",
				"theorem 1: normal form at 100 unit normals n_k = (cos, sin)(-pi + 2 pi k / 100); "
				"theorem 2: gradient form at B1's 100 surface angles; kx, ky the kissing point on B1",
				s1, s2, "normal (theorem 1), gradient (theorem 2)", "normal (theorem 1), surface (theorem 2)",
				N, "k = 100 repeats k = 0" };
			mkDemoRun_Commit(run, &csv, &e);
		}
	}
}

/* B1 and B2 placed at the contact, in both panels. */
static void mkFigure2_Bodies(mkDemoRun *run, const mkFig2 *f, const mkDemoPts *ol)
{
	const mkDemosOptions *o = run->o;
	mkCsv csv;
	const char *s1 = f->s1, *s2 = f->s2;
	mkBody2 b1 = f->b1, b2 = f->b2;
	const mkVec2 *xs = f->xs;
	static const char *const bcols[] = { "theorem", "body", "k", "x", "y" };
	if (!run->failed && mkDemoRun_Open(run, "fig2-bodies.csv", bcols, 5, &csv) == 0) {
		for (int th = 1; th <= 2; ++th) {
			mkBody2 placed = b2;
			placed.t = xs[th - 1];
			char lead[2] = { (char)('0' + th), '\0' };
			mkWriteOutline2(&csv, lead, "b1", MK_NO_FIELD, b1, ol, 0);
			mkWriteOutline2(&csv, lead, "b2", MK_NO_FIELD, placed, ol, 0);
		}
		char note[128];
		snprintf(note, sizeof note, "outlines of %ld samples, closed; B2 centred at the contact's sum point", o->outline);
		mkDemoEntry e = { 2, "a,b", "fig2-bodies.csv", "B1 at the origin and B2 placed to touch it", s1, s2,
			"", "", 0, note };
		mkDemoRun_Commit(run, &csv, &e);
	}

}

/* The contact: centres, kissing point, and the vectors each theorem pairs:
 * the unit normals n1 and -n1 (theorem 1), the gradients m1 of B1 and m2 of
 * the placed B2 at the kissing point (theorem 2). */
static void mkFigure2_Contact(mkDemoRun *run, const mkFig2 *f)
{
	const int N = MK_FIG2_N, K0 = MK_FIG2_K0;
	mkCsv csv;
	const char *s1 = f->s1, *s2 = f->s2;
	mkBody2 b1 = f->b1, b2 = f->b2;
	const mkVec2 *xs = f->xs, *kiss = f->kiss;
	mkVec2 u0 = f->u0, n1 = f->n1;
	static const char *const kcols[] = { "theorem", "c1x", "c1y", "c2x", "c2y", "px", "py",
		"v1x", "v1y", "v2x", "v2y", "v1_norm", "v2_norm", "param_index", "param_angle", "x_difference" };
	if (!run->failed && mkDemoRun_Open(run, "fig2-contact.csv", kcols, 16, &csv) == 0) {
		double diff = hypot(xs[0].x - xs[1].x, xs[0].y - xs[1].y);
		for (int th = 1; th <= 2; ++th) {
			mkVec2 p = kiss[th - 1];
			mkBody2 placed = b2;
			placed.t = xs[th - 1];
			mkVec2 v1, v2;
			if (th == 1) {
				v1 = n1;
				v2.x = -n1.x;
				v2.y = -n1.y;
			} else {
				v1 = mkBody2_Gradient(b1, p);
				v2 = mkBody2_Gradient(placed, p);
			}
			mkCsv_Int(&csv, th);
			mkCsv_Double(&csv, b1.t.x);
			mkCsv_Double(&csv, b1.t.y);
			mkCsv_Double(&csv, placed.t.x);
			mkCsv_Double(&csv, placed.t.y);
			mkCsv_Double(&csv, p.x);
			mkCsv_Double(&csv, p.y);
			mkCsv_Double(&csv, v1.x);
			mkCsv_Double(&csv, v1.y);
			mkCsv_Double(&csv, v2.x);
			mkCsv_Double(&csv, v2.y);
			mkCsv_Double(&csv, hypot(v1.x, v1.y));
			mkCsv_Double(&csv, hypot(v2.x, v2.y));
			mkCsv_Int(&csv, K0);
			/* The contact's parameter: n1's angle (theorem 1), u0's (theorem 2). */
			mkCsv_Double(&csv, th == 1 ? atan2(n1.y, n1.x) : atan2(u0.y, u0.x));
			mkCsv_Double(&csv, diff);
			mkCsv_EndRow(&csv);
		}
		mkDemoEntry e = { 2, "a,b", "fig2-contact.csv",
			"the contact at B1's surface parameter k = 24 of 100: centres c1 (B1) and c2 (B2), kissing point p; "
			"theorem 1: v1 = n1, v2 = -n1; theorem 2: v1 = m1 (gradient of B1 at p), v2 = m2 (gradient of the placed B2 at p); "
			"param_angle = the contact's parameter angle in its theorem's curve; "
			"x_difference = distance between the two theorems' sum points",
			s1, s2, "normal (theorem 1), gradient (theorem 2)", "normal (theorem 1), surface (theorem 2)", N,
			"k = 24 is the reference code's idx = 25" };
		mkDemoRun_Commit(run, &csv, &e);
	}
}

static void mkFigure2(mkDemoRun *run)
{
	const mkDemosOptions *o = run->o;
	const int N = MK_FIG2_N, K0 = MK_FIG2_K0;
	mkFig2 f;
	const double p1[3] = { 3.3, 2.6, 0.73 }, p2[3] = { 2.4, 2.0, 1.28 };
	mkSpec2(f.s1, sizeof f.s1, p1, MK_PI / 6.3, 0.276);
	mkSpec2(f.s2, sizeof f.s2, p2, -MK_PI / 3.0, 0.85);
	mkDemoPts pt, ol;
	if (mkDemo_ParseBody(f.s1, 2, "fig2.body1", &f.b1) || mkDemo_ParseBody(f.s2, 2, "fig2.body2", &f.b2)
		|| mkDemoPts_Alloc(&pt, N) || mkDemoPts_Alloc(&ol, (int)o->outline)) {
		run->failed = 1;
		return;
	}
	mkSample2_Angles(N, pt.ux, pt.uy);
	mkSample2_Angles(ol.n, ol.ux, ol.uy);

	/* The contact: B1's surface parameter K0, its point and world normal. */
	f.u0.x = pt.ux[K0];
	f.u0.y = pt.uy[K0];
	mkVec2 x1 = mkBody2_Point(f.b1, f.u0);
	mkVec2 m1 = mkBody2_Gradient(f.b1, x1);
	double m1n = hypot(m1.x, m1.y);
	f.n1.x = m1.x / m1n;
	f.n1.y = m1.y / m1n;
	f.xs[0] = mkSum2_Point(f.b1, f.b2, MK_SET_CONTACT, MK_FORM_NORMAL, MK_PARAM_NORMAL, f.n1, &f.kiss[0]);
	f.xs[1] = mkSum2_Point(f.b1, f.b2, MK_SET_CONTACT, MK_FORM_GRADIENT, MK_PARAM_SURFACE, f.u0, &f.kiss[1]);
	mkFigure2_Curves(run, &f, &pt);
	if (!run->failed)
		mkFigure2_Bodies(run, &f, &ol);
	if (!run->failed)
		mkFigure2_Contact(run, &f);
	mkDemoPts_Free(&pt);
	mkDemoPts_Free(&ol);
}

/* ---- Fig. 3: four 2D pairs, B2 at 10 places -------------------------------- */

static void mkFigure3(mkDemoRun *run)
{
	const mkDemosOptions *o = run->o;
	const int N = MK_FIG3_N;
	static const char *const panels[4] = { "canonical", "rotated", "sheared", "rotated+sheared" };
	mkDemoPts pt, ol;
	if (mkDemoPts_Alloc(&pt, N) || mkDemoPts_Alloc(&ol, (int)o->outline)) {
		run->failed = 1;
		return;
	}
	mkSample2_Angles(N, pt.ux, pt.uy);
	mkSample2_Angles(ol.n, ol.ux, ol.uy);
	static const char *const cols[] = { "panel", "curve", "place", "k", "x", "y", "kx", "ky" };
	mkCsv csv;
	char specs[4][2][256];
	if (mkDemoRun_Open(run, "fig3.csv", cols, 8, &csv) != 0) {
		mkDemoPts_Free(&pt);
		mkDemoPts_Free(&ol);
		return;
	}
	mkSumOptions opt = mkDemo_Options(o, MK_FORM_GRADIENT, MK_PARAM_SURFACE);
	for (int p = 0; p < 4 && !run->failed; ++p) {
		int rot = p == 1 || p == 3, shear = p == 2 || p == 3;
		mkSpec2(specs[p][0], sizeof specs[p][0], mkFig3A1, rot ? mkFig3Angle[0] : 0.0, shear ? mkFig3Shear[0] : 0.0);
		mkSpec2(specs[p][1], sizeof specs[p][1], mkFig3A2, rot ? mkFig3Angle[1] : 0.0, shear ? mkFig3Shear[1] : 0.0);
		mkBody2 b1, b2;
		if (mkDemo_ParseBody(specs[p][0], 2, "fig3.body1", &b1) || mkDemo_ParseBody(specs[p][1], 2, "fig3.body2", &b2)) {
			run->failed = 1;
			break;
		}
		mkResult rc = mkSum2_Batch(b1, b2, &opt, pt.ux, pt.uy, N, pt.x, pt.y, pt.kx, pt.ky);
		if (rc != MK_OK) {
			fprintf(stderr, "demos: fig. 3: the closed form failed: %s\n", mkResult_Name(rc));
			run->failed = 1;
			break;
		}
		mkWriteOutline2(&csv, panels[p], "b1", -1, b1, &ol, 1);
		mkWriteSum2(&csv, panels[p], "sum", -1, &pt, 0);
		for (int place = 0; place < MK_FIG3_PLACES; ++place) {
			int k = place * N / MK_FIG3_PLACES;
			mkBody2 placed = b2;
			placed.t.x = pt.x[k];
			placed.t.y = pt.y[k];
			mkWriteOutline2(&csv, panels[p], "b2", place, placed, &ol, 1);
		}
	}
	if (run->failed) {
		mkCsv_Discard(&csv);
	} else {
		char body1[1200], body2[1200], note[256];
		snprintf(body1, sizeof body1, "%s | %s | %s | %s", specs[0][0], specs[1][0], specs[2][0], specs[3][0]);
		snprintf(body2, sizeof body2, "%s | %s | %s | %s", specs[0][1], specs[1][1], specs[2][1], specs[3][1]);
		snprintf(note, sizeof note, "B2 (curve b2) centred at sum points k = 0, 10, ..., 90 (place = k / 10); "
			"outlines of %ld samples; bodies per panel in the order canonical | rotated | sheared | rotated+sheared",
			o->outline);
		mkDemoEntry e = { 3, "canonical,rotated,sheared,rotated+sheared", "fig3.csv",
			"per panel: B1's outline, the closed-form sum at B1's 100 surface angles (with kissing points), "
			"B2 at 10 places on it; closed curves (last row repeats the first)",
			body1, body2, mkForm_Name(opt.form), mkParam_Name(opt.param), N, note };
		mkDemoRun_Commit(run, &csv, &e);
	}
	mkDemoPts_Free(&pt);
	mkDemoPts_Free(&ol);
}

/* ---- the run ------------------------------------------------------------- */

int mkDemos_Figure(mkRun *run, const mkDemosOptions *o, int f)
{
	mkDemoRun d = { o, run, 0 };
	switch (f) {
	case 1: mkFigure1(&d); break;
	case 2: mkFigure2(&d); break;
	case 3: mkFigure3(&d); break;
	default: mkFigure4(&d); break;
	}
	return d.failed ? -1 : 0;
}

void mkDemos_Describe(mkMeta *meta, const mkDemosOptions *o, const int *units, long begin, long end)
{
	char text[512] = "";
	mkMeta_Set(meta, "seed", "none (no random draws)");
	mkMeta_Set(meta, "trials", "1 (each figure once)");
	for (long i = begin; i < end; ++i)
		snprintf(text + strlen(text), sizeof text - strlen(text), "%s%d", i > begin ? "," : "", units[i]);
	mkMeta_Set(meta, "figures", text[0] ? text : "none");
	mkMeta_Set(meta, "set", mkSet_Name(MK_SET_CONTACT));
	mkMeta_Set(meta, "impl_requested", mkImpl_Name(o->impl));
	mkMeta_Set(meta, "impl", mkImpl_Name(mkImpl_Resolve(o->impl)));
	mkMeta_SetInt(meta, "outline_samples_2d", o->outline);
	mkMeta_Set(meta, "transform_2d", "M = rot(angle) shear(s), shear(s) = [1 s; 0 1] (the paper's M^(3))");
	mkMeta_Set(meta, "choices_fig3", "B1 SE(a=(5.2,3.1), eps=0.45), B2 SE(a=(2.6,1.5), eps=1.55); "
		"angles (pi/5, -2pi/7); shears (0.8, -0.6); N = 100; B2 at sum points k = 0, 10, ..., 90");
	mkMeta_Set(meta, "choices_fig4", "general SQs B1 a=(7.5,5,4) eps=(0.4,1.4), B2 a=(3.5,2.2,1.6) eps=(1.6,0.3); "
		"rotations quat (0.86,0.22,0.38,0.26) for B1 and (0.42,0.71,0.13,0.55) for B2 in every rotated panel; "
		"cubes of edges (5.2,3.3,2.87) and (4.3,2.8,1.254), cylinders (semi-axes, height) (6.24,3.6,10) "
		"and (3.58,2.52,5) (reference demo script); parallelepiped = R S with the paper's shears; "
		"ellipsoids a=(8.6,5.5,3.5) and (3.56,2.4,1.6); B2 placed where B1's normal is closest to (0.85,0.45,0.3)");
	mkMeta_Set(meta, "choices_fig2", "contact at B1's surface parameter k = 24 of 100 (the reference code's idx = 25)");
}

void mkDemos_DescribeIndex(mkMeta *meta)
{
	static const char *const fixed[][2] = {
		{ "figure", "index" },
		{ "panel", "all" },
		{ "content", "one row per geometry file of this run, files in the directory named like this file without .csv" },
		{ "body1", "see rows" },
		{ "body2", "see rows" },
		{ "note", "" },
	};
	mkMeta_SetPairs(meta, fixed, MK_COUNT(fixed));
}
