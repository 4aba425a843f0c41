// The block kernel compiled for avx2 (compile options in CGA/CMakeLists.txt). SLEEF's deterministic
// functions for 4 doubles are its AVX ones (AVX2 adds nothing they use).
#include <immintrin.h>

#define BOOSTED_KERNEL_ISA avx2
#define BOOSTED_KERNEL_VECTOR_BYTES 32
#define BOOSTED_KERNEL_SLEEF(name) Sleef_cinz_##name##d4_u10avx
#define BOOSTED_KERNEL_SQRT _mm256_sqrt_pd
#define BOOSTED_KERNEL_FMA _mm256_fmadd_pd
#include "PointPairKernelLanes.h"
