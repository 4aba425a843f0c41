# The Debian package: `cpack -G DEB` in the build tree writes boostedsurfaces_<version>_amd64.deb
# from the same install rules as `cmake --install`, laid out as Debian's own ParaView plugin and
# Python packages are (CMake/DebianLayout.cmake moves the files in CPack's staging tree):
#   /usr/lib/x86_64-linux-gnu/paraview-5.11/plugins/BoostedSurfaces/   the plugin, beside Debian's
#   /usr/bin/plugins/BoostedSurfaces -> the folder above                 auto-loaded (see below)
#   /usr/lib/python3/dist-packages/boostedsurfaces/                     `import boostedsurfaces`
#   /usr/lib/libBoostedSurfaces*.so, /usr/include/boostedsurfaces/      the libraries and headers
#   /usr/lib/cmake/BoostedSurfaces/                                     find_package(BoostedSurfaces)
#   /usr/share/doc/boostedsurfaces/                                     README, docs/, changelog.gz,
#                                                                       copyright (debian/copyright)
#   /usr/share/lintian/overrides/boostedsurfaces                        debian/lintian-overrides
# Debian's ParaView 5.11 reads no plugin configuration file of its own (no paraview.conf, and its
# plugins/paraview.plugins.xml is not read); what it loads at start-up, in the GUI, pvpython,
# pvbatch and pvserver alike, are the plugins in PV_PLUGIN_PATH and in <executable's folder>/plugins,
# so the package links /usr/bin/plugins/BoostedSurfaces to the plugin's folder (lintian's
# subdir-in-usr-bin, overridden with that reason).
include_guard(GLOBAL)

