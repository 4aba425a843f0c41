#include "HandleSizedToData.h"

// pqInteractivePropertyWidget is in pqApplicationComponents, which the plugin does not link
// (pvpython and pvserver load the plugin too): only its inline widgetProxy() is used, after
// QObject::inherits has checked the class.
#include "pqInteractivePropertyWidget.h"
#include "pqPropertyWidget.h"
#include "pqView.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkInteractorObserver.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointHandleRepresentation3D.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMNewWidgetRepresentationProxy.h"
#include "vtkSMViewProxy.h"

#include <QWidget>

#include <algorithm>
#include <cmath>

void HandleSizedToData::Attach(QWidget* handleWidget, double dataDiagonal)
{
  if (!handleWidget || !handleWidget->inherits("pqHandlePropertyWidget") ||
    !(dataDiagonal > 0.0) || !std::isfinite(dataDiagonal))
  {
    return;
  }
  HandleSizedToData* sizer = handleWidget->findChild<HandleSizedToData*>(
    QString(), Qt::FindDirectChildrenOnly);
  if (!sizer)
  {
    vtkSMNewWidgetRepresentationProxy* widgetProxy =
      static_cast<pqInteractivePropertyWidget*>(handleWidget)->widgetProxy();
    vtkSMProxy* prop = widgetProxy ? widgetProxy->GetRepresentationProxy() : nullptr;
    auto* representation =
      vtkPointHandleRepresentation3D::SafeDownCast(prop ? prop->GetClientSideObject() : nullptr);
    if (!representation)
    {
      return;
    }
    sizer = new HandleSizedToData(handleWidget, representation);
  }
  sizer->Radius = HandleSizedToData::DiagonalFraction * dataDiagonal;
}

HandleSizedToData::HandleSizedToData(
  QWidget* handleWidget, vtkPointHandleRepresentation3D* representation)
  : QObject(handleWidget)
  , Representation(representation)
{
  // A box around the cross, so that a part of it lies off any plane through the handle.
  representation->OutlineOn();
  representation->GetProperty()->SetLineWidth(2.0);
  // The view the widget shows in now, and whichever it moves to.
  auto* propertyWidget = static_cast<pqPropertyWidget*>(handleWidget);
  QObject::connect(
    propertyWidget, &pqPropertyWidget::viewChanged, this, &HandleSizedToData::observe);
  this->observe(propertyWidget->view());
}

HandleSizedToData::~HandleSizedToData()
{
  this->stopObserving();
}

void HandleSizedToData::stopObserving()
{
  if (this->Window && this->ObserverTag)
  {
    this->Window->RemoveObserver(this->ObserverTag);
  }
  this->Window = nullptr;
  this->ObserverTag = 0;
}

void HandleSizedToData::observe(pqView* view)
{
  this->stopObserving();
  vtkSMViewProxy* viewProxy = view ? view->getViewProxy() : nullptr;
  vtkRenderWindow* window = viewProxy ? viewProxy->GetRenderWindow() : nullptr;
  if (!window)
  {
    return;
  }
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(&HandleSizedToData::BeforeRender);
  callback->SetClientData(this);
  this->Window = window;
  this->ObserverTag = window->AddObserver(vtkCommand::StartEvent, callback);
}

void HandleSizedToData::BeforeRender(vtkObject*, unsigned long, void* clientData, void*)
{
  auto* self = static_cast<HandleSizedToData*>(clientData);
  vtkPointHandleRepresentation3D* representation = self->Representation;
  vtkRenderer* renderer = representation ? representation->GetRenderer() : nullptr;
  if (!renderer || !renderer->GetActiveCamera() || !(self->Radius > 0.0))
  {
    return; // the widget is not shown in a view
  }
  // The world length of one pixel at the handle's depth.
  double position[3], display[3], beside[4];
  representation->GetWorldPosition(position);
  vtkInteractorObserver::ComputeWorldToDisplay(
    renderer, position[0], position[1], position[2], display);
  vtkInteractorObserver::ComputeDisplayToWorld(
    renderer, display[0] + 1.0, display[1], display[2], beside);
  const double worldPerPixel = std::sqrt(vtkMath::Distance2BetweenPoints(position, beside));
  if (!(worldPerPixel > 0.0) || !std::isfinite(worldPerPixel))
  {
    return;
  }
  // vtkWidgetRepresentation::SizeHandlesInPixels: a handle size of h pixels gives the cross the
  // half-length h / sqrt(2) pixels.
  const double pixels = std::clamp(std::sqrt(2.0) * self->Radius / worldPerPixel,
    std::sqrt(2.0) * HandleSizedToData::MinimumPixels, 1000.0);
  if (std::abs(pixels - representation->GetHandleSize()) > 0.01 * pixels)
  {
    representation->SetHandleSize(pixels);
  }
}
