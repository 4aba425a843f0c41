// Internal: the block kernel chosen for the running CPU (PointPairKernelDispatch.cpp).
#pragma once

#include "PointPairKernel.h"

#include <string>
#include <vector>

namespace cga
{
namespace kernel
{
MapBlock activeMapBlock();
MapBlockBy activeMapBlockBy();
MapBlockJacobian activeMapBlockJacobian();
/// The active instruction set's MapBlockJets, or null where it has none (all but AVX-512).
MapBlockJets activeMapBlockJets();
MapBlockDirectional activeMapBlockDirectional();
AddFieldBlock activeAddFieldBlock();
AddFieldJacobianBlock activeAddFieldJacobianBlock();
MapBlockJacobianBy activeMapBlockJacobianBy();
SinCosBlock activeSinCosBlock();
/// b = scale B(p) of one point p (3 doubles) by the active kernel's generator loop: the bits of
/// core::fieldBivector for double (its fused multiply-adds are correctly rounded), but on the
/// FMA instruction where the CPU has one, not a call to libm's fma per term as the pointwise
/// code compiled for the baseline makes.
void activeFieldBivector(const FieldArgs& args, const double* p, double scale, double* b);
MapDisplacedBlock activeMapDisplacedBlock();
/// The active instruction set's MapDisplacedWideBlock, or null where it has none (all but AVX-512).
MapDisplacedWideBlock activeMapDisplacedWideBlock();
std::vector<std::string> availableInstructionSets();
std::string activeInstructionSet();
bool useInstructionSet(const std::string& name);
} // namespace kernel
} // namespace cga
