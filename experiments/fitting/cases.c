/* cases.c - the trials of the fitting experiment. */
#include "cases.h"
#include "hull.h"
#include "sqfit.h"

#include <math.h>
#include <stdlib.h>

#include <mink/sum.h>
#include <mink_exp/rng.h>

enum { CASE1_POINTS = 100, CYLINDER_RING = 30, ELLIPSOID_GRID = 9 };


uint64_t mkFitStream(int caseId, int level, int trial)
{
	return ((uint64_t)(unsigned)caseId << 48) | ((uint64_t)(unsigned)(level & 0xffff) << 32)
		| (uint64_t)(unsigned)trial;
}

static mkFitRow blankRow(int caseId, int trial)
{
	mkFitRow r;
	r.caseId = caseId;
	r.trial = trial;
	r.truth = "";
	r.model = "";
	r.sampling = "none";
	r.level = 0;
	r.vertices = 0;
	r.volumeTrue = NAN;
	r.volumeModel = NAN;
	r.eVolume = NAN;
	r.eImplicit = NAN;
	r.shape = (mkShape3){ NAN, NAN, NAN, NAN, NAN };
	for (int i = 0; i < 4; ++i) {
		r.q[i] = NAN;
	}
	r.t = (mkVec3){ NAN, NAN, NAN };
	for (int i = 0; i < 3; ++i) {
		r.size[i] = NAN;
	}
	r.cost = NAN;
	r.iterations = 0;
	r.nfev = 0;
	r.status = "ok";
	return r;
}

static double relError(double model, double truth)
{
	return fabs(model - truth) / truth;
}

static const char *hullStatus(mkResult r)
{
	return r == MK_ERR_MEMORY ? "out-of-memory" : "hull-failed";
}

/* The row's model: the hull of the n x n grid of b (the published code's
 * grid when paper); its volume error against vTrue. Returns -1 when memory
 * runs out, else 0 (a failed hull is the row's status). */
static int gridHullRow(mkFitRow *r, mkBody3 b, int n, int paper, double vTrue)
{
	double v;
	mkResult hr = mkFitGridHullVolume(b, n, paper, &v, &r->vertices, &r->eImplicit);
	if (hr != MK_OK) {
		r->status = hullStatus(hr);
		return hr == MK_ERR_MEMORY ? -1 : 0;
	}
	r->volumeModel = v;
	r->eVolume = relError(v, vTrue);
	return 0;
}

/* ---- case 1 ----------------------------------------------------------------- */

int mkFitCase1_Trial(uint64_t seed, int trial, mkFitRow *rows)
{
	mkRng rng;
	mkRng_Seed(&rng, seed, mkFitStream(1, 0, trial));
	double x[CASE1_POINTS], y[CASE1_POINTS], z[CASE1_POINTS];
	int isVertex[CASE1_POINTS];
	/* the published draw: 3 x N matrix, column by column */
	for (int k = 0; k < CASE1_POINTS; ++k) {
		x[k] = 20.0 * mkRng_Uniform(&rng, -1.0, 1.0);
		y[k] = 15.0 * mkRng_Uniform(&rng, -1.0, 1.0);
		z[k] = 10.0 * mkRng_Uniform(&rng, -1.0, 1.0);
	}

	mkFitRow *r = &rows[0];
	*r = blankRow(1, trial);
	r->truth = "polyhedron";
	r->model = "superquadric";
	r->sampling = "random";
	r->level = CASE1_POINTS;

	double vTrue;
	int nv;
	mkResult hr = mkHull3_Volume(x, y, z, CASE1_POINTS, &vTrue, &nv, isVertex);
	if (hr != MK_OK) {
		r->status = hullStatus(hr);
		return 1;
	}
	r->vertices = nv;
	r->volumeTrue = vTrue;

	/* the polyhedron handed to the fit is its vertex set */
	double vx[CASE1_POINTS], vy[CASE1_POINTS], vz[CASE1_POINTS];
	int m = 0;
	for (int k = 0; k < CASE1_POINTS; ++k) {
		if (isVertex[k]) {
			vx[m] = x[k];
			vy[m] = y[k];
			vz[m] = z[k];
			++m;
		}
	}

	mkSqFit start, fit;
	mkResult sr = mkSqFit_Start(vx, vy, vz, m, &start);
	if (sr != MK_OK) {
		r->status = "start-failed";
		return 1;
	}
	mkResult fr = mkSqFit_Run(vx, vy, vz, m, &start, &fit);
	if (fr != MK_OK) {
		r->status = fr == MK_ERR_MEMORY ? "out-of-memory" : "too-few-vertices";
		return fr == MK_ERR_MEMORY ? -1 : 1;
	}
	r->shape = fit.shape;
	for (int i = 0; i < 4; ++i) {
		r->q[i] = fit.q[i];
	}
	r->t = fit.t;
	r->cost = fit.cost;
	r->iterations = fit.iterations;
	r->nfev = fit.nfev;
	r->status = mkSqFit_StatusName(fit.info);
	if (!mkShape3_IsValid(fit.shape, "fit", NULL, 0)) {
		/* the exponents are kept valid by construction; only an axis
		 * driven outside the core's range can land here */
		r->status = "invalid-fit";
		return 1;
	}
	r->volumeModel = mkShape3_Volume(fit.shape);
	r->eVolume = relError(r->volumeModel, vTrue);
	r->eImplicit = mkSqFit_ImplicitError(&fit, vx, vy, vz, m);
	return 1;
}

