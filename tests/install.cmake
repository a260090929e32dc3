# The installed package works for a user's project: cmake --install, then find_package(gsp)
# in tests/consumer, built and run.
add_test(NAME install_consumer
  COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${CMAKE_BINARY_DIR}
          -DSOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/consumer
          -DWORK_DIR=${CMAKE_BINARY_DIR}/install_consumer
          -P ${CMAKE_CURRENT_SOURCE_DIR}/consumer/check.cmake)
set_tests_properties(install_consumer PROPERTIES TIMEOUT 600)
