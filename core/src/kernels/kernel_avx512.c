/* kernel_avx512.c - the kernels on 8 lanes; compiled with -mavx512f. */
#define MK_X86_W 8
#include "kernels/kernel_x86.h"
