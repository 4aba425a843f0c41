// The block kernel compiled for avx512 (compile options in CGA/CMakeLists.txt).
#define BOOSTED_KERNEL_ISA avx512
#include "PointPairKernelAvx512Macros.h"
// mapBlockJets here only: on narrower registers its second-order jets take minutes to compile
// (AVX2 400 s, the baseline over 17 minutes, against 44 s here); elsewhere the jets are mapped one
// lane at a time (mapJetsByExponential).
#define BOOSTED_KERNEL_JETS
#include "PointPairKernelLanes.h"
