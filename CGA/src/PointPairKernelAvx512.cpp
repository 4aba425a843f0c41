// The block kernel compiled for avx512 (compile options in CGA/CMakeLists.txt).
#define BOOSTED_KERNEL_ISA avx512
#define BOOSTED_KERNEL_VECTOR_BYTES 64
#include "PointPairKernelLanes.h"
