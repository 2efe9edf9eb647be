towsim_add_test(ancf_element_test LABEL unit SOURCES ancf_element_test.cc LIBS towsim::core)
towsim_add_test(hydrodynamics_test LABEL unit SOURCES hydrodynamics_test.cc LIBS towsim::core)
towsim_add_test(block_tridiagonal_test LABEL unit SOURCES block_tridiagonal_test.cc LIBS towsim::core)
towsim_add_test(system_test LABEL unit SOURCES system_test.cc LIBS towsim::core)
towsim_add_test(integrator_test LABEL unit SOURCES integrator_test.cc LIBS towsim::core)
towsim_add_test(vehicle_coupling_test LABEL unit SOURCES vehicle_coupling_test.cc LIBS towsim::core)
towsim_add_test(no_allocation_test LABEL unit SOURCES no_allocation_test.cc LIBS towsim_core_nomalloc)
towsim_add_test(simulation_test LABEL unit SOURCES simulation_test.cc LIBS towsim::core)
towsim_add_test(actuator_test LABEL unit SOURCES actuator_test.cc LIBS towsim::core)
towsim_add_test(current_field_test LABEL unit SOURCES current_field_test.cc LIBS towsim::core)
towsim_add_test(seabed_test LABEL unit SOURCES seabed_test.cc LIBS towsim::core)
towsim_add_test(environment_field_test LABEL unit SOURCES environment_field_test.cc LIBS towsim::core)
# the irregular-sea statistics use the reference library's spectral estimates
towsim_add_test(wave_field_test LABEL unit SOURCES wave_field_test.cc
                LIBS towsim::core towsim_reference)
towsim_add_test(environment_allocation_test LABEL unit SOURCES environment_allocation_test.cc
                LIBS towsim_core_nomalloc)
towsim_add_test(seabed_contact_test LABEL unit SOURCES seabed_contact_test.cc LIBS towsim::core)
towsim_add_test(packet_math_test LABEL unit SOURCES packet_math_test.cc LIBS towsim::core)
