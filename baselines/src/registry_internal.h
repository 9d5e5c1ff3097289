/* registry_internal.h - small pieces the registry entries share. */
#ifndef MINK_REGISTRY_INTERNAL_H
#define MINK_REGISTRY_INTERNAL_H

#include <stddef.h>
#include <mink/mink.h>

/* Accept every valid pair (the bodies are validated by the caller). */
int mkAcceptAny2(mkBody2 b1, mkBody2 b2, mkSet set, char *msg, size_t msglen);
int mkAcceptAny3(mkBody3 b1, mkBody3 b2, mkSet set, char *msg, size_t msglen);

#endif
