/* sum.c - mink.sum and mink.sample: the batch closed forms on numpy arrays,
 * read and written in place (no copies of C-contiguous inputs). */
#include "mkpy.h"

#include <limits.h>

const char mkPy_SampleDoc[] =
	"sample(dim, n, eps=None) -> ndarray (dim, N) float64\n\n"
	"The paper's parameter vectors: 2D n angles -pi + 2 pi k / n (N = n, n >= 1); 3D an n x n\n"
	"grid of (eta, omega) with both poles (N = n*n, n >= 2, index i*n + j). eps: the\n"
	"'almost equally spaced' sampling of a superellipse of exponent eps instead (3D: a pair\n"
	"(eps1, eps2)), see mkSample2_Spaced.";

/* A new (dim, count) array of the paper's (or the spaced) sampling; n is
 * checked here. */
static PyArrayObject *mkPy_NewSample(int dim, long n, const double *eps)
{
	if (n < (dim == 2 ? 1 : 2) || (dim == 3 && n > 46340) || n > INT_MAX) {
		PyErr_Format(PyExc_ValueError, "n: %ld is out of range: %s", n,
			dim == 2 ? "1 <= n <= 2147483647 points" : "2 <= n <= 46340 (an n x n grid)");
		return NULL;
	}
	npy_intp count = dim == 2 ? n : n * n;
	npy_intp dims[2] = {dim, count};
	PyArrayObject *a = (PyArrayObject *)PyArray_SimpleNew(2, dims, NPY_DOUBLE);
	if (!a) return NULL;
	double *u = PyArray_DATA(a);
	mkResult r;
	Py_BEGIN_ALLOW_THREADS
	if (dim == 2)
		r = eps ? mkSample2_Spaced((int)n, eps[0], u, u + count) : mkSample2_Angles((int)n, u, u + count);
	else
		r = eps ? mkSample3_Spaced((int)n, eps[0], eps[1], u, u + count, u + 2 * count)
			: mkSample3_Grid((int)n, u, u + count, u + 2 * count);
	Py_END_ALLOW_THREADS
	if (r != MK_OK) {
		PyErr_Format(PyExc_ValueError, "eps: outside [%g, %g] (%s)", MK_EPS_MIN, MK_EPS_MAX, mkResult_Name(r));
		Py_DECREF(a);
		return NULL;
	}
	return a;
}

PyObject *mkPy_Sample(PyObject *self, PyObject *args, PyObject *kw)
{
	(void)self;
	static char *kwlist[] = {"dim", "n", "eps", NULL};
	int dim;
	long n;
	PyObject *epso = NULL;
	if (!PyArg_ParseTupleAndKeywords(args, kw, "il|O:sample", kwlist, &dim, &n, &epso)) return NULL;
	if (dim != 2 && dim != 3) {
		PyErr_Format(PyExc_ValueError, "dim: %d, must be 2 or 3", dim);
		return NULL;
	}
	double eps[2];
	if (epso && epso != Py_None) {
		if (mkPy_Numbers(epso, "eps", eps, dim - 1, dim == 2 ? "the exponent eps in 2D" : "eps1, eps2 in 3D") < 0)
			return NULL;
	}
	return (PyObject *)mkPy_NewSample(dim, n, epso && epso != Py_None ? eps : NULL);
}

const char mkPy_SumDoc[] =
	"sum(body1, body2, u=None, *, n=None, set='contact', form='gradient', param='surface',\n"
	"    impl='auto', precision='double', out=None, kiss=None) -> points or (points, kiss)\n\n"
	"Boundary points of the contact space B1 (+) (-B2) (set='contact', where B2's centre may go\n"
	"so that B2 touches B1) or of B1 (+) B2 (set='plus'), one per parameter vector, by the\n"
	"closed forms' batch kernels (mkSum2_Batch / mkSum3_Batch).\n"
	"u: the parameter vectors, an array of shape (dim, N), one row per coordinate; float64\n"
	"   (float32 runs the float kernels, mkSum2f_Batch). A C-contiguous array is read in place.\n"
	"n: instead of u, the paper's sampling (sample(dim, n)).\n"
	"form: 'normal' (Theorem 1), 'gradient' (Theorem 2), 'paper'; param: 'surface' (u are B1's\n"
	"surface angles) or 'normal' (u is the world normal); impl: 'auto', 'scalar', 'avx2',\n"
	"'avx512'; precision: 'double' or 'f32'.\n"
	"out: an array of shape (dim, N) and u's dtype, C-contiguous, written in place (returned);\n"
	"kiss: True, or such an array, for the kissing points on B1 too (returns (points, kiss)).\n"
	"The GIL is released during the computation.";

