// The Foxglove servers' bounds through the real binaries (docs/foxglove.md "Bounds",
// docs/faults.md): sim_node --foxglove (fast mode) and towsim_foxglove beside a node, each with
// three clients that never read (tests/integration/raw_websocket_client.h): one idle after the
// handshake, one subscribed to every channel (it reconnects when the server closes it, as
// Foxglove does), one sending malformed frames without pause. Before the bound, one idle
// client took a fast node from 11 MB to 724 MB in 180 s and the flood grew the bridge by
// 10 MB/s with `malformed 0` in its summary. Also: the bridge's bad --address or busy port at
// start-up, and the in-node server's shutdown under clients that come and go.
// DDS domains: leased from 200-205 (TOWSIM_TEST_DOMAINS, set by CMake).

#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "raw_websocket_client.h"
#include "testing/dds_domain.h"
#include "testing/process.h"

namespace towsim::testing {
namespace {

using Clock = std::chrono::steady_clock;

const std::string kSource = TOWSIM_SOURCE_DIR;
const std::string kCase1 = kSource + "/config/scenes/case1_forward.yaml";

// the documented bound on what a server holds for one client (docs/foxglove.md "Bounds")
constexpr std::size_t kBound = 8u << 20;  // [bytes]
constexpr int kClients = 3;               // the never-reading clients of each server
// what a process may grow by beside its clients' queues: the bridge's DDS readers for every
// topic while a client subscribes (Cyclone's history and receive buffers), the allocator's
// arenas of the server thread and fragmentation; measured below 5 MB on this machine
constexpr std::size_t kAllowance = 16u << 20;  // [bytes]
constexpr double kSoak = 60.0;                 // [s] the clients stay this long
constexpr double kFloodPause = 0.05;           // [s] between bursts of the flood
constexpr int kFloodBurst = 500;               // frames of each kind a burst
// [s] the server takes the flood's last frames and answers a subscription after them: on a
// loaded machine it may be seconds behind the flood
constexpr double kDrainTimeout = 60.0;
constexpr double kProcessTimeout = 30.0;  // [s] a stop that takes longer has hung

void Sleep(double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); }

// the port of "...ws://127.0.0.1:PORT..." in a process's stdout, waiting for it
int PortFrom(Process& p, const std::string& marker, double timeout = 20.0) {
  const auto until = Clock::now() + std::chrono::duration<double>(timeout);
  while (Clock::now() < until) {
    const std::string out = p.out();
    const std::size_t at = out.find(marker);
    if (at != std::string::npos) {
      const std::size_t colon = out.find(':', at + marker.size());
      if (colon != std::string::npos) return std::stoi(out.substr(colon + 1));
    }
    if (!p.running()) break;
    Sleep(0.05);
  }
  ADD_FAILURE() << "no '" << marker << "' in stdout: " << p.out() << "\nstderr: " << p.err();
  return -1;
}

// the counts of a server's summary (FoxgloveServer::SummaryText)
struct Summary {
  bool found = false;
  uint64_t sent = 0, dropped = 0, client_messages = 0, client_rejected = 0, client_malformed = 0,
           requests = 0, requests_refused = 0, requests_malformed = 0, replies = 0, suppressed = 0,
           time_dropped = 0, clients = 0, closed = 0;
};

Summary ParseSummary(const std::string& text) {
  static const std::regex kLine(
      R"((\d+) messages sent \(dropped (\d+)\), client messages (\d+) \(rejected (\d+), )"
      R"(malformed (\d+)\), requests (\d+) \(refused (\d+), malformed (\d+)\), error replies )"
      R"((\d+) \(suppressed (\d+)\), time messages dropped (\d+), clients (\d+) \(closed at )"
      R"(the bound (\d+)\))");
  Summary s;
  std::smatch m;
  if (!std::regex_search(text, m, kLine)) return s;
  uint64_t* f[] = {&s.sent,
                   &s.dropped,
                   &s.client_messages,
                   &s.client_rejected,
                   &s.client_malformed,
                   &s.requests,
                   &s.requests_refused,
                   &s.requests_malformed,
                   &s.replies,
                   &s.suppressed,
                   &s.time_dropped,
                   &s.clients,
                   &s.closed};
  for (std::size_t i = 0; i < 13; ++i) *f[i] = std::stoull(m[i + 1].str());
  s.found = true;
  return s;
}

int CountLines(const std::string& text, const std::string& part) {
  int n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
    ++n;
  }
  return n;
}

