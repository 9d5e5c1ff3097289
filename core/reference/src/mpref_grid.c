/* mpref_grid.c - the extremes grid and the SPEC text of a body
 * (mink/mpref_grid.h). */
#include <mink/mpref_grid.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

static const double epsFull[] = { 1e-6, 1e-4, 1e-3, 1e-2, 0.1, 0.5, 1.0, 1.5, 1.9, 1.99, 1.999,
	2.0 - 1e-4, 2.0 - 1e-6 };
static const double epsQuick[] = { 1e-6, 1e-2, 1.0, 1.99, 2.0 - 1e-6 };
static const double sweepFull[] = { 1e-6, 1.0, 2.0 - 1e-6 };
static const double sweepQuick[] = { 1.0 };

static const double axisFull[] = { 1.0, 10.0, 1e2, 1e3, 1e4, 1e5, 1e6 };
static const double shearFull[] = { 0.0, 0.1, 1.0, 10.0, 100.0 };
static const double sizeFull[] = { 1e-6, 1e-4, 1e-2, 1.0, 1e2, 1e4, 1e6 };
static const double shiftFull[] = { 0.0, 1.0, 1e3, 1e6, 1e9 };
static const double axisQuick[] = { 1.0, 1e6 };
static const double shearQuick[] = { 0.0, 100.0 };
static const double sizeQuick[] = { 1e-6, 1e6 };
static const double shiftQuick[] = { 0.0, 1e9 };

#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

typedef struct sweepDef { const char *name; const double *v; int n; } sweepDef;

static void sweeps(refGridKind kind, sweepDef out[4])
{
	int full = kind == REF_GRID_FULL;
	out[0] = (sweepDef){ "axis", full ? axisFull : axisQuick, full ? COUNT(axisFull) : COUNT(axisQuick) };
	out[1] = (sweepDef){ "shear", full ? shearFull : shearQuick, full ? COUNT(shearFull) : COUNT(shearQuick) };
	out[2] = (sweepDef){ "size", full ? sizeFull : sizeQuick, full ? COUNT(sizeFull) : COUNT(sizeQuick) };
	out[3] = (sweepDef){ "shift", full ? shiftFull : shiftQuick, full ? COUNT(shiftFull) : COUNT(shiftQuick) };
}

int refGrid_Eps(refGridKind kind, const double **values)
{
	*values = kind == REF_GRID_FULL ? epsFull : epsQuick;
	return kind == REF_GRID_FULL ? COUNT(epsFull) : COUNT(epsQuick);
}

int refGrid_SweepEps(refGridKind kind, const double **values)
{
	*values = kind == REF_GRID_FULL ? sweepFull : sweepQuick;
	return kind == REF_GRID_FULL ? COUNT(sweepFull) : COUNT(sweepQuick);
}

static int sweepCells(refGridKind kind)
{
	sweepDef s[4];
	const double *e;
	sweeps(kind, s);
	int n = 0;
	for (int i = 0; i < 4; ++i)
		n += s[i].n;
	return n * refGrid_SweepEps(kind, &e);
}

int refGrid_Count(refGridKind kind, int dim)
{
	if (dim != 2 && dim != 3)
		return 0;
	const double *e;
	int ne = refGrid_Eps(kind, &e);
	return ne * ne + sweepCells(kind);
}

/* R(angle about unit axis) by Rodrigues' formula, in double. */
static void rotation3(const double *axis, double angle, double R[3][3])
{
	double l = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
	double k[3] = { axis[0] / l, axis[1] / l, axis[2] / l };
	double c = cos(angle), s = sin(angle), C = 1.0 - c;
	R[0][0] = c + k[0] * k[0] * C;
	R[0][1] = k[0] * k[1] * C - k[2] * s;
	R[0][2] = k[0] * k[2] * C + k[1] * s;
	R[1][0] = k[1] * k[0] * C + k[2] * s;
	R[1][1] = c + k[1] * k[1] * C;
	R[1][2] = k[1] * k[2] * C - k[0] * s;
	R[2][0] = k[2] * k[0] * C - k[1] * s;
	R[2][1] = k[2] * k[1] * C + k[0] * s;
	R[2][2] = c + k[2] * k[2] * C;
}

/* One body of the grid: base shape of body `which`, exponents e1, e2, the
 * axis ratio, shear, size factor and translation factor. */
