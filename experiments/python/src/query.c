/* query.c - mink.collide and mink.collide_batch (the core's collision
 * queries, one pair or many per call), mink.score and
 * mink.area (the baselines' independent error measure, mink/error.h),
 * mink.methods and mink.run (the method registry, mink/registry.h). */
#include "mkpy.h"

#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <mink/error.h>
#include <mink/registry.h>

static PyTypeObject mkPy_CollisionType, mkPy_DeviationType, mkPy_MethodType;
static int mkPy_BatchTypeReady(PyObject *module);

static PyStructSequence_Field mkPy_CollisionFields[] = {
	{"status", "'separated', 'touching', 'overlapping' or 'unknown'"},
	{"distance", "signed distance: > 0 the Euclidean distance, < 0 minus the penetration depth (NaN for ray)"},
	{"directional", "ray: the translation of B2 along the centre line that makes the bodies touch"},
	{"normal", "unit normal (x, y, z) from B1 towards B2"},
	{"p1", "witness point on B1's boundary"},
	{"p2", "witness point on B2's boundary"},
	{"bound", "f(n) at the answer, a lower bound of the signed distance"},
	{"gap", "certificate width (see mink/collision.h)"},
	{"residual", "optimality residual relative to scale"},
	{"scale", "the pair's size, the unit of every tolerance"},
	{"iterations", "Newton iterations"},
	{"restarts", "extra starts tried"},
	{"certified", "1 when the signed distance is certified in [bound, bound + gap], 0 when not, -1 for ray"},
	{"cert_evals", "pair evaluations of the branch and bound (overlaps), -1 otherwise"},
	{NULL, NULL}};
static PyStructSequence_Desc mkPy_CollisionDesc = {"mink.Collision", "The answer of mink.collide (mkCollision3).",
	mkPy_CollisionFields, 14};

static PyStructSequence_Field mkPy_DeviationFields[] = {
	{"points", "points given"},
	{"nonfinite", "of them with a NaN or infinite coordinate (left out)"},
	{"vertices", "vertices of the points' convex hull P"},
	{"size", "the sum's size S, the unit of the relative figures"},
	{"gap_in", "max over n of h_K(n) - h_P(n): how far the true set K reaches beyond P"},
	{"gap_out", "max signed distance of the points to K (> 0 outside)"},
	{"hausdorff_abs", "Hausdorff distance between P and K"},
	{"hausdorff_rel", "hausdorff_abs / size"},
	{"hausdorff_bound", "the true distance lies in [hausdorff_abs - allowance, hausdorff_abs + hausdorff_bound]"},
	{"off_boundary_max", "the points' largest distance off K's boundary"},
	{"off_boundary_rel", "off_boundary_max / size"},
	{"off_boundary_bound", "its bound"},
	{"worst", "index of the point with the largest distance off the boundary"},
	{"area_p", "|P|: area (2D) or volume (3D)"},
	{"area_k", "|K|"},
	{"area_rel", "(|P| - |K|) / |K|"},
	{"area_bound", "bound on the error of area_rel"},
	{"message", "one line with the figures"},
	{NULL, NULL}};
static PyStructSequence_Desc mkPy_DeviationDesc = {"mink.Deviation",
	"The answer of mink.score (mkDeviation): how far a point set is from the true boundary.",
	mkPy_DeviationFields, 18};

static PyStructSequence_Field mkPy_MethodFields[] = {
	{"name", "the registry name, e.g. 'closed-gradient'"},
	{"summary", "one line"},
	{"reference", "where it comes from"},
	{"dims", "the dimensions it runs in, e.g. (2, 3)"},
	{"exact", "its points lie exactly on the smooth boundary"},
	{"sampled", "n is samples per body and the output a hull"},
	{"approx", "a faster tier within a stated tolerance"},
	{"tolerance", "its stated accuracy relative to the sum's size (0: exact up to rounding, or none stated)"},
	{NULL, NULL}};
static PyStructSequence_Desc mkPy_MethodDesc = {"mink.Method", "One entry of the method registry (mkMethod).",
	mkPy_MethodFields, 8};

