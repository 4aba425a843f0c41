// The block kernel compiled for avx2 (compile options in CGA/CMakeLists.txt).
#define BOOSTED_KERNEL_ISA avx2
#define BOOSTED_KERNEL_VECTOR_BYTES 32
#include "PointPairKernelLanes.h"
