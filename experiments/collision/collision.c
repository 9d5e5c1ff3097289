/* collision.c - the collision and distance benchmark on the collider
 * registry: draws, the referee, the timed runs, rows and sidecar (what is
 * measured is in collision.h). The summary is in summary.c. */
#include "collision.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const mkCollision_Columns[] = {
	"pair", "trial", "algorithm", "seconds", "status", "distance", "referee_distance", "error", "agrees",
	"success", "iterations", "limited", "referee_certain", "certified", "path", NULL
};
const char *const mkCollision_PairNames[MK_COLLISION_KINDS] = { "ellipsoids", "superquadrics", "near", "deep" };
/* The batch entries' rows, by mkBatchMode, and the names of mkBatchPath. */
static const char *const mkBatchEntry[MK_COLLISION_MODES] = { "minksum-batch-status", "minksum-batch-clearance",
	"minksum-batch-distance", "minksum-batch-full" };
static const char *const mkPathName[4] = { "separating", "overlap-point", "one-pair", "failed" };

/* The near kind's separations, in units of the size, by (trial / 2) % 12. */
static const double mkNearSteps[12] = { 1e-1, -1e-1, 1e-2, -1e-2, 1e-3, -1e-3, 1e-4, -1e-4, 1e-5, -1e-5,
	1e-6, -1e-6 };
/* The near kind's construction stops when the referee's distance is within
 * this fraction of the target. */
#define MK_NEAR_REL 1e-3
#define MK_NEAR_STEPS 20

int mkCollision_ParseLimit(void *context, const char *text, char *msg, size_t msglen)
{
	mkCollisionOptions *o = context;
	const char *eq = strchr(text, '=');
	char name[64];
	size_t n = eq ? (size_t)(eq - text) : 0;
	if (!eq || n == 0 || n >= sizeof name) {
		snprintf(msg, msglen, "is not allowed: must be NAME=N, NAME a collider, N a trial count");
		return -1;
	}
	memcpy(name, text, n);
	name[n] = '\0';
	const mkCollider *c = mkColliders_Find(name);
	char *end = NULL;
	errno = 0;
	long v = strtol(eq + 1, &end, 10);
	if (!c || c->referee || end == eq + 1 || *end != '\0' || errno || v < 0) {
		snprintf(msg, msglen, "is not allowed: must be NAME=N, NAME a collider of the registry other "
			"than the referee (mink collide --help lists them), N an integer >= 0");
		return -1;
	}
	if (o->nlimits >= MK_COLLISION_LIMITS) {
		snprintf(msg, msglen, "is not allowed: at most %d limits", MK_COLLISION_LIMITS);
		return -1;
	}
	o->limit_entry[o->nlimits] = c;
	o->limit_trials[o->nlimits++] = v;
	return 0;
}

/* The trial limit of entry c (-1: none). */
static long mkLimitOf(const mkCollisionOptions *o, const mkCollider *c)
{
	for (int i = 0; i < o->nlimits; ++i)
		if (o->limit_entry[i] == c)
			return o->limit_trials[i];
	return -1;
}

static const mkCollider *mkReferee(void)
{
	for (int i = 0; i < mkColliders_Count(); ++i)
		if (mkColliders_At(i)->referee)
			return mkColliders_At(i);
	return NULL;
}

