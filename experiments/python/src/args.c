/* args.c - the argument helpers every function of the extension uses
 * (enums by name, numpy rows without copies, number lists) and the
 * exception mink.Error, made by module.c at import. */
#include "mkpy.h"

#include <stdio.h>
#include <string.h>

PyObject *mkPy_Error;

int mkPy_Enum(PyObject *o, const char *field, int (*parse)(const char *), const char *allowed, int fallback)
{
	if (!o || o == Py_None) return fallback;
	if (!PyUnicode_Check(o)) {
		PyErr_Format(PyExc_TypeError, "%s: expected a str (one of %s), got %s", field, allowed, Py_TYPE(o)->tp_name);
		return -1;
	}
	const char *s = PyUnicode_AsUTF8(o);
	if (!s) return -1;
	int v = parse(s);
	if (v < 0) PyErr_Format(PyExc_ValueError, "%s: '%s' is not one of %s", field, s, allowed);
	return v;
}

static const char *mkPy_TypeName(int type)
{
	return type == NPY_FLOAT ? "float32" : "float64";
}

PyArrayObject *mkPy_Rows(PyObject *o, const char *field, int dim, int type, int exact)
{
	if (!o) {
		PyErr_Format(PyExc_TypeError, "%s: missing", field);
		return NULL;
	}
	if (PyArray_Check(o) && exact && PyArray_TYPE((PyArrayObject *)o) != type) {
		PyArray_Descr *d = PyArray_DESCR((PyArrayObject *)o);
		PyObject *name = PyObject_Str((PyObject *)d);
		PyErr_Format(PyExc_TypeError, "%s: dtype %s is not accepted: it must be %s%s", field,
			name ? PyUnicode_AsUTF8(name) : "?", mkPy_TypeName(type),
			type == NPY_DOUBLE ? " (or float32 where the function says so)" : "");
		Py_XDECREF(name);
		return NULL;
	}
	if (PyArray_Check(o) && !PyArray_ISNUMBER((PyArrayObject *)o)) {
		PyErr_Format(PyExc_TypeError, "%s: dtype is not numeric: it must be %s", field, mkPy_TypeName(type));
		return NULL;
	}
	PyArrayObject *a = (PyArrayObject *)PyArray_FromAny(o, PyArray_DescrFromType(type), 0, 0,
		NPY_ARRAY_C_CONTIGUOUS | NPY_ARRAY_ALIGNED | NPY_ARRAY_FORCECAST, NULL);
	if (!a) {
		PyErr_Clear();
		PyErr_Format(PyExc_TypeError, "%s: expected a %s array of shape (%d, N), got %s", field,
			mkPy_TypeName(type), dim, Py_TYPE(o)->tp_name);
		return NULL;
	}
	if (PyArray_NDIM(a) != 2 || PyArray_DIM(a, 0) != dim) {
		char shape[96] = "(";
		for (int i = 0; i < PyArray_NDIM(a) && i < 4; ++i)
			snprintf(shape + strlen(shape), sizeof shape - strlen(shape), "%s%zd", i ? ", " : "",
				(Py_ssize_t)PyArray_DIM(a, i));
		snprintf(shape + strlen(shape), sizeof shape - strlen(shape), "%s)",
			PyArray_NDIM(a) > 4 ? ", ..." : PyArray_NDIM(a) == 1 ? "," : "");
		PyErr_Format(PyExc_ValueError, "%s: shape %s, expected (%d, N): one row per coordinate", field, shape, dim);
		Py_DECREF(a);
		return NULL;
	}
	if (PyArray_DIM(a, 1) > INT32_MAX) {
		PyErr_Format(PyExc_ValueError, "%s: %zd points, at most %d", field, (Py_ssize_t)PyArray_DIM(a, 1), INT32_MAX);
		Py_DECREF(a);
		return NULL;
	}
	return a;
}

PyArrayObject *mkPy_OutRows(PyObject *o, const char *field, int dim, npy_intp count, int type)
{
	if (!o || o == Py_None) {
		npy_intp dims[2] = {dim, count};
		return (PyArrayObject *)PyArray_SimpleNew(2, dims, type);
	}
	if (!PyArray_Check(o)) {
		PyErr_Format(PyExc_TypeError, "%s: expected a numpy array, got %s", field, Py_TYPE(o)->tp_name);
		return NULL;
	}
	PyArrayObject *a = (PyArrayObject *)o;
	if (PyArray_TYPE(a) != type) {
		PyErr_Format(PyExc_TypeError, "%s: dtype must be %s (the inputs' type)", field, mkPy_TypeName(type));
		return NULL;
	}
	if (PyArray_NDIM(a) != 2 || PyArray_DIM(a, 0) != dim || PyArray_DIM(a, 1) != count) {
		PyErr_Format(PyExc_ValueError, "%s: shape must be (%d, %zd)", field, dim, (Py_ssize_t)count);
		return NULL;
	}
	if (!PyArray_IS_C_CONTIGUOUS(a) || !PyArray_ISALIGNED(a) || !PyArray_ISWRITEABLE(a)) {
		PyErr_Format(PyExc_ValueError, "%s: must be C-contiguous, aligned and writeable", field);
		return NULL;
	}
	Py_INCREF(a);
	return a;
}

int mkPy_Overlap(PyArrayObject *a, PyArrayObject *b)
{
	if (!a || !b) return 0;
	const char *pa = PyArray_BYTES(a), *pb = PyArray_BYTES(b);
	npy_intp na = PyArray_NBYTES(a), nb = PyArray_NBYTES(b);
	return na > 0 && nb > 0 && pa < pb + nb && pb < pa + na;
}

int mkPy_Numbers(PyObject *o, const char *field, double *v, int n, const char *what)
{
	PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(o, NPY_DOUBLE, 0, 2, NPY_ARRAY_CARRAY_RO | NPY_ARRAY_FORCECAST);
	if (!a) {
		PyErr_Clear();
		PyErr_Format(PyExc_TypeError, "%s: expected %d numbers (%s), got %s", field, n, what, Py_TYPE(o)->tp_name);
		return -1;
	}
	if (PyArray_SIZE(a) != n) {
		PyErr_Format(PyExc_ValueError, "%s: %zd numbers given, expected %d (%s)", field, (Py_ssize_t)PyArray_SIZE(a), n,
			what);
		Py_DECREF(a);
		return -1;
	}
	memcpy(v, PyArray_DATA(a), (size_t)n * sizeof(double));
	Py_DECREF(a);
	return 0;
}
