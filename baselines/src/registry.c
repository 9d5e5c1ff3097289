/* registry.c - the table of methods: every entry's name, description,
 * flags, run and accept functions and resolution range, in one place. The
 * algorithms are in closed.c (the core's closed forms), geometric.c and
 * sampled.c (hulls of pairwise sums, edge sorting). An entry that is one
 * member of a family (one closed form, one hull library) gets its own run
 * functions below, which bind the family's parameter: an mkMethod's run
 * functions take no context. A method of its own kind defines its mkMethod
 * in a file of its own, baselines/src/method_*.c, and adds one line to the
 * table in registry.def (mink/registry.h). */
#include <ctype.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>

#include <mink/baselines.h>
#include <mink/external.h>
#include <mink/registry.h>

#include "registry_internal.h"

/* ---- family members: the parameter bound ---------------------------------- */

static mkResult normal2(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	return mkClosed2_Run(b1, b2, set, n, out, MK_FORM_NORMAL, MK_PRECISION_DOUBLE);
}
static mkResult normal3(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	return mkClosed3_Run(b1, b2, set, n, out, MK_FORM_NORMAL, MK_PRECISION_DOUBLE);
}
static mkResult gradient2(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	return mkClosed2_Run(b1, b2, set, n, out, MK_FORM_GRADIENT, MK_PRECISION_DOUBLE);
}
static mkResult gradient3(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	return mkClosed3_Run(b1, b2, set, n, out, MK_FORM_GRADIENT, MK_PRECISION_DOUBLE);
}
static mkResult paper2(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	return mkClosed2_Run(b1, b2, set, n, out, MK_FORM_PAPER, MK_PRECISION_DOUBLE);
}
static mkResult paper3(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	return mkClosed3_Run(b1, b2, set, n, out, MK_FORM_PAPER, MK_PRECISION_DOUBLE);
}
static mkResult epick2(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	return mkHullSums2_Run(b1, b2, set, n, out, mkHull2_CgalEpick);
}
static mkResult epick3(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	return mkHullSums3_Run(b1, b2, set, n, out, mkHull3_CgalEpick);
}
static mkResult epeck2(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	return mkHullSums2_Run(b1, b2, set, n, out, mkHull2_CgalEpeck);
}
static mkResult epeck3(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	return mkHullSums3_Run(b1, b2, set, n, out, mkHull3_CgalEpeck);
}
static mkResult qhull2(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	return mkHullSums2_Run(b1, b2, set, n, out, mkHull2_Qhull);
}
static mkResult qhull3(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	return mkHullSums3_Run(b1, b2, set, n, out, mkHull3_Qhull);
}

/* ---- the entries ------------------------------------------------------------ */

static mkResult normal2f(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	return mkClosed2_Run(b1, b2, set, n, out, MK_FORM_NORMAL, MK_PRECISION_F32);
}
static mkResult normal3f(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	return mkClosed3_Run(b1, b2, set, n, out, MK_FORM_NORMAL, MK_PRECISION_F32);
}
static mkResult gradient2f(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	return mkClosed2_Run(b1, b2, set, n, out, MK_FORM_GRADIENT, MK_PRECISION_F32);
}
static mkResult gradient3f(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	return mkClosed3_Run(b1, b2, set, n, out, MK_FORM_GRADIENT, MK_PRECISION_F32);
}

const mkMethod mkMethod_ClosedNormal = {
	"closed-normal",
	"closed form, Theorem 1: support points f~1(n) - f~2(-n) along body 1's normals",
	"Ruan & Chirikjian, CAD 2022, Theorem 1 and eq. mink_sum_transform_1",
	MK_METHOD_2D | MK_METHOD_3D | MK_METHOD_EXACT,
	mkAcceptAny2, mkAcceptAny3, normal2, normal3,
};

const mkMethod mkMethod_ClosedGradient = {
	"closed-gradient",
	"closed form, Theorem 2: un-normalised gradients, f~~ evaluated stably",
	"Ruan & Chirikjian, CAD 2022, Theorem 2 and eq. mink_sum_transform_2",
	MK_METHOD_2D | MK_METHOD_3D | MK_METHOD_EXACT,
	mkAcceptAny2, mkAcceptAny3, gradient2, gradient3,
};

const mkMethod mkMethod_ClosedPaper = {
	"closed-paper",
	"Theorem 2 exactly as printed (reference only: loses digits near the 3D poles)",
	"Ruan & Chirikjian, CAD 2022, eqs. 2d_sq_f_m, 3d_sq_f_m, Phi_m1_general",
	MK_METHOD_2D | MK_METHOD_3D,
	mkAcceptAny2, mkAcceptAny3, paper2, paper3,
};

