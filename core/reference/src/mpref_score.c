/* mpref_score.c - scoring a method's points against the exact boundary
 * (refSum_Score, refSum_ScoreMemo, with the memo of searches that repeat
 * across methods) and the problem's condition (refSum_Condition), on the
 * distance search of mpref_measure.c (mink/mpref_measure.h). */
#include <mink/mpref_measure.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mpref_measure_internal.h"

#define RND MPFR_RNDN

/* ---- the memo of refSum_ScoreMemo ---------------------------------------- */

/* Kinds of memoised work: the scan (refSum_CoarseNormal) of a point, the Newton
 * stage from the exact normal at u, and refSum_DistanceFrom from a double start
 * normal with or without the derivative-free stage. */
enum { MEMO_SCAN = 1, MEMO_EXACT_NEWTON = 2, MEMO_START_NEWTON = 3, MEMO_START_FULL = 4 };

typedef struct refMemoEntry {
	int kind;          /* 0: empty slot */
	double p[3], s[3]; /* the point and its start (u or the start normal; unused by MEMO_SCAN) */
	int done;          /* refSum_DistanceFrom's return */
	double phi;        /* MEMO_SCAN: refSum_CoarseNormal's return */
	double n0[3];      /* MEMO_SCAN: the normal it found */
	refDistance d;
} refMemoEntry;

struct refScoreMemo {
	refBody b1, b2;
	int plus, valid;
	refMemoEntry *slot;
	size_t cap, used;
	long hits, misses;
};

refScoreMemo *refScoreMemo_New(void)
{
	return calloc(1, sizeof(refScoreMemo));
}

void refScoreMemo_Free(refScoreMemo *memo)
{
	if (memo)
		free(memo->slot);
	free(memo);
}

void refScoreMemo_Counts(const refScoreMemo *memo, long *hits, long *misses)
{
	*hits = memo ? memo->hits : 0;
	*misses = memo ? memo->misses : 0;
}

static int bodySame(const refBody *a, const refBody *b)
{
	if (a->s.dim != b->s.dim || a->s.e1 != b->s.e1 || a->s.e2 != b->s.e2)
		return 0;
	for (int i = 0; i < 3; ++i) {
		if (a->s.a[i] != b->s.a[i] || a->t[i] != b->t[i])
			return 0;
		for (int j = 0; j < 3; ++j)
			if (a->M.m[i][j] != b->M.m[i][j])
				return 0;
	}
	return 1;
}

/* Bound the memo to the pair (emptied when it was another's). */
static void memoBind(refScoreMemo *m, const refBody *b1, const refBody *b2, int plus)
{
	if (m->valid && m->plus == plus && bodySame(&m->b1, b1) && bodySame(&m->b2, b2))
		return;
	if (m->slot)
		memset(m->slot, 0, m->cap * sizeof *m->slot);
	m->used = 0;
	m->b1 = *b1;
	m->b2 = *b2;
	m->plus = plus;
	m->valid = 1;
}

/* Keys compare by bits (so -0 and 0 differ, as they may for the search). */
static uint64_t memoHash(int kind, const double *p, const double *s)
{
	uint64_t h = 0x9e3779b97f4a7c15u * (uint64_t)kind;
	for (int i = 0; i < 6; ++i) {
		uint64_t w;
		memcpy(&w, i < 3 ? &p[i] : &s[i - 3], sizeof w);
		h ^= w + 0x9e3779b97f4a7c15u + (h << 6) + (h >> 2);
		h *= 0xbf58476d1ce4e5b9u;
	}
	return h ^ (h >> 31);
}

static int memoKeyEq(const refMemoEntry *e, int kind, const double *p, const double *s)
{
	return e->kind == kind && memcmp(e->p, p, sizeof e->p) == 0 && memcmp(e->s, s, sizeof e->s) == 0;
}

/* The slot of (kind, p, s): its entry when present (*found = 1), else the
 * empty slot to fill (NULL when the table cannot grow). */
