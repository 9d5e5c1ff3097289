/* message.h - the core's one way to report a failure with a message: format
 * into the caller's buffer (when it is not NULL and not empty) and return the
 * result code, so that a parser can write `return mkFail(r, msg, len, ...)`.
 * Internal to the library (not exported). */
#ifndef MINK_MESSAGE_H
#define MINK_MESSAGE_H

#include <stddef.h>

#include "mink/base.h"

mkResult mkFail(mkResult r, char *msg, size_t msglen, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 4, 5)))
#endif
	;

#endif
