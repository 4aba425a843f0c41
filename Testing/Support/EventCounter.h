// Counts the ErrorEvents and WarningEvents of a VTK object and keeps the last error's and the last
// warning's text (the messages then go here instead of to the output window).
#ifndef EventCounter_h
#define EventCounter_h

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObject.h"

#include <string>

struct EventCounter
{
  int errors = 0;
  int warnings = 0;
  std::string lastError;
  std::string lastWarning;

  explicit EventCounter(vtkObject* object)
  {
    vtkNew<vtkCallbackCommand> command; // the object keeps a reference
    command->SetCallback(&EventCounter::Callback);
    command->SetClientData(this);
    object->AddObserver(vtkCommand::ErrorEvent, command);
    object->AddObserver(vtkCommand::WarningEvent, command);
  }
  EventCounter(const EventCounter&) = delete; // the observer points at this one
  EventCounter& operator=(const EventCounter&) = delete;

  static void Callback(vtkObject*, unsigned long event, void* clientData, void* callData)
  {
    auto* self = static_cast<EventCounter*>(clientData);
    if (event == vtkCommand::ErrorEvent)
    {
      ++self->errors;
      self->lastError = static_cast<const char*>(callData);
    }
    else
    {
      ++self->warnings;
      self->lastWarning = static_cast<const char*>(callData);
    }
  }
};

#endif