// the three never-reading clients of one server, on threads of their own
class Stallers {
 public:
  explicit Stallers(int port) : port_(port) {
    idle_ = std::make_unique<RawWebSocketClient>(port_);  // the handshake, then nothing
    threads_.emplace_back([this] { Subscriber(); });
    threads_.emplace_back([this] { Flood(); });
  }
  ~Stallers() { Stop(); }
  void Stop() {
    stop_ = true;
    for (std::thread& t : threads_) {
      if (t.joinable()) t.join();
    }
  }
  // the end: the flood stops, the subscriber does not come back once closed (the sockets stay
  // open, so that the server takes every frame sent before the end)
  void StopFlood() {
    stop_flood_ = true;
    no_reconnect_ = true;
  }

  std::atomic<uint64_t> binary_sent{0}, text_sent{0};  // malformed frames the flood wrote
  std::atomic<int> subscribes{0};                      // connections of the subscriber
  std::atomic<int> closed_seen{0};                     // ... that the server closed
  std::atomic<int> syncs{0};  // the flood's subscription after it: 1 when it was served
  std::string error;          // a client that failed

 private:
  // subscribes to every channel and reads nothing; reconnects once the server closed it
  void Subscriber() {
    try {
      while (!stop_ && !no_reconnect_) {
        RawWebSocketClient c(port_);
        c.SubscribeAll(c.ReadAdvertisedChannels());
        ++subscribes;
        while (!stop_ && !c.Closed()) Sleep(0.2);
        if (c.Closed()) ++closed_seen;
      }
    } catch (const std::exception& e) {
      Fail(std::string("subscriber: ") + e.what());
    }
  }
  // bursts of malformed frames (a binary frame of an unknown opcode, a text frame that is no
  // JSON), every kFloodPause, never reading
  void Flood() {
    try {
      RawWebSocketClient c(port_);
      std::string burst;
      const std::string binary = RawWebSocketClient::Frame(0x2, std::string("\x07"
                                                                            "abcdef",
                                                                            7));
      const std::string text = RawWebSocketClient::Frame(0x1, "{\"op\":");
      for (int i = 0; i < kFloodBurst; ++i) burst += binary + text;
      while (!stop_ && !stop_flood_) {
        c.Send(burst);
        binary_sent += kFloodBurst;
        text_sent += kFloodBurst;
        Sleep(kFloodPause);
      }
      // now it reads: once a message of a subscription made after the flood came, the server
      // has counted every frame of the flood (however far a loaded machine kept it behind)
      c.SyncThroughTopic("/towsim/scene_info", kDrainTimeout);
      ++syncs;
      while (!stop_) Sleep(0.1);  // connected until the end
    } catch (const std::exception& e) {
      Fail(std::string("flood: ") + e.what());
    }
  }
  void Fail(const std::string& e) {
    std::lock_guard<std::mutex> lock(mutex_);
    error += e + "\n";
  }

  int port_;
  std::unique_ptr<RawWebSocketClient> idle_;
  std::vector<std::thread> threads_;
  std::atomic<bool> stop_{false}, stop_flood_{false}, no_reconnect_{false};
  std::mutex mutex_;
};

