/* scene.c - mink.scene: certified C-obstacles of a scene (libmink_cspace).
 * The boundaries' arrays are views of the C result's memory, which lives
 * as long as any of them (a capsule is their base). */
#include "mkpy.h"

#include <math.h>
#include <string.h>

#include <mink/cspace.h>

static PyTypeObject mkPy_BoundaryType;

static PyStructSequence_Field mkPy_BoundaryFields[] = {
	{"orientation", "the scene orientation (index of its heading or rotation)"},
	{"obstacle", "the obstacle's index, in the scene's order"},
	{"bound", "'inner' (points on the C-obstacle's boundary) or 'outer' (a boundary enclosing it)"},
	{"points", "ndarray (dim, count) float64: the boundary's points, counter-clockwise in 2D"},
	{"faces", "3D: ndarray (F, 3) int32 of point indices, counter-clockwise seen from outside; 2D: None"},
	{"error", "certified Hausdorff bound to the C-obstacle, model error included (NaN in paper mode)"},
	{"model_error", "the part of error from modelling boxes and cylinders"},
	{"seconds", "wall time of the (orientation, obstacle) task"},
	{"within_tol", "error <= tol"},
	{"model", "the obstacle's model, e.g. 'ellipse' or 'superellipse eps=0.0834'"},
	{NULL, NULL}};
static PyStructSequence_Desc mkPy_BoundaryDesc = {"mink.Boundary", "One C-obstacle boundary of mink.scene.",
	mkPy_BoundaryFields, 10};

int mkPy_SceneTypesReady(PyObject *module)
{
	if (PyStructSequence_InitType2(&mkPy_BoundaryType, &mkPy_BoundaryDesc) < 0) return -1;
	Py_INCREF(&mkPy_BoundaryType);
	if (PyModule_AddObject(module, "Boundary", (PyObject *)&mkPy_BoundaryType) < 0) {
		Py_DECREF(&mkPy_BoundaryType);
		return -1;
	}
	return 0;
}

static void mkPy_ResultRelease(PyObject *capsule)
{
	mkCSpaceResult *r = PyCapsule_GetPointer(capsule, "mink.CSpaceResult");
	if (!r) return;
	mkCSpaceResult_Free(r);
	PyMem_Free(r);
}

/* A view of C memory owned by the capsule. */
static PyObject *mkPy_View(PyObject *capsule, int nd, npy_intp *dims, int type, const void *data)
{
	PyObject *a = PyArray_New(&PyArray_Type, nd, dims, type, NULL, (void *)data, 0, NPY_ARRAY_CARRAY_RO, NULL);
	if (!a) return NULL;
	Py_INCREF(capsule);
	if (PyArray_SetBaseObject((PyArrayObject *)a, capsule) < 0) {
		Py_DECREF(a);
		return NULL;
	}
	return a;
}

/* The list of Boundary of a run. */
static PyObject *mkPy_Boundaries(const mkCSpace *cs, mkCSpaceResult *res, PyObject *capsule)
{
	PyObject *list = PyList_New(0);
	static const double empty[1] = {0};
	for (int o = 0; list && o < res->orientations; ++o)
		for (int i = 0; list && i < res->obstacles; ++i)
			for (int k = 0; list && k < res->bounds; ++k) {
				int so = res->orientation_begin + o;
				mkCSpaceBoundary b = mkCSpaceResult_Boundary(res, so, i, (mkBound)k);
				npy_intp pd[2] = {res->dim, b.count}, fd[2] = {b.face_count, 3};
				PyObject *pts = mkPy_View(capsule, 2, pd, NPY_DOUBLE, b.x ? (const void *)b.x : empty);
				PyObject *faces = res->dim == 3 && pts
					? mkPy_View(capsule, 2, fd, NPY_INT32, b.faces ? (const void *)b.faces : empty) : (Py_INCREF(Py_None), Py_None);
				PyObject *e = pts && faces ? PyStructSequence_New(&mkPy_BoundaryType) : NULL;
				if (e) {
					PyObject *v[10] = {PyLong_FromLong(so), PyLong_FromLong(i),
						PyUnicode_FromString(k ? "outer" : "inner"), pts, faces, PyFloat_FromDouble(b.error),
						PyFloat_FromDouble(b.model_error), PyFloat_FromDouble(b.seconds),
						PyBool_FromLong(b.within_tol), PyUnicode_FromString(mkCSpace_ModelName(cs, i))};
					pts = faces = NULL;
					for (int j = 0; j < 10; ++j) {
						if (!v[j]) Py_CLEAR(e);
						if (e) PyStructSequence_SET_ITEM(e, j, v[j]);
						else Py_XDECREF(v[j]);
					}
				}
				Py_XDECREF(pts);
				Py_XDECREF(faces);
				if (!e || PyList_Append(list, e) < 0) Py_CLEAR(list);
				Py_XDECREF(e);
			}
	return list;
}

