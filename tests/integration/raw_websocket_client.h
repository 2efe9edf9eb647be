#pragma once
// A Foxglove client on a bare TCP socket, for the hostile cases of the server's bounds
// (docs/foxglove.md "Bounds"): it does the WebSocket opening handshake (RFC 6455 §4.1, the
// subprotocol foxglove.websocket.v1), may read the frames up to the server's advertisement
// and subscribe, and then reads nothing at all: with a small receive buffer (SO_RCVBUF set
// before connect, so the TCP window stays small) the server's writes stall at once, as for a
// frozen app. It can also send frames (masked, as a client must) as fast as asked without
// reading a byte, and tell whether the server has reset the connection without reading
// (TCP_INFO).

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace towsim::testing {

class RawWebSocketClient {
 public:
  // connects to 127.0.0.1:port and completes the handshake; throws std::runtime_error
  RawWebSocketClient(int port, int receive_buffer = 4096);
  ~RawWebSocketClient();
  RawWebSocketClient(const RawWebSocketClient&) = delete;
  RawWebSocketClient& operator=(const RawWebSocketClient&) = delete;

  // reads frames until the advertisement; returns its channel ids (throws after `timeout` s)
  std::vector<uint32_t> ReadAdvertisedChannels(double timeout = 10.0);
  // reads every frame (the advertisement among them), subscribes to `topic` and reads on until
  // a message on it comes: the server has then handled every frame this client sent before
  // (it handles a connection's frames in order). Throws after `timeout` s.
  void SyncThroughTopic(const std::string& topic, double timeout);
  // sends a subscribe request for every channel (subscription id = channel id)
  void SubscribeAll(const std::vector<uint32_t>& channels);
  // one client frame: opcode 0x1 text, 0x2 binary, 0x9 ping; masked
  static std::string Frame(uint8_t opcode, const std::string& payload);
  // writes `bytes` whole (blocks while the server's receive window is full)
  void Send(const std::string& bytes);
  // the server closed or reset the connection (read without taking any byte)
  bool Closed() const;

 private:
  struct ServerFrame {
    uint8_t opcode = 0;
    std::string payload;
  };
  // the next whole frame from the server (unmasked); throws after the deadline
  ServerFrame ReadFrame(std::chrono::steady_clock::time_point until);

  int fd_ = -1;
  std::string pending_;  // bytes read past the handshake, not yet parsed
};

// the resident set of process `pid` [bytes] (VmRSS of /proc/pid/status); 0 if unknown
std::size_t ResidentBytes(int pid);

}  // namespace towsim::testing
