// The wide block (PointPairKernel.h, MapDisplacedWideBlock) compiled for avx512, as
// PointPairKernelAvx512.cpp (the same compile options) with kWideLanes lanes.
#define BOOSTED_KERNEL_ISA avx512wide
#define BOOSTED_KERNEL_WIDE
#include "PointPairKernelAvx512Macros.h"
#include "PointPairKernelLanes.h"
