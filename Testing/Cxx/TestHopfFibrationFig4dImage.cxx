// Regression image of the paper's Fig 4d: the twistor mesh swept by the fibers over one meridian
// (theta = 0), with the fibers of nine latitudes drawn over it, Paper mode.
// Usage: TestHopfFibrationFig4dImage -V <baseline.png> -T <output directory>
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
  vtkNew<vtkHopfFibrationSource> mesh;
  mesh->SetOutputTypeToTwistorMesh();
  mesh->SetThetaRange(0.0, 0.0);
  mesh->SetThetaResolution(1);
  mesh->SetPhiResolution(64);
  mesh->SetFiberResolution(128);
  mesh->SetClipRadius(2.2);
  vtkNew<vtkPolyDataMapper> meshMapper;
  meshMapper->SetInputConnection(mesh->GetOutputPort());
  meshMapper->SetScalarModeToUsePointFieldData();
  meshMapper->SelectColorArray("phi");
  meshMapper->SetScalarRange(-pi / 2, pi / 2);
  vtkNew<vtkActor> meshActor;
  meshActor->SetMapper(meshMapper);

  vtkNew<vtkHopfFibrationSource> fibers;
  fibers->SetThetaRange(0.0, 0.0);
  fibers->SetThetaResolution(1);
  fibers->SetPhiResolution(9);
  fibers->SetFiberResolution(256);
  fibers->SetClipRadius(2.2);
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
  camera->SetPosition(0.35, -1.0, 0.45);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCamera();
  camera->Zoom(1.2);
  window->Render();

  const int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? 1 : 0;
}
