/* spec.c - parse and validate the SPEC text of a body. */
#include "mink/spec.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/message.h"

#define SPEC_MAX_LEN 4096
#define SPEC_MAX_VALUES 9

static const char *const kind_names[] = {"circle", "ellipse", "superellipse", "sphere", "ellipsoid", "superquadric"};

const char *mkKind_Name(mkKind k)
{
	return (int)k >= 0 && k <= MK_KIND_SUPERQUADRIC ? kind_names[k] : "?";
}

/* Keys, in a fixed order; a kind allows a subset. */
enum { K_A, K_B, K_C, K_EPS, K_EPS1, K_EPS2, K_ROT, K_QUAT, K_SHEAR, K_M, K_AT, K_COUNT };
static const char *const key_names[K_COUNT] = {"a", "b", "c", "eps", "eps1", "eps2", "rot", "quat", "shear", "M", "at"};

static unsigned allowed_keys(mkKind k)
{
	const unsigned pose2 = 1u << K_ROT | 1u << K_SHEAR | 1u << K_M | 1u << K_AT;
	const unsigned pose3 = 1u << K_QUAT | 1u << K_M | 1u << K_AT;
	switch (k) {
	case MK_KIND_CIRCLE: return 1u << K_A | pose2;
	case MK_KIND_ELLIPSE: return 1u << K_A | 1u << K_B | pose2;
	case MK_KIND_SUPERELLIPSE: return 1u << K_A | 1u << K_B | 1u << K_EPS | pose2;
	case MK_KIND_SPHERE: return 1u << K_A | pose3;
	case MK_KIND_ELLIPSOID: return 1u << K_A | 1u << K_B | 1u << K_C | pose3;
	case MK_KIND_SUPERQUADRIC: return 1u << K_A | 1u << K_B | 1u << K_C | 1u << K_EPS1 | 1u << K_EPS2 | pose3;
	}
	return 0;
}

static const unsigned shape_keys = 1u << K_A | 1u << K_B | 1u << K_C | 1u << K_EPS | 1u << K_EPS1 | 1u << K_EPS2;

static void list_keys(unsigned mask, char *buf, size_t len)
{
	buf[0] = 0;
	for (int i = 0; i < K_COUNT; ++i) {
		if (!(mask & 1u << i)) continue;
		size_t n = strlen(buf);
		snprintf(buf + n, len - n, "%s%s", n ? ", " : "", key_names[i]);
	}
}

/* Parse a comma-separated list of exactly `count` finite numbers. */
static int parse_numbers(const char *s, size_t len, int count, double *out, int *got)
{
	char buf[SPEC_MAX_LEN];
	if (len >= sizeof buf) return 0;
	memcpy(buf, s, len);
	buf[len] = 0;
	int n = 0;
	char *p = buf;
	for (;;) {
		char *end;
		errno = 0;
		double v = strtod(p, &end);
		if (end == p || (*end != ',' && *end != 0)) { *got = -1; return 0; }
		if (n < SPEC_MAX_VALUES) out[n] = v;
		++n;
		if (*end == 0) break;
		p = end + 1;
	}
	*got = n;
	return n == count;
}

