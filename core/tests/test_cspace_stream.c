/* test_cspace_stream.c - mkCSpace_Stream against mkCSpace_Run, on 1, 2 and
 * 3 threads, and mkCSpace_Estimate against the run it estimates.
 *
 * Reference: mkCSpace_Run on one thread (every boundary computed alone, kept
 * in index order), whose boundaries test_cspace checks against an
 * independent referee. Checked:
 *  - the sink is called once per boundary, in index order (orientation,
 *    obstacle, bound), never twice at once (a counter of calls in flight),
 *    with the same points, faces, errors and checksums bit for bit as the
 *    reference, on 1, 2 and 3 threads, 2D and 3D, inner and outer, adaptive
 *    and uniform; and mkCSpace_Run on 2 and 3 threads gives the reference's
 *    bits too;
 *  - a sink returning nonzero stops the run: MK_ERR_ARGUMENT, no call after;
 *  - paper mode and store = 0 are refused (MK_ERR_UNSUPPORTED);
 *  - mkCSpace_Estimate: the run's points counted by the sink lie within a
 *    factor of 4 of the estimate (the documented accuracy), the largest
 *    boundary likewise, for scenes whose boundaries reach the sample's cap
 *    of 2000 points and scenes whose boundaries do not. */
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/cspace.h>

#include "ensure.h"

static const char *scene2_text =
	"dim 2\nrobot superellipse a=2 b=1 eps=0.3\n"
	"obstacle circle a=3 at=10,0\nobstacle box size=6,2 rot=0.3 at=-30,-30\n"
	"obstacle superellipse a=4 b=2 eps=0.1 at=0,30\nobstacle ellipse a=1 b=3 rot=1\nheadings 11\n";
static const char *scene3_text =
	"dim 3\nrobot box size=1,0.5,0.7\nobstacle sphere a=2 at=5,0,0\n"
	"obstacle cylinder r=1 h=3 quat=0.7,0.7,0,0\nobstacle superquadric a=1 b=2 c=1 eps1=0.3 eps2=1.5\n"
	"quaternions 1,0,0,0;0.7071,0,0.7071,0;0.5,0.5,0.5,0.5;0,0,0,1\n";

/* a robot of three parts: the stream's order is (orientation, obstacle, part, bound) */
static const char *scene2_parts_text =
	"dim 2\npart box size=2,1 rot=0.2\npart ellipse a=0.6 b=0.3 rot=1 at=1.5,0.4\npart circle a=0.4 at=-1.2,-0.5\n"
	"object table\nobstacle box size=4,1 at=5,0\nobstacle circle a=0.3 at=4,2\nobject wall\n"
	"obstacle superellipse a=1 b=3 eps=0.2 at=-5,1\nheadings 5\n";

typedef struct StreamCheck {
	const mkCSpaceResult *ref;
	long next;            /* the index the next call must have */
	atomic_int in_flight;
	int max_in_flight, stop_after;
	long mismatches, points;
	double largest;
} StreamCheck;

static int same_boundary(const mkCSpaceBoundary *a, const mkCSpaceBoundary *b, int dim)
{
	if (a->count != b->count || a->face_count != b->face_count || a->stride != b->stride) return 0;
	if (memcmp(&a->error, &b->error, sizeof a->error) || memcmp(&a->checksum, &b->checksum, sizeof a->checksum)
		|| memcmp(&a->model_error, &b->model_error, sizeof a->model_error) || a->within_tol != b->within_tol)
		return 0;
	/* interleaved (stride dim): x is the whole array; else one array each */
	size_t n = (size_t)a->count * (size_t)a->stride;
	if (a->count && (memcmp(a->x, b->x, n * sizeof(double))
		|| (a->stride == 1 && (memcmp(a->y, b->y, n * sizeof(double))
		|| (dim == 3 && memcmp(a->z, b->z, n * sizeof(double)))))))
		return 0;
	return !a->face_count || memcmp(a->faces, b->faces, (size_t)a->face_count * 3 * sizeof(int)) == 0;
}