int mkPy_QueryTypesReady(PyObject *module)
{
	if (PyStructSequence_InitType2(&mkPy_CollisionType, &mkPy_CollisionDesc) < 0
		|| PyStructSequence_InitType2(&mkPy_DeviationType, &mkPy_DeviationDesc) < 0
		|| PyStructSequence_InitType2(&mkPy_MethodType, &mkPy_MethodDesc) < 0 || mkPy_BatchTypeReady(module) < 0)
		return -1;
	PyTypeObject *types[] = {&mkPy_CollisionType, &mkPy_DeviationType, &mkPy_MethodType};
	const char *names[] = {"Collision", "Deviation", "Method"};
	for (int i = 0; i < 3; ++i) {
		Py_INCREF(types[i]);
		if (PyModule_AddObject(module, names[i], (PyObject *)types[i]) < 0) {
			Py_DECREF(types[i]);
			return -1;
		}
	}
	return 0;
}

/* Fill a struct sequence from a Py_BuildValue format, one item a field. */
static PyObject *mkPy_Struct(PyTypeObject *type, const char *format, ...)
{
	va_list ap;
	va_start(ap, format);
	PyObject *t = Py_VaBuildValue(format, ap);
	va_end(ap);
	if (!t) return NULL;
	PyObject *s = PyStructSequence_New(type);
	for (Py_ssize_t i = 0; s && i < PyTuple_GET_SIZE(t); ++i) {
		PyObject *v = PyTuple_GET_ITEM(t, i);
		Py_INCREF(v);
		PyStructSequence_SET_ITEM(s, i, v);
	}
	Py_DECREF(t);
	return s;
}

const char mkPy_CollideDoc[] =
	"collide(body1, body2, method='normal', start=None) -> Collision\n\n"
	"Signed distance, contact status and witness points of two 3D bodies on the closed-form\n"
	"support map: method 'normal' (MinkSum (Normal), mkCollide3_Normal; start: a direction to\n"
	"start from, e.g. the previous answer's normal) or 'ray' (MinkSum (Ray), mkCollide3_Ray).\n"
	"Raises mink.Error when the solver does not converge. The GIL is released.";

PyObject *mkPy_Collide(PyObject *self, PyObject *args, PyObject *kw)
{
	(void)self;
	static char *kwlist[] = {"body1", "body2", "method", "start", NULL};
	PyObject *o1, *o2, *starto = NULL;
	const char *method = "normal";
	if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|sO:collide", kwlist, &o1, &o2, &method, &starto)) return NULL;
	mkPyBody *b1, *b2;
	if (mkPy_BodyPair(o1, o2, &b1, &b2) < 0) return NULL;
	if (b1->dim != 3) {
		PyErr_SetString(PyExc_ValueError, "body1: a 2D body: the collision queries take 3D bodies (sphere, ellipsoid, "
			"superquadric)");
		return NULL;
	}
	int ray = strcmp(method, "ray") == 0;
	if (!ray && strcmp(method, "normal") != 0) {
		PyErr_Format(PyExc_ValueError, "method: '%s' is not one of normal, ray", method);
		return NULL;
	}
	mkVec3 start = {0, 0, 0};
	int have_start = starto && starto != Py_None;
	if (have_start && ray) {
		PyErr_SetString(PyExc_ValueError, "start: only with method='normal'");
		return NULL;
	}
	double sv[3];
	if (have_start && mkPy_Numbers(starto, "start", sv, 3, "a direction x, y, z") < 0) return NULL;
	if (have_start) start = (mkVec3){sv[0], sv[1], sv[2]};
	if (have_start && (!isfinite(start.x + start.y + start.z) || (start.x == 0 && start.y == 0 && start.z == 0))) {
		PyErr_SetString(PyExc_ValueError, "start: must be a nonzero finite direction");
		return NULL;
	}
	mkCollision3 c;
	mkResult r;
	Py_BEGIN_ALLOW_THREADS
	r = ray ? mkCollide3_Ray(b1->b3, b2->b3, &c)
		: have_start ? mkCollide3_NormalFrom(b1->b3, b2->b3, start, &c) : mkCollide3_Normal(b1->b3, b2->b3, &c);
	Py_END_ALLOW_THREADS
	if (r != MK_OK) {
		PyErr_Format(mkPy_Error, "collide: %s (%s; last iterate: bound %g, residual %g, scale %g)",
			r == MK_ERR_CONVERGENCE ? "the solver did not converge" : "the query failed", mkResult_Name(r), c.bound,
			c.residual, c.scale);
		return NULL;
	}
	return mkPy_Struct(&mkPy_CollisionType, "(sd d(ddd)(ddd)(ddd) dddd iiii)", mkContact_Name(c.status), c.distance,
		c.directional, c.normal.x, c.normal.y, c.normal.z, c.p1.x, c.p1.y, c.p1.z, c.p2.x, c.p2.y, c.p2.z, c.bound,
		c.gap, c.residual, c.scale, c.iterations, c.restarts, c.certified, c.cert_evals);
}

