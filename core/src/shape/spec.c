/* spec.c - parse and validate the SPEC text of a body: its kind, then
 * key=value tokens (the tokenizer and the pose parser are shared through
 * spec_keys.h with the scene parser's box and cylinder). */
#include "mink/spec.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/message.h"
#include "shape/spec_keys.h"

#define SPEC_MAX_LEN 4096

static const char *const mkSpec_KindNames[] = {"circle", "ellipse", "superellipse", "sphere", "ellipsoid", "superquadric"};

const char *mkKind_Name(mkKind k)
{
	return (int)k >= 0 && k <= MK_KIND_SUPERQUADRIC ? mkSpec_KindNames[k] : "?";
}

static const char *const mkSpec_KeyNames[MK_SPEC_KEY_COUNT] = {"a", "b", "c", "eps", "eps1", "eps2", "size", "r", "h",
	"rot", "quat", "shear", "M", "at"};

unsigned mkSpecKeys_Pose(int dim)
{
	return dim == 2 ? MK_SPEC_BIT(MK_SPEC_ROT) | MK_SPEC_BIT(MK_SPEC_SHEAR) | MK_SPEC_BIT(MK_SPEC_M) | MK_SPEC_BIT(MK_SPEC_AT)
		: MK_SPEC_BIT(MK_SPEC_QUAT) | MK_SPEC_BIT(MK_SPEC_M) | MK_SPEC_BIT(MK_SPEC_AT);
}

static unsigned mkSpec_AllowedKeys(mkKind k)
{
	const unsigned a = MK_SPEC_BIT(MK_SPEC_A), b = MK_SPEC_BIT(MK_SPEC_B), c = MK_SPEC_BIT(MK_SPEC_C);
	switch (k) {
	case MK_KIND_CIRCLE: return a | mkSpecKeys_Pose(2);
	case MK_KIND_ELLIPSE: return a | b | mkSpecKeys_Pose(2);
	case MK_KIND_SUPERELLIPSE: return a | b | MK_SPEC_BIT(MK_SPEC_EPS) | mkSpecKeys_Pose(2);
	case MK_KIND_SPHERE: return a | mkSpecKeys_Pose(3);
	case MK_KIND_ELLIPSOID: return a | b | c | mkSpecKeys_Pose(3);
	case MK_KIND_SUPERQUADRIC: return a | b | c | MK_SPEC_BIT(MK_SPEC_EPS1) | MK_SPEC_BIT(MK_SPEC_EPS2) | mkSpecKeys_Pose(3);
	}
	return 0;
}

static const unsigned mkSpec_ShapeKeys = MK_SPEC_BIT(MK_SPEC_A) | MK_SPEC_BIT(MK_SPEC_B) | MK_SPEC_BIT(MK_SPEC_C)
	| MK_SPEC_BIT(MK_SPEC_EPS) | MK_SPEC_BIT(MK_SPEC_EPS1) | MK_SPEC_BIT(MK_SPEC_EPS2);

void mkSpecKeys_List(unsigned mask, char *buf, size_t len)
{
	buf[0] = 0;
	for (int i = 0; i < MK_SPEC_KEY_COUNT; ++i) {
		if (!(mask & 1u << i)) continue;
		size_t n = strlen(buf);
		snprintf(buf + n, len - n, "%s%s", n ? ", " : "", mkSpec_KeyNames[i]);
	}
}

int mkSpecKeys_Numbers(const char *s, size_t len, double *out, int max)
{
	char buf[SPEC_MAX_LEN];
	if (len == 0 || len >= sizeof buf) return -1;
	memcpy(buf, s, len);
	buf[len] = 0;
	int n = 0;
	char *p = buf;
	for (;;) {
		char *end;
		double v = strtod(p, &end);
		if (end == p || (*end != ',' && *end != 0)) return -1;
		if (n < max) out[n] = v;
		++n;
		if (*end == 0) break;
		p = end + 1;
	}
	return n;
}

/* Parse a comma-separated list of exactly `count` numbers; *got is how many
 * were given, -1 when the list is malformed. */
static int mkSpec_ParseNumbers(const char *s, size_t len, int count, double *out, int *got)
{
	*got = mkSpecKeys_Numbers(s, len, out, MK_SPEC_VALUES_MAX);
	return *got == count;
}

/* How many numbers key takes. */
static int mkSpecKeys_Count(int key, int dim)
{
	if (key == MK_SPEC_QUAT) return 4;
	if (key == MK_SPEC_M) return dim * dim;
	if (key == MK_SPEC_AT || key == MK_SPEC_SIZE) return dim;
	return 1;
}

