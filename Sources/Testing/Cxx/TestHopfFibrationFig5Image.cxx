// Regression image of the paper's Fig 5: the twistor meshes of six meridians (Paper mode, the
// settings documented in README.md and Examples/fig5_hopf_fibration.py), with a coarse grid of
// fibers drawn over them.
// Usage: TestHopfFibrationFig5Image -V <baseline.png> -T <output directory>
#include "vtkHopfFibrationSource.h"

#include "RegressionScene.h"

int main(int argc, char* argv[])
{
  const double pi = 3.14159265358979323846;
  vtkNew<vtkHopfFibrationSource> mesh; // the Fig 5 preset
  mesh->SetOutputTypeToTwistorMesh();
  mesh->SetThetaResolution(6);
  mesh->SetPhiResolution(96);
  mesh->SetFiberResolution(128);
  mesh->SetClipRadius(3.0);

  vtkNew<vtkHopfFibrationSource> fibers;
  fibers->SetThetaResolution(3);
  fibers->SetPhiRange(-3 * pi / 8, 3 * pi / 8);
  fibers->SetPhiResolution(5);
  fibers->SetFiberResolution(256);
  fibers->SetClipRadius(3.0);

  RegressionScene scene(400, 400);
  scene.renderer->AddActor(ColoredActor(mesh, "StripId", 0, 5));
  auto fibersActor = PlainActor(fibers, 0.1, 0.1, 0.1);
  fibersActor->GetProperty()->SetLineWidth(2);
  scene.renderer->AddActor(fibersActor);
  scene.LookAtOriginFrom(0.6, -1.0, 0.7, 1.25);
  return scene.RenderAndCompare(argc, argv);
}
