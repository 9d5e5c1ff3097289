/* test_cspace.c - certified C-obstacle boundaries (mink/cobstacle.h) and
 * scene files and models (mink/scene.h), checked by an independent referee.
 *
 * The referee computes support functions from the textbook formulas of the
 * declared shapes, sharing nothing with the library's kernels:
 *   superellipse |x/a|^p + |y/b|^p <= 1 (p = 2/eps):  h(v) = |(a v1, b v2)|_q,
 *     q = p/(p-1) = 2/(2-eps)  (the dual norm, evaluated with pow());
 *   superquadric: h(v) = | ( |(a v1, b v2)|_q2 , c v3 ) |_q1, q_i = 2/(2-eps_i)
 *     (the dual of the nested norm);
 *   box with half sides s_i: h(v) = sum s_i |v_i|;  cylinder: R |(v1, v2)| + c |v3|;
 *   a placed body t + M S: h(u) = <t, u> + h_S(M^T u);
 *   the C-obstacle K = O (+) (-R_o): h_K(u) = h_O(u) + h_R(-u).
 * With these, for dense directions u (every 1/20000 of a turn in 2D, 6000
 * Fibonacci directions in 3D):
 *   inner vertices p lie in K:   <u, p> <= h_K(u) + rounding;
 *   the inner gap:               h_K(u) - max_k <u, p_k> <= T;
 *   outer polygon contains K:    for each edge normal nu, h_K(nu) <= <nu, v_k> + rounding;
 *   the outer gap:               max_k <u, v_k> - h_K(u) <= T.
 * Sampling directions can only under-estimate a Hausdorff distance, so these
 * checks can catch a wrong certificate, not prove one; the proofs are in
 * docs/scene.md. Rounding: 1e-9 times the coordinates' size, far above the
 * closed forms' ~1e-15 relative error and far below every T used (1e-3..1e-1). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/cspace.h>

#include "ensure.h"

/* ---- the referee ---------------------------------------------------------------- */

static double qnorm2(double x, double y, double q)
{
	x = fabs(x); y = fabs(y);
	double m = fmax(x, y);
	if (m == 0.0) return 0.0;
	return m * pow(pow(x / m, q) + pow(y / m, q), 1.0 / q);
}

/* Support function of a declared scene body (its `at` applied when `placed`). */
static double ref_h2(const mkSceneBody *b, mkMat2 Rot, int placed, mkVec2 u)
{
	mkMat2 M = mkMat2_Mul(Rot, b->spec.body2.M);
	mkVec2 v = mkMat2_MulTVec(M, u);
	double h;
	if (b->kind == MK_SCENE_BOX) h = 0.5 * b->size[0] * fabs(v.x) + 0.5 * b->size[1] * fabs(v.y);
	else {
		mkShape2 s = b->spec.body2.shape;
		h = qnorm2(s.a * v.x, s.b * v.y, 2.0 / (2.0 - s.eps));
	}
	return h + (placed ? mkVec2_Dot(b->spec.body2.t, u) : 0.0);
}

static double ref_h3(const mkSceneBody *b, mkMat3 Rot, int placed, mkVec3 u)
{
	mkMat3 M = mkMat3_Mul(Rot, b->spec.body3.M);
	mkVec3 v = mkMat3_MulTVec(M, u);
	double h;
	if (b->kind == MK_SCENE_BOX)
		h = 0.5 * (b->size[0] * fabs(v.x) + b->size[1] * fabs(v.y) + b->size[2] * fabs(v.z));
	else if (b->kind == MK_SCENE_CYLINDER)
		h = b->size[0] * hypot(v.x, v.y) + 0.5 * b->size[1] * fabs(v.z);
	else {
		mkShape3 s = b->spec.body3.shape;
		double in = qnorm2(s.a * v.x, s.b * v.y, 2.0 / (2.0 - s.eps2));
		h = qnorm2(in, s.c * v.z, 2.0 / (2.0 - s.eps1));
	}
	return h + (placed ? mkVec3_Dot(b->spec.body3.t, u) : 0.0);
}

/* h of the C-obstacle of obstacle i against robot part j at orientation o
 * (R): O (+) (-R M_j B_j) - R t_j. */
static double ref_k2(const mkScene *s, int i, int j, int o, mkVec2 u)
{
	mkMat2 R = mkScene2_Orientation(s, o);
	return ref_h2(&s->obstacles[i], mkMat2_Identity(), 1, u) + ref_h2(&s->parts[j], R, 0, mkVec2_Neg(u))
		- mkVec2_Dot(mkMat2_MulVec(R, s->parts[j].spec.body2.t), u);
}

static double ref_k3(const mkScene *s, int i, int j, int o, mkVec3 u)
{
	mkMat3 R = mkScene3_Orientation(s, o);
	return ref_h3(&s->obstacles[i], mkMat3_Identity(), 1, u) + ref_h3(&s->parts[j], R, 0, mkVec3_Neg(u))
		- mkVec3_Dot(mkMat3_MulVec(R, s->parts[j].spec.body3.t), u);
}

static double worst_fold; /* largest fold of an inner 3D surface seen */

static int cmp_u64(const void *a, const void *b)
{
	unsigned long long x = *(const unsigned long long *)a, y = *(const unsigned long long *)b;
	return x < y ? -1 : x > y;
}

/* Check one 2D boundary; returns the largest support gap seen. */
static double referee2(const mkScene *s, int i, int part, int o, mkBound bound, const double *x, const double *y, int n,
	double tol, double certified)
{
	double scale = 0.0;
	for (int k = 0; k < n; ++k) scale = fmax(scale, fabs(x[k]) + fabs(y[k]));
	double rnd = 1e-9 * (scale + 1.0), worst = 0.0;
	int bad_inside = 0, bad_gap = 0, bad_edge = 0, bad_convex = 0;
	for (int d = 0; d < 20000; ++d) {
		double t = 2.0 * MK_PI * d / 20000.0;
		mkVec2 u = {cos(t), sin(t)};
		double hk = ref_k2(s, i, part, o, u), hp = -INFINITY;
		for (int k = 0; k < n; ++k) {
			double v = u.x * x[k] + u.y * y[k];
			if (v > hp) hp = v;
			if (bound == MK_BOUND_INNER && v > hk + rnd) ++bad_inside;
		}
		double gap = bound == MK_BOUND_INNER ? hk - hp : hp - hk;
		if (gap > worst) worst = gap;
		if (gap > tol + rnd || gap > certified + rnd) ++bad_gap;
	}
	if (bound == MK_BOUND_OUTER) {
		for (int k = 0; k < n; ++k) {
			int j = (k + 1) % n, l = (k + 2) % n;
			mkVec2 e = {x[j] - x[k], y[j] - y[k]}, f = {x[l] - x[j], y[l] - y[j]};
			if (mkVec2_Cross(e, f) < -rnd * mkVec2_Length(e)) ++bad_convex;
			mkVec2 nu = mkVec2_Normalize(mkVec2_Make(e.y, -e.x));
			if (mkVec2_Length(e) == 0.0) continue;
			if (ref_k2(s, i, part, o, nu) > nu.x * x[k] + nu.y * y[k] + rnd) ++bad_edge;
		}
	} else {
		for (int k = 0; k < n; ++k) { /* counter-clockwise and convex */
			int j = (k + 1) % n, l = (k + 2) % n;
			mkVec2 e = {x[j] - x[k], y[j] - y[k]}, f = {x[l] - x[j], y[l] - y[j]};
			if (mkVec2_Cross(e, f) < -rnd * mkVec2_Length(e)) ++bad_convex;
		}
	}
	ENSURE(bad_inside == 0);
	ENSURE(bad_gap == 0);
	ENSURE(bad_edge == 0);
	ENSURE(bad_convex == 0);
	if (bad_inside || bad_gap || bad_edge || bad_convex)
		fprintf(stderr, "  obstacle %d orientation %d %s: inside %d gap %d (worst %g, tol %g, certified %g) edge %d convex %d\n",
			i, o, bound == MK_BOUND_INNER ? "inner" : "outer", bad_inside, bad_gap, worst, tol, certified, bad_edge, bad_convex);
	return worst;
}

