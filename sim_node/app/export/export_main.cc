// towsim_export: a towsim recording (MCAP) to the CSV files of DESIGN §5 (--csv DIR) and / or a
// summary like `ros2 bag info` (--info). Exit codes: 0 done, 1 unexpected error (e.g. a CSV
// file could not be written), 2 bad input (command line, unreadable or corrupt recording: the
// reader's message names the byte offset), 4 --recover read the file but skipped damaged or
// cut-off byte ranges (each on stderr: bytes, message count, the damage); the output holds
// every intact chunk.
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

#include "app/export/export_csv.h"
#include "app/export/export_info.h"
#include "io/cdr_reader.h"
#include "io/mcap_format.h"
#include "io/mcap_reader.h"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitError = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitRecoveredWithLosses = 4;

constexpr char kUsage[] =
    "usage: towsim_export FILE.mcap [--csv DIR] [--info] [--namespace NS] [--recover]\n"
    "  --csv DIR         write bodies.csv, cable.csv, forces.csv, status.csv into DIR\n"
    "  --info            print topics, types, counts and the time range (like ros2 bag info)\n"
    "  --namespace NS    the node's namespace in the recording (default /towsim)\n"
    "  --recover         read what a killed recorder or damage left: every intact chunk;\n"
    "                    skipped byte ranges on stderr and exit 4 if anything was lost\n"
    "  --help            print this and exit\n"
    "At least one of --csv and --info.\n";

int Usage(const std::string& error) {
  std::fprintf(stderr, "towsim_export: error: %s\n%s", error.c_str(), kUsage);
  return kExitBadInput;
}

}  // namespace

int main(int argc, char** argv) {
  std::string file, csv_dir, ns = "/towsim";
  bool info = false, recover = false;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i], value;
    bool has_value = false;
    if (arg.rfind("--", 0) == 0 && arg.find('=') != std::string::npos) {
      value = arg.substr(arg.find('=') + 1);
      arg = arg.substr(0, arg.find('='));
      has_value = true;
    }
    // the option's value: after '=' or the next argument
    auto take = [&]() -> bool {
      if (has_value) return true;
      if (i + 1 >= argc) return false;
      value = argv[++i];
      return true;
    };
    if (arg == "--help" || arg == "-h") {
      std::printf("%s", kUsage);
      return kExitOk;
    } else if (arg == "--csv") {
      if (!take() || value.empty()) return Usage("--csv needs a directory");
      csv_dir = value;
    } else if (arg == "--namespace") {
      if (!take() || value.empty() || value[0] != '/') {
        return Usage("--namespace = '" + value + "': must start with '/'");
      }
      ns = value.size() > 1 && value.back() == '/' ? value.substr(0, value.size() - 1) : value;
    } else if (arg == "--info" && !has_value) {
      info = true;
    } else if (arg == "--recover" && !has_value) {
      recover = true;
    } else if (arg.rfind("-", 0) == 0) {
      return Usage("unknown option '" + arg + "'");
    } else if (file.empty()) {
      file = arg;
    } else {
      return Usage("more than one file: '" + file + "' and '" + arg + "'");
    }
  }
  if (file.empty()) return Usage("no recording given");
  if (csv_dir.empty() && !info) return Usage("nothing to do: give --csv DIR and / or --info");

  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    std::fprintf(stderr, "towsim_export: error: %s: not a readable file\n", file.c_str());
    return kExitBadInput;
  }
  try {
    using towsim::io::McapReader;
    const McapReader reader = recover ? McapReader::Recover(file) : McapReader::Open(file);
    if (info) std::printf("%s", towsim::app::RecordingInfo(reader, file, recover).c_str());
    if (!csv_dir.empty()) {
      const auto n = towsim::app::ExportCsv(reader, csv_dir, ns);
      std::fprintf(stderr,
                   "towsim_export: %s -> %s: bodies %llu rows, cable %llu, forces %llu, status "
                   "%llu%s\n",
                   file.c_str(), csv_dir.c_str(), static_cast<unsigned long long>(n.bodies_rows),
                   static_cast<unsigned long long>(n.cable_rows),
                   static_cast<unsigned long long>(n.forces_rows),
                   static_cast<unsigned long long>(n.status_rows),
                   n.environment_rows == 0
                       ? ""
                       : (", environment " + std::to_string(n.environment_rows)).c_str());
    }
    if (!reader.skipped().empty()) {
      for (const towsim::io::McapSkipped& skipped : reader.skipped()) {
        std::fprintf(stderr, "towsim_export: %s: skipped %s\n", file.c_str(),
                     towsim::io::DescribeSkipped(skipped).c_str());
      }
      std::fprintf(stderr,
                   "towsim_export: %s: recovered %llu messages in %zu chunks; %zu byte ranges "
                   "lost (exit 4)\n",
                   file.c_str(), static_cast<unsigned long long>(reader.statistics().message_count),
                   reader.chunk_indexes().size(), reader.skipped().size());
      return kExitRecoveredWithLosses;
    }
  } catch (const towsim::io::mcap::McapError& e) {
    std::fprintf(stderr, "towsim_export: error: %s: %s\n", file.c_str(), e.what());
    return kExitBadInput;
  } catch (const towsim::io::cdr::CdrError& e) {
    std::fprintf(stderr, "towsim_export: error: %s: %s\n", file.c_str(), e.what());
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