static int sink(void *user, int o, int i, int part, mkBound k, const mkCSpaceBoundary *b)
{
	StreamCheck *c = user;
	const mkCSpaceResult *r = c->ref;
	int now = atomic_fetch_add(&c->in_flight, 1) + 1;
	if (now > c->max_in_flight) c->max_in_flight = now;
	long idx = (((long)(o - r->orientation_begin) * r->obstacles + i) * r->parts + part) * r->bounds + (int)k;
	mkCSpaceBoundary want = mkCSpaceResult_PartBoundary(r, o, i, part, k);
	if (idx != c->next || !same_boundary(b, &want, r->dim)) ++c->mismatches;
	c->next = idx + 1;
	c->points += b->count;
	if (b->count > c->largest) c->largest = b->count;
	atomic_fetch_sub(&c->in_flight, 1);
	return c->stop_after > 0 && c->next >= c->stop_after;
}

static int results_same(const mkCSpaceResult *a, const mkCSpaceResult *b)
{
	for (int o = a->orientation_begin; o < a->orientation_begin + a->orientations; ++o)
		for (int i = 0; i < a->obstacles; ++i)
			for (int j = 0; j < a->parts; ++j)
				for (int k = 0; k < a->bounds; ++k) {
					mkCSpaceBoundary x = mkCSpaceResult_PartBoundary(a, o, i, j, (mkBound)k);
					mkCSpaceBoundary y = mkCSpaceResult_PartBoundary(b, o, i, j, (mkBound)k);
					if (!same_boundary(&x, &y, a->dim)) return 0;
				}
	return 1;
}

/* Stream and Run on 1, 2, 3 threads against the one-thread Run. */
static void check_scene(const char *text, double tol, int outer, mkCSpaceMode mode, int uniform, int interleaved)
{
	char msg[512];
	mkScene s;
	ENSURE(mkScene_Parse(text, &s, msg, sizeof msg) == MK_OK);
	mkCSpaceOptions o = mkCSpaceOptions_Default();
	o.tol = tol; o.outer = outer; o.mode = mode; o.uniform = uniform; o.interleaved = interleaved;
	mkCSpace *cs1 = NULL;
	ENSURE(mkCSpace_Create(&s, &o, &cs1, msg, sizeof msg) == MK_OK);
	int begin = 1, end = s.orientation_count; /* a range not starting at 0 */
	mkCSpaceResult ref;
	ENSURE(mkCSpace_Run(cs1, begin, end, &ref, msg, sizeof msg) == MK_OK);
	long nb = (long)ref.obstacles * ref.orientations * ref.parts * ref.bounds;
	for (int th = 1; th <= 3; ++th) {
		o.threads = th;
		mkCSpace *cs = NULL;
		ENSURE(mkCSpace_Create(&s, &o, &cs, msg, sizeof msg) == MK_OK);
		StreamCheck c;
		memset(&c, 0, sizeof c);
		atomic_init(&c.in_flight, 0);
		c.ref = &ref;
		ENSURE(mkCSpace_Stream(cs, begin, end, sink, &c, msg, sizeof msg) == MK_OK);
		ENSURE(c.next == nb && c.mismatches == 0 && c.max_in_flight == 1);
		mkCSpaceResult r;
		ENSURE(mkCSpace_Run(cs, begin, end, &r, msg, sizeof msg) == MK_OK);
		ENSURE(results_same(&ref, &r));
		mkCSpaceResult_Free(&r);
		/* a sink that says stop after 3 boundaries */
		memset(&c, 0, sizeof c);
		atomic_init(&c.in_flight, 0);
		c.ref = &ref;
		c.stop_after = 3;
		ENSURE(mkCSpace_Stream(cs, begin, end, sink, &c, msg, sizeof msg) == MK_ERR_ARGUMENT);
		ENSURE(c.next == 3 && c.mismatches == 0 && strstr(msg, "stopped by the caller") != NULL);
		mkCSpace_Destroy(cs);
	}
	mkCSpaceResult_Free(&ref);
	mkCSpace_Destroy(cs1);
	mkScene_Free(&s);
}

