# tests of the DDS layer: msgs/ (wire contract types), sim_node/dds/ (adapter) and the node
# loop's pure parts (sim_node/app/node/dds_*). Included from tests/unit/CMakeLists.txt.
towsim_add_test(towsim_msgs_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/towsim_msgs_test.cc
  LIBS towsim::msgs)

towsim_add_test(dds_translators_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/dds_translators_test.cc
  LIBS towsim::dds towsim::scene)

towsim_add_test(sensor_translators_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sensor_translators_test.cc
  LIBS towsim::dds towsim::scene)

# the sensor models on the messages (dds/sensor_errors.h)
towsim_add_test(sensor_errors_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sensor_errors_test.cc
  LIBS towsim::dds towsim::scene)

towsim_add_test(environment_translator_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/environment_translator_test.cc
  LIBS towsim::dds towsim::scene)
# a vehicle's actuators on the wire (dds/actuator_state_translator)
towsim_add_test(actuator_state_translator_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/actuator_state_translator_test.cc
  LIBS towsim::dds towsim::scene)
towsim_add_test(dds_winch_command_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/dds_winch_command_test.cc
  LIBS towsim::dds)

# an external vessel's pose on the wire (dds/vessel_pose_translator)
towsim_add_test(dds_vessel_pose_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/dds_vessel_pose_test.cc
  LIBS towsim::dds towsim::scene)

towsim_add_test(dds_command_arbiter_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/dds_command_arbiter_test.cc
  LIBS towsim::dds)

towsim_add_test(dds_pacer_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/dds_pacer_test.cc
          ${PROJECT_SOURCE_DIR}/sim_node/app/node/dds_pacer.cc
  LIBS towsim::core)
target_include_directories(dds_pacer_test PRIVATE ${PROJECT_SOURCE_DIR}/sim_node)

# a participant on the loopback configuration (the test sets CYCLONEDDS_URI itself), domains
# 57 and 58
towsim_add_test(dds_entities_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/dds_entities_test.cc
  LIBS towsim::dds)

# raw CDR plumbing (sim_node/dds/raw_cdr): one participant, domain 80
towsim_add_test(raw_cdr_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/raw_cdr_test.cc
  LIBS towsim::dds)

# frames and tf (docs/frames.md), the 3D markers and the ROS 2 graph entry
towsim_add_test(dds_frames_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/dds_frames_test.cc
  LIBS towsim::dds towsim::scene)
towsim_add_test(dds_markers_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/dds_markers_test.cc
  LIBS towsim::dds towsim::scene)
# the RTPS port mapping: which domain ids have ports with a configuration (docs/faults.md)
towsim_add_test(dds_port_mapping_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/dds_port_mapping_test.cc
  LIBS towsim::dds)
