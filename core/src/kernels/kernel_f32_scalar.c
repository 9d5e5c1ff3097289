/* kernel_f32_scalar.c - the scalar single-precision kernels on double arrays (kernel_scalarf.h). */
#include "kernels/kernel_scalarf.h"
