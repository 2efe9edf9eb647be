# controllers (issue 5): their pure control laws, no DDS
if(TARGET towsim::controller_laws)
  towsim_add_test(controller_laws_test LABEL unit
    SOURCES ${PROJECT_SOURCE_DIR}/controllers/tests/controller_laws_test.cc
    LIBS towsim::controller_laws)
endif()
