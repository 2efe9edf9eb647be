# tests of the scene layer (YAML -> core::Model). Included from tests/unit/CMakeLists.txt.
towsim_add_test(scene_loader_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/scene_loader_test.cc
  LIBS towsim::scene)

# the sweep file of towsim_sweep (docs/sweeps.md): parser, ranges and seeded draws
towsim_add_test(sweep_file_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sweep_file_test.cc
  LIBS towsim::scene)
towsim_add_test(sweep_values_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sweep_values_test.cc
  LIBS towsim::scene)
towsim_add_test(environment_reader_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/environment_reader_test.cc
  LIBS towsim::scene)
