/* A program outside the project that uses the installed C-space library:
 * one 2D scene prepared, run on two threads, one boundary read. */
#include <stdio.h>

#include <mink/cspace.h>

int main(void)
{
	const char *text = "dim 2\nrobot ellipse a=1 b=0.5\nobstacle box size=4,2 at=10,0\nheadings 4\n";
	char msg[512];
	mkScene scene;
	if (mkScene_Parse(text, &scene, msg, sizeof msg) != MK_OK) { fprintf(stderr, "%s\n", msg); return 1; }
	mkCSpaceOptions o = mkCSpaceOptions_Default();
	o.tol = 0.01;
	o.threads = 2;
	mkCSpace *cs = NULL;
	mkCSpaceResult r;
	int ok = mkCSpace_Create(&scene, &o, &cs, msg, sizeof msg) == MK_OK
		&& mkCSpace_Run(cs, 0, scene.orientation_count, &r, msg, sizeof msg) == MK_OK;
	if (!ok) fprintf(stderr, "%s\n", msg);
	if (ok) {
		mkCSpaceBoundary b = mkCSpaceResult_Boundary(&r, 1, 0, MK_BOUND_INNER);
		printf("mink-cspace: %s, %d points, certified error %g\n", mkCSpace_ModelName(cs, 0), b.count, b.error);
		ok = b.count > 8 && b.within_tol && mkCSpaceResult_OverTolerance(&r) == 0;
		mkCSpaceResult_Free(&r);
	}
	mkCSpace_Destroy(cs);
	mkScene_Free(&scene);
	return ok ? 0 : 1;
}