static void test_refusals(void)
{
	char msg[512];
	mkScene s;
	ENSURE(mkScene_Parse(scene2_text, &s, msg, sizeof msg) == MK_OK);
	mkCSpaceOptions o = mkCSpaceOptions_Default();
	o.mode = MK_CSPACE_PAPER;
	o.uniform = 50;
	mkCSpace *cs = NULL;
	StreamCheck c;
	memset(&c, 0, sizeof c);
	atomic_init(&c.in_flight, 0);
	ENSURE(mkCSpace_Create(&s, &o, &cs, msg, sizeof msg) == MK_OK);
	ENSURE(mkCSpace_Stream(cs, 0, 1, sink, &c, msg, sizeof msg) == MK_ERR_UNSUPPORTED && c.next == 0);
	mkCSpace_Destroy(cs);
	o = mkCSpaceOptions_Default();
	o.store = 0;
	ENSURE(mkCSpace_Create(&s, &o, &cs, msg, sizeof msg) == MK_OK);
	ENSURE(mkCSpace_Stream(cs, 0, 1, sink, &c, msg, sizeof msg) == MK_ERR_UNSUPPORTED && c.next == 0);
	ENSURE(mkCSpace_Stream(cs, 0, 99, sink, &c, msg, sizeof msg) == MK_ERR_ARGUMENT);
	mkCSpace_Destroy(cs);
	mkScene_Free(&s);
}

/* The estimate against the run's counted points. */
static void check_estimate(const char *text, double tol, int outer)
{
	char msg[512];
	mkScene s;
	ENSURE(mkScene_Parse(text, &s, msg, sizeof msg) == MK_OK);
	mkCSpaceOptions o = mkCSpaceOptions_Default();
	o.tol = tol; o.outer = outer; o.threads = 2;
	mkCSpace *cs = NULL;
	ENSURE(mkCSpace_Create(&s, &o, &cs, msg, sizeof msg) == MK_OK);
	mkCSpaceEstimate e;
	ENSURE(mkCSpace_Estimate(cs, 0, s.orientation_count, &e, msg, sizeof msg) == MK_OK);
	mkCSpaceResult r;
	ENSURE(mkCSpace_Run(cs, 0, s.orientation_count, &r, msg, sizeof msg) == MK_OK);
	double points = 0.0, largest = 0.0;
	long nb = (long)r.obstacles * r.orientations * r.bounds;
	for (long b = 0; b < nb; ++b) {
		points += r.count[b];
		if (r.count[b] > largest) largest = r.count[b];
	}
	printf("estimate %dD tol %g outer %d: %.0f points estimated, %.0f computed (largest %.0f / %.0f)\n", s.dim, tol,
		outer, e.points, points, e.largest, largest);
	ENSURE(e.points >= points / 4.0 && e.points <= 4.0 * points);
	ENSURE(e.largest >= largest / 4.0 && e.largest <= 4.0 * largest);
	ENSURE(e.sampled == (long)s.obstacle_count * r.bounds);
	mkCSpaceResult_Free(&r);
	mkCSpace_Destroy(cs);
	mkScene_Free(&s);
}

int main(void)
{
	check_scene(scene2_text, 0.01, 1, MK_CSPACE_ADAPTIVE, 0, 1);
	check_scene(scene2_text, 0.05, 0, MK_CSPACE_UNIFORM, 64, 0);
	check_scene(scene3_text, 0.05, 1, MK_CSPACE_ADAPTIVE, 0, 1);
	check_scene(scene3_text, 0.05, 0, MK_CSPACE_UNIFORM, 3, 0);
	check_scene(scene2_parts_text, 0.01, 1, MK_CSPACE_ADAPTIVE, 0, 1);
	test_refusals();
	check_estimate(scene2_text, 1e-2, 1);
	check_estimate(scene2_text, 1e-5, 0);
	check_estimate(scene3_text, 2e-2, 0);
	check_estimate(scene3_text, 1e-2, 1);
	return mk_summary("test_cspace_stream");
}
