# Builds a private MeshLab prefix that loads the plugin from the build tree:
#   PREFIX/bin/{meshlab,meshlabserver}          real copies (Qt resolves symlinks
#                                               when computing the application dir)
#   PREFIX/lib/x86_64-linux-gnu/meshlab/
#       libmeshlab-common.so -> system library
#       plugins/*.so         -> every stock plugin, and ours
# Usage: cmake -DPREFIX=... -DPLUGIN=... -DMESHLAB_LIB_DIR=... -DEXECUTABLES="a|b" -P this
foreach(_var IN ITEMS PREFIX PLUGIN MESHLAB_LIB_DIR EXECUTABLES)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "MakePrivatePrefix.cmake: ${_var} not set")
  endif()
endforeach()

set(_libdir "${PREFIX}/lib/x86_64-linux-gnu/meshlab")
set(_plugindir "${_libdir}/plugins")
file(REMOVE_RECURSE "${_plugindir}")  # drop links to plugins that went away
file(MAKE_DIRECTORY "${PREFIX}/bin" "${_plugindir}")

string(REPLACE "|" ";" _executables "${EXECUTABLES}")
foreach(_exe IN LISTS _executables)
  get_filename_component(_real "${_exe}" REALPATH)
  get_filename_component(_name "${_exe}" NAME)
  set(_dest "${PREFIX}/bin/${_name}")
  if(IS_SYMLINK "${_dest}")
    file(REMOVE "${_dest}")
  endif()
  execute_process(COMMAND "${CMAKE_COMMAND}" -E copy_if_different "${_real}" "${_dest}"
                  RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "cannot copy ${_real} to ${_dest}")
  endif()
endforeach()

file(REMOVE "${_libdir}/libmeshlab-common.so")
file(CREATE_LINK "${MESHLAB_LIB_DIR}/libmeshlab-common.so" "${_libdir}/libmeshlab-common.so" SYMBOLIC)

get_filename_component(_ours "${PLUGIN}" NAME)
file(GLOB _stock "${MESHLAB_LIB_DIR}/plugins/*.so")
set(_count 0)
foreach(_plugin IN LISTS _stock)
  get_filename_component(_name "${_plugin}" NAME)
  if(_name STREQUAL _ours)  # an installed copy of this plugin: use the fresh build instead
    continue()
  endif()
  file(CREATE_LINK "${_plugin}" "${_plugindir}/${_name}" SYMBOLIC)
  math(EXPR _count "${_count} + 1")
endforeach()
file(CREATE_LINK "${PLUGIN}" "${_plugindir}/${_ours}" SYMBOLIC)
message(STATUS "MeshLab prefix ${PREFIX}: ${_count} stock plugins + ${_ours}")
