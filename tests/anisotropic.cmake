# Tests of gsp::anisotropic: closed forms on planes and cylinders, bit-for-bit identity with
# plain GSP at ratio 1, curvature estimation, errors; the app test runs gsp-geodesic --metric.
gsp_test(anisotropic_flat_test SOURCES anisotropic_flat_test.cpp DEPS gsp::anisotropic)
gsp_test(anisotropic_identity_test SOURCES anisotropic_identity_test.cpp DEPS gsp::anisotropic gsp::io)
gsp_test(anisotropic_curvature_test SOURCES anisotropic_curvature_test.cpp DEPS gsp::anisotropic gsp::io)
gsp_test(anisotropic_errors_test SOURCES anisotropic_errors_test.cpp DEPS gsp::anisotropic gsp::io)
if(TARGET gsp-geodesic)
  gsp_test(anisotropic_app_test SOURCES anisotropic_app_test.cpp DEPS gsp::anisotropic gsp::io)
  add_dependencies(anisotropic_app_test gsp-geodesic)   # the test runs the binary
endif()