const char mkPy_ScoreDoc[] =
	"score(body1, body2, points, set='contact', tol=0, truth=0, truth_bound=0) -> Deviation\n\n"
	"How far any point set is from the true boundary of the contact space (set='contact') or\n"
	"of B1 (+) B2 (set='plus'): the baselines' independent error measure (mkDeviation2_Measure /\n"
	"mkDeviation3_Measure, the measure of `mink score` and of the tradeoff study), which shares\n"
	"nothing with the closed forms. points: an array (dim, N) float64, read in place when\n"
	"C-contiguous. tol: relative precision of gap_in (0: 1e-6). truth, truth_bound: the true\n"
	"area/volume and its bound when known (mink.area), else computed (about a second in 2D).\n"
	"The GIL is released.";

/* The pair of bodies and the set of score, area and run; -1 with an exception. */
static int mkPy_PairAndSet(PyObject *o1, PyObject *o2, PyObject *seto, mkPyBody **b1, mkPyBody **b2, mkSet *set)
{
	if (mkPy_BodyPair(o1, o2, b1, b2) < 0) return -1;
	int v = mkPy_Enum(seto, "set", mkSet_Parse, "contact, plus", MK_SET_CONTACT);
	*set = (mkSet)v;
	return v < 0 ? -1 : 0;
}

PyObject *mkPy_Score(PyObject *self, PyObject *args, PyObject *kw)
{
	(void)self;
	static char *kwlist[] = {"body1", "body2", "points", "set", "tol", "truth", "truth_bound", NULL};
	PyObject *o1, *o2, *po, *seto = NULL;
	mkDeviationOptions opt = {0, 0, 0};
	if (!PyArg_ParseTupleAndKeywords(args, kw, "OOO|Oddd:score", kwlist, &o1, &o2, &po, &seto, &opt.tol, &opt.truth,
			&opt.truth_bound))
		return NULL;
	mkPyBody *b1, *b2;
	mkSet set;
	if (mkPy_PairAndSet(o1, o2, seto, &b1, &b2, &set) < 0) return NULL;
	if (!(opt.tol >= 0 && opt.tol < 1) || !(opt.truth >= 0) || !(opt.truth_bound >= 0)) {
		PyErr_SetString(PyExc_ValueError, !(opt.tol >= 0 && opt.tol < 1) ? "tol: must be in [0, 1)"
			: "truth, truth_bound: must be >= 0");
		return NULL;
	}
	PyArrayObject *p = mkPy_Rows(po, "points", b1->dim, NPY_DOUBLE, 1);
	if (!p) return NULL;
	npy_intp n = PyArray_DIM(p, 1);
	if (n < 1) {
		Py_DECREF(p);
		PyErr_SetString(PyExc_ValueError, "points: no points: at least one is needed");
		return NULL;
	}
	double *d = PyArray_DATA(p);
	mkPointSet ps = {b1->dim, (int)n, (int)n, d, d + n, b1->dim == 3 ? d + 2 * n : NULL};
	mkDeviation dev;
	mkResult r;
	Py_BEGIN_ALLOW_THREADS
	r = b1->dim == 2 ? mkDeviation2_Measure(b1->b2, b2->b2, set, &ps, &opt, &dev)
		: mkDeviation3_Measure(b1->b3, b2->b3, set, &ps, &opt, &dev);
	Py_END_ALLOW_THREADS
	Py_DECREF(p);
	if (r != MK_OK) {
		PyErr_Format(r == MK_ERR_MEMORY ? PyExc_MemoryError : mkPy_Error, "score: the measure failed (%s%s)",
			mkResult_Name(r), r == MK_ERR_UNSUPPORTED ? ": CGAL's 3D hull failed" : "");
		return NULL;
	}
	return mkPy_Struct(&mkPy_DeviationType, "(iiid ddddd ddd i dddd s)", dev.points, dev.nonfinite, dev.vertices,
		dev.size, dev.gap_in, dev.gap_out, dev.hausdorff_abs, dev.hausdorff_rel, dev.hausdorff_bound,
		dev.off_boundary_max, dev.off_boundary_rel, dev.off_boundary_bound, dev.worst, dev.area_p, dev.area_k,
		dev.area_rel, dev.area_bound, dev.message);
}

