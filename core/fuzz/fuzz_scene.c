/* fuzz_scene.c - libFuzzer harness over the scene file parser
 * (mkScene_Parse), its rotations files (mkScene_SetRotations) and the
 * models a prepared scene makes of its bodies (mkCSpace_Create).
 *
 * The input bytes up to the first NUL are the scene file's text; the bytes
 * after it are the text of the rotations file, read when the scene names
 * one (`rotations FILE`, 3D). Each text is copied into a heap buffer of
 * exactly its length + 1 (NUL-terminated), so that AddressSanitizer catches
 * a read past the terminator; messages go to buffers of exactly their
 * declared length.
 *
 * Contract checked (scene.h, cobstacle.h):
 *  - every call returns MK_OK, MK_ERR_ARGUMENT or MK_ERR_RANGE (Create also
 *    MK_ERR_UNSUPPORTED), the same verdict whatever the message buffer, and
 *    on failure a NUL-terminated, non-empty message within its buffer;
 *  - a failed parse leaves the scene empty (nothing to free);
 *  - a parsed scene has dimension 2 or 3, a valid robot, valid parts and
 *    valid obstacles (mkBody*_IsValid on the smooth ones), each obstacle in
 *    an object with a terminated name, bounds with lo < hi, finite start and
 *    goal poses with their lines, finite headings, and rotations that are
 *    rotations (R^T R = I to 1e-5, det R = 1) once set;
 *  - mkCSpace_Create at two tolerances either prepares the scene or fails
 *    with a message.
 * A violation aborts, which libFuzzer reports as a crash with its input. */
#include <mink/cspace.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_CHECK(expr) do { \
	if (!(expr)) { \
		fprintf(stderr, "fuzz_scene: check failed: %s\n", #expr); \
		abort(); \
	} \
} while (0)

static char *fuzzText(const uint8_t *data, size_t size)
{
	char *t = malloc(size + 1);
	if (!t) return NULL;
	memcpy(t, data, size);
	t[size] = '\0';
	return t;
}

static void fuzzCheckFailure(mkResult r, const char *msg, size_t len)
{
	FUZZ_CHECK(r == MK_ERR_ARGUMENT || r == MK_ERR_RANGE);
	FUZZ_CHECK(memchr(msg, '\0', len) != NULL);
	FUZZ_CHECK(len < 2 || msg[0] != '\0');
}

static void fuzzCheckBody(const mkSceneBody *b, int dim)
{
	FUZZ_CHECK(b->dim == dim);
	if (b->kind == MK_SCENE_SMOOTH)
		FUZZ_CHECK(dim == 2 ? mkBody2_IsValid(b->spec.body2, "b", NULL, 0) : mkBody3_IsValid(b->spec.body3, "b", NULL, 0));
	else
		FUZZ_CHECK(b->kind == MK_SCENE_BOX || (dim == 3 && b->kind == MK_SCENE_CYLINDER));
}

static void fuzzCheckScene(const mkScene *s)
{
	FUZZ_CHECK(s->dim == 2 || s->dim == 3);
	fuzzCheckBody(&s->robot, s->dim);
	FUZZ_CHECK(s->part_count >= 1 && s->parts != NULL);
	for (int j = 0; j < s->part_count; ++j) fuzzCheckBody(&s->parts[j], s->dim);
	FUZZ_CHECK(s->obstacle_count >= 0);
	for (int i = 0; i < s->obstacle_count; ++i) {
		fuzzCheckBody(&s->obstacles[i], s->dim);
		FUZZ_CHECK(s->obstacle_object[i] >= 0 && s->obstacle_object[i] < s->object_count);
		FUZZ_CHECK(memchr(s->objects[s->obstacle_object[i]].name, '\0', sizeof s->objects[0].name) != NULL);
	}
	FUZZ_CHECK(s->query_count >= 0 && (s->query_count == 0 || s->queries != NULL));
	int pose = s->dim == 2 ? 3 : 7;
	if (s->bounds_line > 0)
		for (int i = 0; i < s->dim; ++i) FUZZ_CHECK(s->bounds_lo[i] < s->bounds_hi[i]);
	for (int q = 0; q < s->query_count; ++q)
		for (int i = 0; i < pose; ++i) {
			FUZZ_CHECK(isfinite(s->queries[q].start[i]) && isfinite(s->queries[q].goal[i]));
			FUZZ_CHECK(s->queries[q].start_line > 0 && s->queries[q].goal_line > s->queries[q].start_line);
		}
	FUZZ_CHECK(s->orientation_count >= 0);
	for (int o = 0; o < s->orientation_count; ++o) {
		if (s->dim == 2) {
			FUZZ_CHECK(isfinite(s->headings[o]));
			continue;
		}
		mkMat3 R = s->rotations[o];
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j) {
				double d = 0.0;
				for (int k = 0; k < 3; ++k) d += R.m[k][i] * R.m[k][j];
				FUZZ_CHECK(fabs(d - (i == j)) <= 1e-5);
			}
		double det = R.m[0][0] * (R.m[1][1] * R.m[2][2] - R.m[1][2] * R.m[2][1])
			- R.m[0][1] * (R.m[1][0] * R.m[2][2] - R.m[1][2] * R.m[2][0])
			+ R.m[0][2] * (R.m[1][0] * R.m[2][1] - R.m[1][1] * R.m[2][0]);
		FUZZ_CHECK(fabs(det - 1.0) <= 1e-5);
	}
}

