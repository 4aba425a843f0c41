/**
 * @class   vtkBoostedWholeInput
 * @brief   asks for the whole of an input on every rank
 *
 * The inputs that every piece needs whole (the Hopf source's sphere points, the orbit source's
 * seeds, the deformation filter's generators): the pieces divide the output, not these inputs,
 * so each rank requests piece 0 of 1 without ghost levels (and the whole extent of a structured
 * input).
 */
#ifndef vtkBoostedWholeInput_h
#define vtkBoostedWholeInput_h

#include "vtkInformation.h"
#include "vtkStreamingDemandDrivenPipeline.h"

namespace vtkBoostedWholeInput
{
/// Sets the update request of the input `information` (nothing when it is null).
inline void Request(vtkInformation* information)
{
  if (!information)
  {
    return;
  }
  information->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  information->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  information->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  if (information->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    information->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
      information->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
  }
}
} // namespace vtkBoostedWholeInput

#endif