# The documentation (in `cmake --install`'s tree too), laid out as in the repository so that the
# README's links (docs/conventions.md, docs/classes/*.png) resolve where it is installed.
install(FILES README.md DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/doc/boostedsurfaces")
install(FILES docs/architecture.md docs/benchmark-runs.md docs/conventions.md docs/performance.md
  docs/gallery.png docs/many_generators.png
  DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/doc/boostedsurfaces/docs")
install(DIRECTORY docs/classes/ DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/doc/boostedsurfaces/docs/classes"
  FILES_MATCHING PATTERN "*.png")

find_program(BOOSTEDSURFACES_DPKG_QUERY dpkg-query)
if (NOT BOOSTEDSURFACES_DPKG_QUERY OR NOT ParaView_FOUND OR NOT BOOSTEDSURFACES_BUILD_PLUGIN)
  message(STATUS "BoostedSurfaces: no Debian package (needs dpkg and the ParaView plugin)")
  return ()
endif ()
# The plugin and the modules work with the ParaView they were built against only: its upstream
# version, any Debian revision, as Debian's own ParaView plugins pin it (5.11.0+dfsg-1+b1 gives
# (>= 5.11.0+dfsg), (<< 5.11.0+dfsg.)).
execute_process(COMMAND "${BOOSTEDSURFACES_DPKG_QUERY}" -W "-f=\${Version}" paraview
  OUTPUT_VARIABLE boostedsurfaces_paraview_version RESULT_VARIABLE boostedsurfaces_dpkg_result ERROR_QUIET)
if (NOT boostedsurfaces_dpkg_result EQUAL 0 OR NOT boostedsurfaces_paraview_version)
  message(STATUS "BoostedSurfaces: no Debian package (ParaView is not Debian's package `paraview`)")
  return ()
endif ()
string(REGEX REPLACE "-[^-]*$" "" boostedsurfaces_paraview_upstream "${boostedsurfaces_paraview_version}")
set(boostedsurfaces_python_version "${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}")
math(EXPR boostedsurfaces_python_next_minor "${Python3_VERSION_MINOR} + 1")

set(BOOSTEDSURFACES_DEBIAN_PACKAGE ON)  # Testing/Install adds Install.DebianPackage
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME boostedsurfaces)
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
# Debian wants a name and an e-mail address; the project has no public address yet.
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "BoostedSurfaces developers <boostedsurfaces@localhost>")
set(CPACK_PACKAGE_CONTACT "${CPACK_DEBIAN_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "ParaView plugin and VTK classes for boosted surfaces")
set(CPACK_PACKAGE_DESCRIPTION [[
Point pairs of conformal geometric algebra, exponentiated into boosts,
bend lines into circles and sweep circles into surfaces (P. Colapinto,
Boosted Surfaces, 2014). VTK sources, a deformation filter and a filter
that fits generators to a target shape (Ceres Solver), the Python
package boostedsurfaces, and the ParaView plugin BoostedSurfaces (Sources
and Filters > Boosted Surfaces), loaded automatically by ParaView 5.11.]])
set(CPACK_STRIP_FILES ON)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # boostedsurfaces_<version>_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# dpkg-shlibdeps adds the libraries' packages: libc6, libstdc++6, ... and, from paraview's shlibs
# file, paraview (>= <upstream>), paraview (<< <upstream>.). The rest is what no ELF file says: the
# Python modules need ParaView's vtkmodules (python3-paraview, the same version) and the python3
# whose minor version they were built for. libceres3 (Ceres Solver, the fit filter's solver) is
# named too although dpkg-shlibdeps finds it from libBoostedSurfacesFilters.so: the one library
# outside Debian's ParaView stack that the package needs at run time, visible here.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
set(CPACK_DEBIAN_PACKAGE_DEPENDS
  "libceres3, python3-paraview (>= ${boostedsurfaces_paraview_upstream}), python3-paraview (<< ${boostedsurfaces_paraview_upstream}.), python3 (>= ${boostedsurfaces_python_version}), python3 (<< ${Python3_VERSION_MAJOR}.${boostedsurfaces_python_next_minor})")
# The shared libraries in /usr/lib: a shlibs file (so that packages built against them depend on
# this version or later) and dpkg's ldconfig trigger (CMake/debian/triggers). CPack still writes
# its postinst/postrm calling ldconfig, which it adds for every package with libraries in /usr/lib
# unless the package brings scripts of its own; lintian notes them as maintscript-calls-ldconfig
# (scripts of our own would be empty: maintainer-script-empty). CPack warns (dev) that the Python
# modules and the plugin have no SONAME: they are modules, not libraries, and rightly not in shlibs.
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS_POLICY ">=")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA "${CMAKE_CURRENT_LIST_DIR}/debian/triggers")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
# The package's changelog: CMake/DebianLayout.cmake writes it, compressed, into the package's doc
# folder (a native package: the version has no Debian revision, so it is changelog.gz).
configure_file("${CMAKE_CURRENT_LIST_DIR}/debian/changelog.in"
  "${CMAKE_BINARY_DIR}/debian/changelog" @ONLY)
set(CPACK_BOOSTEDSURFACES_CHANGELOG "${CMAKE_BINARY_DIR}/debian/changelog")
# The copyright file and the lintian overrides, copied into the package by DebianLayout.cmake.
set(CPACK_BOOSTEDSURFACES_DEBIAN_DIR "${CMAKE_CURRENT_LIST_DIR}/debian")
# Read by CMake/DebianLayout.cmake, which CPack runs on its staging tree before packing it.
set(CPACK_PRE_BUILD_SCRIPTS "${CMAKE_CURRENT_LIST_DIR}/DebianLayout.cmake")
set(CPACK_BOOSTEDSURFACES_PYTHON_DIR "${boostedsurfaces_python_destination}")
set(CPACK_BOOSTEDSURFACES_PLUGIN_DIR
  "${CMAKE_INSTALL_LIBDIR}/paraview-${ParaView_VERSION_MAJOR}.${ParaView_VERSION_MINOR}/plugins")
set(CPACK_BOOSTEDSURFACES_MULTIARCH_PLUGIN_DIR
  "lib/${CMAKE_LIBRARY_ARCHITECTURE}/paraview-${ParaView_VERSION_MAJOR}.${ParaView_VERSION_MINOR}/plugins")

include(CPack)
