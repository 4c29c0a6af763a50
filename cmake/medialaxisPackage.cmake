# The installed package: find_package(medialaxis) in another project.
#   medialaxis_install_package(<destination> <vtk.module file>...)
# installs medialaxisConfig.cmake and medialaxisConfigVersion.cmake into <destination>,
# beside the targets file (medialaxis-targets.cmake) and the module properties that
# vtk_module_build(INSTALL_EXPORT MedialAxis) writes there. The config finds what the
# installed libraries link: the VTK modules named in the modules' DEPENDS and
# PRIVATE_DEPENDS (read from the vtk.module files, so the list cannot drift), and
# OpenMP (linked by the static MedialAxis::Core).
include(CMakePackageConfigHelpers)

function (medialaxis_install_package destination)
  set(components)
  set(modules)
  foreach (module_file IN LISTS ARGN)
    file(STRINGS "${module_file}" lines)
    set(section "")
    foreach (line IN LISTS lines)
      if (line MATCHES "^([A-Z_]+)$")
        set(section "${CMAKE_MATCH_1}")
      elseif (section STREQUAL "NAME" AND line MATCHES "^ +(MedialAxis::[A-Za-z]+)")
        list(APPEND modules "${CMAKE_MATCH_1}")
      elseif (section MATCHES "^(DEPENDS|PRIVATE_DEPENDS)$" AND line MATCHES "^ +VTK::([A-Za-z0-9]+)")
        list(APPEND components "${CMAKE_MATCH_1}")
      endif ()
    endforeach ()
  endforeach ()
  list(REMOVE_DUPLICATES components)
  list(SORT components)
  # Space-separated for the template.
  string(REPLACE ";" " " MEDIALAXIS_VTK_COMPONENTS "${components}")
  string(REPLACE ";" " " MEDIALAXIS_MODULES "${modules}")
  set(MEDIALAXIS_VTK_VERSION "${VTK_VERSION_MAJOR}.${VTK_VERSION_MINOR}")
  configure_package_config_file(
    "${CMAKE_SOURCE_DIR}/cmake/medialaxisConfig.cmake.in"
    "${CMAKE_BINARY_DIR}/medialaxisConfig.cmake"
    INSTALL_DESTINATION "${destination}"
    NO_SET_AND_CHECK_MACRO)
  # 0.x: a new minor version may change the API.
  write_basic_package_version_file("${CMAKE_BINARY_DIR}/medialaxisConfigVersion.cmake"
    VERSION "${PROJECT_VERSION}"
    COMPATIBILITY SameMinorVersion)
  install(FILES
    "${CMAKE_BINARY_DIR}/medialaxisConfig.cmake"
    "${CMAKE_BINARY_DIR}/medialaxisConfigVersion.cmake"
    DESTINATION "${destination}")
endfunction ()