static double referee3(const mkScene *s, int i, int part, int o, mkBound bound, const double *x, const double *y,
	const double *z, int n, const int *faces, int nf, double tol, double certified)
{
	double scale = 0.0;
	for (int k = 0; k < n; ++k) scale = fmax(scale, fabs(x[k]) + fabs(y[k]) + fabs(z[k]));
	double rnd = 1e-9 * (scale + 1.0), worst = 0.0;
	int bad_inside = 0, bad_gap = 0;
	const int D = 6000;
	for (int d = 0; d < D; ++d) { /* Fibonacci sphere */
		double zz = 1.0 - (2.0 * d + 1.0) / D, r = sqrt(1.0 - zz * zz), ph = d * 2.399963229728653;
		mkVec3 u = {r * cos(ph), r * sin(ph), zz};
		double hk = ref_k3(s, i, part, o, u), hp = -INFINITY;
		for (int k = 0; k < n; ++k) {
			double v = u.x * x[k] + u.y * y[k] + u.z * z[k];
			if (v > hp) hp = v;
			if (bound == MK_BOUND_INNER && v > hk + rnd) ++bad_inside;
		}
		double gap = bound == MK_BOUND_INNER ? hk - hp : hp - hk;
		if (gap > worst) worst = gap;
		if (gap > tol + rnd || gap > certified + rnd) ++bad_gap;
	}
	/* a closed surface: every directed edge (a, b) appears once and has its
	 * reverse (b, a) */
	int bad_closed = 0;
	unsigned long long *ek = malloc((size_t)(3 * nf + 1) * sizeof *ek);
	for (int f = 0; f < nf; ++f)
		for (int e = 0; e < 3; ++e)
			ek[3 * f + e] = (unsigned long long)faces[3 * f + e] << 32 | (unsigned)faces[3 * f + (e + 1) % 3];
	qsort(ek, (size_t)(3 * nf), sizeof *ek, cmp_u64);
	for (int e = 0; e < 3 * nf; ++e) {
		unsigned long long rev = (ek[e] & 0xffffffffULL) << 32 | ek[e] >> 32;
		if ((e > 0 && ek[e] == ek[e - 1]) || !bsearch(&rev, ek, (size_t)(3 * nf), sizeof *ek, cmp_u64)) ++bad_closed;
	}
	free(ek);
	/* inner: the faces are the convex hull's: no point lies above a face's
	 * plane (beyond rounding) */
	double fold = 0.0;
	if (bound == MK_BOUND_INNER)
		for (int f = 0; f < nf; ++f) {
			int a = faces[3 * f], b = faces[3 * f + 1], c = faces[3 * f + 2];
			mkVec3 pa = {x[a], y[a], z[a]}, pb = {x[b], y[b], z[b]}, pc = {x[c], y[c], z[c]};
			mkVec3 cr = mkVec3_Cross(mkVec3_Sub(pb, pa), mkVec3_Sub(pc, pa));
			/* slivers (area below 1e-6 of the square of the longest edge)
			 * carry no reliable plane */
			double l2 = fmax(fmax(mkVec3_Dot(mkVec3_Sub(pb, pa), mkVec3_Sub(pb, pa)),
				mkVec3_Dot(mkVec3_Sub(pc, pa), mkVec3_Sub(pc, pa))), mkVec3_Dot(mkVec3_Sub(pc, pb), mkVec3_Sub(pc, pb)));
			if (!(mkVec3_Length(cr) > 1e-6 * l2)) continue;
			mkVec3 nu = mkVec3_Normalize(cr);
			for (int k = 0; k < n; ++k)
				fold = fmax(fold, nu.x * (x[k] - pa.x) + nu.y * (y[k] - pa.y) + nu.z * (z[k] - pa.z));
		}
	ENSURE_LE(fold, rnd);
	if (fold > worst_fold) worst_fold = fold;
	/* outer: K lies behind the plane of every face (faces counter-clockwise
	 * from outside; slivers below 1e-12 of area carry no direction) */
	int bad_face = 0;
	if (bound == MK_BOUND_OUTER)
		for (int f = 0; f < nf; ++f) {
			int a = faces[3 * f], b = faces[3 * f + 1], c = faces[3 * f + 2];
			mkVec3 pa = {x[a], y[a], z[a]}, pb = {x[b], y[b], z[b]}, pc = {x[c], y[c], z[c]};
			mkVec3 cr = mkVec3_Cross(mkVec3_Sub(pb, pa), mkVec3_Sub(pc, pa));
			if (mkVec3_Length(cr) < 1e-12) continue;
			mkVec3 nu = mkVec3_Normalize(cr);
			if (ref_k3(s, i, part, o, nu) > mkVec3_Dot(nu, pa) + rnd) ++bad_face;
		}
	ENSURE(bad_inside == 0);
	ENSURE(bad_gap == 0);
	ENSURE(bad_closed == 0);
	ENSURE(bad_face == 0);
	if (bad_inside || bad_gap || bad_closed || bad_face)
		fprintf(stderr, "  3D obstacle %d orientation %d %s: inside %d gap %d (worst %g tol %g certified %g) closed %d face %d\n",
			i, o, bound == MK_BOUND_INNER ? "inner" : "outer", bad_inside, bad_gap, worst, tol, certified, bad_closed, bad_face);
	return worst;
}

