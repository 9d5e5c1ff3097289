/* bench_colliders.c - every entry of the collider registry on the same pairs
 * of the paper's draws (Sec. 7.2), in one process: per pair kind and entry,
 * the median and mean time of one query, the failures, the status
 * disagreements with the referee outside a margin, and the distribution of
 * the distance and penetration errors against the referee, and how often an
 * entry's signed distance lies outside the referee's bracket by more than
 * 1e-10 of the scale ("below" its certified lower bound, or "above" its
 * certified upper bound on separated pairs: such an answer is certainly that
 * wrong), and for entries that give witness points the largest
 * ||p2 - p1| - sd| / scale over the separated pairs ("wit_max": 0 when the
 * witnesses are the nearest points). Pairs where the referee is not certain
 * (its bracket wider than 1e-10 of the scale, or an overlap it could not
 * certify) are counted ("uncertain") and left out of the status comparison
 * and the errors; the referee's own time and bracket widths are printed per
 * kind. A benchmark that prints figures, not a test.
 *
 * Draws (as experiments/collision.c): B1 semi-axes U(1,11)^3, centre
 * U(-5,5)^3; B2 semi-axes U(1,6)^3, centre U(5,15)^3; exponents U(0.1,1.9)
 * (ellipsoids: 1); rotations from four U(0,1) quaternion components,
 * normalised. "near" pairs: a superquadric or ellipsoid pair moved along
 * minksum-normal's normal so that the signed distance is s * scale, s in
 * {1e-1, ..., 1e-6}, and "deep" pairs: centres within U(-2,2)^3. "box-like"
 * pairs (only when asked for, KIND 4): the superquadric draws with every
 * exponent U(0.05, 0.3), nearly flat faces and nearly kinked support
 * functions.
 *
 * Timing: CLOCK_MONOTONIC around the run call only (prepare untimed), the
 * entries interleaved pair by pair (A B C A B C ...), one thread. The batch
 * modes of mink/batch.h are timed twice: as one-pair calls interleaved with
 * the entries (rows batch-<mode>), and amortised over chunks of 64 pairs
 * interleaved chunk by chunk with ccd-gjk and ccd-gjk-epa-1e-10 on the same
 * chunk (rows batch-<mode> x64: the median and mean over the chunks of the
 * time per pair), each with its ratios to those two peers.
 *
 * usage: bench_colliders [--help] [pairs per kind, default 2000] [seed, default 2022]
 *                        [entries to leave out, comma-separated, e.g. implicit]
 *                        [only this kind: 0 ellipsoids .. 3 deep-overlap, 4 box-like] */
#define _POSIX_C_SOURCE 199309L
#include <mink/colliders.h>
#include <mink/batch.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double mkNow(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static unsigned long long mkState;
static double mkUnit(void)
{
	unsigned long long z = (mkState += 0x9E3779B97F4A7C15ULL);
	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
	z ^= z >> 31;
	return (double)(z >> 11) * 0x1.0p-53;
}
static double mkUniform(double a, double b) { return a + (b - a) * mkUnit(); }

/* Exponents U(elo, ehi) unless an ellipsoid. */
static mkBody3 mkDraw(double amax, double clo, double chi, int ellipsoid, double elo, double ehi)
{
	mkShape3 s = { mkUniform(1, amax), mkUniform(1, amax), mkUniform(1, amax), 1.0, 1.0 };
	if (!ellipsoid) {
		s.eps1 = mkUniform(elo, ehi);
		s.eps2 = mkUniform(elo, ehi);
	}
	mkVec3 t = mkVec3_Make(mkUniform(clo, chi), mkUniform(clo, chi), mkUniform(clo, chi));
	double q[4];
	for (int i = 0; i < 4; ++i)
		q[i] = mkUnit();
	return mkBody3_Make(s, mkMat3_FromQuat(q[0], q[1], q[2], q[3]), t);
}