const char mkPy_AreaDoc[] =
	"area(body1, body2, set='contact') -> (value, bound)\n\n"
	"The true area (2D) or volume (3D) of the contact space or of B1 (+) B2 and a bound on its\n"
	"error, as the error measure computes it (mkDeviation2_Area / mkDeviation3_Volume); pass\n"
	"them to score(..., truth=value, truth_bound=bound) to score many point sets of one pair.";

PyObject *mkPy_Area(PyObject *self, PyObject *args, PyObject *kw)
{
	(void)self;
	static char *kwlist[] = {"body1", "body2", "set", NULL};
	PyObject *o1, *o2, *seto = NULL;
	if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|O:area", kwlist, &o1, &o2, &seto)) return NULL;
	mkPyBody *b1, *b2;
	mkSet set;
	if (mkPy_PairAndSet(o1, o2, seto, &b1, &b2, &set) < 0) return NULL;
	double v = NAN, bound = NAN;
	mkResult r;
	Py_BEGIN_ALLOW_THREADS
	r = b1->dim == 2 ? mkDeviation2_Area(b1->b2, b2->b2, set, &v, &bound)
		: mkDeviation3_Volume(b1->b3, b2->b3, set, &v, &bound);
	Py_END_ALLOW_THREADS
	if (r != MK_OK) {
		PyErr_Format(r == MK_ERR_MEMORY ? PyExc_MemoryError : mkPy_Error, "area: failed (%s)", mkResult_Name(r));
		return NULL;
	}
	return Py_BuildValue("(dd)", v, bound);
}

const char mkPy_MethodsDoc[] =
	"methods() -> list of Method\n\n"
	"The method registry (mink/registry.h) in its order: the closed forms and every baseline,\n"
	"as `mink methods` lists them. Run one with mink.run.";

PyObject *mkPy_Methods(PyObject *self, PyObject *args)
{
	(void)self;
	(void)args;
	PyObject *list = PyList_New(0);
	for (int i = 0; list && i < mkRegistry_Count(); ++i) {
		const mkMethod *m = mkRegistry_At(i);
		PyObject *dims = (m->flags & MK_METHOD_2D) && (m->flags & MK_METHOD_3D) ? Py_BuildValue("(ii)", 2, 3)
			: Py_BuildValue("(i)", m->flags & MK_METHOD_2D ? 2 : 3);
		PyObject *e = dims ? mkPy_Struct(&mkPy_MethodType, "(sssONNNd)", m->name, m->summary, m->reference, dims,
			PyBool_FromLong(m->flags & MK_METHOD_EXACT), PyBool_FromLong(m->flags & MK_METHOD_SAMPLED),
			PyBool_FromLong(m->flags & MK_METHOD_APPROX), mkMethod_Tolerance(m)) : NULL;
		Py_XDECREF(dims);
		if (!e || PyList_Append(list, e) < 0) Py_CLEAR(list);
		Py_XDECREF(e);
	}
	return list;
}

const char mkPy_RunDoc[] =
	"run(method, body1, body2, n, set='contact') -> ndarray (dim, count) float64\n\n"
	"Run one registered method (a name from methods()) at resolution n: the closed forms give\n"
	"one point per parameter of sample(dim, n); sampled methods n samples per body and the\n"
	"hull's vertices. Raises ValueError when the method does not take this pair, dimension or n.";

