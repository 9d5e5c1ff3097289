/* base.c - result names, the version, and the formatted failure helper. */
#include "mink/method.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/message.h"

const char *mkResult_Name(mkResult r)
{
	switch (r) {
	case MK_OK: return "ok";
	case MK_ERR_ARGUMENT: return "invalid argument";
	case MK_ERR_RANGE: return "value out of range";
	case MK_ERR_UNSUPPORTED: return "unsupported";
	case MK_ERR_MEMORY: return "out of memory";
	case MK_ERR_CONVERGENCE: return "no convergence";
	}
	return "unknown result";
}

#define MK_STR2(x) #x
#define MK_STR(x) MK_STR2(x)

const char *mkVersion(void)
{
	return MK_STR(MK_VERSION_MAJOR) "." MK_STR(MK_VERSION_MINOR) "." MK_STR(MK_VERSION_PATCH);
}

mkResult mkFail(mkResult r, char *msg, size_t msglen, const char *fmt, ...)
{
	if (msg && msglen) {
		va_list ap;
		va_start(ap, fmt);
		vsnprintf(msg, msglen, fmt, ap);
		va_end(ap);
	}
	return r;
}