/* The single-precision tier (mink/sum.h, MK_PRECISION_F32): the same closed
 * forms, each point within MK_F32_TOL of the sum's size of the exact boundary;
 * pairs outside the tier's domain run in double. */
const mkMethod mkMethod_ClosedNormalF32 = {
	"closed-normal-f32",
	"closed form, Theorem 1, in single precision (about 2x faster; points within 1e-6 of scale)",
	"Ruan & Chirikjian, CAD 2022, Theorem 1; mink's f32 tier (docs/fast-tiers.md)",
	MK_METHOD_2D | MK_METHOD_3D | MK_METHOD_APPROX,
	mkAcceptAny2, mkAcceptAny3, normal2f, normal3f,
};

const mkMethod mkMethod_ClosedGradientF32 = {
	"closed-gradient-f32",
	"closed form, Theorem 2, in single precision (about 2x faster; points within 1e-6 of scale)",
	"Ruan & Chirikjian, CAD 2022, Theorem 2; mink's f32 tier (docs/fast-tiers.md)",
	MK_METHOD_2D | MK_METHOD_3D | MK_METHOD_APPROX,
	mkAcceptAny2, mkAcceptAny3, gradient2f, gradient3f,
};

const mkMethod mkMethod_Geometric = {
	"geometric",
	"closed-form geometric: body 1 offset through the map that makes ellipse body 2 a sphere",
	"Yan & Chirikjian, Geometriae Dedicata 2015; Ruan et al., WAFR 2018 (body2 an ellipse/ellipsoid)",
	MK_METHOD_2D | MK_METHOD_3D | MK_METHOD_EXACT | MK_METHOD_BASELINE,
	mkGeometric2_Accepts, mkGeometric3_Accepts, mkGeometric2_Run, mkGeometric3_Run,
};

const mkMethod mkMethod_HullCgalEpick = {
	"hull-cgal-epick",
	"convex hull of all pairwise sums of samples, CGAL on exact predicates (inexact constructions)",
	"definition (Lozano-Perez); CGAL convex_hull_2 / convex_hull_3, Epick kernel",
	MK_METHOD_2D | MK_METHOD_3D | MK_METHOD_SAMPLED,
	mkAcceptAny2, mkAcceptAny3, epick2, epick3,
};

const mkMethod mkMethod_HullCgalEpeck = {
	"hull-cgal-epeck",
	"convex hull of all pairwise sums of samples, CGAL on exact predicates and exact constructions",
	"definition (Lozano-Perez); CGAL convex_hull_2 / convex_hull_3, Epeck kernel",
	MK_METHOD_2D | MK_METHOD_3D | MK_METHOD_SAMPLED,
	mkAcceptAny2, mkAcceptAny3, epeck2, epeck3,
};

const mkMethod mkMethod_HullQhull = {
	"hull-qhull",
	"convex hull of all pairwise sums of samples, Qhull (what MATLAB's convhull runs)",
	"definition (Lozano-Perez); Barber, Dobkin & Huhdanpaa, ACM TOMS 1996 (libqhull_r)",
	MK_METHOD_2D | MK_METHOD_3D | MK_METHOD_SAMPLED,
	mkAcceptAny2, mkAcceptAny3, qhull2, qhull3,
};

const mkMethod mkMethod_EdgeSort = {
	"edge-sort",
	"edge sorting: O(m+n) merge of the two sample polygons' edges by slope, exact tests",
	"de Berg, Cheong, van Kreveld & Overmars, Computational Geometry, 3rd ed. 2008, Sec. 13.3",
	MK_METHOD_2D | MK_METHOD_SAMPLED,
	mkAcceptAny2, NULL, mkEdgeSort2_Run, NULL,
};

/* ---- the table, with each entry's indexing and resolution range ------------ */

/* Every entry's mkMethod, declared from the table itself, so that a method
 * defined in a file of its own needs no declaration here. */
#define MK_REGISTRY_ENTRY(symbol, indexing, nmin2, nmax2, nmin3, nmax3, tol) extern const mkMethod symbol;
#include "registry.def"
#undef MK_REGISTRY_ENTRY

typedef struct mkRegistry_Entry {
	const mkMethod *method;
	mkMethodIndexing indexing; /* how its points are indexed */
	int nmin2, nmax2;          /* resolution range in 2D */
	int nmin3, nmax3;          /* and in 3D (grid side) */
	double tol;                /* stated accuracy of an MK_METHOD_APPROX method */
} mkRegistry_Entry;

