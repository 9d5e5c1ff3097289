/* batch_avx2.c - batch_x86.h for 4 lanes (AVX2). */
#include <string.h>
#define MK_BX_W 4
#include "collide/batch_x86.h"
