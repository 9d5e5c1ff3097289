/* method_support_normal.c - a method added the documented way (one file
 * under baselines/src named method_*.c, one line of registry.def), used to
 * check that those two steps are all a new method needs: the exact support
 * points of the sum at n given unit normals u_k (mkSample2_Angles(n), 3D
 * mkSample3_Grid(n)), each the sum of both bodies' support points. Its
 * points are indexed by the sum's normal (MK_INDEX_NORMAL), not by body 1's
 * surface parameter. Its registry line:
 *   MK_REGISTRY_ENTRY(mkMethod_SupportNormal, NORMAL, 1, INT_MAX, 2, MK_CLOSED3_N_MAX, 0)
 * (baselines/tests/add_method/run.sh copies that line into registry.def). */
#include <stdlib.h>

#include <mink/registry.h>

/* Body 2's part of the set in direction n: its support point (plus set) or
 * that of -B2 about its centre, b2.t - support(b2, -n) (contact set). */
static mkVec2 mkSupportNormal_Part2(mkBody2 b2, mkSet set, mkVec2 n)
{
	if (set == MK_SET_PLUS) return mkBody2_Support(b2, n);
	mkVec2 q = mkBody2_Support(b2, (mkVec2){-n.x, -n.y});
	return (mkVec2){b2.t.x - q.x, b2.t.y - q.y};
}

static mkVec3 mkSupportNormal_Part3(mkBody3 b2, mkSet set, mkVec3 n)
{
	if (set == MK_SET_PLUS) return mkBody3_Support(b2, n);
	mkVec3 q = mkBody3_Support(b2, (mkVec3){-n.x, -n.y, -n.z});
	return (mkVec3){b2.t.x - q.x, b2.t.y - q.y, b2.t.z - q.z};
}

static mkResult mkSupportNormal_Run2(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	if (n < 1) return MK_ERR_RANGE;
	double *u = malloc(2 * (size_t)n * sizeof *u);
	if (!u) return MK_ERR_MEMORY;
	mkResult r = mkSample2_Angles(n, u, u + n);
	if (r == MK_OK) r = mkPointSet_Resize(out, 2, n);
	for (int k = 0; r == MK_OK && k < n; ++k) {
		mkVec2 d = {u[k], u[n + k]};
		mkVec2 p = mkBody2_Support(b1, d), q = mkSupportNormal_Part2(b2, set, d);
		out->x[k] = p.x + q.x;
		out->y[k] = p.y + q.y;
	}
	free(u);
	return r;
}

static mkResult mkSupportNormal_Run3(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	if (n < 2 || n > MK_CLOSED3_N_MAX) return MK_ERR_RANGE;
	int count = n * n;
	double *u = malloc(3 * (size_t)count * sizeof *u);
	if (!u) return MK_ERR_MEMORY;
	mkResult r = mkSample3_Grid(n, u, u + count, u + 2 * (size_t)count);
	if (r == MK_OK) r = mkPointSet_Resize(out, 3, count);
	for (int k = 0; r == MK_OK && k < count; ++k) {
		mkVec3 d = {u[k], u[count + k], u[2 * (size_t)count + k]};
		mkVec3 p = mkBody3_Support(b1, d), q = mkSupportNormal_Part3(b2, set, d);
		out->x[k] = p.x + q.x;
		out->y[k] = p.y + q.y;
		out->z[k] = p.z + q.z;
	}
	free(u);
	return r;
}

const mkMethod mkMethod_SupportNormal = {
	"support-normal",
	"support points of both bodies summed at n given unit normals (indexed by the sum's normal)",
	"definition: h_K = h_B1 + h_B2, x_K(n) = x_B1(n) + x_B2(n)",
	MK_METHOD_2D | MK_METHOD_3D | MK_METHOD_EXACT,
	mkAcceptAny2, mkAcceptAny3, mkSupportNormal_Run2, mkSupportNormal_Run3,
};