mkResult mkSpecKeys_Parse(const char *text, int dim, const char *what, const char *kind, unsigned allow,
	mkSpecValues *v, char *msg, size_t msglen)
{
	const char *p = text;
	char keys[128];
	memset(v, 0, sizeof *v);
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
		for (int i = 0; i < MK_SPEC_KEY_COUNT; ++i)
			if (strlen(mkSpec_KeyNames[i]) == nl && strncmp(mkSpec_KeyNames[i], ts, nl) == 0) key = i;
		if (key < 0 || !(allow & 1u << key)) {
			mkSpecKeys_List(allow, keys, sizeof keys);
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: key '%.*s' is not allowed for %s: allowed keys are %s",
				what, (int)(nl > 32 ? 32 : nl), ts, kind, keys);
		}
		if (v->seen & 1u << key)
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: key '%s' is given twice", what, mkSpec_KeyNames[key]);
		v->seen |= 1u << key;
		int want = mkSpecKeys_Count(key, dim);
		size_t vl = tl - nl - 1;
		if (vl == 0)
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s.%s: missing value", what, mkSpec_KeyNames[key]);
		int got = 0;
		if (!mkSpec_ParseNumbers(eq + 1, vl, want, v->val[key], &got)) {
			if (got < 0)
				return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s.%s = '%.*s' is not a number%s", what, mkSpec_KeyNames[key],
					(int)(vl > 64 ? 64 : vl), eq + 1, want > 1 ? " list" : "");
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s.%s takes %d comma-separated number%s, got %d", what,
				mkSpec_KeyNames[key], want, want > 1 ? "s" : "", got);
		}
	}
	return MK_OK;
}

mkResult mkSpecKeys_Pose2(const mkSpecValues *v, const char *what, mkMat2 *M, mkVec2 *t, char *msg, size_t msglen)
{
	unsigned seen = v->seen;
	if ((seen & MK_SPEC_BIT(MK_SPEC_M)) && (seen & (MK_SPEC_BIT(MK_SPEC_ROT) | MK_SPEC_BIT(MK_SPEC_SHEAR))))
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: M replaces rot and shear: give one or the other", what);
	*M = mkMat2_Identity();
	if (seen & MK_SPEC_BIT(MK_SPEC_M)) {
		memcpy(&M->m[0][0], v->val[MK_SPEC_M], 4 * sizeof(double));
	} else {
		double rot = (seen & MK_SPEC_BIT(MK_SPEC_ROT)) ? v->val[MK_SPEC_ROT][0] : 0.0;
		double sh = (seen & MK_SPEC_BIT(MK_SPEC_SHEAR)) ? v->val[MK_SPEC_SHEAR][0] : 0.0;
		if (!isfinite(rot) || fabs(rot) > 1e6)
			return mkFail(MK_ERR_RANGE, msg, msglen, "%s.rot = %g is out of range: must be a finite angle in "
				"radians in [-1e6, 1e6]", what, rot);
		if (!isfinite(sh) || fabs(sh) > MK_MAP_ENTRY_MAX)
			return mkFail(MK_ERR_RANGE, msg, msglen, "%s.shear = %g is out of range: must be a finite number "
				"in [-%g, %g]", what, sh, MK_MAP_ENTRY_MAX, MK_MAP_ENTRY_MAX);
		*M = mkMat2_Mul(mkMat2_Rotation(rot), mkMat2_Shear(sh));
	}
	int at = (seen & MK_SPEC_BIT(MK_SPEC_AT)) != 0;
	t->x = at ? v->val[MK_SPEC_AT][0] : 0.0;
	t->y = at ? v->val[MK_SPEC_AT][1] : 0.0;
	return MK_OK;
}

mkResult mkSpecKeys_Pose3(const mkSpecValues *v, const char *what, mkMat3 *M, mkVec3 *t, char *msg, size_t msglen)
{
	unsigned seen = v->seen;
	if ((seen & MK_SPEC_BIT(MK_SPEC_M)) && (seen & MK_SPEC_BIT(MK_SPEC_QUAT)))
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: M replaces quat: give one or the other", what);
	*M = mkMat3_Identity();
	if (seen & MK_SPEC_BIT(MK_SPEC_M)) {
		memcpy(&M->m[0][0], v->val[MK_SPEC_M], 9 * sizeof(double));
	} else if (seen & MK_SPEC_BIT(MK_SPEC_QUAT)) {
		const double *q = v->val[MK_SPEC_QUAT];
		for (int i = 0; i < 4; ++i)
			if (!isfinite(q[i]) || fabs(q[i]) > 1e150)
				return mkFail(MK_ERR_RANGE, msg, msglen, "%s.quat component %d = %g is out of range: must be "
					"finite with magnitude at most 1e150", what, i + 1, q[i]);
		*M = mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
		if (!mkMat3_IsFinite(*M))
			return mkFail(MK_ERR_RANGE, msg, msglen, "%s.quat = %g,%g,%g,%g is zero: must be a nonzero "
				"quaternion w,x,y,z", what, q[0], q[1], q[2], q[3]);
	}
	int at = (seen & MK_SPEC_BIT(MK_SPEC_AT)) != 0;
	t->x = at ? v->val[MK_SPEC_AT][0] : 0.0;
	t->y = at ? v->val[MK_SPEC_AT][1] : 0.0;
	t->z = at ? v->val[MK_SPEC_AT][2] : 0.0;
	return MK_OK;
}

