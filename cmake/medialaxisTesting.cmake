# Settings shared by every module's C++ test executable.
#   medialaxis_test_settings(<executable> <module> [<test that may skip> ...])
# Tests include the shared support in Testing/Cxx, know where the shared meshes are,
# and a test listed after the module exits with MEDIALAXIS_SKIP_RETURN_CODE to be
# reported as skipped when those meshes are absent.
function (medialaxis_test_settings executable module)
  target_include_directories(${executable} PRIVATE "${CMAKE_SOURCE_DIR}/Testing/Cxx")
  target_compile_definitions(${executable} PRIVATE
    "MEDIALAXIS_SHARED_MESH_DIR=\"${MEDIALAXIS_SHARED_MESH_DIR}\""
    "MEDIALAXIS_SKIP_RETURN_CODE=${MEDIALAXIS_SKIP_RETURN_CODE}")
  foreach (test IN LISTS ARGN)
    set_tests_properties("${module}Cxx-${test}" PROPERTIES SKIP_RETURN_CODE ${MEDIALAXIS_SKIP_RETURN_CODE})
  endforeach ()
endfunction ()
