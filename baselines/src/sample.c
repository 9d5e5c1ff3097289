/* sample.c - the boundary samples and pairwise sums every sampled method
 * starts from (mink/baselines.h). One definition, so that the referee can
 * rebuild a method's input bit for bit. */
#include <stdlib.h>

#include <mink/baselines.h>

mkResult mkSampled2_Bodies(mkBody2 b1, mkBody2 b2, mkSet set, int n, double *p, double *q)
{
	if (n < 1 || !p || !q || (set != MK_SET_CONTACT && set != MK_SET_PLUS)) return MK_ERR_ARGUMENT;
	double *u = malloc(2 * (size_t)n * sizeof *u);
	if (!u) return MK_ERR_MEMORY;
	mkResult r = mkSample2_Angles(n, u, u + n);
	if (r == MK_OK) {
		for (int k = 0; k < n; ++k) {
			mkVec2 uk = {u[k], u[n + k]};
			mkVec2 a = mkBody2_Point(b1, uk);
			mkVec2 b = mkBody2_Point(b2, uk);
			p[2 * k] = a.x;
			p[2 * k + 1] = a.y;
			if (set == MK_SET_CONTACT) {
				/* -(b - t2): the reflected body centred at the origin */
				q[2 * k] = b2.t.x - b.x;
				q[2 * k + 1] = b2.t.y - b.y;
			} else {
				q[2 * k] = b.x;
				q[2 * k + 1] = b.y;
			}
		}
	}
	free(u);
	return r;
}

mkResult mkSampled3_Bodies(mkBody3 b1, mkBody3 b2, mkSet set, int n, double *p, double *q)
{
	if (n < 2 || n > 46340 || !p || !q || (set != MK_SET_CONTACT && set != MK_SET_PLUS))
		return MK_ERR_ARGUMENT;
	size_t count = (size_t)n * (size_t)n;
	double *u = malloc(3 * count * sizeof *u);
	if (!u) return MK_ERR_MEMORY;
	mkResult r = mkSample3_Grid(n, u, u + count, u + 2 * count);
	if (r == MK_OK) {
		for (size_t k = 0; k < count; ++k) {
			mkVec3 uk = {u[k], u[count + k], u[2 * count + k]};
			mkVec3 a = mkBody3_Point(b1, uk);
			mkVec3 b = mkBody3_Point(b2, uk);
			p[3 * k] = a.x;
			p[3 * k + 1] = a.y;
			p[3 * k + 2] = a.z;
			if (set == MK_SET_CONTACT) {
				q[3 * k] = b2.t.x - b.x;
				q[3 * k + 1] = b2.t.y - b.y;
				q[3 * k + 2] = b2.t.z - b.z;
			} else {
				q[3 * k] = b.x;
				q[3 * k + 1] = b.y;
				q[3 * k + 2] = b.z;
			}
		}
	}
	free(u);
	return r;
}

/* One loop for both dimensions; the public pair fixes dim. */
static void sums(int dim, const double *p, int m, const double *q, int n, double *s)
{
	size_t k = 0;
	for (int i = 0; i < m; ++i)
		for (int j = 0; j < n; ++j)
			for (int c = 0; c < dim; ++c) s[k++] = p[dim * i + c] + q[dim * j + c];
}

void mkSampled2_Sums(const double *p, int m, const double *q, int n, double *s)
{
	sums(2, p, m, q, n, s);
}

void mkSampled3_Sums(const double *p, int m, const double *q, int n, double *s)
{
	sums(3, p, m, q, n, s);
}
