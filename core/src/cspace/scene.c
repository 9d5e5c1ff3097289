/* scene.c - scene files, box and cylinder bodies and their superquadric
 * models (derivation of the exponent and the scale: docs/scene.md). */
#include "mink/scene.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/message.h"
#include "shape/spec_keys.h"

const char *mkSceneBody_KindName(const mkSceneBody *b)
{
	if (!b) return "?";
	if (b->kind == MK_SCENE_BOX) return "box";
	if (b->kind == MK_SCENE_CYLINDER) return "cylinder";
	return mkKind_Name(b->spec.kind);
}

/* ---- bodies ------------------------------------------------------------------- */

/* Box and cylinder: the shape keys' ranges, then the pose on a unit body
 * (its shape fields unused), validated as every SPEC's. */
static mkResult mkSceneBody_ParseSolid(const char *text, int dim, const char *what, int box, mkSceneBody *out,
	char *msg, size_t msglen)
{
	const char *kind = box ? "box" : "cylinder";
	unsigned shape = box ? MK_SPEC_BIT(MK_SPEC_SIZE) : MK_SPEC_BIT(MK_SPEC_R) | MK_SPEC_BIT(MK_SPEC_H);
	mkSpecValues v;
	mkResult r = mkSpecKeys_Parse(text, dim, what, kind, shape | mkSpecKeys_Pose(dim), &v, msg, msglen);
	if (r != MK_OK) return r;
	if (box && !(v.seen & MK_SPEC_BIT(MK_SPEC_SIZE)))
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: box needs size=%s (full side lengths)", what,
			dim == 2 ? "l,w" : "l,w,h");
	if (!box && (v.seen & shape) != shape)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: cylinder needs %s", what,
			!(v.seen & MK_SPEC_BIT(MK_SPEC_R)) ? "r (the radius)" : "h (the full height)");
	/* box: size[0..dim); cylinder: size[0] the radius, size[1] the height */
	int n = box ? dim : 2;
	for (int i = 0; i < n; ++i) {
		int key = box ? MK_SPEC_SIZE : (i == 0 ? MK_SPEC_R : MK_SPEC_H);
		double val = v.val[key][box ? i : 0];
		double lo = key == MK_SPEC_R ? MK_AXIS_MIN : MK_SCENE_SIZE_MIN, hi = key == MK_SPEC_R ? MK_AXIS_MAX : MK_SCENE_SIZE_MAX;
		if (!(isfinite(val) && val >= lo && val <= hi)) {
			char field[32];
			if (box) snprintf(field, sizeof field, "size[%d]", i + 1);
			else snprintf(field, sizeof field, "%s", key == MK_SPEC_R ? "r" : "h");
			return mkFail(MK_ERR_RANGE, msg, msglen, "%s.%s = %.17g is out of range: must be a finite "
				"number in [%.10g, %.10g]", what, field, val, lo, hi);
		}
		out->size[i] = val;
	}
	out->kind = box ? MK_SCENE_BOX : MK_SCENE_CYLINDER;
	out->spec.dim = dim;
	if (dim == 2) {
		mkBody2 *b = &out->spec.body2;
		out->spec.kind = MK_KIND_ELLIPSE;
		b->shape = (mkShape2){1.0, 1.0, 1.0};
		if ((r = mkSpecKeys_Pose2(&v, what, &b->M, &b->t, msg, msglen)) != MK_OK) return r;
		return mkBody2_IsValid(*b, what, msg, msglen) ? MK_OK : MK_ERR_RANGE;
	}
	mkBody3 *b = &out->spec.body3;
	out->spec.kind = MK_KIND_ELLIPSOID;
	b->shape = (mkShape3){1.0, 1.0, 1.0, 1.0, 1.0};
	if ((r = mkSpecKeys_Pose3(&v, what, &b->M, &b->t, msg, msglen)) != MK_OK) return r;
	return mkBody3_IsValid(*b, what, msg, msglen) ? MK_OK : MK_ERR_RANGE;
}