static const mkRegistry_Entry table[] = {
#define MK_REGISTRY_ENTRY(symbol, indexing, nmin2, nmax2, nmin3, nmax3, tol) \
	{&symbol, MK_INDEX_##indexing, nmin2, nmax2, nmin3, nmax3, tol},
#include "registry.def"
#undef MK_REGISTRY_ENTRY
};

enum { COUNT = (int)(sizeof table / sizeof table[0]) };

int mkRegistry_Count(void)
{
	return COUNT + mkExternal_Count();
}

const mkMethod *mkRegistry_At(int i)
{
	return i >= 0 && i < COUNT ? table[i].method : mkExternal_At(i - COUNT);
}

int mkRegistry_Names(const char **names, int max)
{
	int count = 0;
	for (; count < mkRegistry_Count() && count < max; ++count)
		names[count] = mkRegistry_At(count)->name;
	return count;
}

const mkMethod *mkRegistry_Find(const char *name)
{
	if (!name) return NULL;
	for (int i = 0; i < mkRegistry_Count(); ++i)
		if (strcmp(mkRegistry_At(i)->name, name) == 0) return mkRegistry_At(i);
	if (strncmp(name, "exec:", 5) == 0) return mkExternal_Find(name, NULL, 0);
	return NULL;
}

/* Append name to the comma-separated list out (used characters so far). */
static int mkRegistry_Append(char *out, size_t outlen, size_t *used, const char *name, char *msg, size_t msglen)
{
	int w = snprintf(out + *used, outlen - *used, "%s%s", *used ? "," : "", name);
	if (w < 0 || (size_t)w >= outlen - *used) return mkRefuse(msg, msglen, "the list is too long");
	*used += (size_t)w;
	return 1;
}

/* One line of a methods file, trimmed, registered; its name appended. */
static int mkRegistry_FileLine(const char *path, int lineno, char *line, char *out, size_t outlen, size_t *used,
	char *msg, size_t msglen)
{
	char item[1024], why[512];
	size_t len = strcspn(line, "=");
	if (!line[len] || len == 0)
		return mkRefuse(msg, msglen, "%s line %d: NAME: expected NAME=COMMAND, got '%.60s'", path, lineno, line);
	const char *cmd = line + len + 1;
	while (*cmd == ' ' || *cmd == '\t') ++cmd;
	if (!*cmd) return mkRefuse(msg, msglen, "%s line %d: COMMAND: empty after '='", path, lineno);
	while (len > 0 && (line[len - 1] == ' ' || line[len - 1] == '\t')) --len;
	int w = snprintf(item, sizeof item, "exec:%.*s=%s", (int)len, line, cmd);
	if (w < 0 || (size_t)w >= sizeof item)
		return mkRefuse(msg, msglen, "%s line %d: COMMAND: longer than %d characters", path, lineno,
			(int)sizeof item - 8);
	for (size_t i = 0; i < len; ++i)
		if (len > 100 || (!isalnum((unsigned char)line[i]) && !strchr("._-", line[i])))
			return mkRefuse(msg, msglen, "%s line %d: NAME '%.*s': must be 1 to 100 letters, digits, '.', '_', '-'",
				path, lineno, (int)len, line);
	const mkMethod *m = mkExternal_Find(item, why, sizeof why);
	if (!m) return mkRefuse(msg, msglen, "%s line %d: NAME=COMMAND: %s", path, lineno, why);
	return mkRegistry_Append(out, outlen, used, m->name, msg, msglen);
}

/* A methods file: one NAME=COMMAND per line, # comments and blank lines
 * skipped; every method registered and its name appended to out. */
static int mkRegistry_File(const char *path, char *out, size_t outlen, size_t *used, char *msg, size_t msglen)
{
	FILE *fp = fopen(path, "r");
	if (!fp) return mkRefuse(msg, msglen, "methods file %s cannot be opened", path);
	char line[1200];
	int lineno = 0, count = 0, ok = 1;
	while (ok && fgets(line, sizeof line, fp)) {
		++lineno;
		size_t len = strlen(line);
		if (len == sizeof line - 1 && line[len - 1] != '\n' && !feof(fp)) {
			ok = mkRefuse(msg, msglen, "%s line %d: longer than %d characters", path, lineno, (int)sizeof line - 2);
			break;
		}
		while (len > 0 && strchr(" \t\r\n", line[len - 1])) line[--len] = '\0';
		char *p = line + strspn(line, " \t");
		if (!*p || *p == '#') continue;
		ok = mkRegistry_FileLine(path, lineno, p, out, outlen, used, msg, msglen);
		count += ok;
	}
	if (ok && ferror(fp)) ok = mkRefuse(msg, msglen, "methods file %s: read error", path);
	fclose(fp);
	if (ok && count == 0) ok = mkRefuse(msg, msglen, "methods file %s names no method", path);
	return ok;
}

int mkRegistry_Resolve(const char *list, char *out, size_t outlen, char *msg, size_t msglen)
{
	size_t used = 0;
	if (!list || !out || outlen == 0) return mkRefuse(msg, msglen, "no list given");
	out[0] = '\0';
	for (const char *p = list; *p;) {
		size_t len = strcspn(p, ",");
		char item[1024];
		if (len >= sizeof item) return mkRefuse(msg, msglen, "an item of the list is too long");
		memcpy(item, p, len);
		item[len] = '\0';
		const char *name = item;
		if (item[0] == '@') {
			if (!mkRegistry_File(item + 1, out, outlen, &used, msg, msglen)) return 0;
			name = NULL;
		} else if (strncmp(item, "exec:", 5) == 0) {
			const mkMethod *m = mkExternal_Find(item, msg, msglen);
			if (!m) return 0;
			name = m->name;
		}
		if (name && !mkRegistry_Append(out, outlen, &used, name, msg, msglen)) return 0;
		p += len;
		if (*p == ',') ++p;
	}
	return 1;
}

static int runs_in(const mkMethod *m, int dim)
{
	return (dim == 2 && (m->flags & MK_METHOD_2D) && m->run2)
		|| (dim == 3 && (m->flags & MK_METHOD_3D) && m->run3);
}

static const mkRegistry_Entry *mkRegistry_EntryOf(const mkMethod *m)
{
	for (int i = 0; i < COUNT; ++i)
		if (table[i].method == m) return &table[i];
	return NULL;
}

double mkMethod_Tolerance(const mkMethod *m)
{
	const mkRegistry_Entry *e = mkRegistry_EntryOf(m);
	return e && (m->flags & MK_METHOD_APPROX) ? e->tol : 0.0;
}

mkMethodIndexing mkMethod_Indexing(const mkMethod *m)
{
	const mkRegistry_Entry *e = mkRegistry_EntryOf(m);
	if (e) return e->indexing;
	return m && ((m->flags & MK_METHOD_SAMPLED) || mkExternal_Is(m)) ? MK_INDEX_UNORDERED : MK_INDEX_PARAMETER;
}

int mkMethod_CheckN(const mkMethod *m, int dim, int n, char *msg, size_t msglen)
{
	if (!m) return mkRefuse(msg, msglen, "no method given");
	if (!runs_in(m, dim)) return mkRefuse(msg, msglen, "method %s does not run in %dD", m->name, dim);
	int lo = 1, hi = INT_MAX;
	const mkRegistry_Entry *e = mkRegistry_EntryOf(m);
	if (e) {
		lo = dim == 2 ? e->nmin2 : e->nmin3;
		hi = dim == 2 ? e->nmax2 : e->nmax3;
	}
	if (n >= lo && n <= hi) return 1;
	const char *unit = (m->flags & MK_METHOD_SAMPLED) ? (dim == 2 ? "samples per body" : "grid side per body")
		: (dim == 2 ? "points" : "grid side");
	return mkRefuse(msg, msglen, "n = %d is out of range for method %s in %dD: n (%s) must be in [%d, %d]",
		n, m->name, dim, unit, lo, hi);
}

int mkMethod2_Accepts(const mkMethod *m, mkBody2 b1, mkBody2 b2, mkSet set, char *msg, size_t msglen)
{
	if (!m || !runs_in(m, 2) || !m->accepts2)
		return mkRefuse(msg, msglen, "method %s does not run in 2D", m ? m->name : "(none)");
	return m->accepts2(b1, b2, set, msg, msglen);
}

int mkMethod3_Accepts(const mkMethod *m, mkBody3 b1, mkBody3 b2, mkSet set, char *msg, size_t msglen)
{
	if (!m || !runs_in(m, 3) || !m->accepts3)
		return mkRefuse(msg, msglen, "method %s does not run in 3D", m ? m->name : "(none)");
	return m->accepts3(b1, b2, set, msg, msglen);
}
