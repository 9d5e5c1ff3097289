/* tables.c - every published number of the paper beside this suite's
 * reproduction of it, as Markdown (tables.md) and LaTeX (tables.tex),
 * computed from the stored results only: <dir>/validation.csv,
 * fitting.csv, timing.csv, cobstacle.csv and collision.csv with their
 * ".meta" sidecars. Nothing is measured here and nothing is invented: a
 * number whose result file is missing (or lacks the columns read) is listed
 * as NOT REPRODUCED YET.
 *
 * Ratios are reproduced / published. Where the paper states an outcome
 * without a number (the running-time figures), the table gives the measured
 * quantity that decides the statement and the rule applied, so a reader can
 * check the verdict.
 *
 * The published figures below are the paper's (Ruan & Chirikjian, CAD 2022,
 * Secs. 6.1-6.3 and 7, Tables 1-3). */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include <mink_exp/outfile.h>

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MK_CELL_MAX 256

/* ---- reading CSV files ----------------------------------------------------- */

/* A whole CSV in memory: cells[r * cols + c] point into buf (unquoted,
 * NUL-terminated). Row 0 of the file is the header (names). */
typedef struct mkTable {
	int cols;
	long rows;
	char **names;
	char **cells;
	char *buf;
	int present;
} mkTable;

/* Split buf (RFC 4180: fields may be quoted, "" is a quote) into fields in
 * place; *out_cells (allocated) receives them row by row and *out_cols the
 * fields per row. Returns the number of fields, or -1 when the rows are
 * ragged or memory runs out. */
static long mkCsvSplit(char *buf, char ***out_cells, int *out_cols)
{
	long cap = 1024, count = 0;
	char **cells = malloc((size_t)cap * sizeof *cells);
	if (!cells)
		return -1;
	int cols = -1, col = 0;
	char *r = buf, *w = buf;
	while (*r) {
		char *start = w;
		if (*r == '"') {
			++r;
			while (*r) {
				if (*r == '"' && r[1] == '"') {
					*w++ = '"';
					r += 2;
				} else if (*r == '"') {
					++r;
					break;
				} else {
					*w++ = *r++;
				}
			}
		}
		while (*r && *r != ',' && *r != '\n' && *r != '\r')
			*w++ = *r++;
		char end = *r;
		if (*r == '\r')
			++r;
		if (*r)
			++r;
		if (end == '\r' && *r == '\n')
			++r;
		*w++ = '\0';
		if (count == cap) {
			cap *= 2;
			char **grown = realloc(cells, (size_t)cap * sizeof *cells);
			if (!grown) {
				free(cells);
				return -1;
			}
			cells = grown;
		}
		cells[count++] = start;
		++col;
		if (end != ',') {
			if (cols < 0)
				cols = col;
			else if (col != cols) {
				free(cells);
				return -1;
			}
			col = 0;
		}
	}
	if (col != 0 || cols <= 0) {
		free(cells);
		return -1;
	}
	*out_cells = cells;
	*out_cols = cols;
	return count;
}

/* Load path into t. A missing file leaves t->present = 0; a malformed one
 * is reported and treated as missing. */
static void mkTable_Load(mkTable *t, const char *path)
{
	memset(t, 0, sizeof *t);
	FILE *fp = fopen(path, "rb");
	if (!fp)
		return;
	size_t cap = 1 << 20, len = 0;
	char *buf = malloc(cap + 1);
	while (buf) {
		size_t got = fread(buf + len, 1, cap - len, fp);
		len += got;
		if (len < cap)
			break;
		cap *= 2;
		char *grown = realloc(buf, cap + 1);
		if (!grown)
			free(buf);
		buf = grown;
	}
	fclose(fp);
	if (!buf) {
		fprintf(stderr, "tables: %s: out of memory\n", path);
		return;
	}
	buf[len] = '\0';
	char **cells = NULL;
	int cols = 0;
	long count = mkCsvSplit(buf, &cells, &cols);
	if (count < 0) {
		fprintf(stderr, "tables: %s: not a rectangular CSV file; treated as missing\n", path);
		free(buf);
		return;
	}
	t->buf = buf;
	t->cols = cols;
	t->names = cells;
	t->cells = cells + cols;
	t->rows = count / cols - 1;
	t->present = 1;
}

static void mkTable_Free(mkTable *t)
{
	free(t->names);
	free(t->buf);
	memset(t, 0, sizeof *t);
}

static int mkTable_Col(const mkTable *t, const char *name)
{
	for (int c = 0; t->present && c < t->cols; ++c)
		if (strcmp(t->names[c], name) == 0)
			return c;
	return -1;
}

static const char *mkTable_Str(const mkTable *t, long r, int c)
{
	return c >= 0 ? t->cells[r * t->cols + c] : "";
}

/* A number, NaN when empty or not a number ("nan" reads as NaN). */
static double mkTable_Num(const mkTable *t, long r, int c)
{
	const char *s = mkTable_Str(t, r, c);
	char *end = NULL;
	double v = strtod(s, &end);
	return (s[0] && end && *end == '\0') ? v : NAN;
}

/* ---- reading sidecars ------------------------------------------------------ */

typedef struct mkSidecar {
	int count;
	char *keys[128];
	char *values[128];
} mkSidecar;

static void mkSidecar_Load(mkSidecar *m, const char *csv_path)
{
	memset(m, 0, sizeof *m);
	char path[MK_PATH_MAX];
	snprintf(path, sizeof path, "%s.meta", csv_path);
	FILE *fp = fopen(path, "r");
	if (!fp)
		return;
	char line[8192];
	while (m->count < 128 && fgets(line, sizeof line, fp)) {
		line[strcspn(line, "\n")] = '\0';
		char *colon = strstr(line, ": ");
		if (!colon)
			continue;
		*colon = '\0';
		m->keys[m->count] = strdup(line);
		m->values[m->count] = strdup(colon + 2);
		if (m->keys[m->count] && m->values[m->count])
			m->count += 1;
	}
	fclose(fp);
}

static const char *mkSidecar_Get(const mkSidecar *m, const char *key)
{
	for (int i = 0; i < m->count; ++i)
		if (strcmp(m->keys[i], key) == 0)
			return m->values[i];
	return NULL;
}

static void mkSidecar_Free(mkSidecar *m)
{
	for (int i = 0; i < m->count; ++i) {
		free(m->keys[i]);
		free(m->values[i]);
	}
	memset(m, 0, sizeof *m);
}

/* ---- writing Markdown and LaTeX at once ------------------------------------ */

/* Text given to the writer is Markdown-flavoured UTF-8: `code` and **bold**
 * are the only markup; the LaTeX side translates them and the few
 * non-ASCII symbols used here. */
typedef struct mkDoc {
	FILE *md, *tex;
	int cols;
} mkDoc;

static const struct { const char *utf8, *tex; } mkSymbols[] = {
	{ "\xc2\xb1", "$\\pm$" }, { "\xc2\xb5", "$\\mu$" }, { "\xc3\x97", "$\\times$" },
	{ "\xe2\x9c\x93", "$\\surd$" }, { "\xe2\x89\xa4", "$\\le$" }, { "\xe2\x89\xa5", "$\\ge$" },
	{ "\xe2\x88\x92", "$-$" }, { "\xe2\x80\x94", "---" }, { "\xe2\x80\x93", "--" },
	{ "\xe2\x8a\x95", "$\\oplus$" }, { "\xce\xb5", "$\\varepsilon$" }, { "\xc2\xa7", "\\S{}" },
	{ "\xc2\xb2", "$^2$" }, { "\xe2\x81\xb4", "$^4$" }, { "\xe2\x89\x88", "$\\approx$" },
	{ "\xe2\x86\x92", "$\\to$" }, { "\xce\xb7", "$\\eta$" }, { "\xcf\x80", "$\\pi$" },
	{ "\xe2\x80\xa6", "\\ldots{}" }, { "\xc3\xb6", "\\\"{o}" },
};