mkResult mkSceneBody_Parse(const char *text, int dim, const char *what, mkSceneBody *out,
	char *msg, size_t msglen)
{
	if (!what) what = "body";
	if (!text || !out) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: no SPEC given", what);
	if (dim != 2 && dim != 3) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: dimension %d: must be 2 or 3", what, dim);
	memset(out, 0, sizeof *out);
	out->dim = dim;
	const char *p = text;
	while (isspace((unsigned char)*p)) ++p;
	const char *ks = p;
	while (*p && !isspace((unsigned char)*p)) ++p;
	size_t kl = (size_t)(p - ks);
	int box = kl == 3 && strncmp(ks, "box", 3) == 0;
	int cyl = kl == 8 && strncmp(ks, "cylinder", 8) == 0;
	if (!box && !cyl) {
		mkResult r = mkSpec_Parse(text, dim, what, &out->spec, msg, msglen);
		if (r != MK_OK && msg && strstr(msg, "unknown kind"))
			mkFail(r, msg, msglen, "%s: unknown kind '%.*s': must be one of %s", what, (int)(kl > 64 ? 64 : kl), ks,
				dim == 2 ? "circle, ellipse, superellipse, box" : "sphere, ellipsoid, superquadric, box, cylinder");
		out->kind = MK_SCENE_SMOOTH;
		return r;
	}
	if (cyl && dim != 3)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: kind 'cylinder' is 3D but the scene is 2D: use circle, "
			"ellipse, superellipse or box", what);
	if (strlen(p) > 4096)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: SPEC is longer than %d characters", what, 4096);
	return mkSceneBody_ParseSolid(p, dim, what, box, out, msg, msglen);
}

/* ---- models -------------------------------------------------------------------- */

/* Largest eigenvalue of a symmetric 2x2 [p r; r q]. */
static double mkSym2_MaxEigen(double p, double q, double r)
{
	return 0.5 * (p + q) + sqrt(0.25 * (p - q) * (p - q) + r * r);
}

/* The largest |M x| over the placed shape's points x (the support radius
 * about its centre), exact for boxes, an upper bound (exact for rigid maps)
 * for cylinders. */
static double mkBox2_Reach(mkMat2 M, double a, double b)
{
	double best = 0.0;
	for (int s = 0; s < 4; ++s) {
		mkVec2 c = {(s & 1) ? -a : a, (s & 2) ? -b : b};
		double l = mkVec2_Length(mkMat2_MulVec(M, c));
		if (l > best) best = l;
	}
	return best;
}

static double mkBox3_Reach(mkMat3 M, double a, double b, double c)
{
	double best = 0.0;
	for (int s = 0; s < 8; ++s) {
		mkVec3 v = {(s & 1) ? -a : a, (s & 2) ? -b : b, (s & 4) ? -c : c};
		double l = mkVec3_Length(mkMat3_MulVec(M, v));
		if (l > best) best = l;
	}
	return best;
}

/* Rim points R M12 w +- c M e3 (|w| = 1): |.|^2 <= R^2 s^2 + 2 R c |M12^T M e3| + c^2 |M e3|^2
 * with s the largest singular value of the first two columns M12. */
static double mkCylinder3_Reach(mkMat3 M, double R, double c)
{
	mkVec3 c1 = {M.m[0][0], M.m[1][0], M.m[2][0]}, c2 = {M.m[0][1], M.m[1][1], M.m[2][1]};
	mkVec3 c3 = {M.m[0][2], M.m[1][2], M.m[2][2]};
	double s2 = mkSym2_MaxEigen(mkVec3_Dot(c1, c1), mkVec3_Dot(c2, c2), mkVec3_Dot(c1, c2));
	double cr = hypot(mkVec3_Dot(c1, c3), mkVec3_Dot(c2, c3));
	return sqrt(R * R * s2 + 2.0 * R * c * cr + c * c * mkVec3_Dot(c3, c3));
}

/* Exponent eps = 2/p of the model for the relative error f = delta / D, with
 * `terms` the number of p-power terms of the norm (2: box2D, cylinder; 3:
 * box3D). Inner: the deviation is D (1 - terms^(-1/p)); outer (scaled by
 * terms^(1/p)): at most D (terms^(1/p) - 1). Capped at 1 (the ellipse),
 * which the closed forms treat exactly and cheaply. */
static double mkModel_Exponent(double f, int terms, mkBound side)
{
	double lt = log((double)terms);
	double inv_p = side == MK_BOUND_INNER ? (f >= 1.0 ? INFINITY : -log1p(-f) / lt) : log1p(f) / lt;
	/* a hair smaller, so that rounding cannot push the error above delta */
	double eps = 2.0 * inv_p * (1.0 - 1e-9);
	return eps > 1.0 ? 1.0 : eps;
}

static double mkModel_Error(double D, double eps, int terms, mkBound side)
{
	double e = pow((double)terms, 0.5 * eps); /* terms^(1/p) */
	return side == MK_BOUND_INNER ? D * (1.0 - 1.0 / e) : D * (e - 1.0);
}