const char mkPy_SceneDoc[] =
	"scene(text, *, tol=1e-3, outer=False, mode='adaptive', uniform=0, threads=1,\n"
	"      max_points=1000000, orientations=None, rotations=None) -> list of Boundary\n\n"
	"Certified C-obstacles of a scene (the scene file format of docs/scene.md, given as text):\n"
	"for each orientation and obstacle the inner boundary (points on the C-obstacle) and, with\n"
	"outer=True, an enclosing one, each with its certified Hausdorff bound. mode: 'adaptive'\n"
	"(points placed until the bound is at most tol), 'uniform' (uniform normals: 2D\n"
	"`uniform` >= 4 normals, 3D 0..10 splits of the octahedron). orientations: a range\n"
	"(begin, end) of the scene's orientations, default all. rotations: the text of the\n"
	"rotations file a 3D scene names (mink.scene_file reads it for you). Errors name the line.\n"
	"The GIL is released while the C-obstacles are computed on `threads` threads.";

/* Parse the scene and its rotations; 0 or -1 with ValueError. */
static int mkPy_SceneParse(const char *text, const char *rotations, mkScene *scene, char *msg, size_t msglen)
{
	if (mkScene_Parse(text, scene, msg, msglen) != MK_OK) {
		PyErr_Format(PyExc_ValueError, "scene: %s", msg);
		return -1;
	}
	if (scene->rotations_file[0] && !rotations) {
		PyErr_Format(PyExc_ValueError, "scene: line %d: rotations %s: pass the file's text as rotations= "
			"(mink.scene_file reads it)", scene->rotations_line, scene->rotations_file);
		return -1;
	}
	if (rotations && mkScene_SetRotations(scene, rotations, "rotations", msg, msglen) != MK_OK) {
		PyErr_Format(PyExc_ValueError, "rotations: %s", msg);
		return -1;
	}
	return 0;
}

PyObject *mkPy_Scene(PyObject *self, PyObject *args, PyObject *kw)
{
	(void)self;
	static char *kwlist[] = {"text", "tol", "outer", "mode", "uniform", "threads", "max_points", "orientations",
		"rotations", NULL};
	const char *text, *mode = "adaptive", *rotations = NULL;
	PyObject *rangeo = NULL;
	mkCSpaceOptions opt = mkCSpaceOptions_Default();
	opt.interleaved = 0;
	if (!PyArg_ParseTupleAndKeywords(args, kw, "s|$dpsiiiOz:scene", kwlist, &text, &opt.tol, &opt.outer, &mode,
			&opt.uniform, &opt.threads, &opt.max_points, &rangeo, &rotations))
		return NULL;
	if (strcmp(mode, "adaptive") && strcmp(mode, "uniform")) {
		PyErr_Format(PyExc_ValueError, "mode: '%s' is not one of adaptive, uniform", mode);
		return NULL;
	}
	opt.mode = strcmp(mode, "uniform") == 0 ? MK_CSPACE_UNIFORM : MK_CSPACE_ADAPTIVE;
	char msg[1024] = "";
	mkScene scene;
	memset(&scene, 0, sizeof scene);
	mkCSpace *cs = NULL;
	mkCSpaceResult *res = NULL;
	PyObject *capsule = NULL, *list = NULL;
	if (mkPy_SceneParse(text, rotations, &scene, msg, sizeof msg) < 0) goto done;
	int begin = 0, end = scene.orientation_count;
	if (rangeo && rangeo != Py_None) {
		double be[2];
		if (mkPy_Numbers(rangeo, "orientations", be, 2, "a range begin, end") < 0) goto done;
		if (!(fabs(be[0]) <= 1e9 && fabs(be[1]) <= 1e9) || be[0] != (int)be[0] || be[1] != (int)be[1]) {
			PyErr_SetString(PyExc_ValueError, "orientations: begin and end must be integers");
			goto done;
		}
		begin = (int)be[0];
		end = (int)be[1];
	}
	if (mkCSpace_Create(&scene, &opt, &cs, msg, sizeof msg) != MK_OK) {
		PyErr_Format(PyExc_ValueError, "scene: %s", msg);
		goto done;
	}
	if (!(res = PyMem_Calloc(1, sizeof *res))) {
		PyErr_NoMemory();
		goto done;
	}
	mkResult r;
	Py_BEGIN_ALLOW_THREADS
	r = mkCSpace_Run(cs, begin, end, res, msg, sizeof msg);
	Py_END_ALLOW_THREADS
	if (r != MK_OK) {
		PyErr_Format(r == MK_ERR_MEMORY ? PyExc_MemoryError : PyExc_ValueError, "%s%s", r == MK_ERR_MEMORY ? "" :
			"orientations: ", msg);
		PyMem_Free(res);
		goto done;
	}
	if (!(capsule = PyCapsule_New(res, "mink.CSpaceResult", mkPy_ResultRelease))) {
		mkCSpaceResult_Free(res);
		PyMem_Free(res);
		goto done;
	}
	list = mkPy_Boundaries(cs, res, capsule);
done:
	Py_XDECREF(capsule);
	mkCSpace_Destroy(cs);
	mkScene_Free(&scene);
	return list;
}