static refMemoEntry *memoSlot(refScoreMemo *m, int kind, const double *p, const double *s, int *found)
{
	*found = 0;
	if (2 * (m->used + 1) > m->cap) {
		size_t cap = m->cap ? 2 * m->cap : 256;
		refMemoEntry *slot = calloc(cap, sizeof *slot);
		if (!slot)
			return NULL;
		for (size_t i = 0; i < m->cap; ++i) {
			const refMemoEntry *e = &m->slot[i];
			if (!e->kind)
				continue;
			size_t j = memoHash(e->kind, e->p, e->s) & (cap - 1);
			while (slot[j].kind)
				j = (j + 1) & (cap - 1);
			slot[j] = *e;
		}
		free(m->slot);
		m->slot = slot;
		m->cap = cap;
	}
	size_t j = memoHash(kind, p, s) & (m->cap - 1);
	while (m->slot[j].kind) {
		if (memoKeyEq(&m->slot[j], kind, p, s)) {
			*found = 1;
			return &m->slot[j];
		}
		j = (j + 1) & (m->cap - 1);
	}
	return &m->slot[j];
}

static void memoFill(refScoreMemo *m, refMemoEntry *e, int kind, const double *p, const double *s)
{
	e->kind = kind;
	memcpy(e->p, p, sizeof e->p);
	memcpy(e->s, s, sizeof e->s);
	m->used++;
	m->misses++;
}

/* refSum_CoarseNormal through the memo. Returns 0, or -1 when the memo cannot grow. */
static int memoScan(refScoreMemo *m, const refBody *b1, const refBody *b2, int plus, const double *p,
	double *n0, double *phi)
{
	static const double none[3] = { 0.0, 0.0, 0.0 };
	if (!m) {
		*phi = refSum_CoarseNormal(b1, b2, plus, p, n0);
		return 0;
	}
	int found;
	refMemoEntry *e = memoSlot(m, MEMO_SCAN, p, none, &found);
	if (!e)
		return -1;
	if (found) {
		m->hits++;
	} else {
		e->phi = refSum_CoarseNormal(b1, b2, plus, p, e->n0);
		memoFill(m, e, MEMO_SCAN, p, none);
	}
	*phi = e->phi;
	memcpy(n0, e->n0, sizeof e->n0);
	return 0;
}

/* refSum_DistanceFrom through the memo: from the double start n0 (u NULL), or
 * from the exact normal nn of B1 at u (newtonOnly then). Returns
 * refSum_DistanceFrom's result, or -1 when the memo cannot grow. */
static int distanceAt(const refBody *b1, const refBody *b2, int plus, const double *p,
	const double *n0, const double *u, double S, int newtonOnly, refDistance *out)
{
	if (!u)
		return refSum_DistanceFrom(b1, b2, plus, p, n0, NULL, S, newtonOnly, out);
	/* The exact normal of B1 at u, kept at 256 bits (see refSum_DistanceFrom). */
	int dim = b1->s.dim;
	double nd[3] = { 0.0, 0.0, 0.0 };
	refVec uu, nn;
	refVec_Init(&uu);
	refVec_Init(&nn);
	refVec_FromD(&uu, dim, u);
	refBody_Normal(b1, &uu, &nn);
	refVec_ToD(&nn, dim, nd);
	int done = refSum_DistanceFrom(b1, b2, plus, p, nd, &nn, S, 1, out);
	refVec_Clear(&uu);
	refVec_Clear(&nn);
	return done;
}

static int memoDistance(refScoreMemo *m, const refBody *b1, const refBody *b2, int plus, const double *p,
	const double *n0, const double *u, double S, int newtonOnly, refDistance *out)
{
	if (!m)
		return distanceAt(b1, b2, plus, p, n0, u, S, newtonOnly, out);
	int kind = u ? MEMO_EXACT_NEWTON : newtonOnly ? MEMO_START_NEWTON : MEMO_START_FULL, found;
	const double *s = u ? u : n0;
	refMemoEntry *e = memoSlot(m, kind, p, s, &found);
	if (!e)
		return -1;
	if (found) {
		m->hits++;
	} else {
		e->done = distanceAt(b1, b2, plus, p, n0, u, S, newtonOnly, &e->d);
		memoFill(m, e, kind, p, s);
	}
	*out = e->d;
	return e->done;
}

