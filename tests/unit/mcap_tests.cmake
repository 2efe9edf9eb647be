# MCAP writer / reader (sim_node/io/mcap_*), issue 6
towsim_add_test(mcap_test LABEL unit SOURCES mcap_test.cc LIBS towsim::io)

# an independent reader, @mcap/core (tests/mcap_js), opens a file our writer wrote. Only where
# Node.js is found at configure time; skipped (exit 77) until `npm ci` ran in tests/mcap_js.
find_program(NODE_EXECUTABLE NAMES node nodejs)
if(NODE_EXECUTABLE)
  set(_mcap_js ${PROJECT_SOURCE_DIR}/tests/mcap_js)
  set(_mcap_js_file ${CMAKE_CURRENT_BINARY_DIR}/mcap_js_fixture.mcap)
  add_executable(mcap_js_write_fixture ${_mcap_js}/write_fixture.cc)
  target_link_libraries(mcap_js_write_fixture PRIVATE towsim::io)
  add_test(NAME mcap_js_write_fixture COMMAND mcap_js_write_fixture ${_mcap_js_file} 5000)
  set_tests_properties(mcap_js_write_fixture PROPERTIES
    FIXTURES_SETUP mcap_js_fixture LABELS integration)
  add_test(NAME mcap_js_core_reader
    COMMAND ${NODE_EXECUTABLE} ${_mcap_js}/check_mcap.mjs ${_mcap_js_file} 5000)
  set_tests_properties(mcap_js_core_reader PROPERTIES
    FIXTURES_REQUIRED mcap_js_fixture LABELS integration SKIP_RETURN_CODE 77)
else()
  message(STATUS "node not found: the @mcap/core reader test (tests/mcap_js) is not added")
endif()
