/* jacobi.c - cyclic Jacobi method for symmetric 3x3 matrices. */
#include "jacobi.h"

#include <math.h>

enum { JACOBI_MAX_SWEEPS = 50 };

int mkSym3_Eigen(mkMat3 a, double w[3], mkMat3 *v)
{
	double s[3][3];
	for (int i = 0; i < 3; ++i) {
		for (int j = 0; j < 3; ++j) {
			/* mirror the upper triangle so the input need not be exact */
			s[i][j] = i <= j ? a.m[i][j] : a.m[j][i];
			if (!isfinite(s[i][j])) {
				for (int k = 0; k < 3; ++k) {
					w[k] = NAN;
				}
				for (int r = 0; r < 3; ++r) {
					for (int c = 0; c < 3; ++c) {
						v->m[r][c] = NAN;
					}
				}
				return -1;
			}
		}
	}
	mkMat3 q = { { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } } };

	int sweep = 0;
	for (; sweep < JACOBI_MAX_SWEEPS; ++sweep) {
		double off = fabs(s[0][1]) + fabs(s[0][2]) + fabs(s[1][2]);
		double diag = fabs(s[0][0]) + fabs(s[1][1]) + fabs(s[2][2]);
		/* Converged when the off-diagonal part no longer changes the
		 * diagonal in double precision (also covers the zero matrix). */
		if (off == 0.0 || diag + off == diag) {
			break;
		}
		for (int p = 0; p < 2; ++p) {
			for (int r = p + 1; r < 3; ++r) {
				double apr = s[p][r];
				if (apr == 0.0) {
					continue;
				}
				/* Rotation that zeroes s[p][r] (Golub & Van Loan, sym.schur2),
				 * with t the smaller root for stability. */
				double theta = (s[r][r] - s[p][p]) / (2.0 * apr);
				double t = (theta >= 0.0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
				double c = 1.0 / sqrt(t * t + 1.0);
				double sn = t * c;
				for (int k = 0; k < 3; ++k) {
					double skp = s[k][p], skr = s[k][r];
					s[k][p] = c * skp - sn * skr;
					s[k][r] = sn * skp + c * skr;
				}
				for (int k = 0; k < 3; ++k) {
					double spk = s[p][k], srk = s[r][k];
					s[p][k] = c * spk - sn * srk;
					s[r][k] = sn * spk + c * srk;
				}
				for (int k = 0; k < 3; ++k) {
					double qkp = q.m[k][p], qkr = q.m[k][r];
					q.m[k][p] = c * qkp - sn * qkr;
					q.m[k][r] = sn * qkp + c * qkr;
				}
			}
		}
	}
	if (sweep == JACOBI_MAX_SWEEPS) {
		for (int k = 0; k < 3; ++k) {
			w[k] = NAN;
			for (int r = 0; r < 3; ++r) {
				v->m[r][k] = NAN;
			}
		}
		return -1;
	}

	/* Sort ascending, carrying the eigenvector columns along. */
	int idx[3] = { 0, 1, 2 };
	for (int i = 0; i < 2; ++i) {
		for (int j = i + 1; j < 3; ++j) {
			if (s[idx[j]][idx[j]] < s[idx[i]][idx[i]]) {
				int tmp = idx[i];
				idx[i] = idx[j];
				idx[j] = tmp;
			}
		}
	}
	for (int c = 0; c < 3; ++c) {
		w[c] = s[idx[c]][idx[c]];
		for (int r = 0; r < 3; ++r) {
			v->m[r][c] = q.m[r][idx[c]];
		}
	}
	/* A product of rotations has det +1; a column swap may flip it. Flip
	 * the middle axis then, as the reference code does. */
	double det = v->m[0][0] * (v->m[1][1] * v->m[2][2] - v->m[1][2] * v->m[2][1])
		- v->m[0][1] * (v->m[1][0] * v->m[2][2] - v->m[1][2] * v->m[2][0])
		+ v->m[0][2] * (v->m[1][0] * v->m[2][1] - v->m[1][1] * v->m[2][0]);
	if (det < 0.0) {
		for (int r = 0; r < 3; ++r) {
			v->m[r][1] = -v->m[r][1];
		}
	}
	return sweep;
}