typedef struct mkPySumArgs {
	mkPyBody *b1, *b2;
	mkSumOptions opt;
	PyArrayObject *u, *out, *kiss;
} mkPySumArgs;

static int mkPy_SumOptions(mkSumOptions *opt, PyObject *set, PyObject *form, PyObject *param, PyObject *impl,
	PyObject *precision)
{
	*opt = mkSumOptions_Default();
	int v[5] = {
		mkPy_Enum(set, "set", mkSet_Parse, "contact, plus", opt->set),
		mkPy_Enum(form, "form", mkForm_Parse, "normal, gradient, paper", opt->form),
		mkPy_Enum(param, "param", mkParam_Parse, "surface, normal", opt->param),
		mkPy_Enum(impl, "impl", mkImpl_Parse, "auto, scalar, avx2, avx512", opt->impl),
		mkPy_Enum(precision, "precision", mkPrecision_Parse, "double, f32", opt->precision)};
	for (int i = 0; i < 5; ++i)
		if (v[i] < 0) return -1;
	*opt = (mkSumOptions){(mkSet)v[0], (mkForm)v[1], (mkParam)v[2], (mkImpl)v[3], (mkPrecision)v[4]};
	if (!mkImpl_Available(opt->impl)) {
		PyErr_Format(PyExc_ValueError, "impl: '%s' does not run on this CPU (mink.impls() lists those that do)",
			mkImpl_Name(opt->impl));
		return -1;
	}
	if (opt->form == MK_FORM_PAPER
		&& (opt->param != MK_PARAM_SURFACE || opt->impl != MK_IMPL_SCALAR || opt->precision != MK_PRECISION_DOUBLE)) {
		PyErr_SetString(PyExc_ValueError, "form: 'paper' needs param='surface', impl='scalar' and precision='double'");
		return -1;
	}
	return 0;
}

/* The call itself, on rows of u, out and kiss; GIL released. */
static mkResult mkPy_SumRun(const mkPySumArgs *a)
{
	npy_intp n = PyArray_DIM(a->u, 1);
	int dim = a->b1->dim, f32 = PyArray_TYPE(a->u) == NPY_FLOAT;
	size_t step = (size_t)n * (f32 ? sizeof(float) : sizeof(double));
	char *u = PyArray_BYTES(a->u), *o = PyArray_BYTES(a->out), *k = a->kiss ? PyArray_BYTES(a->kiss) : NULL;
#define MKPY_ROW(p, i) ((p) ? (void *)((p) + (i) * step) : NULL)
	mkResult r;
	Py_BEGIN_ALLOW_THREADS
	if (dim == 2 && !f32)
		r = mkSum2_Batch(a->b1->b2, a->b2->b2, &a->opt, MKPY_ROW(u, 0), MKPY_ROW(u, 1), (int)n, MKPY_ROW(o, 0),
			MKPY_ROW(o, 1), MKPY_ROW(k, 0), MKPY_ROW(k, 1));
	else if (dim == 2)
		r = mkSum2f_Batch(a->b1->b2, a->b2->b2, &a->opt, MKPY_ROW(u, 0), MKPY_ROW(u, 1), (int)n, MKPY_ROW(o, 0),
			MKPY_ROW(o, 1), MKPY_ROW(k, 0), MKPY_ROW(k, 1));
	else if (!f32)
		r = mkSum3_Batch(a->b1->b3, a->b2->b3, &a->opt, MKPY_ROW(u, 0), MKPY_ROW(u, 1), MKPY_ROW(u, 2), (int)n,
			MKPY_ROW(o, 0), MKPY_ROW(o, 1), MKPY_ROW(o, 2), MKPY_ROW(k, 0), MKPY_ROW(k, 1), MKPY_ROW(k, 2));
	else
		r = mkSum3f_Batch(a->b1->b3, a->b2->b3, &a->opt, MKPY_ROW(u, 0), MKPY_ROW(u, 1), MKPY_ROW(u, 2), (int)n,
			MKPY_ROW(o, 0), MKPY_ROW(o, 1), MKPY_ROW(o, 2), MKPY_ROW(k, 0), MKPY_ROW(k, 1), MKPY_ROW(k, 2));
	Py_END_ALLOW_THREADS
#undef MKPY_ROW
	return r;
}

