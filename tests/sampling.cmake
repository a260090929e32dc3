# gsp::sampling: geodesic Poisson-disk and farthest-point sampling; the gsp-sample app.
gsp_test(sampling_test SOURCES sampling_test.cpp DEPS gsp::sampling gsp::io)
if(TARGET gsp-sample)
  gsp_test(sampling_app_test SOURCES sampling_app_test.cpp DEPS gsp::sampling gsp::io)
  add_dependencies(sampling_app_test gsp-sample)   # the test runs the binary
endif()
