/* geom.c - small matrix helpers. */
#include "mink/geom.h"

#include <math.h>

#include "base/geom_inline.h"

mkMat2 mkMat2_Identity(void)
{
	mkMat2 r = {{{1.0, 0.0}, {0.0, 1.0}}};
	return r;
}

mkMat3 mkMat3_Identity(void)
{
	mkMat3 r = {{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};
	return r;
}

mkMat2 mkMat2_Rotation(double angle)
{
	double c = cos(angle), s = sin(angle);
	mkMat2 r = {{{c, -s}, {s, c}}};
	return r;
}

mkMat2 mkMat2_Shear(double s)
{
	mkMat2 r = {{{1.0, s}, {0.0, 1.0}}};
	return r;
}

double mkVec2_Length(mkVec2 a) { return mkVec2_LengthInline(a); }

mkVec2 mkVec2_Normalize(mkVec2 a) { return mkVec2_NormalizeInline(a); }

double mkVec3_Length(mkVec3 a) { return mkVec3_LengthInline(a); }

mkVec3 mkVec3_Normalize(mkVec3 a) { return mkVec3_NormalizeInline(a); }

int mkMat2_IsFinite(mkMat2 a)
{
	for (int i = 0; i < 2; ++i)
		for (int j = 0; j < 2; ++j)
			if (!isfinite(a.m[i][j]))
				return 0;
	return 1;
}

int mkMat3_IsFinite(mkMat3 a) { return mkMat3_IsFiniteInline(a); }

mkMat3 mkMat3_FromQuat(double w, double x, double y, double z) { return mkMat3_FromQuatInline(w, x, y, z); }

mkMat2 mkMat2_Mul(mkMat2 a, mkMat2 b)
{
	mkMat2 r;
	for (int i = 0; i < 2; ++i)
		for (int j = 0; j < 2; ++j)
			r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j];
	return r;
}

mkMat3 mkMat3_Mul(mkMat3 a, mkMat3 b) { return mkMat3_MulInline(a, b); }

mkMat2 mkMat2_Transpose(mkMat2 a)
{
	mkMat2 r = {{{a.m[0][0], a.m[1][0]}, {a.m[0][1], a.m[1][1]}}};
	return r;
}

mkMat3 mkMat3_Transpose(mkMat3 a)
{
	mkMat3 r;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			r.m[i][j] = a.m[j][i];
	return r;
}

double mkMat2_Det(mkMat2 a)
{
	return a.m[0][0] * a.m[1][1] - a.m[0][1] * a.m[1][0];
}

double mkMat3_Det(mkMat3 a)
{
	return a.m[0][0] * (a.m[1][1] * a.m[2][2] - a.m[1][2] * a.m[2][1])
		- a.m[0][1] * (a.m[1][0] * a.m[2][2] - a.m[1][2] * a.m[2][0])
		+ a.m[0][2] * (a.m[1][0] * a.m[2][1] - a.m[1][1] * a.m[2][0]);
}

mkMat2 mkMat2_Inverse(mkMat2 a)
{
	double d = mkMat2_Det(a);
	double s = 1.0 / d; /* inf when singular: entries become inf/NaN, as documented */
	if (d == 0.0) s = NAN;
	mkMat2 r = {{{a.m[1][1] * s, -a.m[0][1] * s}, {-a.m[1][0] * s, a.m[0][0] * s}}};
	return r;
}

mkMat3 mkMat3_Inverse(mkMat3 a)
{
	double d = mkMat3_Det(a);
	double s = d == 0.0 ? NAN : 1.0 / d;
	mkMat3 r;
	r.m[0][0] = (a.m[1][1] * a.m[2][2] - a.m[1][2] * a.m[2][1]) * s;
	r.m[0][1] = (a.m[0][2] * a.m[2][1] - a.m[0][1] * a.m[2][2]) * s;
	r.m[0][2] = (a.m[0][1] * a.m[1][2] - a.m[0][2] * a.m[1][1]) * s;
	r.m[1][0] = (a.m[1][2] * a.m[2][0] - a.m[1][0] * a.m[2][2]) * s;
	r.m[1][1] = (a.m[0][0] * a.m[2][2] - a.m[0][2] * a.m[2][0]) * s;
	r.m[1][2] = (a.m[0][2] * a.m[1][0] - a.m[0][0] * a.m[1][2]) * s;
	r.m[2][0] = (a.m[1][0] * a.m[2][1] - a.m[1][1] * a.m[2][0]) * s;
	r.m[2][1] = (a.m[0][1] * a.m[2][0] - a.m[0][0] * a.m[2][1]) * s;
	r.m[2][2] = (a.m[0][0] * a.m[1][1] - a.m[0][1] * a.m[1][0]) * s;
	return r;
}

static double frob(const double *m, int n)
{
	double s = 0.0;
	for (int i = 0; i < n; ++i) s += m[i] * m[i];
	return sqrt(s);
}

double mkMat2_Cond(mkMat2 a)
{
	if (mkMat2_Det(a) == 0.0) return INFINITY;
	mkMat2 i = mkMat2_Inverse(a);
	double c = frob(&a.m[0][0], 4) * frob(&i.m[0][0], 4);
	return isfinite(c) ? c : INFINITY;
}

double mkMat3_Cond(mkMat3 a)
{
	if (mkMat3_Det(a) == 0.0) return INFINITY;
	mkMat3 i = mkMat3_Inverse(a);
	double c = frob(&a.m[0][0], 9) * frob(&i.m[0][0], 9);
	return isfinite(c) ? c : INFINITY;
}

mkVec2 mkMat2_MulVec(mkMat2 a, mkVec2 v)
{
	mkVec2 r = {a.m[0][0] * v.x + a.m[0][1] * v.y, a.m[1][0] * v.x + a.m[1][1] * v.y};
	return r;
}

mkVec3 mkMat3_MulVec(mkMat3 a, mkVec3 v) { return mkMat3_MulVecInline(a, v); }

mkVec2 mkMat2_MulTVec(mkMat2 a, mkVec2 v)
{
	mkVec2 r = {a.m[0][0] * v.x + a.m[1][0] * v.y, a.m[0][1] * v.x + a.m[1][1] * v.y};
	return r;
}

mkVec3 mkMat3_MulTVec(mkMat3 a, mkVec3 v) { return mkMat3_MulTVecInline(a, v); }
