// sim_node/app/foxglove/foxglove_server: the server alone on loopback (no DDS), with small
// bounds so that each case takes a second: a client that never reads is held to its bound and
// closed with a reset; publishing from another thread while clients come and go and the
// server stops, round after round. Built also with -fsanitize=thread and -fsanitize=address
// (docs/faults.md, "Foxglove server shutdown under the sanitizers").

#include "app/foxglove/foxglove_server.h"

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "raw_websocket_client.h"

namespace towsim::app {
namespace {

using testing::RawWebSocketClient;

void Sleep(double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); }

FoxgloveServer::Options SmallBounds() {
  FoxgloveServer::Options o;
  o.port = 0;
  o.program = "foxglove_server_test";
  o.quiet = true;
  o.limits.bound = 256u << 10;
  o.limits.reserve = 16u << 10;
  o.limits.window = 32u << 10;
  o.limits.close_after = 0.5;
  return o;
}

// publishes 2 KB messages on `channel` and the time as fast as it can until `stop`
std::thread Publisher(FoxgloveServer* server, uint32_t channel, std::atomic<bool>* stop) {
  return std::thread([=] {
    const std::string payload(2000, 'x');
    for (uint64_t t = 0; !*stop; ++t) {
      if (server->HasSubscribers(channel)) {
        server->Publish(channel, t, reinterpret_cast<const uint8_t*>(payload.data()),
                        payload.size());
      }
      server->BroadcastTime(t);
      if (t % 64 == 0) std::this_thread::yield();
    }
  });
}

TEST(FoxgloveServer, ANeverReadingSubscriberIsHeldToItsBoundThenReset) {
  FoxgloveServer server(SmallBounds());
  const uint32_t channel = server.AddChannel("/data", "std_msgs/msg/String", "string data");
  server.Start();
  std::atomic<bool> stop{false};
  std::thread publisher = Publisher(&server, channel, &stop);
  RawWebSocketClient idle(server.port());  // the handshake, then nothing
  RawWebSocketClient stalled(server.port());
  stalled.SubscribeAll(stalled.ReadAdvertisedChannels());
  std::size_t max_queued = 0;
  const auto start = std::chrono::steady_clock::now();
  while (!stalled.Closed() && std::chrono::steady_clock::now() - start < std::chrono::seconds(10)) {
    max_queued = std::max(max_queued, server.queued_bytes());
    Sleep(0.005);
  }
  EXPECT_TRUE(stalled.Closed()) << "the never-reading subscriber was not closed in 10 s";
  EXPECT_FALSE(idle.Closed()) << "an idle client is not over its bound";
  // two clients: each at most its bound (sampled: the peak may fall between samples)
  EXPECT_LE(max_queued, 2 * SmallBounds().limits.bound);
  EXPECT_GT(max_queued, SmallBounds().limits.bound / 2);
  stop = true;
  publisher.join();
  server.Stop();
  const FoxgloveServer::Totals t = server.totals();
  EXPECT_EQ(t.clients, 2u);
  EXPECT_EQ(t.clients_closed, 1u);
  EXPECT_GT(t.dropped, 0u);
  EXPECT_GT(t.time_dropped, 0u);
}

TEST(FoxgloveServer, StopsWhilePublishingAndClientsComeAndGo) {
  for (int round = 0; round < 5; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    FoxgloveServer server(SmallBounds());
    const uint32_t channel = server.AddChannel("/data", "std_msgs/msg/String", "string data");
    server.Start();
    const int port = server.port();
    std::atomic<bool> stop{false}, stop_clients{false};
    std::thread publisher = Publisher(&server, channel, &stop);
    std::vector<std::thread> churn;
    std::atomic<int> sessions{0};
    for (int i = 0; i < 3; ++i) {
      churn.emplace_back([&, i] {
        for (int k = 0; !stop_clients; ++k) {
          try {  // refused once the server stops: that is the point
            RawWebSocketClient c(port, 65536);
            c.SubscribeAll(c.ReadAdvertisedChannels(2.0));
            ++sessions;
            if ((i + k) % 3 == 0)
              c.Send(RawWebSocketClient::Frame(0x8, std::string("\x03\xe8", 2)));
            if ((i + k) % 4 == 1) c.Send(RawWebSocketClient::Frame(0x9, "ping"));
            if ((i + k) % 5 == 2) c.Send(RawWebSocketClient::Frame(0x1, "{not json"));
          } catch (const std::exception&) {
            Sleep(0.005);
          }
        }
      });
    }
    RawWebSocketClient stalled(port);
    stalled.SubscribeAll(stalled.ReadAdvertisedChannels());
    Sleep(0.3 + 0.1 * round);
    server.Stop();  // while publishing and churning
    stop = true;
    publisher.join();
    stop_clients = true;
    for (std::thread& t : churn) t.join();
    EXPECT_GT(sessions.load(), 0);
    EXPECT_EQ(server.clients(), 0);
  }
}

}  // namespace
}  // namespace towsim::app
