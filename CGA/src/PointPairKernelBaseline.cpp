// The block kernel compiled for the build's default target (on x86-64: SSE2 only), the fallback
// every CPU runs.
#define BOOSTED_KERNEL_ISA baseline
#include "PointPairKernelLanes.h"