static int mkCmp(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* Quantile q of v[0..n) (sorted in place); NaN when n == 0. */
static double mkQuantile(double *v, int n, double q)
{
	if (n == 0)
		return NAN;
	qsort(v, (size_t)n, sizeof *v, mkCmp);
	int i = (int)ceil(q * n) - 1;
	return v[i < 0 ? 0 : i >= n ? n - 1 : i];
}

/* 1 when name is an item of the comma-separated list. */
static int mkListed(const char *list, const char *name)
{
	size_t nl = strlen(name);
	for (const char *hit = strstr(list, name); hit; hit = strstr(hit + 1, name))
		if ((hit == list || hit[-1] == ',') && (hit[nl] == '\0' || hit[nl] == ','))
			return 1;
	return 0;
}

/* Kinds 0 .. 3 run by default; box-like (4) only when asked for. */
enum { MK_KINDS = 5, MK_KINDS_DEFAULT = 4 };
static const char *const mkKindNames[MK_KINDS] = { "ellipsoids", "superquadrics", "near-touching", "deep-overlap",
	"box-like" };

static const char mkUsage[] =
	"usage: bench_colliders [PAIRS [SEED [SKIP [KIND]]]]\n"
	"Every entry of the collider registry on the same pairs, interleaved pair by pair;\n"
	"prints per pair kind and entry the median and mean time, failures, status\n"
	"disagreements with the referee and the distance/penetration error distribution.\n"
	"  PAIRS  pairs per kind, an integer in [1, 10000000] (default 2000)\n"
	"  SEED   run seed, 0..2^64-1, decimal or 0x.. (default 2022)\n"
	"  SKIP   entries to leave out, comma-separated, e.g. implicit (default none)\n"
	"  KIND   only this kind: 0 ellipsoids, 1 superquadrics, 2 near-touching,\n"
	"         3 deep-overlap (default: these four), 4 box-like (superquadric\n"
	"         draws with every exponent U(0.05, 0.3): nearly flat faces)\n";

/* An integer argument in [lo, hi], or exit 2 with one line naming it. */
static long mkArgInt(const char *name, const char *text, long lo, long hi)
{
	char *end;
	errno = 0;
	long v = strtol(text, &end, 10);
	if (errno || end == text || *end || v < lo || v > hi) {
		fprintf(stderr, "bench_colliders: %s = '%s' is out of range: must be an integer in [%ld, %ld]\n", name,
			text, lo, hi);
		exit(2);
	}
	return v;
}

/* The command line (see mkUsage): -1 to run, else the exit status (0 after
 * the help, 2 on a bad argument, with one line naming it). */
static int mkBenchArgs(int argc, char **argv, int *pairs, unsigned long long *seed, const char **skip, int *only)
{
	if (argc > 1 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
		fputs(mkUsage, stdout);
		return 0;
	}
	if (argc > 5) {
		fputs(mkUsage, stderr);
		return 2;
	}
	*pairs = argc > 1 ? (int)mkArgInt("PAIRS", argv[1], 1, 10000000) : 2000;
	*seed = 2022;
	if (argc > 2) {
		char *end;
		errno = 0;
		*seed = strtoull(argv[2], &end, 0);
		if (errno || end == argv[2] || *end || argv[2][0] == '-') {
			fprintf(stderr, "bench_colliders: SEED = '%s' is out of range: must be an integer in [0, 2^64-1]\n",
				argv[2]);
			return 2;
		}
	}
	*skip = argc > 3 ? argv[3] : "";
	*only = argc > 4 ? (int)mkArgInt("KIND", argv[4], 0, MK_KINDS - 1) : -1;
	return -1;
}

/* The pairs of one kind (0 .. 4, see mkKindNames) drawn from the run seed,
 * and the referee's answer and time (microseconds) on each. */
static void mkBenchDraw(int kind, int pairs, unsigned long long seed, const mkCollider *referee,
	mkColliderScratch *scratch, mkBody3 *B1, mkBody3 *B2, mkCollision3 *ref, double *reftime)
{
	mkState = seed * 1000003ULL + (unsigned long long)kind;
	for (int p = 0; p < pairs; ++p) {
		int ell = kind == 0 || ((kind == 2 || kind == 3) && p % 2 == 0);
		double elo = kind == 4 ? 0.05 : 0.1, ehi = kind == 4 ? 0.3 : 1.9;
		if (kind == 3) {
			B1[p] = mkDraw(11.0, -1.0, 1.0, ell, elo, ehi);
			B2[p] = mkDraw(6.0, -2.0, 2.0, ell, elo, ehi);
		} else {
			B1[p] = mkDraw(11.0, -5.0, 5.0, ell, elo, ehi);
			B2[p] = mkDraw(6.0, 5.0, 15.0, ell, elo, ehi);
		}
		if (kind == 2) {
			static const double sep[6] = { 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6 };
			mkCollision3 c;
			if (mkCollide3_Normal(B1[p], B2[p], &c) == MK_OK)
				B2[p].t = mkVec3_Add(B2[p].t, mkVec3_Scale(c.normal, sep[p % 6] * c.scale - c.distance));
		}
		double t0 = mkNow();
		mkCollider_Run(referee, B1[p], B2[p], scratch, &ref[p]);
		reftime[p] = 1e6 * (mkNow() - t0);
	}
}

/* One entry's line: times t[nt] (microseconds), distance and penetration
 * errors dd[nd], pp[np], counts = failed, disagree, below, above, and the
 * witnesses' worst error. */
static void mkBenchRow(const mkCollider *c, double *t, int nt, double *dd, int nd, double *pp, int np,
	const int counts[4], double wit)
{
	double mean = 0.0;
	for (int i = 0; i < nt; ++i)
		mean += t[i];
	mean /= nt;
	printf("%-18s %9.3f %9.3f %7d %8d %6d %6d %10.2e %10.2e %10.2e %10.2e %10.2e %10.2e %10.2e\n", c->name,
		mkQuantile(t, nt, 0.5), mean, counts[0], counts[1], counts[2], counts[3], mkQuantile(dd, nd, 0.5),
		mkQuantile(dd, nd, 0.99), mkQuantile(dd, nd, 1.0), mkQuantile(pp, np, 0.5), mkQuantile(pp, np, 0.99),
		mkQuantile(pp, np, 1.0), c->gives & MK_GIVES_WITNESS ? wit : NAN);
}

/* The referee's own line: its statuses, time and bracket on separated
 * pairs (refgap is scratch space of pairs entries). */
static void mkBenchRefereeLine(const mkCollision3 *ref, double *reftime, double *refgap, int pairs, int nref_fail,
	int nuncertain)
{
	int nsep = 0, ng = 0;
	double rmean = 0.0;
	for (int p = 0; p < pairs; ++p) {
		nsep += ref[p].distance > 0.0;
		rmean += reftime[p];
		if (ref[p].distance > 0.0)
			refgap[ng++] = ref[p].gap / ref[p].scale;
	}
	printf("(referee: %d separated, %d overlapping, %d failed, %d uncertain; median %.1f us, mean %.1f us; "
		"bracket / scale on separated pairs: median %.2e, p99 %.2e, max %.2e)\n", nsep, pairs - nsep - nref_fail,
		nref_fail, nuncertain, mkQuantile(reftime, pairs, 0.5), rmean / pairs, mkQuantile(refgap, ng, 0.5),
		mkQuantile(refgap, ng, 0.99), mkQuantile(refgap, ng, 1.0));
}

/* The batch modes (mink/batch.h), timed as one-pair calls interleaved with
 * the entries, so that their median and mean compare with the entries'
 * (the scalar batch path has nothing to amortise over pairs). The
 * clearance asked is MK_BENCH_DELTA times the pair's scale. */
#define MK_BENCH_DELTA 1e-2
enum { MK_BATCH_MODES = 4 };

/* One pair in one batch mode: the time (microseconds), whether the bounds
 * answered it (not the one-pair query), and the status disagreement with a
 * certain referee. */
static double mkBenchBatch(mkBatchMode mode, const mkBody3 *b1, const mkBody3 *b2, const mkCollision3 *ref,
	int certain, double margin, int *bounds, int *disagree)
{
	mkContact st;
	double dist;
	unsigned char path;
	mkBatchOut3 out = { &st, &dist, NULL, NULL, NULL, NULL, NULL, NULL, &path };
	mkBatchPairs3 pr = { 1, b1, b2, NULL, NULL };
	double delta = MK_BENCH_DELTA * ref->scale;
	double t0 = mkNow();
	mkResult r = mkCollide3_Batch(&pr, mode, delta, &out, NULL);
	double t1 = mkNow();
	*bounds += r == MK_OK && path != MK_PATH_ONE_PAIR;
	double sdr = ref->distance;
	if (certain && fabs(sdr) > margin * ref->scale) {
		int says = st == MK_CONTACT_SEPARATED ? 1 : st == MK_CONTACT_OVERLAPPING ? 0 : -1;
		*disagree += says != (sdr > 0.0);
	}
	return 1e6 * (t1 - t0);
}

/* The batch rows, then each mode's ratios to ccd-gjk and ccd-gjk-epa-1e-10
 * (their pairs per second over the entry's, by median and by mean). */
static void mkBenchBatchRows(double *bt, int pairs, const int *bounds, const int *dis, const double *ref_med,
	const double *ref_mean)
{
	static const char *const names[MK_BATCH_MODES] = { "batch-status", "batch-clearance", "batch-distance",
		"batch-full" };
	for (int m = 0; m < MK_BATCH_MODES; ++m) {
		double *t = bt + (size_t)m * (size_t)pairs, mean = 0.0;
		for (int i = 0; i < pairs; ++i)
			mean += t[i];
		mean /= pairs;
		double med = mkQuantile(t, pairs, 0.5);
		printf("%-18s %9.3f %9.3f %7d %8d   bounds answered %5.1f %%; x ccd-gjk: median %.2f, mean %.2f; "
			"x ccd-gjk-epa-1e-10: median %.2f, mean %.2f\n", names[m], med, mean, 0, dis[m], 100.0 * bounds[m] / pairs,
			ref_med[0] / med, ref_mean[0] / mean, ref_med[1] / med, ref_mean[1] / mean);
	}
}

/* Amortised: the pairs of a kind in chunks of MK_BENCH_CHUNK, each chunk
 * run by ccd-gjk (one query per pair, run calls only timed) and by each
 * batch mode (one call), interleaved chunk by chunk; per chunk the time per
 * pair. Prints each mode's median and mean over the chunks and the ratios
 * to ccd-gjk's and ccd-gjk-epa-1e-10's (pairs per second over theirs). */
#define MK_BENCH_CHUNK 64
static void mkBatchStats_Add(mkBatchStats3 *t, const mkBatchStats3 *s)
{
	t->separating += s->separating;
	t->overlap_point += s->overlap_point;
	t->one_pair += s->one_pair;
	t->failed += s->failed;
	t->newton += s->newton;
	t->newton_left += s->newton_left;
}

static void mkBenchChunks(const mkBody3 *B1, const mkBody3 *B2, const mkCollision3 *ref, int pairs,
	mkColliderScratch *scratch, double *work)
{
	mkBatchStats3 total[MK_BATCH_MODES];
	memset(total, 0, sizeof total);
	double derr = 0.0; /* the distance mode's largest |sd - referee| / scale (separated, certain) */
	const mkCollider *peer[2] = { mkColliders_Find("ccd-gjk"), mkColliders_Find("ccd-gjk-epa-1e-10") };
	int nch = (pairs + MK_BENCH_CHUNK - 1) / MK_BENCH_CHUNK;
	static mkContact st[MK_BENCH_CHUNK];
	static double dist[MK_BENCH_CHUNK];
	mkBatchOut3 out = { st, dist, NULL, NULL, NULL, NULL, NULL, NULL, NULL };
	for (int c = 0; c < nch; ++c) {
		int at = c * MK_BENCH_CHUNK, n = pairs - at < MK_BENCH_CHUNK ? pairs - at : MK_BENCH_CHUNK;
		for (int e = 0; e < 2; ++e) {
			double t = 0.0;
			for (int p = at; p < at + n && peer[e]; ++p) {
				mkCollision3 o;
				if (peer[e]->prepare && peer[e]->prepare(B1[p], B2[p], scratch) != MK_OK)
					continue;
				double t0 = mkNow();
				peer[e]->run(B1[p], B2[p], scratch, &o);
				t += mkNow() - t0;
			}
			work[(size_t)e * (size_t)nch + (size_t)c] = 1e6 * t / n;
		}
		mkBatchPairs3 pr = { n, B1 + at, B2 + at, NULL, NULL };
		for (int m = 0; m < MK_BATCH_MODES; ++m) {
			double delta = MK_BENCH_DELTA * mkCollide3_PairSize(B1[at], B2[at]);
			mkBatchStats3 bs;
			double t0 = mkNow();
			mkCollide3_Batch(&pr, (mkBatchMode)m, delta, &out, &bs);
			work[(size_t)(2 + m) * (size_t)nch + (size_t)c] = 1e6 * (mkNow() - t0) / n;
			mkBatchStats_Add(&total[m], &bs);
			for (int p = 0; m == MK_BATCH_DISTANCE && p < n; ++p) {
				const mkCollision3 *rf = &ref[at + p];
				if (rf->residual <= 1e-10 && rf->distance > 0.0 && out.status[p] == MK_CONTACT_SEPARATED)
					derr = fmax(derr, fabs(dist[p] - rf->distance) / rf->scale);
			}
		}
	}
	double med[2 + MK_BATCH_MODES], mean[2 + MK_BATCH_MODES];
	for (int r = 0; r < 2 + MK_BATCH_MODES; ++r) {
		double *t = work + (size_t)r * (size_t)nch, sum = 0.0;
		for (int i = 0; i < nch; ++i)
			sum += t[i];
		mean[r] = sum / nch;
		med[r] = mkQuantile(t, nch, 0.5);
	}
	printf("(amortised, %d chunks of %d pairs, us per pair: ccd-gjk median %.3f mean %.3f; ccd-gjk-epa-1e-10 median %.3f "
		"mean %.3f)\n", nch, MK_BENCH_CHUNK, med[0], mean[0], med[1], mean[1]);
	static const char *const names[MK_BATCH_MODES] = { "status", "clearance", "distance", "full" };
	for (int m = 0; m < MK_BATCH_MODES; ++m)
		printf("batch-%-9s x%-3d %9.3f %9.3f   x ccd-gjk: median %.2f, mean %.2f; x ccd-gjk-epa-1e-10: median %.2f, "
			"mean %.2f\n", names[m], MK_BENCH_CHUNK, med[2 + m], mean[2 + m], med[0] / med[2 + m], mean[0] / mean[2 + m],
			med[1] / med[2 + m], mean[1] / mean[2 + m]);
	const mkBatchStats3 *d = &total[MK_BATCH_DISTANCE];
	printf("(batch-distance x%d: %d pairs by a certificate (%d of them by the Newton lanes), %d by the one-pair query "
		"(%d of them left the Newton lanes), %d failed; max |sd - referee| / scale %.2e)\n", MK_BENCH_CHUNK,
		d->separating + d->overlap_point, d->newton, d->one_pair, d->newton_left, d->failed, derr);
}

int main(int argc, char **argv)
{
	int pairs, only, rc;
	unsigned long long seed;
	const char *skip;
	if ((rc = mkBenchArgs(argc, argv, &pairs, &seed, &skip, &only)) >= 0)
		return rc;
	int ne = mkColliders_Count();
	double *times = malloc(sizeof(double) * (size_t)pairs * (size_t)ne);
	double *derr = malloc(sizeof(double) * (size_t)pairs * (size_t)ne);
	double *perr = malloc(sizeof(double) * (size_t)pairs * (size_t)ne);
	mkBody3 *B1 = malloc(sizeof(mkBody3) * (size_t)pairs), *B2 = malloc(sizeof(mkBody3) * (size_t)pairs);
	mkCollision3 *ref = malloc(sizeof(mkCollision3) * (size_t)pairs);
	double *reftime = malloc(sizeof(double) * (size_t)pairs), *refgap = malloc(sizeof(double) * (size_t)pairs);
	double *btimes = malloc(sizeof(double) * (size_t)pairs * MK_BATCH_MODES);
	if (!btimes || !times || !derr || !perr || !B1 || !B2 || !ref || !reftime || !refgap) {
		fprintf(stderr, "bench_colliders: out of memory\n");
		return 1;
	}
	const mkCollider *referee = NULL, *normal = mkColliders_Find("minksum-normal");
	for (int e = 0; e < ne; ++e)
		if (mkColliders_At(e)->referee)
			referee = mkColliders_At(e);
	mkColliderScratch scratch;
	const double margin = 1e-9;
	printf("# bench_colliders: %d pairs per kind, seed %llu; times in microseconds per query (CLOCK_MONOTONIC,\n"
		"# entries interleaved pair by pair); errors |value - referee| / scale; status compared outside |sd| <= %g scale\n"
		"# batch lanes: %s\n", pairs, seed, margin, mkCollide3_BatchLanes());
	for (int kind = 0; kind < MK_KINDS; ++kind) {
		if (only >= 0 ? kind != only : kind >= MK_KINDS_DEFAULT)
			continue;
		mkBenchDraw(kind, pairs, seed, referee, &scratch, B1, B2, ref, reftime);
		int nref_fail = 0, nuncertain = 0;
		printf("\n## %s\n%-18s %9s %9s %7s %8s %6s %6s %10s %10s %10s %10s %10s %10s %10s\n", mkKindNames[kind], "entry",
			"median_us", "mean_us", "failed", "disagree", "below", "above", "dist_med", "dist_p99", "dist_max", "pen_med",
			"pen_p99", "pen_max", "wit_max");
		int nt[64] = { 0 }, nd[64] = { 0 }, np[64] = { 0 }, fails[64] = { 0 }, dis[64] = { 0 }, worse[64] = { 0 };
		int above[64] = { 0 };
		double wit[64] = { 0 };
		int bbounds[MK_BATCH_MODES] = { 0 }, bdis[MK_BATCH_MODES] = { 0 };
		for (int p = 0; p < pairs; ++p) {
			double sdr = ref[p].distance, scale = ref[p].scale;
			if (!isfinite(sdr))
				++nref_fail;
			/* The referee's bracket: [lower, upper] certified; certain iff
			 * the bracket (separated) is within 1e-10 of the scale or the
			 * overlap is certified (residual 0). */
			double lower = ref[p].bound, upper = sdr > 0.0 ? sdr + ref[p].gap : 0.0;
			int certain = ref[p].residual <= 1e-10;
			nuncertain += !certain;
			for (int m = 0; m < MK_BATCH_MODES; ++m)
				btimes[(size_t)m * (size_t)pairs + (size_t)p] = mkBenchBatch((mkBatchMode)m, &B1[p], &B2[p], &ref[p],
					certain, margin, &bbounds[m], &bdis[m]);
			for (int e = 0; e < ne && e < 64; ++e) {
				const mkCollider *c = mkColliders_At(e);
				if (c->referee || !mkCollider_Accepts(c, B1[p], B2[p], NULL, 0))
					continue;
				if (mkListed(skip, c->name))
					continue;
				mkCollision3 out;
				mkCollision3_Clear(&out);
				mkResult r = MK_OK;
				if (c->prepare)
					r = c->prepare(B1[p], B2[p], &scratch);
				double t0 = mkNow();
				if (r == MK_OK)
					r = c->run(B1[p], B2[p], &scratch, &out);
				double t1 = mkNow();
				times[(size_t)e * (size_t)pairs + (size_t)nt[e]++] = 1e6 * (t1 - t0);
				if (r != MK_OK) {
					++fails[e];
					continue;
				}
				if (certain && fabs(sdr) > margin * scale) {
					int truth = sdr > 0.0;
					int says = out.status == MK_CONTACT_SEPARATED ? 1 : out.status == MK_CONTACT_OVERLAPPING ? 0 : -1;
					if (says != truth)
						++dis[e];
				}
				/* Outside the referee's certified bracket by more than 1e-10 of
				 * the scale: such an answer is wrong by at least that much
				 * (certain or not, the bounds hold). */
				if (isfinite(out.distance) && (c->gives & (MK_GIVES_DISTANCE | MK_GIVES_PENETRATION))
					&& out.distance < lower - 1e-10 * scale)
					++worse[e];
				if (isfinite(out.distance) && (c->gives & MK_GIVES_DISTANCE) && out.status == MK_CONTACT_SEPARATED
					&& out.distance > upper + 1e-10 * scale)
					++above[e];
				if (!certain)
					continue;
				if (isfinite(out.distance) && sdr > 0.0 && out.distance > 0.0 && (c->gives & MK_GIVES_DISTANCE))
					derr[(size_t)e * (size_t)pairs + (size_t)nd[e]++] = fabs(out.distance - sdr) / scale;
				if (sdr > 0.0 && out.status == MK_CONTACT_SEPARATED && (c->gives & MK_GIVES_WITNESS)) {
					/* how far the witnesses are from being the nearest points */
					double w = fabs(mkVec3_Length(mkVec3_Sub(out.p2, out.p1)) - sdr) / scale;
					wit[e] = isnan(w) || w > wit[e] ? w : wit[e];
				}
				if (isfinite(out.distance) && sdr < 0.0 && out.distance < 0.0 && (c->gives & MK_GIVES_PENETRATION))
					perr[(size_t)e * (size_t)pairs + (size_t)np[e]++] = fabs(out.distance - sdr) / scale;
			}
		}
		for (int e = 0; e < ne && e < 64; ++e) {
			if (nt[e] == 0)
				continue;
			size_t at = (size_t)e * (size_t)pairs;
			int counts[4] = { fails[e], dis[e], worse[e], above[e] };
			mkBenchRow(mkColliders_At(e), times + at, nt[e], derr + at, nd[e], perr + at, np[e], counts, wit[e]);
		}
		/* the peers' medians and means for the ratios (mkBenchRow sorted their times) */
		double rmed[2] = { NAN, NAN }, rmean[2] = { NAN, NAN };
		for (int e = 0; e < ne && e < 64; ++e) {
			const char *nm = mkColliders_At(e)->name;
			int w = strcmp(nm, "ccd-gjk") == 0 ? 0 : strcmp(nm, "ccd-gjk-epa-1e-10") == 0 ? 1 : -1;
			if (w < 0 || nt[e] == 0)
				continue;
			double *t = times + (size_t)e * (size_t)pairs, sum = 0.0;
			for (int i = 0; i < nt[e]; ++i)
				sum += t[i];
			rmed[w] = mkQuantile(t, nt[e], 0.5);
			rmean[w] = sum / nt[e];
		}
		mkBenchBatchRows(btimes, pairs, bbounds, bdis, rmed, rmean);
		mkBenchChunks(B1, B2, ref, pairs, &scratch, btimes);
		mkBenchRefereeLine(ref, reftime, refgap, pairs, nref_fail, nuncertain);
	}
	(void)normal;
	free(times);
	free(btimes);
	free(derr);
	free(perr);
	free(B1);
	free(B2);
	free(ref);
	free(reftime);
	free(refgap);
	return 0;
}
