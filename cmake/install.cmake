# cmake --install build --prefix P (docs/testing_controllers.md, "The installed package"):
#   P/bin/                     sim_node, the tools and the controllers (TOWSIM_INSTALLED_PROGRAMS)
#   P/libexec/towsim/          sim_node_dds (the DDS modes sim_node execs)
#   P/share/towsim/            scenes/, vehicles/, vessels/, line_types/, maneuvers/, autopilot/,
#                              sweeps/, foxglove/,
#                              cyclonedds.xml (the loopback configuration for CYCLONEDDS_URI),
#                              cyclonedds_two_hosts.xml, idl/*.idl,
#                              ros2/towsim_msgs/ (the ROS 2 package's files), examples/,
#                              scripts/ (the plotting scripts and paper_cases.py they import)
#   P/include/towsim/          msgs/*.h (generated from the IDL), wire/*.h (topic names, QoS,
#                              Security, ROS 2 graph, decoders), common/*.h (client library),
#                              testing/*.h (test fixture)
#   P/lib/                     libtowsim_msgs.a, libtowsim_wire.a, libtowsim_domain_lock.a, libtowsim_client.a (+ laws),
#                              libtowsim_testing.a (+ libtowsim_installed.a, which it links)
#   P/lib/cmake/towsim/        find_package(towsim): towsim::msgs, towsim::wire, towsim::client,
#                              towsim::testing, towsim::sim_node (and every installed program as
#                              towsim::<name>), towsim_SIM_NODE, towsim_DATA_DIR, towsim_DDS_URI
# The programs find P/share/towsim from their own location (installed/installed_data.h).
# docs/testing_controllers.md's table of these paths is checked against this file
# (tests/docs/doc_facts_test.cc).

include(CMakePackageConfigHelpers)

# every program of the package: add a new tool here (one line)
set(TOWSIM_INSTALLED_PROGRAMS
  sim_node
  towsim_record
  towsim_replay
  towsim_export
  towsim_sweep
  towsim_foxglove
  towsim_vessel_feed
  maneuver_runner
  towfish_depth
  autopilot
  hello_controller
)
foreach(_program IN LISTS TOWSIM_INSTALLED_PROGRAMS)
  if(NOT TARGET ${_program})
    message(FATAL_ERROR "TOWSIM_INSTALLED_PROGRAMS: ${_program} is not a target")
  endif()
endforeach()
install(TARGETS ${TOWSIM_INSTALLED_PROGRAMS} EXPORT towsimTargets
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# the programs only other programs run: sim_node's DDS modes (sim_node/app/node/node_main.h), found
# by sim_node at P/libexec/towsim (kPrivateProgramDir in installed/installed_data.h)
install(TARGETS sim_node_dds RUNTIME DESTINATION libexec/towsim)

# the libraries a user's controllers and tests link
set_target_properties(towsim_controller_laws PROPERTIES EXPORT_NAME controller_laws)
install(TARGETS towsim_msgs towsim_wire towsim_domain_lock towsim_controller_laws towsim_controller_common
                towsim_testing towsim_installed
        EXPORT towsimTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(FILES ${TOWSIM_MSGS_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/towsim/msgs)
install(FILES ${TOWSIM_WIRE_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/towsim/wire)
install(FILES controllers/common/client.h controllers/common/flags.h controllers/common/laws.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/towsim/common)
install(DIRECTORY controllers/testing/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/towsim/testing
        FILES_MATCHING PATTERN "*.h")

# the configuration, the wire contract and the example
set(TOWSIM_DATA_DESTINATION ${CMAKE_INSTALL_DATADIR}/towsim)
install(DIRECTORY config/scenes config/vehicles config/line_types config/maneuvers config/autopilot
                  config/sweeps config/vessels
                  config/foxglove
        DESTINATION ${TOWSIM_DATA_DESTINATION})
install(FILES config/cyclonedds.xml config/cyclonedds_two_hosts.xml
        DESTINATION ${TOWSIM_DATA_DESTINATION})
install(FILES ${TOWSIM_IDL_FILES} DESTINATION ${TOWSIM_DATA_DESTINATION}/idl)
install(DIRECTORY msgs/towsim_msgs DESTINATION ${TOWSIM_DATA_DESTINATION}/ros2)
install(DIRECTORY examples/controller_ci DESTINATION ${TOWSIM_DATA_DESTINATION}/examples
        PATTERN "build" EXCLUDE)
# the plotting scripts (python3 P/share/towsim/scripts/plot_paper.py DIR; matplotlib) and the
# module they import beside them; not in P/bin: they are python3 scripts with their own
# dependency, run by path as in the source tree (docs/testing_controllers.md)
install(PROGRAMS scripts/plot_paper.py scripts/plot_uturn_3d.py scripts/plot_waves.py
                 scripts/plot_sweep.py
                 scripts/paper_cases.py
        DESTINATION ${TOWSIM_DATA_DESTINATION}/scripts)

# the CMake package
set(TOWSIM_CMAKE_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/towsim)
install(EXPORT towsimTargets NAMESPACE towsim:: DESTINATION ${TOWSIM_CMAKE_DESTINATION})
configure_package_config_file(cmake/towsimConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/towsimConfig.cmake
  INSTALL_DESTINATION ${TOWSIM_CMAKE_DESTINATION}
  PATH_VARS CMAKE_INSTALL_BINDIR TOWSIM_DATA_DESTINATION)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/towsimConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/towsimConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/towsimConfigVersion.cmake
        DESTINATION ${TOWSIM_CMAKE_DESTINATION})
