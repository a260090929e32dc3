# Every dependency is a Debian package (scripts/setup.sh installs them).
# Reuse a target the parent project already has before asking find_package.
macro(gsp_find target)
  if(NOT TARGET ${target})
    find_package(${ARGN})
  endif()
endmacro()

find_package(Threads REQUIRED)
gsp_find(Eigen3::Eigen Eigen3 3.3 REQUIRED NO_MODULE)
gsp_find(TinyGLTF::TinyGLTF TinyGLTF REQUIRED)
gsp_find(nanoflann::nanoflann nanoflann REQUIRED)
gsp_find(embree embree 3 REQUIRED)
gsp_find(CLI11::CLI11 CLI11 REQUIRED)
find_package(PNG REQUIRED)
if(GSP_WITH_CGAL)
  gsp_find(CGAL::CGAL CGAL REQUIRED COMPONENTS Core)
  gsp_find(OpenMeshCore OpenMesh REQUIRED CONFIG)   # CONFIG: CGAL ships a FindOpenMesh that shadows it
endif()
if(GSP_BUILD_TESTS)
  gsp_find(GTest::gtest_main GTest REQUIRED)
  gsp_find(benchmark::benchmark benchmark REQUIRED)
endif()