mkResult mkSceneBody2_Model(const mkSceneBody *b, double delta, mkBound side, mkBody2 *out,
	double *error, char *msg, size_t msglen)
{
	if (!b || !out || !error || b->dim != 2) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "model: not a 2D body");
	if (b->kind == MK_SCENE_SMOOTH) { *out = b->spec.body2; *error = 0.0; return MK_OK; }
	if (!(delta > 0.0) || !isfinite(delta)) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "model: tolerance %g must be positive", delta);
	double a = 0.5 * b->size[0], bb = 0.5 * b->size[1];
	mkMat2 M = b->spec.body2.M;
	double D = mkBox2_Reach(M, a, bb);
	double eps = mkModel_Exponent(delta / D, 2, side);
	if (!(eps >= MK_EPS_MIN))
		return mkFail(MK_ERR_RANGE, msg, msglen, "box model: tolerance %g is too small for a box of reach %g: "
			"the model exponent would be %g, below %g", delta, D, eps, MK_EPS_MIN);
	double s = side == MK_BOUND_INNER ? 1.0 : pow(2.0, 0.5 * eps);
	mkShape2 sh = {s * a, s * bb, eps};
	*out = mkBody2_Make(sh, M, b->spec.body2.t);
	*error = mkModel_Error(D, eps, 2, side);
	return MK_OK;
}

mkResult mkSceneBody3_Model(const mkSceneBody *b, double delta, mkBound side, mkBody3 *out,
	double *error, char *msg, size_t msglen)
{
	if (!b || !out || !error || b->dim != 3) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "model: not a 3D body");
	if (b->kind == MK_SCENE_SMOOTH) { *out = b->spec.body3; *error = 0.0; return MK_OK; }
	if (!(delta > 0.0) || !isfinite(delta)) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "model: tolerance %g must be positive", delta);
	mkMat3 M = b->spec.body3.M;
	int terms;
	double a, bb, c, D;
	if (b->kind == MK_SCENE_BOX) {
		a = 0.5 * b->size[0]; bb = 0.5 * b->size[1]; c = 0.5 * b->size[2];
		D = mkBox3_Reach(M, a, bb, c);
		terms = 3;
	} else {
		a = bb = b->size[0]; c = 0.5 * b->size[1];
		D = mkCylinder3_Reach(M, a, c);
		terms = 2;
	}
	double eps = mkModel_Exponent(delta / D, terms, side);
	if (!(eps >= MK_EPS_MIN))
		return mkFail(MK_ERR_RANGE, msg, msglen, "%s model: tolerance %g is too small for a body of reach %g: "
			"the model exponent would be %g, below %g", mkSceneBody_KindName(b), delta, D, eps, MK_EPS_MIN);
	double s = side == MK_BOUND_INNER ? 1.0 : pow((double)terms, 0.5 * eps);
	/* box: |x/a|^p + |y/b|^p + |z/c|^p (eps1 = eps2 = eps); cylinder: the
	 * round cross-section eps2 = 1 with rho^p + |z/c|^p (eps1 = eps). */
	mkShape3 sh = {s * a, s * bb, s * c, eps, b->kind == MK_SCENE_BOX ? eps : 1.0};
	*out = mkBody3_Make(sh, M, b->spec.body3.t);
	*error = mkModel_Error(D, eps, terms, side);
	return MK_OK;
}

/* ---- scene files ---------------------------------------------------------------- */

void mkScene_Free(mkScene *s)
{
	if (!s) return;
	free(s->obstacles);
	free(s->parts);
	free(s->obstacle_object);
	free(s->objects);
	free(s->queries);
	free(s->headings);
	free(s->rotations);
	memset(s, 0, sizeof *s);
}

mkMat2 mkScene2_Orientation(const mkScene *s, int o) { return mkMat2_Rotation(s->headings[o]); }
mkMat3 mkScene3_Orientation(const mkScene *s, int o) { return s->rotations[o]; }

/* The next line of text (without its newline and comment), trimmed;
 * returns 0 at the end. */
static int mkScene_NextLine(const char **cursor, char *buf, size_t len, int *too_long)
{
	const char *p = *cursor;
	if (!*p) return 0;
	const char *e = strchr(p, '\n');
	size_t n = e ? (size_t)(e - p) : strlen(p);
	*cursor = e ? e + 1 : p + n;
	const char *hash = memchr(p, '#', n);
	if (hash) n = (size_t)(hash - p);
	*too_long = n >= len;
	if (*too_long) n = len - 1;
	memcpy(buf, p, n);
	buf[n] = 0;
	while (n && isspace((unsigned char)buf[n - 1])) buf[--n] = 0;
	size_t s = 0;
	while (buf[s] && isspace((unsigned char)buf[s])) ++s;
	if (s) memmove(buf, buf + s, n - s + 1);
	return 1;
}

static int mkScene_Grow(void **arr, int *cap, int need, size_t elem)
{
	if (need <= *cap) return 1;
	int nc = *cap ? *cap * 2 : 16;
	while (nc < need) nc *= 2;
	void *p = realloc(*arr, (size_t)nc * elem);
	if (!p) return 0;
	*arr = p;
	*cap = nc;
	return 1;
}