/* ---- scenes ------------------------------------------------------------------------- */

/* The benchmark scenes (also in docs/scene.md). */
static const char *scene2_text =
	"# 2D benchmark: a boxy robot among smooth, boxy and modelled obstacles\n"
	"dim 2\n"
	"robot superellipse a=2 b=1 eps=0.3 at=100,100   # at is ignored\n"
	"obstacle circle a=3 at=10,0\n"
	"obstacle ellipse a=5 b=1 rot=0.4 at=-20,5\n"
	"obstacle superellipse a=4 b=2 eps=0.1 rot=0.2 at=0,30\n"
	"obstacle superellipse a=3 b=3 eps=1.8 at=40,-10\n"
	"obstacle box size=6,2 rot=0.3 at=-30,-30\n"
	"obstacle box size=1,8 shear=0.5 at=25,25\n"
	"headings 12\n";

static const char *scene3_text =
	"dim 3\n"
	"robot superquadric a=1 b=0.5 c=0.7 eps1=0.2 eps2=0.3\n"
	"obstacle sphere a=2 at=5,0,0\n"
	"obstacle ellipsoid a=3 b=1 c=2 quat=0.9,0.1,0.3,0.2\n"
	"obstacle superquadric a=2 b=1.5 c=1 eps1=0.1 eps2=0.1 at=0,-8,3\n"
	"obstacle box size=2,3,1 quat=1,0.2,0.1,0.4 at=-6,0,0\n"
	"obstacle cylinder r=1 h=3 quat=0.7,0.7,0,0 at=0,6,0\n"
	"quaternions 1,0,0,0; 0.9,0.3,0.2,0.1; 0.5,0.5,0.5,0.5\n";

static void test_scene_parse(void)
{
	mkScene s;
	char msg[1024];
	ENSURE(mkScene_Parse(scene2_text, &s, msg, sizeof msg) == MK_OK);
	ENSURE(s.dim == 2 && s.obstacle_count == 6 && s.orientation_count == 12);
	ENSURE(s.obstacles[4].kind == MK_SCENE_BOX && s.obstacles[4].size[0] == 6.0);
	ENSURE_NEAR(s.headings[3], 2.0 * MK_PI * 3 / 12, 1e-15);
	ENSURE(s.robot.spec.body2.t.x == 100.0); /* kept, and ignored by the computation */
	mkScene_Free(&s);
	ENSURE(mkScene_Parse(scene3_text, &s, msg, sizeof msg) == MK_OK);
	ENSURE(s.dim == 3 && s.obstacle_count == 5 && s.orientation_count == 3);
	ENSURE(s.obstacles[4].kind == MK_SCENE_CYLINDER && s.obstacles[4].size[0] == 1.0 && s.obstacles[4].size[1] == 3.0);
	mkScene_Free(&s);

	/* every error names the line, the field and the allowed range */
	static const struct { const char *text, *want; } bad[] = {
		{"dim 4\n", "line 1: dim = '4' is out of range: must be 2 or 3"},
		{"robot circle a=1\n", "line 1: the first line must be 'dim 2' or 'dim 3'"},
		{"dim 2\nrobot circle a=1\nobstacle blob a=1\nheadings 4\n", "line 3: obstacle0: unknown kind 'blob'"},
		{"dim 2\nrobot circle a=1\nobstacle circle a=1 zz=2\nheadings 4\n", "line 3: obstacle0: key 'zz' is not allowed"},
		{"dim 2\nrobot circle a=1\nobstacle box size=1,2 r=3\nheadings 4\n", "line 3: obstacle0: key 'r' is not allowed for box: allowed keys are size, rot, shear, M, at"},
		{"dim 2\nrobot circle a=1\nobstacle box rot=1\nheadings 4\n", "line 3: obstacle0: box needs size=l,w"},
		{"dim 2\nrobot circle a=1\nobstacle circle a=1\nobstacle box size=1,-2\nheadings 4\n", "line 4: obstacle1.size[2] = -2 is out of range: must be a finite number in [2e-09, 2000000000]"},
		{"dim 2\nrobot circle a=-1\nheadings 4\n", "line 2: robot.a = -1 is out of range"},
		{"dim 2\nrobot superellipse a=1 b=1 eps=2.5\nheadings 4\n", "line 2: robot.eps = 2.5 is out of range: must be a finite number in [1e-06, 1.999999]"},
		{"dim 2\nobstacle circle a=1\nheadings 4\n", "no robot"},
		{"dim 2\nrobot circle a=1\n", "no orientations"},
		{"dim 2\nrobot circle a=1\nheadings 0\n", "line 3: headings = '0' is out of range: must be an integer N in [1, 10000000]"},
		{"dim 2\nrobot circle a=1\nheadings 1,x\n", "line 3: headings: item 2 'x' is not a number"},
		{"dim 3\nrobot sphere a=1\nquaternions 0,0,0,0\n", "line 3: quaternions: item 1 = 0,0,0,0 is out of range"},
		{"dim 3\nrobot cylinder r=1\nquaternions 1,0,0,0\n", "line 2: robot: cylinder needs h"},
		{"dim 2\nrobot cylinder r=1 h=2\nheadings 3\n", "line 2: robot: kind 'cylinder' is 3D"},
		{"dim 2\nrobot circle a=1\nheading 3\n", "line 3: unknown keyword 'heading': must be one of dim, robot, part, object, obstacle, bounds, start, goal, headings"},
		{"dim 2\nrobot circle a=1\nrobot circle a=2\n", "line 3: robot: the robot is already given on line 2"},
		{"dim 2\npart circle a=1\nrobot circle a=2\n", "line 3: robot: the robot's parts are given (first on line 2)"},
		{"dim 2\nrobot circle a=1\npart circle a=2\n", "line 3: part: the robot is already given on line 2"},
		{"dim 2\npart circle a=1\npart box size=1,-2\n", "line 3: part1.size[2] = -2 is out of range"},
		{"dim 2\nrobot circle a=1\nobject t\nobject u\n", "line 4: object 't' (line 3) has no obstacle lines"},
		{"dim 2\nrobot circle a=1\nobject t\nheadings 3\n", "line 4: object 't' (line 3) has no obstacle lines"},
		{"dim 2\nrobot circle a=1\nobject a/b\n", "line 3: object name 'a/b' is not allowed"},
		{"dim 2\nrobot circle a=1\nobstacle circle a=1\nobject obstacle0\n", "line 4: object 'obstacle0' is the name of an obstacle of its own"},
	};
	for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
		msg[0] = 0;
		mkResult r = mkScene_Parse(bad[k].text, &s, msg, sizeof msg);
		ENSURE(r != MK_OK);
		ENSURE(s.obstacles == NULL && s.headings == NULL);
		if (!strstr(msg, bad[k].want)) {
			ENSURE(!"message");
			fprintf(stderr, "  got '%s'\n  want '%s'\n", msg, bad[k].want);
		}
	}
	/* rotations file: a header, matrices and a quaternion; a non-rotation fails */
	ENSURE(mkScene_Parse("dim 3\nrobot sphere a=1\nrotations so3.csv\n", &s, msg, sizeof msg) == MK_OK);
	ENSURE(strcmp(s.rotations_file, "so3.csv") == 0 && s.orientation_count == 0);
	ENSURE(mkScene_SetRotations(&s, "r11,r12,r13,r21,r22,r23,r31,r32,r33\n1,0,0,0,1,0,0,0,1\n0,-1,0,1,0,0,0,0,1\n1,0,0,0\n",
		"so3.csv", msg, sizeof msg) == MK_OK);
	ENSURE(s.orientation_count == 3 && s.rotations[1].m[0][1] == -1.0);
	ENSURE(mkScene_SetRotations(&s, "1,0,0,0,2,0,0,0,1\n", "so3.csv", msg, sizeof msg) == MK_ERR_RANGE);
	ENSURE(strstr(msg, "so3.csv:1: the matrix is not a rotation") != NULL);
	mkScene_Free(&s);
}