/* u from its argument or from n; NULL with an exception. */
static PyArrayObject *mkPy_SumParams(PyObject *uo, PyObject *no, int dim)
{
	if ((uo && uo != Py_None) == (no && no != Py_None)) {
		PyErr_SetString(PyExc_TypeError, "sum: give exactly one of u (parameter vectors) and n (the paper's sampling)");
		return NULL;
	}
	if (no && no != Py_None) {
		long n = PyLong_AsLong(no);
		if (n == -1 && PyErr_Occurred()) {
			PyErr_Clear();
			PyErr_Format(PyExc_TypeError, "n: expected an int, got %s", Py_TYPE(no)->tp_name);
			return NULL;
		}
		return mkPy_NewSample(dim, n, NULL);
	}
	int type = PyArray_Check(uo) && PyArray_TYPE((PyArrayObject *)uo) == NPY_FLOAT ? NPY_FLOAT : NPY_DOUBLE;
	return mkPy_Rows(uo, "u", dim, type, 1);
}

PyObject *mkPy_Sum(PyObject *self, PyObject *args, PyObject *kw)
{
	(void)self;
	static char *kwlist[] = {"body1", "body2", "u", "n", "set", "form", "param", "impl", "precision", "out", "kiss",
		NULL};
	PyObject *o1, *o2, *uo = NULL, *no = NULL, *set = NULL, *form = NULL, *param = NULL, *impl = NULL, *prec = NULL;
	PyObject *outo = NULL, *kisso = NULL;
	if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|O$OOOOOOOO:sum", kwlist, &o1, &o2, &uo, &no, &set, &form, &param,
			&impl, &prec, &outo, &kisso))
		return NULL;
	mkPySumArgs a = {0};
	if (mkPy_BodyPair(o1, o2, &a.b1, &a.b2) < 0 || mkPy_SumOptions(&a.opt, set, form, param, impl, prec) < 0)
		return NULL;
	int want_kiss = kisso && kisso != Py_None && kisso != Py_False;
	if (!(a.u = mkPy_SumParams(uo, no, a.b1->dim))) return NULL;
	int dim = a.b1->dim, type = PyArray_TYPE(a.u);
	npy_intp n = PyArray_DIM(a.u, 1);
	PyObject *result = NULL;
	if (!(a.out = mkPy_OutRows(outo, "out", dim, n, type))) goto done;
	if (want_kiss && !(a.kiss = mkPy_OutRows(kisso == Py_True ? NULL : kisso, "kiss", dim, n, type))) goto done;
	if (mkPy_Overlap(a.out, a.u) || mkPy_Overlap(a.kiss, a.u) || mkPy_Overlap(a.out, a.kiss)) {
		PyErr_SetString(PyExc_ValueError, "out: the output arrays (out, kiss) must not share memory with u or "
			"with each other");
		goto done;
	}
	mkResult r = mkPy_SumRun(&a);
	if (r != MK_OK) {
		PyErr_Format(mkPy_Error, "sum: the batch call failed (%s)", mkResult_Name(r));
		goto done;
	}
	result = want_kiss ? Py_BuildValue("(OO)", a.out, a.kiss) : (Py_INCREF(a.out), (PyObject *)a.out);
done:
	Py_XDECREF(a.u);
	Py_XDECREF(a.out);
	Py_XDECREF(a.kiss);
	return result;
}
