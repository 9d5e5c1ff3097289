/* test_registry.c - the method table: names, flags, lookups, resolution
 * limits and the messages for pairs or sizes a method does not take. */
#include <string.h>

#include <mink/registry.h>

#include "ensure.h"

static mkBody2 superellipse(double a, double b, double eps)
{
	mkShape2 s = {a, b, eps};
	return mkBody2_Make(s, mkMat2_Rotation(0.3), (mkVec2){1, 2});
}

static mkBody3 superquadric(double a, double b, double c, double e1, double e2)
{
	mkShape3 s = {a, b, c, e1, e2};
	return mkBody3_Make(s, mkMat3_FromQuat(0.9, 0.1, 0.2, 0.3), (mkVec3){1, 2, 3});
}

int main(void)
{
	static const char *const names[] = {"closed-normal", "closed-gradient", "closed-normal-f32",
		"closed-gradient-f32", "closed-paper", "geometric", "hull-cgal-epick", "hull-cgal-epeck", "hull-qhull",
		"edge-sort"};
	int count = mkRegistry_Count();
	ENSURE(count >= 10);
	for (size_t k = 0; k < sizeof names / sizeof names[0]; ++k) {
		const mkMethod *m = mkRegistry_Find(names[k]);
		ENSURE(m != NULL);
		if (m) ENSURE(strcmp(m->name, names[k]) == 0);
	}
	ENSURE(mkRegistry_Find("no-such-method") == NULL);
	ENSURE(mkRegistry_Find(NULL) == NULL);
	ENSURE(mkRegistry_At(-1) == NULL);
	ENSURE(mkRegistry_At(count) == NULL);

	/* Every entry: unique name, texts, a dimension, run and accept functions
	 * exactly for its dimensions, and exact xor sampled where it says so. */
	for (int i = 0; i < count; ++i) {
		const mkMethod *m = mkRegistry_At(i);
		ENSURE(m && m->name && m->summary && m->reference);
		if (!m) continue;
		ENSURE(mkRegistry_Find(m->name) == m);
		ENSURE(m->flags & (MK_METHOD_2D | MK_METHOD_3D));
		ENSURE(!!(m->flags & MK_METHOD_2D) == (m->run2 != NULL && m->accepts2 != NULL));
		ENSURE(!!(m->flags & MK_METHOD_3D) == (m->run3 != NULL && m->accepts3 != NULL));
		ENSURE(!((m->flags & MK_METHOD_EXACT) && (m->flags & MK_METHOD_SAMPLED)));
		/* an approximate tier states its accuracy; no other method does */
		ENSURE(!((m->flags & MK_METHOD_APPROX) && (m->flags & (MK_METHOD_EXACT | MK_METHOD_SAMPLED))));
		ENSURE(!!(m->flags & MK_METHOD_APPROX) == (mkMethod_Tolerance(m) > 0));
		for (int j = 0; j < i; ++j) ENSURE(strcmp(mkRegistry_At(j)->name, m->name) != 0);
	}
	ENSURE(mkMethod_EdgeSort.flags == (MK_METHOD_2D | MK_METHOD_SAMPLED));
	ENSURE(mkMethod_ClosedGradient.flags & MK_METHOD_EXACT);
	ENSURE(!(mkMethod_ClosedPaper.flags & MK_METHOD_EXACT));
	ENSURE(mkMethod_ClosedGradientF32.flags & MK_METHOD_APPROX);
	ENSURE(mkMethod_Tolerance(&mkMethod_ClosedNormalF32) == MK_F32_TOL);
	ENSURE(mkMethod_Tolerance(&mkMethod_ClosedGradient) == 0.0);
	ENSURE(mkMethod_Tolerance(NULL) == 0.0);
	/* Indexing: the closed forms by body 1's parameter, every sampled method
	 * unordered; the helpers every method uses. */
	ENSURE(mkMethod_Indexing(&mkMethod_ClosedNormal) == MK_INDEX_PARAMETER);
	ENSURE(mkMethod_Indexing(&mkMethod_Geometric) == MK_INDEX_PARAMETER);
	ENSURE(mkMethod_Indexing(&mkMethod_HullQhull) == MK_INDEX_UNORDERED);
	for (int i = 0; i < count; ++i) {
		const mkMethod *m = mkRegistry_At(i);
		mkMethodIndexing x = mkMethod_Indexing(m);
		ENSURE(x == MK_INDEX_PARAMETER || x == MK_INDEX_NORMAL || x == MK_INDEX_UNORDERED);
		if (m->flags & MK_METHOD_SAMPLED) ENSURE(x == MK_INDEX_UNORDERED);
	}
	{
		char msg[64] = "stale";
		mkBody2 b = mkBody2_Make((mkShape2){1, 1, 1}, mkMat2_Identity(), (mkVec2){0, 0});
		ENSURE(mkAcceptAny2(b, b, MK_SET_CONTACT, msg, sizeof msg) == 1 && msg[0] == '\0');
		ENSURE(mkRefuse(msg, sizeof msg, "body2.eps = %g: no", 0.5) == 0 && strcmp(msg, "body2.eps = 0.5: no") == 0);
		ENSURE(mkRefuse(NULL, 0, "nothing") == 0);
	}

	/* The geometric formula needs body 2 an ellipse / ellipsoid. */
	char msg[512];
	mkBody2 se = superellipse(3, 2, 0.5), el = superellipse(3, 2, 1.0);
	ENSURE(mkMethod2_Accepts(&mkMethod_Geometric, se, el, MK_SET_CONTACT, msg, sizeof msg));
	ENSURE(!mkMethod2_Accepts(&mkMethod_Geometric, el, se, MK_SET_CONTACT, msg, sizeof msg));
	ENSURE(strstr(msg, "body2.eps") != NULL);
	mkBody3 sq = superquadric(3, 2, 1, 0.5, 1.5), ed = superquadric(3, 2, 1, 1, 1);
	ENSURE(mkMethod3_Accepts(&mkMethod_Geometric, sq, ed, MK_SET_PLUS, msg, sizeof msg));
	ENSURE(!mkMethod3_Accepts(&mkMethod_Geometric, sq, sq, MK_SET_PLUS, msg, sizeof msg));
	ENSURE(strstr(msg, "body2.eps1") != NULL);
	/* Run anyway: refused, nothing computed. */
	mkPointSet out = {0};
	ENSURE(mkMethod_Geometric.run3(sq, sq, MK_SET_CONTACT, 10, &out) == MK_ERR_UNSUPPORTED);

	/* Edge sorting is 2D only. */
	ENSURE(!mkMethod3_Accepts(&mkMethod_EdgeSort, sq, ed, MK_SET_CONTACT, msg, sizeof msg));
	ENSURE(strstr(msg, "does not run in 3D") != NULL);
	ENSURE(!mkMethod_CheckN(&mkMethod_EdgeSort, 3, 10, msg, sizeof msg));

	/* Resolution limits, with a message naming n and the range. */
	ENSURE(mkMethod_CheckN(&mkMethod_ClosedGradient, 2, 1, msg, sizeof msg));
	ENSURE(!mkMethod_CheckN(&mkMethod_ClosedGradient, 2, 0, msg, sizeof msg));
	ENSURE(strstr(msg, "n = 0") != NULL);
	ENSURE(!mkMethod_CheckN(&mkMethod_ClosedGradient, 3, 1, msg, sizeof msg));
	ENSURE(mkMethod_CheckN(&mkMethod_HullQhull, 3, MK_HULL3_N_MAX, msg, sizeof msg));
	ENSURE(!mkMethod_CheckN(&mkMethod_HullQhull, 3, MK_HULL3_N_MAX + 1, msg, sizeof msg));
	ENSURE(strstr(msg, "[3, 64]") != NULL);
	ENSURE(!mkMethod_CheckN(&mkMethod_HullCgalEpick, 2, 2, msg, sizeof msg));
	ENSURE(mkMethod_CheckN(&mkMethod_EdgeSort, 2, 100000, msg, sizeof msg));
	/* The run functions keep the same limits. */
	ENSURE(mkMethod_HullCgalEpick.run2(se, el, MK_SET_CONTACT, 2, &out) == MK_ERR_RANGE);
	ENSURE(mkMethod_HullQhull.run3(sq, ed, MK_SET_CONTACT, MK_HULL3_N_MAX + 1, &out) == MK_ERR_RANGE);
	ENSURE(mkMethod_EdgeSort.run2(se, el, MK_SET_CONTACT, 0, &out) == MK_ERR_RANGE);
	ENSURE(mkMethod_ClosedNormal.run3(sq, ed, MK_SET_CONTACT, 1, &out) == MK_ERR_RANGE);

	/* Output sizes: n points (2D) or n*n (3D) for closed forms; a hull for
	 * sampled methods. */
	ENSURE(mkMethod_ClosedGradient.run2(se, el, MK_SET_CONTACT, 37, &out) == MK_OK);
	ENSURE(out.dim == 2 && out.count == 37);
	ENSURE(mkMethod_Geometric.run3(sq, ed, MK_SET_PLUS, 9, &out) == MK_OK);
	ENSURE(out.dim == 3 && out.count == 81);
	ENSURE(mkMethod_EdgeSort.run2(se, el, MK_SET_CONTACT, 40, &out) == MK_OK);
	ENSURE(out.dim == 2 && out.count >= 3 && out.count <= 80);
	ENSURE(mkMethod_HullQhull.run3(sq, ed, MK_SET_CONTACT, 6, &out) == MK_OK);
	ENSURE(out.dim == 3 && out.count >= 4 && out.count <= 36 * 36);
	mkPointSet_Free(&out);
	/* the names, in registry order, and a cap */
	{
		const char *listed[64];
		int n = mkRegistry_Names(listed, 64);
		ENSURE(n == mkRegistry_Count());
		for (int i = 0; i < n; ++i)
			ENSURE(strcmp(listed[i], mkRegistry_At(i)->name) == 0);
		ENSURE(mkRegistry_Names(listed, 2) == 2 && strcmp(listed[1], mkRegistry_At(1)->name) == 0);
	}
	return mk_summary("test_registry");
}