static int mkScene_IsRotation(mkMat3 R)
{
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) {
			double d = 0.0;
			for (int k = 0; k < 3; ++k) d += R.m[k][i] * R.m[k][j];
			if (!(fabs(d - (i == j)) <= 1e-6)) return 0;
		}
	return fabs(mkMat3_Det(R) - 1.0) <= 1e-6;
}

/* A quaternion "w,x,y,z" (4 numbers already parsed) into *R; 0 if zero or not finite. */
static int mkScene_QuatRotation(const double *q, mkMat3 *R)
{
	for (int i = 0; i < 4; ++i)
		if (!isfinite(q[i]) || fabs(q[i]) > 1e150) return 0;
	*R = mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
	return mkMat3_IsFinite(*R);
}

/* `headings N` or `headings a1,a2,...` into s; a failure's message in err. */
static mkResult mkScene_ParseHeadings(mkScene *s, int *hcap, const char *arg, char *err, size_t errlen)
{
	if (!strchr(arg, ',') && !strchr(arg, '.') && !strchr(arg, 'e') && !strchr(arg, 'E')) {
		char *end;
		errno = 0;
		long n = strtol(arg, &end, 10);
		if (*end || end == arg || errno || n < 1 || n > MK_SCENE_HEADINGS_MAX)
			return mkFail(MK_ERR_RANGE, err, errlen, "headings = '%.40s' is out of range: must be an integer N in "
				"[1, %d] or a comma-separated list of angles in radians", arg, MK_SCENE_HEADINGS_MAX);
		if (!mkScene_Grow((void **)&s->headings, hcap, (int)n, sizeof *s->headings))
			return mkFail(MK_ERR_MEMORY, err, errlen, "out of memory");
		for (long k = 0; k < n; ++k) s->headings[k] = 2.0 * MK_PI * (double)k / (double)n;
		s->orientation_count = (int)n;
		return MK_OK;
	}
	const char *p = arg;
	for (;;) {
		char *end;
		double v = strtod(p, &end);
		if (end == p || (*end != ',' && *end != 0))
			return mkFail(MK_ERR_ARGUMENT, err, errlen, "headings: item %d '%.20s' is not a number: must be an angle "
				"in radians", s->orientation_count + 1, p);
		if (!isfinite(v) || fabs(v) > MK_SCENE_ANGLE_MAX)
			return mkFail(MK_ERR_RANGE, err, errlen, "headings: item %d = %g is out of range: must be a finite angle "
				"in radians in [-%g, %g]", s->orientation_count + 1, v, MK_SCENE_ANGLE_MAX, MK_SCENE_ANGLE_MAX);
		if (!mkScene_Grow((void **)&s->headings, hcap, s->orientation_count + 1, sizeof *s->headings))
			return mkFail(MK_ERR_MEMORY, err, errlen, "out of memory");
		s->headings[s->orientation_count++] = v;
		if (!*end) return MK_OK;
		p = end + 1;
	}
}

/* `quaternions w,x,y,z;...` into s; a failure's message in err. */
static mkResult mkScene_ParseQuaternions(mkScene *s, int *rcap, const char *arg, char *err, size_t errlen)
{
	const char *p = arg;
	for (;;) {
		const char *semi = strchr(p, ';');
		size_t len = semi ? (size_t)(semi - p) : strlen(p);
		while (len && isspace((unsigned char)*p)) { ++p; --len; }
		while (len && isspace((unsigned char)p[len - 1])) --len;
		double q[4];
		int got = mkSpecKeys_Numbers(p, len, q, 4);
		int item = s->orientation_count + 1;
		if (got != 4)
			return mkFail(MK_ERR_ARGUMENT, err, errlen, "quaternions: item %d '%.*s' must be 4 comma-separated numbers "
				"w,x,y,z", item, (int)(len > 40 ? 40 : len), p);
		mkMat3 R;
		if (!mkScene_QuatRotation(q, &R))
			return mkFail(MK_ERR_RANGE, err, errlen, "quaternions: item %d = %g,%g,%g,%g is out of range: must be a "
				"nonzero quaternion with finite components of magnitude at most 1e150", item, q[0], q[1], q[2], q[3]);
		if (!mkScene_Grow((void **)&s->rotations, rcap, s->orientation_count + 1, sizeof *s->rotations))
			return mkFail(MK_ERR_MEMORY, err, errlen, "out of memory");
		s->rotations[s->orientation_count++] = R;
		if (!semi || !semi[1]) return MK_OK;
		p = semi + 1;
	}
}

/* The parser's state of robot, part, object and obstacle lines. */
typedef struct mkSceneParser {
	int ocap, pcap, jcap;
	int robot_line, part_line;
	int object, object_used;   /* the current `object` (-1: none) and whether an obstacle followed it */
} mkSceneParser;

