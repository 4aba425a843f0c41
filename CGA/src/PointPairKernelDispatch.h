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
MapBlockDirectional activeMapBlockDirectional();
AddFieldBlock activeAddFieldBlock();
MapDisplacedBlock activeMapDisplacedBlock();
std::vector<std::string> availableInstructionSets();
std::string activeInstructionSet();
bool useInstructionSet(const std::string& name);
} // namespace kernel
} // namespace cga