PyObject *mkPy_Run(PyObject *self, PyObject *args, PyObject *kw)
{
	(void)self;
	static char *kwlist[] = {"method", "body1", "body2", "n", "set", NULL};
	const char *name;
	PyObject *o1, *o2, *seto = NULL;
	int n;
	if (!PyArg_ParseTupleAndKeywords(args, kw, "sOOi|O:run", kwlist, &name, &o1, &o2, &n, &seto)) return NULL;
	mkPyBody *b1, *b2;
	mkSet set;
	if (mkPy_PairAndSet(o1, o2, seto, &b1, &b2, &set) < 0) return NULL;
	const mkMethod *m = mkRegistry_Find(name);
	if (!m) {
		PyErr_Format(PyExc_ValueError, "method: '%s' is unknown: mink.methods() lists them", name);
		return NULL;
	}
	char msg[512] = "";
	int dim = b1->dim;
	if (!mkMethod_CheckN(m, dim, n, msg, sizeof msg)
		|| !(dim == 2 ? mkMethod2_Accepts(m, b1->b2, b2->b2, set, msg, sizeof msg)
			: mkMethod3_Accepts(m, b1->b3, b2->b3, set, msg, sizeof msg))) {
		PyErr_SetString(PyExc_ValueError, msg);
		return NULL;
	}
	mkPointSet ps;
	memset(&ps, 0, sizeof ps);
	mkResult r;
	Py_BEGIN_ALLOW_THREADS
	r = dim == 2 ? m->run2(b1->b2, b2->b2, set, n, &ps) : m->run3(b1->b3, b2->b3, set, n, &ps);
	Py_END_ALLOW_THREADS
	PyArrayObject *a = NULL;
	npy_intp dims[2] = {dim, ps.count};
	if (r != MK_OK) {
		PyErr_Format(r == MK_ERR_MEMORY ? PyExc_MemoryError : mkPy_Error, "run: method %s failed (%s)", m->name,
			mkResult_Name(r));
	} else if ((a = (PyArrayObject *)PyArray_SimpleNew(2, dims, NPY_DOUBLE))) {
		double *d = PyArray_DATA(a);
		const double *rows[3] = {ps.x, ps.y, ps.z};
		for (int i = 0; i < dim; ++i)
			if (ps.count) memcpy(d + (size_t)i * ps.count, rows[i], (size_t)ps.count * sizeof(double));
	}
	mkPointSet_Free(&ps);
	return (PyObject *)a;
}

static PyTypeObject mkPy_BatchType;

static PyStructSequence_Field mkPy_BatchFields[] = {
	{"status", "ndarray (N,) int8: 0 separated, 1 touching, 2 overlapping, -1 unknown (the one-pair query failed)"},
	{"distance", "ndarray (N,) float64: the signed distance (mode distance: of non-overlapping pairs; full: all; "
		"NaN where the mode does not give it)"},
	{"lower", "ndarray (N,) float64: sd >= lower, certified (-inf when only an upper bound is known)"},
	{"upper", "ndarray (N,) float64: sd <= upper (+inf likewise)"},
	{"normal", "ndarray (3, N) float64: the separating direction, or the one-pair query's normal"},
	{"p1", "ndarray (3, N) float64: witness on B1 (an overlap point: p1 = p2 = the point)"},
	{"p2", "ndarray (3, N) float64: witness on B2"},
	{"clear", "mode clearance: ndarray (N,) bool, True when sd >= delta; None in the other modes"},
	{"path", "ndarray (N,) uint8: 0 separating direction, 1 overlap point, 2 one-pair query, 3 failed"},
	{"scale", "ndarray (N,) float64: each pair's size, the unit of every tolerance"},
	{"lanes", "the search's kernel on this CPU: 'avx512', 'avx2' or 'scalar'"},
	{NULL, NULL}};
static PyStructSequence_Desc mkPy_BatchDesc = {"mink.Batch", "The answers of mink.collide_batch (mkBatchOut3).",
	mkPy_BatchFields, 11};

static int mkPy_BatchTypeReady(PyObject *module)
{
	if (PyStructSequence_InitType2(&mkPy_BatchType, &mkPy_BatchDesc) < 0) return -1;
	Py_INCREF(&mkPy_BatchType);
	if (PyModule_AddObject(module, "Batch", (PyObject *)&mkPy_BatchType) < 0) {
		Py_DECREF(&mkPy_BatchType);
		return -1;
	}
	return 0;
}

const char mkPy_CollideBatchDoc[] =
	"collide_batch(bodies1, bodies2, mode='status', *, index1=None, index2=None, delta=0.0) -> Batch\n\n"
	"Many 3D collision queries in one call (mkCollide3_Batch): pair k is bodies1[index1[k]] and\n"
	"bodies2[index2[k]]. bodies1, bodies2: a sequence of mink.Body, or one Body for all pairs.\n"
	"index1, index2: integer arrays (N,); without them pair k takes item k (a single Body: item 0).\n"
	"mode: 'status' (separated / touching / overlapping, each certified), 'clearance' (is\n"
	"sd >= delta?, delta finite and >= 0), 'distance' (the signed distance of separated pairs),\n"
	"'full' (distance and certified depth, as collide). The answers agree with collide pair by\n"
	"pair (status equal, distances within 1e-12 of the scale). A pair the one-pair query fails on\n"
	"gets status -1 and path 3 (no exception). The GIL is released.";

