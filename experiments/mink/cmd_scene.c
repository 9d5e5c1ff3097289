/* cmd_scene.c - `mink scene`: the certified C-obstacles of a scene file
 * (mink/cobstacle.h) as CSV, with a report per obstacle. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/mink.h>
#include <mink_exp/args.h>
#include <mink_exp/outfile.h>
#include <mink_exp/shard.h>

#include "commands.h"

#define SCENE_FILE_MAX (1L << 30)
#define THREADS_MAX 256

static void help(void)
{
	printf(
		"usage: mink scene FILE --tol T --out PATH [options]\n"
		"\n"
		"Configuration-space obstacles of the scene in FILE: for every robot orientation\n"
		"and obstacle, an inner boundary (inside the C-obstacle) and with --outer an outer\n"
		"one (enclosing it), each within Hausdorff distance T of the C-obstacle of the\n"
		"declared shapes (model error of boxes and cylinders included), with normals\n"
		"placed adaptively where the curvature needs them. See docs/scene.md.\n"
		"\n"
		"  --tol T          the tolerance, in the scene's length unit, in [1e-12, 1e12]\n"
		"  --out PATH       CSV obstacle,orientation,kind,k,x,y[,z] (kind inner or outer; 2D\n"
		"                   counter-clockwise); 3D faces go to PATH with .csv replaced by\n"
		"                   .faces.csv: obstacle,orientation,kind,f,i,j,k. Written\n"
		"                   atomically: nothing on any error\n"
		"  --report PATH    CSV per obstacle: model, model error, points, certified error,\n"
		"                   seconds (and a robot row)\n"
		"  --outer          also the outer boundaries\n"
		"  --threads K      worker threads, 1..%d (default 1); the output does not depend on K\n"
		"  --shard I/N      only block I (0-based) of N of the orientations; the shards'\n"
		"                   rows concatenated in order (one header) equal the whole run's\n"
		"  --impl auto|scalar|avx2|avx512   kernel (default auto)\n"
		"\n"
		"Scene file:\n"
		"  # comment\n"
		"  dim 2|3                              first line\n"
		"  robot SPEC                           once; its at= is ignored\n"
		"  obstacle SPEC                        any number; indices 0, 1, ... in order\n"
		"  headings N | headings a1,a2,...      2D: angles 2 pi k / N, or these radians\n"
		"  quaternions w,x,y,z;w,x,y,z;...      3D orientations\n"
		"  rotations FILE                       3D: one rotation per line, r11,...,r33 or\n"
		"                                       w,x,y,z (relative to the scene's folder)\n"
		"SPEC as in 'mink sum' (circle, ellipse, superellipse, sphere, ellipsoid,\n"
		"superquadric) plus 'box size=l,w[,h]' and 'cylinder r=R h=H' (axis z), with the\n"
		"pose keys rot, shear (2D), quat (3D), M, at. The robot at heading a (rotation R)\n"
		"is the body with map R M.\n",
		THREADS_MAX);
}

static char *read_file(const char *path, long *len, char *msg, size_t msglen)
{
	FILE *f = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
	if (!f) {
		snprintf(msg, msglen, "%s: cannot open: %s", path, strerror(errno));
		return NULL;
	}
	size_t cap = 1 << 16, n = 0;
	char *buf = malloc(cap);
	while (buf) {
		if (n + 1 >= cap) {
			if (cap >= (size_t)SCENE_FILE_MAX) { free(buf); buf = NULL; snprintf(msg, msglen, "%s: larger than 1 GiB", path); break; }
			char *nb = realloc(buf, cap * 2);
			if (!nb) { free(buf); buf = NULL; snprintf(msg, msglen, "out of memory"); break; }
			buf = nb;
			cap *= 2;
		}
		size_t got = fread(buf + n, 1, cap - n - 1, f);
		n += got;
		if (got == 0) break;
	}
	if (buf && ferror(f)) { free(buf); buf = NULL; snprintf(msg, msglen, "%s: read error", path); }
	if (buf && memchr(buf, 0, n)) { free(buf); buf = NULL; snprintf(msg, msglen, "%s: not a text file (NUL byte)", path); }
	if (f != stdin) fclose(f);
	if (buf) { buf[n] = 0; *len = (long)n; }
	return buf;
}

/* PATH with .csv replaced by .faces.csv (or .faces.csv appended). */
static void faces_path(const char *out, char *buf, size_t len)
{
	size_t n = strlen(out);
	if (n > 4 && strcmp(out + n - 4, ".csv") == 0) snprintf(buf, len, "%.*s.faces.csv", (int)(n - 4), out);
	else snprintf(buf, len, "%s.faces.csv", out);
}

