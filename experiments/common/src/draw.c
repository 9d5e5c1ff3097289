/* draw.c - shared random draws. */
#include "mink_exp/draw.h"

#include <math.h>

const char *const mkRotDraw_Names[2] = { "paper", "uniform" };

void mkDraw_Quat(mkRng *rng, mkRotDraw kind, double q[4])
{
	if (kind == MK_ROT_PAPER) {
		for (int i = 0; i < 4; ++i)
			q[i] = mkRng_Unit(rng);
		return;
	}
	double u1 = mkRng_Unit(rng), u2 = mkRng_Unit(rng), u3 = mkRng_Unit(rng);
	double r1 = sqrt(1.0 - u1), r2 = sqrt(u1);
	q[0] = r2 * cos(2.0 * MK_PI * u3);
	q[1] = r1 * sin(2.0 * MK_PI * u2);
	q[2] = r1 * cos(2.0 * MK_PI * u2);
	q[3] = r2 * sin(2.0 * MK_PI * u3);
}

mkMat3 mkDraw_Rotation3(mkRng *rng, mkRotDraw kind)
{
	double q[4];
	mkDraw_Quat(rng, kind, q);
	return mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
}

double mkDraw_Value(mkRng *rng, double lo, double hi)
{
	return lo == hi ? lo : mkRng_Uniform(rng, lo, hi);
}

mkShape2 mkDraw_Shape2(mkRng *rng, const mkShapeRange2 *r)
{
	mkShape2 s;
	s.a = mkDraw_Value(rng, r->a[0], r->a[1]);
	s.b = mkDraw_Value(rng, r->b[0], r->b[1]);
	s.eps = mkDraw_Value(rng, r->eps[0], r->eps[1]);
	return s;
}

mkShape3 mkDraw_Shape3(mkRng *rng, const mkShapeRange3 *r)
{
	mkShape3 s;
	s.a = mkDraw_Value(rng, r->a[0], r->a[1]);
	s.b = mkDraw_Value(rng, r->b[0], r->b[1]);
	s.c = mkDraw_Value(rng, r->c[0], r->c[1]);
	s.eps1 = mkDraw_Value(rng, r->eps1[0], r->eps1[1]);
	s.eps2 = mkDraw_Value(rng, r->eps2[0], r->eps2[1]);
	return s;
}

mkMat2 mkDraw_RotShear2(mkRng *rng, double shear, double *angle, double *s)
{
	double phi = 2.0 * MK_PI * mkRng_Unit(rng);
	double sh = mkRng_Uniform(rng, -shear, shear);
	if (angle)
		*angle = phi;
	if (s)
		*s = sh;
	return mkMat2_Mul(mkMat2_Rotation(phi), mkMat2_Shear(sh));
}
