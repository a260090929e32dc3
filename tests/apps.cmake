# Apps: unit tests of the shared CLI helper, and integration tests that run the built
# binaries (GSP_BIN_DIR) on the shared meshes and on a corpus of broken files.
gsp_test(apps_cli_test SOURCES apps_cli_test.cpp DEPS gsp::cli)
if(TARGET gsp-info)
  gsp_test(apps_info_test SOURCES apps_info_test.cpp DEPS gsp::io gsp::render)
  add_dependencies(apps_info_test gsp-info)   # the test runs the binary
endif()
