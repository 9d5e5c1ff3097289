/* cmd_collide.c - `mink collide`: status, distance or penetration depth and
 * witness points of two superquadrics, by any entry of the collider
 * registry (mink/colliders.h) or all of them. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <mink/colliders.h>
#include <mink/mink.h>
#include <mink_exp/args.h>

#include "commands.h"

static void help(void)
{
	printf(
		"usage: mink collide --body1 SPEC --body2 SPEC [--method NAME|all] [--csv]\n"
		"       mink collide --pairs FILE [--mode status|clearance|distance|full] [--delta D] [--out FILE]\n"
		"         (many pairs in one batch: see 'mink collide --pairs --help')\n"
		"\n"
		"Collision status, distance (separated or touching) or penetration depth\n"
		"(overlapping) and witness points of two 3D bodies. Text output, one block per\n"
		"method:\n"
		"  method: NAME\n"
		"  status: separated|touching|overlapping\n"
		"  distance: D         (separated or touching, where the method gives it)\n"
		"  penetration: P      (overlapping, where the method gives it)\n"
		"  witness1: x,y,z     witness2: x,y,z   (where the method gives them)\n"
		"  iterations: K       residual: R       (iterative methods)\n"
		"A method that does not converge says so (status: unknown) and the exit status\n"
		"is 1; bad input exits with 2.\n"
		"\n"
		"  --body1 SPEC     the first body, e.g. \"ellipsoid a=20 b=40 c=50\"\n"
		"  --body2 SPEC     the second body, e.g. \"sphere a=10 at=40,0,0\"\n"
		"  --method NAME    one of the methods below (default minksum-normal), or all\n"
		"  --csv            one CSV row per method instead of text\n"
		"\n"
		"SPEC: KIND key=value ...  with KIND sphere, ellipsoid or superquadric; keys a, b,\n"
		"c, eps1, eps2, quat=w,x,y,z, M=m11,...,m33 (row-major), at=x,y,z (as mink sum).\n"
		"\n"
		"methods:\n");
	for (int i = 0; i < mkColliders_Count(); ++i) {
		const mkCollider *c = mkColliders_At(i);
		printf("  %-18s %s%s\n", c->name, c->summary, (c->pairs & MK_PAIRS_SUPERQUADRICS) ? "" : " [ellipsoids only]");
	}
}

static const mkOption options[] = {
	{ "--body1", 1 }, { "--body2", 1 }, { "--method", 1 }, { "--csv", 0 },
};

static void print_vec(const char *label, mkVec3 v)
{
	printf("%s: %.17g,%.17g,%.17g\n", label, v.x, v.y, v.z);
}

static int finite3(mkVec3 v)
{
	return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

/* One method's answer as text or a CSV row. Returns 0, or 1 when the method
 * gave no verdict. */
static int report(const mkCollider *c, mkResult r, const mkCollision3 *o, int csv)
{
	int verdict = r == MK_OK && o->status != MK_CONTACT_UNKNOWN;
	int sep = o->status == MK_CONTACT_SEPARATED || o->status == MK_CONTACT_TOUCHING;
	int give_d = verdict && sep && (c->gives & MK_GIVES_DISTANCE) && isfinite(o->distance);
	int give_p = verdict && o->status == MK_CONTACT_OVERLAPPING && (c->gives & MK_GIVES_PENETRATION)
		&& isfinite(o->distance);
	int give_w = verdict && (c->gives & MK_GIVES_WITNESS) && finite3(o->p1) && finite3(o->p2);
	double dist = give_d ? fmax(o->distance, 0.0) : NAN;
	if (csv) {
		printf("%s,%s,", c->name, verdict ? mkContact_Name(o->status) : "unknown");
		if (give_d) printf("%.17g", dist);
		printf(",");
		if (give_p) printf("%.17g", -o->distance);
		printf(",");
		if (give_w)
			printf("%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", o->p1.x, o->p1.y, o->p1.z, o->p2.x, o->p2.y, o->p2.z);
		else
			printf(",,,,,");
		printf(",");
		if (o->iterations >= 0) printf("%d", o->iterations);
		printf(",");
		if (isfinite(o->residual)) printf("%.6g", o->residual);
		printf(",%s\n", r == MK_OK ? "" : mkResult_Name(r));
	} else {
		printf("method: %s\n", c->name);
		printf("status: %s\n", verdict ? mkContact_Name(o->status) : "unknown");
		if (!verdict)
			printf("error: %s\n", r == MK_ERR_CONVERGENCE ? "the solver did not converge" : mkResult_Name(r));
		if (give_d) printf("distance: %.17g\n", dist);
		if (give_p) printf("penetration: %.17g\n", -o->distance);
		if (give_w) {
			print_vec("witness1", o->p1);
			print_vec("witness2", o->p2);
		}
		if (o->iterations >= 0) printf("iterations: %d\n", o->iterations);
		if (isfinite(o->residual)) printf("residual: %.6g\n", o->residual);
	}
	if (!verdict)
		fprintf(stderr, "mink collide: method %s gave no verdict: %s\n", c->name,
			r == MK_ERR_CONVERGENCE ? "the solver did not converge" : mkResult_Name(r));
	return verdict ? 0 : 1;
}

