# Apps: unit tests of the shared CLI helper, and integration tests that run the built
# binaries (GSP_BIN_DIR) on the shared meshes and on a corpus of broken files.
gsp_test(apps_cli_test SOURCES apps_cli_test.cpp DEPS gsp::cli)
# The apps' operator new, compiled in as gsp_app compiles it into every app.
gsp_test(app_huge_pages_test SOURCES app_huge_pages_test.cpp ${PROJECT_SOURCE_DIR}/apps/common/huge_page_new.cpp)
if(TARGET gsp-info)
  gsp_test(apps_info_test SOURCES apps_info_test.cpp DEPS gsp::io gsp::render)
  add_dependencies(apps_info_test gsp-info)   # the test runs the binary
endif()
