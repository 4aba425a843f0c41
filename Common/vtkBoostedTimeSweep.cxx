#include "vtkBoostedTimeSweep.h"

#include "vtkAlgorithm.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <vector>

void vtkBoostedTimeSweep::ReportTimeSteps(vtkInformation* outInfo, int numberOfTimeSteps)
{
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  if (numberOfTimeSteps < 1)
  {
    return;
  }
  const int n = std::min(numberOfTimeSteps, MaximumNumberOfTimeSteps);
  std::vector<double> times(n, 1.0);
  for (int k = 0; k + 1 < n; ++k)
  {
    times[k] = static_cast<double>(k) / (n - 1);
  }
  const double range[2] = { times.front(), times.back() };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), n);
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
}

void vtkBoostedTimeSweep::ReportOnEveryPort(
  vtkInformationVector* outputVector, int numberOfTimeSteps, bool pieces)
{
  for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
  {
    vtkInformation* info = outputVector->GetInformationObject(port);
    if (pieces)
    {
      info->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
    }
    ReportTimeSteps(info, numberOfTimeSteps);
  }
}

double vtkBoostedTimeSweep::Fraction(vtkInformation* outInfo, int numberOfTimeSteps)
{
  if (numberOfTimeSteps < 1 || !outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    return 1.0;
  }
  const double t = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  return std::isnan(t) ? 1.0 : std::min(1.0, std::max(0.0, t));
}

void vtkBoostedTimeSweep::StampTime(
  vtkInformation* outInfo, int numberOfTimeSteps, vtkDataObject* output)
{
  if (output && numberOfTimeSteps >= 1 &&
    outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(),
      outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()));
  }
}
