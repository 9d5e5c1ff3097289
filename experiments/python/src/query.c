/* query.c - mink.collide (the core's collision queries), mink.score and
 * mink.area (the baselines' independent error measure, mink/error.h),
 * mink.methods and mink.run (the method registry, mink/registry.h). */
#include "mkpy.h"

#include <math.h>
#include <string.h>

#include <mink/error.h>
#include <mink/registry.h>

static PyTypeObject mkPy_CollisionType, mkPy_DeviationType, mkPy_MethodType;

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
		|| PyStructSequence_InitType2(&mkPy_MethodType, &mkPy_MethodDesc) < 0)
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
