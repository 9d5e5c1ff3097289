/* collision_fma.c - MinkSum (Normal)'s solver (collision.c) compiled a
 * second time, for processors with AVX2 and FMA: core/CMakeLists.txt gives
 * this unit -mavx2 -mfma and lets the compiler contract a * b + c into one
 * fused multiply-add. collision.c calls this build where the processor has
 * them (mkCollide3_Build says which build runs). Its answers differ from the
 * portable build's by rounding only: docs/collide.md, "Tenth pass". */
#define MK_COLLISION_FMA_UNIT 1
#include "collide/collision.c"
