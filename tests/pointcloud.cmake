# Tests of gsp::pointcloud (geodesics on point clouds) and of triangle soups through the mesh
# core (split, flipped, welded). The accuracy test compares with exact geodesics (CGAL) when
# gsp::reference exists, else with mesh GSP on the same vertices.
gsp_test(pointcloud_graph_test SOURCES pointcloud_graph_test.cpp DEPS gsp::pointcloud)
gsp_test(pointcloud_robustness_test SOURCES pointcloud_robustness_test.cpp DEPS gsp::pointcloud gsp::io)
gsp_test(pointcloud_accuracy_test SOURCES pointcloud_accuracy_test.cpp DEPS gsp::pointcloud gsp::io)
gsp_test(pointcloud_gap_accuracy_test SOURCES pointcloud_gap_accuracy_test.cpp DEPS gsp::pointcloud gsp::io)
gsp_test(pointcloud_elliptic_test SOURCES pointcloud_elliptic_test.cpp DEPS gsp::pointcloud gsp::io)
if(TARGET gsp::reference)
  foreach(t pointcloud_accuracy_test pointcloud_gap_accuracy_test pointcloud_elliptic_test)
    target_link_libraries(${t} PRIVATE gsp::reference)
    target_compile_definitions(${t} PRIVATE GSP_HAVE_EXACT_REFERENCE=1)
  endforeach()
endif()
gsp_test(pointcloud_soup_test SOURCES pointcloud_soup_test.cpp DEPS gsp::core gsp::io)
gsp_test(pointcloud_soup_orientation_test SOURCES pointcloud_soup_orientation_test.cpp DEPS gsp::core gsp::io)
target_include_directories(pointcloud_soup_orientation_test PRIVATE ${PROJECT_SOURCE_DIR}/libgsp/src)
gsp_test(pointcloud_rules_test SOURCES pointcloud_rules_test.cpp DEPS gsp::pointcloud)
gsp_test(pointcloud_triangles_test SOURCES pointcloud_triangles_test.cpp DEPS gsp::pointcloud)