/* Box and cylinder models against the true support functions: the model's
 * deviation (inner: h_box - h_model, outer: h_model - h_box) lies in
 * [0, error] and error <= delta, over dense directions. */
static void test_models(void)
{
	static const char *bodies2[] = {"box size=4,1", "box size=2,2 rot=0.7 at=3,4", "box size=3,1 shear=1.5"};
	static const char *bodies3[] = {"box size=4,1,2", "box size=1,1,1 quat=0.9,0.2,0.3,0.1", "cylinder r=1 h=4",
		"cylinder r=2 h=0.5 quat=0.6,0.1,0.7,0.2", "cylinder r=1 h=1 M=1,0.5,0,0,1,0,0,0,2"};
	static const double deltas[] = {0.1, 1e-3};
	char msg[512];
	for (size_t bi = 0; bi < 3; ++bi)
		for (int di = 0; di < 2; ++di)
			for (int side = 0; side < 2; ++side) {
				mkSceneBody b;
				ENSURE(mkSceneBody_Parse(bodies2[bi], 2, "b", &b, msg, sizeof msg) == MK_OK);
				mkBody2 m;
				double err = -1;
				ENSURE(mkSceneBody2_Model(&b, deltas[di], (mkBound)side, &m, &err, msg, sizeof msg) == MK_OK);
				ENSURE(err <= deltas[di] && err > 0.0);
				double lo = INFINITY, hi = -INFINITY;
				mkSceneBody mb = b;
				mb.kind = MK_SCENE_SMOOTH;
				mb.spec.body2 = m;
				for (int d = 0; d < 20000; ++d) {
					mkVec2 u = {cos(2 * MK_PI * d / 20000.0), sin(2 * MK_PI * d / 20000.0)};
					double dev = ref_h2(&b, mkMat2_Identity(), 1, u) - ref_h2(&mb, mkMat2_Identity(), 1, u);
					if (side) dev = -dev;
					lo = fmin(lo, dev); hi = fmax(hi, dev);
				}
				ENSURE(lo >= -1e-12);
				ENSURE(hi <= err * (1 + 1e-9));
				/* the bound is the corner's deviation: tight for rigid maps */
				if (bi == 1 && side == 0) ENSURE(hi >= 0.9 * err); /* the square */
			}
	for (size_t bi = 0; bi < 5; ++bi)
		for (int di = 0; di < 2; ++di)
			for (int side = 0; side < 2; ++side) {
				mkSceneBody b;
				ENSURE(mkSceneBody_Parse(bodies3[bi], 3, "b", &b, msg, sizeof msg) == MK_OK);
				mkBody3 m;
				double err = -1;
				ENSURE(mkSceneBody3_Model(&b, deltas[di], (mkBound)side, &m, &err, msg, sizeof msg) == MK_OK);
				ENSURE(err <= deltas[di] && err > 0.0);
				mkSceneBody mb = b;
				mb.kind = MK_SCENE_SMOOTH;
				mb.spec.body3 = m;
				double lo = INFINITY, hi = -INFINITY;
				const int D = 20000;
				for (int d = 0; d < D; ++d) {
					double zz = 1.0 - (2.0 * d + 1.0) / D, r = sqrt(1.0 - zz * zz), ph = d * 2.399963229728653;
					mkVec3 u = {r * cos(ph), r * sin(ph), zz};
					double dev = ref_h3(&b, mkMat3_Identity(), 1, u) - ref_h3(&mb, mkMat3_Identity(), 1, u);
					if (side) dev = -dev;
					lo = fmin(lo, dev); hi = fmax(hi, dev);
				}
				ENSURE(lo >= -1e-12);
				ENSURE(hi <= err * (1 + 1e-9));
			}
	/* a tolerance too small for the exponent range is refused with a message */
	mkSceneBody b;
	mkBody2 m;
	double err;
	ENSURE(mkSceneBody_Parse("box size=1000,1000", 2, "b", &b, msg, sizeof msg) == MK_OK);
	ENSURE(mkSceneBody2_Model(&b, 1e-9, MK_BOUND_INNER, &m, &err, msg, sizeof msg) == MK_ERR_RANGE);
	ENSURE(strstr(msg, "too small") != NULL);
}

/* Prepare the scene, run orientations [begin, end), release the prepared scene. */
static mkResult run_scene(const mkScene *s, const mkCSpaceOptions *o, int begin, int end, mkCSpaceResult *r,
	char *msg, size_t msglen)
{
	mkCSpace *cs = NULL;
	mkResult rc = mkCSpace_Create(s, o, &cs, msg, msglen);
	if (rc == MK_OK) rc = mkCSpace_Run(cs, begin, end, r, msg, msglen);
	mkCSpace_Destroy(cs);
	return rc;
}

/* The boundaries of b, from its first orientation on, equal a's there (in
 * either's layout). */
static int results_equal(const mkCSpaceResult *a, const mkCSpaceResult *b)
{
	if (a->obstacles != b->obstacles || a->bounds != b->bounds || a->dim != b->dim) return 0;
	for (int o = b->orientation_begin; o < b->orientation_begin + b->orientations; ++o)
		for (int i = 0; i < a->obstacles; ++i)
			for (int k = 0; k < a->bounds; ++k) {
				mkCSpaceBoundary u = mkCSpaceResult_Boundary(a, o, i, (mkBound)k);
				mkCSpaceBoundary v = mkCSpaceResult_Boundary(b, o, i, (mkBound)k);
				if (u.count != v.count || memcmp(&u.error, &v.error, sizeof u.error)
					|| memcmp(&u.checksum, &v.checksum, sizeof u.checksum) || u.face_count != v.face_count)
					return 0;
				for (long j = 0; j < u.count; ++j)
					if (u.x[j * u.stride] != v.x[j * v.stride] || u.y[j * u.stride] != v.y[j * v.stride]
						|| (a->dim == 3 && u.z[j * u.stride] != v.z[j * v.stride]))
						return 0;
				if (u.face_count && memcmp(u.faces, v.faces, (size_t)u.face_count * 3 * sizeof(int))) return 0;
			}
	return 1;
}