struct RssTrace {
  std::size_t baseline = 0;          // before the clients came [bytes]
  std::vector<std::size_t> samples;  // while they stayed
  std::size_t Max(std::size_t from, std::size_t to) const {
    std::size_t m = 0;
    for (std::size_t i = from; i < std::min(to, samples.size()); ++i) m = std::max(m, samples[i]);
    return m;
  }
};

void CheckServer(const std::string& name, const RssTrace& rss, const Stallers& clients,
                 const std::string& summary_text, const std::string& err) {
  SCOPED_TRACE(name);
  ASSERT_FALSE(rss.samples.empty());
  const std::size_t peak = rss.Max(0, rss.samples.size());
  const double mb = 1.0 / (1 << 20);
  std::printf(
      "%s: RSS %.1f MB before the clients, peak %.1f MB (growth %.1f MB; bound %d x %.0f "
      "MB + %.0f MB), first half's peak %.1f MB, second half's %.1f MB\n",
      name.c_str(), rss.baseline * mb, peak * mb, (peak - rss.baseline) * mb, kClients, kBound * mb,
      kAllowance * mb, rss.Max(0, rss.samples.size() / 2) * mb,
      rss.Max(rss.samples.size() / 2, rss.samples.size()) * mb);
  EXPECT_LE(peak, rss.baseline + kClients * kBound + kAllowance);

  const Summary s = ParseSummary(summary_text);
  ASSERT_TRUE(s.found) << summary_text;
  ASSERT_EQ(clients.syncs.load(), 1) << "the flood's subscription after it was not served";
  // every malformed frame counted, none lost to the summary
  EXPECT_EQ(s.client_malformed, clients.binary_sent.load()) << summary_text;
  EXPECT_EQ(s.client_rejected, clients.binary_sent.load()) << summary_text;
  EXPECT_EQ(s.requests_malformed, clients.text_sent.load()) << summary_text;
  // and the subscriber's and the flood's subscriptions
  EXPECT_EQ(s.requests, clients.text_sent.load() + clients.subscribes.load() + 1) << summary_text;
  EXPECT_GT(clients.binary_sent.load(), 100000u);  // a flood: ~20000 frames a second
  // replies: one per malformed frame offered, few sent (10 a second, 20 saved up)
  EXPECT_EQ(s.replies, s.client_malformed + s.requests_malformed) << summary_text;
  EXPECT_GE(s.suppressed, s.replies - static_cast<uint64_t>(20 + 10 * (kSoak + 20)))
      << summary_text;
  // the subscriber filled its queue, was dropped data and closed at the bound (and came back)
  EXPECT_GT(s.dropped, 0u) << summary_text;
  EXPECT_GE(s.closed, 1u) << summary_text;
  EXPECT_GE(clients.closed_seen.load(), 1) << "the subscriber never saw its connection closed";
  // the idle client, the flood, a probe, each connection of the subscriber
  EXPECT_EQ(s.clients, static_cast<uint64_t>(3 + clients.subscribes.load())) << summary_text;
  EXPECT_GT(s.time_dropped, 0u) << summary_text;
  // the notes on stderr: 10 in full, then a count every 10 s (and one at the end)
  const int refusal_lines = CountLines(err, ": unsupported binary opcode 7") +
                            CountLines(err, "more Foxglove client messages or requests refused");
  EXPECT_LE(refusal_lines, 10 + static_cast<int>(kSoak / 10) + 4) << err;
  EXPECT_GE(CountLines(err, " closed: send queue at its bound (8 MiB) for "), 1) << err;
}

