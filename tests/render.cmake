# Tests of gsp::render (framing, shading, PNG) and integration tests of the gsp-render app.
# Pictures are checked by pixel statistics against closed forms, never by eye; all headless.
gsp_test(render_camera_test SOURCES render_camera_test.cpp DEPS gsp::render)
gsp_test(render_shading_test SOURCES render_shading_test.cpp DEPS gsp::render)
gsp_test(render_png_test SOURCES render_png_test.cpp DEPS gsp::render)
if(TARGET gsp-render)
  gsp_test(render_app_test SOURCES render_app_test.cpp DEPS gsp::render)
  add_dependencies(render_app_test gsp-render)   # the test runs the binary
endif()

# render_bench: a Google Benchmark program (not a test) for the speed quoted in the docs.
add_executable(render_bench render_bench.cpp)
target_link_libraries(render_bench PRIVATE gsp::render gsp::io benchmark::benchmark)
target_include_directories(render_bench PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_compile_definitions(render_bench PRIVATE GSP_DATA_DIR="${GSP_DATA_DIR}" GSP_TEST_DIR="${CMAKE_CURRENT_SOURCE_DIR}")
