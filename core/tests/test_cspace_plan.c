/* test_cspace_plan.c - planning problems in scene files (bounds, start,
 * goal) and the certified motion check of mink/scenequery.h on hand-worked
 * cases: a disc passing a disc (the clearance along the way is known in
 * closed form, and so is the time of first contact when the path cuts
 * through), a bar turning in place, and the interpolation of poses. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <mink/cspace.h>

#include "ensure.h"

static void test_parse(void)
{
	mkScene s;
	char msg[1024];
	ENSURE(mkScene_Parse("dim 3\nrobot sphere a=1\nbounds -1,2,-3,4,-5,6\nstart 0,0,0,1,0,0,0\ngoal 1,1,1,0,1,0,0\n"
		"goal 2,4,6,0,0,1,0\n", &s, msg, sizeof msg) == MK_OK);
	ENSURE(s.query_count == 2 && s.bounds_line == 3 && s.orientation_count == 0);
	ENSURE(s.bounds_lo[2] == -5.0 && s.bounds_hi[1] == 4.0);
	ENSURE(s.queries[1].start_line == 4 && s.queries[1].goal_line == 6 && s.queries[1].goal[2] == 6.0);
	ENSURE(s.queries[1].start[3] == 1.0);
	mkScene_Free(&s);
	static const struct { const char *text, *want; } bad[] = {
		{"dim 2\nrobot circle a=1\nstart 0,0,0\n", "line 3: start before bounds"},
		{"dim 2\nrobot circle a=1\nbounds 0,1,2\n", "line 3: bounds = '0,1,2' must be 4 comma-separated numbers xlo,xhi,ylo,yhi"},
		{"dim 2\nrobot circle a=1\nbounds 1,0,0,1\n", "line 3: bounds[1..2] = 1,0 is out of range: must be finite, lo < hi"},
		{"dim 2\nrobot circle a=1\nbounds 0,1,0,1\nbounds 0,1,0,1\n", "line 4: bounds are given twice (first on line 3)"},
		{"dim 2\nrobot circle a=1\nbounds 0,1,0,1\nstart 0.5,2,0\n", "line 4: start.y = 2 is out of range: must be in the bounds [0, 1] (line 3)"},
		{"dim 2\nrobot circle a=1\nbounds 0,1,0,1\ngoal 0.5,0.5,0\n", "line 4: goal without a start"},
		{"dim 2\nrobot circle a=1\nbounds 0,1,0,1\nstart 0.5,0.5,0\n", "line 4: start without a goal"},
		{"dim 2\nrobot circle a=1\nbounds 0,1,0,1\nstart 0.5,0.5\n", "line 4: start = '0.5,0.5' must be 3 comma-separated numbers x,y,theta"},
		{"dim 2\nrobot circle a=1\nbounds 0,1,0,1\nstart 0.5,0.5,inf\n", "line 4: start[3] = inf is out of range"},
		{"dim 3\nrobot sphere a=1\nbounds 0,1,0,1,0,1\nstart 0.5,0.5,0.5,0,0,0,0\n", "line 4: start: the quaternion qw,qx,qy,qz = 0,0,0,0 is out of range"},
		{"dim 2\nrobot circle a=1\n", "no orientations"},
	};
	for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
		msg[0] = 0;
		ENSURE(mkScene_Parse(bad[k].text, &s, msg, sizeof msg) != MK_OK);
		if (!strstr(msg, bad[k].want)) {
			ENSURE(!"message");
			fprintf(stderr, "  got '%s'\n  want '%s'\n", msg, bad[k].want);
		}
	}
}

static mkSceneQuery *make(const char *text, mkScene *s)
{
	char msg[1024];
	mkSceneQuery *q = NULL;
	ENSURE(mkScene_Parse(text, s, msg, sizeof msg) == MK_OK);
	mkSceneQueryOptions o = mkSceneQueryOptions_Default();
	ENSURE(mkSceneQuery_Create(s, &o, &q, msg, sizeof msg) == MK_OK);
	return q;
}

static void test_motions(void)
{
	/* a disc of radius 1 along y = 0 from x = -5 to 5, a disc of radius 1 at
	 * (0, 3): the clearance is sqrt(x^2 + 9) - 2, least 1 at x = 0 */
	mkScene s;
	mkSceneQuery *q = make("dim 2\nrobot circle a=1\nobstacle circle a=1 at=0,3\nheadings 1\n", &s);
	double a[3] = {-5, 0, 0}, b[3] = {5, 0, 0};
	mkMotionAnswer m;
	ENSURE(mkSceneQuery_Motion(q, a, b, 0.0, 1000000, &m) == MK_OK);
	ENSURE(m.status == MK_POSE_FREE && m.free_until == 1.0);
	ENSURE(m.clearance >= 0.5 - 1e-9 && m.clearance <= 1.0 + 1e-12);   /* at least half the certified minimum */
	printf("disc past a disc: certified minimum clearance %.6f (true 1) in %d poses\n", m.clearance, m.poses);
	/* the verdict alone: free, the clearance at least a tenth of the true minimum */
	ENSURE(mkSceneQuery_MotionTest(q, a, b, 0.0, 1000000, &m) == MK_OK && m.status == MK_POSE_FREE && m.free_until == 1.0);
	ENSURE(m.clearance >= 0.1 - 1e-9 && m.clearance <= 1.0 + 1e-12);
	ENSURE(mkSceneQuery_MotionTest(q, a, b, 1.1, 1000000, &m) == MK_OK && m.status != MK_POSE_FREE);
	/* with a margin of 0.9 it still passes; with 1.1 it cannot */
	ENSURE(mkSceneQuery_Motion(q, a, b, 0.9, 1000000, &m) == MK_OK && m.status == MK_POSE_FREE && m.clearance >= 0.9);
	ENSURE(mkSceneQuery_Motion(q, a, b, 1.1, 1000000, &m) == MK_OK && m.status != MK_POSE_FREE);
	ENSURE(m.free_until < 0.5);
	mkSceneQuery_Destroy(q);
	mkScene_Free(&s);
	/* the obstacle at (0, 1.5): first contact where x^2 + 1.5^2 = 4,
	 * x = -sqrt(1.75), t = (5 - sqrt(1.75)) / 10 */
	q = make("dim 2\nrobot circle a=1\nobstacle circle a=1 at=0,1.5\nheadings 1\n", &s);
	double tc = (5.0 - sqrt(1.75)) / 10.0;
	ENSURE(mkSceneQuery_Motion(q, a, b, 0.0, 1000000, &m) == MK_OK);
	ENSURE(m.status == MK_POSE_COLLIDING && m.obstacle == 0 && m.part == 0);
	ENSURE(m.free_until <= tc && m.free_until > tc - 1e-6);
	ENSURE(m.contact_time >= tc && m.contact_time <= tc + 1e-3);
	printf("disc through a disc: first contact at t = %.9f (closed form %.9f), contact found at %.6f\n", m.free_until, tc,
		m.contact_time);
	/* the verdict alone: some contact, the centres at x = 10 t - 5 and (0, 1.5) nearer than 2 */
	ENSURE(mkSceneQuery_MotionTest(q, a, b, 0.0, 1000000, &m) == MK_OK && m.status == MK_POSE_COLLIDING);
	ENSURE(m.free_until <= tc && hypot(10.0 * m.contact_time - 5.0, 1.5) < 2.0);
	mkSceneQuery_Destroy(q);
	mkScene_Free(&s);
	/* a wall 0.002 thick across the path of a disc of radius 0.01 moving 10:
	 * the disc is inside it only for t in 0.5 +- 0.0011, far less than the
	 * spacing of any sampling at a usual resolution; neither check passes it */
	q = make("dim 2\nrobot circle a=0.01\nobstacle box size=0.002,4 at=0.0003,0\nheadings 1\n", &s);
	ENSURE(mkSceneQuery_MotionTest(q, a, b, 0.0, 1000000, &m) == MK_OK && m.status != MK_POSE_FREE);
	ENSURE(m.free_until <= 0.5 - 0.0011 + 0.00003);
	ENSURE(mkSceneQuery_Motion(q, a, b, 0.0, 1000000, &m) == MK_OK && m.status == MK_POSE_COLLIDING);
	ENSURE(m.free_until <= 0.50003 - 0.0011 && m.free_until > 0.50003 - 0.0011 - 1e-4);
	ENSURE(fabs(10.0 * m.contact_time - 5.0 - 0.0003) < 0.011);
	printf("disc through a thin wall: motion test %s, first contact at t = %.7f (closed form %.7f)\n", "not free",
		m.free_until, 0.50003 - 0.0011);
	mkSceneQuery_Destroy(q);
	mkScene_Free(&s);
	/* a bar of half length 2 turning a quarter turn in place sweeps the disc
	 * of radius 2: a disc of radius 0.5 at (1.5, 1.5) is hit before 45
	 * degrees, one at (2.5, 2.5) (distance 3.04 from the centre) never */
	q = make("dim 2\nrobot box size=4,0.2\nobstacle circle a=0.5 at=1.5,1.5\nobstacle circle a=0.5 at=-2.5,2.5\nheadings 1\n", &s);
	double r0[3] = {0, 0, 0}, r1[3] = {0, 0, MK_PI / 2};
	ENSURE(mkSceneQuery_Motion(q, r0, r1, 0.0, 1000000, &m) == MK_OK);
	ENSURE(m.status == MK_POSE_COLLIDING && m.obstacle == 0 && m.contact_time < 0.5);
	ENSURE(mkSceneQuery_MotionTest(q, r0, r1, 0.0, 1000000, &m) == MK_OK);
	ENSURE(m.status == MK_POSE_COLLIDING && m.obstacle == 0);
	mkSceneQuery_Destroy(q);
	mkScene_Free(&s);
	q = make("dim 2\nrobot box size=4,0.2\nobstacle circle a=0.5 at=2.5,2.5\nheadings 1\n", &s);
	ENSURE(mkSceneQuery_Motion(q, r0, r1, 0.0, 1000000, &m) == MK_OK && m.status == MK_POSE_FREE);
	ENSURE(m.clearance > 0.0 && m.clearance <= sqrt(12.5) - 0.5 - 2.0 + 1e-12);
	ENSURE(mkSceneQuery_MotionTest(q, r0, r1, 0.0, 1000000, &m) == MK_OK && m.status == MK_POSE_FREE);
	ENSURE(m.clearance > 0.0 && m.clearance <= sqrt(12.5) - 0.5 - 2.0 + 1e-12);
	mkSceneQuery_Destroy(q);
	mkScene_Free(&s);
	/* a chain of 17 discs of radius 0.1 (more parts than the cheap layer
	 * takes: pose queries only) along x from -5 to 5: 1.9 from a unit disc
	 * at (0, 3); through one at (0, 1.05), where some disc's centre lies
	 * within 1.1 of the obstacle's at the contact found */
	char chain[2048] = "dim 2\n";
	for (int k = 0; k < 17; ++k)
		snprintf(chain + strlen(chain), sizeof chain - strlen(chain), "part circle a=0.1 at=%g,0\n", 0.1 * k);
	size_t base = strlen(chain);
	snprintf(chain + base, sizeof chain - base, "obstacle circle a=1 at=0,3\nheadings 1\n");
	q = make(chain, &s);
	ENSURE(mkSceneQuery_MotionTest(q, a, b, 0.0, 1000000, &m) == MK_OK && m.status == MK_POSE_FREE);
	ENSURE(m.clearance > 0.0 && m.clearance <= 1.9 + 1e-12);
	mkSceneQuery_Destroy(q);
	mkScene_Free(&s);
	snprintf(chain + base, sizeof chain - base, "obstacle circle a=1 at=0,1.05\nheadings 1\n");
	q = make(chain, &s);
	ENSURE(mkSceneQuery_MotionTest(q, a, b, 0.0, 1000000, &m) == MK_OK && m.status == MK_POSE_COLLIDING);
	double near = INFINITY;
	for (int k = 0; k < 17; ++k) near = fmin(near, hypot(10.0 * m.contact_time - 5.0 + 0.1 * k, 1.05));
	ENSURE(near < 1.1);
	/* interpolation: the heading the shorter way round, wrapped */
	double h0[3] = {0, 0, 3.0}, h1[3] = {2, 4, -3.0}, p[3];
	mkSceneQuery_Interpolate(q, h0, h1, 0.5, p);
	ENSURE(p[0] == 1.0 && p[1] == 2.0);
	ENSURE_NEAR(fabs(p[2]), MK_PI, 1e-12);
	mkSceneQuery_Destroy(q);
	mkScene_Free(&s);
	/* 3D: slerp halfway between the identity and a half turn about z */
	q = make("dim 3\nrobot sphere a=1\nquaternions 1,0,0,0\n", &s);
	double qa[7] = {0, 0, 0, 1, 0, 0, 0}, qb[7] = {2, 0, 0, 0, 0, 0, -1}, qm[7];
	mkSceneQuery_Interpolate(q, qa, qb, 0.5, qm);
	ENSURE_NEAR(qm[0], 1.0, 1e-15);
	ENSURE_NEAR(qm[3], sqrt(0.5), 1e-12);   /* a quarter turn about z */
	ENSURE_NEAR(fabs(qm[6]), sqrt(0.5), 1e-12);
	/* -q is the same rotation as q: the motion from q to -q does not turn */
	double qn[7] = {0, 0, 0, -1, 0, 0, 0};
	mkSceneQuery_Interpolate(q, qa, qn, 0.5, qm);
	ENSURE_NEAR(qm[3], 1.0, 1e-12);
	ENSURE_NEAR(fabs(qm[4]) + fabs(qm[5]) + fabs(qm[6]), 0.0, 1e-12);
	mkSceneQuery_Destroy(q);
	mkScene_Free(&s);
}

int main(void)
{
	test_parse();
	test_motions();
	return mk_summary("test_cspace_plan");
}