TEST(FoxgloveBounds, NeverReadingClientsCostTheNodeAndTheBridgeAtMostTheBoundEach) {
  DomainLease node_domain, bridge_domain;
  // the node with its own server, in fast mode
  Process node(SimNodeArgs(TOWSIM_SIM_NODE, kCase1, "fast", node_domain.id(),
                           {"--foxglove", "0", "--duration", "1e7"}),
               LogPrefix("node"));
  // a paced node (400 steps a second) and the bridge serving it
  Process paced(SimNodeArgs(TOWSIM_SIM_NODE, kCase1, "realtime", bridge_domain.id(),
                            {"--rate", "20", "--duration", "1e7"}),
                LogPrefix("paced"));
  Process bridge({TOWSIM_FOXGLOVE, "--domain", std::to_string(bridge_domain.id()), "--port", "0"},
                 LogPrefix("bridge"));
  const int node_port = PortFrom(node, "Foxglove at ws://127.0.0.1");
  const int bridge_port = PortFrom(bridge, "serving ws://127.0.0.1");
  ASSERT_GT(node_port, 0);
  ASSERT_GT(bridge_port, 0);
  // the bridge accepts once the paced node's scene info came: a client's handshake waits
  for (int port : {node_port, bridge_port}) {
    RawWebSocketClient probe(port, 65536);
    probe.ReadAdvertisedChannels(20.0);
  }
  Sleep(2.0);  // both servers past their start

  RssTrace node_rss, bridge_rss;
  node_rss.baseline = ResidentBytes(node.pid());
  bridge_rss.baseline = ResidentBytes(bridge.pid());
  Stallers at_node(node_port), at_bridge(bridge_port);
  const auto start = Clock::now();
  while (Clock::now() - start < std::chrono::duration<double>(kSoak)) {
    Sleep(0.5);
    node_rss.samples.push_back(ResidentBytes(node.pid()));
    bridge_rss.samples.push_back(ResidentBytes(bridge.pid()));
    ASSERT_TRUE(node.running()) << node.err();
    ASSERT_TRUE(bridge.running()) << bridge.err();
  }
  at_node.StopFlood();
  at_bridge.StopFlood();
  const auto drain_start = Clock::now();
  while ((at_node.syncs < 1 || at_bridge.syncs < 1) &&
         Clock::now() - drain_start < std::chrono::duration<double>(kDrainTimeout + 5.0)) {
    Sleep(0.1);
  }
  std::printf("the servers took the flood's last frames %.1f s after it ended\n",
              std::chrono::duration<double>(Clock::now() - drain_start).count());
  node.Signal(SIGINT);
  bridge.Signal(SIGINT);
  ASSERT_TRUE(node.Wait(kProcessTimeout)) << "sim_node did not stop";
  ASSERT_TRUE(bridge.Wait(kProcessTimeout)) << "towsim_foxglove did not stop";
  at_node.Stop();
  at_bridge.Stop();
  paced.Signal(SIGINT);
  ASSERT_TRUE(paced.Wait(kProcessTimeout));
  EXPECT_EQ(node.exit_code(), 0) << node.err();
  EXPECT_EQ(bridge.exit_code(), 0) << bridge.err();
  EXPECT_TRUE(at_node.error.empty()) << at_node.error;
  EXPECT_TRUE(at_bridge.error.empty()) << at_bridge.error;

  const std::string node_err = node.err();
  const std::size_t fox = node_err.find("sim_node: Foxglove: ");
  ASSERT_NE(fox, std::string::npos) << node_err;
  CheckServer("sim_node --foxglove", node_rss, at_node, node_err.substr(fox), node_err);
  CheckServer("towsim_foxglove", bridge_rss, at_bridge, bridge.out(), bridge.err());
}

