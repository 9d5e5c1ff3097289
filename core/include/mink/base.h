/* mink/base.h - export macros, C/C++ linkage, version and result codes.
 *
 * Every public header of the core includes this one first, so that the C++
 * baselines can include the C headers unchanged. */
#ifndef MINK_BASE_H
#define MINK_BASE_H

#if defined(_WIN32) && defined(MINK_SHARED)
#  if defined(MINK_BUILDING)
#    define MK_API __declspec(dllexport)
#  else
#    define MK_API __declspec(dllimport)
#  endif
#elif defined(__GNUC__)
#  define MK_API __attribute__((visibility("default")))
#else
#  define MK_API
#endif

#ifdef __cplusplus
#  define MK_EXTERN_C_BEGIN extern "C" {
#  define MK_EXTERN_C_END }
#else
#  define MK_EXTERN_C_BEGIN
#  define MK_EXTERN_C_END
#endif

#define MK_VERSION_MAJOR 0
#define MK_VERSION_MINOR 1
#define MK_VERSION_PATCH 0

MK_EXTERN_C_BEGIN

/* Result of every fallible call. Negative values are errors. */
typedef enum mkResult {
	MK_OK = 0,
	MK_ERR_ARGUMENT = -1, /* a documented precondition on an argument does not hold */
	MK_ERR_RANGE = -2,    /* a numeric input lies outside its documented range */
	MK_ERR_UNSUPPORTED = -3, /* the combination of inputs is not supported */
	MK_ERR_MEMORY = -4,   /* allocation failed (only in functions that allocate) */
	MK_ERR_CONVERGENCE = -5 /* an iterative solve did not converge (no answer) */
} mkResult;

/* A short English name for a result code ("ok", "argument", ...). */
MK_API const char *mkResult_Name(mkResult r);

/* The library version as "MAJOR.MINOR.PATCH". */
MK_API const char *mkVersion(void);

MK_EXTERN_C_END

#endif
