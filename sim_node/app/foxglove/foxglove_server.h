#pragma once
// A Foxglove WebSocket server (app/foxglove/foxglove_protocol.h, docs/foxglove.md) on websocketpp
// with standalone asio, running its network loop on a thread of its own. Shared by the bridge
// towsim_foxglove (app/foxglove/foxglove_main.cc) and sim_node --foxglove; nothing in it knows
// DDS.
//
//   FoxgloveServer server({"127.0.0.1", 8765, "towsim"});
//   uint32_t odom = server.AddChannel("/towsim/towfish/odom", "nav_msgs/msg/Odometry", schema);
//   server.Start();                                    // throws std::runtime_error (port in use)
//   if (server.HasSubscribers(odom)) server.Publish(odom, t_ns, bytes, size);
//   server.BroadcastTime(t_ns);
//
// Thread safety: every public call may come from any thread (the callbacks are set before
// Start). Client publishes are handed to the ClientPublish callback on the server's thread; its
// refusal goes back to the client as an error status and is counted.
//
// Bounds (docs/foxglove.md "Bounds", docs/faults.md): every frame for a client goes through its
// ClientQueue (app/foxglove/client_queue.h), which holds at most Limits::bound bytes: data is
// dropped and counted at the bound, time frames replace the one waiting, status replies and
// pongs are rate-limited, and a client that stays at the bound reading nothing for
// Limits::close_after seconds is closed (close code 1008 with the reason). So the server holds
// at most clients x bound for its clients. Publish and BroadcastTime only queue (no socket work
// on the caller's thread); the server's thread hands the frames to the sockets. A client
// message larger than max_client_message closes its connection (1009). Refused and malformed
// client messages and requests are counted (totals()) and noted on stderr through a
// NoteThrottle: the first 10 in full, then a count every 10 s.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "app/foxglove/client_queue.h"
#include "app/foxglove/foxglove_protocol.h"

namespace towsim::app {

class FoxgloveServer {
 public:
  struct Options {
    std::string address = "127.0.0.1";          // interface to bind (0.0.0.0: every one)
    uint16_t port = 8765;                       // 0: a free port (see port())
    std::string name = "towsim";                // serverInfo name
    std::string program = "towsim";             // names the notes on stderr ("sim_node: ...")
    bool quiet = false;                         // no notes on stderr
    foxglove::ClientQueue::Limits limits;       // per client
    std::size_t max_client_message = 1u << 20;  // [bytes] one message from a client
  };
  // why a client message was refused ("" taken); malformed: not a valid message of its type
  struct Verdict {
    std::string error;
    bool malformed = false;
  };
  // client channel, its payload; returns the verdict
  using ClientPublish =
      std::function<Verdict(const foxglove::ClientChannel&, const uint8_t*, std::size_t)>;
  // a client channel advertised; returns "" if the server takes messages on it, else why not
  using ClientAdvertise = std::function<std::string(const foxglove::ClientChannel&)>;

  // what the server counted since it started (the summary lines of both programs)
  struct Totals {
    uint64_t sent = 0;          // data messages handed to a client's socket
    uint64_t dropped = 0;       // data messages dropped: a client's queue at its bound
    uint64_t time_dropped = 0;  // time messages replaced by a newer one before being sent
    uint64_t client_messages = 0, client_rejected = 0, client_malformed = 0;  // clientPublish
    uint64_t requests = 0, requests_refused = 0, requests_malformed = 0;      // text requests
    uint64_t replies = 0, replies_suppressed = 0;  // error status replies: queued, not sent
    uint64_t clients = 0, clients_closed = 0;      // connections opened; closed at the bound
  };
  // "1234 messages sent (dropped 0), client messages 10 (rejected 1, malformed 1), requests 4
  // (refused 1, malformed 0), error replies 2 (suppressed 0), time messages dropped 0, clients 1
  // (closed at the bound 0)"
  static std::string SummaryText(const Totals& t);

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

  // binds and listens (port() is then known), accepting no connection yet; throws
  // std::runtime_error naming the address. Idempotent.
  void Listen();
  // Listen() if not yet, then accepts and serves on a thread
  void Start();
  // closes every connection and joins the thread; idempotent
  void Stop();
  uint16_t port() const { return port_; }  // the bound port (after Listen)

  bool HasSubscribers(uint32_t channel) const;
  int clients() const { return clients_.load(); }
  // queued for every client subscribed to `channel` (and kept, if latched)
  void Publish(uint32_t channel, uint64_t log_time_ns, const uint8_t* data, std::size_t size);
  // queued for every client (the `time` capability)
  void BroadcastTime(uint64_t time_ns);

  Totals totals() const;
  // the bytes queued for every client now (ClientQueue::queued(), summed)
  std::size_t queued_bytes() const;

 private:
  // on the server's thread: hands queued frames to the sockets, closes clients at the bound
  void Pump();
  // asks the server's thread to Pump (once, however often asked before it runs)
  void RequestPump();
  void Tick();  // Pump and the notes' counts, every kTick
  // a client's message (websocketpp's connection_hdl is a std::weak_ptr<void>)
  void OnMessage(const std::weak_ptr<void>& h, bool binary, const std::string& payload);

  struct Impl;  // the websocketpp endpoint, the clients and their queues
  std::unique_ptr<Impl> impl_;
  Options opt_;
  uint16_t port_ = 0;
  ClientAdvertise on_advertise_;
  ClientPublish on_publish_;
  std::atomic<int> clients_{0};
};

}  // namespace towsim::app