/* Parse with message buffers of several lengths; the verdicts agree. */
static mkResult fuzzParse(const char *text, mkScene *out)
{
	static const size_t lens[] = { 1, 7, 300 };
	mkResult r0 = MK_OK;
	for (size_t k = 0; k < sizeof lens / sizeof lens[0]; ++k) {
		char *msg = malloc(lens[k]);
		if (!msg) abort();
		memset(msg, 'x', lens[k]);
		mkScene s;
		memset(&s, 0xab, sizeof s);
		mkResult r = mkScene_Parse(text, &s, msg, lens[k]);
		if (k == 0) r0 = r;
		FUZZ_CHECK(r == r0);
		if (r != MK_OK) {
			fuzzCheckFailure(r, msg, lens[k]);
			FUZZ_CHECK(s.obstacles == NULL && s.headings == NULL && s.rotations == NULL);
		} else if (k + 1 < sizeof lens / sizeof lens[0]) {
			mkScene_Free(&s);
		} else {
			*out = s;
		}
		free(msg);
	}
	return r0;
}

static void fuzzPrepare(const mkScene *s)
{
	static const double tols[] = { 1e-2, 1e-6 };
	for (int k = 0; k < 2; ++k) {
		mkCSpaceOptions o = mkCSpaceOptions_Default();
		o.tol = tols[k];
		o.outer = k;
		mkCSpace *cs = NULL;
		char msg[64];
		memset(msg, 'x', sizeof msg);
		mkResult r = mkCSpace_Create(s, &o, &cs, msg, sizeof msg);
		if (r == MK_OK) {
			FUZZ_CHECK(cs != NULL);
			mkCSpace_Destroy(cs);
		} else {
			FUZZ_CHECK(cs == NULL && (r == MK_ERR_RANGE || r == MK_ERR_ARGUMENT || r == MK_ERR_UNSUPPORTED));
			FUZZ_CHECK(memchr(msg, '\0', sizeof msg) != NULL && msg[0] != '\0');
		}
	}
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	if (size > 8192)
		return 0; /* longer files add lines the parser has met already */
	const uint8_t *nul = memchr(data, 0, size);
	size_t n1 = nul ? (size_t)(nul - data) : size;
	char *scene = fuzzText(data, n1);
	char *rot = nul ? fuzzText(nul + 1, size - n1 - 1) : NULL;
	if (!scene || (nul && !rot)) abort();
	mkScene s;
	if (fuzzParse(scene, &s) == MK_OK) {
		fuzzCheckScene(&s);
		if (s.rotations_file[0]) {
			FUZZ_CHECK(s.dim == 3 && s.orientation_count == 0);
			char msg[80];
			memset(msg, 'x', sizeof msg);
			mkResult r = mkScene_SetRotations(&s, rot ? rot : "", "rot.csv", msg, sizeof msg);
			if (r != MK_OK) fuzzCheckFailure(r, msg, sizeof msg);
			else fuzzCheckScene(&s);
		}
		if (s.orientation_count > 0) fuzzPrepare(&s);
		mkScene_Free(&s);
	}
	free(scene);
	free(rot);
	return 0;
}
