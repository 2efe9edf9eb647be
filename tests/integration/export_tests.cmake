# towsim_export round trips: sim_node --record + --csv, then towsim_export --csv;
# real processes over loopback DDS, domains 91, 92, 134, 188, 194, 195, 198 and 216 and one
# automatic (DomainLease, 200-231). Included from tests/unit/mcap_tests.cmake.
set(_export_dir ${PROJECT_SOURCE_DIR}/tests/integration)
add_executable(export_roundtrip_test ${_export_dir}/export_roundtrip_test.cc)
target_link_libraries(export_roundtrip_test PRIVATE towsim::testing towsim::io GTest::gtest
  GTest::gtest_main)
target_compile_definitions(export_roundtrip_test PRIVATE
  TOWSIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
  TOWSIM_DDS_URI="file://${PROJECT_SOURCE_DIR}/config/cyclonedds.xml"
  TOWSIM_SIM_NODE="$<TARGET_FILE:sim_node>"
  TOWSIM_EXPORT="$<TARGET_FILE:towsim_export>"
  TOWSIM_RECORD="$<TARGET_FILE:towsim_record>"
  TOWSIM_TEST_CONTROLLER="$<TARGET_FILE:test_controller>")
add_dependencies(export_roundtrip_test sim_node towsim_export towsim_record test_controller)
gtest_discover_tests(export_roundtrip_test
  PROPERTIES LABELS integration
  ENVIRONMENT "CYCLONEDDS_URI=file://${PROJECT_SOURCE_DIR}/config/cyclonedds.xml"
  DISCOVERY_TIMEOUT 60)
