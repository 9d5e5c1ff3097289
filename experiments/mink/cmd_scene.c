/* cmd_scene.c - `mink scene`: the certified C-obstacles of a scene file
 * (mink/cobstacle.h) as CSV, with a report per obstacle. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/cspace.h>
#include <mink_exp/args.h>
#include <mink_exp/outfile.h>
#include <mink_exp/shard.h>

#include "cli.h"
#include "commands.h"
#include "scenefile.h"

#define SCENE_FILE_MAX (1L << 30)
#define THREADS_MAX 256
/* --max-points: the default cap on a run's estimated points (about 1.4 GB
 * of output in 3D with faces, 0.6 GB in 2D) */
#define SCENE_POINTS_DEFAULT 1e7

static void mkSceneCmd_Help(FILE *fp)
{
	fprintf(fp,
		"usage: mink scene FILE --tol T --out PATH [options]\n"
		"\n"
		"Configuration-space obstacles of the scene in FILE: for every robot orientation\n"
		"and obstacle, an inner boundary (inside the C-obstacle) and with --outer an outer\n"
		"one (enclosing it), each within Hausdorff distance T of the C-obstacle of the\n"
		"declared shapes (model error of boxes and cylinders included), with normals\n"
		"placed adaptively where the curvature needs them. See docs/scene.md.\n"
		"\n"
		"Scene file:\n"
		"  # comment\n"
		"  dim 2|3                              first line\n"
		"  robot SPEC                           once; its at= is ignored\n"
		"  part SPEC                            instead of robot: a part of a robot of several\n"
		"                                       bodies, its pose (at=, rot/quat/M) in the robot's frame\n"
		"  object NAME                          the obstacle lines that follow form object NAME\n"
		"  obstacle SPEC                        any number; indices 0, 1, ... in order\n"
		"  headings N | headings a1,a2,...      2D: angles 2 pi k / N, or these radians\n"
		"  quaternions w,x,y,z;w,x,y,z;...      3D orientations\n"
		"  rotations FILE                       3D: one rotation per line, r11,...,r33 or\n"
		"                                       w,x,y,z (relative to the scene's folder)\n"
		"SPEC as in 'mink sum' (circle, ellipse, superellipse, sphere, ellipsoid,\n"
		"superquadric) plus 'box size=l,w[,h]' and 'cylinder r=R h=H' (axis z), with the\n"
		"pose keys rot, shear (2D), quat (3D), M, at. The robot at heading a (rotation R)\n"
		"is the body with map R M. With parts or objects the rows end with part,object:\n"
		"the C-obstacle of an object is the union of its rows' boundaries.\n\n");
}

static char *mkSceneCmd_ReadFile(const char *path, long *len, char *msg, size_t msglen)
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
static void mkSceneCmd_FacesPath(const char *out, char *buf, size_t len)
{
	size_t n = strlen(out);
	if (n > 4 && strcmp(out + n - 4, ".csv") == 0) snprintf(buf, len, "%.*s.faces.csv", (int)(n - 4), out);
	else snprintf(buf, len, "%s.faces.csv", out);
}

typedef struct mkSceneCmdSum {
	long points;
	double error, model_error, seconds;
} mkSceneCmdSum;

/* The run: the scene, its options, the prepared scene and the open output files. */
typedef struct mkSceneCmd {
	const char *file, *out, *report;
	mkScene scene;
	mkCSpaceOptions o;
	mkCSpace *cs;
	mkOutFile f[3];   /* points, faces (3D), report */
	int open[3];
	mkSceneCmdSum *sum;
	long short_of_tol;
	int unions;       /* parts or objects: the rows end with part,object */
	double max_points;   /* cap on the estimated points of the run */
} mkSceneCmd;

/* 1 when the scene has a robot of several parts or `object` lines. */
static int mkSceneCmd_Unions(const mkScene *s)
{
	if (s->part_count > 1) return 1;
	for (int k = 0; k < s->object_count; ++k)
		if (s->objects[k].line > 0) return 1;
	return 0;
}

