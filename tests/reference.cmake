# Tests of gsp::reference (exact geodesics, heat method; GPL, CGAL) and the mesh adapters.
# Only included with GSP_WITH_CGAL=ON (tests/CMakeLists.txt).
gsp_test(reference_exact_geodesics SOURCES reference_exact_geodesics.cpp DEPS gsp::reference)
gsp_test(reference_heat_method SOURCES reference_heat_method.cpp DEPS gsp::reference)
