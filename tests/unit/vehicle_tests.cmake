# tests of the 6-DOF vehicle model (core/vehicle_model, core/lifting_surface) and of the vehicle
# files config/vehicles/*.yaml. Included from tests/unit/CMakeLists.txt.
towsim_add_test(vehicle_model_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/vehicle_model_test.cc
  LIBS towsim::core)
towsim_add_test(lifting_surface_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/lifting_surface_test.cc
  LIBS towsim::core)
# reads the vehicle files through the scene loader (vehicle_file.h)
towsim_add_test(vehicle_maneuver_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/vehicle_maneuver_test.cc ${CMAKE_CURRENT_LIST_DIR}/vehicle_file.cc
  LIBS towsim::core towsim::scene)
# Froude scaling of a vehicle model (core/vehicle_scaling): every field's exponent from its
# unit, scale 1, composition, and the model's right-hand side under similarity
towsim_add_test(vehicle_scaling_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/vehicle_scaling_test.cc ${CMAKE_CURRENT_LIST_DIR}/vehicle_file.cc
  LIBS towsim::core towsim::scene)