/* The bodies of argument `field` (one Body or a sequence) into a new
 * PyMem array; *single is 1 for one Body. NULL with TypeError/ValueError. */
static mkBody3 *mkPy_BatchBodies(PyObject *o, const char *field, Py_ssize_t *count, int *single)
{
	*single = PyObject_TypeCheck(o, &mkPyBody_Type);
	PyObject *seq = *single ? NULL : PySequence_Fast(o, "");
	if (!*single && !seq) {
		PyErr_Format(PyExc_TypeError, "%s: expected a mink.Body or a sequence of them, got %s", field,
			Py_TYPE(o)->tp_name);
		return NULL;
	}
	*count = *single ? 1 : PySequence_Fast_GET_SIZE(seq);
	mkBody3 *b = PyMem_Malloc((size_t)(*count ? *count : 1) * sizeof *b);
	if (!b) PyErr_NoMemory();
	for (Py_ssize_t i = 0; b && i < *count; ++i) {
		PyObject *item = *single ? o : PySequence_Fast_GET_ITEM(seq, i);
		if (!PyObject_TypeCheck(item, &mkPyBody_Type) || ((mkPyBody *)item)->dim != 3) {
			int is_body = PyObject_TypeCheck(item, &mkPyBody_Type);
			PyErr_Format(is_body ? PyExc_ValueError : PyExc_TypeError, "%s: item %zd: %s%s", field, i,
				is_body ? "a 2D body: the collision queries take 3D bodies" : "expected a mink.Body, got ",
				is_body ? "" : Py_TYPE(item)->tp_name);
			PyMem_Free(b);
			b = NULL;
		} else {
			b[i] = ((mkPyBody *)item)->b3;
		}
	}
	Py_XDECREF(seq);
	return b;
}

/* An index argument as a C int array of values in [0, bodies), or NULL
 * with an exception naming `field`. Integers only (no float is rounded). */
static PyArrayObject *mkPy_BatchIndex(PyObject *o, const char *field, Py_ssize_t bodies)
{
	PyArrayObject *g = (PyArrayObject *)PyArray_FROMANY(o, NPY_NOTYPE, 1, 1, 0);
	PyArrayObject *a = g && (PyArray_ISINTEGER(g) || PyArray_SIZE(g) == 0)
		? (PyArrayObject *)PyArray_FROMANY((PyObject *)g, NPY_INT64, 1, 1, NPY_ARRAY_IN_ARRAY | NPY_ARRAY_FORCECAST) : NULL;
	Py_XDECREF(g);
	if (!a) {
		PyErr_Clear();
		PyErr_Format(PyExc_TypeError, "%s: expected a 1-D sequence or array of integers", field);
		return NULL;
	}
	npy_intp n = PyArray_DIM(a, 0);
	PyArrayObject *c = (PyArrayObject *)PyArray_SimpleNew(1, &n, NPY_INT);
	const npy_int64 *v = PyArray_DATA(a);
	for (npy_intp k = 0; c && k < n; ++k) {
		if (v[k] < 0 || v[k] >= bodies) {
			PyErr_Format(PyExc_ValueError, "%s: %lld at position %zd is out of range: 0 <= index < %zd (the bodies)",
				field, (long long)v[k], (Py_ssize_t)k, bodies);
			Py_CLEAR(c);
		} else {
			((int *)PyArray_DATA(c))[k] = (int)v[k];
		}
	}
	Py_DECREF(a);
	return c;
}

/* The pairs of collide_batch: bodies, indices, count. */
typedef struct mkPyBatchPairs {
	mkBody3 *b1, *b2;
	PyArrayObject *i1, *i2;
	npy_intp count;
} mkPyBatchPairs;

static void mkPy_BatchPairsFree(mkPyBatchPairs *p)
{
	PyMem_Free(p->b1);
	PyMem_Free(p->b2);
	Py_XDECREF(p->i1);
	Py_XDECREF(p->i2);
}

/* Bodies and indices from the arguments (a side without an index: one Body
 * for every pair, or as many bodies as pairs); 0 or -1 with an exception. */
