// Regression image of the paper's Fig 2 (lambda in [0, 2]) and a Fig 1 family of circles.
// Usage: TestBoostedSurfaceSourceImage -V <baseline.png> -T <output directory>
#include "vtkBoostedSurfaceSource.h"

#include "RegressionScene.h"

int main(int argc, char* argv[])
{
  vtkNew<vtkBoostedSurfaceSource> surface; // Fig 2: yz circle boosted along x, lambda in [0, 2]

  vtkNew<vtkBoostedSurfaceSource> circles; // Fig 1: xy circle boosted in its plane
  circles->SetCircleCenter(0, -3.5, 0);
  circles->SetCircleNormal(0, 0, 1);
  circles->SetLambdaRange(-3, 3);
  circles->SetLambdaResolution(24);
  circles->SetThetaResolution(256);
  circles->SetClipRadius(4);
  circles->SetOutputTypeToCircles();

  RegressionScene scene(400, 400);
  scene.renderer->AddActor(PlainActor(surface, 0.85, 0.55, 0.3));
  auto circlesActor = ColoredActor(circles, "lambda", -3, 3);
  circlesActor->GetProperty()->SetLineWidth(2);
  scene.renderer->AddActor(circlesActor);

  scene.renderer->ResetCamera();
  scene.renderer->GetActiveCamera()->Elevation(-20);
  scene.renderer->ResetCamera();
  return scene.RenderAndCompare(argc, argv);
}
