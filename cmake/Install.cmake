# The CMake package `gsp` for a user's project:
#
#   find_package(gsp 0.1 REQUIRED COMPONENTS core io)   # or no COMPONENTS: every installed one
#   target_link_libraries(app PRIVATE gsp::core gsp::io)
#
# One export file per module (cmake/GspModule.cmake); this writes gsp-config.cmake, which
# loads the requested components with the components they link and looks up only the
# packages those need: gsp::core needs nothing but Threads.

# The find_package call for each dependency target a module may link. A module linking a
# target that is not here stops the configuration, so the table cannot fall out of date.
set(_gsp_find_Threads::Threads "Threads")
set(_gsp_find_TinyGLTF::TinyGLTF "TinyGLTF")
set(_gsp_find_embree "embree 3")
set(_gsp_find_PNG::PNG "PNG")
set(_gsp_find_CLI11::CLI11 "CLI11")
set(_gsp_find_nanoflann::nanoflann "nanoflann")
set(_gsp_find_Eigen3::Eigen "Eigen3 3.3 NO_MODULE")
set(_gsp_find_CGAL::CGAL "CGAL COMPONENTS Core")
set(_gsp_find_OpenMeshCore "OpenMesh CONFIG")

function(gsp_write_package_config)
  get_property(modules GLOBAL PROPERTY GSP_MODULES)
  set(tables "")
  foreach(module IN LISTS modules)
    get_property(links GLOBAL PROPERTY GSP_MODULE_LINKS_${module})
    set(components "")
    set(finds "")
    foreach(link IN LISTS links)
      if(link MATCHES "^gsp::(.+)$")
        list(APPEND components ${CMAKE_MATCH_1})
      elseif(link STREQUAL "CGAL::Eigen3_support")
        # Defined by CGAL's module file, not by a package of its own.
        string(APPEND finds "  find_dependency(Eigen3 3.3 NO_MODULE)\n  include(CGAL_Eigen3_support)\n")
      elseif(DEFINED _gsp_find_${link})
        string(APPEND finds "  find_dependency(${_gsp_find_${link}})\n")
      else()
        message(FATAL_ERROR "gsp::${module} links ${link}: add its find_package call to cmake/Install.cmake")
      endif()
    endforeach()
    list(REMOVE_DUPLICATES components)
    string(APPEND tables "set(_gsp_links_${module} \"${components}\")\nmacro(_gsp_find_${module})\n${finds}endmacro()\n")
  endforeach()
  set(GSP_COMPONENT_TABLES "${tables}")
  set(GSP_COMPONENTS "${modules}")
  include(CMakePackageConfigHelpers)
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/gsp-config.cmake.in
    ${PROJECT_BINARY_DIR}/gsp-config.cmake INSTALL_DESTINATION ${GSP_INSTALL_CMAKEDIR})
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/gsp-config-version.cmake
    COMPATIBILITY SameMinorVersion)   # 0.x: a minor version may change the API
  install(FILES ${PROJECT_BINARY_DIR}/gsp-config.cmake ${PROJECT_BINARY_DIR}/gsp-config-version.cmake
          DESTINATION ${GSP_INSTALL_CMAKEDIR})
endfunction()

gsp_write_package_config()