int mkSceneCmd_LoadFile(const char *cmd, const char *file, mkScene *scene)
{
	char msg[2048];
	long len = 0;
	char *text = mkSceneCmd_ReadFile(file, &len, msg, sizeof msg);
	if (!text) { fprintf(stderr, "mink %s: %s\n", cmd, msg); return 2; }
	mkResult r = mkScene_Parse(text, scene, msg, sizeof msg);
	free(text);
	if (r != MK_OK) { fprintf(stderr, "mink %s: %s: %s\n", cmd, file, msg); return 2; }
	if (!scene->rotations_file[0])
		return 0;
	char path[MK_PATH_MAX];
	const char *slash = strrchr(file, '/');
	if (scene->rotations_file[0] != '/' && slash)
		snprintf(path, sizeof path, "%.*s/%s", (int)(slash - file), file, scene->rotations_file);
	else
		snprintf(path, sizeof path, "%s", scene->rotations_file);
	char *rt = mkSceneCmd_ReadFile(path, &len, msg, sizeof msg);
	r = rt ? mkScene_SetRotations(scene, rt, path, msg, sizeof msg) : MK_ERR_ARGUMENT;
	free(rt);
	if (r != MK_OK) {
		fprintf(stderr, "mink %s: %s: line %d: rotations: %s\n", cmd, file, scene->rotations_line, msg);
		return 2;
	}
	return 0;
}

/* Prepare the scene (its models: a tolerance too small for a box fails
 * here), before any file exists. */
static int mkSceneCmd_Prepare(mkSceneCmd *s)
{
	char msg[2048];
	if (mkCSpace_Create(&s->scene, &s->o, &s->cs, msg, sizeof msg) != MK_OK) {
		fprintf(stderr, "mink scene: %s: %s\n", s->file, msg);
		return 2;
	}
	s->sum = calloc((size_t)s->scene.obstacle_count + 1, sizeof *s->sum);
	if (!s->sum) { fprintf(stderr, "mink scene: out of memory\n"); return 1; }
	return 0;
}

/* Estimate the run's points, output bytes and memory (mkCSpace_Estimate)
 * and refuse it beyond --max-points. Returns 0, or 2 after printing. */
static int mkSceneCmd_Estimate(mkSceneCmd *s, long begin, long end)
{
	char msg[2048];
	mkCSpaceEstimate e;
	if (mkCSpace_Estimate(s->cs, (int)begin, (int)end, &e, msg, sizeof msg) != MK_OK) {
		fprintf(stderr, "mink scene: %s\n", msg);
		return 1;
	}
	if (e.points <= s->max_points)
		return 0;
	/* bytes per row: the indices, the kind and %.17g numbers (~22 bytes
	 * each); memory: a thread's scratch space per point of the largest
	 * boundary (3D about 1000 bytes: normals, points, triangles, edge
	 * hashes, the outer polytope; 0.96 GB a thread was measured at 10^6
	 * points with --outer; 2D about 100) and the finished boundaries it
	 * may hold */
	int dim = s->scene.dim, bounds = s->o.outer ? 2 : 1;
	double bytes = e.points * (dim == 3 ? 81.0 : 59.0) + e.faces * 32.0;
	double held = (dim == 3 ? 1000.0 : 100.0) + MK_CSPACE_WINDOW * bounds * (dim == 3 ? 48.0 : 16.0);
	double memory = s->o.threads * e.largest * held;
	fprintf(stderr, "mink scene: %s: the run would compute about %.3g points (largest boundary %.3g), write "
		"about %.3g MB and hold about %.3g MB: more than --max-points %.6g allows; raise --max-points to run "
		"it anyway, or raise --tol\n", s->file, e.points, e.largest, bytes / 1e6, memory / 1e6, s->max_points);
	return 2;
}

static int mkSceneCmd_OpenOutputs(mkSceneCmd *s)
{
	char msg[2048], fpath[MK_PATH_MAX];
	mkSceneCmd_FacesPath(s->out, fpath, sizeof fpath);
	const char *paths[3] = { s->out, s->scene.dim == 3 ? fpath : NULL, s->report };
	for (int k = 0; k < 3; ++k) {
		if (!paths[k])
			continue;
		if (mkOutFile_Open(&s->f[k], paths[k], msg, sizeof msg)) {
			fprintf(stderr, "mink scene: %s: %s\n", paths[k], msg);
			return 1;
		}
		s->open[k] = 1;
	}
	s->unions = mkSceneCmd_Unions(&s->scene);
	const char *tail = s->unions ? ",part,object" : "";
	fprintf(s->f[0].fp, "obstacle,orientation,kind,k,x,y%s%s\n", s->scene.dim == 3 ? ",z" : "", tail);
	if (s->open[1])
		fprintf(s->f[1].fp, "obstacle,orientation,kind,f,i,j,k%s\n", tail);
	return 0;
}

