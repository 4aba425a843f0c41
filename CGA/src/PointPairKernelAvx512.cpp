// The block kernel compiled for avx512 (compile options in CGA/CMakeLists.txt).
#define BOOSTED_KERNEL_ISA avx512
#include "PointPairKernelAvx512Macros.h"
#include "PointPairKernelLanes.h"