/* ---- scoring a point set ------------------------------------------------ */

typedef struct refCand { int index; double bound; double n0[3]; } refCand;

static int candCompare(const void *a, const void *b)
{
	double x = ((const refCand *)a)->bound, y = ((const refCand *)b)->bound;
	return x < y ? 1 : x > y ? -1 : 0;
}

static void scoreTake(refScore *out, int index, const refDistance *d)
{
	double a = fabs(d->dist);
	if (out->worst < 0 || a > out->errorAbs) {
		out->errorAbs = a;
		out->worst = index;
		out->worstDist = d->dist;
	}
}

int refSum_Score(const refBody *b1, const refBody *b2, int plus,
	const double *x, const double *y, const double *z, int count,
	const double *ux, const double *uy, const double *uz, refScore *out)
{
	return refSum_ScoreMemo(b1, b2, plus, x, y, z, count, ux, uy, uz, NULL, out);
}

/* One scoring: the bodies, the points and the running maximum of the
 * accuracy estimates. */
typedef struct refScoring {
	const refBody *b1, *b2;
	int plus, dim;
	const double *x, *y, *z;
	refScoreMemo *memo;
	refScore *out;
	double accMax;
} refScoring;

static void scoringPoint(const refScoring *sc, int i, double *p)
{
	p[0] = sc->x[i];
	p[1] = sc->y[i];
	p[2] = sc->dim == 3 ? sc->z[i] : 0.0;
}

/* Point i into p, counted among the points (1) or the non-finite ones (0). */
static int scoringCount(refScoring *sc, int i, double *p)
{
	scoringPoint(sc, i, p);
	if (!refFinite(p, sc->dim)) {
		sc->out->nonfinite++;
		return 0;
	}
	sc->out->points++;
	return 1;
}

static void scoringTake(refScoring *sc, int index, const refDistance *d)
{
	scoreTake(sc->out, index, d);
	if (d->accuracy > sc->accMax)
		sc->accMax = d->accuracy;
}

/* Without parameters (hull vertices): the scan's phi in double is within
 * MARGIN of d(p) (the double support value errs by up to q u h <= 2e6 *
 * 1.1e-16 * S at eps = 2 - 1e-6, the pattern search stops 1e-12 rad from a
 * kink of slope <= S), so |d| <= |phi| + MARGIN. Every finite point becomes
 * a candidate with that bound and the scan's normal; -1 when out of memory. */
static int scoringScan(refScoring *sc, int count, refCand *cand, int *pending)
{
	refScore *out = sc->out;
	for (int i = 0; i < count; ++i) {
		double p[3];
		if (!scoringCount(sc, i, p))
			continue;
		refCand *c = &cand[(*pending)++];
		c->index = i;
		double f;
		if (memoScan(sc->memo, sc->b1, sc->b2, sc->plus, p, c->n0, &f) != 0)
			return -1;
		c->bound = fabs(f) + 1e-9 * out->size + 1e-6 * fabs(f);
	}
	return 0;
}

/* With parameters: Newton from the exact normal of every point. Where it
 * converges the distance is known; elsewhere (kinks) the point becomes a
 * candidate with the bound |d| <= |v| and the normal reached. -1 when out
 * of memory. */
static int scoringNewton(refScoring *sc, int count, const double *ux, const double *uy, const double *uz,
	refCand *cand, int *pending)
{
	refScore *out = sc->out;
	for (int i = 0; i < count; ++i) {
		double p[3];
		if (!scoringCount(sc, i, p))
			continue;
		double ud[3] = { ux[i], uy[i], sc->dim == 3 ? uz[i] : 0.0 };
		refDistance d;
		out->searched++;
		int done = memoDistance(sc->memo, sc->b1, sc->b2, sc->plus, p, NULL, ud, out->size, 1, &d);
		if (done < 0)
			return -1;
		if (done) {
			scoringTake(sc, i, &d);
		} else {
			refCand *c = &cand[(*pending)++];
			c->index = i;
			c->bound = d.upper;
			memcpy(c->n0, d.normal, sizeof c->n0);
		}
	}
	return 0;
}

