#include "GeneratorArrowDefaults.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPVDataInformation.h"
#include "vtkPVXMLElement.h"
#include "vtkSMProperty.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxyManager.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSourceProxy.h"

#include <algorithm>
#include <cstring>

namespace
{
// The arrows' length as a fraction of the largest extent of the shown data: long enough to read
// the direction at the default camera, short enough not to hide the surface.
constexpr double ArrowLengthPerExtent = 0.2;

// The hint of the producer's XML that names this output port, or nullptr.
vtkPVXMLElement* FindGeneratorArrowsHint(vtkSMProxy* producer, unsigned int port)
{
  vtkPVXMLElement* hints = producer->GetHints();
  if (!hints)
  {
    return nullptr;
  }
  for (unsigned int i = 0; i < hints->GetNumberOfNestedElements(); ++i)
  {
    vtkPVXMLElement* hint = hints->GetNestedElement(i);
    int hintPort = -1;
    if (hint->GetName() && std::strcmp(hint->GetName(), "GeneratorArrows") == 0 &&
      hint->GetScalarAttribute("port", &hintPort) && hintPort == static_cast<int>(port))
    {
      return hint;
    }
  }
  return nullptr;
}

// Grows extent (min, max per axis) to hold bounds, unless they are empty.
void AddBounds(const double* bounds, double* extent)
{
  if (bounds[0] > bounds[1])
  {
    return; // empty data: VTK's uninitialized bounds
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    extent[2 * axis] = std::min(extent[2 * axis], bounds[2 * axis]);
    extent[2 * axis + 1] = std::max(extent[2 * axis + 1], bounds[2 * axis + 1]);
  }
}

// Sets a property only if it still holds its XML default (a user's or a state's value wins).
template <typename Value>
void SetIfDefault(vtkSMProxy* representation, const char* name, Value value)
{
  vtkSMProperty* property = representation->GetProperty(name);
  if (property && property->IsValueDefault())
  {
    vtkSMPropertyHelper(property).Set(value);
  }
}

void AimGeneratorArrows(vtkSMProxy* representation, vtkSMSourceProxy* producer, unsigned int port,
  vtkPVXMLElement* hint)
{
  if (!representation->GetProperty("Orient") || !representation->GetProperty("ScaleFactor"))
  {
    return; // not a geometry representation (e.g. a spreadsheet's)
  }
  const char* orientationArray = hint->GetAttribute("orientation_array");
  if (orientationArray)
  {
    SetIfDefault(representation, "SelectOrientationVectors", orientationArray);
  }
  SetIfDefault(representation, "OrientationMode", 0); // Direction
  SetIfDefault(representation, "Orient", 1);

  double extent[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  AddBounds(producer->GetDataInformation(0)->GetBounds(), extent);
  AddBounds(producer->GetDataInformation(port)->GetBounds(), extent);
  const double largest =
    std::max({ extent[1] - extent[0], extent[3] - extent[2], extent[5] - extent[4] });
  if (largest > 0 && largest < VTK_DOUBLE_MAX)
  {
    vtkSMProperty* scaling = representation->GetProperty("Scaling");
    const bool scalingWasDefault = scaling && scaling->IsValueDefault();
    SetIfDefault(representation, "ScaleMode", 0); // one length for all: no data scaling
    SetIfDefault(representation, "Scaling", 1);
    // ScaleFactor's domain has already given it a default from the generators' own bounds, so it
    // is sized here only together with Scaling.
    if (scalingWasDefault)
    {
      vtkSMPropertyHelper(representation, "ScaleFactor").Set(ArrowLengthPerExtent * largest);
    }
  }
  representation->UpdateVTKObjects();
}

void OnProxyRegistered(vtkObject* caller, unsigned long, void*, void* callData)
{
  auto* proxyManager = vtkSMSessionProxyManager::SafeDownCast(caller);
  auto* info = static_cast<vtkSMProxyManager::RegisteredProxyInformation*>(callData);
  if (!proxyManager || !info || info->Type != vtkSMProxyManager::RegisteredProxyInformation::PROXY ||
    !info->Proxy || !info->GroupName || std::strcmp(info->GroupName, "representations") != 0 ||
    proxyManager->GetInLoadXMLState())
  {
    return;
  }
  vtkSMProxy* representation = info->Proxy;
  if (!representation->GetProperty("Input"))
  {
    return;
  }
  vtkSMPropertyHelper input(representation, "Input", /*quiet=*/true);
  auto* producer = vtkSMSourceProxy::SafeDownCast(input.GetAsProxy(0));
  if (!producer)
  {
    return;
  }
  const unsigned int port = input.GetOutputPort(0);
  if (vtkPVXMLElement* hint = FindGeneratorArrowsHint(producer, port))
  {
    AimGeneratorArrows(representation, producer, port, hint);
  }
}

vtkCallbackCommand* RegistrationObserver()
{
  static vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(&OnProxyRegistered);
  return observer;
}

// Every session has its own proxy manager (pvpython's Connect() makes a new one): watch the
// active one, once.
void WatchActiveSession()
{
  vtkSMSessionProxyManager* proxyManager =
    vtkSMProxyManager::GetProxyManager()->GetActiveSessionProxyManager();
  if (proxyManager && !proxyManager->HasObserver(vtkCommand::RegisterEvent, RegistrationObserver()))
  {
    proxyManager->AddObserver(vtkCommand::RegisterEvent, RegistrationObserver());
  }
}

void OnActiveSessionChanged(vtkObject*, unsigned long, void*, void*)
{
  WatchActiveSession();
}
}

void BoostedSurfacesInstallGeneratorArrowDefaults()
{
  if (!vtkSMProxyManager::IsInitialized())
  {
    return; // a server process: nothing is shown here
  }
  static vtkNew<vtkCallbackCommand> sessionObserver;
  vtkSMProxyManager* manager = vtkSMProxyManager::GetProxyManager();
  if (!manager->HasObserver(vtkSMProxyManager::ActiveSessionChanged, sessionObserver))
  {
    sessionObserver->SetCallback(&OnActiveSessionChanged);
    manager->AddObserver(vtkSMProxyManager::ActiveSessionChanged, sessionObserver);
  }
  WatchActiveSession();
}