/* ---- case 2 ----------------------------------------------------------------- */

void mkFitSample3_PaperGrid(int n, double *ux, double *uy, double *uz)
{
	/* eta = -pi/2 : pi/(n-1) : pi/2 and omega = -pi-1e-6 : 2pi/(n-1) : pi+1e-6,
	 * the published code's meshgrid; both ranges hold exactly n values. */
	for (int i = 0; i < n; ++i) {
		double eta = -MK_PI / 2.0 + MK_PI * i / (n - 1);
		for (int j = 0; j < n; ++j) {
			double omega = -MK_PI - 1e-6 + 2.0 * MK_PI * j / (n - 1);
			ux[i * n + j] = cos(eta) * cos(omega);
			uy[i * n + j] = cos(eta) * sin(omega);
			uz[i * n + j] = sin(eta);
		}
	}
}

mkResult mkFitGridHullVolume(mkBody3 b, int n, int paperGrid, double *volume, int *vertices,
	double *eImplicit)
{
	int count = n * n;
	double *buf = malloc(sizeof(double) * 6 * (size_t)count);
	if (buf == NULL) {
		return MK_ERR_MEMORY;
	}
	double *ux = buf, *uy = ux + count, *uz = uy + count;
	double *px = uz + count, *py = px + count, *pz = py + count;
	if (paperGrid) {
		mkFitSample3_PaperGrid(n, ux, uy, uz);
	} else {
		mkSample3_Grid(n, ux, uy, uz);
	}
	/* Psi = N^(2/eps1) through the scaled gauge: with exponents 2/eps2 in
	 * the hundreds, the plain sum of powers would underflow */
	mkMat3 Mi = mkMat3_Inverse(b.M);
	double sum = 0.0;
	for (int k = 0; k < count; ++k) {
		mkVec3 p = mkBody3_Point(b, (mkVec3){ ux[k], uy[k], uz[k] });
		px[k] = p.x;
		py[k] = p.y;
		pz[k] = p.z;
		mkVec3 local = mkMat3_MulVec(Mi, (mkVec3){ p.x - b.t.x, p.y - b.t.y, p.z - b.t.z });
		sum += fabs(pow(mkSq_Gauge(b.shape, local), 2.0 / b.shape.eps1) - 1.0);
	}
	*eImplicit = sum / count;
	mkResult hr = mkHull3_Volume(px, py, pz, count, volume, vertices, NULL);
	free(buf);
	return hr;
}

/* U(lo, hi) raised into [min, max]; *clamped set when that moved it. */
static double drawIn(mkRng *rng, double lo, double hi, double min, double max, int *clamped)
{
	double v = mkRng_Uniform(rng, lo, hi);
	if (v < min || v > max) {
		*clamped = 1;
		v = v < min ? min : max;
	}
	return v;
}