// the bridge found a bad address or a busy port only after a node appeared (without one it
// waited forever); now it listens first
TEST(FoxgloveBounds, BridgeRefusesABadAddressOrABusyPortAtStartUp) {
  DomainLease domain;  // no node on it
  const int busy = socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(busy, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(bind(busy, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
  ASSERT_EQ(listen(busy, 1), 0);
  socklen_t size = sizeof a;
  ASSERT_EQ(getsockname(busy, reinterpret_cast<sockaddr*>(&a), &size), 0);
  const std::string port = std::to_string(ntohs(a.sin_port));
  struct Case {
    std::vector<std::string> flags;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"--port", port},
       "towsim_foxglove: error: --address 127.0.0.1 --port " + port +
           ": listening on 127.0.0.1:" + port +
           ": Address already in use (the address must be one of this machine's, the "
           "port free)"},
      {{"--port", "0", "--address", "999.1.1.1"},
       "towsim_foxglove: error: --address 999.1.1.1 --port 0: address 999.1.1.1: not an IPv4 or "
       "IPv6 address"},
      // TEST-NET-1 (RFC 5737): an address of no interface here
      {{"--port", "0", "--address", "192.0.2.1"},
       "listening on 192.0.2.1:0: Cannot assign requested address"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> argv = {TOWSIM_FOXGLOVE, "--domain", std::to_string(domain.id())};
    argv.insert(argv.end(), c.flags.begin(), c.flags.end());
    Process bridge(argv, LogPrefix("bridge"));
    ASSERT_TRUE(bridge.Wait(15.0)) << "still waiting, for a node: " << bridge.command_line();
    EXPECT_EQ(bridge.exit_code(), 2) << bridge.err();
    EXPECT_NE(bridge.err().find(c.message), std::string::npos) << bridge.err();
    EXPECT_EQ(bridge.out().find("serving"), std::string::npos) << bridge.out();
  }
  close(busy);
}

// sim_node --foxglove once ended with SIGSEGV on SIGINT right after a client disconnected: the
// node is stopped, round after round, while clients connect, subscribe and leave (some with a
// close frame, most dropping the socket with unread data: a reset) and one never reads
TEST(FoxgloveBounds, InNodeServerStopsCleanlyWhileClientsComeAndGo) {
  constexpr int kRounds = 6;
  constexpr int kChurners = 3;  // clients coming and going
  DomainLease domain;
  for (int round = 0; round < kRounds; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    Process node(SimNodeArgs(TOWSIM_SIM_NODE, kCase1, "fast", domain.id(),
                             {"--foxglove", "0", "--duration", "1e7"}),
                 LogPrefix("node" + std::to_string(round)));
    const int port = PortFrom(node, "Foxglove at ws://127.0.0.1");
    ASSERT_GT(port, 0);
    std::atomic<bool> stop{false};
    std::atomic<int> sessions{0};
    std::vector<std::thread> churn;
    for (int i = 0; i < kChurners; ++i) {
      churn.emplace_back([&, i] {
        for (int k = 0; !stop; ++k) {
          try {  // refused or cut once the node stops: that is the point
            RawWebSocketClient c(port, 65536);
            c.SubscribeAll(c.ReadAdvertisedChannels(5.0));
            ++sessions;
            Sleep(0.01 * ((i + k) % 5));
            if (k % 3 == 0) c.Send(RawWebSocketClient::Frame(0x8, std::string("\x03\xe8", 2)));
          } catch (const std::exception&) {
            Sleep(0.01);
          }
        }
      });
    }
    std::unique_ptr<RawWebSocketClient> stalled;
    try {
      stalled = std::make_unique<RawWebSocketClient>(port);
      stalled->SubscribeAll(stalled->ReadAdvertisedChannels());
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
    }
    Sleep(1.0 + 0.1 * round);
    node.Signal(SIGINT);
    const bool exited = node.Wait(kProcessTimeout);
    stop = true;
    for (std::thread& t : churn) t.join();
    ASSERT_TRUE(exited) << "sim_node did not stop: " << node.err();
    EXPECT_EQ(node.exit_code(), 0) << node.err();
    EXPECT_NE(node.out().find("sim_node: case1_forward: fast, "), std::string::npos) << node.out();
    EXPECT_NE(node.err().find("sim_node: Foxglove: "), std::string::npos) << node.err();
    EXPECT_GT(sessions.load(), 0);
  }
}

}  // namespace
}  // namespace towsim::testing
