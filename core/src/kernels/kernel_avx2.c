/* kernel_avx2.c - the kernels on 4 lanes; compiled with -mavx2 -mfma. */
#define MK_X86_W 4
#include "kernels/kernel_x86.h"
