/* cmd_verify.c - `mink verify`: put a method's output (a CSV of points, as
 * `mink sum` writes it) through the referee and print the verdict. */
#include <float.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/referee.h>
#include <mink/registry.h>

#include "cli.h"
#include "commands.h"
#include "points.h"

static void help(FILE *fp)
{
	fprintf(fp, "usage: mink verify --dim 2|3 --body1 SPEC --body2 SPEC --method NAME --points FILE [options]\n"
		"\n"
		"Check that the points in FILE are what method NAME claims for the two bodies,\n"
		"with the referee of the baselines (exact CGAL predicates for sampled methods;\n"
		"a two-sided support-function check for the others). Prints the verdict; the\n"
		"exit status is 0 when the output passes, 1 when it fails, 2 on bad input.\n"
		"--points: a CSV with a header naming columns x, y (and z), as 'mink sum'\n"
		"writes, or no header and x, y[, z] first; lines starting with # are skipped.\n"
		"--n: required for sampled methods (samples per body); for the others it\n"
		"follows from the number of points (N in 2D, N x N in 3D) and is checked.\n"
		"--dense: default 8192 (2D) / 128 (3D grid side).\n"
		"Points of a method that is not sampled must be in its order: point k belongs\n"
		"to body 1's surface parameter k, or the sum's normal k (mink/registry.h).\n"
		"A method that is not sampled and whose points are unordered (an external\n"
		"exec: method, or a registry method declaring MK_INDEX_UNORDERED) is judged\n"
		"by the error measure ('mink score'): it passes when every point lies within\n"
		"--tol of the sum's size off the true boundary (default: the method's stated\n"
		"tolerance, or for an exact method the measure's rounding allowance; an\n"
		"external method states none, so --tol is required for it).\n\n");
}

/* The referee's verdict on standard output; the exit status. */
static int mkVerify_Report(const mkMethod *m, int dim, mkSet set, int n, mkResult r, const mkVerdict *v, int quiet)
{
	if (r == MK_ERR_UNSUPPORTED && v->message[0]) {
		fprintf(stderr, "mink verify: %s\n", v->message);
		return 2;
	}
	if (r != MK_OK) {
		fprintf(stderr, "mink verify: the referee could not run: %s\n", mkResult_Name(r));
		return 2;
	}
	if (!quiet) {
		if (v->kind == MK_VERDICT_MEASURE)
			printf("method %s, %dD, %s set, %d points, unordered: judged by the error measure\n", m->name, dim,
				mkSet_Name(set), n);
		else
			printf("method %s, %dD, %s set, n = %d\n", m->name, dim, mkSet_Name(set), n);
		printf("%s\n", v->message);
		if (fflush(stdout)) {
			fprintf(stderr, "mink verify: writing to standard output failed\n");
			return 2;
		}
	}
	return v->pass ? 0 : 1;
}

/* ---- the command ----------------------------------------------------------- */

