# Tests of gsp::reference (exact geodesics, heat method; GPL, CGAL) and the mesh adapters.
# Only included with GSP_WITH_CGAL=ON (tests/CMakeLists.txt).
gsp_test(reference_exact_geodesics SOURCES reference_exact_geodesics.cpp DEPS gsp::reference)
gsp_test(reference_heat_method SOURCES reference_heat_method.cpp DEPS gsp::reference)
gsp_test(adapters_cgal SOURCES adapters_cgal.cpp DEPS gsp::cgal_adapter)
if(TARGET gsp::openmesh_adapter)
  gsp_test(adapters_openmesh SOURCES adapters_openmesh.cpp DEPS gsp::openmesh_adapter)
endif()
if(TARGET gsp::openmesh_adapter)
  gsp_test(reference_shared_meshes SOURCES reference_shared_meshes.cpp
    DEPS gsp::reference gsp::cgal_adapter gsp::openmesh_adapter gsp::io)
endif()
if(TARGET gsp-exact)
  gsp_test(reference_gsp_exact SOURCES reference_gsp_exact.cpp DEPS gsp::reference gsp::io)
  add_dependencies(reference_gsp_exact gsp-exact)   # the test runs the binary
endif()
