# MCAP writer / reader (sim_node/io/mcap_*)
towsim_add_test(mcap_test LABEL unit SOURCES mcap_test.cc LIBS towsim::io)
towsim_add_test(mcap_records_test LABEL unit SOURCES mcap_records_test.cc LIBS towsim::io)

# independent readers (tests/mcap_js, Node.js): @mcap/core opens a file our writer wrote; and
# @mcap/core + @foxglove/rosmsg + @foxglove/rosmsg2-serialization decode a real recording
# (sim_node --record, case1_forward in fast mode, domain 93) and compare it with the node's own
# --csv output of the same run. Only where Node.js is found at configure time; skipped (exit
# 77) until `npm ci` ran in tests/mcap_js (test.sh runs it).
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

  # the recording: 40 s of Case 1 in a sheared current (so that the node publishes the sea at
  # each body), every topic at the CSV output rate (10 Hz)
  set(_js_run ${CMAKE_CURRENT_BINARY_DIR}/mcap_js_run)
  set(_dds_uri "file://${PROJECT_SOURCE_DIR}/config/cyclonedds.xml")
  add_test(NAME mcap_js_record_run
    COMMAND ${CMAKE_COMMAND} -E env CYCLONEDDS_URI=${_dds_uri}
      $<TARGET_FILE:sim_node> --scene ${PROJECT_SOURCE_DIR}/config/scenes/case1_forward.yaml
      --mode fast --domain 93 --duration 40 --csv ${_js_run}/csv --record ${_js_run}/run.mcap
      --overwrite
      --set publish.odom=10 --set publish.cable_force=10 --set publish.cable_state=10
      --set publish.status=10 --set publish.markers=10 --set publish.sensors=10
      "--set=environment.current={profile: [[0, [0.3, 0, 0]], [200, [0, 0.2, 0]]]}")
  set_tests_properties(mcap_js_record_run PROPERTIES
    FIXTURES_SETUP mcap_js_run LABELS integration ENVIRONMENT "CYCLONEDDS_URI=${_dds_uri}")
  add_test(NAME mcap_js_decode_recording
    COMMAND ${NODE_EXECUTABLE} ${_mcap_js}/decode_recording.mjs ${_js_run}/run.mcap
      ${_js_run}/csv)
  set_tests_properties(mcap_js_decode_recording PROPERTIES
    FIXTURES_REQUIRED mcap_js_run LABELS integration SKIP_RETURN_CODE 77)
else()
  message(STATUS "node not found: the independent reader tests (tests/mcap_js) are not added")
endif()

# ROS 2 schemas and the rosbag2 metadata record (sim_node/io/ros2_schemas)
towsim_add_test(ros2_schemas_test LABEL unit SOURCES ros2_schemas_test.cc
  LIBS towsim::io yaml-cpp)

# CDR decoder of the published types (sim_node/io/cdr_*): by hand, and against bytes serialized
# by Cyclone DDS (dds/raw_cdr; one participant on the loopback configuration, domain 90)
towsim_add_test(cdr_reader_test LABEL unit SOURCES cdr_reader_test.cc LIBS towsim::io)
towsim_add_test(cdr_messages_test LABEL unit SOURCES cdr_messages_test.cc
  LIBS towsim::io towsim::dds)

# towsim_export round trips (tests/integration/export_*, integration label)
include(${PROJECT_SOURCE_DIR}/tests/integration/export_tests.cmake)
