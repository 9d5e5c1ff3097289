/* kernel_f32io_avx512.c - the single-precision kernels on 16 float lanes, reading and writing
 * float arrays (mkSum2f_Batch, mkSum3f_Batch); compiled with -mavx512f. */
#define MK_X86F_W 16
#define MK_F32_FLOATIO 1
#include "kernels/kernel_x86f.h"
