#include "app/export/export_info.h"

#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <string>

#include "io/mcap_reader.h"

namespace towsim::app {
namespace {

// "19.0 KiB", as rosbag2 prints sizes
std::string HumanSize(std::uintmax_t bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  double v = static_cast<double>(bytes);
  int u = 0;
  while (v >= 1024.0 && u < 4) {
    v /= 1024.0;
    ++u;
  }
  char out[32];
  std::snprintf(out, sizeof out, u == 0 ? "%.0f %s" : "%.1f %s", v, units[u]);
  return out;
}

// "Jan  1 2024 12:00:00.123456789 (1704110400.123456789)", local time
std::string TimePoint(std::uint64_t ns) {
  const std::time_t sec = static_cast<std::time_t>(ns / 1'000'000'000);
  const unsigned long frac = static_cast<unsigned long>(ns % 1'000'000'000);
  std::tm tm{};
  localtime_r(&sec, &tm);
  char date[64];
  std::strftime(date, sizeof date, "%b %e %Y %H:%M:%S", &tm);
  char out[128];
  std::snprintf(out, sizeof out, "%s.%09lu (%lld.%09lu)", date, frac, static_cast<long long>(sec),
                frac);
  return out;
}

}  // namespace

std::string RecordingInfo(const std::string& mcap_path, bool recover) {
  return RecordingInfo(
      recover ? io::McapReader::Recover(mcap_path) : io::McapReader::Open(mcap_path), mcap_path,
      recover);
}

std::string RecordingInfo(const io::McapReader& r, const std::string& mcap_path, bool recover) {
  const io::McapStatistics& s = r.statistics();
  const std::uint64_t duration =
      s.message_count > 0 ? s.message_end_time - s.message_start_time : 0;
  std::string storage = "mcap";
  for (const auto& m : r.metadata()) {
    if (m.name != "rosbag2") continue;
    // "storage_identifier: "mcap"" in the bag information YAML
    const auto it = m.metadata.find("serialized_metadata");
    if (it == m.metadata.end()) continue;
    const auto key = it->second.find("storage_identifier:");
    if (key == std::string::npos) continue;
    std::string v = it->second.substr(key + 19, it->second.find('\n', key) - key - 19);
    v.erase(0, v.find_first_not_of(" \""));
    v.erase(v.find_last_not_of(" \"") + 1);
    if (!v.empty()) storage = v;
  }

  std::string out;
  char line[512];
  auto add = [&](const char* label, const std::string& value) {
    std::snprintf(line, sizeof line, "%-19s%s\n", label, value.c_str());
    out += line;
  };
  add("Files:", mcap_path);
  add("Bag size:", HumanSize(std::filesystem::file_size(mcap_path)));
  add("Storage id:", storage);
  char d[64];
  std::snprintf(d, sizeof d, "%llu.%09llus",
                static_cast<unsigned long long>(duration / 1'000'000'000),
                static_cast<unsigned long long>(duration % 1'000'000'000));
  add("Duration:", d);
  add("Start:", s.message_count > 0 ? TimePoint(s.message_start_time) : "-");
  add("End:", s.message_count > 0 ? TimePoint(s.message_end_time) : "-");
  add("Messages:", std::to_string(s.message_count));
  bool first = true;
  for (const auto& [id, c] : r.channels()) {
    const auto schema = r.schemas().find(c.schema_id);
    const auto count = s.channel_message_counts.find(id);
    const std::string topic =
        "Topic: " + c.topic +
        " | Type: " + (schema == r.schemas().end() ? std::string("-") : schema->second.name) +
        " | Count: " + std::to_string(count == s.channel_message_counts.end() ? 0 : count->second) +
        " | Serialization Format: " + c.message_encoding;
    add(first ? "Topic information:" : "", topic);
    first = false;
  }
  if (first) add("Topic information:", "-");
  add("MCAP profile:", r.profile() + " (library " + r.library() + ")");
  add("Chunks:", std::to_string(r.chunk_indexes().size()));
  std::string metadata;
  for (const auto& m : r.metadata()) metadata += (metadata.empty() ? "" : ", ") + m.name;
  add("Metadata records:", metadata.empty() ? "-" : metadata);
  if (recover) {
    add("Recovered:",
        r.recovered() ? r.recovery_note() : "the data section is complete (summary not used)");
  }
  return out;
}

}  // namespace towsim::app
