gsp_test(geodesic_exactness_test SOURCES geodesic_exactness_test.cpp DEPS gsp::core)
gsp_test(geodesic_invariants_test SOURCES geodesic_invariants_test.cpp DEPS gsp::core gsp::io)
gsp_test(geodesic_meshes_test SOURCES geodesic_meshes_test.cpp DEPS gsp::core gsp::io)