/* The candidates in decreasing order of their bound, searched until the
 * bound falls below the largest distance known: a sampled hull's errors
 * (1e-6 ... 1e-2 of S) are decided by a few vertices. newtonFirst tries
 * Newton before the derivative-free search (candidates of the scan).
 * -1 when out of memory. */
static int scoringSearch(refScoring *sc, refCand *cand, int pending, int newtonFirst)
{
	refScore *out = sc->out;
	qsort(cand, (size_t)pending, sizeof *cand, candCompare);
	for (int i = 0; i < pending; ++i) {
		if (out->worst >= 0 && cand[i].bound <= out->errorAbs)
			break; /* every remaining point is bounded below the maximum */
		int j = cand[i].index;
		double p[3];
		scoringPoint(sc, j, p);
		refDistance d;
		int done = 0;
		if (newtonFirst)
			done = memoDistance(sc->memo, sc->b1, sc->b2, sc->plus, p, cand[i].n0, NULL, out->size, 1, &d);
		if (done == 0) {
			done = memoDistance(sc->memo, sc->b1, sc->b2, sc->plus, p, cand[i].n0, NULL, out->size, 0, &d);
			out->refined++;
		}
		if (done < 0)
			return -1;
		if (newtonFirst)
			out->searched++;
		scoringTake(sc, j, &d);
	}
	return 0;
}

int refSum_ScoreMemo(const refBody *b1, const refBody *b2, int plus,
	const double *x, const double *y, const double *z, int count,
	const double *ux, const double *uy, const double *uz, refScoreMemo *memo, refScore *out)
{
	if (!out)
		return -1;
	memset(out, 0, sizeof *out);
	out->worst = -1;
	if (!b1 || !b2)
		return -1;
	int dim = b1->s.dim;
	out->size = refSum_Size(b1, b2, plus);
	if (count < 0 || (count > 0 && (!x || !y || (dim == 3 && !z))))
		return -1;
	int hints = ux && uy && (dim == 2 || uz);
	refCand *cand = malloc(sizeof *cand * (size_t)(count > 0 ? count : 1));
	if (!cand)
		return -1;
	if (memo)
		memoBind(memo, b1, b2, plus);
	refScoring sc = { b1, b2, plus, dim, x, y, z, memo, out, 0.0 };
	int pending = 0, rc;
	if (hints)
		rc = scoringNewton(&sc, count, ux, uy, uz, cand, &pending);
	else
		rc = scoringScan(&sc, count, cand, &pending);
	if (rc == 0)
		rc = scoringSearch(&sc, cand, pending, !hints);
	if (out->worst >= 0) {
		out->errorRel = out->errorAbs / out->size;
		out->accuracy = sc.accMax / out->size;
	}
	free(cand);
	if (rc < 0) {
		memset(out, 0, sizeof *out);
		out->worst = -1;
		return -1;
	}
	return 0;
}

/* ---- the problem's condition ------------------------------------------- */

void refSample_Params(int dim, int n, double *ux, double *uy, double *uz)
{
	if (dim == 2) {
		for (int k = 0; k < n; ++k) {
			ux[k] = cos(2.0 * MEAS_PI * k / n);
			uy[k] = sin(2.0 * MEAS_PI * k / n);
		}
		return;
	}
	for (int i = 0; i < n; ++i)
		for (int j = 0; j < n; ++j) {
			double lon = 2.0 * MEAS_PI * i / n, col = MEAS_PI * j / (n - 1);
			ux[i * n + j] = sin(col) * cos(lon);
			uy[i * n + j] = sin(col) * sin(lon);
			uz[i * n + j] = cos(col);
		}
}

static uint64_t splitmix(uint64_t *s)
{
	uint64_t z = (*s += 0x9e3779b97f4a7c15u);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return z ^ (z >> 31);
}

static double ulpMove(double v, uint64_t *rng)
{
	return nextafter(v, (splitmix(rng) >> 63) ? INFINITY : -INFINITY);
}

