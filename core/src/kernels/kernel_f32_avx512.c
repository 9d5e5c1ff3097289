/* kernel_f32_avx512.c - the single-precision kernels on 16 lanes; compiled with -mavx512f. */
#define MK_X86F_W 16
#include "kernels/kernel_x86f.h"
