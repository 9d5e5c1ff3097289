/* test_jacobi.c - the symmetric 3x3 eigen-solver against matrices built
 * from known eigen-decompositions. */
#include "ensure.h"
#include "jacobi.h"

static mkMat3 rotationXYZ(double ax, double ay, double az)
{
	double cx = cos(ax), sx = sin(ax), cy = cos(ay), sy = sin(ay), cz = cos(az), sz = sin(az);
	mkMat3 r = { { { cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx },
		{ sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx },
		{ -sy, cy * sx, cy * cx } } };
	return r;
}

/* Q diag(l) Q^T */
static mkMat3 compose(mkMat3 q, const double l[3])
{
	mkMat3 a;
	for (int i = 0; i < 3; ++i) {
		for (int j = 0; j < 3; ++j) {
			a.m[i][j] = 0.0;
			for (int k = 0; k < 3; ++k) {
				a.m[i][j] += q.m[i][k] * l[k] * q.m[j][k];
			}
		}
	}
	return a;
}

static double det3(mkMat3 v)
{
	return v.m[0][0] * (v.m[1][1] * v.m[2][2] - v.m[1][2] * v.m[2][1])
		- v.m[0][1] * (v.m[1][0] * v.m[2][2] - v.m[1][2] * v.m[2][0])
		+ v.m[0][2] * (v.m[1][0] * v.m[2][1] - v.m[1][1] * v.m[2][0]);
}

/* max over columns of |A v - w v| / max|w|, and of |V^T V - I| */
static void residuals(mkMat3 a, const double w[3], mkMat3 v, double *eig, double *orth)
{
	double scale = fmax(fabs(w[0]), fmax(fabs(w[1]), fabs(w[2])));
	*eig = 0.0;
	*orth = 0.0;
	for (int c = 0; c < 3; ++c) {
		for (int r = 0; r < 3; ++r) {
			double av = a.m[r][0] * v.m[0][c] + a.m[r][1] * v.m[1][c] + a.m[r][2] * v.m[2][c];
			*eig = fmax(*eig, fabs(av - w[c] * v.m[r][c]) / scale);
			double vtv = v.m[0][r] * v.m[0][c] + v.m[1][r] * v.m[1][c] + v.m[2][r] * v.m[2][c];
			*orth = fmax(*orth, fabs(vtv - (r == c ? 1.0 : 0.0)));
		}
	}
}

/* R diag(l) R^T: eigenvalues `sorted` (ascending) within slack * tol, an
 * orthonormal right-handed eigenbasis within tol. */
static void checkEigen(mkMat3 R, const double *l, const double *sorted, double tol, double slack)
{
	mkMat3 a = compose(R, l);
	double w[3], e, o;
	mkMat3 v;
	ENSURE(mkSym3_Eigen(a, w, &v) >= 0);
	for (int k = 0; k < 3; ++k)
		ENSURE_NEAR(w[k], sorted[k], tol * slack);
	residuals(a, w, v, &e, &o);
	ENSURE(e < tol);
	ENSURE(o < tol);
	ENSURE_NEAR(det3(v), 1.0, tol);
}

int main(void)
{
	/* Jacobi is backward stable: eigenvalues within a few ulps of the
	 * largest one, eigenvectors orthonormal to a few ulps. 1e-14 leaves a
	 * factor of ~50 over double's 2.2e-16. */
	const double tol = 1e-14;

	/* distinct eigenvalues, given in scrambled order */
	checkEigen(rotationXYZ(0.3, -1.1, 2.5), (const double[3]){ 3.0, -1.5, 0.25 },
		(const double[3]){ -1.5, 0.25, 3.0 }, tol, 3.0);
	/* a double eigenvalue: any orthonormal basis of its plane will do */
	checkEigen(rotationXYZ(-0.7, 0.4, 0.1), (const double[3]){ 2.0, 2.0, 5.0 },
		(const double[3]){ 2.0, 2.0, 5.0 }, tol, 5.0);

	/* widely spread scales, as a scatter matrix of a flat cloud gives:
	 * the small eigenvalue is only determined to ~ulp(largest) = 2e-16 * 1e6 */
	{
		const double l[3] = { 1e6, 1.0, 1e-3 };
		mkMat3 a = compose(rotationXYZ(1.2, 0.9, -0.4), l);
		double w[3], e, o;
		mkMat3 v;
		ENSURE(mkSym3_Eigen(a, w, &v) >= 0);
		ENSURE_NEAR(w[0], 1e-3, 1e6 * tol);
		ENSURE_NEAR(w[1], 1.0, 1e6 * tol);
		ENSURE_REL(w[2], 1e6, tol);
		residuals(a, w, v, &e, &o);
		ENSURE(e < tol);
		ENSURE(o < tol);
	}

	/* already diagonal (no sweep needed), a negative-determinant ordering,
	 * and the zero matrix */
	{
		mkMat3 a = { { { 4, 0, 0 }, { 0, 1, 0 }, { 0, 0, 9 } } };
		double w[3];
		mkMat3 v;
		ENSURE(mkSym3_Eigen(a, w, &v) == 0);
		ENSURE(w[0] == 1 && w[1] == 4 && w[2] == 9);
		ENSURE_NEAR(det3(v), 1.0, 0.0);
		ENSURE(fabs(v.m[1][0]) == 1 && fabs(v.m[0][1]) == 1 && fabs(v.m[2][2]) == 1);
		mkMat3 zero = { { { 0 } } };
		ENSURE(mkSym3_Eigen(zero, w, &v) == 0);
		ENSURE(w[0] == 0 && w[1] == 0 && w[2] == 0);
	}

	/* only the upper triangle is read */
	{
		mkMat3 a = { { { 2, 1, 0 }, { 99, 2, 0 }, { 99, 99, 7 } } };
		double w[3];
		mkMat3 v;
		ENSURE(mkSym3_Eigen(a, w, &v) >= 0);
		ENSURE_NEAR(w[0], 1.0, tol * 7);
		ENSURE_NEAR(w[1], 3.0, tol * 7);
		ENSURE_NEAR(w[2], 7.0, tol * 7);
	}

	/* non-finite input fails */
	{
		mkMat3 a = { { { 1, NAN, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } };
		double w[3];
		mkMat3 v;
		ENSURE(mkSym3_Eigen(a, w, &v) == -1);
		ENSURE(isnan(w[0]) && isnan(v.m[0][0]));
	}
	return mk_summary("fitting.test_jacobi");
}