static void mkTex_Put(FILE *fp, const char *s)
{
	int code = 0, bold = 0;
	while (*s) {
		int matched = 0;
		for (size_t i = 0; i < sizeof mkSymbols / sizeof mkSymbols[0]; ++i) {
			size_t n = strlen(mkSymbols[i].utf8);
			if (strncmp(s, mkSymbols[i].utf8, n) == 0) {
				fputs(mkSymbols[i].tex, fp);
				s += n;
				matched = 1;
				break;
			}
		}
		if (matched)
			continue;
		char ch = *s++;
		if (ch == '`') {
			fputs(code ? "}" : "\\texttt{", fp);
			code = !code;
		} else if (ch == '*' && *s == '*') {
			++s;
			fputs(bold ? "}" : "\\textbf{", fp);
			bold = !bold;
		} else if (ch == '\\' && *s == '|') {
			/* a Markdown-escaped bar */
			++s;
			fputs("$|$", fp);
		} else if (strchr("&%$#_{}", ch)) {
			fprintf(fp, "\\%c", ch);
		} else if (ch == '~') {
			fputs("\\textasciitilde{}", fp);
		} else if (ch == '^') {
			fputs("\\textasciicircum{}", fp);
		} else if (ch == '\\') {
			fputs("\\textbackslash{}", fp);
		} else if (ch == '<' || ch == '>' || ch == '|') {
			fprintf(fp, "$%c$", ch);
		} else {
			fputc(ch, fp);
		}
	}
	if (code)
		fputs("}", fp);
	if (bold)
		fputs("}", fp);
}

static void mkDoc_Heading(mkDoc *d, int level, const char *text)
{
	fprintf(d->md, "\n%.*s %s\n\n", level, "####", text);
	fputs(level <= 1 ? "\\section*{" : level == 2 ? "\\subsection*{" : "\\subsubsection*{", d->tex);
	mkTex_Put(d->tex, text);
	fputs("}\n", d->tex);
}

/* A paragraph (printf-style). */
static void mkDoc_Para(mkDoc *d, const char *fmt, ...)
{
	char text[4096];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(text, sizeof text, fmt, ap);
	va_end(ap);
	fprintf(d->md, "%s\n\n", text);
	mkTex_Put(d->tex, text);
	fputs("\n\n", d->tex);
}

/* A bullet list item (consecutive items form one list in Markdown; each
 * is its own paragraph in LaTeX, led by a dash). */
static void mkDoc_Item(mkDoc *d, const char *fmt, ...)
{
	char text[4096];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(text, sizeof text, fmt, ap);
	va_end(ap);
	fprintf(d->md, "- %s\n", text);
	fputs("\\noindent -- ", d->tex);
	mkTex_Put(d->tex, text);
	fputs("\n\n", d->tex);
}

static void mkDoc_EndItems(mkDoc *d)
{
	fputs("\n", d->md);
}

static void mkDoc_TableBegin(mkDoc *d, const char *caption, int cols, const char *const *head)
{
	d->cols = cols;
	fprintf(d->md, "*%s*\n\n|", caption);
	for (int c = 0; c < cols; ++c)
		fprintf(d->md, " %s |", head[c]);
	fputs("\n|", d->md);
	for (int c = 0; c < cols; ++c)
		fputs("---|", d->md);
	fputs("\n", d->md);
	fputs("\\begin{table}[!htbp]\n\\centering\\footnotesize\\setlength{\\tabcolsep}{3pt}\n\\caption{", d->tex);
	mkTex_Put(d->tex, caption);
	fputs("}\n\\begin{tabular}{", d->tex);
	for (int c = 0; c < cols; ++c)
		fputs("l", d->tex);
	fputs("}\n\\hline\n", d->tex);
	for (int c = 0; c < cols; ++c) {
		if (c)
			fputs(" & ", d->tex);
		mkTex_Put(d->tex, head[c]);
	}
	fputs(" \\\\\n\\hline\n", d->tex);
}

static void mkDoc_Row(mkDoc *d, const char *const *cells)
{
	fputs("|", d->md);
	for (int c = 0; c < d->cols; ++c)
		fprintf(d->md, " %s |", cells[c]);
	fputs("\n", d->md);
	for (int c = 0; c < d->cols; ++c) {
		if (c)
			fputs(" & ", d->tex);
		mkTex_Put(d->tex, cells[c]);
	}
	fputs(" \\\\\n", d->tex);
}

static void mkDoc_TableEnd(mkDoc *d)
{
	fputs("\n", d->md);
	fputs("\\hline\n\\end{tabular}\n\\end{table}\n\n", d->tex);
}

/* ---- numbers as text ------------------------------------------------------- */

static const char *const mkNotYet = "**NOT REPRODUCED YET**";

static void mkFmtSci(char *buf, size_t len, double v)
{
	if (isnan(v))
		snprintf(buf, len, "—");
	else
		snprintf(buf, len, "%.4e", v);
}

static void mkFmtRatio(char *buf, size_t len, double got, double published)
{
	if (isnan(got) || isnan(published) || published == 0.0)
		snprintf(buf, len, "—");
	else
		snprintf(buf, len, "%.3g", got / published);
}

/* "mean ± std unit": the unit that suits the mean (µs, ms or s), the mean
 * to three significant digits and the std to two, in the same unit. */
static void mkFmtTime(char *buf, size_t len, double mean, double std)
{
	double scale = mean < 1e-3 ? 1e6 : mean < 1.0 ? 1e3 : 1.0;
	const char *unit = mean < 1e-3 ? "µs" : mean < 1.0 ? "ms" : "s";
	if (isnan(mean))
		snprintf(buf, len, "—");
	else
		snprintf(buf, len, "%.3g ± %.2g %s", mean * scale, std * scale, unit);
}

/* ---- bookkeeping of published numbers -------------------------------------- */

typedef struct mkTally {
	int published, reproduced, missing;
} mkTally;

static void mkTally_Add(mkTally *t, int reproduced)
{
	t->published += 1;
	if (reproduced)
		t->reproduced += 1;
	else
		t->missing += 1;
}

/* One line on where a table's numbers come from. */
static void mkDoc_Source(mkDoc *d, const char *path, const mkTable *t, const mkSidecar *m)
{
	const char *date = mkSidecar_Get(m, "date_utc");
	const char *commit = mkSidecar_Get(m, "git_commit");
	const char *seed = mkSidecar_Get(m, "seed");
	const char *trials = mkSidecar_Get(m, "trials");
	mkDoc_Para(d, "Source: `%s` (%ld rows; run %s, commit %.12s, seed %s, %s trials).", path, t->rows,
		date ? date : "unknown", commit ? commit : "unknown", seed ? seed : "?", trials ? trials : "?");
}

/* ---- Sec. 6.1: numerical validation ----------------------------------------- */

typedef struct mkMean {
	double sum;
	long n, nan;
} mkMean;

static void mkMean_Add(mkMean *m, double v)
{
	if (isfinite(v)) {
		m->sum += v;
		m->n += 1;
	} else {
		m->nan += 1;
	}
}

static double mkMean_Get(const mkMean *m)
{
	return m->n ? m->sum / (double)m->n : NAN;
}

