# One function builds every module the same way: gsp_module(NAME name SOURCES ... DEPS ...)
# gives the target gsp_<name> with the alias gsp::<name>, public headers in <dir>/include.
# Each module is also installed as its own component of the CMake package `gsp`
# (cmake/Install.cmake): find_package(gsp COMPONENTS core io) looks up only what those need.
include(GNUInstallDirs)

function(gsp_module)
  cmake_parse_arguments(M "" "NAME;DIR" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  if(NOT M_DIR)
    set(M_DIR ${CMAKE_CURRENT_SOURCE_DIR})
  endif()
  add_library(gsp_${M_NAME} ${M_SOURCES})
  add_library(gsp::${M_NAME} ALIAS gsp_${M_NAME})
  target_include_directories(gsp_${M_NAME} PUBLIC $<BUILD_INTERFACE:${M_DIR}/include>
                                                  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(gsp_${M_NAME} PUBLIC ${M_DEPS} PRIVATE ${M_PRIVATE_DEPS})
  target_compile_options(gsp_${M_NAME} PRIVATE ${GSP_WARNINGS})
  if(GSP_NATIVE)
    target_compile_options(gsp_${M_NAME} PRIVATE -march=native)
  endif()

  set_target_properties(gsp_${M_NAME} PROPERTIES EXPORT_NAME ${M_NAME})
  install(TARGETS gsp_${M_NAME} EXPORT gsp-${M_NAME}-targets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${M_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT gsp-${M_NAME}-targets NAMESPACE gsp:: DESTINATION ${GSP_INSTALL_CMAKEDIR})
  # What the package configuration needs to know to look up this component's dependencies.
  set_property(GLOBAL APPEND PROPERTY GSP_MODULES ${M_NAME})
  set_property(GLOBAL PROPERTY GSP_MODULE_LINKS_${M_NAME} ${M_DEPS} ${M_PRIVATE_DEPS})
endfunction()

# gsp_app(name SOURCES ... DEPS ...): one executable in build/bin, installed to bin/.
function(gsp_app NAME)
  cmake_parse_arguments(A "" "" "SOURCES;DEPS" ${ARGN})
  # Every app allocates its big arrays on huge pages (apps/common/huge_page_new.cpp).
  add_executable(${NAME} ${A_SOURCES} ${PROJECT_SOURCE_DIR}/apps/common/huge_page_new.cpp)
  target_link_libraries(${NAME} PRIVATE ${A_DEPS})
  target_compile_options(${NAME} PRIVATE ${GSP_WARNINGS})
  install(TARGETS ${NAME} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endfunction()

set(GSP_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wno-unused-parameter)
set(GSP_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/gsp)
