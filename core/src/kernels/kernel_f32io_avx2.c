/* kernel_f32io_avx2.c - the single-precision kernels on 8 float lanes, reading and writing
 * float arrays (mkSum2f_Batch, mkSum3f_Batch); compiled with -mavx2 -mfma. */
#define MK_X86F_W 8
#define MK_F32_FLOATIO 1
#include "kernels/kernel_x86f.h"
