/* test_metrics.c - the validation metrics on points whose errors are known
 * by construction. */
#include <mink/mink.h>

#include "ensure.h"

int main(void)
{
	/* Two circles r1 = 1 at the origin, r2 = 2: the contact point x = 3 e1
	 * with kiss k = e1 is exact; moving x outward by d makes B2 miss B1:
	 * Psi2 of y = (k - x)/2 = (-(2 + d)/2, 0) is ((2 + d)/2)^2, so
	 * e_implicit = d + d^2/4. */
	mkBody2 b1 = mkBody2_Make((mkShape2){1, 1, 1}, mkMat2_Identity(), (mkVec2){0, 0});
	mkBody2 b2 = mkBody2_Make((mkShape2){2, 2, 1}, mkMat2_Identity(), (mkVec2){0, 0});
	mkCheck c = mkCheck2(b1, b2, MK_SET_CONTACT, (mkVec2){3, 0}, (mkVec2){1, 0});
	ENSURE(c.e_implicit == 0 && c.e_gradient == 0 && c.angle == 0 && c.e_implicit1 == 0);
	c = mkCheck2(b1, b2, MK_SET_CONTACT, (mkVec2){3.25, 0}, (mkVec2){1, 0});
	ENSURE_NEAR(c.e_implicit, 0.25 + 0.25 * 0.25 / 4, 1e-15);
	/* Rotating B2's contact point about k by angle t tilts B2's normal by t:
	 * angle = t and e_gradient = 1 - cos t = 2 sin^2(t/2). */
	double t = 1e-3;
	c = mkCheck2(b1, b2, MK_SET_CONTACT, (mkVec2){1 + 2 * cos(t), 2 * sin(t)}, (mkVec2){1, 0});
	ENSURE_NEAR(c.angle, t, 1e-15);
	ENSURE_NEAR(c.e_gradient, 2 * sin(0.5 * t) * sin(0.5 * t), 2e-19); /* the point carries ~1e-16 of rounding, which tilts the normal by that much: t * 1e-16 in e_gradient */
	ENSURE_NEAR(c.e_implicit, 0, 1e-15);
	/* plus set: x = k + t2 + M2 y with parallel normals */
	b2.t = (mkVec2){5, 5};
	c = mkCheck2(b1, b2, MK_SET_PLUS, (mkVec2){8, 5}, (mkVec2){1, 0});
	ENSURE(c.e_implicit == 0 && c.e_gradient == 0);
	/* 3D: spheres, an off-boundary kissing point shows in e_implicit1 */
	mkBody3 s1 = mkBody3_Make((mkShape3){1, 1, 1, 1, 1}, mkMat3_Identity(), (mkVec3){0, 0, 0});
	mkBody3 s2 = mkBody3_Make((mkShape3){2, 2, 2, 1, 1}, mkMat3_Identity(), (mkVec3){0, 0, 0});
	mkCheck d = mkCheck3(s1, s2, MK_SET_CONTACT, (mkVec3){0, 0, 3}, (mkVec3){0, 0, 1});
	ENSURE(d.e_implicit == 0 && d.e_gradient == 0 && d.e_implicit1 == 0);
	d = mkCheck3(s1, s2, MK_SET_CONTACT, (mkVec3){0, 0, 3.5}, (mkVec3){0, 0, 1.5});
	ENSURE_NEAR(d.e_implicit1, 1.25, 1e-15);
	return mk_summary("test_metrics");
}
