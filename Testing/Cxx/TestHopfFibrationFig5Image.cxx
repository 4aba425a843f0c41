// Regression image of the paper's Fig 5: the twistor meshes of six meridians (Paper mode, the
// settings documented in README.md and Examples/fig5_hopf_fibration.py), with a coarse grid of
// fibers drawn over them.
// Usage: TestHopfFibrationFig5Image -V <baseline.png> -T <output directory>
#include "vtkHopfFibrationSource.h"

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
  const double pi = 3.14159265358979323846;
  vtkNew<vtkHopfFibrationSource> mesh; // the Fig 5 preset
  mesh->SetOutputTypeToTwistorMesh();
  mesh->SetThetaResolution(6);
  mesh->SetPhiResolution(96);
  mesh->SetFiberResolution(128);
  mesh->SetClipRadius(3.0);
  vtkNew<vtkPolyDataMapper> meshMapper;
  meshMapper->SetInputConnection(mesh->GetOutputPort());
  meshMapper->SetScalarModeToUsePointFieldData();
  meshMapper->SelectColorArray("StripId");
  meshMapper->SetScalarRange(0, 5);
  vtkNew<vtkActor> meshActor;
  meshActor->SetMapper(meshMapper);

  vtkNew<vtkHopfFibrationSource> fibers;
  fibers->SetThetaResolution(3);
  fibers->SetPhiRange(-3 * pi / 8, 3 * pi / 8);
  fibers->SetPhiResolution(5);
  fibers->SetFiberResolution(256);
  fibers->SetClipRadius(3.0);
  vtkNew<vtkPolyDataMapper> fibersMapper;
  fibersMapper->SetInputConnection(fibers->GetOutputPort());
  fibersMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> fibersActor;
  fibersActor->SetMapper(fibersMapper);
  fibersActor->GetProperty()->SetColor(0.1, 0.1, 0.1);
  fibersActor->GetProperty()->SetLineWidth(2);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(meshActor);
  renderer->AddActor(fibersActor);
  renderer->SetBackground(1, 1, 1);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 400);
  window->AddRenderer(renderer);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.6, -1.0, 0.7);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCamera();
  camera->Zoom(1.25);
  window->Render();

  const int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? 1 : 0;
}
