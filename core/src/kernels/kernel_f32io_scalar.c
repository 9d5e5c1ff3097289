/* kernel_f32io_scalar.c - the scalar single-precision kernels on float arrays (kernel_scalarf.h). */
#define MK_F32_FLOATIO 1
#include "kernels/kernel_scalarf.h"