int mkCmd_Verify(int argc, char **argv)
{
	const char *spec1 = NULL, *spec2 = NULL, *method = NULL, *points = NULL;
	long dim = 0, n = 0, dense = 0;
	double tol = 0.0;
	int quiet = 0, setc = 0;
	mkFlag flags[] = {
		MK_FLAG_LONG("--dim", "2|3", "dimension (required)", &dim, 2, 3),
		MK_FLAG_TEXT("--body1", "SPEC", "the first body (required)", &spec1, NULL),
		MK_FLAG_TEXT("--body2", "SPEC", "the second body (required)", &spec2, NULL),
		MK_FLAG_TEXT("--method", "NAME", "the method that made the points (required; 'mink methods')", &method, NULL),
		MK_FLAG_TEXT("--points", "FILE", "the points as CSV (x,y[,z] first), '-' for standard input (required)",
			&points, NULL),
		MK_FLAG_SET("--set", "the set the points are of (default contact)", &setc),
		MK_FLAG_LONG("--n", "N", "the method's resolution (default: from the point count)", &n, 1, 100000000),
		MK_FLAG_LONG("--dense", "K", "the referee's dense samples, 8..1048576", &dense, 8, 1 << 20),
		MK_FLAG_SWITCH("--quiet", "print nothing; only the exit status", &quiet),
		MK_FLAG_DOUBLE("--tol", "T", "unordered points: largest distance off the boundary allowed,\n"
			"relative to the sum's size (default: what the method states)", &tol, 1e-17, 1.0),
	};
	int rc = mkCli_Parse("verify", flags, MK_COUNT(flags), argc, argv, help);
	if (rc != MK_CLI_GO)
		return rc;
	for (int k = 0; k < 5; ++k)
		if ((rc = mkCli_Require("verify", &flags[k])) != MK_CLI_GO)
			return rc;
	int have_n = flags[6].given;
	mkSet set = setc == 0 ? MK_SET_CONTACT : MK_SET_PLUS;
	const mkMethod *m = mkRegistry_Find(method);
	if (!m) {
		fprintf(stderr, "mink verify: --method %s is unknown: see 'mink methods' for the list\n", method);
		return 2;
	}
	mkSpec s1, s2;
	char msg[512];
	if (mkSpec_Parse(spec1, (int)dim, "body1", &s1, msg, sizeof msg) != MK_OK
		|| mkSpec_Parse(spec2, (int)dim, "body2", &s2, msg, sizeof msg) != MK_OK) {
		fprintf(stderr, "mink verify: %s\n", msg);
		return 2;
	}
	int ok = dim == 2 ? mkMethod2_Accepts(m, s1.body2, s2.body2, set, msg, sizeof msg)
		: mkMethod3_Accepts(m, s1.body3, s2.body3, set, msg, sizeof msg);
	if (!ok) {
		fprintf(stderr, "mink verify: method %s does not accept this pair: %s\n", m->name, msg);
		return 2;
	}

	mkPointSet pts = {0};
	if (mkPoints_Read("verify", points, (int)dim, &pts)) {
		mkPointSet_Free(&pts);
		return 2;
	}

	mkRefereeOptions opt = {(int)dense, 0, 0, flags[9].given ? tol : 0.0};
	mkVerdict v = {0};
	mkResult r;
	if (mkMethod_Indexing(m) == MK_INDEX_UNORDERED && !(m->flags & MK_METHOD_SAMPLED)) {
		/* no index to check the points by: the referee judges them by the error measure */
		r = dim == 2 ? mkReferee2_Check(m, s1.body2, s2.body2, set, pts.count, &pts, &opt, &v)
			: mkReferee3_Check(m, s1.body3, s2.body3, set, pts.count, &pts, &opt, &v);
		int count = pts.count;
		mkPointSet_Free(&pts);
		return mkVerify_Report(m, (int)dim, set, count, r, &v, quiet);
	}

	/* The resolution: given, or (not sampled) read off the point count. */
	int sampled = !!(m->flags & MK_METHOD_SAMPLED);
	long implied = pts.count;
	if (!sampled && dim == 3) {
		implied = 0;
		while ((implied + 1) * (implied + 1) <= pts.count) ++implied;
		if (implied * implied != pts.count) {
			fprintf(stderr, "mink verify: %d points: method %s gives N x N points in 3D\n", pts.count, m->name);
			mkPointSet_Free(&pts);
			return 2;
		}
	}
	if (sampled && !have_n) {
		fprintf(stderr, "mink verify: method %s is sampled: give --n, the samples per body it ran with\n", m->name);
		mkPointSet_Free(&pts);
		return 2;
	}
	if (!sampled && have_n && n != implied) {
		fprintf(stderr, "mink verify: --n %ld, but %d points mean N = %ld for method %s in %ldD\n", n, pts.count,
			implied, m->name, dim);
		mkPointSet_Free(&pts);
		return 2;
	}
	if (!have_n) n = implied;
	if (!mkMethod_CheckN(m, (int)dim, (int)n, msg, sizeof msg)) {
		fprintf(stderr, "mink verify: %s\n", msg);
		mkPointSet_Free(&pts);
		return 2;
	}
	if (sampled && n > (dim == 2 ? MK_HULL2_N_MAX : MK_HULL3_N_MAX)) {
		fprintf(stderr, "mink verify: --n %ld: the referee holds all pairwise sums and takes n <= %d in %ldD\n", n,
			dim == 2 ? MK_HULL2_N_MAX : MK_HULL3_N_MAX, dim);
		mkPointSet_Free(&pts);
		return 2;
	}

	/* An approximate tier is held to the accuracy it states (relative to the
	 * scale), not to the rounding allowance of the exact methods. */
	if (m->flags & MK_METHOD_APPROX)
		opt.tol_factor = mkMethod_Tolerance(m) / (MK_REFEREE_ULPS * DBL_EPSILON / 2);
	r = dim == 2 ? mkReferee2_Check(m, s1.body2, s2.body2, set, (int)n, &pts, &opt, &v)
		: mkReferee3_Check(m, s1.body3, s2.body3, set, (int)n, &pts, &opt, &v);
	mkPointSet_Free(&pts);
	return mkVerify_Report(m, (int)dim, set, (int)n, r, &v, quiet);
}
