/* module.c - the extension module mink._mink: its function table and its
 * types, and the exception mink.Error (args.c holds the helpers). */
#define MKPY_MODULE_UNIT
#include "mkpy.h"

#include <stdio.h>
#include <string.h>

static PyObject *mkPy_Version(PyObject *self, PyObject *args)
{
	(void)self;
	(void)args;
	return PyUnicode_FromString(mkVersion());
}

static PyObject *mkPy_Impls(PyObject *self, PyObject *args)
{
	(void)self;
	(void)args;
	PyObject *list = PyList_New(0);
	for (int i = MK_IMPL_SCALAR; list && i <= MK_IMPL_AVX512; ++i) {
		if (!mkImpl_Available((mkImpl)i)) continue;
		PyObject *s = PyUnicode_FromString(mkImpl_Name((mkImpl)i));
		if (!s || PyList_Append(list, s) < 0) Py_CLEAR(list);
		Py_XDECREF(s);
	}
	return list;
}

#define MKPY_KW (PyCFunction)(void (*)(void))
static PyMethodDef mkPy_Functions[] = {
	{"sum", MKPY_KW mkPy_Sum, METH_VARARGS | METH_KEYWORDS, mkPy_SumDoc},
	{"sample", MKPY_KW mkPy_Sample, METH_VARARGS | METH_KEYWORDS, mkPy_SampleDoc},
	{"collide", MKPY_KW mkPy_Collide, METH_VARARGS | METH_KEYWORDS, mkPy_CollideDoc},
	{"score", MKPY_KW mkPy_Score, METH_VARARGS | METH_KEYWORDS, mkPy_ScoreDoc},
	{"area", MKPY_KW mkPy_Area, METH_VARARGS | METH_KEYWORDS, mkPy_AreaDoc},
	{"methods", mkPy_Methods, METH_NOARGS, mkPy_MethodsDoc},
	{"run", MKPY_KW mkPy_Run, METH_VARARGS | METH_KEYWORDS, mkPy_RunDoc},
	{"scene", MKPY_KW mkPy_Scene, METH_VARARGS | METH_KEYWORDS, mkPy_SceneDoc},
	{"collide_batch", MKPY_KW mkPy_CollideBatch, METH_VARARGS | METH_KEYWORDS, mkPy_CollideBatchDoc},
	{"version", mkPy_Version, METH_NOARGS, "version() -> str: the C library's version, MAJOR.MINOR.PATCH."},
	{"impls", mkPy_Impls, METH_NOARGS, "impls() -> list of str: the kernels this CPU runs (scalar, avx2, avx512)."},
	{NULL, NULL, 0, NULL}};

static struct PyModuleDef mkPy_Module = {
	PyModuleDef_HEAD_INIT, "mink._mink",
	"The C core of the mink package: closed-form Minkowski sums, collision queries, "
	"C-obstacles, the error measure and the method registry (see the package mink).",
	-1, mkPy_Functions, NULL, NULL, NULL, NULL};

PyMODINIT_FUNC PyInit__mink(void);
PyMODINIT_FUNC PyInit__mink(void)
{
	import_array();
	if (PyType_Ready(&mkPyBody_Type) < 0) return NULL;
	PyObject *m = PyModule_Create(&mkPy_Module);
	if (!m) return NULL;
	mkPy_Error = PyErr_NewExceptionWithDoc("mink.Error",
		"A failure of the C library that is not bad input: a solve that did not converge, "
		"a hull that failed, memory. Bad input raises ValueError or TypeError.",
		PyExc_RuntimeError, NULL);
	Py_INCREF(&mkPyBody_Type);
	if (!mkPy_Error || PyModule_AddObject(m, "Error", mkPy_Error) < 0
		|| PyModule_AddObject(m, "Body", (PyObject *)&mkPyBody_Type) < 0
		|| mkPy_QueryTypesReady(m) < 0 || mkPy_SceneTypesReady(m) < 0) {
		Py_DECREF(m);
		return NULL;
	}
	Py_INCREF(mkPy_Error);
	return m;
}
