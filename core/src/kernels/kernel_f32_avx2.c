/* kernel_f32_avx2.c - the single-precision kernels on 8 lanes; compiled with -mavx2 -mfma. */
#define MK_X86F_W 8
#include "kernels/kernel_x86f.h"
