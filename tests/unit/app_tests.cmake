# tests of the app layer: io/, app/ (sim_node) and the layering rule of the core.
# Included from tests/unit/CMakeLists.txt.

# the core includes the standard library, Eigen and itself only (reads the sources)
towsim_add_test(core_isolation_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/core_isolation_test.cc)

towsim_add_test(csv_writer_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/csv_writer_test.cc
  LIBS towsim::io towsim::core)

# runs the built sim_node binary (TOWSIM_SIM_NODE) as a process
towsim_add_test(sim_node_cli_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sim_node_cli_test.cc)

# TOWSIM_SIM_NODE names the binary in every test: build it first
foreach(t core_isolation_test csv_writer_test sim_node_cli_test)
  add_dependencies(${t} sim_node)
endforeach()

# what a Foxglove client's message must meet (app/foxglove/foxglove_commands)
towsim_add_test(foxglove_commands_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/foxglove_commands_test.cc
  LIBS towsim::foxglove_commands)

# a Foxglove layout for a scene (app/foxglove/foxglove_layout): the node's topics for the
# scene, indices in range, the camera framing the system, the shipped layout its output
towsim_add_test(foxglove_layout_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/foxglove_layout_test.cc
  LIBS towsim::foxglove_layout towsim::recording towsim::scene towsim::core)
target_include_directories(foxglove_layout_test PRIVATE ${CMAKE_CURRENT_LIST_DIR})

# the bound on what the Foxglove server holds for a client and the throttled notes
# (app/foxglove/client_queue, note_throttle), no sockets
towsim_add_test(foxglove_client_queue_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/foxglove_client_queue_test.cc
  LIBS towsim::foxglove)

# the Foxglove server alone on loopback (no DDS): a never-reading client held to its bound and
# reset; stops while publishing and clients come and go (also built with the sanitizers,
# docs/faults.md)
towsim_add_test(foxglove_server_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/foxglove_server_test.cc
    ${PROJECT_SOURCE_DIR}/tests/integration/raw_websocket_client.cc
  LIBS towsim::foxglove)
target_include_directories(foxglove_server_test PRIVATE ${PROJECT_SOURCE_DIR}/tests/integration)

# the Foxglove WebSocket protocol messages (app/foxglove/foxglove_protocol), no sockets
towsim_add_test(foxglove_protocol_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/foxglove_protocol_test.cc
  LIBS towsim::foxglove)

# the tools' command lines (app/common/tool_flags, tool_command_line) and the options the DDS
# tools share (app/common/dds_tool_options)
towsim_add_test(tool_flags_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/tool_flags_test.cc
  LIBS towsim::tool_main)
towsim_add_test(tool_command_line_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/tool_command_line_test.cc
  LIBS towsim::tool_main)
towsim_add_test(dds_tool_options_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/dds_tool_options_test.cc
  LIBS towsim::recording)
foreach(t tool_flags_test tool_command_line_test dds_tool_options_test)
  target_include_directories(${t} PRIVATE ${CMAKE_CURRENT_LIST_DIR})  # tool_argv.h
endforeach()
# the topics of a node the recorder and the Foxglove bridge subscribe to (app/common/topic_types)
towsim_add_test(topic_types_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/topic_types_test.cc LIBS towsim::recording)
# the installed-file lookup of every program (sim_node --scene, the controllers' --config)
towsim_add_test(installed_data_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/installed_data_test.cc LIBS towsim::installed)
target_include_directories(installed_data_test PRIVATE ${CMAKE_CURRENT_LIST_DIR})

# towsim_sweep (docs/sweeps.md): the sweep file (parser, ranges and seeded draws), the
# combinator and the results of a case
towsim_add_test(sweep_file_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sweep_file_test.cc
  LIBS towsim_sweep_lib)
towsim_add_test(sweep_values_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sweep_values_test.cc
  LIBS towsim_sweep_lib)
towsim_add_test(sweep_combinator_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sweep_combinator_test.cc
  LIBS towsim_sweep_lib)
towsim_add_test(sweep_signals_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sweep_signals_test.cc
  LIBS towsim_sweep_lib)
towsim_add_test(sweep_controllers_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sweep_controllers_test.cc
  LIBS towsim_sweep_lib)
towsim_add_test(sweep_case_run_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sweep_case_run_test.cc
  LIBS towsim_sweep_lib)
towsim_add_test(sweep_case_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sweep_case_test.cc
  LIBS towsim_sweep_lib)
towsim_add_test(sweep_slurm_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sweep_slurm_test.cc
  LIBS towsim_sweep_lib)
towsim_add_test(csv_reader_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/csv_reader_test.cc
  LIBS towsim::io towsim::core)
towsim_add_test(sweep_table_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sweep_table_test.cc
  LIBS towsim_sweep_lib)

# the DDS node's counters and its summary line (app/node/run_counters): pure
towsim_add_test(run_counters_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/run_counters_test.cc
          ${PROJECT_SOURCE_DIR}/sim_node/app/node/run_counters.cc)
target_include_directories(run_counters_test PRIVATE ${PROJECT_SOURCE_DIR}/sim_node)

# why --fail-on-failsafe ends a run (app/node/failsafe_failure): pure, over the arbiter
towsim_add_test(failsafe_failure_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/failsafe_failure_test.cc
          ${PROJECT_SOURCE_DIR}/sim_node/app/node/failsafe_failure.cc
  LIBS towsim::dds)

# the node's run control (app/node/run_control): a pure state machine, no DDS
towsim_add_test(run_control_test LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/run_control_test.cc
          ${PROJECT_SOURCE_DIR}/sim_node/app/node/run_control.cc
  LIBS towsim::dds)
