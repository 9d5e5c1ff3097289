/* extremes.c - one cell of the extremes experiment (extremes.h): the
 * registry's methods run on the cell's pair, each output scored at 256 bits;
 * and the cells on several threads, their rows in cell order. */
#define _POSIX_C_SOURCE 200809L /* open_memstream */
#include "extremes.h"

#include <mink/mpref_measure.h>

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const mkExtremes_Columns[] = {
	"dim", "cell", "family", "set", "method", "n", "points",
	"eps1_b1", "eps2_b1", "eps1_b2", "eps2_b2", "axis", "shear", "size", "shift",
	"error_abs", "error_rel", "accuracy", "condition", "nonfinite", "status", "body1", "body2", NULL,
};

void mkExtremesOptions_Default(mkExtremesOptions *o)
{
	memset(o, 0, sizeof *o);
	o->grid = REF_GRID_QUICK;
	o->dim_on[2] = o->dim_on[3] = 1;
	o->set_on[0] = o->set_on[1] = 1;
	o->n2 = 64;
	o->n3 = 5;
	o->s2 = 64;
	o->s3 = 5;
	o->threads = 2;
	for (int i = 0; i < MK_EXTREMES_METHODS_MAX; ++i)
		o->method_on[i] = 1;
}

int mkExtremes_ParseMethods(void *on, const char *text, char *msg, size_t msglen)
{
	const char *names[MK_EXTREMES_METHODS_MAX];
	char list[4096];
	if (!mkRegistry_Resolve(text, list, sizeof list, msg, msglen))
		return -1;
	return mkArg_NameList(list, names, mkRegistry_Names(names, MK_EXTREMES_METHODS_MAX), (int *)on, msg, msglen);
}

long mkExtremes_N(const mkExtremesOptions *o, const mkMethod *m, int dim)
{
	int sampled = (m->flags & MK_METHOD_SAMPLED) != 0;
	return dim == 2 ? (sampled ? o->s2 : o->n2) : (sampled ? o->s3 : o->n3);
}

int mkExtremes_Check(const mkExtremesOptions *o, char *msg, size_t msglen)
{
	for (int i = 0; i < mkRegistry_Count() && i < MK_EXTREMES_METHODS_MAX; ++i) {
		const mkMethod *m = mkRegistry_At(i);
		for (int dim = 2; dim <= 3; ++dim) {
			unsigned runs = dim == 2 ? MK_METHOD_2D : MK_METHOD_3D;
			if (o->method_on[i] && o->dim_on[dim] && (m->flags & runs)
				&& !mkMethod_CheckN(m, dim, (int)mkExtremes_N(o, m, dim), msg, msglen))
				return -1;
		}
	}
	return 0;
}

long mkExtremes_Units(const mkExtremesOptions *o, int *dims, int *cells)
{
	long k = 0;
	for (int dim = 2; dim <= 3; ++dim) {
		long count = o->dim_on[dim] ? refGrid_Count(o->grid, dim) : 0;
		if (o->cells > 0 && count > o->cells)
			count = o->cells;
		for (long c = 0; c < count; ++c, ++k) {
			if (dims)
				dims[k] = dim;
			if (cells)
				cells[k] = (int)c;
		}
	}
	return k;
}

/* ---- one cell ------------------------------------------------------------- */

/* What a cell's rows share. */
typedef struct mkCellRun {
	refCell cell;
	mkSpec s1, s2;
	mkPointSet out;
	double *u;       /* body 1's surface parameters of the closed forms: ux, uy, uz */
	long ucap;
	refScoreMemo *memo; /* the searches of the (cell, set) so far: a point that
	                       an earlier method gave bit for bit is not searched again */
} mkCellRun;

/* The row of one method on one (cell, set). */
static void mkExtremes_Row(mkCsv *csv, const mkCellRun *cr, int plus, const mkMethod *m, long n,
	mkResult rc, const refScore *sc, double condition)
{
	const refCell *c = &cr->cell;
	mkCsv_Int(csv, c->dim);
	mkCsv_Int(csv, c->index);
	mkCsv_Str(csv, c->family);
	mkCsv_Str(csv, plus ? "plus" : "contact");
	mkCsv_Str(csv, m->name);
	mkCsv_Int(csv, n);
	mkCsv_Int(csv, rc == MK_OK ? cr->out.count : 0);
	mkCsv_Double(csv, c->eps[0][0]);
	mkCsv_Double(csv, c->eps[0][1]);
	mkCsv_Double(csv, c->eps[1][0]);
	mkCsv_Double(csv, c->eps[1][1]);
	mkCsv_Double(csv, c->axis);
	mkCsv_Double(csv, c->shear);
	mkCsv_Double(csv, c->size);
	mkCsv_Double(csv, c->shift);
	if (rc == MK_OK && sc->points > 0) {
		mkCsv_Double(csv, sc->errorAbs);
		mkCsv_Double(csv, sc->errorRel);
		mkCsv_Double(csv, sc->accuracy);
	} else {
		mkCsv_Empty(csv);
		mkCsv_Empty(csv);
		mkCsv_Empty(csv);
	}
	mkCsv_Double(csv, condition);
	mkCsv_Int(csv, rc == MK_OK ? sc->nonfinite : 0);
	char status[64];
	if (rc != MK_OK)
		snprintf(status, sizeof status, "error:%s", mkResult_Name(rc));
	else
		snprintf(status, sizeof status, "%s", sc->nonfinite > 0 ? "nonfinite" : "ok");
	mkCsv_Str(csv, status);
	mkCsv_Str(csv, c->spec1);
	mkCsv_Str(csv, c->spec2);
	mkCsv_EndRow(csv);
}

