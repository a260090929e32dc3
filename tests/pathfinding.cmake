# Tests of gsp::pathfinding (path tracing, goal-directed queries) and the gsp-path app.
gsp_test(pathfinding_trace_test SOURCES pathfinding_trace_test.cpp DEPS gsp::pathfinding gsp::io)
if(GSP_WITH_CGAL)
  gsp_test(pathfinding_exact_test SOURCES pathfinding_exact_test.cpp DEPS gsp::pathfinding gsp::io gsp::reference)
endif()
gsp_test(pathfinding_astar_test SOURCES pathfinding_astar_test.cpp DEPS gsp::core gsp::io)
if(TARGET gsp-path)
  gsp_test(pathfinding_app_test SOURCES pathfinding_app_test.cpp DEPS gsp::pathfinding gsp::io TinyGLTF::TinyGLTF)
  add_dependencies(pathfinding_app_test gsp-path)   # the test runs the binary
endif()
if(GSP_WITH_CGAL)
  gsp_test(pathfinding_shared_test SOURCES pathfinding_shared_test.cpp DEPS gsp::pathfinding gsp::io gsp::reference)
endif()
