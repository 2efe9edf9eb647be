# controllers (issue 5): their pure control laws (no DDS) and their configuration
if(TARGET towsim::controller_laws)
  towsim_add_test(controller_laws_test LABEL unit
    SOURCES ${PROJECT_SOURCE_DIR}/controllers/tests/controller_laws_test.cc
            ${PROJECT_SOURCE_DIR}/controllers/tests/maneuver_laws_test.cc
            ${PROJECT_SOURCE_DIR}/controllers/tests/autopilot_laws_test.cc
            ${PROJECT_SOURCE_DIR}/controllers/tests/seabed_test.cc
    LIBS towsim::controller_laws)
  towsim_add_test(controller_config_test LABEL unit
    SOURCES ${PROJECT_SOURCE_DIR}/controllers/tests/controller_config_test.cc
    LIBS towsim::controller_config)
endif()
