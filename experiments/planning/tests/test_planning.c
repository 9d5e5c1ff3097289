/* test_planning.c - runs of the experiment `planning`:
 *  - FCL's inscribed meshes against a hand-worked case: a circle robot of
 *    radius 0.02 whose centre is 0.95 from the centre of a unit circle
 *    obstacle, in the direction pi/8. The true shapes overlap
 *    (0.95 - 0.02 < 1), mink rejects the start. At --res 8 the obstacle is
 *    a regular octagon with vertices at angles k pi/4, whose apothem
 *    cos(pi/8) = 0.924 lies below 0.93, the robot's nearest reach: FCL
 *    accepts the start (the mesh misses the contact). At --res 32 a vertex
 *    of the obstacle's 32-gon lies at angle pi/8 on the unit circle and one
 *    of the robot's points at 0.93 towards it: FCL rejects the start too.
 *  - a query of the 2D room with both checkers: a path from start to goal
 *    no shorter than the straight line (12, from the scene file), and
 *    mink's path certified free segment by segment. */
#include "planning.h"
#include "ensure.h"

#include <math.h>
#include <stdio.h>

static int mkTest_WriteScene(const char *path, double x, double y)
{
	FILE *fp = fopen(path, "w");
	if (!fp) return -1;
	fprintf(fp, "dim 2\nrobot circle a=0.02\nobstacle circle a=1\nbounds -3,3,-3,3\nstart %.17g,%.17g,0\ngoal 2.5,2.5,0\n",
		x, y);
	return fclose(fp);
}

int main(int argc, char **argv)
{
	const char *scenes = argc > 1 ? argv[1] : "experiments/plan/scenes";
	const char *tmp = argc > 2 ? argv[2] : ".";
	char path[1024], msg[1024];
	mkPlanningScene s;
	mkPlanningResult r;

	snprintf(path, sizeof path, "%s/planning-octagon.txt", tmp);
	double pi = acos(-1.0);
	ENSURE(mkTest_WriteScene(path, 0.95 * cos(pi / 8), 0.95 * sin(pi / 8)) == 0);
	ENSURE(mkPlanningScene_Load(&s, path, msg, sizeof msg) == 0);
	mkPlanningSetup setup = { "RRTConnect", MK_PLANNING_MINK, 1.0, 8, 3 };
	ENSURE(mkPlanning_Run(&s, 0, &setup, &r) == 0);
	ENSURE(r.status == MK_PLANNING_BAD);
	setup.checker = MK_PLANNING_FCL;
	ENSURE(mkPlanning_Run(&s, 0, &setup, &r) == 0);
	ENSURE(r.status == MK_PLANNING_PATH || r.status == MK_PLANNING_NONE);
	if (r.status == MK_PLANNING_PATH) ENSURE(r.colliding >= 1 && r.first_contact == 0 && r.contact_obstacle == 0);
	setup.res = 32;
	ENSURE(mkPlanning_Run(&s, 0, &setup, &r) == 0);
	ENSURE(r.status == MK_PLANNING_BAD);
	mkPlanningScene_Free(&s);

	snprintf(path, sizeof path, "%s/room2d.txt", scenes);
	ENSURE(mkPlanningScene_Load(&s, path, msg, sizeof msg) == 0);
	ENSURE(s.scene.query_count == 2);
	for (int c = 0; c < 2; ++c) {
		mkPlanningSetup q = { "RRTConnect", (mkPlanningChecker)c, 20.0, 32, 7 };
		ENSURE(mkPlanning_Run(&s, 1, &q, &r) == 0);
		ENSURE(r.status == MK_PLANNING_PATH);
		ENSURE(r.waypoints >= 2 && r.segments == r.waypoints - 1);
		ENSURE(r.length >= 12.0 - 1e-9);
		ENSURE(r.free + r.colliding + r.uncertain == r.segments);
		ENSURE(r.states > 0 && r.motions > 0);
		if (c == MK_PLANNING_MINK) ENSURE(r.free == r.segments);
	}
	mkPlanningScene_Free(&s);
	return mk_summary("planning.runs");
}
