// Shared by the C++ regression-image tests: a white scene in a window of a given size, the two
// kinds of actor they draw, and the comparison with the baseline named by `-V` (the rendered image
// goes to `-T`), as vtkRegressionTestImage does, under the project's one image threshold.
#ifndef RegressionScene_h
#define RegressionScene_h

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

struct RegressionScene
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderWindowInteractor> interactor;

  RegressionScene(int width, int height)
  {
    renderer->SetBackground(1, 1, 1);
    window->SetSize(width, height);
    window->AddRenderer(renderer);
    interactor->SetRenderWindow(window);
  }

  // The camera looks at the origin from `position`, +z up, then is fitted to the actors and zoomed.
  void LookAtOriginFrom(double x, double y, double z, double zoom)
  {
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(x, y, z);
    camera->SetFocalPoint(0, 0, 0);
    camera->SetViewUp(0, 0, 1);
    renderer->ResetCamera();
    camera->Zoom(zoom);
  }

  // Renders and compares with the baseline; the exit code of the test (0: passed).
  int RenderAndCompare(int argc, char* argv[])
  {
    window->Render();
    // The one threshold of every image test, from CMake/BoostedSurfacesTesting.cmake.
    const int result = vtkRegressionTestImageThreshold(window, BOOSTEDSURFACES_IMAGE_THRESHOLD);
    if (result == vtkRegressionTester::DO_INTERACTOR)
    {
      interactor->Start();
    }
    return result == vtkRegressionTester::FAILED ? 1 : 0;
  }
};

// The output of `source` coloured by its point array `pointArray` over [low, high].
inline vtkSmartPointer<vtkActor> ColoredActor(
  vtkAlgorithm* source, const char* pointArray, double low, double high)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray(pointArray);
  mapper->SetScalarRange(low, high);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  return actor.Get();
}

// The output of `source` in one colour.
inline vtkSmartPointer<vtkActor> PlainActor(vtkAlgorithm* source, double r, double g, double b)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  return actor.Get();
}

#endif
