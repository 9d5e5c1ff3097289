/* body.c - mink.Body: a placed body from a SPEC string or from parameters. */
#include "mkpy.h"

#include <string.h>

/* The dimension of a SPEC's kind (its first word), 0 when unknown. */
static int mkPyBody_SpecDim(const char *text)
{
	while (*text == ' ' || *text == '\t') ++text;
	size_t len = strcspn(text, " \t");
	for (int k = MK_KIND_CIRCLE; k <= MK_KIND_SUPERQUADRIC; ++k) {
		const char *name = mkKind_Name((mkKind)k);
		if (strlen(name) == len && strncmp(name, text, len) == 0) return k <= MK_KIND_SUPERELLIPSE ? 2 : 3;
	}
	return 0;
}

static int mkPyBody_FromSpec(mkPyBody *self, PyObject *spec)
{
	if (!PyUnicode_Check(spec)) {
		PyErr_Format(PyExc_TypeError, "spec: expected a str such as 'ellipse a=2 b=1', got %s", Py_TYPE(spec)->tp_name);
		return -1;
	}
	const char *text = PyUnicode_AsUTF8(spec);
	if (!text) return -1;
	int dim = mkPyBody_SpecDim(text);
	char msg[512] = "";
	mkSpec s;
	if (mkSpec_Parse(text, dim ? dim : 2, "spec", &s, msg, sizeof msg) != MK_OK) {
		PyErr_SetString(PyExc_ValueError, msg);
		return -1;
	}
	self->dim = s.dim;
	self->b2 = s.body2;
	self->b3 = s.body3;
	Py_INCREF(spec);
	Py_XSETREF(self->spec, spec);
	return 0;
}

static int mkPyBody_FromParams(mkPyBody *self, PyObject *shape, PyObject *M, PyObject *at)
{
	if (!shape) {
		PyErr_SetString(PyExc_TypeError, "Body: give a SPEC string, e.g. Body('ellipse a=2 b=1'), or shape=(a, b, eps) "
			"(2D) / shape=(a, b, c, eps1, eps2) (3D) with optional M and at");
		return -1;
	}
	PyObject *seq = PySequence_Fast(shape, "shape: expected a sequence of 3 (2D) or 5 (3D) numbers");
	if (!seq) return -1;
	Py_ssize_t n = PySequence_Fast_GET_SIZE(seq);
	Py_DECREF(seq);
	if (n != 3 && n != 5) {
		PyErr_Format(PyExc_ValueError, "shape: %zd numbers given, expected 3 (a, b, eps: 2D) or 5 (a, b, c, eps1, eps2: "
			"3D)", n);
		return -1;
	}
	int dim = n == 3 ? 2 : 3;
	double sv[5], mv[9] = {1, 0, 0, 1}, tv[3] = {0, 0, 0};
	if (dim == 3) memcpy(mv, (double[9]){1, 0, 0, 0, 1, 0, 0, 0, 1}, sizeof mv);
	if (mkPy_Numbers(shape, "shape", sv, (int)n, dim == 2 ? "a, b, eps" : "a, b, c, eps1, eps2") < 0) return -1;
	if (M && M != Py_None && mkPy_Numbers(M, "M", mv, dim * dim, dim == 2 ? "a 2 x 2 map" : "a 3 x 3 map") < 0)
		return -1;
	if (at && at != Py_None && mkPy_Numbers(at, "at", tv, dim, "the centre") < 0) return -1;
	char msg[512] = "";
	int ok;
	if (dim == 2) {
		self->b2 = mkBody2_Make((mkShape2){sv[0], sv[1], sv[2]}, (mkMat2){{{mv[0], mv[1]}, {mv[2], mv[3]}}},
			(mkVec2){tv[0], tv[1]});
		ok = mkBody2_IsValid(self->b2, "Body", msg, sizeof msg);
	} else {
		self->b3 = mkBody3_Make((mkShape3){sv[0], sv[1], sv[2], sv[3], sv[4]},
			(mkMat3){{{mv[0], mv[1], mv[2]}, {mv[3], mv[4], mv[5]}, {mv[6], mv[7], mv[8]}}}, (mkVec3){tv[0], tv[1], tv[2]});
		ok = mkBody3_IsValid(self->b3, "Body", msg, sizeof msg);
	}
	if (!ok) {
		PyErr_SetString(PyExc_ValueError, msg);
		return -1;
	}
	self->dim = dim;
	return 0;
}

