# What every test of BoostedSurfaces shares: the optional packages the tests need, the functions
# that add GoogleTest, image and Python tests, and the one image-comparison threshold. Included by
# the top CMakeLists.txt when BUILD_TESTING is on, before the modules (whose Testing/ folders
# vtk_module_build adds when their TEST_DEPENDS are there).
include_guard(GLOBAL)

# Optional: without them the library, Python package and plugin still build, and the tests that
# need them are skipped (listed at the end of the configure output).
find_package(GTest QUIET)
find_package(Eigen3 QUIET NO_MODULE)
find_package(nlohmann_json QUIET)
if (TARGET GTest::gtest_main)
  include(GoogleTest)
endif ()

# The image-comparison policy, for the C++, Python and ParaView tests alike: a rendered image
# passes when vtkImageDifference's thresholded error against its baseline
# (Testing/Data/Baseline/<name>.png) is at most this. A missing baseline fails after writing the
# image to the output directory; copy it to Testing/Data/Baseline/ to make the baseline.
set(BOOSTEDSURFACES_IMAGE_THRESHOLD 0.05)
set(BOOSTEDSURFACES_BASELINE_DIR "${PROJECT_SOURCE_DIR}/Testing/Data/Baseline")
set(BOOSTEDSURFACES_TEST_OUTPUT_DIR "${CMAKE_BINARY_DIR}/Testing/Temporary")
file(MAKE_DIRECTORY "${BOOSTEDSURFACES_TEST_OUTPUT_DIR}")
# The helpers both modules' tests share (C++ headers and python_test_common.py).
set(BOOSTEDSURFACES_TEST_SUPPORT_DIR "${PROJECT_SOURCE_DIR}/Testing/Support")

# boostedsurfaces_skip_test(<what> <missing package>): remember a test that is not built.
function (boostedsurfaces_skip_test what missing)
  set_property(GLOBAL APPEND PROPERTY boostedsurfaces_skipped_tests "${missing} not found, skipping ${what}")
endfunction ()

# Prints the tests that boostedsurfaces_skip_test recorded; called once at the end of configuring.
function (boostedsurfaces_report_skipped_tests)
  get_property(skipped GLOBAL PROPERTY boostedsurfaces_skipped_tests)
  foreach (test IN LISTS skipped)
    message(STATUS "BoostedSurfaces: ${test}")
  endforeach ()
endfunction ()

# vtk_module_build adds a module's Testing/ folder only when every TEST_DEPENDS of its vtk.module
# is a target, and says nothing otherwise: record such modules as skipped.
function (boostedsurfaces_skip_modules_without_test_depends)
  foreach (module IN LISTS ARGN)
    get_property(test_depends GLOBAL PROPERTY "_vtk_module_${module}_test_depends") # VTK's record
    foreach (depend IN LISTS test_depends)
      if (NOT TARGET "${depend}")
        boostedsurfaces_skip_test("the tests of ${module} (its Testing/ folder)" "${depend}")
      endif ()
    endforeach ()
  endforeach ()
endfunction ()

# Every test that opens a render window shares the one Xvfb display of a test run; several render
# windows starting on it at once fail ("bad X server connection"), so under ctest -j they take turns.
function (boostedsurfaces_mark_rendering_test name)
  set_tests_properties("${name}" PROPERTIES LABELS "image" RESOURCE_LOCK boostedsurfaces_x_display)
endfunction ()

