/* cspace.c - the scene API of mink/cobstacle.h: options, a scene prepared
 * once (its checked options, every body's model, error and name, the paper
 * mode's parameters), and the accessors of a run's result. The runs
 * themselves are in run.c. */
#include "cspace/work.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/message.h"

mkCSpaceOptions mkCSpaceOptions_Default(void)
{
	mkCSpaceOptions o;
	memset(&o, 0, sizeof o);
	o.tol = 1e-3;
	o.mode = MK_CSPACE_ADAPTIVE;
	o.uniform = 0;
	o.threads = 1;
	o.store = 1;
	o.max_points = 1000000;
	o.form = MK_FORM_GRADIENT;
	o.impl = MK_IMPL_AUTO;
	return o;
}

/* The options against the scene's dimension: MK_OK or the failure, with a message. */
static mkResult mkCSpace_CheckOptions(int dim, const mkCSpaceOptions *opt, char *msg, size_t msglen)
{
	if (!(opt->tol > 0.0) || !isfinite(opt->tol))
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "tolerance = %g is out of range: must be a positive finite number", opt->tol);
	if (opt->threads < 1 || opt->threads > 1024)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "threads = %d is out of range: must be in [1, 1024]", opt->threads);
	if (opt->max_points < 8)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "max_points = %d is out of range: must be at least 8", opt->max_points);
	if (opt->mode == MK_CSPACE_UNIFORM
		&& (dim == 2 ? opt->uniform < 4 : (opt->uniform < 0 || opt->uniform > MK_CSPACE_MAX_SPLITS)))
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "uniform = %d is out of range: must be %s", opt->uniform,
			dim == 2 ? "at least 4 normals" : "0..10 splits");
	if (opt->mode == MK_CSPACE_PAPER) {
		if (dim == 2 ? opt->uniform < 1 : (opt->uniform < 2 || opt->uniform > 46340))
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "uniform = %d is out of range for the paper's sampling", opt->uniform);
		if (opt->outer) return mkFail(MK_ERR_UNSUPPORTED, msg, msglen, "the paper's sampling gives no outer bound");
		if (opt->form != MK_FORM_NORMAL && opt->form != MK_FORM_GRADIENT)
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "form must be normal or gradient");
	} else if (opt->mode != MK_CSPACE_ADAPTIVE && opt->mode != MK_CSPACE_UNIFORM) {
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "unknown mode %d", (int)opt->mode);
	}
	if (!mkImpl_Available(opt->impl))
		return mkFail(MK_ERR_UNSUPPORTED, msg, msglen, "kernel %s is not available", mkImpl_Name(opt->impl));
	return MK_OK;
}

/* A body's model as text: its kind when it is its own model, else the model's shape. */
static void mkCSpace_Describe(const mkCSpace *cs, const mkSceneBody *d, int slot, char *buf, size_t len)
{
	if (d->kind == MK_SCENE_SMOOTH) {
		snprintf(buf, len, "%s", mkSceneBody_KindName(d));
	} else if (cs->dim == 2) {
		mkShape2 m = slot < 0 ? cs->part2[-1 - slot].shape : cs->obs2[slot].shape;
		snprintf(buf, len, "%s eps=%.6g", mkShape2_IsEllipse(m) ? "ellipse" : "superellipse", m.eps);
	} else {
		mkShape3 m = slot < 0 ? cs->part3[-1 - slot].shape : cs->obs3[slot].shape;
		snprintf(buf, len, "%s eps1=%.6g eps2=%.6g", mkShape3_IsEllipsoid(m) ? "ellipsoid" : "superquadric", m.eps1,
			m.eps2);
	}
}

/* The name of body i (-1 - j: robot part j), both bounds' models when there are two. */
static void mkCSpace_Name(const mkCSpace *cs, int i, char *buf, size_t len)
{
	const mkSceneBody *d = i < 0 ? &cs->part_body[-1 - i] : &cs->scene->obstacles[i];
	char a[56], b[56] = "";
	mkCSpace_Describe(cs, d, i < 0 ? -1 - 2 * (-1 - i) : 2 * i, a, sizeof a);
	if (cs->bounds == 2) mkCSpace_Describe(cs, d, i < 0 ? -2 - 2 * (-1 - i) : 2 * i + 1, b, sizeof b);
	if (cs->bounds == 2 && d->kind != MK_SCENE_SMOOTH) snprintf(buf, len, "inner %s; outer %s", a, b);
	else snprintf(buf, len, "%s", a);
}

/* Every body's model for both bounds: each box or cylinder gets a budget
 * of T/4 (see the header). */
