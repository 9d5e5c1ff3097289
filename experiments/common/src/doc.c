/* doc.c - Markdown and LaTeX written side by side. */
#include "mink_exp/doc.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* Text given to the writer is Markdown-flavoured UTF-8: `code` and **bold**
 * are the only markup; the LaTeX side translates them and the few
 * non-ASCII symbols used here. */

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

void mkDoc_Heading(mkDoc *d, int level, const char *text)
{
	fprintf(d->md, "\n%.*s %s\n\n", level, "####", text);
	fputs(level <= 1 ? "\\section*{" : level == 2 ? "\\subsection*{" : "\\subsubsection*{", d->tex);
	mkTex_Put(d->tex, text);
	fputs("}\n", d->tex);
}

/* One block of text: Markdown `md_lead` text `md_end`, LaTeX `tex_lead`
 * text and a blank line. */
static void mkDoc_Block(mkDoc *d, const char *md_lead, const char *md_end, const char *tex_lead,
	const char *fmt, va_list ap)
{
	char text[4096];
	vsnprintf(text, sizeof text, fmt, ap);
	fprintf(d->md, "%s%s%s", md_lead, text, md_end);
	fputs(tex_lead, d->tex);
	mkTex_Put(d->tex, text);
	fputs("\n\n", d->tex);
}

/* A paragraph (printf-style). */
void mkDoc_Para(mkDoc *d, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	mkDoc_Block(d, "", "\n\n", "", fmt, ap);
	va_end(ap);
}

/* A bullet list item (consecutive items form one list in Markdown; each
 * is its own paragraph in LaTeX, led by a dash). */
void mkDoc_Item(mkDoc *d, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	mkDoc_Block(d, "- ", "\n", "\\noindent -- ", fmt, ap);
	va_end(ap);
}

void mkDoc_EndItems(mkDoc *d)
{
	fputs("\n", d->md);
}

void mkDoc_TableBegin(mkDoc *d, const char *caption, int cols, const char *const *head)
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

void mkDoc_Row(mkDoc *d, const char *const *cells)
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

void mkDoc_TableEnd(mkDoc *d)
{
	fputs("\n", d->md);
	fputs("\\hline\n\\end{tabular}\n\\end{table}\n\n", d->tex);
}

/* ---- numbers as text ------------------------------------------------------- */

const char *const mkNotYet = "**NOT REPRODUCED YET**";

void mkFmt_Sci(char *buf, size_t len, double v)
{
	if (isnan(v))
		snprintf(buf, len, "—");
	else
		snprintf(buf, len, "%.4e", v);
}

void mkFmt_Ratio(char *buf, size_t len, double got, double published)
{
	if (isnan(got) || isnan(published) || published == 0.0)
		snprintf(buf, len, "—");
	else
		snprintf(buf, len, "%.3g", got / published);
}

/* "mean ± std unit": the unit that suits the mean (µs, ms or s), the mean
 * to three significant digits and the std to two, in the same unit. */
void mkFmt_Time(char *buf, size_t len, double mean, double std)
{
	double scale = mean < 1e-3 ? 1e6 : mean < 1.0 ? 1e3 : 1.0;
	const char *unit = mean < 1e-3 ? "µs" : mean < 1.0 ? "ms" : "s";
	if (isnan(mean))
		snprintf(buf, len, "—");
	else
		snprintf(buf, len, "%.3g ± %.2g %s", mean * scale, std * scale, unit);
}

/* ---- bookkeeping ---------------------------------------------------------- */

void mkTally_Add(mkTally *t, int reproduced)
{
	t->published += 1;
	if (reproduced)
		t->reproduced += 1;
	else
		t->missing += 1;
}

/* One line on where a table's numbers come from. */
void mkDoc_Source(mkDoc *d, const char *path, const mkTable *t, const mkMeta *m)
{
	const char *date = mkMeta_Get(m, "date_utc");
	const char *commit = mkMeta_Get(m, "git_commit");
	const char *seed = mkMeta_Get(m, "seed");
	const char *trials = mkMeta_Get(m, "trials");
	mkDoc_Para(d, "Source: `%s` (%ld rows; run %s, commit %.12s, seed %s, %s trials).", path, t->rows,
		date ? date : "unknown", commit ? commit : "unknown", seed ? seed : "?", trials ? trials : "?");
}


int mkResult_Load(const char *dir, const char *file, mkTable *t, mkMeta *m, char *path, size_t pathlen)
{
	snprintf(path, pathlen, "%s/%s", dir, file);
	mkTable_Load(t, path);
	mkMeta_InitEmpty(m);
	char stored[MK_PATH_MAX], side[MK_PATH_MAX + 8], msg[512];
	mkPath_Stored(path, stored, sizeof stored);
	snprintf(side, sizeof side, "%s.meta", stored);
	if (t->present && mkMeta_ReadFile(m, side, msg, sizeof msg) != 0)
		fprintf(stderr, "%s\n", msg);
	return t->present;
}

void mkResult_Free(mkTable *t, mkMeta *m)
{
	mkTable_Free(t);
	mkMeta_Free(m);
}

void mkMean_Add(mkMean *m, double v)
{
	if (isfinite(v)) {
		m->sum += v;
		m->n += 1;
	} else {
		m->nan += 1;
	}
}

double mkMean_Get(const mkMean *m)
{
	return m->n ? m->sum / (double)m->n : NAN;
}

int mkSection_Begin(mkSection *s, mkDoc *d, const char *heading, const char *dir, const char *file,
	const char *const *columns, const char *consequence)
{
	mkDoc_Heading(d, 2, heading);
	s->usable = mkResult_Load(dir, file, &s->t, &s->m, s->path, sizeof s->path);
	char list[512] = "";
	size_t len = 0;
	for (int i = 0; columns[i]; ++i) {
		s->usable = s->usable && mkTable_Col(&s->t, columns[i]) >= 0;
		len += (size_t)snprintf(list + len, len < sizeof list ? sizeof list - len : 0, "%s%s", i ? ", " : "",
			columns[i]);
	}
	if (s->usable) {
		mkDoc_Source(d, s->path, &s->t, &s->m);
		return 1;
	}
	size_t stem = strcspn(file, ".");
	if (s->t.present)
		mkDoc_Para(d, "%s: `%s` lacks the columns %s. %s", mkNotYet, s->path, list, consequence);
	else
		mkDoc_Para(d, "%s: `%s` does not exist (run the `%.*s` driver). %s", mkNotYet, s->path, (int)stem, file,
			consequence);
	return 0;
}

void mkSection_End(mkSection *s)
{
	mkResult_Free(&s->t, &s->m);
}