static void test_scene2(void)
{
	mkScene s;
	char msg[1024];
	ENSURE(mkScene_Parse(scene2_text, &s, msg, sizeof msg) == MK_OK);
	static const double tols[] = {0.1, 0.003};
	for (int ti = 0; ti < 2; ++ti) {
		mkCSpaceOptions o = mkCSpaceOptions_Default();
		o.tol = tols[ti];
		o.outer = 1;
		mkCSpaceResult r1, r2;
		ENSURE(run_scene(&s, &o, 0, s.orientation_count, &r1, msg, sizeof msg) == MK_OK);
		o.threads = 2;
		ENSURE(run_scene(&s, &o, 0, s.orientation_count, &r2, msg, sizeof msg) == MK_OK);
		ENSURE(results_equal(&r1, &r2)); /* the thread count changes nothing */
		ENSURE(mkCSpaceResult_MaxError(&r1) <= o.tol);
		double worst = 0.0;
		long points = 0;
		for (int orel = 0; orel < r1.orientations; ++orel)
			for (int i = 0; i < r1.obstacles; ++i)
				for (int k = 0; k < 2; ++k) {
					mkCSpaceBoundary v = mkCSpaceResult_Boundary(&r1, orel, i, (mkBound)k);
					points += v.count;
					double w = referee2(&s, i, 0, orel, (mkBound)k, v.x, v.y, v.count, o.tol, v.error);
					worst = fmax(worst, w);
				}
		printf("2D scene, T = %g: %ld points in %d boundaries, certified max %.3g, referee's worst gap %.3g\n",
			o.tol, points, r1.obstacles * r1.orientations * 2, mkCSpaceResult_MaxError(&r1), worst);
		/* orientations in two pieces give the same boundaries (what --shard relies on) */
		mkCSpaceResult a, b;
		o.threads = 1;
		ENSURE(run_scene(&s, &o, 0, 5, &a, msg, sizeof msg) == MK_OK);
		ENSURE(run_scene(&s, &o, 5, s.orientation_count, &b, msg, sizeof msg) == MK_OK);
		ENSURE(results_equal(&r1, &a));
		ENSURE(results_equal(&r1, &b));
		mkCSpaceResult_Free(&a);
		mkCSpaceResult_Free(&b);
		/* the interleaved layout holds the same points; one prepared scene runs any range */
		o.interleaved = 1;
		mkCSpace *cs = NULL;
		ENSURE(mkCSpace_Create(&s, &o, &cs, msg, sizeof msg) == MK_OK);
		ENSURE(mkCSpace_Run(cs, 0, s.orientation_count, &a, msg, sizeof msg) == MK_OK);
		ENSURE(mkCSpace_Run(cs, 3, 7, &b, msg, sizeof msg) == MK_OK);
		ENSURE(a.interleaved && mkCSpaceResult_Boundary(&a, 0, 0, MK_BOUND_INNER).stride == 2);
		ENSURE(results_equal(&r1, &a));
		ENSURE(results_equal(&r1, &b));
		ENSURE(mkCSpaceResult_OverTolerance(&a) == 0);
		mkCSpace_Destroy(cs);
		mkCSpaceResult_Free(&a);
		mkCSpaceResult_Free(&b);
		mkCSpaceResult_Free(&r1);
		mkCSpaceResult_Free(&r2);
	}
	mkScene_Free(&s);
}

/* The smallest n for which certified(n) <= target, by doubling from 4 and
 * bisection (certified errors shrink with n, though not strictly: the
 * result is the first n found, for both samplings alike). Capped at 65536:
 * the count is then a lower bound, which only lowers the factor. */
typedef double (*CertFn)(const void *ctx, int n);
static int smallest_n(CertFn f, const void *ctx, double target)
{
	int lo = 3, hi = 4;
	while (f(ctx, hi) > target) {
		if (hi >= (1 << 16)) return hi; /* a lower bound: enough for the factor's floor */
		lo = hi;
		hi *= 2;
	}
	while (hi - lo > 1) {
		int mid = (lo + hi) / 2;
		if (f(ctx, mid) <= target) hi = mid; else lo = mid;
	}
	return hi;
}

typedef struct Pair { mkBody2 ob, rob; } Pair;

/* uniform normals 2 pi k / n */
static double cert_uniform(const void *ctx, int n)
{
	const Pair *p = ctx;
	double *x = NULL, *y = NULL, err = INFINITY;
	int cap = 0, cnt = 0;
	mkCSpace2_Uniform(p->ob, p->rob, MK_BOUND_INNER, n, MK_IMPL_AUTO, &x, &y, &cap, &cnt, &err);
	free(x); free(y);
	return err;
}

/* the paper's sampling: n uniform angles of the obstacle's surface parameter
 * (mkSample2_Angles), whose boundary points have the obstacle's normals
 * M^-T g(u); the same points, certified by the same bound */
static double cert_paper(const void *ctx, int n)
{
	const Pair *p = ctx;
	double *ux = malloc((size_t)n * sizeof *ux), *uy = malloc((size_t)n * sizeof *uy);
	double *nx = malloc((size_t)n * sizeof *nx), *ny = malloc((size_t)n * sizeof *ny);
	mkSample2_Angles(n, ux, uy);
	mkMat2 Mi = mkMat2_Inverse(p->ob.M);
	int flip = mkMat2_Det(p->ob.M) < 0.0;
	for (int k = 0; k < n; ++k) {
		mkVec2 g = mkMat2_MulTVec(Mi, mkShape2_PointGradient(p->ob.shape, mkVec2_Make(ux[k], uy[k])));
		int j = flip ? n - 1 - k : k;
		nx[j] = g.x; ny[j] = g.y;
	}
	double *x = NULL, *y = NULL, err = INFINITY;
	int cap = 0, cnt = 0;
	mkCSpace2_Certify(p->ob, p->rob, MK_BOUND_INNER, nx, ny, n, MK_IMPL_AUTO, &x, &y, &cap, &cnt, &err);
	free(x); free(y); free(ux); free(uy); free(nx); free(ny);
	return err;
}

