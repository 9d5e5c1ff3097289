/* points.c - reading a point set from a CSV file (points.h), parsed by
 * the harness's reader (mink_exp/points.h, the one the fuzz harness runs). */
#include "points.h"

#include <mink_exp/points.h>

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct mkPointsText {
	char *data;
	size_t len;
} mkPointsText;

static int mkPoints_Slurp(const char *cmd, const char *path, mkPointsText *t)
{
	FILE *fp = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
	if (!fp) {
		fprintf(stderr, "mink %s: --points %s: %s\n", cmd, path, strerror(errno));
		return -1;
	}
	size_t cap = 1 << 16;
	t->data = malloc(cap);
	t->len = 0;
	for (;;) {
		if (!t->data) break;
		if (t->len + 1 >= cap) {
			char *bigger = realloc(t->data, cap *= 2);
			if (!bigger) {
				free(t->data);
				t->data = NULL;
				break;
			}
			t->data = bigger;
		}
		size_t got = fread(t->data + t->len, 1, cap - 1 - t->len, fp);
		t->len += got;
		if (got == 0) break;
	}
	int bad = ferror(fp);
	if (fp != stdin) fclose(fp);
	if (!t->data || bad) {
		fprintf(stderr, "mink %s: --points %s: %s\n", cmd, path, t->data ? "read error" : "out of memory");
		free(t->data);
		return -1;
	}
	t->data[t->len] = '\0';
	return 0;
}

int mkPoints_Read(const char *cmd, const char *path, int dim, mkPointSet *out)
{
	mkPointsText text;
	if (mkPoints_Slurp(cmd, path, &text)) return -1;
	mkPoints read;
	char msg[256];
	int bad = mkPoints_Parse(text.data, dim, &read, msg, sizeof msg) != 0;
	free(text.data);
	if (bad) {
		fprintf(stderr, "mink %s: --points %s %s\n", cmd, path, msg);
	} else if (mkPointSet_Resize(out, dim, read.count) != MK_OK) {
		fprintf(stderr, "mink %s: out of memory reading the points\n", cmd);
		bad = 1;
	} else {
		memcpy(out->x, read.x, (size_t)read.count * sizeof(double));
		memcpy(out->y, read.y, (size_t)read.count * sizeof(double));
		if (dim == 3) memcpy(out->z, read.z, (size_t)read.count * sizeof(double));
	}
	mkPoints_Free(&read);
	return bad ? -1 : 0;
}
