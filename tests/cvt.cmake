# gsp::cvt: geodesic CVT (Lloyd with GSP), restricted Delaunay remeshing, quality figures; gsp-cvt.
gsp_test(cvt_test SOURCES cvt_test.cpp DEPS gsp::cvt gsp::io)
gsp_test(cvt_quality_test SOURCES cvt_quality_test.cpp DEPS gsp::cvt gsp::io)
gsp_test(cvt_remesh_test SOURCES cvt_remesh_test.cpp DEPS gsp::cvt gsp::io)
gsp_test(cvt_boundary_test SOURCES cvt_boundary_test.cpp DEPS gsp::cvt gsp::io)
gsp_test(cvt_smoothing_test SOURCES cvt_smoothing_test.cpp DEPS gsp::cvt gsp::io)
gsp_test(cvt_components_test SOURCES cvt_components_test.cpp DEPS gsp::cvt gsp::io)
gsp_test(cvt_surface_test SOURCES cvt_surface_test.cpp DEPS gsp::cvt gsp::io)
gsp_test(cvt_features_test SOURCES cvt_features_test.cpp DEPS gsp::cvt gsp::io)
gsp_test(cvt_feature_curves_test SOURCES cvt_feature_curves_test.cpp DEPS gsp::cvt gsp::io)
if(TARGET gsp-cvt)
  gsp_test(cvt_app_test SOURCES cvt_app_test.cpp DEPS gsp::cvt gsp::io)
  add_dependencies(cvt_app_test gsp-cvt)   # the test runs the binary
endif()