void mkCollision_Meta(mkMeta *meta, const mkCollisionOptions *o, const int on[MK_COLLISION_KINDS])
{
	char buf[512] = "";
	for (int k = 0; k < MK_COLLISION_KINDS; ++k)
		if (on[k])
			snprintf(buf + strlen(buf), sizeof buf - strlen(buf), "%s%s", buf[0] ? "," : "", mkCollision_PairNames[k]);
	mkMeta_Set(meta, "pairs", buf);
	mkMeta_Set(meta, "rotation_draw", mkRotDraw_Names[o->rotations]);
	char margin[32];
	snprintf(margin, sizeof margin, "%g", o->margin);
	mkMeta_Set(meta, "referee_margin", margin);
	mkMeta_Set(meta, "referee_margin_unit", "scale (mkCollide3_PairSize of the pair)");
	mkMeta_Set(meta, "rng", "xoshiro256** seeded by splitmix64, one stream per trial: (kind << 32) | trial, "
		"kind 0 ellipsoids 1 superquadrics 2 near 3 deep");
	mkMeta_Set(meta, "draw", "B1 a,b,c~U(1,11) c~U(-5,5)^3; B2 a,b,c~U(1,6) c~U(5,15)^3; eps1,eps2~U(0.1,1.9) "
		"(ellipsoids 1,1); near and deep: ellipsoids on even trials, superquadrics on odd ones");
	mkMeta_Set(meta, "near", "B2 moved along the centre line to touching (minksum-ray's directional gap), then "
		"by secant steps on the referee's signed distance to s*size within 1e-3 relative, s = "
		"+-1e-1..+-1e-6 by (trial/2)%12, size = the smallest semi-axis of the two bodies");
	mkMeta_Set(meta, "deep", "centres U(-1,1)^3 and U(-2,2)^3");
	mkMeta_Set(meta, "error", "|distance - referee_distance| / mkCollide3_PairSize of the pair; empty (and agrees "
		"empty) where the referee is not certain");
	mkMeta_Set(meta, "referee_certain", "1 when the referee's answer is certified: separated with its bracket "
		"[lower, upper] of sd narrower than 1e-10 of the scale, or an overlap certified by an enclosing tetrahedron "
		"of support points; referee_distance is its certified lower bound of sd either way");
	mkMeta_Set(meta, "certified", "1/0 when the entry certifies its answer (minksum-normal: sd in [bound, bound + gap], "
		"for overlaps by a branch and bound over the sphere of normals within MK_COLLIDE3_GLOBAL_TOL of the scale; 0: "
		"its budget ran out, the depth is then a local optimum with a wider bracket); empty for entries that do not");
	mkMeta_Set(meta, "minksum_build", mkCollide3_Build());
	mkMeta_Set(meta, "batch_lanes", mkCollide3_BatchLanes());
	mkMeta_SetDouble(meta, "batch_chunk", MK_COLLISION_CHUNK);
	mkMeta_SetDouble(meta, "batch_clearance_delta", MK_COLLISION_DELTA);
	mkMeta_Set(meta, "batch", "rows minksum-batch-<mode>: each pair kind's pairs of a chunk of batch_chunk trials "
		"(aligned to trial numbers, cut at the run's ends) answered by one mkCollide3_Batch call per mode, before "
		"the one-pair entries run on the chunk; seconds = the call's time (repeated once when under 1 ms, the "
		"faster kept) / the chunk's pairs; distance where the mode gives one (distance: non-overlapping pairs, "
		"full: all); path = where the answer came from (separating, overlap-point, one-pair, failed); "
		"clearance asked: batch_clearance_delta (length units)");
	mkMeta_Set(meta, "timer", "CLOCK_MONOTONIC around the entry's run only (prepare untimed), one thread; a run "
		"under 1 ms is repeated at once on the same pair and the faster of the two kept (the first call after "
		"the other entries' calls finds its code and the pair out of cache)");
	buf[0] = '\0';
	for (int i = 0; i < o->nlimits; ++i)
		snprintf(buf + strlen(buf), sizeof buf - strlen(buf), "%s%s=%ld", i ? "," : "", o->limit_entry[i]->name,
			o->limit_trials[i]);
	mkMeta_Set(meta, "limits", o->nlimits ? buf : "none");
	for (int i = 0; i < mkColliders_Count(); ++i) {
		const mkCollider *c = mkColliders_At(i);
		char key[96];
		/* Sidecar keys are [a-z0-9_]: "minksum-normal" -> collider_minksum_normal. */
		snprintf(key, sizeof key, "collider_%s", c->name);
		for (char *p = key; *p; ++p)
			if (*p == '-')
				*p = '_';
		mkMeta_Set(meta, key, c->params ? c->params : "");
		if (c->version) {
			snprintf(key + strlen(key), sizeof key - strlen(key), "_version");
			mkMeta_Set(meta, key, c->version());
		}
	}
	/* The published means (ms), for the figure and readers of the sidecar;
	 * keys paper_table3_<i>_<kind>_ms, i the row of mkPaper_Table3. */
	for (int i = 0; i < mkPaper_Table3Count; ++i) {
		char key[96];
		snprintf(key, sizeof key, "paper_table3_%d_ellipsoids_ms", i);
		mkMeta_SetDouble(meta, key, mkPaper_Table3[i].ellipsoids_ms);
		snprintf(key, sizeof key, "paper_table3_%d_superquadrics_ms", i);
		mkMeta_SetDouble(meta, key, mkPaper_Table3[i].superquadrics_ms);
	}
}

/* ---- draws ------------------------------------------------------------------ */

