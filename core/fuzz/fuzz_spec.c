/* fuzz_spec.c - libFuzzer harness over the SPEC parser.
 *
 * The input bytes are the SPEC text. It is copied into a heap buffer of
 * exactly size + 1 bytes (NUL-terminated), so that AddressSanitizer catches
 * any read past the terminator, and parsed as a 2D and as a 3D body, with
 * message buffers of exactly their declared length (so that an overlong
 * message is caught too), of several lengths, and with no message buffer.
 *
 * Contract checked (spec.h, body.h):
 *  - the result is MK_OK, MK_ERR_ARGUMENT or MK_ERR_RANGE;
 *  - on failure the message is a NUL-terminated, non-empty line within its
 *    buffer; on success the body passes mkBody2_IsValid / mkBody3_IsValid;
 *  - a parsed body is valid input, so the batch closed forms on it (against a
 *    fixed partner, both ways round) give finite points in every available
 *    kernel, form (normal, gradient), parameterisation and set.
 * A violation aborts, which libFuzzer reports as a crash with its input. */
#include <mink/mink.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FUZZ_CHECK(expr, text) do { \
	if (!(expr)) { \
		fprintf(stderr, "fuzz_spec: check failed: %s (input: \"%s\")\n", #expr, text); \
		abort(); \
	} \
} while (0)

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const mkImpl implList[] = { MK_IMPL_SCALAR, MK_IMPL_AVX2, MK_IMPL_AVX512 };

static void sumsAreFinite2(mkBody2 b, const char *text)
{
	enum { N = 12 };
	double ux[N], uy[N], o[4][N];
	mkSample2_Angles(N, ux, uy);
	mkBody2 other = mkBody2_Make((mkShape2){ 1.0, 0.5, 0.7 }, mkMat2_Rotation(0.3), (mkVec2){ 1.0, -1.0 });
	for (int ii = 0; ii < 3; ++ii) {
		if (!mkImpl_Available(implList[ii]))
			continue;
		for (int mask = 0; mask < 16; ++mask) {
			mkSumOptions opt = { (mask & 1) ? MK_SET_PLUS : MK_SET_CONTACT,
				(mask & 2) ? MK_FORM_GRADIENT : MK_FORM_NORMAL,
				(mask & 4) ? MK_PARAM_NORMAL : MK_PARAM_SURFACE, implList[ii], MK_PRECISION_DOUBLE };
			mkBody2 b1 = (mask & 8) ? other : b, b2 = (mask & 8) ? b : other;
			mkResult r = mkSum2_Batch(b1, b2, &opt, ux, uy, N, o[0], o[1], o[2], o[3]);
			FUZZ_CHECK(r == MK_OK, text);
			for (int k = 0; k < 4; ++k)
				for (int j = 0; j < N; ++j)
					FUZZ_CHECK(isfinite(o[k][j]), text);
		}
	}
}

static void sumsAreFinite3(mkBody3 b, const char *text)
{
	enum { G = 4, N = G * G };
	double ux[N], uy[N], uz[N], o[6][N];
	mkSample3_Grid(G, ux, uy, uz);
	mkBody3 other = mkBody3_Make((mkShape3){ 1.0, 0.5, 2.0, 0.7, 1.3 }, mkMat3_Identity(), (mkVec3){ 1.0, -1.0, 0.5 });
	for (int ii = 0; ii < 3; ++ii) {
		if (!mkImpl_Available(implList[ii]))
			continue;
		for (int mask = 0; mask < 16; ++mask) {
			mkSumOptions opt = { (mask & 1) ? MK_SET_PLUS : MK_SET_CONTACT,
				(mask & 2) ? MK_FORM_GRADIENT : MK_FORM_NORMAL,
				(mask & 4) ? MK_PARAM_NORMAL : MK_PARAM_SURFACE, implList[ii], MK_PRECISION_DOUBLE };
			mkBody3 b1 = (mask & 8) ? other : b, b2 = (mask & 8) ? b : other;
			mkResult r = mkSum3_Batch(b1, b2, &opt, ux, uy, uz, N, o[0], o[1], o[2], o[3], o[4], o[5]);
			FUZZ_CHECK(r == MK_OK, text);
			for (int k = 0; k < 6; ++k)
				for (int j = 0; j < N; ++j)
					FUZZ_CHECK(isfinite(o[k][j]), text);
		}
	}
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	if (size > 4096)
		return 0; /* longer texts add nothing the parser has not seen */
	char *text = malloc(size + 1);
	if (!text)
		return 0;
	memcpy(text, data, size);
	text[size] = '\0';

	static const size_t msgLens[] = { 1, 2, 9, 64, 256 };
	for (int dim = 2; dim <= 3; ++dim) {
		mkSpec spec;
		/* no message buffer at all */
		mkResult r0 = mkSpec_Parse(text, dim, "body", &spec, NULL, 0);
		FUZZ_CHECK(r0 == MK_OK || r0 == MK_ERR_ARGUMENT || r0 == MK_ERR_RANGE, text);
		for (size_t k = 0; k < sizeof msgLens / sizeof msgLens[0]; ++k) {
			size_t len = msgLens[k];
			char *msg = malloc(len);
			if (!msg)
				break;
			memset(msg, 'x', len);
			mkResult r = mkSpec_Parse(text, dim, "body", &spec, msg, len);
			/* the same input gives the same verdict whatever the buffer */
			FUZZ_CHECK(r == r0, text);
			if (r != MK_OK) {
				FUZZ_CHECK(memchr(msg, '\0', len) != NULL, text);
				FUZZ_CHECK(len < 2 || msg[0] != '\0', text);
			} else {
				FUZZ_CHECK(spec.dim == dim, text);
				if (dim == 2)
					FUZZ_CHECK(mkBody2_IsValid(spec.body2, "body", NULL, 0), text);
				else
					FUZZ_CHECK(mkBody3_IsValid(spec.body3, "body", NULL, 0), text);
			}
			free(msg);
		}
		if (r0 == MK_OK) {
			if (dim == 2)
				sumsAreFinite2(spec.body2, text);
			else
				sumsAreFinite3(spec.body3, text);
		}
	}
	free(text);
	return 0;
}
