#include "raw_websocket_client.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace towsim::testing {
namespace {

std::runtime_error Error(const std::string& what) {
  return std::runtime_error(what + ": " + std::strerror(errno));
}

}  // namespace

RawWebSocketClient::RawWebSocketClient(int port, int receive_buffer) {
  fd_ = socket(AF_INET, SOCK_STREAM, 0);
  if (fd_ < 0) throw Error("socket");
  // before connect: the window the client offers stays this small
  setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &receive_buffer, sizeof receive_buffer);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
    close(fd_);
    throw Error("connecting to 127.0.0.1:" + std::to_string(port));
  }
  Send("GET / HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
       "\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
       "Sec-WebSocket-Key: dG93c2ltIHJhdyBjbGllbnQ=\r\nSec-WebSocket-Version: 13\r\n"
       "Sec-WebSocket-Protocol: foxglove.websocket.v1\r\n\r\n");
  // the response's head, byte by byte: nothing after it is taken
  std::string head;
  while (head.size() < 4 || head.compare(head.size() - 4, 4, "\r\n\r\n") != 0) {
    char c;
    const ssize_t n = recv(fd_, &c, 1, 0);
    if (n <= 0) {
      close(fd_);
      throw std::runtime_error("handshake: connection ended after " + head);
    }
    head.push_back(c);
  }
  if (head.rfind("HTTP/1.1 101", 0) != 0) {
    close(fd_);
    throw std::runtime_error("handshake refused: " + head);
  }
}

RawWebSocketClient::~RawWebSocketClient() {
  if (fd_ >= 0) close(fd_);
}

RawWebSocketClient::ServerFrame RawWebSocketClient::ReadFrame(
    std::chrono::steady_clock::time_point until) {
  for (;;) {
    // one whole frame in pending_? (FIN, opcode; length in 7, 7+16 or 7+64 bits; payload)
    if (pending_.size() >= 2) {
      const auto b = [this](std::size_t i) { return static_cast<uint8_t>(pending_[i]); };
      std::size_t len = b(1) & 0x7f, at = 2;
      bool whole_header = true;
      if (len == 126) {
        whole_header = pending_.size() >= 4;
        if (whole_header) len = (std::size_t{b(2)} << 8) | b(3);
        at = 4;
      } else if (len == 127) {
        whole_header = pending_.size() >= 10;
        if (whole_header) {
          len = 0;
          for (int i = 0; i < 8; ++i) len = (len << 8) | b(2 + i);
        }
        at = 10;
      }
      if (whole_header && pending_.size() >= at + len) {
        ServerFrame f{static_cast<uint8_t>(b(0) & 0x0f), pending_.substr(at, len)};
        pending_.erase(0, at + len);
        return f;
      }
    }
    if (std::chrono::steady_clock::now() > until) throw std::runtime_error("no frame in time");
    pollfd p{fd_, POLLIN, 0};
    if (poll(&p, 1, 100) <= 0) continue;
    char buffer[65536];
    const ssize_t n = recv(fd_, buffer, sizeof buffer, 0);
    if (n <= 0) throw std::runtime_error("the server ended the connection");
    pending_.append(buffer, static_cast<std::size_t>(n));
  }
}

std::vector<uint32_t> RawWebSocketClient::ReadAdvertisedChannels(double timeout) {
  const auto until = std::chrono::steady_clock::now() +
                     std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                         std::chrono::duration<double>(timeout));
  for (;;) {
    const ServerFrame f = ReadFrame(until);
    if (f.opcode != 1) continue;
    const nlohmann::json j = nlohmann::json::parse(f.payload);
    if (j.at("op") != "advertise") continue;
    std::vector<uint32_t> ids;
    for (const auto& c : j.at("channels")) ids.push_back(c.at("id").get<uint32_t>());
    return ids;
  }
}

void RawWebSocketClient::SyncThroughTopic(const std::string& topic, double timeout) {
  constexpr uint32_t kSubscription = 0x5e1f;
  const auto until = std::chrono::steady_clock::now() +
                     std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                         std::chrono::duration<double>(timeout));
  bool subscribed = false;
  for (;;) {
    const ServerFrame f = ReadFrame(until);
    if (f.opcode == 1 && !subscribed) {
      const nlohmann::json j = nlohmann::json::parse(f.payload);
      if (j.at("op") != "advertise") continue;
      for (const auto& c : j.at("channels")) {
        if (c.at("topic") != topic) continue;
        const nlohmann::json sub = {{"id", kSubscription}, {"channelId", c.at("id")}};
        Send(Frame(0x1, nlohmann::json{{"op", "subscribe"}, {"subscriptions", {sub}}}.dump()));
        subscribed = true;
      }
    } else if (f.opcode == 2 && subscribed && f.payload.size() >= 5 && f.payload[0] == 0x01) {
      uint32_t id = 0;
      for (int i = 0; i < 4; ++i) id |= uint32_t{static_cast<uint8_t>(f.payload[1 + i])} << (8 * i);
      if (id == kSubscription) return;
    }
  }
}

void RawWebSocketClient::SubscribeAll(const std::vector<uint32_t>& channels) {
  nlohmann::json subs = nlohmann::json::array();
  for (uint32_t c : channels) subs.push_back({{"id", c}, {"channelId", c}});
  Send(Frame(0x1, nlohmann::json{{"op", "subscribe"}, {"subscriptions", subs}}.dump()));
}

std::string RawWebSocketClient::Frame(uint8_t opcode, const std::string& payload) {
  // FIN, opcode; MASK, length (7, 7+16 or 7+64 bits); the masking key; the masked payload
  static const uint8_t kMask[4] = {0x5a, 0x17, 0xc3, 0x29};  // any key does (RFC 6455 §5.3)
  std::string f;
  f.push_back(static_cast<char>(0x80 | opcode));
  const std::size_t n = payload.size();
  if (n < 126) {
    f.push_back(static_cast<char>(0x80 | n));
  } else if (n < 65536) {
    f.push_back(static_cast<char>(0x80 | 126));
    f.push_back(static_cast<char>(n >> 8));
    f.push_back(static_cast<char>(n & 0xff));
  } else {
    f.push_back(static_cast<char>(0x80 | 127));
    for (int i = 7; i >= 0; --i) f.push_back(static_cast<char>((n >> (8 * i)) & 0xff));
  }
  for (uint8_t m : kMask) f.push_back(static_cast<char>(m));
  for (std::size_t i = 0; i < n; ++i) f.push_back(static_cast<char>(payload[i] ^ kMask[i % 4]));
  return f;
}

void RawWebSocketClient::Send(const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = send(fd_, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw Error("send");
    }
    done += static_cast<std::size_t>(n);
  }
}

bool RawWebSocketClient::Closed() const {
  tcp_info info{};
  socklen_t size = sizeof info;
  if (getsockopt(fd_, IPPROTO_TCP, TCP_INFO, &info, &size) != 0) return true;
  return info.tcpi_state != TCP_ESTABLISHED;
}

std::size_t ResidentBytes(int pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stoull(line.substr(6)) * 1024;  // kB
  }
  return 0;
}

}  // namespace towsim::testing
