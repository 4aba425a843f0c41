// The GUI side's handles (with BoostedSurfacesPanelFit; Qt client only). ParaView 5.11's handle
// widget (panel_widget="InteractiveHandle") draws vtkPointHandleRepresentation3D's default: a
// cross 15 pixels wide of lines half a pixel thick, whatever the data's size, hidden inside a
// surface or a slice through it. Its size is in pixels only (HandleSize; ParaView exposes no
// property for it), so HandleSizedToData, attached to one handle widget, gives the cross an
// outline box and thicker lines and, before each render of the widget's view, sets the size in
// pixels that makes the cross a fixed length in the world (a fraction of the data's diagonal) at
// the handle's depth, no smaller than MinimumPixels: the handle is as large as the data, zooms
// with it, and its box shows above and below a slice that holds it. It changes the client's
// representation only (ParaView renders the widgets on the client).
#ifndef BoostedSurfaces_HandleSizedToData_h
#define BoostedSurfaces_HandleSizedToData_h

#include <QObject>

#include "vtkWeakPointer.h"

class pqView;
class vtkObject;
class vtkPointHandleRepresentation3D;
class vtkRenderWindow;

class HandleSizedToData : public QObject
{
  Q_OBJECT

public:
  // The handle's half-length as a fraction of the data's diagonal, and its smallest half-length
  // on the screen.
  static constexpr double DiagonalFraction = 0.05;
  static constexpr double MinimumPixels = 8.0;

  // Sizes the handle of `handleWidget` (a pqHandlePropertyWidget) to data of the given diagonal:
  // the first call attaches a HandleSizedToData to it, later calls update the diagonal. Nothing
  // for a widget that is not a handle or has no representation yet.
  static void Attach(QWidget* handleWidget, double dataDiagonal);

  ~HandleSizedToData() override;

private Q_SLOTS:
  void observe(pqView* view);

private:
  HandleSizedToData(QWidget* handleWidget, vtkPointHandleRepresentation3D* representation);
  void stopObserving();
  // The render window's StartEvent: the size in pixels of this render's camera.
  static void BeforeRender(vtkObject*, unsigned long, void* clientData, void*);

  vtkWeakPointer<vtkPointHandleRepresentation3D> Representation;
  vtkWeakPointer<vtkRenderWindow> Window;
  unsigned long ObserverTag = 0;
  double Radius = 0.0; // the cross's half-length in the world
};

#endif
