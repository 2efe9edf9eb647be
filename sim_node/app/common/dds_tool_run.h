#pragma once
// The rest of a DDS tool's main once its command line is read (towsim_record,
// towsim_foxglove): the stop handlers, the DDS URI, the tool built (its participant and
// entities), then its run. Each failure is reported as `<tool>: error: ...` with its exit
// code (docs/command_line.md, "Exit codes"):
//   building: an identity DDS Security refuses, or the DDS setup            -> 2 (bad input)
//   running:  a DDS error, when `dds_run_error_is_bad_input` ("DDS: ...")   -> 2
//             any other error                                               -> 1
//
//   Options options;
//   if (const std::optional<int> exit = CommandLine(&options).Read(argc, argv)) return *exit;
//   return RunDdsTool<Recorder>("towsim_record", options, true);
// Tool: constructible from (const Options&, const std::string& dds_uri), with int Run().

#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include "app/common/dds_uri.h"
#include "app/common/exit_codes.h"
#include "app/common/stop_signal.h"
#include "dds/entities.h"
#include "wire/security.h"

namespace towsim::app {

template <class Tool, class Options>
int RunDdsTool(const char* tool, const Options& options, bool dds_run_error_is_bad_input) {
  auto fail = [tool](const std::string& message, int code) {
    std::fprintf(stderr, "%s: error: %s\n", tool, message.c_str());
    return code;
  };
  InstallStopHandlers();
  const std::string uri = DdsUriFromEnvironment(tool);
  std::unique_ptr<Tool> run;
  try {
    run = std::make_unique<Tool>(options, uri);
  } catch (const wire::SecurityError& e) {
    return fail(e.what(), kExitBadInput);
  } catch (const dds::DdsError& e) {
    return fail(std::string("DDS setup failed: ") + e.what(), kExitBadInput);
  }
  try {
    return run->Run();
  } catch (const dds::DdsError& e) {
    if (dds_run_error_is_bad_input) return fail(std::string("DDS: ") + e.what(), kExitBadInput);
    return fail(e.what(), kExitError);
  } catch (const std::exception& e) {
    return fail(e.what(), kExitError);
  }
}

}  // namespace towsim::app
