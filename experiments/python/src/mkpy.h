/* mkpy.h - what the translation units of the Python extension mink._mink
 * share: the Body type, the exception, argument helpers.
 *
 * Layout: module.c (the module, its exception, enum parsing), body.c (the
 * Body type), sum.c (sum, sample), query.c (collide, collide_batch, score,
 * area, methods, run), scene.c (scene). Every array crossing the boundary is a numpy array
 * of shape (dim, N), one contiguous row per coordinate: the structure of
 * arrays the core's batch functions take, so they read and write numpy's
 * memory directly. */
#ifndef MINK_PY_H
#define MINK_PY_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#define PY_ARRAY_UNIQUE_SYMBOL mkPy_ArrayApi
#ifndef MKPY_MODULE_UNIT
#define NO_IMPORT_ARRAY
#endif
#include <numpy/arrayobject.h>

#include <mink/mink.h>

/* A placed body, immutable, valid by construction (mkBody2/3_IsValid). */
typedef struct mkPyBody {
	PyObject_HEAD
	int dim;
	mkBody2 b2;     /* dim == 2 */
	mkBody3 b3;     /* dim == 3 */
	PyObject *spec; /* the SPEC text it was made from, or NULL */
} mkPyBody;

extern PyTypeObject mkPyBody_Type;
/* mink.Error: failures that are not bad input (no convergence, a CGAL hull
 * that failed); bad input raises ValueError or TypeError. */
extern PyObject *mkPy_Error;

/* The body of argument `field`, or NULL with TypeError naming the field. */
mkPyBody *mkPy_BodyArg(PyObject *o, const char *field);
/* Both bodies of a pair, of the same dimension (ValueError otherwise). */
int mkPy_BodyPair(PyObject *o1, PyObject *o2, mkPyBody **b1, mkPyBody **b2);

/* Parse an enum keyword (`field` names it in the error): the value, or -1
 * with ValueError listing the allowed names. `parse` is mkSet_Parse etc. */
int mkPy_Enum(PyObject *o, const char *field, int (*parse)(const char *), const char *allowed, int fallback);

/* An array argument as a C-contiguous, aligned array of shape (dim, N) and
 * type `type` (NPY_DOUBLE or NPY_FLOAT): a numpy array of that dtype whose
 * memory is already laid out so is used as it is (no copy); a list or a
 * non-contiguous array of the dtype is converted. Raises TypeError naming
 * `field` for another dtype (when `exact`; lists are always converted) and
 * ValueError for another shape. New reference or NULL. */
PyArrayObject *mkPy_Rows(PyObject *o, const char *field, int dim, int type, int exact);
/* An output array: exactly dtype `type`, shape (dim, count), C-contiguous,
 * aligned, writeable; TypeError/ValueError naming `field` otherwise. o NULL
 * or None: a new array. New reference or NULL. */
PyArrayObject *mkPy_OutRows(PyObject *o, const char *field, int dim, npy_intp count, int type);
/* n doubles from a sequence or array argument into v; TypeError or
 * ValueError naming `field` and saying what they are (`what`). */
int mkPy_Numbers(PyObject *o, const char *field, double *v, int n, const char *what);
/* 1 when the memory of two arrays overlaps. */
int mkPy_Overlap(PyArrayObject *a, PyArrayObject *b);

/* The module's functions (their docstrings are next to them). */
PyObject *mkPy_Sum(PyObject *self, PyObject *args, PyObject *kw);
PyObject *mkPy_Sample(PyObject *self, PyObject *args, PyObject *kw);
PyObject *mkPy_Collide(PyObject *self, PyObject *args, PyObject *kw);
PyObject *mkPy_Score(PyObject *self, PyObject *args, PyObject *kw);
PyObject *mkPy_Area(PyObject *self, PyObject *args, PyObject *kw);
PyObject *mkPy_Methods(PyObject *self, PyObject *args);
PyObject *mkPy_Run(PyObject *self, PyObject *args, PyObject *kw);
PyObject *mkPy_Scene(PyObject *self, PyObject *args, PyObject *kw);
PyObject *mkPy_CollideBatch(PyObject *self, PyObject *args, PyObject *kw);
extern const char mkPy_SumDoc[], mkPy_SampleDoc[], mkPy_CollideDoc[], mkPy_ScoreDoc[], mkPy_AreaDoc[],
	mkPy_MethodsDoc[], mkPy_RunDoc[], mkPy_SceneDoc[], mkPy_CollideBatchDoc[];

/* The struct-sequence types of results, made ready by the module (query.c's
 * include mink.Batch). */
int mkPy_QueryTypesReady(PyObject *module);
int mkPy_SceneTypesReady(PyObject *module);

#endif