/* Run method m on the cell and score it. Returns the method's result; -2 when
 * the parameters cannot be allocated or the scoring refuses its input. */
static int mkExtremes_Method(mkCellRun *cr, int plus, const mkMethod *m, long n, refScore *sc, mkResult *rc)
{
	int dim = cr->cell.dim;
	mkSet set = plus ? MK_SET_PLUS : MK_SET_CONTACT;
	*rc = dim == 2 ? m->run2(cr->s1.body2, cr->s2.body2, set, (int)n, &cr->out)
		: m->run3(cr->s1.body3, cr->s2.body3, set, (int)n, &cr->out);
	memset(sc, 0, sizeof *sc);
	if (*rc != MK_OK)
		return 0;
	const double *ux = NULL, *uy = NULL, *uz = NULL;
	long count = dim == 2 ? n : n * n;
	if (!(m->flags & MK_METHOD_SAMPLED) && cr->out.count == count) {
		if (count > cr->ucap) {
			free(cr->u);
			cr->u = malloc(3 * (size_t)count * sizeof *cr->u);
			cr->ucap = cr->u ? count : 0;
			if (!cr->u)
				return -2;
		}
		ux = cr->u;
		uy = cr->u + count;
		uz = dim == 3 ? cr->u + 2 * count : NULL;
		if ((dim == 2 ? mkSample2_Angles((int)n, cr->u, cr->u + count)
			: mkSample3_Grid((int)n, cr->u, cr->u + count, cr->u + 2 * count)) != MK_OK)
			return -2;
	}
	return refSum_ScoreMemo(&cr->cell.b1, &cr->cell.b2, plus, cr->out.x, cr->out.y, dim == 3 ? cr->out.z : NULL,
		cr->out.count, ux, uy, uz, cr->memo, sc) == 0 ? 0 : -2;
}

static int mkExtremes_Accepts(const mkMethod *m, const mkCellRun *cr, int plus)
{
	char msg[256];
	mkSet set = plus ? MK_SET_PLUS : MK_SET_CONTACT;
	return cr->cell.dim == 2 ? mkMethod2_Accepts(m, cr->s1.body2, cr->s2.body2, set, msg, sizeof msg)
		: mkMethod3_Accepts(m, cr->s1.body3, cr->s2.body3, set, msg, sizeof msg);
}

int mkExtremes_RunCell(const mkExtremesOptions *o, int dim, int cell, mkCsv *csv, mkExtremesTally *tally)
{
	mkCellRun cr;
	memset(&cr, 0, sizeof cr);
	char msg[256];
	if (refGrid_Cell(o->grid, dim, cell, &cr.cell) != 0
		|| mkSpec_Parse(cr.cell.spec1, dim, "body1", &cr.s1, msg, sizeof msg) != MK_OK
		|| mkSpec_Parse(cr.cell.spec2, dim, "body2", &cr.s2, msg, sizeof msg) != MK_OK) {
		fprintf(stderr, "extremes: %dD cell %d cannot be built\n", dim, cell);
		return -1;
	}
	cr.memo = refScoreMemo_New();
	if (!cr.memo) {
		fprintf(stderr, "extremes: out of memory\n");
		return -1;
	}
	int failed = 0;
	for (int plus = 0; plus <= 1 && !failed; ++plus) {
		if (!o->set_on[plus])
			continue;
		refCondition cond;
		/* The condition's sampling as the reference's preview has it: 16
		 * normals (2D) or a 5 x 5 grid (3D), three draws, a seed per cell. */
		if (refSum_Condition(&cr.cell.b1, &cr.cell.b2, plus, dim == 2 ? 16 : 5, 3, 1000u + (unsigned)cell, &cond) != 0)
			cond.value = NAN;
		for (int i = 0; i < mkRegistry_Count() && i < MK_EXTREMES_METHODS_MAX && !failed; ++i) {
			const mkMethod *m = mkRegistry_At(i);
			if (!o->method_on[i] || !(m->flags & (dim == 2 ? MK_METHOD_2D : MK_METHOD_3D)))
				continue;
			if (!mkExtremes_Accepts(m, &cr, plus)) {
				tally->rejected += 1;
				continue;
			}
			long n = mkExtremes_N(o, m, dim);
			refScore sc;
			mkResult rc;
			if (mkExtremes_Method(&cr, plus, m, n, &sc, &rc) != 0) {
				fprintf(stderr, "extremes: %dD cell %d %s: out of memory or unscorable output\n", dim, cell, m->name);
				failed = 1;
				break;
			}
			mkExtremes_Row(csv, &cr, plus, m, n, rc, &sc, cond.value);
			tally->rows += 1;
			tally->failed += rc != MK_OK;
			tally->nonfinite += rc == MK_OK ? sc.nonfinite : 0;
		}
	}
	long hits, misses;
	refScoreMemo_Counts(cr.memo, &hits, &misses);
	tally->reused += hits;
	tally->searches += misses;
	refScoreMemo_Free(cr.memo);
	mkPointSet_Free(&cr.out);
	free(cr.u);
	return failed ? -1 : 0;
}