static void mkValidation(mkDoc *d, const char *dir, mkTally *tally)
{
	char path[MK_PATH_MAX];
	snprintf(path, sizeof path, "%s/validation.csv", dir);
	mkTable t;
	mkTable_Load(&t, path);
	mkSidecar m;
	mkSidecar_Load(&m, path);
	mkDoc_Heading(d, 2, "Numerical validation (paper §6.1)");

	static const char *const forms[3] = { "paper", "gradient", "normal" };
	static const struct { int dim; const char *metric, *col, *published_text; double published; } pub[4] = {
		{ 2, "e_implicit", "e_implicit_mean", "5.9194e-16", 5.9194e-16 },
		{ 2, "e_gradient", "e_gradient_mean", "6.1839e-7", 6.1839e-7 },
		{ 3, "e_implicit", "e_implicit_mean", "1.8303e-9", 1.8303e-9 },
		{ 3, "e_gradient", "e_gradient_mean", "4.0654e-7", 4.0654e-7 },
	};
	int cdim = mkTable_Col(&t, "dim"), cform = mkTable_Col(&t, "form");
	int ci = mkTable_Col(&t, "e_implicit_mean"), cg = mkTable_Col(&t, "e_gradient_mean");
	int cs = mkTable_Col(&t, "e_support_mean"), cnf = mkTable_Col(&t, "nonfinite_count");
	int usable = t.present && cdim >= 0 && cform >= 0 && ci >= 0 && cg >= 0;
	if (!usable) {
		mkDoc_Para(d, "%s: `%s` %s. The four published means are listed without a counterpart.",
			mkNotYet, path, t.present ? "lacks the columns dim, form, e_implicit_mean, e_gradient_mean"
			: "does not exist (run the `validation` driver)");
	} else {
		mkDoc_Source(d, path, &t, &m);
		const char *rot = mkSidecar_Get(&m, "rotation_draw");
		mkDoc_Para(d, "Rotation draw (3D): **%s**%s. The 2D bodies are rotated and sheared "
			"(`M = rot(2π U) [1 s; 0 1]`, s ~ U(−2, 2)).", rot ? rot : "not recorded",
			rot && strcmp(rot, "paper") == 0 ? " (the reference code's normalised quaternion with "
			"four U(0,1) entries, not uniform on SO(3))" : rot && strcmp(rot, "uniform") == 0
			? " (uniform on SO(3))" : "");
	}
	/* Means over trials of the per-trial means, per (dim, form, metric). */
	mkMean mean[4][3][3];
	long nonfinite[4][3];
	memset(mean, 0, sizeof mean);
	memset(nonfinite, 0, sizeof nonfinite);
	for (long r = 0; usable && r < t.rows; ++r) {
		int dim = (int)mkTable_Num(&t, r, cdim);
		int f = -1;
		for (int k = 0; k < 3; ++k)
			if (strcmp(mkTable_Str(&t, r, cform), forms[k]) == 0)
				f = k;
		if ((dim != 2 && dim != 3) || f < 0)
			continue;
		mkMean_Add(&mean[dim][f][0], mkTable_Num(&t, r, ci));
		mkMean_Add(&mean[dim][f][1], mkTable_Num(&t, r, cg));
		if (cs >= 0)
			mkMean_Add(&mean[dim][f][2], mkTable_Num(&t, r, cs));
		if (cnf >= 0)
			nonfinite[dim][f] += (long)mkTable_Num(&t, r, cnf);
	}
	static const char *const head[] = { "dim", "metric (mean over trials)", "published",
		"reproduced: paper form", "ratio", "gradient form", "ratio", "normal form", "ratio" };
	mkDoc_TableBegin(d, "Validation means: the paper's figures and this run's, per form of the closed "
		"form (paper form = Theorem 2 as printed, what the published code computes; gradient form = "
		"Theorem 2 evaluated stably; normal form = Theorem 1). Ratio = reproduced / published.", 9, head);
	for (int i = 0; i < 4; ++i) {
		char cell[7][MK_CELL_MAX], dimtext[8];
		snprintf(dimtext, sizeof dimtext, "%dD", pub[i].dim);
		int k = strcmp(pub[i].metric, "e_implicit") == 0 ? 0 : 1;
		for (int f = 0; f < 3; ++f) {
			double v = usable ? mkMean_Get(&mean[pub[i].dim][f][k]) : NAN;
			if (usable)
				mkFmtSci(cell[2 * f], MK_CELL_MAX, v);
			else
				snprintf(cell[2 * f], MK_CELL_MAX, "%s", f == 0 ? mkNotYet : "—");
			mkFmtRatio(cell[2 * f + 1], MK_CELL_MAX, v, pub[i].published);
		}
		const char *row[9] = { dimtext, pub[i].metric, pub[i].published_text, cell[0], cell[1], cell[2],
			cell[3], cell[4], cell[5] };
		mkDoc_Row(d, row);
		mkTally_Add(tally, usable && !isnan(mkMean_Get(&mean[pub[i].dim][0][k])));
	}
	if (usable && cs >= 0) {
		for (int dim = 2; dim <= 3; ++dim) {
			char cell[3][MK_CELL_MAX], dimtext[8];
			snprintf(dimtext, sizeof dimtext, "%dD", dim);
			for (int f = 0; f < 3; ++f)
				mkFmtSci(cell[f], MK_CELL_MAX, mkMean_Get(&mean[dim][f][2]));
			const char *row[9] = { dimtext, "e_support (not in the paper)", "—", cell[0], "—", cell[1], "—",
				cell[2], "—" };
			mkDoc_Row(d, row);
		}
	}
	mkDoc_TableEnd(d);
	if (!usable) {
		mkSidecar_Free(&m);
		mkTable_Free(&t);
		return;
	}

	/* What the comparison says, from the numbers above. */
	mkDoc_Item(d, "e_gradient as printed is dominated by the rounding of the output near the tips of "
		"bodies with ε near 2, where the normal is only Hölder continuous: a normal recomputed from a "
		"point rounded to double can be off by a tenth of a radian whatever computed the point, so "
		"e_gradient measures that rounding rather than the method%s.", cs >= 0
		? "; e_support tests the same anti-parallel-normal condition as a support gap, without "
		"differentiating positions" : " (this CSV has no e_support column to show beside it)");
	for (int i = 0; i < 4; ++i) {
		int k = strcmp(pub[i].metric, "e_implicit") == 0 ? 0 : 1;
		double paper = mkMean_Get(&mean[pub[i].dim][0][k]);
		double stable = fmax(mkMean_Get(&mean[pub[i].dim][1][k]), mkMean_Get(&mean[pub[i].dim][2][k]));
		double ratio = paper / pub[i].published;
		if (isnan(ratio))
			continue;
		if (ratio >= 0.1 && ratio <= 10.0) {
			mkDoc_Item(d, "%dD %s: the paper form agrees with the published mean within a factor of %.2g.",
				pub[i].dim, pub[i].metric, ratio >= 1.0 ? ratio : 1.0 / ratio);
		} else {
			mkDoc_Item(d, "**%dD %s disagrees with the paper**: the paper form gives %.3g, %.3g times the "
				"published %s.", pub[i].dim, pub[i].metric, paper, ratio, pub[i].published_text);
		}
		if (pub[i].dim == 3 && k == 0 && stable < paper / 100.0)
			mkDoc_Item(d, "3D e_implicit: the stable forms (%.3g at most) are %.0f times below the paper "
				"form: the printed formula recomputes cos²η as 1 − (…), which cancels near the poles; "
				"the published %s reflects that loss, not the closed form.", stable, paper / stable,
				pub[i].published_text);
	}
	for (int dim = 2; dim <= 3; ++dim)
		for (int f = 0; f < 3; ++f)
			if (nonfinite[dim][f] || mean[dim][f][0].nan)
				mkDoc_Item(d, "%dD %s form: %ld boundary points with a non-finite metric were left out of "
					"the per-trial means (counted by the driver, never dropped silently); %ld trials had no "
					"finite point.", dim, forms[f], nonfinite[dim][f], mean[dim][f][0].nan);
	mkDoc_EndItems(d);
	mkSidecar_Free(&m);
	mkTable_Free(&t);
}

/* ---- Sec. 6.2: fitting errors ---------------------------------------------- */