static int mkPyBody_Init(PyObject *o, PyObject *args, PyObject *kw)
{
	static char *kwlist[] = {"spec", "shape", "M", "at", NULL};
	mkPyBody *self = (mkPyBody *)o;
	PyObject *spec = NULL, *shape = NULL, *M = NULL, *at = NULL;
	if (!PyArg_ParseTupleAndKeywords(args, kw, "|O$OOO:Body", kwlist, &spec, &shape, &M, &at)) return -1;
	if (self->dim) {
		PyErr_SetString(PyExc_TypeError, "Body: a body is immutable; make a new one");
		return -1;
	}
	if (spec && spec != Py_None) {
		if (shape || M || at) {
			PyErr_SetString(PyExc_TypeError, "Body: give either a SPEC string or shape/M/at, not both");
			return -1;
		}
		return mkPyBody_FromSpec(self, spec);
	}
	return mkPyBody_FromParams(self, shape, M, at);
}

static void mkPyBody_Dealloc(PyObject *o)
{
	Py_XDECREF(((mkPyBody *)o)->spec);
	Py_TYPE(o)->tp_free(o);
}

static PyObject *mkPyBody_Shape(PyObject *o, void *closure)
{
	(void)closure;
	mkPyBody *b = (mkPyBody *)o;
	if (b->dim == 2) return Py_BuildValue("(ddd)", b->b2.shape.a, b->b2.shape.b, b->b2.shape.eps);
	mkShape3 s = b->b3.shape;
	return Py_BuildValue("(ddddd)", s.a, s.b, s.c, s.eps1, s.eps2);
}

static PyObject *mkPyBody_Map(PyObject *o, void *closure)
{
	(void)closure;
	mkPyBody *b = (mkPyBody *)o;
	npy_intp dims[2] = {b->dim, b->dim};
	PyArrayObject *a = (PyArrayObject *)PyArray_SimpleNew(2, dims, NPY_DOUBLE);
	if (!a) return NULL;
	double *p = PyArray_DATA(a);
	for (int i = 0; i < b->dim; ++i)
		for (int j = 0; j < b->dim; ++j) p[i * b->dim + j] = b->dim == 2 ? b->b2.M.m[i][j] : b->b3.M.m[i][j];
	return (PyObject *)a;
}

static PyObject *mkPyBody_At(PyObject *o, void *closure)
{
	(void)closure;
	mkPyBody *b = (mkPyBody *)o;
	if (b->dim == 2) return Py_BuildValue("(dd)", b->b2.t.x, b->b2.t.y);
	return Py_BuildValue("(ddd)", b->b3.t.x, b->b3.t.y, b->b3.t.z);
}

static PyObject *mkPyBody_Dim(PyObject *o, void *closure)
{
	(void)closure;
	return PyLong_FromLong(((mkPyBody *)o)->dim);
}

static PyObject *mkPyBody_Spec(PyObject *o, void *closure)
{
	(void)closure;
	PyObject *s = ((mkPyBody *)o)->spec ? ((mkPyBody *)o)->spec : Py_None;
	Py_INCREF(s);
	return s;
}

static PyObject *mkPyBody_Measure(PyObject *o, PyObject *args)
{
	(void)args;
	mkPyBody *b = (mkPyBody *)o;
	return PyFloat_FromDouble(b->dim == 2 ? mkBody2_Area(b->b2) : mkBody3_Volume(b->b3));
}

