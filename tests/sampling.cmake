# gsp::sampling: geodesic Poisson-disk and farthest-point sampling; the gsp-sample app.
gsp_test(sampling_test SOURCES sampling_test.cpp DEPS gsp::sampling gsp::io)
if(TARGET gsp-sample)
  gsp_test(sampling_app_test SOURCES sampling_app_test.cpp DEPS gsp::sampling gsp::io)
  add_dependencies(sampling_app_test gsp-sample)   # the test runs the binary
endif()
# sampling_bench: a Google Benchmark program (not a test): sampling time over one full GSP.
add_executable(sampling_bench sampling_bench.cpp)
target_link_libraries(sampling_bench PRIVATE gsp::sampling gsp::io benchmark::benchmark)
target_include_directories(sampling_bench PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_compile_definitions(sampling_bench PRIVATE GSP_TEST_DIR="${CMAKE_CURRENT_SOURCE_DIR}")