static void mkFitting(mkDoc *d, const char *dir, mkTally *tally)
{
	char path[MK_PATH_MAX];
	snprintf(path, sizeof path, "%s/fitting.csv", dir);
	mkTable t;
	mkTable_Load(&t, path);
	mkSidecar m;
	mkSidecar_Load(&m, path);
	mkDoc_Heading(d, 2, "Fitting errors (paper §6.2)");
	int ccase = mkTable_Col(&t, "case"), ctruth = mkTable_Col(&t, "truth"), cmodel = mkTable_Col(&t, "model");
	int csamp = mkTable_Col(&t, "sampling"), clevel = mkTable_Col(&t, "level");
	int cvol = mkTable_Col(&t, "e_volume"), cimp = mkTable_Col(&t, "e_implicit");
	int usable = t.present && ccase >= 0 && ctruth >= 0 && cmodel >= 0 && csamp >= 0 && clevel >= 0
		&& cvol >= 0 && cimp >= 0;
	if (!usable) {
		mkDoc_Para(d, "%s: `%s` %s.", mkNotYet, path, t.present ? "lacks the columns case, truth, model, "
			"sampling, level, e_volume, e_implicit" : "does not exist (run the `fitting` driver)");
	} else {
		mkDoc_Source(d, path, &t, &m);
		const char *c2 = mkSidecar_Get(&m, "case2_draw");
		mkDoc_Para(d, "Rotation draw: only case 2 rotates its superquadric (%s); a rotation cannot change a "
			"volume, so the draw does not enter these errors. Ratio = reproduced / published.",
			c2 ? c2 : "draw not recorded");
	}
	/* One published figure each: which rows it is the mean of. An empty
	 * truth/model/sampling matches anything; level 0 matches any level. */
	static const struct {
		int c;
		const char *what, *truth, *model, *sampling;
		int level;
		int implicit;
		const char *published_text;
		double published;
	} pub[] = {
		{ 1, "case 1: superquadric fitted to a random polyhedron, e_volume", "polyhedron", "superquadric", "",
			0, 0, "0.2095", 0.2095 },
		{ 1, "case 1: same fits, e_implicit", "polyhedron", "superquadric", "", 0, 1, "0.5808", 0.5808 },
		{ 2, "case 2: polyhedron of 16 superquadric points, e_volume", "superquadric", "polyhedron", "paper",
			16, 0, "0.6573", 0.6573 },
		{ 2, "case 2: polyhedron of 81 points, e_volume", "superquadric", "polyhedron", "paper", 81, 0,
			"0.094", 0.094 },
		{ 2, "case 2: polyhedron of 400 points, e_volume", "superquadric", "polyhedron", "paper", 400, 0,
			"0.0171", 0.0171 },
		{ 3, "case 3: cube as superquadric ε = (0.1, 0.1)", "cube", "superquadric", "", 0, 0, "0.0112",
			0.0112 },
		{ 3, "case 3: ellipsoid as 9 × 9-grid polyhedron", "ellipsoid", "polyhedron", "paper", 0, 0, "0.1340",
			0.1340 },
		{ 3, "case 3: elliptic cylinder as superquadric ε = (0.1, 1)", "cylinder", "superquadric", "", 0, 0,
			"0.0074", 0.0074 },
		{ 3, "case 3: elliptic cylinder as 2 × 30-point polyhedron", "cylinder", "polyhedron", "paper", 0, 0,
			"0.0078", 0.0078 },
	};
	static const char *const head[] = { "published figure (mean of 100 trials)", "published", "reproduced",
		"ratio", "rows (finite)" };
	mkDoc_TableBegin(d, "Fitting errors: relative volume error e_volume (and e_implicit in case 1), "
		"published and reproduced means.", 5, head);
	int disagree = 0;
	for (size_t i = 0; i < sizeof pub / sizeof pub[0]; ++i) {
		mkMean mean;
		memset(&mean, 0, sizeof mean);
		for (long r = 0; usable && r < t.rows; ++r) {
			if ((int)mkTable_Num(&t, r, ccase) != pub[i].c)
				continue;
			if (pub[i].truth[0] && strcmp(mkTable_Str(&t, r, ctruth), pub[i].truth) != 0)
				continue;
			if (pub[i].model[0] && strcmp(mkTable_Str(&t, r, cmodel), pub[i].model) != 0)
				continue;
			if (pub[i].sampling[0] && strcmp(mkTable_Str(&t, r, csamp), pub[i].sampling) != 0)
				continue;
			if (pub[i].level && (int)mkTable_Num(&t, r, clevel) != pub[i].level)
				continue;
			mkMean_Add(&mean, mkTable_Num(&t, r, pub[i].implicit ? cimp : cvol));
		}
		double v = mkMean_Get(&mean);
		char got[MK_CELL_MAX], ratio[MK_CELL_MAX], rows[MK_CELL_MAX];
		if (!usable || (mean.n == 0 && mean.nan == 0)) {
			snprintf(got, sizeof got, "%s", mkNotYet);
			snprintf(rows, sizeof rows, "0");
		} else {
			snprintf(got, sizeof got, "%.4f", v);
			snprintf(rows, sizeof rows, "%ld (%ld)", mean.n + mean.nan, mean.n);
		}
		mkFmtRatio(ratio, sizeof ratio, usable ? v : NAN, pub[i].published);
		const char *row[5] = { pub[i].what, pub[i].published_text, got, ratio, rows };
		mkDoc_Row(d, row);
		mkTally_Add(tally, usable && mean.n > 0);
		double q = v / pub[i].published;
		if (mean.n > 0 && (q < 0.8 || q > 1.25))
			disagree += 1;
	}
	mkDoc_TableEnd(d);
	if (usable)
		mkDoc_Para(d, "%d of %zu figures differ from the published mean by more than 25%% (ratio outside "
			"[0.8, 1.25]); means of 100 random trials of these errors scatter by several percent between "
			"seeds. The `distinct` sampling rows of the CSV (grids without the repeated longitude of the "
			"reference code) are not in this table.", disagree, sizeof pub / sizeof pub[0]);
	mkSidecar_Free(&m);
	mkTable_Free(&t);
}

/* ---- Sec. 6.3: running time ------------------------------------------------ */

typedef struct mkCellStat {
	int dim, c, method, level;
	long points;   /* points per body */
	long n;        /* ok rows */
	long failed;   /* rows with another status */
	double mean, m2; /* Welford */
	long planned, run;
	double *v;       /* every ok time, sorted after loading */
	long nv, capv;
	double median;
} mkCellStat;

static const char *const mkCases[3] = { "EE", "ES", "SQ" };
static const char *const mkMethods[] = { "closed-gradient", "closed-normal", "closed-paper", "geometric",
	"edge-sort", "hull-qhull", "hull-cgal-epick", "hull-cgal-epeck" };
#define MK_NMETHODS ((int)(sizeof mkMethods / sizeof mkMethods[0]))

typedef struct mkTiming {
	mkCellStat *cell;
	long count, cap;
} mkTiming;

static int mkIndexOf(const char *const *names, int count, const char *s)
{
	for (int i = 0; i < count; ++i)
		if (strcmp(names[i], s) == 0)
			return i;
	return -1;
}

static const mkCellStat *mkTiming_Find(const mkTiming *tm, int dim, int c, int method, int level)
{
	for (long i = 0; i < tm->count; ++i) {
		const mkCellStat *s = &tm->cell[i];
		if (s->dim == dim && s->c == c && s->method == method && s->level == level)
			return s;
	}
	return NULL;
}

/* Levels (sorted, distinct) present for one dimension; returns the count. */
static int mkTiming_Levels(const mkTiming *tm, int dim, int *levels, int max)
{
	int n = 0;
	for (long i = 0; i < tm->count; ++i) {
		if (tm->cell[i].dim != dim)
			continue;
		int v = tm->cell[i].level, k = 0;
		while (k < n && levels[k] < v)
			++k;
		if (k < n && levels[k] == v)
			continue;
		if (n == max)
			break;
		memmove(levels + k + 1, levels + k, (size_t)(n - k) * sizeof *levels);
		levels[k] = v;
		++n;
	}
	return n;
}

static double mkStd(const mkCellStat *s)
{
	return s->n ? sqrt(s->m2 / (double)s->n) : NAN; /* population std, as the paper's std(x, 1) */
}

/* Least-squares slope of log(median time) against log(points per body)
 * over the top decade of sizes present (points >= largest / 10). NaN with
 * fewer than three levels. Medians, because one call preempted by another
 * process moves a mean of few trials by milliseconds. */
static double mkSlope(const mkTiming *tm, int dim, int c, int method, long *from, long *to)
{
	long most = 0;
	for (long i = 0; i < tm->count; ++i) {
		const mkCellStat *s = &tm->cell[i];
		if (s->dim == dim && s->c == c && s->method == method && s->n > 0 && s->points > most)
			most = s->points;
	}
	double sx = 0, sy = 0, sxx = 0, sxy = 0;
	int k = 0;
	*from = 0;
	*to = most;
	for (long i = 0; i < tm->count; ++i) {
		const mkCellStat *s = &tm->cell[i];
		if (s->dim != dim || s->c != c || s->method != method || s->n == 0 || s->points * 10 < most
			|| !(s->median > 0.0))
			continue;
		double x = log((double)s->points), y = log(s->median);
		sx += x;
		sy += y;
		sxx += x * x;
		sxy += x * y;
		if (!*from || s->points < *from)
			*from = s->points;
		++k;
	}
	if (k < 3)
		return NAN;
	double den = k * sxx - sx * sx;
	return den > 0 ? (k * sxy - sx * sy) / den : NAN;
}

/* Median time ratio a / b at the largest level where both ran; its level
 * in *level. */
static double mkRatioAtTop(const mkTiming *tm, int dim, int c, int a, int b, int *level)
{
	int best = -1;
	double ratio = NAN;
	for (long i = 0; i < tm->count; ++i) {
		const mkCellStat *s = &tm->cell[i];
		if (s->dim != dim || s->c != c || s->method != a || s->n == 0 || s->level <= best)
			continue;
		const mkCellStat *o = mkTiming_Find(tm, dim, c, b, s->level);
		if (!o || o->n == 0)
			continue;
		best = s->level;
		ratio = s->median / o->median;
	}
	*level = best;
	return ratio;
}

/* Levels where method a's median time is below b's, out of those where both
 * ran. */
static int mkFasterCount(const mkTiming *tm, int dim, int c, int a, int b, int *both)
{
	int faster = 0;
	*both = 0;
	for (long i = 0; i < tm->count; ++i) {
		const mkCellStat *s = &tm->cell[i];
		if (s->dim != dim || s->c != c || s->method != a || s->n == 0)
			continue;
		const mkCellStat *o = mkTiming_Find(tm, dim, c, b, s->level);
		if (!o || o->n == 0)
			continue;
		*both += 1;
		faster += s->median < o->median;
	}
	return faster;
}