static PyObject *mkPyBody_Repr(PyObject *o)
{
	mkPyBody *b = (mkPyBody *)o;
	if (b->spec) return PyUnicode_FromFormat("mink.Body(%R)", b->spec);
	PyObject *shape = mkPyBody_Shape(o, NULL), *M = mkPyBody_Map(o, NULL), *at = mkPyBody_At(o, NULL), *r = NULL;
	PyObject *Ml = M ? PyObject_CallMethod(M, "tolist", NULL) : NULL;
	if (shape && Ml && at) r = PyUnicode_FromFormat("mink.Body(shape=%R, M=%R, at=%R)", shape, Ml, at);
	Py_XDECREF(shape);
	Py_XDECREF(M);
	Py_XDECREF(Ml);
	Py_XDECREF(at);
	return r;
}

mkPyBody *mkPy_BodyArg(PyObject *o, const char *field)
{
	if (o && PyObject_TypeCheck(o, &mkPyBody_Type) && ((mkPyBody *)o)->dim) return (mkPyBody *)o;
	PyErr_Format(PyExc_TypeError, "%s: expected a mink.Body, got %s", field, o ? Py_TYPE(o)->tp_name : "nothing");
	return NULL;
}

int mkPy_BodyPair(PyObject *o1, PyObject *o2, mkPyBody **b1, mkPyBody **b2)
{
	if (!(*b1 = mkPy_BodyArg(o1, "body1")) || !(*b2 = mkPy_BodyArg(o2, "body2"))) return -1;
	if ((*b1)->dim != (*b2)->dim) {
		PyErr_Format(PyExc_ValueError, "body2: a %dD body with a %dD body1: both must have the same dimension",
			(*b2)->dim, (*b1)->dim);
		return -1;
	}
	return 0;
}

static PyGetSetDef mkPyBody_GetSet[] = {
	{"dim", mkPyBody_Dim, NULL, "2 or 3", NULL},
	{"shape", mkPyBody_Shape, NULL, "(a, b, eps) in 2D, (a, b, c, eps1, eps2) in 3D", NULL},
	{"M", mkPyBody_Map, NULL, "the linear map, a new (dim, dim) array", NULL},
	{"at", mkPyBody_At, NULL, "the centre (translation)", NULL},
	{"spec", mkPyBody_Spec, NULL, "the SPEC text the body was made from, or None", NULL},
	{NULL, NULL, NULL, NULL, NULL}};

static PyMethodDef mkPyBody_Methods[] = {
	{"measure", mkPyBody_Measure, METH_NOARGS, "measure() -> float: the area (2D) or volume (3D) of the body."},
	{NULL, NULL, 0, NULL}};

PyTypeObject mkPyBody_Type = {
	PyVarObject_HEAD_INIT(NULL, 0)
	.tp_name = "mink.Body",
	.tp_basicsize = sizeof(mkPyBody),
	.tp_dealloc = mkPyBody_Dealloc,
	.tp_repr = mkPyBody_Repr,
	.tp_flags = Py_TPFLAGS_DEFAULT,
	.tp_doc = "Body(spec) or Body(shape=..., M=None, at=None): a placed convex body at + M B.\n\n"
		"spec: a SPEC string, 'KIND key=value ...' (KIND circle, ellipse, superellipse, sphere,\n"
		"ellipsoid, superquadric; keys a, b, c, eps, eps1, eps2, rot, quat, shear, M, at), e.g.\n"
		"Body('superellipse a=3 b=2 eps=0.5 rot=0.3').\n"
		"shape: (a, b, eps) for a 2D superellipse, (a, b, c, eps1, eps2) for a 3D superquadric;\n"
		"M: the dim x dim linear map (row-major numbers or nested), default the identity;\n"
		"at: the centre, default the origin.\n"
		"Every value is checked (ValueError naming the field and the allowed range).",
	.tp_methods = mkPyBody_Methods,
	.tp_getset = mkPyBody_GetSet,
	.tp_init = mkPyBody_Init,
	.tp_new = PyType_GenericNew,
};
