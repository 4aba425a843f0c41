// Records the ProgressEvents of an algorithm and can abort it at a chosen one (shared by the
// C++ tests of progress and abort).
#ifndef ProgressLog_h
#define ProgressLog_h

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"

#include <vector>

struct ProgressLog
{
  std::vector<double> values;
  bool abortOnFirst = false;        // abort at the first event (the executive's 0 before RequestData)
  bool abortAfterFirstStep = false; // abort at the first event strictly between 0 and 1

  void Observe(vtkAlgorithm* algorithm)
  {
    vtkNew<vtkCallbackCommand> command; // the algorithm keeps a reference
    command->SetCallback(&ProgressLog::Callback);
    command->SetClientData(this);
    algorithm->AddObserver(vtkCommand::ProgressEvent, command);
  }

  /// The values strictly between 0 and 1 (up to rounding): the algorithm's own steps.
  std::vector<double> Steps() const
  {
    std::vector<double> steps;
    for (double value : this->values)
    {
      if (value > 0.0 && value < 1.0 + 1e-12)
      {
        steps.push_back(value);
      }
    }
    return steps;
  }

  static void Callback(vtkObject* caller, unsigned long, void* clientData, void* callData)
  {
    auto* log = static_cast<ProgressLog*>(clientData);
    const double value = *static_cast<double*>(callData);
    log->values.push_back(value);
    if (log->abortOnFirst || (log->abortAfterFirstStep && value > 0.0 && value < 1.0))
    {
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
    }
  }
};

#endif
