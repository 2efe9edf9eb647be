# tests of the scene layer (YAML -> core::Model). Included from tests/unit/CMakeLists.txt.
towsim_add_test(scene_loader_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/scene_loader_test.cc
  LIBS towsim::scene)
towsim_add_test(environment_reader_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/environment_reader_test.cc
  LIBS towsim::scene)
# the scene loader's text file reader (scene/yaml_reader.h): exact bytes, the size limit, and
# a buffer of the file's size
towsim_add_test(yaml_reader_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/yaml_reader_test.cc
  LIBS towsim::scene)
target_include_directories(yaml_reader_test PRIVATE ${CMAKE_CURRENT_LIST_DIR})
# line types (scene/line_type_reader.h): the keys, the library lookup, the cable over the type
towsim_add_test(line_type_reader_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/line_type_reader_test.cc
  LIBS towsim::scene)
# networks (scene/network_reader.h): cables:, names, holding, junctions, winches, warnings
towsim_add_test(network_reader_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/network_reader_test.cc
  LIBS towsim::scene)
# vessels (scene/rao_file.h, scene/time_history_file.h, scene/rao_coverage.h) and the shipped
# example RAO table of config/vessels/
towsim_add_test(rao_file_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/rao_file_test.cc
  LIBS towsim::scene)
towsim_add_test(time_history_file_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/time_history_file_test.cc
  LIBS towsim::scene)
towsim_add_test(rao_coverage_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/rao_coverage_test.cc
  LIBS towsim::scene)
towsim_add_test(survey_ship_raos_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/survey_ship_raos_test.cc
  LIBS towsim::scene)
# vessels in scenes (scene/vessel_reader.h): keys, course entries, the rules
towsim_add_test(vessel_reader_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/vessel_reader_test.cc
  LIBS towsim::scene)
# the bodies map (scene/body_reader.h): bodies.NAME.scale, a vehicle scaled from its model file
towsim_add_test(body_reader_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/body_reader_test.cc
  LIBS towsim::scene)
target_include_directories(body_reader_test PRIVATE ${CMAKE_CURRENT_LIST_DIR})
# bodies.NAME.sensors (scene/sensor_reader.h): the sensor error keys and their rules
towsim_add_test(sensor_reader_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sensor_reader_test.cc
  LIBS towsim::scene)