static refBody makeBody(int dim, int which, double e1, double e2, double axis, double shear,
	double size, double shift)
{
	refBody b;
	memset(&b, 0, sizeof b);
	b.s.dim = dim;
	b.s.e1 = e1;
	b.s.e2 = dim == 3 ? e2 : 0.0;
	double R[3][3] = { { 0 } };
	if (dim == 2) {
		double th = which == 0 ? 0.3 : 1.2;
		b.s.a[0] = which == 0 ? 1.0 : 0.8;
		b.s.a[1] = (which == 0 ? 0.5 : 0.3) / axis;
		R[0][0] = cos(th);
		R[0][1] = -sin(th);
		R[1][0] = sin(th);
		R[1][1] = cos(th);
	} else {
		static const double ax0[3] = { 1.0, 2.0, 3.0 }, ax1[3] = { -2.0, 1.0, 1.0 };
		b.s.a[0] = which == 0 ? 1.0 : 0.7;
		b.s.a[1] = (which == 0 ? 0.5 : 0.4) / axis;
		b.s.a[2] = (which == 0 ? 0.8 : 0.5) / axis;
		rotation3(which == 0 ? ax0 : ax1, which == 0 ? 0.3 : 1.2, R);
	}
	if (which == 1)
		for (int i = 0; i < dim; ++i)
			b.s.a[i] *= size;
	/* M = R [1 s; 0 1] (3D: shear of the first axis along the second). */
	for (int i = 0; i < dim; ++i) {
		b.M.m[i][0] = R[i][0];
		b.M.m[i][1] = R[i][0] * shear + R[i][1];
		if (dim == 3)
			b.M.m[i][2] = R[i][2];
	}
	if (which == 0) {
		b.t[0] = 0.6 * shift;
		b.t[1] = 0.8 * shift;
	} else {
		b.t[0] = 0.25 - 0.8 * shift;
		b.t[1] = -0.5 + 0.6 * shift;
		if (dim == 3)
			b.t[2] = 0.3 + 0.5 * shift;
	}
	return b;
}

int refGrid_Cell(refGridKind kind, int dim, int index, refCell *cell)
{
	if ((dim != 2 && dim != 3) || index < 0 || index >= refGrid_Count(kind, dim))
		return -1;
	const double *ev, *sv;
	int ne = refGrid_Eps(kind, &ev), ns = refGrid_SweepEps(kind, &sv);
	refCell c;
	memset(&c, 0, sizeof c);
	c.dim = dim;
	c.index = index;
	c.axis = 1.0;
	c.size = 1.0;
	if (index < ne * ne) {
		c.family = "eps";
		double ei = ev[index / ne], ej = ev[index % ne];
		if (dim == 2) {
			c.eps[0][0] = c.eps[0][1] = ei;
			c.eps[1][0] = c.eps[1][1] = ej;
		} else {
			c.eps[0][0] = c.eps[1][0] = ei;
			c.eps[0][1] = c.eps[1][1] = ej;
		}
	} else {
		int k = index - ne * ne;
		sweepDef s[4];
		sweeps(kind, s);
		double e = sv[k % ns];
		k /= ns;
		int f = 0;
		while (k >= s[f].n) {
			k -= s[f].n;
			++f;
		}
		c.family = s[f].name;
		double v = s[f].v[k];
		if (f == 0)
			c.axis = v;
		else if (f == 1)
			c.shear = v;
		else if (f == 2)
			c.size = v;
		else
			c.shift = v;
		c.eps[0][0] = c.eps[0][1] = c.eps[1][0] = c.eps[1][1] = e;
	}
	c.b1 = makeBody(dim, 0, c.eps[0][0], c.eps[0][1], c.axis, c.shear, 1.0, c.shift);
	c.b2 = makeBody(dim, 1, c.eps[1][0], c.eps[1][1], c.axis, c.shear, c.size, c.shift);
	if (refBody_Spec(&c.b1, c.spec1, sizeof c.spec1) < 0 || refBody_Spec(&c.b2, c.spec2, sizeof c.spec2) < 0)
		return -1; /* cannot happen: a SPEC of 21 numbers fits in REF_SPEC_MAX */
	*cell = c;
	return 0;
}

int refGrid_Parse(const char *text, const char *flag, refGridKind *kind, char *msg, size_t msglen)
{
	if (text && strcmp(text, "quick") == 0) {
		*kind = REF_GRID_QUICK;
		return 0;
	}
	if (text && strcmp(text, "full") == 0) {
		*kind = REF_GRID_FULL;
		return 0;
	}
	if (msg && msglen)
		snprintf(msg, msglen, "%s = '%.64s' is out of range: must be one of quick, full",
			flag ? flag : "grid", text ? text : "");
	return -1;
}

int refBody_Spec(const refBody *b, char *buf, size_t len)
{
	int dim = b->s.dim, n;
	if (dim == 2)
		n = snprintf(buf, len, "superellipse a=%.17g b=%.17g eps=%.17g M=%.17g,%.17g,%.17g,%.17g at=%.17g,%.17g",
			b->s.a[0], b->s.a[1], b->s.e1, b->M.m[0][0], b->M.m[0][1], b->M.m[1][0], b->M.m[1][1],
			b->t[0], b->t[1]);
	else
		n = snprintf(buf, len, "superquadric a=%.17g b=%.17g c=%.17g eps1=%.17g eps2=%.17g "
			"M=%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g at=%.17g,%.17g,%.17g",
			b->s.a[0], b->s.a[1], b->s.a[2], b->s.e1, b->s.e2,
			b->M.m[0][0], b->M.m[0][1], b->M.m[0][2], b->M.m[1][0], b->M.m[1][1], b->M.m[1][2],
			b->M.m[2][0], b->M.m[2][1], b->M.m[2][2], b->t[0], b->t[1], b->t[2]);
	return n < 0 || (size_t)n >= len ? -1 : n;
}