static int mkDrawBody(mkRng *r, double amax, double clo, double chi, int ellipsoid, mkRotDraw rot,
	mkBody3 *body)
{
	double elo = ellipsoid ? 1.0 : 0.1, ehi = ellipsoid ? 1.0 : 1.9;
	mkShapeRange3 range = { { 1.0, amax }, { 1.0, amax }, { 1.0, amax }, { elo, ehi }, { elo, ehi } };
	mkShape3 s = mkDraw_Shape3(r, &range);
	mkVec3 t;
	t.x = mkRng_Uniform(r, clo, chi);
	t.y = mkRng_Uniform(r, clo, chi);
	t.z = mkRng_Uniform(r, clo, chi);
	mkMat3 R = mkDraw_Rotation3(r, rot);
	if (!mkMat3_IsFinite(R))
		return 0;
	*body = mkBody3_Make(s, R, t);
	return mkBody3_IsValid(*body, "body", NULL, 0);
}

/* The size a near pair's separation is measured in: the smallest semi-axis
 * of the two bodies, so that every separation asked for, overlaps of a
 * tenth of it included, exists along the centre line. */
static double mkNearSize(mkBody3 b1, mkBody3 b2)
{
	double s = b1.shape.a;
	double v[5] = { b1.shape.b, b1.shape.c, b2.shape.a, b2.shape.b, b2.shape.c };
	for (int i = 0; i < 5; ++i)
		s = v[i] < s ? v[i] : s;
	return s;
}

/* Move B2 along the centre line u so that the referee's signed distance is
 * target = s * size: to touching by minksum-ray's directional gap, then
 * secant steps on the referee's value (first slope <n, u> of its normal).
 * Returns 0, or -1 when the construction does not reach the target within
 * MK_NEAR_REL. */
static int mkPlaceNear(const mkCollider *referee, mkBody3 b1, mkBody3 *b2, double s, mkColliderScratch *scratch)
{
	mkCollision3 c;
	mkVec3 u = mkVec3_Normalize(mkVec3_Sub(b2->t, b1.t));
	if (mkCollide3_Ray(b1, *b2, &c) != MK_OK || !isfinite(c.directional))
		return -1;
	b2->t = mkVec3_Sub(b2->t, mkVec3_Scale(u, c.directional));
	double target = s * mkNearSize(b1, *b2);
	double slope = 1.0, prev_t = NAN, prev_miss = NAN, t = target;
	mkVec3 base = b2->t;
	for (int k = 0; k < MK_NEAR_STEPS; ++k) {
		b2->t = mkVec3_Add(base, mkVec3_Scale(u, t));
		if (mkCollider_Run(referee, b1, *b2, scratch, &c) != MK_OK || !isfinite(c.distance))
			return -1;
		double miss = c.distance - target;
		if (fabs(miss) <= MK_NEAR_REL * fabs(target))
			return 0;
		double d = mkVec3_Dot(c.normal, u);
		if (!isnan(prev_t) && miss != prev_miss)
			d = (miss - prev_miss) / (t - prev_t);
		if (isfinite(d) && d > 0.05)
			slope = d;
		prev_t = t;
		prev_miss = miss;
		t -= miss / slope;
	}
	return -1;
}

/* The pair of trial `trial` of kind `kind`; 0, or -1 after printing why. */
static int mkDrawPair(const mkCollisionOptions *o, int kind, long trial, const mkCollider *referee,
	mkColliderScratch *scratch, mkBody3 *b1, mkBody3 *b2)
{
	mkRng rng;
	mkRng_Seed(&rng, o->seed, ((uint64_t)kind << 32) | (uint64_t)trial);
	int ellipsoid = kind == 0 || (kind >= 2 && trial % 2 == 0);
	int deep = kind == 3;
	int ok = mkDrawBody(&rng, 11.0, deep ? -1.0 : -5.0, deep ? 1.0 : 5.0, ellipsoid, o->rotations, b1);
	ok = mkDrawBody(&rng, 6.0, deep ? -2.0 : 5.0, deep ? 2.0 : 15.0, ellipsoid, o->rotations, b2) && ok;
	if (!ok) {
		/* The ranges above keep every draw valid; a failure is a bug. */
		fprintf(stderr, "collision: %s trial %ld: invalid body drawn\n", mkCollision_PairNames[kind], trial);
		return -1;
	}
	if (kind == 2 && mkPlaceNear(referee, *b1, b2, mkNearSteps[(trial / 2) % 12], scratch) != 0) {
		fprintf(stderr, "collision: near trial %ld: the pair could not be placed at %g of its size\n", trial,
			mkNearSteps[(trial / 2) % 12]);
		return -1;
	}
	return 0;
}

/* ---- the runs --------------------------------------------------------------- */

static const char *mkStatusName(mkResult r, mkContact s)
{
	if (r != MK_OK || s == MK_CONTACT_UNKNOWN)
		return "failed";
	return mkContact_Name(s);
}