/* ---- the cells on several threads ---------------------------------------- */

/* One unit's rows, gathered in memory until the units before it are written. */
typedef struct mkUnitOut {
	char *text;
	size_t len;
	long rows;
	int misuse, failed, done;
	mkExtremesTally tally;
} mkUnitOut;

typedef struct mkUnitPool {
	const mkExtremesOptions *o;
	const int *dims, *cells;
	long count, next;
	int stop;
	int columns;
	mkUnitOut *out;
	pthread_mutex_t lock;
	pthread_cond_t ready;
} mkUnitPool;

static void mkExtremes_RunUnit(mkUnitPool *p, long k)
{
	mkUnitOut *u = &p->out[k];
	mkCsv csv;
	memset(&csv, 0, sizeof csv);
	csv.columns = p->columns;
	csv.file.fp = open_memstream(&u->text, &u->len);
	if (!csv.file.fp) {
		fprintf(stderr, "extremes: out of memory\n");
		u->failed = 1;
		return;
	}
	u->failed = mkExtremes_RunCell(p->o, p->dims[k], p->cells[k], &csv, &u->tally) != 0;
	if (fclose(csv.file.fp) != 0)
		u->failed = 1;
	u->rows = csv.rows;
	u->misuse = csv.misuse || csv.field != 0;
}

static void *mkExtremes_Worker(void *arg)
{
	mkUnitPool *p = arg;
	pthread_mutex_lock(&p->lock);
	while (!p->stop && p->next < p->count) {
		long k = p->next++;
		pthread_mutex_unlock(&p->lock);
		mkExtremes_RunUnit(p, k);
		pthread_mutex_lock(&p->lock);
		p->out[k].done = 1;
		if (p->out[k].failed)
			p->stop = 1;
		pthread_cond_broadcast(&p->ready);
	}
	pthread_mutex_unlock(&p->lock);
	refThread_Release();
	return NULL;
}

int mkExtremes_RunUnits(const mkExtremesOptions *o, const int *dims, const int *cells, long count,
	mkCsv *csv, mkExtremesTally *tally, void (*step)(void *ctx), void *ctx)
{
	mkUnitPool p;
	memset(&p, 0, sizeof p);
	p.o = o;
	p.dims = dims;
	p.cells = cells;
	p.count = count;
	while (mkExtremes_Columns[p.columns])
		p.columns += 1;
	p.out = calloc((size_t)(count > 0 ? count : 1), sizeof *p.out);
	long nt = o->threads < 1 ? 1 : o->threads;
	if (nt > count)
		nt = count > 0 ? count : 1;
	pthread_t *th = malloc((size_t)nt * sizeof *th);
	if (!p.out || !th) {
		free(p.out);
		free(th);
		fprintf(stderr, "extremes: out of memory\n");
		return -1;
	}
	pthread_mutex_init(&p.lock, NULL);
	pthread_cond_init(&p.ready, NULL);
	long started = 0;
	int failed = 0;
	for (; started < nt; ++started)
		if (pthread_create(&th[started], NULL, mkExtremes_Worker, &p) != 0)
			break;
	if (started == 0) {
		fprintf(stderr, "extremes: cannot start a thread\n");
		failed = 1;
	}
	/* Write the units in order as they complete. */
	for (long k = 0; k < count && !failed; ++k) {
		pthread_mutex_lock(&p.lock);
		while (!p.out[k].done)
			pthread_cond_wait(&p.ready, &p.lock);
		pthread_mutex_unlock(&p.lock);
		mkUnitOut *u = &p.out[k];
		if (u->failed) {
			failed = 1;
			break;
		}
		if (u->len > 0)
			fwrite(u->text, 1, u->len, csv->file.fp);
		csv->rows += u->rows;
		csv->misuse |= u->misuse;
		tally->rows += u->tally.rows;
		tally->failed += u->tally.failed;
		tally->nonfinite += u->tally.nonfinite;
		tally->rejected += u->tally.rejected;
		tally->searches += u->tally.searches;
		tally->reused += u->tally.reused;
		free(u->text);
		u->text = NULL;
		if (step)
			step(ctx);
	}
	pthread_mutex_lock(&p.lock);
	p.stop = 1;
	pthread_mutex_unlock(&p.lock);
	for (long i = 0; i < started; ++i)
		pthread_join(th[i], NULL);
	for (long k = 0; k < count; ++k)
		free(p.out[k].text);
	pthread_mutex_destroy(&p.lock);
	pthread_cond_destroy(&p.ready);
	free(p.out);
	free(th);
	return failed ? -1 : 0;
}