static mkResult mkCSpace_Model(mkCSpace *cs, char *msg, size_t msglen)
{
	const mkScene *scene = cs->scene;
	double budget = 0.25 * cs->opt.tol;
	char sub[512];
	for (int k = 0; k < cs->bounds; ++k) {
		mkResult r = MK_OK;
		for (int j = 0; j < cs->parts && r == MK_OK; ++j) {
			int q = 2 * j + k;
			r = cs->dim == 2
				? mkSceneBody2_Model(&cs->part_body[j], budget, (mkBound)k, &cs->part2[q], &cs->part_err[q], sub, sizeof sub)
				: mkSceneBody3_Model(&cs->part_body[j], budget, (mkBound)k, &cs->part3[q], &cs->part_err[q], sub, sizeof sub);
			if (r != MK_OK && cs->parts > 1) return mkFail(r, msg, msglen, "part %d: %s", j, sub);
		}
		if (r == MK_OK && scene->part_count == 0) { /* a hand-built scene's robot: its at= unused */
			if (cs->dim == 2) cs->part2[k].t = mkVec2_Make(0.0, 0.0);
			else cs->part3[k].t = mkVec3_Make(0.0, 0.0, 0.0);
		}
		if (r != MK_OK) return mkFail(r, msg, msglen, "robot: %s", sub);
		if (cs->dim == 2) cs->robot2[k] = cs->part2[k];
		else cs->robot3[k] = cs->part3[k];
		cs->robot_err[k] = cs->part_err[k];
		for (int i = 0; i < cs->nob; ++i) {
			r = cs->dim == 2 ? mkSceneBody2_Model(&scene->obstacles[i], budget, (mkBound)k, &cs->obs2[2 * i + k],
					&cs->obs_err[2 * i + k], sub, sizeof sub)
				: mkSceneBody3_Model(&scene->obstacles[i], budget, (mkBound)k, &cs->obs3[2 * i + k],
					&cs->obs_err[2 * i + k], sub, sizeof sub);
			if (r != MK_OK) return mkFail(r, msg, msglen, "obstacle %d: %s", i, sub);
		}
	}
	for (int j = 0; j < cs->parts; ++j) mkCSpace_Name(cs, -1 - j, cs->part_name[j], sizeof cs->part_name[j]);
	snprintf(cs->robot_name, sizeof cs->robot_name, "%s", cs->part_name[0]);
	for (int i = 0; i < cs->nob; ++i) mkCSpace_Name(cs, i, cs->model_name[i], sizeof cs->model_name[i]);
	return MK_OK;
}

/* Paper mode: B1's surface parameters, the same for every task. */
static mkResult mkCSpace_PaperSamples(mkCSpace *cs)
{
	int n = cs->opt.uniform;
	long np = cs->dim == 2 ? n : (long)n * n;
	cs->paper_n = n;
	for (int d = 0; d < cs->dim; ++d)
		if (!(cs->paper_u[d] = malloc((size_t)np * sizeof(double)))) return MK_ERR_MEMORY;
	if (cs->dim == 2) mkSample2_Angles(n, cs->paper_u[0], cs->paper_u[1]);
	else mkSample3_Grid(n, cs->paper_u[0], cs->paper_u[1], cs->paper_u[2]);
	return MK_OK;
}

mkResult mkCSpace_Create(const mkScene *scene, const mkCSpaceOptions *opt, mkCSpace **out, char *msg, size_t msglen)
{
	if (!out) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "no result");
	*out = NULL;
	if (!scene || !opt || (scene->dim != 2 && scene->dim != 3) || (scene->part_count > 0 && !scene->parts))
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "no scene or options");
	mkResult r = mkCSpace_CheckOptions(scene->dim, opt, msg, msglen);
	if (r != MK_OK) return r;
	if (opt->mode == MK_CSPACE_PAPER && scene->part_count > 1)
		return mkFail(MK_ERR_UNSUPPORTED, msg, msglen, "the paper's sampling takes a robot of one body, not %d parts",
			scene->part_count);
	mkCSpace *cs = calloc(1, sizeof *cs);
	if (!cs) return mkFail(MK_ERR_MEMORY, msg, msglen, "out of memory");
	cs->scene = scene;
	cs->opt = *opt;
	cs->dim = scene->dim;
	cs->nob = scene->obstacle_count;
	cs->bounds = opt->outer ? 2 : 1;
	cs->parts = scene->part_count > 0 ? scene->part_count : 1;
	cs->part_body = scene->part_count > 0 ? scene->parts : &scene->robot;
	size_t nm = (size_t)(2 * cs->nob + 1), np = (size_t)(2 * cs->parts);
	cs->obs_err = calloc(nm, sizeof(double));
	cs->part_err = calloc(np, sizeof(double));
	if (cs->dim == 2) { cs->obs2 = calloc(nm, sizeof(mkBody2)); cs->part2 = calloc(np, sizeof(mkBody2)); }
	else { cs->obs3 = calloc(nm, sizeof(mkBody3)); cs->part3 = calloc(np, sizeof(mkBody3)); }
	cs->model_name = calloc((size_t)cs->nob + 1, sizeof *cs->model_name);
	cs->part_name = calloc((size_t)cs->parts, sizeof *cs->part_name);
	if (!cs->obs_err || !cs->part_err || (!cs->obs2 && !cs->obs3) || (!cs->part2 && !cs->part3) || !cs->model_name
		|| !cs->part_name)
		r = MK_ERR_MEMORY;
	else r = mkCSpace_Model(cs, msg, msglen);
	if (r == MK_OK && opt->mode == MK_CSPACE_PAPER) r = mkCSpace_PaperSamples(cs);
	if (r != MK_OK) {
		if (r == MK_ERR_MEMORY) mkFail(r, msg, msglen, "out of memory");
		mkCSpace_Destroy(cs);
		return r;
	}
	*out = cs;
	return MK_OK;
}