static int mkCompareDouble(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

static int mkTiming_Load(mkTiming *tm, const mkTable *t)
{
	int cdim = mkTable_Col(t, "dim"), ccase = mkTable_Col(t, "case"), cmeth = mkTable_Col(t, "method");
	int clevel = mkTable_Col(t, "level"), cpts = mkTable_Col(t, "points_per_body");
	int cstat = mkTable_Col(t, "status"), csec = mkTable_Col(t, "seconds");
	int cplan = mkTable_Col(t, "trials_planned"), crun = mkTable_Col(t, "trials_run");
	if (cdim < 0 || ccase < 0 || cmeth < 0 || clevel < 0 || cpts < 0 || cstat < 0 || csec < 0 || cplan < 0
		|| crun < 0)
		return -1;
	long last = -1;
	for (long r = 0; r < t->rows; ++r) {
		int dim = (int)mkTable_Num(t, r, cdim);
		int c = mkIndexOf(mkCases, 3, mkTable_Str(t, r, ccase));
		int method = mkIndexOf(mkMethods, MK_NMETHODS, mkTable_Str(t, r, cmeth));
		int level = (int)mkTable_Num(t, r, clevel);
		if ((dim != 2 && dim != 3) || c < 0 || method < 0)
			continue; /* a method this table does not know: not in the paper */
		mkCellStat *s = last >= 0 ? &tm->cell[last] : NULL;
		if (!s || s->dim != dim || s->c != c || s->method != method || s->level != level) {
			s = (mkCellStat *)mkTiming_Find(tm, dim, c, method, level);
			if (!s) {
				if (tm->count == tm->cap) {
					long cap = tm->cap ? 2 * tm->cap : 256;
					mkCellStat *grown = realloc(tm->cell, (size_t)cap * sizeof *grown);
					if (!grown)
						return -1;
					tm->cell = grown;
					tm->cap = cap;
				}
				s = &tm->cell[tm->count++];
				memset(s, 0, sizeof *s);
				s->dim = dim;
				s->c = c;
				s->method = method;
				s->level = level;
				s->points = (long)mkTable_Num(t, r, cpts);
			}
			last = s - tm->cell;
		}
		s->planned = (long)mkTable_Num(t, r, cplan);
		s->run = (long)mkTable_Num(t, r, crun);
		double v = mkTable_Num(t, r, csec);
		if (strcmp(mkTable_Str(t, r, cstat), "ok") != 0 || !isfinite(v)) {
			s->failed += 1;
			continue;
		}
		s->n += 1;
		double delta = v - s->mean;
		s->mean += delta / (double)s->n;
		s->m2 += delta * (v - s->mean);
		if (s->nv == s->capv) {
			long cap = s->capv ? 2 * s->capv : 16;
			double *grown = realloc(s->v, (size_t)cap * sizeof *grown);
			if (!grown)
				return -1;
			s->v = grown;
			s->capv = cap;
		}
		s->v[s->nv++] = v;
	}
	for (long i = 0; i < tm->count; ++i) {
		mkCellStat *s = &tm->cell[i];
		s->median = NAN;
		if (s->nv == 0)
			continue;
		qsort(s->v, (size_t)s->nv, sizeof *s->v, mkCompareDouble);
		s->median = s->nv % 2 ? s->v[s->nv / 2] : 0.5 * (s->v[s->nv / 2 - 1] + s->v[s->nv / 2]);
	}
	return 0;
}

static void mkTiming_Free(mkTiming *tm)
{
	for (long i = 0; i < tm->count; ++i)
		free(tm->cell[i].v);
	free(tm->cell);
	memset(tm, 0, sizeof *tm);
}

/* The levels a means table shows: the paper's round sizes (2D N = 20, 100,
 * ..., 500; 3D n = 5, 10, 20, ..., 50) when all were run, otherwise up to
 * `want` levels spread over those present (first, last, evenly between). */
static int mkShownLevels(int dim, const int *levels, int n, int *out, int want)
{
	static const int round2[6] = { 20, 100, 200, 300, 400, 500 }, round3[6] = { 5, 10, 20, 30, 40, 50 };
	const int *round = dim == 2 ? round2 : round3;
	int found = 0;
	for (int i = 0; i < 6; ++i)
		for (int j = 0; j < n; ++j)
			found += levels[j] == round[i];
	if (found == 6 && want >= 6) {
		memcpy(out, round, 6 * sizeof *round);
		return 6;
	}
	if (n <= want) {
		memcpy(out, levels, (size_t)n * sizeof *levels);
		return n;
	}
	for (int i = 0; i < want; ++i)
		out[i] = levels[(int)lround((double)i * (n - 1) / (want - 1))];
	return want;
}

static void mkTiming_Statements(mkDoc *d, const mkTiming *tm, mkTally *tally)
{
	enum { CG = 0, GEO = 3, ES = 4, QH = 5 };
	static const char *const head[] = { "published statement (Figs. 5–8)", "dim", "case",
		"reproduced quantity", "value", "rule", "verdict" };
	mkDoc_TableBegin(d, "Running time: the paper's outcome statements (no published numbers) and the "
		"measured quantity that decides each, from per-level medians (robust to a call preempted by "
		"another process; the means are in the tables below). Slopes are least-squares slopes of "
		"log(median time) against log(points per body) over the top decade of sizes (1 = linear).", 7, head);
	int any = 0;
	for (int dim = 2; dim <= 3; ++dim)
		for (int c = 0; c < 3; ++c) {
			long from, to;
			char where[MK_CELL_MAX], value[MK_CELL_MAX], dimtext[8];
			snprintf(dimtext, sizeof dimtext, "%dD", dim);
			/* 1. closed form linear */
			double s = mkSlope(tm, dim, c, CG, &from, &to);
			if (!isnan(s)) {
				snprintf(where, sizeof where, "slope of closed-gradient, %ld–%ld points", from, to);
				snprintf(value, sizeof value, "%.2f", s);
				const char *row[7] = { "closed form (proposed) is linear in N", dimtext, mkCases[c], where, value,
					"\\|slope − 1\\| ≤ 0.25", fabs(s - 1.0) <= 0.25 ? "agrees" : "**disagrees**" };
				mkDoc_Row(d, row);
				any = 1;
			}
			/* 2. convex hull grows much faster */
			double sc = s;
			s = mkSlope(tm, dim, c, QH, &from, &to);
			int level;
			double q = mkRatioAtTop(tm, dim, c, QH, CG, &level);
			if (!isnan(s) && !isnan(sc) && !isnan(q)) {
				snprintf(where, sizeof where, "slopes of hull-qhull and closed-gradient; time ratio at level %d",
					level);
				snprintf(value, sizeof value, "%.2f vs %.2f; %.3g", s, sc, q);
				const char *row[7] = { "convex hull grows much faster", dimtext, mkCases[c], where, value,
					"slopes differ by ≥ 0.5 and ratio ≥ 10", s - sc >= 0.5 && q >= 10.0 ? "agrees"
					: "**disagrees**" };
				mkDoc_Row(d, row);
				any = 1;
			}
			if (dim == 2) {
				/* 3. edge sorting linear */
				s = mkSlope(tm, dim, c, ES, &from, &to);
				if (!isnan(s)) {
					snprintf(where, sizeof where, "slope of edge-sort, %ld–%ld points", from, to);
					snprintf(value, sizeof value, "%.2f", s);
					const char *row[7] = { "edge sorting is linear", dimtext, mkCases[c], where, value,
						"\\|slope − 1\\| ≤ 0.25", fabs(s - 1.0) <= 0.25 ? "agrees" : "**disagrees**" };
					mkDoc_Row(d, row);
				}
				/* 4./5. edge sorting faster for SQ, slower for ellipses */
				int both = 0, faster = mkFasterCount(tm, dim, c, ES, CG, &both);
				if (both > 0 && c != 1) {
					int want_faster = c == 2;
					snprintf(where, sizeof where, "levels where edge-sort is faster than closed-gradient");
					snprintf(value, sizeof value, "%d of %d", faster, both);
					const char *row[7] = { want_faster ? "edge sorting is faster than the closed form for two "
						"superellipses" : "edge sorting is slower than the closed form for ellipses", dimtext,
						mkCases[c], where, value, want_faster ? "faster at more than half" : "slower at more than half",
						(want_faster ? 2 * faster > both : 2 * (both - faster) > both) ? "agrees" : "**disagrees**" };
					mkDoc_Row(d, row);
				}
			}
			/* 6. geometric about as fast as proposed (EE, ES) */
			q = mkRatioAtTop(tm, dim, c, GEO, CG, &level);
			if (!isnan(q) && c != 2) {
				snprintf(where, sizeof where, "geometric / closed-gradient time at level %d", level);
				snprintf(value, sizeof value, "%.3g", q);
				const char *row[7] = { "closed-form geometric is about as fast as the proposed one", dimtext,
					mkCases[c], where, value, "ratio in [0.5, 2]", q >= 0.5 && q <= 2.0 ? "agrees" : "**disagrees**" };
				mkDoc_Row(d, row);
			}
		}
	if (!any) {
		const char *row[7] = { "all statements", "—", "—", "—", mkNotYet, "—", "—" };
		mkDoc_Row(d, row);
	}
	mkDoc_TableEnd(d);
	/* Six statements in the paper's text. */
	for (int i = 0; i < 6; ++i)
		mkTally_Add(tally, any);
}

static void mkTiming_Applicability(mkDoc *d, const mkTiming *tm)
{
	static const struct { const char *name, *dims, *exact, *cases; int methods[3]; } alg[] = {
		{ "Convex hull (Quickhull; also CGAL)", "Any", "", "✓ ✓ ✓", { 5, 6, 7 } },
		{ "Edge sorting", "2D", "", "✓ ✓ ✓", { 4, -1, -1 } },
		{ "Closed-form geometric", "Any", "✓", "✓ ✓ —", { 3, -1, -1 } },
		{ "Closed-form (proposed): closed-gradient", "Any", "✓", "✓ ✓ ✓", { 0, -1, -1 } },
	};
	static const char *const head[] = { "algorithm", "published: dims", "exact", "published: EE ES SQ",
		"reproduced: 2D EE ES SQ", "reproduced: 3D EE ES SQ" };
	mkDoc_TableBegin(d, "Table 1 of the paper (applicable algorithms per case) beside the cases this run "
		"timed (✓: rows present; —: the method was skipped, see the sidecar's `skipped`).", 6, head);
	for (size_t i = 0; i < sizeof alg / sizeof alg[0]; ++i) {
		char rep[4][32];
		for (int dim = 2; dim <= 3; ++dim) {
			rep[dim][0] = '\0';
			for (int c = 0; c < 3; ++c) {
				int has = 0;
				for (int k = 0; k < 3; ++k) {
					if (alg[i].methods[k] < 0)
						continue;
					for (long j = 0; j < tm->count; ++j) {
						const mkCellStat *s = &tm->cell[j];
						has = has || (s->dim == dim && s->c == c && s->method == alg[i].methods[k] && s->n > 0);
					}
				}
				strcat(rep[dim], c ? " " : "");
				strcat(rep[dim], has ? "✓" : "—");
			}
		}
		const char *row[6] = { alg[i].name, alg[i].dims, alg[i].exact[0] ? alg[i].exact : "—", alg[i].cases,
			rep[2], rep[3] };
		mkDoc_Row(d, row);
	}
	mkDoc_TableEnd(d);
}

static void mkTiming_Means(mkDoc *d, const mkTiming *tm, int dim)
{
	int levels[1024], shown[8];
	int n = mkTiming_Levels(tm, dim, levels, 1024);
	if (n == 0)
		return;
	int k = mkShownLevels(dim, levels, n, shown, 6);
	const char *head[9];
	char names[8][48];
	head[0] = "case";
	head[1] = "method";
	for (int i = 0; i < k; ++i) {
		if (dim == 2)
			snprintf(names[i], sizeof names[i], "N = %d", shown[i]);
		else
			snprintf(names[i], sizeof names[i], "n = %d (%d pts)", shown[i], shown[i] * shown[i]);
		head[2 + i] = names[i];
	}
	char caption[512];
	snprintf(caption, sizeof caption, "%dD mean running time ± population std per call, at %d of the %d "
		"levels run (%s). A count in brackets is the trials a capped cell ran (see `trials_run`).", dim, k, n,
		dim == 2 ? "N points per body" : "n × n points per body");
	mkDoc_TableBegin(d, caption, 2 + k, head);
	for (int c = 0; c < 3; ++c)
		for (int m = 0; m < MK_NMETHODS; ++m) {
			int any = 0;
			char cells[8][MK_CELL_MAX];
			const char *row[9];
			row[0] = mkCases[c];
			row[1] = mkMethods[m];
			for (int i = 0; i < k; ++i) {
				const mkCellStat *s = mkTiming_Find(tm, dim, c, m, shown[i]);
				if (!s || s->n == 0) {
					snprintf(cells[i], MK_CELL_MAX, "—");
				} else {
					char a[64];
					mkFmtTime(a, sizeof a, s->mean, mkStd(s));
					if (s->run < s->planned)
						snprintf(cells[i], MK_CELL_MAX, "%s [%ld]", a, s->n);
					else
						snprintf(cells[i], MK_CELL_MAX, "%s", a);
					any = 1;
				}
				row[2 + i] = cells[i];
			}
			if (any)
				mkDoc_Row(d, row);
		}
	mkDoc_TableEnd(d);
}

static void mkTimingSection(mkDoc *d, const char *dir, mkTally *tally)
{
	char path[MK_PATH_MAX];
	snprintf(path, sizeof path, "%s/timing.csv", dir);
	mkTable t;
	mkTable_Load(&t, path);
	mkSidecar m;
	mkSidecar_Load(&m, path);
	mkDoc_Heading(d, 2, "Running time (paper §6.3, Table 1, Figs. 5–8)");
	mkTiming tm;
	memset(&tm, 0, sizeof tm);
	int usable = t.present && mkTiming_Load(&tm, &t) == 0;
	if (!usable) {
		mkDoc_Para(d, "%s: `%s` %s. The paper publishes no running-time numbers for this section, only the "
			"statements listed below, none of which is checked here yet.", mkNotYet, path, t.present
			? "lacks the columns of the `timing` driver" : "does not exist (run the `timing` driver)");
	} else {
		mkDoc_Source(d, path, &t, &m);
		const char *keys[] = { "rotation_draw", "clock", "timed_call", "warm_up", "trial_cap", "threads",
			"closed_form_impl", "cpu_model", "cpus_allowed", "loadavg_start", "loadavg_end", "skipped" };
		const char *label[] = { "Rotation draw (3D)", "Clock", "One measurement", "Warm-up", "Trial cap",
			"Threads", "Closed-form kernel", "CPU", "CPUs allowed", "Load average at start",
			"Load average at end", "Skipped" };
		for (size_t i = 0; i < sizeof keys / sizeof keys[0]; ++i) {
			const char *v = mkSidecar_Get(&m, keys[i]);
			mkDoc_Item(d, "%s: %s%s", label[i], v ? v : "not recorded",
				strcmp(keys[i], "rotation_draw") == 0 && v && strcmp(v, "paper") == 0
				? " (the reference code's normalised quaternion with four U(0,1) entries, not uniform on SO(3))"
				: "");
		}
		mkDoc_EndItems(d);
		mkDoc_Para(d, "The paper ran MATLAB R2020b on an Intel Xeon at 2.80 GHz and reports curves, not "
			"numbers; absolute times here are not comparable with its figures, only the shapes and orderings "
			"that its text states.");
	}
	mkTiming_Applicability(d, &tm);
	mkTiming_Statements(d, &tm, tally);
	if (usable) {
		mkTiming_Means(d, &tm, 2);
		mkTiming_Means(d, &tm, 3);
		long failed = 0;
		for (long i = 0; i < tm.count; ++i)
			failed += tm.cell[i].failed;
		if (failed)
			mkDoc_Para(d, "**%ld calls failed** (status other than ok); they are left out of the means.", failed);
	}
	mkTiming_Free(&tm);
	mkSidecar_Free(&m);
	mkTable_Free(&t);
}

/* ---- Sec. 7.1: configuration-space obstacles (Table 2) --------------------- */

static void mkCObstacles(mkDoc *d, const char *dir, mkTally *tally)
{
	char path[MK_PATH_MAX];
	snprintf(path, sizeof path, "%s/cobstacle.csv", dir);
	mkTable t;
	mkTable_Load(&t, path);
	mkSidecar m;
	mkSidecar_Load(&m, path);
	mkDoc_Heading(d, 2, "Configuration-space obstacles (paper §7.1, Table 2)");
	static const struct { int dim, obstacles, points, orientations; const char *total, *per; double t, p; } pub[] = {
		{ 2, 50, 50, 50, "0.36", "2.860", 0.36, 2.860 },
		{ 2, 1000, 50, 50, "6.41", "2.563", 6.41, 2.563 },
		{ 2, 10000, 50, 50, "64.26", "2.570", 64.26, 2.570 },
		{ 3, 50, 100, 3600, "95.54", "5.308", 95.54, 5.308 },
		{ 3, 200, 100, 3600, "375.02", "5.209", 375.02, 5.209 },
		{ 3, 1000, 100, 3600, "1907.85", "5.299", 1907.85, 5.299 },
	};
	int cdim = mkTable_Col(&t, "dim"), cobs = mkTable_Col(&t, "obstacles"), cpts = mkTable_Col(&t, "points");
	int cori = mkTable_Col(&t, "orientations"), ctot = mkTable_Col(&t, "total_s");
	int cper = mkTable_Col(&t, "us_per_point");
	int usable = t.present && cdim >= 0 && cobs >= 0 && cpts >= 0 && cori >= 0 && ctot >= 0;
	if (!usable)
		mkDoc_Para(d, "%s: `%s` %s. None of the 12 published numbers below has a counterpart.", mkNotYet, path,
			t.present ? "lacks the columns dim, obstacles, points, orientations, total_s"
			: "does not exist (run the `cobstacle` driver)");
	else {
		mkDoc_Source(d, path, &t, &m);
		const char *d3 = mkSidecar_Get(&m, "draw_3d"), *so3 = mkSidecar_Get(&m, "so3_file");
		const char *timed = mkSidecar_Get(&m, "timed_region");
		mkDoc_Para(d, "Rotation draw: in the 3D draws (%s); robot orientations from %s. Timed: %s. The paper "
			"ran MATLAB on one core of a Xeon at 2.8 GHz. Means over the trials of each level.",
			d3 ? d3 : "(draw not recorded)", so3 ? so3 : "(not recorded)", timed ? timed : "not recorded");
	}
	static const char *const head[] = { "dim", "obstacles", "points", "orientations", "published total (s)",
		"reproduced", "ratio", "published per point (µs)", "reproduced", "ratio" };
	mkDoc_TableBegin(d, "C-obstacle generation: total time and time per boundary point.", 10, head);
	for (size_t i = 0; i < sizeof pub / sizeof pub[0]; ++i) {
		mkMean total, perpoint;
		memset(&total, 0, sizeof total);
		memset(&perpoint, 0, sizeof perpoint);
		for (long r = 0; usable && r < t.rows; ++r)
			if ((int)mkTable_Num(&t, r, cdim) == pub[i].dim && (int)mkTable_Num(&t, r, cobs) == pub[i].obstacles
				&& (int)mkTable_Num(&t, r, cpts) == pub[i].points
				&& (int)mkTable_Num(&t, r, cori) == pub[i].orientations) {
				double tot = mkTable_Num(&t, r, ctot);
				mkMean_Add(&total, tot);
				/* the driver's own per-point figure, else total / points computed */
				mkMean_Add(&perpoint, cper >= 0 ? mkTable_Num(&t, r, cper)
					: tot / ((double)pub[i].obstacles * pub[i].points * pub[i].orientations) * 1e6);
			}
		double v = mkMean_Get(&total);
		double per = mkMean_Get(&perpoint);
		char a[8][MK_CELL_MAX];
		snprintf(a[0], MK_CELL_MAX, "%dD", pub[i].dim);
		snprintf(a[1], MK_CELL_MAX, "%d", pub[i].obstacles);
		snprintf(a[2], MK_CELL_MAX, "%d", pub[i].points);
		snprintf(a[3], MK_CELL_MAX, "%d", pub[i].orientations);
		if (isnan(v)) {
			snprintf(a[4], MK_CELL_MAX, "%s", mkNotYet);
			snprintf(a[6], MK_CELL_MAX, "%s", mkNotYet);
		} else {
			snprintf(a[4], MK_CELL_MAX, "%.4g", v);
			snprintf(a[6], MK_CELL_MAX, "%.4g", per);
		}
		mkFmtRatio(a[5], MK_CELL_MAX, v, pub[i].t);
		mkFmtRatio(a[7], MK_CELL_MAX, per, pub[i].p);
		const char *row[10] = { a[0], a[1], a[2], a[3], pub[i].total, a[4], a[5], pub[i].per, a[6], a[7] };
		mkDoc_Row(d, row);
		mkTally_Add(tally, !isnan(v));
		mkTally_Add(tally, !isnan(v));
	}
	mkDoc_TableEnd(d);
	mkSidecar_Free(&m);
	mkTable_Free(&t);
}

/* ---- Sec. 7.2: collision detection (Table 3) ------------------------------- */

/* Letters and digits only, lower case: "MinkSum (Ray)" -> "minksumray". */
static void mkSquash(const char *s, char *out, size_t len)
{
	size_t n = 0;
	for (; *s && n + 1 < len; ++s)
		if (isalnum((unsigned char)*s))
			out[n++] = (char)tolower((unsigned char)*s);
	out[n] = '\0';
}

/* The reproduction's own figures per pair and algorithm (nothing
 * published to compare with): mean and median time, the solvers' success
 * rate and the agreement with the referee outside its margin. */
static void mkCollisionDetails(mkDoc *d, const mkTable *t, const mkSidecar *m, int cpair, int calg, int csec)
{
	static const char *const pairs[] = { "ellipsoids", "superquadrics" };
	static const char *const algs[] = { "GJK", "ASC", "Implicit", "Common Normal", "MinkSum (Ray)",
		"MinkSum (Normal)" };
	int csucc = mkTable_Col(t, "success"), cagree = mkTable_Col(t, "agrees");
	const char *margin = mkSidecar_Get(m, "referee_margin");
	mkDoc_Para(d, "Per algorithm: success = residual below 1e-10 (LM) or Ipopt's Solve_Succeeded "
		"(Implicit); agreement = same verdict as the support-function referee, over the trials whose "
		"|min g| exceeds the margin (%s); the others are too close to call.", margin ? margin : "not recorded");
	static const char *const head[] = { "pair", "algorithm", "queries", "mean (ms)", "median (ms)",
		"success", "agreement", "too close" };
	mkDoc_TableBegin(d, "Collision detection: the reproduction's figures per algorithm.", 8, head);
	double *ms = malloc((size_t)(t->rows > 0 ? t->rows : 1) * sizeof(double));
	for (int p = 0; ms && p < 2; ++p) {
		for (size_t a = 0; a < sizeof algs / sizeof algs[0]; ++a) {
			char want[64], alg[64];
			mkSquash(algs[a], want, sizeof want);
			long n = 0, ns = 0, ok = 0, nd = 0, ag = 0, close = 0;
			double sum = 0.0;
			for (long r = 0; r < t->rows; ++r) {
				if (strcmp(mkTable_Str(t, r, cpair), pairs[p]) != 0)
					continue;
				mkSquash(mkTable_Str(t, r, calg), alg, sizeof alg);
				if (strcmp(alg, want) != 0)
					continue;
				double v = 1e3 * mkTable_Num(t, r, csec);
				ms[n++] = v;
				sum += v;
				double sv = mkTable_Num(t, r, csucc), av = mkTable_Num(t, r, cagree);
				if (!isnan(sv)) {
					ns += 1;
					ok += sv == 1.0;
				}
				if (!isnan(av)) {
					nd += 1;
					ag += av == 1.0;
				} else {
					close += 1;
				}
			}
			if (n == 0)
				continue;
			qsort(ms, (size_t)n, sizeof(double), mkCompareDouble);
			double med = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
			char c[6][MK_CELL_MAX];
			snprintf(c[0], MK_CELL_MAX, "%ld", n);
			snprintf(c[1], MK_CELL_MAX, "%.3g", sum / (double)n);
			snprintf(c[2], MK_CELL_MAX, "%.3g", med);
			if (ns)
				snprintf(c[3], MK_CELL_MAX, "%.4f", (double)ok / (double)ns);
			else
				snprintf(c[3], MK_CELL_MAX, "—");
			if (nd)
				snprintf(c[4], MK_CELL_MAX, "%.4f (%ld/%ld)", (double)ag / (double)nd, ag, nd);
			else
				snprintf(c[4], MK_CELL_MAX, "—");
			snprintf(c[5], MK_CELL_MAX, "%ld", close);
			const char *row[8] = { pairs[p], algs[a], c[0], c[1], c[2], c[3], c[4], c[5] };
			mkDoc_Row(d, row);
		}
	}
	free(ms);
	mkDoc_TableEnd(d);
}

static void mkCollisions(mkDoc *d, const char *dir, mkTally *tally)
{
	char path[MK_PATH_MAX];
	snprintf(path, sizeof path, "%s/collision.csv", dir);
	mkTable t;
	mkTable_Load(&t, path);
	mkSidecar m;
	mkSidecar_Load(&m, path);
	mkDoc_Heading(d, 2, "Collision detection (paper §7.2, Table 3)");
	static const struct { const char *alg, *ell, *sq; double e, s; } pub[] = {
		{ "GJK", "18.4", "18.3", 18.4, 18.3 },
		{ "ASC", "0.133", "—", 0.133, NAN },
		{ "Implicit", "27.0", "42.3", 27.0, 42.3 },
		{ "Common Normal", "4.1", "7.1", 4.1, 7.1 },
		{ "MinkSum (Ray)", "3.5", "5.2", 3.5, 5.2 },
		{ "MinkSum (Normal)", "3.5", "5.1", 3.5, 5.1 },
	};
	int cpair = mkTable_Col(&t, "pair"), calg = mkTable_Col(&t, "algorithm"), csec = mkTable_Col(&t, "seconds");
	int usable = t.present && cpair >= 0 && calg >= 0 && csec >= 0;
	if (!usable)
		mkDoc_Para(d, "%s: `%s` %s. None of the 11 published mean times below has a counterpart.", mkNotYet,
			path, t.present ? "lacks the columns pair (ellipsoids|superquadrics), algorithm, seconds"
			: "does not exist (the collision experiment is not built)");
	else {
		mkDoc_Source(d, path, &t, &m);
		const char *rot = mkSidecar_Get(&m, "rotation_draw");
		mkDoc_Para(d, "Rotation draw: %s.", rot ? rot : "not recorded in the sidecar");
	}
	static const char *const head[] = { "algorithm", "published ellipsoids (ms)", "reproduced", "ratio",
		"published superquadrics (ms)", "reproduced", "ratio" };
	mkDoc_TableBegin(d, "Collision detection: mean time per query over 10⁴ random poses.", 7, head);
	for (size_t i = 0; i < sizeof pub / sizeof pub[0]; ++i) {
		char want[64], alg[64];
		mkSquash(pub[i].alg, want, sizeof want);
		mkMean e, s;
		memset(&e, 0, sizeof e);
		memset(&s, 0, sizeof s);
		for (long r = 0; usable && r < t.rows; ++r) {
			mkSquash(mkTable_Str(&t, r, calg), alg, sizeof alg);
			if (strcmp(alg, want) != 0)
				continue;
			const char *pair = mkTable_Str(&t, r, cpair);
			double ms = 1e3 * mkTable_Num(&t, r, csec);
			if (strcmp(pair, "ellipsoids") == 0)
				mkMean_Add(&e, ms);
			else if (strcmp(pair, "superquadrics") == 0)
				mkMean_Add(&s, ms);
		}
		char a[4][MK_CELL_MAX];
		double ve = mkMean_Get(&e), vs = mkMean_Get(&s);
		if (isnan(ve))
			snprintf(a[0], MK_CELL_MAX, "%s", mkNotYet);
		else
			snprintf(a[0], MK_CELL_MAX, "%.3g", ve);
		mkFmtRatio(a[1], MK_CELL_MAX, ve, pub[i].e);
		if (isnan(pub[i].s))
			snprintf(a[2], MK_CELL_MAX, "—");
		else if (isnan(vs))
			snprintf(a[2], MK_CELL_MAX, "%s", mkNotYet);
		else
			snprintf(a[2], MK_CELL_MAX, "%.3g", vs);
		mkFmtRatio(a[3], MK_CELL_MAX, vs, pub[i].s);
		const char *row[7] = { pub[i].alg, pub[i].ell, a[0], a[1], pub[i].sq, a[2], a[3] };
		mkDoc_Row(d, row);
		mkTally_Add(tally, !isnan(ve));
		if (!isnan(pub[i].s))
			mkTally_Add(tally, !isnan(vs));
	}
	mkDoc_TableEnd(d);
	if (usable)
		mkCollisionDetails(d, &t, &m, cpair, calg, csec);
	mkSidecar_Free(&m);
	mkTable_Free(&t);
}

/* ---- main ------------------------------------------------------------------ */

static void mkUsage(FILE *fp)
{
	fputs("usage: tables [--results DIR] [--md PATH] [--tex PATH]\n"
		"Every published number of the paper beside its reproduction, from DIR/validation.csv,\n"
		"fitting.csv, timing.csv, cobstacle.csv and collision.csv (and their .meta sidecars);\n"
		"missing results are listed as NOT REPRODUCED YET. Writes Markdown and LaTeX.\n"
		"\n"
		"  --results DIR   where the result files are (default results)\n"
		"  --md PATH       Markdown output (default DIR/tables.md)\n"
		"  --tex PATH      LaTeX output (default DIR/tables.tex)\n"
		"  --help          this text\n", fp);
}

int main(int argc, char **argv)
{
	const char *dir = "results", *md = NULL, *tex = NULL;
	for (int i = 1; i < argc; ++i) {
		const char *a = argv[i];
		if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
			mkUsage(stdout);
			return 0;
		}
		const char **dst = strcmp(a, "--results") == 0 ? &dir : strcmp(a, "--md") == 0 ? &md
			: strcmp(a, "--tex") == 0 ? &tex : NULL;
		if (!dst) {
			fprintf(stderr, "tables: %s: unknown option (see --help)\n", a);
			return 2;
		}
		if (i + 1 >= argc || !argv[i + 1][0]) {
			fprintf(stderr, "tables: %s: missing value (a path)\n", a);
			return 2;
		}
		*dst = argv[++i];
	}
	char mdpath[MK_PATH_MAX], texpath[MK_PATH_MAX], msg[1024];
	snprintf(mdpath, sizeof mdpath, "%s/tables.md", dir);
	snprintf(texpath, sizeof texpath, "%s/tables.tex", dir);
	mkOutFile fmd, ftex;
	if (mkOutFile_Open(&fmd, md ? md : mdpath, msg, sizeof msg) != 0) {
		fprintf(stderr, "tables: %s\n", msg);
		return 1;
	}
	if (mkOutFile_Open(&ftex, tex ? tex : texpath, msg, sizeof msg) != 0) {
		fprintf(stderr, "tables: %s\n", msg);
		mkOutFile_Discard(&fmd);
		return 1;
	}
	/* The body goes to temporary streams first, so that the summary of what
	 * is reproduced can lead the documents. */
	mkDoc body = { tmpfile(), tmpfile(), 0 };
	if (!body.md || !body.tex) {
		fprintf(stderr, "tables: cannot create a temporary file\n");
		mkOutFile_Discard(&fmd);
		mkOutFile_Discard(&ftex);
		return 1;
	}
	mkTally tally = { 0, 0, 0 };
	mkValidation(&body, dir, &tally);
	mkFitting(&body, dir, &tally);
	mkTimingSection(&body, dir, &tally);
	mkCObstacles(&body, dir, &tally);
	mkCollisions(&body, dir, &tally);

	mkDoc head = { fmd.fp, ftex.fp, 0 };
	fputs("\\documentclass[10pt]{article}\n\\usepackage[utf8]{inputenc}\n\\usepackage[margin=15mm]{geometry}\n"
		"\\begin{document}\n", ftex.fp);
	fprintf(fmd.fp, "# The paper's published numbers beside this reproduction\n\n");
	fputs("\\section*{The paper's published numbers beside this reproduction}\n", ftex.fp);
	mkDoc_Para(&head, "Generated by `tables` from the result files in `%s/` only (nothing is measured "
		"here). Paper: Ruan & Chirikjian, Closed-Form Minkowski Sums of Convex Bodies with Smooth "
		"Positively Curved Boundaries, CAD 2022. Ratio = reproduced / published.", dir);
	mkDoc_Para(&head, "Published figures and statements: %d; with a reproduced counterpart: %d; %s: %d%s.",
		tally.published, tally.reproduced, tally.missing ? mkNotYet : "not reproduced yet", tally.missing,
		tally.missing ? " (listed as such in the tables below, never filled in)" : "");
	FILE *parts[2] = { body.md, body.tex }, *outs[2] = { fmd.fp, ftex.fp };
	for (int i = 0; i < 2; ++i) {
		rewind(parts[i]);
		char buf[8192];
		size_t n;
		while ((n = fread(buf, 1, sizeof buf, parts[i])) > 0)
			fwrite(buf, 1, n, outs[i]);
		fclose(parts[i]);
	}
	fputs("\\end{document}\n", ftex.fp);
	mkOutFile *files[2] = { &fmd, &ftex };
	if (mkOutFile_CommitAll(files, 2, msg, sizeof msg) != 0) {
		fprintf(stderr, "tables: %s\n", msg);
		return 1;
	}
	printf("tables: %d published figures and statements, %d reproduced, %d not reproduced yet\n",
		tally.published, tally.reproduced, tally.missing);
	return 0;
}
