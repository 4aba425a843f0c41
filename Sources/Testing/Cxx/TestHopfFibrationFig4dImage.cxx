// Regression image of the paper's Fig 4d: the twistor mesh swept by the fibers over one meridian
// (theta = 0), with the fibers of nine latitudes drawn over it, Paper mode.
// Usage: TestHopfFibrationFig4dImage -V <baseline.png> -T <output directory>
#include "vtkHopfFibrationSource.h"

#include "RegressionScene.h"

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

  vtkNew<vtkHopfFibrationSource> fibers;
  fibers->SetThetaRange(0.0, 0.0);
  fibers->SetThetaResolution(1);
  fibers->SetPhiResolution(9);
  fibers->SetFiberResolution(256);
  fibers->SetClipRadius(2.2);

  RegressionScene scene(400, 400);
  scene.renderer->AddActor(ColoredActor(mesh, "phi", -pi / 2, pi / 2));
  auto fibersActor = PlainActor(fibers, 0.1, 0.1, 0.1);
  fibersActor->GetProperty()->SetLineWidth(2);
  scene.renderer->AddActor(fibersActor);
  scene.LookAtOriginFrom(0.35, -1.0, 0.45, 1.2);
  return scene.RenderAndCompare(argc, argv);
}