# boostedsurfaces_add_gtest(<name> <prefix> <libraries>...): the GoogleTest executable <name>.cxx
# of the current folder linked to the libraries (and VTK's common modules); its tests are the
# ctest names <prefix>.<Suite>.<Test>.
function (boostedsurfaces_add_gtest name prefix)
  if (NOT TARGET GTest::gtest_main)
    boostedsurfaces_skip_test("the ${prefix}.* tests of ${name}" GTest)
    return ()
  endif ()
  add_executable(${name} ${name}.cxx)
  # Testing/Support, and the kernel tests' helpers (CGA/Testing/TestSupport.h: seeded random
  # inputs, relative comparisons), so that no test keeps a copy of them.
  target_include_directories(${name} PRIVATE
    "${BOOSTEDSURFACES_TEST_SUPPORT_DIR}" "${PROJECT_SOURCE_DIR}/CGA/Testing")
  target_compile_definitions(${name} PRIVATE
    BOOSTED_CGA_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/CGA/Testing/Data")
  target_link_libraries(${name} PRIVATE ${ARGN} VTK::CommonCore VTK::CommonDataModel
    VTK::CommonExecutionModel GTest::gtest_main)
  gtest_discover_tests(${name} TEST_PREFIX "${prefix}." DISCOVERY_TIMEOUT 60)
endfunction ()

# boostedsurfaces_add_image_test(<name> <libraries>...): Image.<name>, the C++ regression image
# <name>.cxx of the current folder against Testing/Data/Baseline/<name>.png (`-V` baseline, `-T`
# output directory, as vtkRegressionTestImage reads them).
function (boostedsurfaces_add_image_test name)
  add_executable(${name} ${name}.cxx)
  target_include_directories(${name} PRIVATE "${BOOSTEDSURFACES_TEST_SUPPORT_DIR}")
  target_compile_definitions(${name} PRIVATE
    BOOSTEDSURFACES_IMAGE_THRESHOLD=${BOOSTEDSURFACES_IMAGE_THRESHOLD})
  target_link_libraries(${name} PRIVATE ${ARGN}
    VTK::CommonCore VTK::CommonExecutionModel VTK::RenderingCore VTK::RenderingOpenGL2
    VTK::InteractionStyle VTK::TestingRendering)
  vtk_module_autoinit(TARGETS ${name} MODULES VTK::RenderingOpenGL2 VTK::InteractionStyle)
  add_test(NAME Image.${name}
    COMMAND ${name} -V "${BOOSTEDSURFACES_BASELINE_DIR}/${name}.png"
                    -T "${BOOSTEDSURFACES_TEST_OUTPUT_DIR}")
  boostedsurfaces_mark_rendering_test(Image.${name})
endfunction ()

# boostedsurfaces_add_python_test(<name> <script> <arguments>...): Python.<name>, the script of
# the current folder run by the build tree's package with /usr/bin/python3 (the interpreter that
# has ParaView's vtkmodules), never an installed copy, with Testing/Support (python_test_common)
# on the path. Not in the sanitizer build (see boostedsurfaces_add_sanitized_python_test).
function (boostedsurfaces_add_python_test name script)
  if (BOOSTEDSURFACES_SANITIZE)
    return ()
  endif ()
  boostedsurfaces_python_test_command(${name} ${script} ${ARGN})
endfunction ()

# boostedsurfaces_add_sanitized_python_test(<name> <script> <arguments>...): in the sanitizer build
# only, Python.<name> as boostedsurfaces_add_python_test's, in a Python that preloads GCC's
# AddressSanitizer runtime (it must come first in a process whose modules are instrumented) and
# libstdc++ (without it the runtime, started before any C++ library, cannot pass on a C++
# exception: its __cxa_throw check fails, as in vtkArrayCalculator's parser), and does not look
# for leaks (the interpreter's own allocations live to its end). With another compiler, or
# without those libraries, the test is skipped.
function (boostedsurfaces_add_sanitized_python_test name script)
  if (NOT BOOSTEDSURFACES_SANITIZE)
    return ()
  endif ()
  set(preload "")
  foreach (library IN ITEMS libasan.so libstdc++.so)
    set(path "")
    if (CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      execute_process(COMMAND "${CMAKE_CXX_COMPILER}" -print-file-name=${library}
        OUTPUT_VARIABLE path OUTPUT_STRIP_TRAILING_WHITESPACE)
    endif ()
    if (NOT IS_ABSOLUTE "${path}" OR NOT EXISTS "${path}")
      boostedsurfaces_skip_test("Python.${name}" "GCC's ${library}")
      return ()
    endif ()
    list(APPEND preload "${path}")
  endforeach ()
  list(JOIN preload ":" preload)
  boostedsurfaces_python_test_command(${name} ${script} ${ARGN})
  set_property(TEST Python.${name} APPEND PROPERTY ENVIRONMENT
    "LD_PRELOAD=${preload}" "ASAN_OPTIONS=detect_leaks=0")
endfunction ()

# The test both add: the script, its arguments and PYTHONPATH.
function (boostedsurfaces_python_test_command name script)
  add_test(NAME Python.${name}
    COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/${script}" ${ARGN})
  set_tests_properties(Python.${name} PROPERTIES ENVIRONMENT
    "PYTHONPATH=${BOOSTEDSURFACES_PYTHONPATH}:${BOOSTEDSURFACES_TEST_SUPPORT_DIR}")
endfunction ()

# boostedsurfaces_add_python_image_test(<name> <script> <baseline png> <arguments>...): a Python
# regression image, compared with Testing/Data/Baseline/<baseline png> under the one threshold.
function (boostedsurfaces_add_python_image_test name script baseline)
  if (BOOSTEDSURFACES_SANITIZE)
    return ()
  endif ()
  boostedsurfaces_add_python_test(${name} ${script} ${ARGN}
    --baseline "${BOOSTEDSURFACES_BASELINE_DIR}/${baseline}"
    --output-dir "${BOOSTEDSURFACES_TEST_OUTPUT_DIR}"
    --threshold ${BOOSTEDSURFACES_IMAGE_THRESHOLD})
  boostedsurfaces_mark_rendering_test(Python.${name})
endfunction ()
