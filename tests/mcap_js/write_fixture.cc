// Writes the MCAP file that check_mcap.mjs opens with @mcap/core:
//   write_fixture FILE N
// N messages, message i on channel i % 3 at log time kT0 + i ms (publish time 5 ns earlier);
// payload = CDR little-endian encapsulation header (00 01 00 00), u32 i, u8 channel id, then
// (i % 37) filler bytes. Chunks close every second of log time, so N = 5000 gives 5 chunks.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <string>
#include <vector>

#include "io/mcap_writer.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s FILE N\n", argv[0]);
    return 2;
  }
  constexpr std::uint64_t kT0 = 1'700'000'000'000'000'000ull;  // [ns]
  constexpr std::uint64_t kMs = 1'000'000;                     // [ns]
  const int n = std::atoi(argv[2]);
  try {
    towsim::io::McapWriter w;
    w.Open(argv[1], "ros2");
    const auto time_schema =
        w.AddSchema("builtin_interfaces/msg/Time", "ros2msg", "int32 sec\nuint32 nanosec\n");
    const auto clock_schema = w.AddSchema(
        "rosgraph_msgs/msg/Clock", "ros2msg",
        "builtin_interfaces/Time clock\n"
        "================================================================================\n"
        "MSG: builtin_interfaces/Time\n"
        "int32 sec\nuint32 nanosec\n");
    const std::vector<std::uint16_t> channels = {
        w.AddChannel(clock_schema, "/clock", "cdr", {{"offered_qos_profiles", ""}}),
        w.AddChannel(time_schema, "/towsim/a", "cdr", {{"offered_qos_profiles", ""}}),
        w.AddChannel(time_schema, "/towsim/b", "cdr", {{"offered_qos_profiles", ""}}),
    };
    w.AddMetadata("towsim", {{"fixture", "write_fixture"}});
    std::map<std::uint16_t, std::uint32_t> sequence;
    for (int i = 0; i < n; ++i) {
      const std::uint16_t c = channels[i % 3];
      std::vector<std::uint8_t> p = {0x00, 0x01, 0x00, 0x00};
      for (int k = 0; k < 4; ++k) p.push_back(static_cast<std::uint8_t>(i >> 8 * k));
      p.push_back(static_cast<std::uint8_t>(c));
      p.resize(p.size() + (i % 37), 0xAB);
      const std::uint64_t t = kT0 + static_cast<std::uint64_t>(i) * kMs;
      w.Write(c, sequence[c]++, t, t - 5, p);
    }
    w.Close();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "write_fixture: %s\n", e.what());
    return 1;
  }
  return 0;
}