/* Adaptive against uniform samplings at equal certified error: for each
 * boundary the smallest n of each sampling whose certified error is at most
 * the adaptive boundary's (all certified by the same bounds, the agreed
 * meaning of "equal certified error"). The uniform counts come from
 * mkCSpace2_Uniform / mkCSpace2_Certify, which certify fixed normals
 * and share nothing with the adaptive walk but the per-arc certificate; the
 * adaptive boundaries' certified errors are checked against the referee
 * first (an understated error would make the uniform target too tight, an
 * overstated one only lowers the factor). The bar held here: the adaptive
 * boundaries need at least 3x fewer points than uniform normals. */
static void test_points_factor2(void)
{
	mkScene s;
	char msg[1024];
	ENSURE(mkScene_Parse(scene2_text, &s, msg, sizeof msg) == MK_OK);
	mkCSpaceOptions o = mkCSpaceOptions_Default();
	o.tol = 0.01;
	mkCSpaceResult ad;
	ENSURE(run_scene(&s, &o, 0, s.orientation_count, &ad, msg, sizeof msg) == MK_OK);
	long pa = 0, pu = 0, pp = 0;
	double worst = 0.0;
	for (int orel = 0; orel < 3; ++orel) /* three headings keep the test fast */
		for (int i = 0; i < ad.obstacles; ++i) {
			long b = (long)orel * ad.obstacles + i;
			pa += ad.count[b];
			mkCSpaceBoundary v = mkCSpaceResult_Boundary(&ad, orel, i, MK_BOUND_INNER);
			worst = fmax(worst, referee2(&s, i, 0, orel, MK_BOUND_INNER, v.x, v.y, v.count, o.tol, v.error));
			Pair pr;
			double e1, e2;
			mkSceneBody2_Model(&s.obstacles[i], 0.25 * o.tol, MK_BOUND_INNER, &pr.ob, &e1, msg, sizeof msg);
			mkSceneBody2_Model(&s.robot, 0.25 * o.tol, MK_BOUND_INNER, &pr.rob, &e2, msg, sizeof msg);
			pr.rob.M = mkMat2_Mul(mkScene2_Orientation(&s, orel), pr.rob.M);
			double target = ad.error[b] - ad.model_error[b];
			pu += smallest_n(cert_uniform, &pr, target);
			pp += smallest_n(cert_paper, &pr, target);
		}
	printf("2D scene, T = %g, headings 0-2: adaptive %ld points (referee's worst gap %.4g); at equal certified error "
		"uniform normals need %ld (factor %.2f), the paper's surface sampling %ld (factor %.2f)\n",
		o.tol, pa, worst, pu, (double)pu / (double)pa, pp, (double)pp / (double)pa);
	ENSURE((double)pp >= 3.0 * (double)pa);
	ENSURE((double)pu >= 3.0 * (double)pa); /* measured 3.12 (1849 / 592) */
	mkCSpaceResult_Free(&ad);
	mkScene_Free(&s);
}

typedef struct Pair3 { mkBody3 ob, rob; } Pair3;

/* The paper's 3D sampling certified: the n x n grid of the obstacle's
 * surface angles (mkSample3_Grid; the pole rows are one point each), the
 * obstacle's normals M^-T g(u) there, the grid's quadrilaterals split into
 * triangles; returns the certified error, *points the distinct points. */
static double cert_paper3(const Pair3 *p, int n, int *points)
{
	int nu = n * n, nv = (n - 2) * n + 2;
	double *ux = malloc((size_t)nu * sizeof *ux), *uy = malloc((size_t)nu * sizeof *uy), *uz = malloc((size_t)nu * sizeof *uz);
	double *nx = malloc((size_t)nv * sizeof *nx), *ny = malloc((size_t)nv * sizeof *ny), *nz = malloc((size_t)nv * sizeof *nz);
	int *tri = malloc((size_t)nu * 6 * sizeof *tri), nt = 0;
	mkSample3_Grid(n, ux, uy, uz);
	mkMat3 Mi = mkMat3_Inverse(p->ob.M);
	int flip = mkMat3_Det(p->ob.M) < 0.0;
#define VID(i, j) ((i) == 0 ? 0 : (i) == n - 1 ? nv - 1 : 1 + ((i) - 1) * n + ((j) % n))
	for (int i = 0; i < n; ++i)
		for (int j = 0; j < n; ++j) {
			mkVec3 g = mkMat3_MulTVec(Mi, mkShape3_PointGradient(p->ob.shape, mkVec3_Make(ux[i * n + j], uy[i * n + j], uz[i * n + j])));
			int v = VID(i, j);
			nx[v] = g.x; ny[v] = g.y; nz[v] = g.z;
		}
	for (int i = 0; i + 1 < n; ++i)
		for (int j = 0; j < n; ++j) {
			int q[2][3] = {{VID(i, j), VID(i, j + 1), VID(i + 1, j + 1)}, {VID(i, j), VID(i + 1, j + 1), VID(i + 1, j)}};
			for (int k = 0; k < 2; ++k) {
				if (q[k][0] == q[k][1] || q[k][1] == q[k][2] || q[k][0] == q[k][2]) continue;
				tri[3 * nt] = q[k][0];
				tri[3 * nt + 1] = flip ? q[k][2] : q[k][1];
				tri[3 * nt + 2] = flip ? q[k][1] : q[k][2];
				++nt;
			}
		}
#undef VID
	double err = INFINITY;
	mkCSpace3_Certify(p->ob, p->rob, nx, ny, nz, nv, tri, nt, MK_IMPL_AUTO, &err);
	free(ux); free(uy); free(uz); free(nx); free(ny); free(nz); free(tri);
	*points = nv;
	return err;
}