/* The sink of mkCSpace_Stream: one boundary's rows (obstacle i, robot part
 * j), in the run's order; with parts or objects the rows end with
 * ",part,object". */
static int mkSceneCmd_Write(void *user, int ori, int i, int j, mkBound k, const mkCSpaceBoundary *b)
{
	static const char *const kinds[] = {"inner", "outer"};
	mkSceneCmd *s = user;
	FILE *fo = s->f[0].fp, *ff = s->open[1] ? s->f[1].fp : NULL;
	char tail[MK_SCENE_NAME_MAX + 32] = "";
	if (s->unions)
		snprintf(tail, sizeof tail, ",%d,%s", j, s->scene.objects[s->scene.obstacle_object[i]].name);
	for (int n = 0; n < b->count; ++n) {
		long q = (long)n * b->stride;
		if (s->scene.dim == 2)
			fprintf(fo, "%d,%d,%s,%d,%.17g,%.17g%s\n", i, ori, kinds[k], n, b->x[q], b->y[q], tail);
		else
			fprintf(fo, "%d,%d,%s,%d,%.17g,%.17g,%.17g%s\n", i, ori, kinds[k], n, b->x[q], b->y[q], b->z[q], tail);
	}
	for (int f = 0; ff && f < b->face_count; ++f)
		fprintf(ff, "%d,%d,%s,%d,%d,%d,%d%s\n", i, ori, kinds[k], f, b->faces[3 * f], b->faces[3 * f + 1],
			b->faces[3 * f + 2], tail);
	mkSceneCmdSum *sum = &s->sum[i];
	sum->points += b->count;
	sum->error = fmax(sum->error, b->error);
	sum->model_error = fmax(sum->model_error, b->model_error);
	sum->seconds += b->seconds;
	s->short_of_tol += !b->within_tol;
	/* a full disk stops the run at once */
	return ferror(fo) || (ff && ferror(ff));
}

static void mkSceneCmd_WriteReport(const mkSceneCmd *s)
{
	FILE *fr = s->f[2].fp;
	fprintf(fr, "obstacle,declared,model,model_error,points,certified_error,seconds\n");
	if (s->scene.part_count <= 1)
		fprintf(fr, "robot,%s,\"%s\",,,,\n", mkSceneBody_KindName(&s->scene.robot), mkCSpace_ModelName(s->cs, -1));
	for (int j = 0; s->scene.part_count > 1 && j < s->scene.part_count; ++j)
		fprintf(fr, "part%d,%s,\"%s\",,,,\n", j, mkSceneBody_KindName(&s->scene.parts[j]),
			mkCSpace_ModelName(s->cs, -1 - j));
	for (int i = 0; i < s->scene.obstacle_count; ++i)
		fprintf(fr, "%d,%s,\"%s\",%.6g,%ld,%.6g,%.6f\n", i, mkSceneBody_KindName(&s->scene.obstacles[i]),
			mkCSpace_ModelName(s->cs, i), s->sum[i].model_error, s->sum[i].points, s->sum[i].error, s->sum[i].seconds);
}

/* Compute the orientations [begin, end), each boundary written as soon as
 * it and those before it are finished (mkCSpace_Stream: memory bounded by
 * what the threads hold), and commit everything. Returns 0, or 1 after
 * printing. */
static int mkSceneCmd_Compute(mkSceneCmd *s, long begin, long end)
{
	char msg[2048];
	if (mkCSpace_Stream(s->cs, (int)begin, (int)end, mkSceneCmd_Write, s, msg, sizeof msg) != MK_OK) {
		fprintf(stderr, "mink scene: %s%s\n", msg, ferror(s->f[0].fp) || (s->open[1] && ferror(s->f[1].fp))
			? " (write error on the output)" : "");
		return 1;
	}
	if (s->open[2])
		mkSceneCmd_WriteReport(s);
	mkOutFile *all[3];
	int na = 0;
	for (int k = 0; k < 3; ++k)
		if (s->open[k])
			all[na++] = &s->f[k];
	int failed = mkOutFile_CommitAll(all, na, msg, sizeof msg) != 0;
	s->open[0] = s->open[1] = s->open[2] = 0;
	if (failed) {
		fprintf(stderr, "mink scene: %s\n", msg);
		return 1;
	}
	return 0;
}