/* A new object named name (line 0: an obstacle of its own); its index or -1 when out of memory. */
static int mkScene_AddObject(mkScene *s, mkSceneParser *P, const char *name, int line)
{
	if (!mkScene_Grow((void **)&s->objects, &P->jcap, s->object_count + 1, sizeof *s->objects)) return -1;
	mkSceneObject *o = &s->objects[s->object_count];
	snprintf(o->name, sizeof o->name, "%s", name);
	o->line = line;
	return s->object_count++;
}

static mkResult mkScene_ParseObject(mkScene *s, mkSceneParser *P, const char *arg, int lineno, char *err, size_t errlen)
{
	size_t n = strlen(arg);
	if (P->object >= 0 && !P->object_used)
		return mkFail(MK_ERR_ARGUMENT, err, errlen, "object '%s' (line %d) has no obstacle lines: an object is followed "
			"by its obstacles", s->objects[P->object].name, s->objects[P->object].line);
	int ok = n >= 1 && n < MK_SCENE_NAME_MAX;
	for (size_t k = 0; ok && k < n; ++k) ok = isalnum((unsigned char)arg[k]) || strchr("_.-", arg[k]) != NULL;
	if (!ok)
		return mkFail(MK_ERR_ARGUMENT, err, errlen, "object name '%.40s' is not allowed: must be 1 to %d characters of "
			"A-Z, a-z, 0-9, _ . -", arg, MK_SCENE_NAME_MAX - 1);
	for (int k = 0; k < s->object_count; ++k)
		if (strcmp(s->objects[k].name, arg) == 0)
			return s->objects[k].line
				? mkFail(MK_ERR_ARGUMENT, err, errlen, "object '%s' is given twice (first on line %d): names must differ",
					arg, s->objects[k].line)
				: mkFail(MK_ERR_ARGUMENT, err, errlen, "object '%s' is the name of an obstacle of its own: names must "
					"differ", arg);
	if ((P->object = mkScene_AddObject(s, P, arg, lineno)) < 0) return mkFail(MK_ERR_MEMORY, err, errlen, "out of memory");
	P->object_used = 0;
	return MK_OK;
}

/* A robot, part, object or obstacle line (kw says which) into s. */
static mkResult mkScene_ParseBodyLine(mkScene *s, mkSceneParser *P, const char *kw, const char *arg, int lineno,
	char *err, size_t errlen)
{
	char what[32];
	if (strcmp(kw, "object") == 0) return mkScene_ParseObject(s, P, arg, lineno, err, errlen);
	if (strcmp(kw, "robot") == 0 || strcmp(kw, "part") == 0) {
		int part = kw[0] == 'p';
		if (P->robot_line)
			return mkFail(MK_ERR_ARGUMENT, err, errlen, "%s: the robot is already given on line %d: a robot is one "
				"'robot SPEC' line or one or more 'part SPEC' lines", kw, P->robot_line);
		if (!part && P->part_line)
			return mkFail(MK_ERR_ARGUMENT, err, errlen, "robot: the robot's parts are given (first on line %d): a robot "
				"is one 'robot SPEC' line or one or more 'part SPEC' lines", P->part_line);
		if (s->part_count >= MK_SCENE_PARTS_MAX)
			return mkFail(MK_ERR_RANGE, err, errlen, "more than %d robot parts", MK_SCENE_PARTS_MAX);
		if (!mkScene_Grow((void **)&s->parts, &P->pcap, s->part_count + 1, sizeof *s->parts))
			return mkFail(MK_ERR_MEMORY, err, errlen, "out of memory");
		if (part) snprintf(what, sizeof what, "part%d", s->part_count);
		else snprintf(what, sizeof what, "robot");
		mkSceneBody *b = &s->parts[s->part_count];
		mkResult r = mkSceneBody_Parse(arg, s->dim, what, b, err, errlen);
		if (r != MK_OK) return r;
		if (!part) { /* robot keeps the text; the part's position is the configuration's */
			s->robot = *b;
			if (s->dim == 2) b->spec.body2.t = mkVec2_Make(0.0, 0.0);
			else b->spec.body3.t = mkVec3_Make(0.0, 0.0, 0.0);
			P->robot_line = lineno;
		} else if (!P->part_line) {
			P->part_line = lineno;
		}
		++s->part_count;
		return MK_OK;
	}
	snprintf(what, sizeof what, "obstacle%d", s->obstacle_count);
	if (s->obstacle_count >= 100000000) return mkFail(MK_ERR_RANGE, err, errlen, "more than 100000000 obstacles");
	int cap = P->ocap;
	if (!mkScene_Grow((void **)&s->obstacles, &P->ocap, s->obstacle_count + 1, sizeof *s->obstacles)
		|| !mkScene_Grow((void **)&s->obstacle_object, &cap, s->obstacle_count + 1, sizeof *s->obstacle_object))
		return mkFail(MK_ERR_MEMORY, err, errlen, "out of memory");
	mkResult r = mkSceneBody_Parse(arg, s->dim, what, &s->obstacles[s->obstacle_count], err, errlen);
	if (r != MK_OK) return r;
	int obj = P->object;
	if (obj < 0 && (obj = mkScene_AddObject(s, P, what, 0)) < 0) return mkFail(MK_ERR_MEMORY, err, errlen, "out of memory");
	P->object_used = 1;
	s->obstacle_object[s->obstacle_count++] = obj;
	return MK_OK;
}