typedef struct ObstacleSum {
	long points;
	double error, model_error, seconds;
	char model[128];
} ObstacleSum;

int mkCmd_Scene(int argc, char **argv)
{
	static const mkOption opts[] = {
		{"--tol", 1}, {"--out", 1}, {"--report", 1}, {"--outer", 0}, {"--threads", 1}, {"--shard", 1}, {"--impl", 1},
	};
	const char *file = NULL, *out = NULL, *report = NULL;
	double tol = 0.0;
	int have_tol = 0, outer = 0, impl = MK_IMPL_AUTO;
	long threads = 1;
	mkShard shard = mkShard_All();
	char msg[2048];
	int first = 1;
	if (argc > 1 && strncmp(argv[1], "--", 2) != 0 && strcmp(argv[1], "-h") != 0) {
		file = argv[1];
		first = 2;
	}
	mkArgs a;
	mkArgs_Begin(&a, argc - first + 1, argv + first - 1);
	const char *name, *value;
	mkArgsStep step;
	while ((step = mkArgs_Step(&a, opts, MK_COUNT(opts), &name, &value, msg, sizeof msg)) == MK_ARGS_OPTION) {
		int bad = 0;
		if (strcmp(name, "--tol") == 0) { bad = mkArg_Double(name, value, 1e-12, 1e12, "a number", &tol, msg, sizeof msg); have_tol = 1; }
		else if (strcmp(name, "--out") == 0) bad = mkArg_Path(name, value, &out, msg, sizeof msg);
		else if (strcmp(name, "--report") == 0) bad = mkArg_Path(name, value, &report, msg, sizeof msg);
		else if (strcmp(name, "--outer") == 0) outer = 1;
		else if (strcmp(name, "--threads") == 0) bad = mkArg_Long(name, value, 1, THREADS_MAX, &threads, msg, sizeof msg);
		else if (strcmp(name, "--shard") == 0) bad = mkShard_Parse(value, name, &shard, msg, sizeof msg);
		else if (strcmp(name, "--impl") == 0) bad = mkArg_Impl(name, value, &impl, msg, sizeof msg);
		if (bad) { fprintf(stderr, "mink scene: %s\n", msg); return 2; }
	}
	if (step == MK_ARGS_HELP) { help(); return 0; }
	if (step == MK_ARGS_ERROR) { fprintf(stderr, "mink scene: %s\n", msg); return 2; }
	if (!file) { fprintf(stderr, "mink scene: no scene FILE given (usage: mink scene FILE --tol T --out PATH)\n"); return 2; }
	if (!have_tol) { fprintf(stderr, "mink scene: --tol is required: a number in [1e-12, 1e+12]\n"); return 2; }
	if (!out) { fprintf(stderr, "mink scene: --out is required\n"); return 2; }

	long len = 0;
	char *text = read_file(file, &len, msg, sizeof msg);
	if (!text) { fprintf(stderr, "mink scene: %s\n", msg); return 2; }
	mkScene scene;
	mkResult r = mkScene_Parse(text, &scene, msg, sizeof msg);
	free(text);
	if (r != MK_OK) { fprintf(stderr, "mink scene: %s: %s\n", file, msg); return 2; }
	int rc = 2;
	mkOutFile fo, ff, fr;
	memset(&fo, 0, sizeof fo); memset(&ff, 0, sizeof ff); memset(&fr, 0, sizeof fr);
	fo.slot = ff.slot = fr.slot = -1;
	int open_o = 0, open_f = 0, open_r = 0;
	ObstacleSum *sum = NULL;
	if (scene.rotations_file[0]) {
		char path[MK_PATH_MAX];
		const char *slash = strrchr(file, '/');
		if (scene.rotations_file[0] != '/' && slash)
			snprintf(path, sizeof path, "%.*s/%s", (int)(slash - file), file, scene.rotations_file);
		else
			snprintf(path, sizeof path, "%s", scene.rotations_file);
		char *rt = read_file(path, &len, msg, sizeof msg);
		if (!rt) { fprintf(stderr, "mink scene: %s: line %d: rotations: %s\n", file, scene.rotations_line, msg); goto done; }
		r = mkScene_SetRotations(&scene, rt, path, msg, sizeof msg);
		free(rt);
		if (r != MK_OK) { fprintf(stderr, "mink scene: %s: line %d: rotations: %s\n", file, scene.rotations_line, msg); goto done; }
	}
	mkCSpaceOptions o = mkCSpaceOptions_Default();
	o.tol = tol;
	o.outer = outer;
	o.threads = (int)threads;
	o.impl = (mkImpl)impl;
	long begin, end;
	mkShard_Range(shard, scene.orientation_count, &begin, &end);
	/* validate the models (a tolerance too small for a box) before any file */
	mkCSpaceResult res;
	r = mkCSpace_Run(&scene, &o, (int)begin, (int)begin, &res, msg, sizeof msg);
	if (r != MK_OK) { fprintf(stderr, "mink scene: %s: %s\n", file, msg); goto done; }
	int nob = scene.obstacle_count;
	sum = calloc((size_t)nob + 1, sizeof *sum);
	if (!sum) { fprintf(stderr, "mink scene: out of memory\n"); rc = 1; mkCSpaceResult_Free(&res); goto done; }
	for (int i = 0; i < nob; ++i) snprintf(sum[i].model, sizeof sum[i].model, "%s", res.model_name[i]);
	mkCSpaceResult_Free(&res);

	rc = 1;
	char fpath[MK_PATH_MAX];
	faces_path(out, fpath, sizeof fpath);
	if (mkOutFile_Open(&fo, out, msg, sizeof msg)) { fprintf(stderr, "mink scene: --out %s: %s\n", out, msg); goto done; }
	open_o = 1;
	if (scene.dim == 3) {
		if (mkOutFile_Open(&ff, fpath, msg, sizeof msg)) { fprintf(stderr, "mink scene: %s: %s\n", fpath, msg); goto done; }
		open_f = 1;
	}
	if (report) {
		if (mkOutFile_Open(&fr, report, msg, sizeof msg)) { fprintf(stderr, "mink scene: --report %s: %s\n", report, msg); goto done; }
		open_r = 1;
	}
	fprintf(fo.fp, "obstacle,orientation,kind,k,x,y%s\n", scene.dim == 3 ? ",z" : "");
	if (open_f) fprintf(ff.fp, "obstacle,orientation,kind,f,i,j,k\n");
	static const char *const kinds[] = {"inner", "outer"};
	/* orientations in chunks, so that memory stays bounded; every boundary is
	 * computed alone, so the chunking changes nothing in the output */
	long budget = scene.dim == 2 ? 20000 : 2000; /* (orientation, obstacle) tasks per chunk */
	long chunk = nob > 0 ? budget / nob : (long)scene.orientation_count + 1;
	if (chunk < 1) chunk = 1;
	int short_of_tol = 0;
	for (long c0 = begin; c0 < end; c0 += chunk) {
		long c1 = c0 + chunk < end ? c0 + chunk : end;
		r = mkCSpace_Run(&scene, &o, (int)c0, (int)c1, &res, msg, sizeof msg);
		if (r != MK_OK) { fprintf(stderr, "mink scene: %s\n", msg); goto done; }
		for (int orel = 0; orel < res.orientations; ++orel)
			for (int i = 0; i < nob; ++i)
				for (int k = 0; k < res.bounds; ++k) {
					long b = ((long)orel * nob + i) * res.bounds + k;
					long ori = c0 + orel;
					for (int j = 0; j < res.count[b]; ++j) {
						long q = res.first[b] + j;
						if (scene.dim == 2)
							fprintf(fo.fp, "%d,%ld,%s,%d,%.17g,%.17g\n", i, ori, kinds[k], j, res.x[q], res.y[q]);
						else
							fprintf(fo.fp, "%d,%ld,%s,%d,%.17g,%.17g,%.17g\n", i, ori, kinds[k], j, res.x[q], res.y[q], res.z[q]);
					}
					if (open_f)
						for (long f = res.face_first[b]; f < res.face_first[b + 1]; ++f)
							fprintf(ff.fp, "%d,%ld,%s,%ld,%d,%d,%d\n", i, ori, kinds[k], f - res.face_first[b],
								res.faces[3 * f], res.faces[3 * f + 1], res.faces[3 * f + 2]);
					sum[i].points += res.count[b];
					if (res.error[b] > sum[i].error) sum[i].error = res.error[b];
					if (res.model_error[b] > sum[i].model_error) sum[i].model_error = res.model_error[b];
					sum[i].seconds += res.seconds[b];
					if (!(res.error[b] <= tol)) ++short_of_tol;
				}
		mkCSpaceResult_Free(&res);
	}
	if (open_r) {
		char rm[2][96];
		for (int k = 0; k < 1 + outer; ++k) {
			double e = 0.0;
			if (scene.dim == 2) {
				mkBody2 m;
				mkSceneBody2_Model(&scene.robot, 0.25 * tol, (mkBound)k, &m, &e, msg, sizeof msg);
				if (scene.robot.kind == MK_SCENE_SMOOTH) snprintf(rm[k], sizeof rm[k], "%s", mkSceneBody_KindName(&scene.robot));
				else snprintf(rm[k], sizeof rm[k], "%s eps=%.6g", mkShape2_IsEllipse(m.shape) ? "ellipse" : "superellipse", m.shape.eps);
			} else {
				mkBody3 m;
				mkSceneBody3_Model(&scene.robot, 0.25 * tol, (mkBound)k, &m, &e, msg, sizeof msg);
				if (scene.robot.kind == MK_SCENE_SMOOTH) snprintf(rm[k], sizeof rm[k], "%s", mkSceneBody_KindName(&scene.robot));
				else snprintf(rm[k], sizeof rm[k], "%s eps1=%.6g eps2=%.6g", mkShape3_IsEllipsoid(m.shape) ? "ellipsoid" : "superquadric",
					m.shape.eps1, m.shape.eps2);
			}
		}
		fprintf(fr.fp, "obstacle,declared,model,model_error,points,certified_error,seconds\n");
		char both[256];
		if (outer && scene.robot.kind != MK_SCENE_SMOOTH) snprintf(both, sizeof both, "inner %s; outer %s", rm[0], rm[1]);
		else snprintf(both, sizeof both, "%s", rm[0]);
		fprintf(fr.fp, "robot,%s,\"%s\",,,,\n", mkSceneBody_KindName(&scene.robot), both);
		for (int i = 0; i < nob; ++i)
			fprintf(fr.fp, "%d,%s,\"%s\",%.6g,%ld,%.6g,%.6f\n", i, mkSceneBody_KindName(&scene.obstacles[i]),
				sum[i].model, sum[i].model_error, sum[i].points, sum[i].error, sum[i].seconds);
	}
	mkOutFile *all[3];
	int na = 0;
	all[na++] = &fo;
	if (open_f) all[na++] = &ff;
	if (open_r) all[na++] = &fr;
	if (mkOutFile_CommitAll(all, na, msg, sizeof msg)) { fprintf(stderr, "mink scene: %s\n", msg); open_o = open_f = open_r = 0; goto done; }
	open_o = open_f = open_r = 0;
	rc = 0;
	if (short_of_tol) {
		fprintf(stderr, "mink scene: warning: %d boundaries are not certified within --tol %g (point cap or "
			"normals closer than 1e-12 rad): see their certified_error in the report\n", short_of_tol, tol);
		rc = 1;
	}
done:
	if (open_o) mkOutFile_Discard(&fo);
	if (open_f) mkOutFile_Discard(&ff);
	if (open_r) mkOutFile_Discard(&fr);
	free(sum);
	mkScene_Free(&scene);
	return rc;
}
