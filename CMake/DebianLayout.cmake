# Run by CPack (CPACK_PRE_BUILD_SCRIPTS, from CMake/Packaging.cmake) on its staging tree, after
# the install rules ran and before the .deb is packed: moves the Python package and the plugin to
# where Debian's python3 and ParaView look, and links the plugin into ParaView's auto-load folder.
# The libraries, headers and CMake package stay where the install rules put them (/usr/lib,
# /usr/include, /usr/lib/cmake), so the CMake package's relative paths stay true.

set(usr "${CPACK_TEMPORARY_DIRECTORY}${CPACK_PACKAGING_INSTALL_PREFIX}")
if (NOT IS_DIRECTORY "${usr}/${CPACK_BOOSTEDSURFACES_PYTHON_DIR}/boostedsurfaces")
  message(FATAL_ERROR "DebianLayout: no Python package in the staging tree ${usr}")
endif ()

# mv <from> <to> (both relative to /usr), then drops the folders <from> leaves empty.
function (move_into_place from to)
  get_filename_component(parent "${usr}/${to}" DIRECTORY)
  file(MAKE_DIRECTORY "${parent}")
  file(RENAME "${usr}/${from}" "${usr}/${to}")
  get_filename_component(folder "${usr}/${from}" DIRECTORY)
  while (NOT folder STREQUAL usr)
    file(GLOB left "${folder}/*")
    if (left)
      break ()
    endif ()
    file(REMOVE_RECURSE "${folder}")
    get_filename_component(folder "${folder}" DIRECTORY)
  endwhile ()
endfunction ()

# Python: /usr/bin/python3 imports from /usr/lib/python3/dist-packages. The modules' RPATH
# $ORIGIN/../../.. is /usr/lib there, where the libraries are.
move_into_place("${CPACK_BOOSTEDSURFACES_PYTHON_DIR}/boostedsurfaces"
  "lib/python3/dist-packages/boostedsurfaces")

# The plugin, beside Debian's ParaView plugins. Its RPATH ($ORIGIN and the folders up to lib/ of
# the install tree) becomes the one folder of the libraries from there, /usr/lib.
set(plugin_dir "${CPACK_BOOSTEDSURFACES_MULTIARCH_PLUGIN_DIR}/BoostedSurfaces")
move_into_place("${CPACK_BOOSTEDSURFACES_PLUGIN_DIR}/BoostedSurfaces" "${plugin_dir}")
file(GLOB plugin_libraries "${usr}/${plugin_dir}/*.so")
foreach (library IN LISTS plugin_libraries)
  file(RPATH_SET FILE "${library}" NEW_RPATH "$ORIGIN/../../../..")
endforeach ()

# Auto-loading: ParaView loads every plugin folder of <folder of its executable>/plugins, the only
# folder it searches without an environment variable; lintian's subdir-in-usr-bin for it is
# overridden, with that reason (CMake/debian/lintian-overrides).
file(MAKE_DIRECTORY "${usr}/bin/plugins")
file(RELATIVE_PATH link_target "${usr}/bin/plugins" "${usr}/${plugin_dir}")
file(CREATE_LINK "${link_target}" "${usr}/bin/plugins/BoostedSurfaces" SYMBOLIC)
file(MAKE_DIRECTORY "${usr}/share/lintian/overrides")
file(COPY_FILE "${CPACK_BOOSTEDSURFACES_DEBIAN_DIR}/lintian-overrides"
  "${usr}/share/lintian/overrides/boostedsurfaces")

# The copyright file (machine-readable, DEP-5): the holders, and that no licence is granted yet.
file(COPY_FILE "${CPACK_BOOSTEDSURFACES_DEBIAN_DIR}/copyright"
  "${usr}/share/doc/boostedsurfaces/copyright")

# The changelog, as Debian's policy asks: gzip -9n (no name or time stamp in the header).
find_program(gzip gzip REQUIRED)
execute_process(COMMAND "${gzip}" -9nc "${CPACK_BOOSTEDSURFACES_CHANGELOG}"
  OUTPUT_FILE "${usr}/share/doc/boostedsurfaces/changelog.gz" RESULT_VARIABLE gzip_result)
if (NOT gzip_result EQUAL 0)
  message(FATAL_ERROR "DebianLayout: gzip of ${CPACK_BOOSTEDSURFACES_CHANGELOG} failed")
endif ()