/* ---- planning problems ---- */

/* A pose "x,y,theta" or "x,y,z,qw,qx,qy,qz" into p, in the bounds when known. */
static mkResult mkScene_ParsePose(const mkScene *s, const char *kw, const char *arg, double *p, char *err, size_t errlen)
{
	int n = s->dim == 2 ? 3 : 7;
	const char *form = s->dim == 2 ? "x,y,theta" : "x,y,z,qw,qx,qy,qz";
	if (mkSpecKeys_Numbers(arg, strlen(arg), p, n) != n)
		return mkFail(MK_ERR_ARGUMENT, err, errlen, "%s = '%.60s' must be %d comma-separated numbers %s", kw, arg, n, form);
	for (int k = 0; k < n; ++k)
		if (!isfinite(p[k]) || fabs(p[k]) > 1e15)
			return mkFail(MK_ERR_RANGE, err, errlen, "%s[%d] = %g is out of range: must be a finite number of magnitude at "
				"most 1e15", kw, k + 1, p[k]);
	if (s->dim == 3 && p[3] == 0.0 && p[4] == 0.0 && p[5] == 0.0 && p[6] == 0.0)
		return mkFail(MK_ERR_RANGE, err, errlen, "%s: the quaternion qw,qx,qy,qz = 0,0,0,0 is out of range: must be nonzero", kw);
	return MK_OK;
}

/* The position of pose p is in the bounds: 1, or 0 with the message. */
static int mkScene_InBounds(const mkScene *s, const char *kw, const double *p, char *err, size_t errlen)
{
	static const char axis[3] = {'x', 'y', 'z'};
	for (int d = 0; d < s->dim; ++d)
		if (!(p[d] >= s->bounds_lo[d] && p[d] <= s->bounds_hi[d])) {
			mkFail(MK_ERR_RANGE, err, errlen, "%s.%c = %g is out of range: must be in the bounds [%g, %g] (line %d)", kw,
				axis[d], p[d], s->bounds_lo[d], s->bounds_hi[d], s->bounds_line);
			return 0;
		}
	return 1;
}

/* bounds, start and goal lines. *start: the last start (NULL before one). */
static mkResult mkScene_ParsePlanLine(mkScene *s, int *qcap, double *start, int *start_line, const char *kw,
	const char *arg, int lineno, char *err, size_t errlen)
{
	if (strcmp(kw, "bounds") == 0) {
		double v[6];
		int n = 2 * s->dim;
		if (s->bounds_line) return mkFail(MK_ERR_ARGUMENT, err, errlen, "bounds are given twice (first on line %d)", s->bounds_line);
		if (s->query_count || *start_line)
			return mkFail(MK_ERR_ARGUMENT, err, errlen, "bounds must come before the first start and goal");
		if (mkSpecKeys_Numbers(arg, strlen(arg), v, n) != n)
			return mkFail(MK_ERR_ARGUMENT, err, errlen, "bounds = '%.60s' must be %d comma-separated numbers %s", arg, n,
				s->dim == 2 ? "xlo,xhi,ylo,yhi" : "xlo,xhi,ylo,yhi,zlo,zhi");
		for (int d = 0; d < s->dim; ++d) {
			if (!(isfinite(v[2 * d]) && isfinite(v[2 * d + 1]) && v[2 * d] < v[2 * d + 1] && fabs(v[2 * d]) <= 1e15
				&& fabs(v[2 * d + 1]) <= 1e15))
				return mkFail(MK_ERR_RANGE, err, errlen, "bounds[%d..%d] = %g,%g is out of range: must be finite, lo < hi, "
					"magnitude at most 1e15", 2 * d + 1, 2 * d + 2, v[2 * d], v[2 * d + 1]);
			s->bounds_lo[d] = v[2 * d];
			s->bounds_hi[d] = v[2 * d + 1];
		}
		s->bounds_line = lineno;
		return MK_OK;
	}
	if (!s->bounds_line)
		return mkFail(MK_ERR_ARGUMENT, err, errlen, "%s before bounds: a planning scene gives 'bounds' first", kw);
	double p[7] = {0, 0, 0, 0, 0, 0, 0};
	mkResult r = mkScene_ParsePose(s, kw, arg, p, err, errlen);
	if (r != MK_OK) return r;
	if (!mkScene_InBounds(s, kw, p, err, errlen)) return MK_ERR_RANGE;
	if (kw[0] == 's') {
		memcpy(start, p, sizeof p);
		*start_line = lineno;
		return MK_OK;
	}
	if (!*start_line) return mkFail(MK_ERR_ARGUMENT, err, errlen, "goal without a start: a 'start POSE' line comes first");
	if (!mkScene_Grow((void **)&s->queries, qcap, s->query_count + 1, sizeof *s->queries))
		return mkFail(MK_ERR_MEMORY, err, errlen, "out of memory");
	mkScenePlanQuery *q = &s->queries[s->query_count++];
	memcpy(q->start, start, sizeof q->start);
	memcpy(q->goal, p, sizeof q->goal);
	q->start_line = *start_line;
	q->goal_line = lineno;
	return MK_OK;
}