/* The kind at the start of text (*rest: what follows it), or -1 with a message. */
static int mkSpec_Kind(const char *text, int dim, const char *what, const char **rest, char *msg, size_t msglen)
{
	const char *p = text;
	while (isspace((unsigned char)*p)) ++p;
	const char *ks = p;
	while (*p && !isspace((unsigned char)*p)) ++p;
	size_t klen = (size_t)(p - ks);
	*rest = p;
	if (klen == 0)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: empty SPEC: expected 'KIND key=value ...' with KIND one of "
			"circle, ellipse, superellipse (2D), sphere, ellipsoid, superquadric (3D)", what), -1;
	int kind = -1;
	for (int i = 0; i < 6; ++i)
		if (strlen(mkSpec_KindNames[i]) == klen && strncmp(mkSpec_KindNames[i], ks, klen) == 0) kind = i;
	if (kind < 0)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: unknown kind '%.*s': must be one of circle, ellipse, "
			"superellipse (2D), sphere, ellipsoid, superquadric (3D)", what, (int)(klen > 64 ? 64 : klen), ks), -1;
	int kdim = kind <= MK_KIND_SUPERELLIPSE ? 2 : 3;
	if (kdim != dim)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: kind '%s' is %dD but the problem is %dD: use %s", what,
			mkSpec_KindNames[kind], kdim, dim, dim == 2 ? "circle, ellipse or superellipse" : "sphere, ellipsoid or superquadric"), -1;
	return kind;
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
	const char *p;
	int kind = mkSpec_Kind(text, dim, what, &p, msg, msglen);
	if (kind < 0) return MK_ERR_ARGUMENT;
	unsigned allow = mkSpec_AllowedKeys((mkKind)kind);
	mkSpecValues v;
	mkResult r = mkSpecKeys_Parse(p, dim, what, mkSpec_KindNames[kind], allow, &v, msg, msglen);
	if (r != MK_OK) return r;
	unsigned need = allow & mkSpec_ShapeKeys;
	if ((need & v.seen) != need) {
		char keys[128];
		mkSpecKeys_List(need & ~v.seen, keys, sizeof keys);
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: %s needs %s", what, mkSpec_KindNames[kind], keys);
	}
	out->dim = dim;
	out->kind = (mkKind)kind;
	double a = v.val[MK_SPEC_A][0];
	if (dim == 2) {
		mkBody2 *b = &out->body2;
		b->shape.a = a;
		b->shape.b = kind == MK_KIND_CIRCLE ? a : v.val[MK_SPEC_B][0];
		b->shape.eps = kind == MK_KIND_SUPERELLIPSE ? v.val[MK_SPEC_EPS][0] : 1.0;
		if ((r = mkSpecKeys_Pose2(&v, what, &b->M, &b->t, msg, msglen)) != MK_OK) return r;
		if (!mkBody2_IsValid(*b, what, msg, msglen)) return MK_ERR_RANGE;
	} else {
		mkBody3 *b = &out->body3;
		int sphere = kind == MK_KIND_SPHERE;
		b->shape.a = a;
		b->shape.b = sphere ? a : v.val[MK_SPEC_B][0];
		b->shape.c = sphere ? a : v.val[MK_SPEC_C][0];
		b->shape.eps1 = kind == MK_KIND_SUPERQUADRIC ? v.val[MK_SPEC_EPS1][0] : 1.0;
		b->shape.eps2 = kind == MK_KIND_SUPERQUADRIC ? v.val[MK_SPEC_EPS2][0] : 1.0;
		if ((r = mkSpecKeys_Pose3(&v, what, &b->M, &b->t, msg, msglen)) != MK_OK) return r;
		if (!mkBody3_IsValid(*b, what, msg, msglen)) return MK_ERR_RANGE;
	}
	return MK_OK;
}