int mkCmd_Collide(int argc, char **argv)
{
	for (int i = 1; i < argc; ++i)
		if (strcmp(argv[i], "--pairs") == 0 || strncmp(argv[i], "--pairs=", 8) == 0)
			return mkCmd_CollidePairs(argc, argv);
	const char *spec1 = NULL, *spec2 = NULL, *method = "minksum-normal";
	int csv = 0;
	char msg[512] = "";
	mkArgs args;
	mkArgs_Begin(&args, argc, argv);
	const char *name, *value;
	mkArgsStep step;
	while ((step = mkArgs_Step(&args, options, MK_COUNT(options), &name, &value, msg, sizeof msg)) == MK_ARGS_OPTION) {
		if (strcmp(name, "--body1") == 0) spec1 = value;
		else if (strcmp(name, "--body2") == 0) spec2 = value;
		else if (strcmp(name, "--method") == 0) method = value;
		else if (strcmp(name, "--csv") == 0) csv = 1;
	}
	if (step == MK_ARGS_HELP) {
		help();
		return 0;
	}
	if (step == MK_ARGS_ERROR) {
		fprintf(stderr, "mink collide: %s\n", msg);
		return 2;
	}
	if (!spec1 || !spec2) {
		fprintf(stderr, "mink collide: --body1 and --body2 are required\n");
		return 2;
	}
	int all = strcmp(method, "all") == 0;
	const mkCollider *one = all ? NULL : mkColliders_Find(method);
	if (!all && !one) {
		fprintf(stderr, "mink collide: --method %s is unknown: see 'mink collide --help' for the list\n", method);
		return 2;
	}
	mkSpec s1, s2;
	if (mkSpec_Parse(spec1, 3, "body1", &s1, msg, sizeof msg) != MK_OK
		|| mkSpec_Parse(spec2, 3, "body2", &s2, msg, sizeof msg) != MK_OK) {
		fprintf(stderr, "mink collide: %s\n", msg);
		return 2;
	}
	mkBody3 b1 = s1.body3, b2 = s2.body3;
	if (one && !mkCollider_Accepts(one, b1, b2, msg, sizeof msg)) {
		fprintf(stderr, "mink collide: method %s does not accept this pair: %s\n", one->name, msg);
		return 2;
	}
	if (csv)
		printf("method,status,distance,penetration,x1,y1,z1,x2,y2,z2,iterations,residual,error\n");
	mkColliderScratch scratch;
	int failed = 0, first = 1;
	for (int i = 0; i < mkColliders_Count(); ++i) {
		const mkCollider *c = mkColliders_At(i);
		if (one && c != one)
			continue;
		if (!mkCollider_Accepts(c, b1, b2, msg, sizeof msg))
			continue; /* with all: the methods that take the pair */
		if (!csv && !first)
			printf("\n");
		first = 0;
		mkCollision3 out;
		mkResult r = mkCollider_Run(c, b1, b2, &scratch, &out);
		failed |= report(c, r, &out, csv);
	}
	if (fflush(stdout) != 0 || ferror(stdout)) {
		fprintf(stderr, "mink collide: writing to standard output failed\n");
		return 1;
	}
	return failed ? 1 : 0;
}