int mkCmd_Scene(int argc, char **argv)
{
	mkSceneCmd s;
	memset(&s, 0, sizeof s);
	s.o = mkCSpaceOptions_Default();
	s.o.interleaved = 1; /* the rows' order */
	s.max_points = SCENE_POINTS_DEFAULT;
	for (int k = 0; k < 3; ++k)
		s.f[k].slot = -1;
	long threads = 1;
	int impl = MK_IMPL_AUTO;
	mkShard shard = mkShard_All();
	/* FILE comes first; the options after it */
	int first = argc > 1 && strncmp(argv[1], "--", 2) != 0 && strcmp(argv[1], "-h") != 0;
	s.file = first ? argv[1] : NULL;
	mkFlag flags[] = {
		MK_FLAG_DOUBLE("--tol", "T", "the tolerance, in the scene's length unit (required)", &s.o.tol, 1e-12, 1e12),
		MK_FLAG_PATH("--out", "PATH", "CSV obstacle,orientation,kind,k,x,y[,z] (kind inner or outer; 2D\n"
			"counter-clockwise); 3D faces go to PATH with .csv replaced by .faces.csv:\n"
			"obstacle,orientation,kind,f,i,j,k. Written atomically (required)", &s.out),
		MK_FLAG_PATH("--report", "PATH", "CSV per obstacle: model, model error, points, certified error,\n"
			"seconds (and a robot row, or one row per part)", &s.report),
		MK_FLAG_SWITCH("--outer", "also the outer boundaries", &s.o.outer),
		MK_FLAG_LONG("--threads", "K", "worker threads (default 1); the output does not depend on K", &threads, 1,
			THREADS_MAX),
		MK_FLAG_DOUBLE("--max-points", "N", "refuse a run whose estimated points exceed N (default 1e7),\n"
			"before it starts, with the estimate of its points, output and memory", &s.max_points, 8, 1e15),
		MK_FLAG_TEXT("--shard", "I/N", "only block I (0-based) of N of the orientations; the shards'\n"
			"rows concatenated in order (one header) equal the whole run's", &shard, mkShard_ParseFlag),
		MK_FLAG_IMPL("--impl", "kernel (default auto)", &impl),
	};
	int rc = mkCli_Parse("scene", flags, MK_COUNT(flags), argc - first, argv + first, mkSceneCmd_Help);
	if (rc != MK_CLI_GO)
		return rc;
	if (!s.file) { fprintf(stderr, "mink scene: no scene FILE given (usage: mink scene FILE --tol T --out PATH)\n"); return 2; }
	if ((rc = mkCli_Require("scene", &flags[0])) != MK_CLI_GO || (rc = mkCli_Require("scene", &flags[1])) != MK_CLI_GO)
		return rc;
	rc = mkSceneCmd_LoadFile("scene", s.file, &s.scene);
	if (rc == 0) {
		s.o.threads = (int)threads;
		s.o.impl = (mkImpl)impl;
		long begin, end;
		mkShard_Range(shard, s.scene.orientation_count, &begin, &end);
		rc = mkSceneCmd_Prepare(&s);
		if (rc == 0)
			rc = mkSceneCmd_Estimate(&s, begin, end);
		if (rc == 0)
			rc = mkSceneCmd_OpenOutputs(&s);
		if (rc == 0)
			rc = mkSceneCmd_Compute(&s, begin, end);
	}
	if (rc == 0 && s.short_of_tol) {
		fprintf(stderr, "mink scene: warning: %ld boundaries are not certified within --tol %g (point cap or "
			"normals closer than 1e-12 rad): see their certified_error in the report\n", s.short_of_tol, s.o.tol);
		rc = 1;
	}
	for (int k = 0; k < 3; ++k)
		if (s.open[k])
			mkOutFile_Discard(&s.f[k]);
	free(s.sum);
	mkCSpace_Destroy(s.cs);
	mkScene_Free(&s.scene);
	return rc;
}
