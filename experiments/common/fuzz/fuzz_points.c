/* fuzz_points.c - libFuzzer harness over the CSV readers of the harness
 * library: the points of `mink verify --points` (mkPoints_Parse) and the
 * result tables (mkTable_FromText, with and without blank-line blocks).
 *
 * The input bytes are the text, copied into a heap buffer of exactly its
 * length + 1 (NUL-terminated; a NUL inside ends the text early, as it would
 * for the readers), so that AddressSanitizer catches a read past the end.
 *
 * Contract checked (mink_exp/points.h, mink_exp/table.h):
 *  - points: 0 with at least one point and at most one point per line of
 *    the text, or -1 with a non-empty message within its buffer; the same
 *    verdict whatever the message buffer's length;
 *  - tables: present with cols >= 1, rows >= 0, and every cell (header
 *    included) a NUL-terminated string inside the table's buffer, read
 *    back by mkTable_Str and mkTable_Num without a fault, and a column
 *    found by its header name.
 * A violation aborts, which libFuzzer reports as a crash with its input. */
#include <mink_exp/points.h>
#include <mink_exp/table.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_CHECK(expr) do { \
	if (!(expr)) { \
		fprintf(stderr, "fuzz_points: check failed: %s\n", #expr); \
		abort(); \
	} \
} while (0)

static char *fuzzText(const uint8_t *data, size_t size)
{
	char *t = malloc(size + 1);
	if (!t) abort();
	memcpy(t, data, size);
	t[size] = '\0';
	return t;
}

static void fuzzPoints(const uint8_t *data, size_t size, int dim)
{
	static const size_t lens[] = { 1, 12, 200 };
	int r0 = 0;
	for (size_t k = 0; k < sizeof lens / sizeof lens[0]; ++k) {
		char *text = fuzzText(data, size), *msg = malloc(lens[k]);
		if (!msg) abort();
		memset(msg, 'x', lens[k]);
		long lines = 1;
		for (const char *c = text; *c; ++c) lines += *c == '\n';
		mkPoints p;
		int r = mkPoints_Parse(text, dim, &p, msg, lens[k]);
		if (k == 0) r0 = r;
		FUZZ_CHECK(r == r0);
		if (r == 0) {
			FUZZ_CHECK(p.count >= 1 && p.count <= lines && p.dim == dim);
			FUZZ_CHECK(p.x && p.y && (dim == 2 || p.z));
		} else {
			FUZZ_CHECK(r == -1 && memchr(msg, '\0', lens[k]) != NULL && (lens[k] < 2 || msg[0]));
		}
		mkPoints_Free(&p);
		free(msg);
		free(text);
	}
}

static void fuzzTable(const uint8_t *data, size_t size, int blocks)
{
	char *text = fuzzText(data, size);
	size_t len = strlen(text);
	mkTable t;
	long blank = 0;
	mkTable_FromText(&t, text, "fuzz.csv", blocks ? &blank : NULL);
	if (t.present) {
		FUZZ_CHECK(t.cols >= 1 && t.rows >= 0 && blank >= 0);
		for (long r = -1; r < t.rows; ++r)
			for (int c = 0; c < t.cols; ++c) {
				const char *s = r < 0 ? t.names[c] : mkTable_Str(&t, r, c);
				FUZZ_CHECK(s >= t.buf && s <= t.buf + len);
				FUZZ_CHECK(memchr(s, '\0', (size_t)(t.buf + len + 1 - s)) != NULL);
				if (r >= 0) (void)mkTable_Num(&t, r, c);
			}
		int c = mkTable_Col(&t, t.names[0]);
		FUZZ_CHECK(c >= 0 && c < t.cols && strcmp(t.names[c], t.names[0]) == 0);
	}
	mkTable_Free(&t);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	if (size > 16384)
		return 0; /* longer texts are more lines of kinds met already */
	fuzzPoints(data, size, 2);
	fuzzPoints(data, size, 3);
	fuzzTable(data, size, 0);
	fuzzTable(data, size, 1);
	return 0;
}
