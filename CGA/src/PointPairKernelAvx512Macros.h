// Internal: the AVX-512 kernels' register width and vector functions for PointPairKernelLanes.h,
// shared by the block (PointPairKernelAvx512.cpp) and the wide block
// (PointPairKernelAvx512Wide.cpp). Included once per translation unit, before that header.
#include <immintrin.h>

#define BOOSTED_KERNEL_VECTOR_BYTES 64
#define BOOSTED_KERNEL_SLEEF(name) Sleef_cinz_##name##d8_u10avx512fnofma
#define BOOSTED_KERNEL_SQRT _mm512_sqrt_pd
#define BOOSTED_KERNEL_FMA _mm512_fmadd_pd
