// towsim_export: a towsim recording (MCAP) to the CSV files of docs/contract.md §5 (--csv DIR) and / or a
// summary like `ros2 bag info` (--info). Exit codes: 0 done, 1 unexpected error (e.g. a CSV
// file could not be written), 2 bad input (command line, unreadable or corrupt recording: the
// reader's message names the byte offset), 4 --recover read the file but skipped damaged or
// cut-off byte ranges (each on stderr: bytes, message count, the damage); the output holds
// every intact chunk.
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>

#include "app/common/exit_codes.h"
#include "app/common/tool_command_line.h"
#include "app/export/export_csv.h"
#include "app/export/export_info.h"
#include "io/cdr_reader.h"
#include "io/mcap_format.h"
#include "io/mcap_reader.h"

namespace {

using towsim::app::kExitBadInput;
using towsim::app::kExitError;
using towsim::app::kExitIncomplete;
using towsim::app::kExitOk;

constexpr char kUsage[] =
    "usage: towsim_export FILE.mcap [--csv DIR] [--info] [--namespace NS] [--recover]\n"
    "  --csv DIR         write bodies.csv, cable.csv, forces.csv, status.csv into DIR\n"
    "                    (a network: <cable>.csv per cable; and winch.csv,\n"
    "                    environment.csv, actuators.csv, commands.csv when recorded)\n"
    "  --info            print topics, types, counts and the time range (like ros2 bag info)\n"
    "  --namespace NS    the node's namespace in the recording (default /towsim)\n"
    "  --recover         read what a killed recorder or damage left: every intact chunk;\n"
    "                    skipped byte ranges on stderr and exit 4 if anything was lost\n"
    "  --help            print this and exit\n"
    "At least one of --csv and --info.\n";

struct Options {
  std::string file, csv_dir, ns = "/towsim";
  bool info = false, recover = false;
};

// the options, read into `o`; --help answers at once and "--info=1" is not --info, as before
towsim::app::ToolCommandLine CommandLine(Options* o) {
  towsim::app::ToolCommandLine line("towsim_export", kUsage);
  line.HelpAtOnce()
      .FlagsTakeNoValue()
      .Value(
          "--csv",
          [o](const std::string& v) -> std::string {
            o->csv_dir = v;
            return v.empty() ? "--csv needs a directory" : "";
          },
          "--csv needs a directory")
      .Value(
          "--namespace",
          [o](const std::string& v) -> std::string {
            if (v.empty() || v[0] != '/') return "--namespace = '" + v + "': must start with '/'";
            o->ns = v.size() > 1 && v.back() == '/' ? v.substr(0, v.size() - 1) : v;
            return "";
          },
          "--namespace = '': must start with '/'")
      .Flag("--info", &o->info)
      .Flag("--recover", &o->recover)
      .Others([o](const towsim::app::ToolFlags& flags) -> std::string {
        const std::string& arg = flags.arg();
        if (arg.rfind("-", 0) == 0) return towsim::app::UnknownOption(flags);
        if (!o->file.empty()) return "more than one file: '" + o->file + "' and '" + arg + "'";
        o->file = arg;
        return "";
      })
      .Require([o]() -> std::string { return o->file.empty() ? "no recording given" : ""; })
      .Require([o]() -> std::string {
        return o->csv_dir.empty() && !o->info ? "nothing to do: give --csv DIR and / or --info"
                                              : "";
      });
  return line;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const std::optional<int> exit = CommandLine(&o).Read(argc, argv)) return *exit;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(o.file, ec)) {
    std::fprintf(stderr, "towsim_export: error: %s: not a readable file\n", o.file.c_str());
    return kExitBadInput;
  }
  try {
    using towsim::io::McapReader;
    const McapReader reader = o.recover ? McapReader::Recover(o.file) : McapReader::Open(o.file);
    for (const towsim::io::McapSkipped& skipped : reader.skipped()) {
      std::fprintf(stderr, "towsim_export: %s: skipped %s\n", o.file.c_str(),
                   towsim::io::DescribeSkipped(skipped).c_str());
    }
    if (const std::string nothing = towsim::io::NothingRecovered(reader); !nothing.empty()) {
      std::fprintf(stderr, "towsim_export: error: %s: %s\n", o.file.c_str(), nothing.c_str());
      return kExitBadInput;
    }
    if (o.info) std::printf("%s", towsim::app::RecordingInfo(reader, o.file, o.recover).c_str());
    if (!o.csv_dir.empty()) {
      const auto n = towsim::app::ExportCsv(reader, o.csv_dir, o.ns);
      std::fprintf(
          stderr,
          "towsim_export: %s -> %s: bodies %llu rows, cable %llu, forces %llu, status "
          "%llu%s%s%s\n",
          o.file.c_str(), o.csv_dir.c_str(), static_cast<unsigned long long>(n.bodies_rows),
          static_cast<unsigned long long>(n.cable_rows),
          static_cast<unsigned long long>(n.forces_rows),
          static_cast<unsigned long long>(n.status_rows),
          n.environment_rows == 0 ? ""
                                  : (", environment " + std::to_string(n.environment_rows)).c_str(),
          n.actuators_rows == 0 ? ""
                                : (", actuators " + std::to_string(n.actuators_rows)).c_str(),
          n.commands_rows == 0 ? "" : (", commands " + std::to_string(n.commands_rows)).c_str());
    }
    if (!reader.skipped().empty()) {
      std::fprintf(stderr,
                   "towsim_export: %s: recovered %llu messages in %zu chunks; %zu byte ranges "
                   "lost (exit 4)\n",
                   o.file.c_str(),
                   static_cast<unsigned long long>(reader.statistics().message_count),
                   reader.chunk_indexes().size(), reader.skipped().size());
      return kExitIncomplete;
    }
  } catch (const towsim::io::mcap::McapError& e) {
    std::fprintf(stderr, "towsim_export: error: %s: %s\n", o.file.c_str(), e.what());
    return kExitBadInput;
  } catch (const towsim::io::cdr::CdrError& e) {
    std::fprintf(stderr, "towsim_export: error: %s: %s\n", o.file.c_str(), e.what());
    return kExitBadInput;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "towsim_export: error: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "towsim_export: error: %s\n", e.what());
    return kExitError;
  }
  return kExitOk;
}