/* Every input moved by one ulp, up or down at random. B2's translation only
 * matters for the plus set. */
static refBody perturb(const refBody *b, uint64_t *rng, int withT)
{
	refBody r = *b;
	int dim = b->s.dim;
	for (int i = 0; i < dim; ++i)
		r.s.a[i] = ulpMove(r.s.a[i], rng);
	r.s.e1 = ulpMove(r.s.e1, rng);
	if (dim == 3)
		r.s.e2 = ulpMove(r.s.e2, rng);
	for (int i = 0; i < dim; ++i)
		for (int j = 0; j < dim; ++j)
			r.M.m[i][j] = ulpMove(r.M.m[i][j], rng);
	if (withT)
		for (int i = 0; i < dim; ++i)
			r.t[i] = ulpMove(r.t[i], rng);
	return r;
}

int refSum_Condition(const refBody *b1, const refBody *b2, int plus,
	int samples, int draws, uint64_t seed, refCondition *out)
{
	int dim = b1->s.dim;
	if (!out)
		return -1;
	memset(out, 0, sizeof *out);
	if (samples < 2 || draws < 1)
		return -1;
	int count = dim == 2 ? samples : samples * samples;
	double *ud = malloc(sizeof(double) * 3 * (size_t)count);
	if (!ud)
		return -1;
	refSample_Params(dim, samples, ud, ud + count, dim == 3 ? ud + 2 * count : NULL);
	double S = refSum_Size(b1, b2, plus);
	refBody *p1 = malloc(sizeof(refBody) * 2 * (size_t)draws);
	if (!p1) {
		free(ud);
		return -1;
	}
	refBody *p2 = p1 + draws;
	uint64_t rng = seed;
	for (int r = 0; r < draws; ++r) {
		p1[r] = perturb(b1, &rng, 1);
		p2[r] = perturb(b2, &rng, plus);
	}
	refVec u, x, n, xp, d;
	mpfr_t h, hp;
	refVec_Init(&u);
	refVec_Init(&x);
	refVec_Init(&n);
	refVec_Init(&xp);
	refVec_Init(&d);
	mpfr_inits2(REF_PREC, h, hp, (mpfr_ptr)0);
	for (int k = 0; k < count; ++k) {
		double uk[3] = { ud[k], ud[count + k], dim == 3 ? ud[2 * count + k] : 0.0 };
		refVec_FromD(&u, dim, uk);
		refSum_Point(b1, b2, plus, 1, &u, &x, NULL, &n);
		refSum_SupportValue(b1, b2, plus, &n, h);
		/* floor: the exact point rounded to double, along the normal */
		double xd[3] = { 0.0, 0.0, 0.0 };
		refVec_ToD(&x, dim, xd);
		refVec_FromD(&d, dim, xd);
		for (int i = 0; i < dim; ++i)
			mpfr_sub(d.c[i], d.c[i], x.c[i], RND);
		refVec_Dot(hp, &d, &n, dim);
		double fl = fabs(mpfr_get_d(hp, RND)) / S;
		if (fl > out->floor)
			out->floor = fl;
		for (int r = 0; r < draws; ++r) {
			refSum_SupportValue(&p1[r], &p2[r], plus, &n, hp);
			mpfr_sub(hp, hp, h, RND);
			double bd = fabs(mpfr_get_d(hp, RND)) / S;
			if (bd > out->boundary)
				out->boundary = bd;
			refSum_Point(&p1[r], &p2[r], plus, 1, &u, &xp, NULL, NULL);
			for (int i = 0; i < dim; ++i)
				mpfr_sub(d.c[i], xp.c[i], x.c[i], RND);
			double pt = refVec_NormD(&d, dim) / S;
			if (pt > out->point)
				out->point = pt;
		}
	}
	out->value = out->boundary > out->floor ? out->boundary : out->floor;
	mpfr_clears(h, hp, (mpfr_ptr)0);
	refVec_Clear(&u);
	refVec_Clear(&x);
	refVec_Clear(&n);
	refVec_Clear(&xp);
	refVec_Clear(&d);
	free(p1);
	free(ud);
	return 0;
}
