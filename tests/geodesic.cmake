gsp_test(geodesic_exactness_test SOURCES geodesic_exactness_test.cpp DEPS gsp::core)
gsp_test(geodesic_dijkstra_test SOURCES geodesic_dijkstra_test.cpp DEPS gsp::core)
gsp_test(geodesic_batch_test SOURCES geodesic_batch_test.cpp DEPS gsp::core)
gsp_test(geodesic_local_test SOURCES geodesic_local_test.cpp DEPS gsp::core gsp::io)
gsp_test(geodesic_heuristic_test SOURCES geodesic_heuristic_test.cpp DEPS gsp::core)
gsp_test(geodesic_invariants_test SOURCES geodesic_invariants_test.cpp DEPS gsp::core gsp::io)
gsp_test(geodesic_meshes_test SOURCES geodesic_meshes_test.cpp DEPS gsp::core gsp::io)
if(GSP_WITH_CGAL)
  # gsp-bench's midpoint split (compiled in, not copied): the test measures the meshes the
  # bench's --subdivision midpoint makes.
  gsp_test(geodesic_accuracy_test
    SOURCES geodesic_accuracy_test.cpp ${PROJECT_SOURCE_DIR}/apps/gsp-bench/src/subdivide.cpp
    DEPS gsp::core gsp::io gsp::reference gsp::cgal_adapter)
  target_include_directories(geodesic_accuracy_test PRIVATE ${PROJECT_SOURCE_DIR}/apps/gsp-bench/src)
endif()
if(TARGET gsp-geodesic)
  gsp_test(geodesic_app_test SOURCES geodesic_app_test.cpp DEPS gsp::core gsp::io gsp::render)
  add_dependencies(geodesic_app_test gsp-geodesic)   # the test runs the binary
endif()
gsp_test(geodesic_intrinsic_delaunay_test SOURCES geodesic_intrinsic_delaunay_test.cpp DEPS gsp::core)
target_include_directories(geodesic_intrinsic_delaunay_test PRIVATE ${PROJECT_SOURCE_DIR}/libgsp/src)
if(GSP_WITH_CGAL)
  gsp_test(geodesic_parallel_test SOURCES geodesic_parallel_test.cpp DEPS gsp::core gsp::io gsp::reference)
  target_compile_definitions(geodesic_parallel_test PRIVATE GSP_HAVE_REFERENCE)
else()
  gsp_test(geodesic_parallel_test SOURCES geodesic_parallel_test.cpp DEPS gsp::core gsp::io)
endif()
# parallel_bench: a Google Benchmark program (not a test): speed-up against one thread.
add_executable(parallel_bench parallel_bench.cpp)
target_link_libraries(parallel_bench PRIVATE gsp::core gsp::io benchmark::benchmark)
target_include_directories(parallel_bench PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_compile_definitions(parallel_bench PRIVATE GSP_TEST_DIR="${CMAKE_CURRENT_SOURCE_DIR}")
gsp_test(geodesic_bounds_test SOURCES geodesic_bounds_test.cpp DEPS gsp::core gsp::io gsp::cli)
