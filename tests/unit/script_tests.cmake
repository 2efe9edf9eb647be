# tests of the offline script (core/script.h). Included from tests/unit/CMakeLists.txt.
towsim_add_test(script_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/script_test.cc
  LIBS towsim::core)
