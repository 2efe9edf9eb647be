# tests of the wire library (wire/: topic names, QoS, Security, decoders) and of the rule that
# keeps it the one way between sim_node/ and controllers/. Included from tests/unit/CMakeLists.txt.
towsim_add_test(wire_topic_names_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/wire_topic_names_test.cc
  LIBS towsim::wire)

towsim_add_test(wire_decoders_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/wire_decoders_test.cc
  LIBS towsim::wire)

# DDS Security setup (wire/security): files, properties, key check; no participant
towsim_add_test(wire_security_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/wire_security_test.cc
  LIBS towsim::wire)
target_include_directories(wire_security_test PRIVATE ${CMAKE_CURRENT_LIST_DIR})

# no file of sim_node/ includes controllers/, no controller includes sim_node/ (only wire/)
towsim_add_test(wire_isolation_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/wire_isolation_test.cc)