/* What the referee says of one pair: its answer and the pair's scale. */
typedef struct mkTruth {
	mkCollision3 ref;
	double scale;
	int certain;  /* the referee's bracket is within MK_REFEREE_CERTAIN of the
	                 scale, or its overlap is certified */
	int decided;  /* certain and |sd| > margin * scale: statuses are compared */
} mkTruth;

/* The widest referee bracket (times the scale) judged against. */
#define MK_REFEREE_CERTAIN 1e-10
/* Entries whose call took less (seconds) are timed twice in a row on the
 * pair, the faster call kept (mkCollision_Trial). */
#define MK_WARM_BELOW 1e-3

static void mkCsv_Maybe(mkCsv *csv, double v)
{
	if (isnan(v))
		mkCsv_Empty(csv);
	else
		mkCsv_Double(csv, v);
}

/* The row of one entry on one pair: limited rows (the entry's --limit
 * reached) have status `skipped` and nothing measured. */
static void mkWriteRow(mkCsv *csv, int kind, long trial, const char *entry, double seconds, mkResult r,
	const mkCollision3 *out, const mkTruth *truth, long limit, int skipped, const char *path)
{
	const char *status = skipped ? "skipped" : mkStatusName(r, out->status);
	int failed = strcmp(status, "failed") == 0;
	double dist = !skipped && !failed && isfinite(out->distance) ? out->distance : NAN;
	mkCsv_Str(csv, mkCollision_PairNames[kind]);
	mkCsv_Int(csv, trial);
	mkCsv_Str(csv, entry);
	mkCsv_Maybe(csv, skipped ? NAN : seconds);
	mkCsv_Str(csv, status);
	mkCsv_Maybe(csv, dist);
	mkCsv_Double(csv, truth->ref.distance);
	mkCsv_Maybe(csv, truth->certain ? fabs(dist - truth->ref.distance) / truth->scale : NAN);
	if (skipped || !truth->decided) {
		mkCsv_Empty(csv);
	} else {
		/* Touching counts as overlapping (in contact). */
		int says_sep = out->status == MK_CONTACT_SEPARATED;
		mkCsv_Int(csv, !failed && says_sep == (truth->ref.distance > 0.0));
	}
	if (skipped)
		mkCsv_Empty(csv);
	else
		mkCsv_Int(csv, !failed);
	if (skipped || failed || out->iterations < 0)
		mkCsv_Empty(csv);
	else
		mkCsv_Int(csv, out->iterations);
	if (limit < 0)
		mkCsv_Empty(csv);
	else
		mkCsv_Int(csv, limit);
	mkCsv_Int(csv, truth->certain);
	/* the entry's own certificate of its answer (minksum-normal: 0 for an
	 * overlap whose depth could not be certified global within its
	 * budget); empty for entries that certify nothing */
	if (skipped || failed || out->certified < 0)
		mkCsv_Empty(csv);
	else
		mkCsv_Int(csv, out->certified);
	if (path)
		mkCsv_Str(csv, path);
	else
		mkCsv_Empty(csv);
	mkCsv_EndRow(csv);
}

