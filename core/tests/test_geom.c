/* test_geom.c - the small matrix helpers, against hand-worked values. */
#include <mink/mink.h>

#include "ensure.h"

int main(void)
{
	mkMat2 A = {{{2, 1}, {1, 3}}};
	ENSURE(mkMat2_Det(A) == 5);
	mkMat2 Ai = mkMat2_Inverse(A);
	ENSURE_NEAR(Ai.m[0][0], 0.6, 2.3e-16);
	ENSURE_NEAR(Ai.m[0][1], -0.2, 2.3e-16);
	/* |A|_F = sqrt(15), |A^-1|_F = sqrt(15)/5 */
	ENSURE_NEAR(mkMat2_Cond(A), 3.0, 1e-15);
	ENSURE(isinf(mkMat2_Cond((mkMat2){{{1, 2}, {2, 4}}})));
	mkMat3 B = {{{1, 2, 0}, {0, 1, 0}, {3, 0, 1}}};
	ENSURE(mkMat3_Det(B) == 1); /* 1 (1 - 0) - 2 (0 - 0) + 0 */
	mkMat3 P = mkMat3_Mul(B, mkMat3_Inverse(B));
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) ENSURE_NEAR(P.m[i][j], i == j, 1e-15);
	/* a quarter turn about z maps x to y */
	mkMat3 R = mkMat3_FromQuat(cos(0.25 * MK_PI), 0, 0, sin(0.25 * MK_PI));
	mkVec3 v = mkMat3_MulVec(R, (mkVec3){1, 0, 0});
	ENSURE_NEAR(v.x, 0, 1e-15);
	ENSURE_NEAR(v.y, 1, 1e-15);
	mkVec3 w = mkMat3_MulTVec(B, (mkVec3){1, 1, 1});
	ENSURE(w.x == 4 && w.y == 3 && w.z == 1);
	mkMat2 S = mkMat2_Mul(mkMat2_Rotation(0.5), mkMat2_Shear(2));
	ENSURE_NEAR(mkMat2_Det(S), 1.0, 1e-15);
	ENSURE(!mkMat3_IsFinite(mkMat3_FromQuat(0, 0, 0, 0)));
	ENSURE(mkMat3_IsFinite(mkMat3_FromQuat(0, 0, 0, 1e-100)));
	/* mkMat2_IsFinite detects the documented NaN of a failed inverse. */
	ENSURE(mkMat2_IsFinite(Ai));
	ENSURE(!mkMat2_IsFinite(mkMat2_Inverse((mkMat2){{{1, 2}, {2, 4}}})));
	ENSURE(!mkMat2_IsFinite((mkMat2){{{1, 0}, {0, INFINITY}}}));
	ENSURE_NEAR(mkVec3_Length(mkVec3_Make(2, 3, 6)), 7.0, 0.0);
	ENSURE_NEAR(mkVec2_Length(mkVec2_Make(3, -4)), 5.0, 0.0);
	ENSURE_NEAR(mkVec3_Cross(mkVec3_Make(1, 0, 0), mkVec3_Make(0, 1, 0)).z, 1.0, 0.0);
	ENSURE_NEAR(mkVec2_Cross(mkVec2_Make(1, 2), mkVec2_Make(3, 4)), -2.0, 0.0);
	ENSURE(isnan(mkVec3_Normalize(mkVec3_Make(0, 0, 0)).x));
	ENSURE_NEAR(mkVec2_Normalize(mkVec2_Make(0, -7)).y, -1.0, 0.0);
	return mk_summary("test_geom");
}
