# controllers: their pure control laws (no DDS) and their configuration
if(TARGET towsim::controller_laws)
  towsim_add_test(controller_laws_test LABEL unit
    SOURCES ${PROJECT_SOURCE_DIR}/controllers/tests/controller_laws_test.cc
            ${PROJECT_SOURCE_DIR}/controllers/tests/maneuver_laws_test.cc
            ${PROJECT_SOURCE_DIR}/controllers/tests/autopilot_laws_test.cc
            ${PROJECT_SOURCE_DIR}/controllers/tests/seabed_test.cc
            ${PROJECT_SOURCE_DIR}/controllers/tests/winch_law_test.cc
    LIBS towsim::controller_laws)
  towsim_add_test(controller_config_test LABEL unit
    SOURCES ${PROJECT_SOURCE_DIR}/controllers/tests/controller_config_test.cc
    LIBS towsim::controller_config)
endif()

# the test fixture's pieces without a node (controllers/testing): golden CSV files, domain leases
if(TARGET towsim::testing)
  towsim_add_test(testing_fixture_test LABEL unit
    SOURCES ${PROJECT_SOURCE_DIR}/controllers/tests/golden_csv_test.cc
            ${PROJECT_SOURCE_DIR}/controllers/tests/dds_domain_test.cc
    LIBS towsim::testing)
  target_include_directories(testing_fixture_test PRIVATE ${CMAKE_CURRENT_LIST_DIR})
endif()
