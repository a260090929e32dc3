# The Python package's tests (pytest), one ctest entry per test file so they run in parallel.
# They import the package assembled in build/python and find the data, the apps (gsp-exact for
# exact values) and this build (for the pip install test) through the environment.
file(GLOB GSP_PYTHON_TESTS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/python/tests/test_*.py)
foreach(test_file ${GSP_PYTHON_TESTS})
  get_filename_component(name ${test_file} NAME_WE)
  add_test(NAME python_${name}
           COMMAND ${Python_EXECUTABLE} -m pytest -q -p no:cacheprovider ${test_file}
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}/python/tests)
  set_tests_properties(python_${name} PROPERTIES TIMEOUT 1800
    ENVIRONMENT "PYTHONPATH=${GSP_PYTHON_DIR};GSP_DATA_DIR=${GSP_DATA_DIR};GSP_BIN_DIR=${CMAKE_BINARY_DIR}/bin;GSP_SOURCE_DIR=${PROJECT_SOURCE_DIR};GSP_BUILD_DIR=${CMAKE_BINARY_DIR};GSP_JOBS=2")
endforeach()
