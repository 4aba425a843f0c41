// Regression image of the paper's Fig 2 (lambda in [0, 2]) and a Fig 1 family of circles.
// Usage: TestBoostedSurfaceSourceImage -V <baseline.png> -T <output directory>
#include "vtkBoostedSurfaceSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

int main(int argc, char* argv[])
{
  vtkNew<vtkBoostedSurfaceSource> surface; // Fig 2: yz circle boosted along x, lambda in [0, 2]
  vtkNew<vtkPolyDataMapper> surfaceMapper;
  surfaceMapper->SetInputConnection(surface->GetOutputPort());
  surfaceMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> surfaceActor;
  surfaceActor->SetMapper(surfaceMapper);
  surfaceActor->GetProperty()->SetColor(0.85, 0.55, 0.3);

  vtkNew<vtkBoostedSurfaceSource> circles; // Fig 1: xy circle boosted in its plane
  circles->SetCircleCenter(0, -3.5, 0);
  circles->SetCircleNormal(0, 0, 1);
  circles->SetLambdaRange(-3, 3);
  circles->SetLambdaResolution(24);
  circles->SetThetaResolution(256);
  circles->SetClipRadius(4);
  circles->SetOutputTypeToCircles();
  vtkNew<vtkPolyDataMapper> circlesMapper;
  circlesMapper->SetInputConnection(circles->GetOutputPort());
  circlesMapper->SetScalarModeToUsePointFieldData();
  circlesMapper->SelectColorArray("lambda");
  circlesMapper->SetScalarRange(-3, 3);
  vtkNew<vtkActor> circlesActor;
  circlesActor->SetMapper(circlesMapper);
  circlesActor->GetProperty()->SetLineWidth(2);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(surfaceActor);
  renderer->AddActor(circlesActor);
  renderer->SetBackground(1, 1, 1);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 400);
  window->AddRenderer(renderer);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);

  renderer->ResetCamera();
  renderer->GetActiveCamera()->Elevation(-20);
  renderer->ResetCamera();
  window->Render();

  const int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? 1 : 0;
}