static void test_scene3(void)
{
	mkScene s;
	char msg[1024];
	ENSURE(mkScene_Parse(scene3_text, &s, msg, sizeof msg) == MK_OK);
	mkCSpaceOptions o = mkCSpaceOptions_Default();
	o.tol = 0.05;
	o.outer = 1;
	mkCSpaceResult r1, r2;
	ENSURE(run_scene(&s, &o, 0, s.orientation_count, &r1, msg, sizeof msg) == MK_OK);
	o.threads = 2;
	ENSURE(run_scene(&s, &o, 0, s.orientation_count, &r2, msg, sizeof msg) == MK_OK);
	ENSURE(results_equal(&r1, &r2));
	ENSURE(mkCSpaceResult_MaxError(&r1) <= o.tol);
	double worst[2] = {0.0, 0.0};
	long points[2] = {0, 0};
	for (int orel = 0; orel < r1.orientations; ++orel)
		for (int i = 0; i < r1.obstacles; ++i)
			for (int k = 0; k < 2; ++k) {
				mkCSpaceBoundary v = mkCSpaceResult_Boundary(&r1, orel, i, (mkBound)k);
				points[k] += v.count;
				worst[k] = fmax(worst[k], referee3(&s, i, 0, orel, (mkBound)k, v.x, v.y, v.z, v.count, v.faces,
					v.face_count, o.tol, v.error));
			}
	printf("3D scene, T = %g: inner %ld points, outer %ld vertices in %d boundaries each, certified max %.3g, "
		"referee's worst gap inner %.3g, outer %.3g; largest fold of an inner surface %.3g\n", o.tol, points[0], points[1],
		r1.obstacles * r1.orientations, mkCSpaceResult_MaxError(&r1), worst[0], worst[1], worst_fold);
	mkCSpaceResult_Free(&r2);
	/* adaptive against uniform at equal certified error (inner, orientation
	 * 0): the fewest uniform splits of the octahedron whose certified error
	 * is at most the adaptive boundary's (the uniform counts grow 4x per
	 * split, so the factor is coarse) */
	long pa = 0, pu = 0, pp = 0;
	for (int i = 0; i < r1.obstacles; ++i) {
		long bi = (long)i * 2;
		pa += r1.count[bi];
		mkBody3 ob, rob;
		double e1, e2;
		mkSceneBody3_Model(&s.obstacles[i], 0.25 * o.tol, MK_BOUND_INNER, &ob, &e1, msg, sizeof msg);
		mkSceneBody3_Model(&s.robot, 0.25 * o.tol, MK_BOUND_INNER, &rob, &e2, msg, sizeof msg);
		rob.M = mkMat3_Mul(mkScene3_Orientation(&s, 0), rob.M);
		double target = r1.error[bi] - r1.model_error[bi];
		double *x = NULL, *y = NULL, *z = NULL, err = INFINITY;
		int cap = 0, n = 0;
		for (int sp = 0; sp <= 8; ++sp) {
			mkCSpace3_Uniform(ob, rob, MK_BOUND_INNER, sp, MK_IMPL_AUTO, &x, &y, &z, &cap, NULL, NULL, &n, NULL, &err);
			if (err <= target) break;
		}
		pu += n;
		free(x); free(y); free(z);
		/* the paper's grid: the smallest side n (doubling, then bisection) */
		Pair3 pr = {ob, rob};
		int lo = 3, hi = 4, pts = 0;
		while (cert_paper3(&pr, hi, &pts) > target && hi < 512) { lo = hi; hi *= 2; }
		while (hi - lo > 1) {
			int mid = (lo + hi) / 2;
			if (cert_paper3(&pr, mid, &pts) <= target) hi = mid; else lo = mid;
		}
		cert_paper3(&pr, hi, &pts);
		pp += pts;
	}
	printf("3D scene, T = %g, orientation 0: adaptive %ld points; at equal certified error uniform octahedron splits %ld "
		"(factor %.2f), the paper's surface grid %ld (factor %.2f; grid side capped at 512)\n", o.tol, pa, pu,
		(double)pu / (double)pa, pp, (double)pp / (double)pa);
	ENSURE((double)pp >= 3.0 * (double)pa);
	ENSURE(pu >= pa);
	mkCSpaceResult_Free(&r1);
	mkScene_Free(&s);
}

/* Single boundaries on hand-worked cases: the contact space of two circles
 * of radii 3 and 1 is the circle of radius 4; the inner polygon of n
 * uniform normals has gap 4 (1 - cos(pi/n)), the outer 4 (1/cos(pi/n) - 1). */
static void test_circles(void)
{
	mkBody2 c3 = mkBody2_Make((mkShape2){3, 3, 1}, mkMat2_Identity(), mkVec2_Make(1, 2));
	mkBody2 c1 = mkBody2_Make((mkShape2){1, 1, 1}, mkMat2_Identity(), mkVec2_Make(0, 0));
	double *x = NULL, *y = NULL, err;
	int cap = 0, n = 0;
	ENSURE(mkCSpace2_Uniform(c3, c1, MK_BOUND_INNER, 16, MK_IMPL_SCALAR, &x, &y, &cap, &n, &err) == MK_OK);
	ENSURE(n == 16);
	ENSURE_NEAR(err, 4 * (1 - cos(MK_PI / 16)), 1e-10);
	ENSURE_NEAR(hypot(x[5] - 1, y[5] - 2), 4.0, 1e-13);
	ENSURE(mkCSpace2_Uniform(c3, c1, MK_BOUND_OUTER, 16, MK_IMPL_SCALAR, &x, &y, &cap, &n, &err) == MK_OK);
	/* the certificate: distance to conv{x_i, x(m), x_j}, here the vertex's
	 * distance to the chord from x_i to x(m): 4 (1/cos(a) - cos(a)) ... at
	 * least the true 4 (1/cos(pi/16) - 1) */
	ENSURE(err >= 4 * (1 / cos(MK_PI / 16) - 1) - 1e-12);
	ENSURE_NEAR(hypot(x[0] - 1, y[0] - 2), 4.0 / cos(MK_PI / 16), 1e-12);
	/* adaptive: the uniform count a circle needs, within a factor */
	ENSURE(mkCSpace2_Adaptive(c3, c1, MK_BOUND_INNER, 1e-4, 1000000, MK_IMPL_AUTO, &x, &y, &cap, &n, &err) == MK_OK);
	ENSURE(err <= 1e-4);
	double nmin = MK_PI / acos(1 - 1e-4 / 4); /* fewest uniform normals with gap <= 1e-4 */
	ENSURE(n >= nmin && n <= 2.1 * nmin);
	/* a point cap below what the tolerance needs: at most that many points,
	 * and the reported error above tol and at least the polygon's true gap
	 * (radius 4 minus the least distance from the centre to an edge) */
	ENSURE(mkCSpace2_Adaptive(c3, c1, MK_BOUND_INNER, 1e-4, 8, MK_IMPL_AUTO, &x, &y, &cap, &n, &err) == MK_OK);
	ENSURE(n >= 4 && n <= 8);
	double gap = 0.0;
	for (int k = 0; k < n; ++k) {
		int j = (k + 1) % n;
		mkVec2 a = {x[k] - 1, y[k] - 2}, b = {x[j] - 1, y[j] - 2};
		ENSURE(mkVec2_Cross(a, b) > 0.0); /* counter-clockwise, steps below 180 degrees */
		gap = fmax(gap, 4.0 - fabs(mkVec2_Cross(a, b)) / mkVec2_Length(mkVec2_Sub(b, a)));
	}
	ENSURE(err > 1e-4 && err >= gap - 1e-12);
	free(x);
	free(y);
	/* 3D: two spheres, radius 4 */
	mkBody3 s3 = mkBody3_Make((mkShape3){3, 3, 3, 1, 1}, mkMat3_Identity(), mkVec3_Make(0, 0, 0));
	mkBody3 s1 = mkBody3_Make((mkShape3){1, 1, 1, 1, 1}, mkMat3_Identity(), mkVec3_Make(0, 0, 0));
	double *z = NULL;
	int *faces = NULL, fcap = 0, nf = 0;
	x = y = NULL;
	cap = 0;
	ENSURE(mkCSpace3_Uniform(s3, s1, MK_BOUND_INNER, 2, MK_IMPL_AUTO, &x, &y, &z, &cap, &faces, &fcap, &n, &nf, &err) == MK_OK);
	ENSURE(n == 66 && nf == 128); /* 4^2 * 8 triangles, 4 * 16 + 2 vertices */
	for (int k = 0; k < n; ++k) ENSURE_NEAR(sqrt(x[k] * x[k] + y[k] * y[k] + z[k] * z[k]), 4.0, 1e-13);
	/* the same octahedron normals through mkCSpace3_Certify: the same
	 * bound; the triangles reversed are no partition: +inf */
	double e2 = 0.0;
	int tri[8 * 3], t = 0;
	double ox[6] = {1, -1, 0, 0, 0, 0}, oy[6] = {0, 0, 1, -1, 0, 0}, oz[6] = {0, 0, 0, 0, 1, -1};
	for (int sg = 0; sg < 8; ++sg) {
		int a = (sg & 1) ? 1 : 0, b = (sg & 2) ? 3 : 2, c = (sg & 4) ? 5 : 4;
		int neg = ((sg & 1) != 0) + ((sg & 2) != 0) + ((sg & 4) != 0);
		tri[t++] = a; tri[t++] = neg % 2 ? c : b; tri[t++] = neg % 2 ? b : c;
	}
	ENSURE(mkCSpace3_Uniform(s3, s1, MK_BOUND_INNER, 0, MK_IMPL_AUTO, &x, &y, &z, &cap, NULL, NULL, &n, NULL, &err) == MK_OK);
	ENSURE(mkCSpace3_Certify(s3, s1, ox, oy, oz, 6, tri, 8, MK_IMPL_AUTO, &e2) == MK_OK);
	ENSURE_NEAR(e2, err, 1e-15);
	/* Proof 3 on an octant of the radius-4 sphere: c = 4 |e_i - e_j|^2 = 8,
	 * d0 = 1/sqrt(3): 8 sqrt(3) / 3, plus the rounding allowance */
	ENSURE_NEAR(err, 8.0 * sqrt(3.0) / 3.0, 1e-10);
	for (int k = 0; k < 8; ++k) { int tmp = tri[3 * k + 1]; tri[3 * k + 1] = tri[3 * k + 2]; tri[3 * k + 2] = tmp; }
	ENSURE(mkCSpace3_Certify(s3, s1, ox, oy, oz, 6, tri, 8, MK_IMPL_AUTO, &e2) == MK_OK);
	ENSURE(isinf(e2));
	free(x); free(y); free(z); free(faces);
}