static int mkPy_BatchPairsParse(PyObject *o1, PyObject *o2, PyObject *x1, PyObject *x2, mkPyBatchPairs *p)
{
	Py_ssize_t n[2];
	int single[2];
	if (!(p->b1 = mkPy_BatchBodies(o1, "bodies1", &n[0], &single[0]))
		|| !(p->b2 = mkPy_BatchBodies(o2, "bodies2", &n[1], &single[1])))
		return -1;
	PyObject *xo[2] = {x1 && x1 != Py_None ? x1 : NULL, x2 && x2 != Py_None ? x2 : NULL};
	PyArrayObject **ix[2] = {&p->i1, &p->i2};
	const char *names[2] = {"index1", "index2"}, *bnames[2] = {"bodies1", "bodies2"};
	for (int s = 0; s < 2; ++s)
		if (xo[s] && !(*ix[s] = mkPy_BatchIndex(xo[s], names[s], n[s]))) return -1;
	/* the count: from the indices, else from a sequence of bodies, else 1 */
	p->count = -1;
	for (int s = 0; s < 2 && p->count < 0; ++s)
		if (*ix[s]) p->count = PyArray_DIM(*ix[s], 0);
	for (int s = 0; s < 2 && p->count < 0; ++s)
		if (!single[s]) p->count = n[s];
	if (p->count < 0) p->count = 1;
	if (p->count > INT_MAX) {
		PyErr_Format(PyExc_ValueError, "bodies1: %zd pairs: at most %d per call", (Py_ssize_t)p->count, INT_MAX);
		return -1;
	}
	for (int s = 0; s < 2; ++s) {
		npy_intp have = *ix[s] ? PyArray_DIM(*ix[s], 0) : single[s] ? p->count : n[s];
		if (have != p->count) {
			PyErr_Format(PyExc_ValueError, "%s: %zd %s for %zd pairs: give one Body, as many as pairs, or an index",
				*ix[s] ? names[s] : bnames[s], (Py_ssize_t)have, *ix[s] ? "indices" : "bodies", (Py_ssize_t)p->count);
			return -1;
		}
		npy_intp cnt = p->count;
		if (!*ix[s] && single[s] && !(*ix[s] = (PyArrayObject *)PyArray_ZEROS(1, &cnt, NPY_INT, 0))) return -1;
	}
	return 0;
}

/* The output arrays of one call; the struct sequence owns them once built. */
typedef struct mkPyBatchOut {
	PyArrayObject *status, *distance, *lower, *upper, *normal, *p1, *p2, *clear, *path, *scale;
	mkContact *contact;
	mkVec3 *vec; /* normal, p1, p2: count each */
} mkPyBatchOut;

static void mkPy_BatchOutFree(mkPyBatchOut *o)
{
	PyArrayObject *a[10] = {o->status, o->distance, o->lower, o->upper, o->normal, o->p1, o->p2, o->clear, o->path,
		o->scale};
	for (int i = 0; i < 10; ++i)
		Py_XDECREF(a[i]);
	PyMem_Free(o->contact);
	PyMem_Free(o->vec);
}

static int mkPy_BatchOutAlloc(mkPyBatchOut *o, npy_intp n, int clearance)
{
	npy_intp d3[2] = {3, n};
	size_t m = (size_t)(n ? n : 1);
	o->status = (PyArrayObject *)PyArray_SimpleNew(1, &n, NPY_INT8);
	o->distance = (PyArrayObject *)PyArray_SimpleNew(1, &n, NPY_DOUBLE);
	o->lower = (PyArrayObject *)PyArray_SimpleNew(1, &n, NPY_DOUBLE);
	o->upper = (PyArrayObject *)PyArray_SimpleNew(1, &n, NPY_DOUBLE);
	o->scale = (PyArrayObject *)PyArray_SimpleNew(1, &n, NPY_DOUBLE);
	o->normal = (PyArrayObject *)PyArray_SimpleNew(2, d3, NPY_DOUBLE);
	o->p1 = (PyArrayObject *)PyArray_SimpleNew(2, d3, NPY_DOUBLE);
	o->p2 = (PyArrayObject *)PyArray_SimpleNew(2, d3, NPY_DOUBLE);
	o->path = (PyArrayObject *)PyArray_SimpleNew(1, &n, NPY_UINT8);
	o->clear = clearance ? (PyArrayObject *)PyArray_ZEROS(1, &n, NPY_BOOL, 0) : NULL;
	o->contact = PyMem_Malloc(m * sizeof *o->contact);
	o->vec = PyMem_Malloc(3 * m * sizeof *o->vec);
	if (!o->status || !o->distance || !o->lower || !o->upper || !o->scale || !o->normal || !o->p1 || !o->p2
		|| !o->path || (clearance && !o->clear) || !o->contact || !o->vec) {
		if (!PyErr_Occurred()) PyErr_NoMemory();
		return -1;
	}
	return 0;
}

