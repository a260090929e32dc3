# Tests of gsp::core's mesh pieces: topology report, welding, cache layout. Tiny meshes are
# built in code (helpers/mesh_builders.hpp); the shared-data test also needs the readers.
gsp_test(core_topology SOURCES core_topology.cpp DEPS gsp::core)
gsp_test(core_weld SOURCES core_weld.cpp DEPS gsp::core)
gsp_test(core_coordinate_range SOURCES core_coordinate_range.cpp DEPS gsp::core)
gsp_test(core_layout SOURCES core_layout.cpp DEPS gsp::core)
gsp_test(core_intrinsic SOURCES core_intrinsic.cpp DEPS gsp::core)
gsp_test(core_saddle_creases SOURCES core_saddle_creases.cpp DEPS gsp::core)
gsp_test(core_surface_point SOURCES core_surface_point.cpp DEPS gsp::core)
gsp_test(core_side_by_side SOURCES core_side_by_side.cpp DEPS gsp::core Threads::Threads)
target_include_directories(core_side_by_side PRIVATE ${PROJECT_SOURCE_DIR}/libgsp/src)
gsp_test(core_shared_meshes SOURCES core_shared_meshes.cpp DEPS gsp::core gsp::io)

# Not a test: prints the layout's locality and run time on every shared mesh (docs/layout.md).
add_executable(gsp-layout-report layout_report.cpp)
target_link_libraries(gsp-layout-report PRIVATE gsp::core gsp::io)
target_include_directories(gsp-layout-report PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_compile_definitions(gsp-layout-report PRIVATE
  GSP_DATA_DIR="${GSP_DATA_DIR}" GSP_TEST_DIR="${CMAKE_CURRENT_SOURCE_DIR}")
gsp_test(core_parallel_passes SOURCES core_parallel_passes.cpp DEPS gsp::core Threads::Threads)
target_include_directories(core_parallel_passes PRIVATE ${PROJECT_SOURCE_DIR}/libgsp/src)
gsp_test(core_straight_line_bound SOURCES core_straight_line_bound.cpp DEPS gsp::core Threads::Threads)
target_include_directories(core_straight_line_bound PRIVATE ${PROJECT_SOURCE_DIR}/libgsp/src)
