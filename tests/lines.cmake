# Tests of gsp::lines (segment sources: planes against closed forms, curved meshes against exact
# geodesics of densely sampled polylines) and of gsp-geodesic's line-source options.
gsp_test(lines_plane_test SOURCES lines_plane_test.cpp DEPS gsp::lines)
gsp_test(lines_source_test SOURCES lines_source_test.cpp DEPS gsp::lines gsp::io)
gsp_test(lines_bound_test SOURCES lines_bound_test.cpp DEPS gsp::lines gsp::io)
if(GSP_WITH_CGAL)
  gsp_test(lines_exact_test SOURCES lines_exact_test.cpp DEPS gsp::lines gsp::io gsp::reference)
endif()
if(GSP_BUILD_APPS)
  gsp_test(lines_app_test SOURCES lines_app_test.cpp DEPS gsp::lines gsp::io)
  add_dependencies(lines_app_test gsp-geodesic)   # the test runs the binary
endif()
