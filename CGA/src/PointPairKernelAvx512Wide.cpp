// The wide block (PointPairKernel.h, MapDisplacedWideBlock) compiled for avx512, as
// PointPairKernelAvx512.cpp (the same compile options) with kWideLanes lanes.
#include <immintrin.h>

#define BOOSTED_KERNEL_ISA avx512wide
#define BOOSTED_KERNEL_WIDE
#define BOOSTED_KERNEL_VECTOR_BYTES 64
#define BOOSTED_KERNEL_SLEEF(name) Sleef_cinz_##name##d8_u10avx512fnofma
#define BOOSTED_KERNEL_SQRT _mm512_sqrt_pd
#define BOOSTED_KERNEL_FMA _mm512_fmadd_pd
#include "PointPairKernelLanes.h"
