gsp_test(geodesic_exactness_test SOURCES geodesic_exactness_test.cpp DEPS gsp::core)