mkResult mkSpec_Parse(const char *text, int dim, const char *what, mkSpec *out, char *msg, size_t msglen)
{
	if (!what) what = "body";
	if (!text || !out) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: no SPEC given", what);
	if (dim != 2 && dim != 3) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: dimension %d: must be 2 or 3", what, dim);
	size_t tlen = 0;
	while (tlen <= SPEC_MAX_LEN && text[tlen]) ++tlen;
	if (tlen > SPEC_MAX_LEN)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: SPEC is longer than %d characters", what, SPEC_MAX_LEN);

	const char *p = text;
	while (isspace((unsigned char)*p)) ++p;
	const char *ks = p;
	while (*p && !isspace((unsigned char)*p)) ++p;
	size_t klen = (size_t)(p - ks);
	if (klen == 0)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: empty SPEC: expected 'KIND key=value ...' with KIND one of "
			"circle, ellipse, superellipse (2D), sphere, ellipsoid, superquadric (3D)", what);
	int kind = -1;
	for (int i = 0; i < 6; ++i)
		if (strlen(kind_names[i]) == klen && strncmp(kind_names[i], ks, klen) == 0) kind = i;
	if (kind < 0)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: unknown kind '%.*s': must be one of circle, ellipse, "
			"superellipse (2D), sphere, ellipsoid, superquadric (3D)", what, (int)(klen > 64 ? 64 : klen), ks);
	int kdim = kind <= MK_KIND_SUPERELLIPSE ? 2 : 3;
	if (kdim != dim)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: kind '%s' is %dD but the problem is %dD: use %s", what,
			kind_names[kind], kdim, dim, dim == 2 ? "circle, ellipse or superellipse" : "sphere, ellipsoid or superquadric");

	unsigned allow = allowed_keys((mkKind)kind), seen = 0;
	double val[K_COUNT][SPEC_MAX_VALUES] = {{0}};
	char keys[128];
	while (*p) {
		while (isspace((unsigned char)*p)) ++p;
		if (!*p) break;
		const char *ts = p;
		while (*p && !isspace((unsigned char)*p)) ++p;
		size_t tl = (size_t)(p - ts);
		const char *eq = memchr(ts, '=', tl);
		int shown = (int)(tl > 64 ? 64 : tl);
		if (!eq)
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: '%.*s' is not of the form key=value", what, shown, ts);
		size_t nl = (size_t)(eq - ts);
		int key = -1;
		for (int i = 0; i < K_COUNT; ++i)
			if (strlen(key_names[i]) == nl && strncmp(key_names[i], ts, nl) == 0) key = i;
		list_keys(allow, keys, sizeof keys);
		if (key < 0 || !(allow & 1u << key))
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: key '%.*s' is not allowed for %s: allowed keys are %s",
				what, (int)(nl > 32 ? 32 : nl), ts, kind_names[kind], keys);
		if (seen & 1u << key)
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: key '%s' is given twice", what, key_names[key]);
		seen |= 1u << key;
		int want = 1;
		if (key == K_QUAT) want = 4;
		else if (key == K_M) want = dim * dim;
		else if (key == K_AT) want = dim;
		size_t vl = tl - nl - 1;
		if (vl == 0)
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s.%s: missing value", what, key_names[key]);
		int got = 0;
		if (!parse_numbers(eq + 1, vl, want, val[key], &got)) {
			if (got < 0)
				return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s.%s = '%.*s' is not a number%s", what, key_names[key],
					(int)(vl > 64 ? 64 : vl), eq + 1, want > 1 ? " list" : "");
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s.%s takes %d comma-separated number%s, got %d", what,
				key_names[key], want, want > 1 ? "s" : "", got);
		}
	}
	unsigned need = allow & shape_keys;
	if ((need & seen) != need) {
		unsigned missing = need & ~seen;
		list_keys(missing, keys, sizeof keys);
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: %s needs %s", what, kind_names[kind], keys);
	}
	if ((seen & 1u << K_M) && (seen & (1u << K_ROT | 1u << K_SHEAR | 1u << K_QUAT)))
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: M replaces %s: give one or the other", what,
			dim == 2 ? "rot and shear" : "quat");

	out->dim = dim;
	out->kind = (mkKind)kind;
	if (dim == 2) {
		mkBody2 *b = &out->body2;
		double a = val[K_A][0];
		b->shape.a = a;
		b->shape.b = kind == MK_KIND_CIRCLE ? a : val[K_B][0];
		b->shape.eps = kind == MK_KIND_SUPERELLIPSE ? val[K_EPS][0] : 1.0;
		b->M = mkMat2_Identity();
		if (seen & 1u << K_M) {
			memcpy(&b->M.m[0][0], val[K_M], 4 * sizeof(double));
		} else {
			double rot = (seen & 1u << K_ROT) ? val[K_ROT][0] : 0.0;
			double sh = (seen & 1u << K_SHEAR) ? val[K_SHEAR][0] : 0.0;
			if (!isfinite(rot) || fabs(rot) > 1e6)
				return mkFail(MK_ERR_RANGE, msg, msglen, "%s.rot = %g is out of range: must be a finite angle in "
					"radians in [-1e6, 1e6]", what, rot);
			if (!isfinite(sh) || fabs(sh) > MK_MAP_ENTRY_MAX)
				return mkFail(MK_ERR_RANGE, msg, msglen, "%s.shear = %g is out of range: must be a finite number "
					"in [-%g, %g]", what, sh, MK_MAP_ENTRY_MAX, MK_MAP_ENTRY_MAX);
			b->M = mkMat2_Mul(mkMat2_Rotation(rot), mkMat2_Shear(sh));
		}
		b->t.x = (seen & 1u << K_AT) ? val[K_AT][0] : 0.0;
		b->t.y = (seen & 1u << K_AT) ? val[K_AT][1] : 0.0;
		if (!mkBody2_IsValid(*b, what, msg, msglen)) return MK_ERR_RANGE;
	} else {
		mkBody3 *b = &out->body3;
		double a = val[K_A][0];
		int sphere = kind == MK_KIND_SPHERE;
		b->shape.a = a;
		b->shape.b = sphere ? a : val[K_B][0];
		b->shape.c = sphere ? a : val[K_C][0];
		b->shape.eps1 = kind == MK_KIND_SUPERQUADRIC ? val[K_EPS1][0] : 1.0;
		b->shape.eps2 = kind == MK_KIND_SUPERQUADRIC ? val[K_EPS2][0] : 1.0;
		b->M = mkMat3_Identity();
		if (seen & 1u << K_M) {
			memcpy(&b->M.m[0][0], val[K_M], 9 * sizeof(double));
		} else if (seen & 1u << K_QUAT) {
			int ok = 0;
			const double *q = val[K_QUAT];
			for (int i = 0; i < 4; ++i)
				if (!isfinite(q[i]) || fabs(q[i]) > 1e150)
					return mkFail(MK_ERR_RANGE, msg, msglen, "%s.quat component %d = %g is out of range: must be "
						"finite with magnitude at most 1e150", what, i + 1, q[i]);
			b->M = mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
			ok = mkMat3_IsFinite(b->M);
			if (!ok)
				return mkFail(MK_ERR_RANGE, msg, msglen, "%s.quat = %g,%g,%g,%g is zero: must be a nonzero "
					"quaternion w,x,y,z", what, q[0], q[1], q[2], q[3]);
		}
		b->t.x = (seen & 1u << K_AT) ? val[K_AT][0] : 0.0;
		b->t.y = (seen & 1u << K_AT) ? val[K_AT][1] : 0.0;
		b->t.z = (seen & 1u << K_AT) ? val[K_AT][2] : 0.0;
		if (!mkBody3_IsValid(*b, what, msg, msglen)) return MK_ERR_RANGE;
	}
	return MK_OK;
}