mkResult mkScene_Parse(const char *text, mkScene *out, char *msg, size_t msglen)
{
	if (!out) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "no scene");
	memset(out, 0, sizeof *out);
	if (!text) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "no scene text");
	char *line = malloc(MK_SCENE_LINE_MAX);
	if (!line) return mkFail(MK_ERR_MEMORY, msg, msglen, "out of memory");
	mkScene s;
	memset(&s, 0, sizeof s);
	int hcap = 0, rcap = 0, orient_line = 0;
	mkSceneParser P;
	memset(&P, 0, sizeof P);
	P.object = -1;
	int qcap = 0, start_line = 0;
	double start[7];
	int lineno = 0, too_long = 0;
	const char *cur = text;
	mkResult r = MK_OK;
#define BAD(code, ...) do { r = (code); char b_[1024]; snprintf(b_, sizeof b_, __VA_ARGS__); \
	mkFail(r, msg, msglen, "line %d: %s", lineno, b_); goto done; } while (0)
	while (mkScene_NextLine(&cur, line, MK_SCENE_LINE_MAX, &too_long)) {
		++lineno;
		if (too_long) BAD(MK_ERR_ARGUMENT, "line is longer than %d characters", MK_SCENE_LINE_MAX - 1);
		if (!line[0]) continue;
		char *arg = line;
		while (*arg && !isspace((unsigned char)*arg)) ++arg;
		size_t kl = (size_t)(arg - line);
		while (isspace((unsigned char)*arg)) ++arg;
#define KW(w) (kl == strlen(w) && strncmp(line, w, kl) == 0)
		if (!s.dim) {
			if (!KW("dim"))
				BAD(MK_ERR_ARGUMENT, "the first line must be 'dim 2' or 'dim 3', got '%.40s'", line);
			if (strcmp(arg, "2") == 0) s.dim = 2;
			else if (strcmp(arg, "3") == 0) s.dim = 3;
			else BAD(MK_ERR_RANGE, "dim = '%.40s' is out of range: must be 2 or 3", arg);
			continue;
		}
		if (!*arg && !KW("dim"))
			BAD(MK_ERR_ARGUMENT, "'%.*s' needs a value", (int)(kl > 40 ? 40 : kl), line);
		if (KW("dim")) {
			BAD(MK_ERR_ARGUMENT, "dim is given twice (first line only)");
		} else if (KW("robot") || KW("part") || KW("object") || KW("obstacle")) {
			char kw[16];
			snprintf(kw, sizeof kw, "%.*s", (int)kl, line);
			char err[1024];
			mkResult br = mkScene_ParseBodyLine(&s, &P, kw, arg, lineno, err, sizeof err);
			if (br != MK_OK) BAD(br, "%s", err);
		} else if (KW("bounds") || KW("start") || KW("goal")) {
			char kw[16], err[1024];
			snprintf(kw, sizeof kw, "%.*s", (int)kl, line);
			mkResult pr = mkScene_ParsePlanLine(&s, &qcap, start, &start_line, kw, arg, lineno, err, sizeof err);
			if (pr != MK_OK) BAD(pr, "%s", err);
		} else if (KW("headings") || KW("quaternions") || KW("rotations")) {
			const char *kw = KW("headings") ? "headings" : KW("quaternions") ? "quaternions" : "rotations";
			if (s.dim == 2 && !KW("headings"))
				BAD(MK_ERR_ARGUMENT, "'%s' is for 3D scenes: a 2D scene gives 'headings N' or 'headings a1,a2,...'", kw);
			if (s.dim == 3 && KW("headings"))
				BAD(MK_ERR_ARGUMENT, "'headings' is for 2D scenes: a 3D scene gives 'quaternions w,x,y,z;...' or 'rotations FILE'");
			if (orient_line) BAD(MK_ERR_ARGUMENT, "orientations are given twice (first on line %d)", orient_line);
			orient_line = lineno;
			char err[1024];
			mkResult hr = MK_OK;
			if (KW("headings")) hr = mkScene_ParseHeadings(&s, &hcap, arg, err, sizeof err);
			else if (KW("quaternions")) hr = mkScene_ParseQuaternions(&s, &rcap, arg, err, sizeof err);
			if (hr != MK_OK) BAD(hr, "%s", err);
			if (KW("rotations")) {
				if (strlen(arg) >= sizeof s.rotations_file)
					BAD(MK_ERR_ARGUMENT, "rotations: file name longer than %d characters", (int)sizeof s.rotations_file - 1);
				snprintf(s.rotations_file, sizeof s.rotations_file, "%s", arg);
				s.rotations_line = lineno;
			}
		} else {
			BAD(MK_ERR_ARGUMENT, "unknown keyword '%.*s': must be one of dim, robot, part, object, obstacle, bounds, start, goal, %s",
				(int)(kl > 40 ? 40 : kl), line, s.dim == 2 ? "headings" : "quaternions, rotations");
		}
#undef KW
	}
	if (!s.dim) BAD(MK_ERR_ARGUMENT, "empty scene: the first line must be 'dim 2' or 'dim 3'");
	if (!s.part_count) BAD(MK_ERR_ARGUMENT, "no robot: a scene needs one line 'robot SPEC' or 'part SPEC' lines");
	if (P.object >= 0 && !P.object_used)
		BAD(MK_ERR_ARGUMENT, "object '%s' (line %d) has no obstacle lines: an object is followed by its obstacles",
			s.objects[P.object].name, s.objects[P.object].line);
	if (!P.robot_line) s.robot = s.parts[0];
	if (start_line && (!s.query_count || s.queries[s.query_count - 1].start_line != start_line)) {
		lineno = start_line;
		BAD(MK_ERR_ARGUMENT, "start without a goal: a 'goal POSE' line follows each start");
	}
	if (!orient_line && !s.query_count)
		BAD(MK_ERR_ARGUMENT, "no orientations: %s", s.dim == 2 ? "a 2D scene needs 'headings N' or 'headings a1,a2,...'"
			: "a 3D scene needs 'quaternions w,x,y,z;...' or 'rotations FILE'");
