/* batch_avx512.c - batch_x86.h for 8 lanes (AVX-512F). */
#include <string.h>
#define MK_BX_W 8
#include "collide/batch_x86.h"