int mkCollision_Trial(const mkCollisionOptions *o, int kind, long trial, const mkCollisionChunk *chunk, mkCsv *csv)
{
	const mkCollider *referee = mkReferee();
	mkColliderScratch scratch;
	if (!referee || trial < chunk->begin || trial >= chunk->begin + chunk->count) {
		fprintf(stderr, "collision: %s trial %ld: %s\n", mkCollision_PairNames[kind], trial,
			referee ? "not in the chunk drawn" : "the collider registry has no referee");
		return -1;
	}
	mkBody3 b1 = chunk->b1[kind][trial - chunk->begin], b2 = chunk->b2[kind][trial - chunk->begin];
	mkTruth truth;
	if (mkCollider_Run(referee, b1, b2, &scratch, &truth.ref) != MK_OK || !isfinite(truth.ref.distance)) {
		fprintf(stderr, "collision: %s trial %ld: the referee failed\n", mkCollision_PairNames[kind], trial);
		return -1;
	}
	truth.scale = mkCollide3_PairSize(b1, b2);
	/* The referee's residual: its bracket width / scale (separated), 0 for a
	 * certified overlap, NaN otherwise (colliders.h). */
	truth.certain = truth.ref.residual <= MK_REFEREE_CERTAIN;
	truth.decided = truth.certain && fabs(truth.ref.distance) > o->margin * truth.scale;
	for (int i = 0; i < mkColliders_Count(); ++i) {
		const mkCollider *c = mkColliders_At(i);
		if (c->referee || !mkCollider_Accepts(c, b1, b2, NULL, 0))
			continue;
		long limit = mkLimitOf(o, c);
		mkCollision3 out;
		mkCollision3_Clear(&out);
		if (limit >= 0 && trial >= limit) {
			mkWriteRow(csv, kind, trial, c->name, 0.0, MK_OK, &out, &truth, limit, 1, NULL);
			continue;
		}
		mkResult r = c->prepare ? c->prepare(b1, b2, &scratch) : MK_OK;
		double t0 = mkClock_Wall();
		if (r == MK_OK)
			r = c->run(b1, b2, &scratch, &out);
		double seconds = mkClock_Wall() - t0;
		if (r == MK_OK && seconds < MK_WARM_BELOW) {
			/* A second call on the pair, the faster kept: the first pays for
			 * the caches the other entries' calls evicted (the same answer:
			 * every entry is deterministic). */
			mkCollision3 again;
			t0 = mkClock_Wall();
			mkResult r2 = c->run(b1, b2, &scratch, &again);
			double s2 = mkClock_Wall() - t0;
			if (r2 == MK_OK && s2 < seconds)
				seconds = s2;
		}
		mkWriteRow(csv, kind, trial, c->name, seconds, r, &out, &truth, limit, 0, NULL);
	}
	int at = (int)(trial - chunk->begin);
	for (int m = 0; m < MK_COLLISION_MODES; ++m) {
		mkCollision3 out;
		mkCollision3_Clear(&out);
		out.status = chunk->status[m][kind][at];
		out.distance = chunk->distance[m][kind][at];
		int path = chunk->path[m][kind][at];
		mkWriteRow(csv, kind, trial, mkBatchEntry[m], chunk->seconds[m][kind],
			path == MK_PATH_FAILED ? MK_ERR_CONVERGENCE : MK_OK, &out, &truth, -1, 0, mkPathName[path & 3]);
	}
	return 0;
}

/* The batch entries on one kind's pairs of the chunk: one call per mode. */
static int mkBatchKind(int kind, mkCollisionChunk *ch)
{
	int n = (int)ch->count;
	mkBatchPairs3 pairs = { n, ch->b1[kind], ch->b2[kind], NULL, NULL };
	for (int m = 0; m < MK_COLLISION_MODES; ++m) {
		mkBatchOut3 out = { ch->status[m][kind], ch->distance[m][kind], NULL, NULL, NULL, NULL, NULL, NULL,
			ch->path[m][kind] };
		double t0 = mkClock_Wall();
		mkResult r = mkCollide3_Batch(&pairs, (mkBatchMode)m, MK_COLLISION_DELTA, &out, NULL);
		double seconds = mkClock_Wall() - t0;
		if (r != MK_OK && r != MK_ERR_CONVERGENCE) {
			fprintf(stderr, "collision: %s trials %ld..%ld: mkCollide3_Batch (%s) failed: %s\n",
				mkCollision_PairNames[kind], ch->begin, ch->begin + n - 1, mkBatchMode_Name((mkBatchMode)m),
				mkResult_Name(r));
			return -1;
		}
		if (seconds < MK_WARM_BELOW) {
			/* the same rule as the one-pair entries: a second call, the
			 * faster kept (the answers are the same: the call is
			 * deterministic) */
			t0 = mkClock_Wall();
			mkCollide3_Batch(&pairs, (mkBatchMode)m, MK_COLLISION_DELTA, &out, NULL);
			double s2 = mkClock_Wall() - t0;
			seconds = s2 < seconds ? s2 : seconds;
		}
		ch->seconds[m][kind] = n > 0 ? seconds / n : NAN;
	}
	return 0;
}

int mkCollision_Chunk(const mkCollisionOptions *o, const int on[MK_COLLISION_KINDS], long begin, long end,
	mkCollisionChunk *chunk)
{
	const mkCollider *referee = mkReferee();
	mkColliderScratch scratch;
	if (!referee) {
		fprintf(stderr, "collision: the collider registry has no referee\n");
		return -1;
	}
	if (end - begin < 0 || end - begin > MK_COLLISION_CHUNK) {
		fprintf(stderr, "collision: a chunk of %ld trials: at most %d\n", end - begin, MK_COLLISION_CHUNK);
		return -1;
	}
	chunk->begin = begin;
	chunk->count = end - begin;
	for (int k = 0; k < MK_COLLISION_KINDS; ++k) {
		if (!on[k])
			continue;
		for (long t = begin; t < end; ++t)
			if (mkDrawPair(o, k, t, referee, &scratch, &chunk->b1[k][t - begin], &chunk->b2[k][t - begin]) != 0)
				return -1;
		if (mkBatchKind(k, chunk) != 0)
			return -1;
	}
	return 0;
}