/* The struct sequence of the answers (steals the arrays). */
static PyObject *mkPy_BatchResult(mkPyBatchOut *o, npy_intp n)
{
	int8_t *st = PyArray_DATA(o->status);
	PyArrayObject *rows[3] = {o->normal, o->p1, o->p2};
	for (npy_intp k = 0; k < n; ++k) {
		st[k] = (int8_t)o->contact[k];
		for (int v = 0; v < 3; ++v) {
			double *r = PyArray_DATA(rows[v]);
			mkVec3 x = o->vec[(size_t)v * n + k];
			r[k] = x.x;
			r[n + k] = x.y;
			r[2 * n + k] = x.z;
		}
	}
	PyObject *s = PyStructSequence_New(&mkPy_BatchType);
	PyObject *lanes = PyUnicode_FromString(mkCollide3_BatchLanes());
	if (!s || !lanes) {
		Py_XDECREF(s);
		Py_XDECREF(lanes);
		return NULL;
	}
	PyArrayObject *a[10] = {o->status, o->distance, o->lower, o->upper, o->normal, o->p1, o->p2, o->clear, o->path,
		o->scale};
	for (int i = 0; i < 10; ++i)
		PyStructSequence_SET_ITEM(s, i, a[i] ? (PyObject *)a[i] : (Py_INCREF(Py_None), Py_None));
	PyStructSequence_SET_ITEM(s, 10, lanes);
	/* the struct sequence owns the arrays now (they come first in o) */
	memset(o, 0, offsetof(mkPyBatchOut, contact));
	return s;
}

PyObject *mkPy_CollideBatch(PyObject *self, PyObject *args, PyObject *kw)
{
	(void)self;
	static char *kwlist[] = {"bodies1", "bodies2", "mode", "index1", "index2", "delta", NULL};
	PyObject *o1, *o2, *x1 = NULL, *x2 = NULL;
	const char *mode_name = "status";
	double delta = 0;
	if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|s$OOd:collide_batch", kwlist, &o1, &o2, &mode_name, &x1, &x2,
			&delta))
		return NULL;
	int mode = mkBatchMode_FromName(mode_name);
	if (mode < 0) {
		PyErr_Format(PyExc_ValueError, "mode: '%s' is not one of status, clearance, distance, full", mode_name);
		return NULL;
	}
	if (!(isfinite(delta) && delta >= 0)) {
		PyErr_Format(PyExc_ValueError, "delta: %g, must be finite and >= 0", delta);
		return NULL;
	}
	mkPyBatchPairs p = {0};
	mkPyBatchOut o = {0};
	PyObject *result = NULL;
	if (mkPy_BatchPairsParse(o1, o2, x1, x2, &p) < 0
		|| mkPy_BatchOutAlloc(&o, p.count, mode == MK_BATCH_CLEARANCE) < 0)
		goto done;
	npy_intp n = p.count;
	const int *i1 = p.i1 ? PyArray_DATA(p.i1) : NULL, *i2 = p.i2 ? PyArray_DATA(p.i2) : NULL;
	mkBatchPairs3 pairs = {(int)n, p.b1, p.b2, i1, i2};
	mkBatchOut3 out = {o.contact, PyArray_DATA(o.distance), PyArray_DATA(o.lower), PyArray_DATA(o.upper), o.vec,
		o.vec + n, o.vec + 2 * n, o.clear ? PyArray_DATA(o.clear) : NULL, PyArray_DATA(o.path)};
	double *scale = PyArray_DATA(o.scale);
	mkResult r;
	Py_BEGIN_ALLOW_THREADS
	r = mkCollide3_Batch(&pairs, (mkBatchMode)mode, delta, &out, NULL);
	for (npy_intp k = 0; k < n; ++k)
		scale[k] = mkCollide3_PairSize(p.b1[i1 ? i1[k] : k], p.b2[i2 ? i2[k] : k]);
	Py_END_ALLOW_THREADS
	if (r != MK_OK && r != MK_ERR_CONVERGENCE) {
		PyErr_Format(mkPy_Error, "collide_batch: the batch call failed (%s)", mkResult_Name(r));
		goto done;
	}
	result = mkPy_BatchResult(&o, n);
done:
	mkPy_BatchOutFree(&o);
	mkPy_BatchPairsFree(&p);
	return result;
}