int mkFitCase2_Trial(uint64_t seed, int trial, mkFitRow *rows)
{
	int count = 0;
	for (int n = MK_FIT_CASE2_NMIN; n <= MK_FIT_CASE2_NMAX; ++n) {
		/* a fresh superquadric for every level, as in the published loop */
		mkRng rng;
		mkRng_Seed(&rng, seed, mkFitStream(2, n, trial));
		int clamped = 0;
		mkShape3 s;
		/* a ~ [20,15,10] .* U(0,1), eps ~ U(0,2): draws outside the core's
		 * valid range (a < 1e-9, eps < 1e-6 or > 2 - 1e-6; chance about
		 * 1e-6 per exponent) are moved to its edge and flagged */
		s.a = drawIn(&rng, 0.0, 20.0, MK_AXIS_MIN, MK_AXIS_MAX, &clamped);
		s.b = drawIn(&rng, 0.0, 15.0, MK_AXIS_MIN, MK_AXIS_MAX, &clamped);
		s.c = drawIn(&rng, 0.0, 10.0, MK_AXIS_MIN, MK_AXIS_MAX, &clamped);
		s.eps1 = drawIn(&rng, 0.0, 2.0, MK_EPS_MIN, MK_EPS_MAX, &clamped);
		s.eps2 = drawIn(&rng, 0.0, 2.0, MK_EPS_MIN, MK_EPS_MAX, &clamped);
		double q[4];
		for (int i = 0; i < 4; ++i) {
			q[i] = mkRng_Unit(&rng); /* the published rand(1,4) quaternion */
		}
		mkMat3 R = mkSq_QuatToMat(q);
		mkBody3 b = mkBody3_Make(s, R, (mkVec3){ 0.0, 0.0, 0.0 });
		double vTrue = mkShape3_Volume(s);
		double qn[4];
		mkSq_MatToQuat(R, qn);

		for (int paper = 1; paper >= 0; --paper) {
			mkFitRow *r = &rows[count++];
			*r = blankRow(2, trial);
			r->truth = "superquadric";
			r->model = "polyhedron";
			r->sampling = paper ? "paper" : "distinct";
			r->level = n * n;
			r->shape = s;
			for (int i = 0; i < 4; ++i) {
				r->q[i] = qn[i];
			}
			r->t = b.t;
			r->volumeTrue = vTrue;
			r->status = clamped ? "clamped" : "ok";
			if (gridHullRow(r, b, n, paper, vTrue) != 0) {
				return -1;
			}
		}
	}
	return count;
}

/* ---- case 3 ----------------------------------------------------------------- */

static void drawSize(uint64_t seed, int primitive, int trial, double size[3])
{
	mkRng rng;
	mkRng_Seed(&rng, seed, mkFitStream(3, primitive, trial));
	size[0] = 50.0 * mkRng_Unit(&rng) + 1.0;
	size[1] = 36.0 * mkRng_Unit(&rng) + 1.0;
	size[2] = 20.0 * mkRng_Unit(&rng) + 1.0;
}

static void setIdentityPose(mkFitRow *r)
{
	r->q[0] = 1.0;
	r->q[1] = r->q[2] = r->q[3] = 0.0;
	r->t = (mkVec3){ 0.0, 0.0, 0.0 };
}

static mkFitRow primitiveRow(int trial, const char *truth, const double size[3], double vTrue)
{
	mkFitRow r = blankRow(3, trial);
	r.truth = truth;
	for (int i = 0; i < 3; ++i) {
		r.size[i] = size[i];
	}
	r.volumeTrue = vTrue;
	return r;
}

static void superquadricModel(mkFitRow *r, mkShape3 s)
{
	r->model = "superquadric";
	r->sampling = "none";
	r->shape = s;
	setIdentityPose(r);
	r->volumeModel = mkShape3_Volume(s);
	r->eVolume = relError(r->volumeModel, r->volumeTrue);
}

static int hullModel(mkFitRow *r, const char *sampling, const double *x, const double *y,
	const double *z, int n)
{
	r->model = "polyhedron";
	r->sampling = sampling;
	r->level = n;
	double v;
	mkResult hr = mkHull3_Volume(x, y, z, n, &v, &r->vertices, NULL);
	if (hr != MK_OK) {
		r->status = hullStatus(hr);
		return hr == MK_ERR_MEMORY ? -1 : 0;
	}
	r->volumeModel = v;
	r->eVolume = relError(v, r->volumeTrue);
	return 0;
}

