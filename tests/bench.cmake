# Tests of gsp-bench (GPL: the app links CGAL). They run the built binary on the bundled
# fertility sample; bench_errors_test recomputes its errors in-process.
if(TARGET gsp-bench)
  gsp_test(bench_app_test SOURCES bench_app_test.cpp DEPS gsp::io)
  add_dependencies(bench_app_test gsp-bench)   # the test runs the binary
  gsp_test(bench_errors_test SOURCES bench_errors_test.cpp DEPS gsp::reference gsp::core gsp::io)
  add_dependencies(bench_errors_test gsp-bench)
  gsp_test(bench_points_test SOURCES bench_points_test.cpp DEPS gsp::io)
  add_dependencies(bench_points_test gsp-bench)
endif()
if(TARGET gsp-bench)
  # The app's bounds and category lookup, compiled in: unit tests without the binary.
  set(GSP_BENCH_SRC ${CMAKE_SOURCE_DIR}/apps/gsp-bench/src)
  gsp_test(bench_bounds_test SOURCES bench_bounds_test.cpp ${GSP_BENCH_SRC}/bounds.cpp ${GSP_BENCH_SRC}/categories.cpp
           DEPS gsp::core)
  target_include_directories(bench_bounds_test PRIVATE ${GSP_BENCH_SRC})
  gsp_test(bench_corpus_test SOURCES bench_corpus_test.cpp DEPS gsp::io)
  add_dependencies(bench_corpus_test gsp-bench)
endif()
