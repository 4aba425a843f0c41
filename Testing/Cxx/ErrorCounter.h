// Counts the ErrorEvents of a VTK object (the messages do not reach the output window's count).
#ifndef ErrorCounter_h
#define ErrorCounter_h

#include "vtkCallbackCommand.h"
#include "vtkNew.h"
#include "vtkObject.h"

struct ErrorCounter
{
  int count = 0;
  vtkNew<vtkCallbackCommand> observer;

  explicit ErrorCounter(vtkObject* object)
  {
    observer->SetCallback(&ErrorCounter::Callback);
    observer->SetClientData(this);
    object->AddObserver(vtkCommand::ErrorEvent, observer);
  }

  static void Callback(vtkObject*, unsigned long, void* clientData, void*)
  {
    ++static_cast<ErrorCounter*>(clientData)->count;
  }
};

#endif