int mkFitCase3_Trial(uint64_t seed, int trial, mkFitRow *rows)
{
	int count = 0;
	double size[3];

	/* cube of edges size: superquadric a = size/2, eps = (0.1, 0.1);
	 * polyhedron of its 8 corners (exact up to rounding) */
	drawSize(seed, 1, trial, size);
	double vCube = size[0] * size[1] * size[2];
	mkFitRow *r = &rows[count++];
	*r = primitiveRow(trial, "cube", size, vCube);
	superquadricModel(r, (mkShape3){ size[0] / 2, size[1] / 2, size[2] / 2, 0.1, 0.1 });
	{
		double x[8], y[8], z[8];
		for (int k = 0; k < 8; ++k) {
			x[k] = (k & 1 ? 0.5 : -0.5) * size[0];
			y[k] = (k & 2 ? 0.5 : -0.5) * size[1];
			z[k] = (k & 4 ? 0.5 : -0.5) * size[2];
		}
		r = &rows[count++];
		*r = primitiveRow(trial, "cube", size, vCube);
		if (hullModel(r, "corners", x, y, z, 8) < 0) {
			return -1;
		}
	}

	/* ellipsoid of semi-axes size: the superquadric eps = (1,1) is exact;
	 * polyhedra from 9 x 9 grids of both samplings */
	drawSize(seed, 2, trial, size);
	double vEll = 4.0 / 3.0 * MK_PI * size[0] * size[1] * size[2];
	mkShape3 ell = { size[0], size[1], size[2], 1.0, 1.0 };
	r = &rows[count++];
	*r = primitiveRow(trial, "ellipsoid", size, vEll);
	superquadricModel(r, ell);
	for (int paper = 1; paper >= 0; --paper) {
		r = &rows[count++];
		*r = primitiveRow(trial, "ellipsoid", size, vEll);
		r->model = "polyhedron";
		r->sampling = paper ? "paper" : "distinct";
		r->level = ELLIPSOID_GRID * ELLIPSOID_GRID;
		r->shape = ell;
		setIdentityPose(r);
		if (gridHullRow(r, mkBody3_Make(ell, mkMat3_Identity(), r->t), ELLIPSOID_GRID, paper, vEll) != 0) {
			return -1;
		}
	}

	/* elliptic cylinder, cross-section semi-axes size_x, size_y, height
	 * size_z: superquadric (size_x, size_y, size_z/2), eps = (0.1, 1);
	 * polyhedra of two rings of 30 points at z = +-size_z/2 */
	drawSize(seed, 3, trial, size);
	double vCyl = MK_PI * size[0] * size[1] * size[2];
	r = &rows[count++];
	*r = primitiveRow(trial, "cylinder", size, vCyl);
	superquadricModel(r, (mkShape3){ size[0], size[1], size[2] / 2, 0.1, 1.0 });
	for (int paper = 1; paper >= 0; --paper) {
		double x[2 * CYLINDER_RING], y[2 * CYLINDER_RING], z[2 * CYLINDER_RING];
		for (int j = 0; j < CYLINDER_RING; ++j) {
			/* paper: -pi : 2pi/29 : pi, its ends coinciding; distinct:
			 * 30 angles 2pi/30 apart */
			double th = paper ? -MK_PI + 2.0 * MK_PI * j / (CYLINDER_RING - 1)
				: -MK_PI + 2.0 * MK_PI * j / CYLINDER_RING;
			for (int ring = 0; ring < 2; ++ring) {
				int k = ring * CYLINDER_RING + j;
				x[k] = size[0] * cos(th);
				y[k] = size[1] * sin(th);
				z[k] = (ring ? 0.5 : -0.5) * size[2];
			}
		}
		r = &rows[count++];
		*r = primitiveRow(trial, "cylinder", size, vCyl);
		if (hullModel(r, paper ? "paper" : "distinct", x, y, z, 2 * CYLINDER_RING) < 0) {
			return -1;
		}
	}
	return count;
}