#undef BAD
done:
	free(line);
	if (r != MK_OK) {
		mkScene_Free(&s);
		return r;
	}
	*out = s;
	return MK_OK;
}

mkResult mkScene_SetRotations(mkScene *s, const char *text, const char *name, char *msg, size_t msglen)
{
	if (!s || s->dim != 3 || !text) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "rotations: not a 3D scene");
	if (!name) name = "rotations";
	char line[4096];
	const char *cur = text;
	int lineno = 0, too_long = 0, count = 0, cap = 0, first = 1;
	mkMat3 *rot = NULL;
	while (mkScene_NextLine(&cur, line, sizeof line, &too_long)) {
		++lineno;
		if (!line[0]) continue;
		if (too_long) { free(rot); return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s:%d: line too long", name, lineno); }
		double v[9];
		int got = mkSpecKeys_Numbers(line, strlen(line), v, 9);
		if (got < 0 && first) { first = 0; continue; } /* a header */
		first = 0;
		mkMat3 R;
		if (got == 9) {
			for (int i = 0; i < 9; ++i) R.m[i / 3][i % 3] = v[i];
			if (!mkScene_IsRotation(R)) {
				free(rot);
				return mkFail(MK_ERR_RANGE, msg, msglen, "%s:%d: the matrix is not a rotation: must have R^T R = I and "
					"det R = 1 to within 1e-6", name, lineno);
			}
		} else if (got == 4) {
			if (!mkScene_QuatRotation(v, &R)) {
				free(rot);
				return mkFail(MK_ERR_RANGE, msg, msglen, "%s:%d: quaternion %g,%g,%g,%g is out of range: must be nonzero "
					"and finite", name, lineno, v[0], v[1], v[2], v[3]);
			}
		} else {
			free(rot);
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s:%d: expected 9 comma-separated numbers r11,...,r33 or a "
				"quaternion w,x,y,z, got '%.40s'", name, lineno, line);
		}
		if (!mkScene_Grow((void **)&rot, &cap, count + 1, sizeof *rot)) {
			free(rot);
			return mkFail(MK_ERR_MEMORY, msg, msglen, "out of memory");
		}
		rot[count++] = R;
	}
	if (!count) { free(rot); return mkFail(MK_ERR_ARGUMENT, msg, msglen, "%s: no rotations in the file", name); }
	free(s->rotations);
	s->rotations = rot;
	s->orientation_count = count;
	return MK_OK;
}