/* Robots of several parts and objects: every part's C-obstacle passes the
 * referee's support-function checks for O (+) (-R M_j B_j) - R t_j, 1 and
 * 2 threads alike; the union's rows name the part and the object. */
static void test_unions(void)
{
	static const char *texts[2] = {
		"dim 2\npart box size=2,1 rot=0.2\npart ellipse a=0.6 b=0.3 rot=1 at=1.5,0.4\npart circle a=0.4 at=-1.2,-0.5\n"
		"object table\nobstacle box size=4,1 at=5,0\nobstacle circle a=0.3 at=4,2\nobject wall\n"
		"obstacle superellipse a=1 b=3 eps=0.2 at=-5,1\nheadings 5\n",
		"dim 3\npart box size=2,1,0.5\npart cylinder r=0.3 h=1 quat=0.9,0.3,0,0 at=1,0.5,0.2\n"
		"part superquadric a=0.5 b=0.4 c=0.3 eps1=0.3 eps2=0.6 at=-1,0,0.5\nobstacle sphere a=1 at=4,0,0\n"
		"object shelf\nobstacle box size=1,3,2 quat=1,0.1,0.2,0 at=0,-5,0\nobstacle ellipsoid a=2 b=1 c=1 at=0,0,5\n"
		"quaternions 1,0,0,0; 0.8,0.2,0.5,0.1\n"};
	for (int d = 0; d < 2; ++d) {
		mkScene s;
		char msg[1024];
		ENSURE(mkScene_Parse(texts[d], &s, msg, sizeof msg) == MK_OK);
		ENSURE(s.part_count == 3 && s.object_count == (d == 0 ? 2 : 2));
		ENSURE(strcmp(s.objects[s.obstacle_object[s.obstacle_count - 1]].name, d == 0 ? "wall" : "shelf") == 0);
		mkCSpaceOptions o = mkCSpaceOptions_Default();
		o.tol = d == 0 ? 0.01 : 0.1;
		o.outer = 1;
		mkCSpaceResult r1, r2;
		ENSURE(run_scene(&s, &o, 0, s.orientation_count, &r1, msg, sizeof msg) == MK_OK);
		o.threads = 2;
		ENSURE(run_scene(&s, &o, 0, s.orientation_count, &r2, msg, sizeof msg) == MK_OK);
		ENSURE(r1.parts == 3 && results_equal(&r1, &r2));
		ENSURE(mkCSpaceResult_MaxError(&r1) <= o.tol);
		double worst = 0.0;
		for (int ori = 0; ori < r1.orientations; ++ori)
			for (int i = 0; i < r1.obstacles; ++i)
				for (int j = 0; j < r1.parts; ++j)
					for (int k = 0; k < 2; ++k) {
						mkCSpaceBoundary v = mkCSpaceResult_PartBoundary(&r1, ori, i, j, (mkBound)k);
						ENSURE(mkCSpaceResult_PartBoundary(&r2, ori, i, j, (mkBound)k).checksum == v.checksum);
						worst = fmax(worst, d == 0 ? referee2(&s, i, j, ori, (mkBound)k, v.x, v.y, v.count, o.tol, v.error)
							: referee3(&s, i, j, ori, (mkBound)k, v.x, v.y, v.z, v.count, v.faces, v.face_count, o.tol,
								v.error));
					}
		printf("%dD robot of 3 parts, T = %g: referee's worst gap %.3g, certified max %.3g\n", d + 2, o.tol, worst,
			mkCSpaceResult_MaxError(&r1));
		mkCSpaceResult_Free(&r1);
		mkCSpaceResult_Free(&r2);
		mkScene_Free(&s);
	}
}

int main(void)
{
	test_scene_parse();
	test_models();
	test_circles();
	test_scene2();
	test_points_factor2();
	test_scene3();
	test_unions();
	return mk_summary("test_cspace");
}
