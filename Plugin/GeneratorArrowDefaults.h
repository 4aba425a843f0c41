// The plugin's load-time hook (paraview_add_plugin INITIALIZERS): aims and sizes the arrows of
// every Generators port when ParaView shows it, in the GUI, pvpython and pvbatch alike.
//
// ParaView 5.11's "3D Glyphs" representation starts with Orient and Scaling off (unit arrows along
// x), and a proxy's XML hints can only pick the representation type, not its properties. So the
// plugin watches the server manager's representation registrations: a representation whose input
// is an output port that its producer's XML hints name with
//   <GeneratorArrows port="N" orientation_array="Direction" />
// gets Orient on (by that array, Direction mode) and Scaling on with one arrow length for all,
// 0.2 times the largest extent of the producer's first output and of the generators together.
// Only properties still at their XML defaults are set, and never while a state file is loaded,
// so a saved or user-chosen value always wins.
#ifndef BoostedSurfaces_GeneratorArrowDefaults_h
#define BoostedSurfaces_GeneratorArrowDefaults_h

// Installs the hook once per process (a no-op where there is no server manager, e.g. pvserver).
void BoostedSurfacesInstallGeneratorArrowDefaults();

#endif
