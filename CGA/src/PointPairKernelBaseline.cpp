// The block kernel compiled for the build's default target (on x86-64: SSE2 only), the fallback
// every CPU runs.
#define BOOSTED_KERNEL_ISA baseline
#if defined(__SSE2__)
#include <emmintrin.h>
#define BOOSTED_KERNEL_VECTOR_BYTES 16
#define BOOSTED_KERNEL_SLEEF(name) Sleef_cinz_##name##d2_u10sse2
#define BOOSTED_KERNEL_SQRT _mm_sqrt_pd
#endif
#include "PointPairKernelLanes.h"