void mkCSpace_Destroy(mkCSpace *cs)
{
	if (!cs) return;
	free(cs->obs_err); free(cs->obs2); free(cs->obs3); free(cs->model_name);
	free(cs->part_err); free(cs->part2); free(cs->part3); free(cs->part_name);
	for (int d = 0; d < 3; ++d) free(cs->paper_u[d]);
	free(cs);
}

const mkCSpaceOptions *mkCSpace_Options(const mkCSpace *cs) { return &cs->opt; }

const char *mkCSpace_ModelName(const mkCSpace *cs, int body)
{
	if (!cs || body < -cs->parts || body >= cs->nob) return "?";
	return body < 0 ? cs->part_name[-1 - body] : cs->model_name[body];
}

/* ---- results ---- */

void mkCSpaceResult_Free(mkCSpaceResult *r)
{
	if (!r) return;
	long nb = (long)r->obstacles * r->orientations * r->parts * r->bounds;
	for (long b = 0; r->points && b < nb; ++b) free(r->points[b]);
	for (long b = 0; r->faces && b < nb; ++b) free(r->faces[b]);
	free(r->count); free(r->error); free(r->model_error); free(r->seconds); free(r->checksum);
	free(r->points); free(r->faces); free(r->face_count);
	memset(r, 0, sizeof *r);
}

double mkCSpaceResult_MaxError(const mkCSpaceResult *r)
{
	double m = 0.0;
	long nb = (long)r->obstacles * r->orientations * r->parts * r->bounds;
	for (long b = 0; b < nb; ++b) {
		if (r->error[b] != r->error[b]) return NAN;
		if (r->error[b] > m) m = r->error[b];
	}
	return m;
}

long mkCSpaceResult_OverTolerance(const mkCSpaceResult *r)
{
	long n = 0, nb = (long)r->obstacles * r->orientations * r->parts * r->bounds;
	for (long b = 0; b < nb; ++b) n += !(r->error[b] <= r->tol);
	return n;
}

mkCSpaceBoundary mkCSpaceResult_Boundary(const mkCSpaceResult *r, int o, int i, mkBound k)
{
	return mkCSpaceResult_PartBoundary(r, o, i, 0, k);
}

mkCSpaceBoundary mkCSpaceResult_PartBoundary(const mkCSpaceResult *r, int o, int i, int part, mkBound k)
{
	return mkCSpaceResult_At(r, (((long)(o - r->orientation_begin) * r->obstacles + i) * r->parts + part) * r->bounds + (int)k);
}

mkCSpaceBoundary mkCSpaceResult_At(const mkCSpaceResult *r, long b)
{
	mkCSpaceBoundary v;
	memset(&v, 0, sizeof v);
	v.count = r->count[b];
	v.error = r->error[b];
	v.model_error = r->model_error[b];
	v.seconds = r->seconds[b];
	v.checksum = r->checksum[b];
	v.within_tol = r->error[b] <= r->tol;
	const double *p = r->points ? r->points[b] : NULL;
	if (p) {
		v.stride = r->interleaved ? r->dim : 1;
		long step = r->interleaved ? 1 : v.count;
		v.x = p;
		v.y = p + step;
		v.z = r->dim == 3 ? p + 2 * step : NULL;
	}
	if (r->faces) {
		v.face_count = r->face_count[b];
		v.faces = r->faces[b];
	}
	return v;
}
