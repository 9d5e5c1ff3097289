/* accept.c - the helpers every method's accept functions use (mink/registry.h):
 * mkRefuse writes the reason and answers no, mkAcceptAny2/3 take any pair. They
 * sit below the table (registry.c) and the external methods (external.c),
 * which both use them. */
#include <stdarg.h>
#include <stdio.h>

#include <mink/registry.h>

int mkRefuse(char *msg, size_t msglen, const char *format, ...)
{
	if (msg && msglen) {
		va_list args;
		va_start(args, format);
		vsnprintf(msg, msglen, format, args);
		va_end(args);
	}
	return 0;
}

int mkAcceptAny2(mkBody2 b1, mkBody2 b2, mkSet set, char *msg, size_t msglen)
{
	(void)b1;
	(void)b2;
	(void)set;
	if (msg && msglen) msg[0] = '\0';
	return 1;
}

int mkAcceptAny3(mkBody3 b1, mkBody3 b2, mkSet set, char *msg, size_t msglen)
{
	(void)b1;
	(void)b2;
	(void)set;
	if (msg && msglen) msg[0] = '\0';
	return 1;
}
