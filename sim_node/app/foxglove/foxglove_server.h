#pragma once
// A Foxglove WebSocket server (app/foxglove/foxglove_protocol.h, docs/foxglove.md) on websocketpp
// with standalone asio, running its network loop on a thread of its own. Shared by the bridge
// towsim_foxglove (app/foxglove/foxglove_main.cc); nothing in it knows DDS.
//
//   FoxgloveServer server({"127.0.0.1", 8765, "towsim"});
//   uint32_t odom = server.AddChannel("/towsim/towfish/odom", "nav_msgs/msg/Odometry", schema);
//   server.Start();                                    // throws std::runtime_error (port in use)
//   if (server.HasSubscribers(odom)) server.Publish(odom, t_ns, bytes, size);
//   server.BroadcastTime(t_ns);
//
// Thread safety: every public call may come from any thread. Client publishes are handed to
// the ClientPublish callback on the server's thread; its answer ("" accepted, else the reason)
// goes back to the client as an error status and counts as rejected. A client whose send
// buffer holds more than kMaxBuffered bytes misses messages (counted) rather than stalling
// the publisher.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "app/foxglove/foxglove_protocol.h"

namespace towsim::app {

class FoxgloveServer {
 public:
  static constexpr std::size_t kMaxBuffered = 16u << 20;  // [bytes] per client

  struct Options {
    std::string address = "127.0.0.1";  // interface to bind (0.0.0.0: every one)
    uint16_t port = 8765;               // 0: a free port (see port())
    std::string name = "towsim";        // serverInfo name
  };
  // client channel, its payload; returns "" if taken, else why not
  using ClientPublish =
      std::function<std::string(const foxglove::ClientChannel&, const uint8_t*, std::size_t)>;
  // a client channel advertised; returns "" if the server takes messages on it, else why not
  using ClientAdvertise = std::function<std::string(const foxglove::ClientChannel&)>;

  explicit FoxgloveServer(Options options);
  ~FoxgloveServer();  // Stop()
  FoxgloveServer(const FoxgloveServer&) = delete;
  FoxgloveServer& operator=(const FoxgloveServer&) = delete;

  // a channel advertised to every client (also those connected later); returns its id. A
  // latched channel keeps its last message and sends it to each new subscriber (transient
  // local topics: scene_info, /tf_static).
  uint32_t AddChannel(const std::string& topic, const std::string& schema_name,
                      const std::string& schema, bool latched = false);
  void OnClientAdvertise(ClientAdvertise f) { on_advertise_ = std::move(f); }
  void OnClientPublish(ClientPublish f) { on_publish_ = std::move(f); }

  // binds and listens, then serves on a thread; throws std::runtime_error naming the address
  void Start();
  // closes every connection and joins the thread; idempotent
  void Stop();
  uint16_t port() const { return port_; }  // the bound port (after Start)

  bool HasSubscribers(uint32_t channel) const;
  int clients() const { return clients_.load(); }
  // to every client subscribed to `channel` (and kept, if latched)
  void Publish(uint32_t channel, uint64_t log_time_ns, const uint8_t* data, std::size_t size);
  // to every client (the `time` capability)
  void BroadcastTime(uint64_t time_ns);

  uint64_t messages_sent() const { return sent_.load(); }
  uint64_t messages_dropped() const { return dropped_.load(); }
  uint64_t client_messages() const { return client_messages_.load(); }
  uint64_t client_rejected() const { return client_rejected_.load(); }

 private:
  struct Impl;  // the websocketpp endpoint and the clients
  std::unique_ptr<Impl> impl_;
  Options opt_;
  uint16_t port_ = 0;
  ClientAdvertise on_advertise_;
  ClientPublish on_publish_;
  std::atomic<int> clients_{0};
  std::atomic<uint64_t> sent_{0}, dropped_{0}, client_messages_{0}, client_rejected_{0};
};

}  // namespace towsim::app
