#include "app/foxglove/foxglove_server.h"

#include <chrono>
#include <cstdio>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>
#include <websocketpp/config/asio_no_tls.hpp>
#include <websocketpp/server.hpp>

#include "app/foxglove/note_throttle.h"

namespace towsim::app {
namespace {

using WsServer = websocketpp::server<websocketpp::config::asio>;
using Handle = websocketpp::connection_hdl;
using foxglove::ClientQueue;
using Kind = ClientQueue::Kind;

constexpr std::size_t kDataHeader = 13;  // Message Data: opcode, subscription, log time
constexpr auto kTick = std::chrono::milliseconds(20);  // the server thread's pump and notes
// a client closed at the bound gets a close frame with the reason, which it reads if it
// reads at all; after kResetAfter its socket is reset (closed with SO_LINGER 0: the kernel
// drops what it still holds for the client at once, and the client sees the connection end
// without reading), before websocketpp's close handshake times out (and would close it in an
// orderly way: the socket would stay in FIN-WAIT-1 with its full send buffer)
constexpr double kResetAfter = 1.0;       // [s]
constexpr long kCloseHandshakeMs = 2000;  // a client's close answer; then the socket is closed
constexpr double kStopWait = 0.5;         // [s] Stop() waits for the closing handshakes

struct Client {
  explicit Client(const ClientQueue::Limits& limits, std::string from)
      : queue(limits), endpoint(std::move(from)) {}
  std::map<uint32_t, uint32_t> subscription_of;            // channel -> subscription id
  std::map<uint32_t, uint32_t> channel_of;                 // subscription id -> channel
  std::map<uint32_t, foxglove::ClientChannel> advertised;  // client channel id -> channel
  ClientQueue queue;
  std::string endpoint;  // "127.0.0.1:40312"
  bool closing = false;  // closed at the bound (or the server stops): nothing more is queued
  std::optional<double> reset_at;  // closed at the bound: its socket is reset then [s]
};

websocketpp::frame::opcode::value OpcodeOf(Kind kind) {
  switch (kind) {
    case Kind::kData:
    case Kind::kTime:
      return websocketpp::frame::opcode::binary;
    case Kind::kControl:
    case Kind::kReply:
      return websocketpp::frame::opcode::text;
    case Kind::kPong:
      return websocketpp::frame::opcode::pong;
  }
  return websocketpp::frame::opcode::binary;
}

}  // namespace

struct FoxgloveServer::Impl {
  explicit Impl(const Options& o)
      : refusals(o.program, "Foxglove client messages or requests refused"),
        queue_notes(o.program, "Foxglove clients at their send queue's bound") {}

  WsServer ws;
  std::thread thread;
  std::optional<asio::steady_timer> timer;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  mutable std::mutex mutex;  // everything below
  std::vector<foxglove::Channel> channels;
  std::map<uint32_t, int> subscribers;  // channel -> subscriptions of every client
  std::map<uint32_t, std::pair<uint64_t, std::string>> latched;  // channel -> (time, payload)
  std::map<Handle, Client, std::owner_less<Handle>> clients;
  std::string session_id;
  bool listening = false;            // the controlling thread only
  std::atomic<bool> running{false};  // read by RequestPump from any thread
  Totals totals;
  foxglove::NoteThrottle refusals, queue_notes;
  std::vector<std::string> lines;  // notes to print (outside the lock)
  std::atomic<bool> pump_posted{false};

  double Now() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  // under mutex: a note for stderr
  void Note(foxglove::NoteThrottle& throttle, const std::string& note, double now) {
    if (auto line = throttle.Event(now, note)) lines.push_back(std::move(*line));
  }
  // takes the notes to print (under mutex)
  std::vector<std::string> TakeLines(double now, bool all = false) {
    for (foxglove::NoteThrottle* t : {&refusals, &queue_notes}) {
      if (auto line = t->Flush(now, all)) lines.push_back(std::move(*line));
    }
    return std::exchange(lines, {});
  }
};

FoxgloveServer::FoxgloveServer(Options options)
    : impl_(std::make_unique<Impl>(options)), opt_(std::move(options)) {
  impl_->session_id = std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(
                                         std::chrono::system_clock::now().time_since_epoch())
                                         .count());
}

FoxgloveServer::~FoxgloveServer() { Stop(); }

std::string FoxgloveServer::SummaryText(const Totals& t) {
  auto u = [](uint64_t v) { return std::to_string(v); };
  return u(t.sent) + " messages sent (dropped " + u(t.dropped) + "), client messages " +
         u(t.client_messages) + " (rejected " + u(t.client_rejected) + ", malformed " +
         u(t.client_malformed) + "), requests " + u(t.requests) + " (refused " +
         u(t.requests_refused) + ", malformed " + u(t.requests_malformed) + "), error replies " +
         u(t.replies) + " (suppressed " + u(t.replies_suppressed) + "), time messages dropped " +
         u(t.time_dropped) + ", clients " + u(t.clients) + " (closed at the bound " +
         u(t.clients_closed) + ")";
}

FoxgloveServer::Totals FoxgloveServer::totals() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->totals;
}

std::size_t FoxgloveServer::queued_bytes() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  std::size_t n = 0;
  for (const auto& [h, c] : impl_->clients) n += c.queue.queued();
  return n;
}

uint32_t FoxgloveServer::AddChannel(const std::string& topic, const std::string& schema_name,
                                    const std::string& schema, bool latched) {
  Impl& m = *impl_;
  foxglove::Channel c;
  {
    std::lock_guard<std::mutex> lock(m.mutex);
    c = {static_cast<uint32_t>(m.channels.size() + 1), topic, schema_name, schema};
    m.channels.push_back(c);
    if (latched) m.latched[c.id] = {0, std::string()};
    if (!m.clients.empty()) {
      const std::string advertise = foxglove::AdvertiseJson({c});
      const double now = m.Now();
      for (auto& [h, client] : m.clients) client.queue.Offer(Kind::kControl, advertise, now);
    }
  }
  RequestPump();
  return c.id;
}

void FoxgloveServer::RequestPump() {
  Impl& m = *impl_;
  if (!m.running || m.pump_posted.exchange(true)) return;
  asio::post(m.ws.get_io_service(), [this] {
    impl_->pump_posted = false;
    Pump();
  });
}

void FoxgloveServer::Pump() {
  Impl& m = *impl_;
  const double now = m.Now();
  std::vector<std::pair<Handle, std::string>> to_close;
  std::vector<Handle> to_reset;
  std::vector<std::string> lines;
  {
    std::lock_guard<std::mutex> lock(m.mutex);
    for (auto& [h, client] : m.clients) {
      if (client.reset_at && now >= *client.reset_at) {
        client.reset_at.reset();
        to_reset.push_back(h);
      }
      if (client.closing) continue;
      websocketpp::lib::error_code ec;
      WsServer::connection_ptr con = m.ws.get_con_from_hdl(h, ec);
      if (ec) continue;
      client.queue.HandOver(con->get_buffered_amount(), [&](const ClientQueue::Frame& f) {
        websocketpp::lib::error_code send_ec;
        if (f.kind == Kind::kPong) {
          con->pong(f.bytes, send_ec);
        } else {
          send_ec = con->send(f.bytes, OpcodeOf(f.kind));
        }
        if (f.kind == Kind::kData && !send_ec) ++m.totals.sent;
      });
      if (client.queue.ShouldClose(now)) {
        to_close.emplace_back(h, client.queue.CloseReason(now));
        client.closing = true;
        client.reset_at = now + kResetAfter;
        ++m.totals.clients_closed;
        m.Note(m.queue_notes,
               "Foxglove client " + client.endpoint + " closed: " + to_close.back().second, now);
        m.totals.dropped += client.queue.Clear();
      }
    }
    lines = m.TakeLines(now);
  }
  if (!opt_.quiet) {
    for (const std::string& l : lines) std::fprintf(stderr, "%s\n", l.c_str());
  }
  for (const auto& [h, reason] : to_close) {
    websocketpp::lib::error_code ec;
    m.ws.close(h, websocketpp::close::status::policy_violation, reason, ec);
  }
  for (const Handle& h : to_reset) {
    websocketpp::lib::error_code ec;
    WsServer::connection_ptr con = m.ws.get_con_from_hdl(h, ec);
    if (ec) continue;  // it closed in the meantime
    // an explicit close keeps SO_LINGER 0 (asio clears it when a socket's destructor closes
    // it); websocketpp's pending read and write then fail and it ends the connection
    asio::error_code socket_ec;
    con->get_raw_socket().set_option(asio::socket_base::linger(true, 0), socket_ec);
    con->get_raw_socket().close(socket_ec);
  }
}

void FoxgloveServer::Tick() {
  Impl& m = *impl_;
  Pump();
  m.timer->expires_after(kTick);
  m.timer->async_wait([this](const asio::error_code& ec) {
    if (!ec) Tick();
  });
}

void FoxgloveServer::Listen() {
  Impl& m = *impl_;
  if (m.listening) return;
  m.ws.clear_access_channels(websocketpp::log::alevel::all);
  m.ws.clear_error_channels(websocketpp::log::elevel::all);
  m.ws.init_asio();
  m.ws.set_reuse_addr(true);
  m.ws.set_close_handshake_timeout(kCloseHandshakeMs);
  m.ws.set_max_message_size(opt_.max_client_message);
  m.ws.set_validate_handler([&m](Handle h) {
    WsServer::connection_ptr con = m.ws.get_con_from_hdl(h);
    const std::string p = foxglove::ChooseSubprotocol(con->get_requested_subprotocols());
    if (p.empty()) return false;  // not a Foxglove client
    con->select_subprotocol(p);
    return true;
  });
  m.ws.set_open_handler([this, &m](Handle h) {
    WsServer::connection_ptr con = m.ws.get_con_from_hdl(h);
    // small messages at the step rate: no Nagle delay (a lockstep client waits for each one)
    asio::error_code nodelay_ec;
    con->get_raw_socket().set_option(asio::ip::tcp::no_delay(true), nodelay_ec);
    {
      std::lock_guard<std::mutex> lock(m.mutex);
      const double now = m.Now();
      Client& c =
          m.clients.emplace(h, Client(opt_.limits, con->get_remote_endpoint())).first->second;
      c.queue.Offer(Kind::kControl, foxglove::ServerInfoJson(opt_.name, m.session_id), now);
      c.queue.Offer(Kind::kControl, foxglove::AdvertiseJson(m.channels), now);
      ++m.totals.clients;
    }
    ++clients_;
    Pump();
  });
  m.ws.set_close_handler([this, &m](Handle h) {
    std::lock_guard<std::mutex> lock(m.mutex);
    const auto it = m.clients.find(h);
    if (it == m.clients.end()) return;
    for (const auto& [channel, sub] : it->second.subscription_of) --m.subscribers[channel];
    m.totals.dropped += it->second.queue.Clear();
    m.clients.erase(it);
    --clients_;
  });
  // pongs go through the client's queue (counted, rate-limited) instead of websocketpp's own
  m.ws.set_ping_handler([this, &m](Handle h, std::string payload) {
    {
      std::lock_guard<std::mutex> lock(m.mutex);
      const auto it = m.clients.find(h);
      if (it != m.clients.end() && !it->second.closing) {
        it->second.queue.Offer(Kind::kPong, std::move(payload), m.Now());
      }
    }
    Pump();
    return false;
  });
  m.ws.set_message_handler([this, &m](Handle h, WsServer::message_ptr msg) {
    OnMessage(h, msg->get_opcode() == websocketpp::frame::opcode::binary, msg->get_payload());
  });

  websocketpp::lib::error_code ec;
  const asio::ip::address address = asio::ip::make_address(opt_.address, ec);
  if (ec) throw std::runtime_error("address " + opt_.address + ": not an IPv4 or IPv6 address");
  m.ws.listen(asio::ip::tcp::endpoint(address, opt_.port), ec);
  if (ec) {
    throw std::runtime_error("listening on " + opt_.address + ":" + std::to_string(opt_.port) +
                             ": " + ec.message() +
                             " (the address must be one of this machine's, the port free)");
  }
  asio::error_code aec;
  const auto local = m.ws.get_local_endpoint(aec);
  port_ = aec ? opt_.port : local.port();
  m.listening = true;
}

void FoxgloveServer::OnMessage(const Handle& h, bool binary, const std::string& payload) {
  Impl& m = *impl_;
  std::vector<std::string> errors;  // for the client, in order
  bool malformed = false;
  if (binary) {
    foxglove::ClientData data;
    std::string error;
    foxglove::ClientChannel channel;
    if (!foxglove::ParseClientBinary(reinterpret_cast<const uint8_t*>(payload.data()),
                                     payload.size(), &data, &error)) {
      malformed = true;
    } else {
      std::lock_guard<std::mutex> lock(m.mutex);
      const auto c = m.clients.find(h);
      if (c == m.clients.end() || c->second.closing) return;
      const auto a = c->second.advertised.find(data.channel);
      if (a == c->second.advertised.end()) {
        error = "client channel " + std::to_string(data.channel) + " not advertised";
      } else {
        channel = a->second;
      }
    }
    if (error.empty() && on_publish_) {
      const Verdict v = on_publish_(channel, data.data, data.size);
      error = v.error;
      malformed = v.malformed;
    }
    std::lock_guard<std::mutex> lock(m.mutex);
    ++m.totals.client_messages;
    if (!error.empty()) {
      ++m.totals.client_rejected;
      if (malformed) ++m.totals.client_malformed;
      errors.push_back(error);
    }
  } else {
    const foxglove::ClientRequest r = foxglove::ParseClientText(payload);
    std::lock_guard<std::mutex> lock(m.mutex);
    ++m.totals.requests;
    const auto c = m.clients.find(h);
    if (c == m.clients.end() || c->second.closing) return;
    Client& client = c->second;
    const double now = m.Now();
    switch (r.kind) {
      case foxglove::ClientRequest::kSubscribe:
        for (const auto& [sub, channel] : r.subscribe) {
          if (channel == 0 || channel > m.channels.size()) {
            errors.push_back("subscribe: no channel " + std::to_string(channel));
          } else if (client.channel_of.count(sub) || client.subscription_of.count(channel)) {
            errors.push_back("subscribe: subscription " + std::to_string(sub) + " or channel " +
                             std::to_string(channel) + " already in use");
          } else {
            client.channel_of[sub] = channel;
            client.subscription_of[channel] = sub;
            ++m.subscribers[channel];
            // the latched message, as data (dropped at the bound like any)
            const auto l = m.latched.find(channel);
            if (l != m.latched.end() && !l->second.second.empty()) {
              const std::string& p = l->second.second;
              if (client.queue.AdmitData(kDataHeader + p.size(), now)) {
                std::string frame;
                foxglove::MessageDataFrame(sub, l->second.first,
                                           reinterpret_cast<const uint8_t*>(p.data()), p.size(),
                                           &frame);
                client.queue.Offer(Kind::kData, std::move(frame), now);
              } else {
                ++m.totals.dropped;
              }
            }
          }
        }
        break;
      case foxglove::ClientRequest::kUnsubscribe:
        for (uint32_t sub : r.ids) {
          const auto s = client.channel_of.find(sub);
          if (s == client.channel_of.end()) continue;
          --m.subscribers[s->second];
          client.subscription_of.erase(s->second);
          client.channel_of.erase(s);
        }
        break;
      case foxglove::ClientRequest::kAdvertise:
        for (const foxglove::ClientChannel& ch : r.channels) {
          const std::string e = on_advertise_ ? on_advertise_(ch) : "client publishing is off";
          if (e.empty()) {
            client.advertised[ch.id] = ch;
          } else {
            errors.push_back("advertise " + ch.topic + ": " + e);
          }
        }
        break;
      case foxglove::ClientRequest::kUnadvertise:
        for (uint32_t id : r.ids) client.advertised.erase(id);
        break;
      case foxglove::ClientRequest::kOther:
        errors.push_back("unsupported operation \"" + r.op + "\"");
        break;
      case foxglove::ClientRequest::kInvalid:
        errors.push_back(r.error);
        malformed = true;
        break;
    }
    if (!errors.empty()) ++m.totals.requests_refused;
    if (malformed) ++m.totals.requests_malformed;
  }
  if (!errors.empty()) {
    std::lock_guard<std::mutex> lock(m.mutex);
    const auto c = m.clients.find(h);
    if (c == m.clients.end() || c->second.closing) return;
    const double now = m.Now();
    for (const std::string& e : errors) {
      m.Note(m.refusals, "Foxglove client " + c->second.endpoint + ": " + e, now);
      ++m.totals.replies;
      const ClientQueue::Result r = c->second.queue.Offer(
          Kind::kReply, foxglove::StatusJson(foxglove::StatusLevel::kError, e), now);
      if (r != ClientQueue::Result::kQueued) ++m.totals.replies_suppressed;
    }
  }
  Pump();
}

void FoxgloveServer::Start() {
  Listen();
  Impl& m = *impl_;
  if (m.running) return;
  websocketpp::lib::error_code ec;
  m.ws.start_accept(ec);
  if (ec) throw std::runtime_error("accepting connections: " + ec.message());
  m.timer.emplace(m.ws.get_io_service());
  m.running = true;
  asio::post(m.ws.get_io_service(), [this] { Tick(); });
  m.thread = std::thread([&m] { m.ws.run(); });
}

void FoxgloveServer::Stop() {
  Impl& m = *impl_;
  if (!m.listening) return;
  m.listening = false;
  if (!m.running) {  // listening only: no thread, no connection
    websocketpp::lib::error_code ec;
    m.ws.stop_listening(ec);
    return;
  }
  m.running = false;
  // on the server's thread, like every other call into websocketpp
  asio::post(m.ws.get_io_service(), [this, &m] {
    Pump();  // what waits and fits the window goes before the close frames
    websocketpp::lib::error_code ec;
    m.ws.stop_listening(ec);
    m.timer->cancel();
    std::vector<Handle> open;
    {
      std::lock_guard<std::mutex> lock(m.mutex);
      for (auto& [h, client] : m.clients) {
        client.closing = true;
        open.push_back(h);
      }
    }
    for (const Handle& h : open) m.ws.close(h, websocketpp::close::status::going_away, "", ec);
  });
  // the closing handshakes get a moment, then the loop ends
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(kStopWait);
  while (clients_.load() > 0 && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  m.ws.stop();
  if (m.thread.joinable()) m.thread.join();
  std::vector<std::string> lines;
  {
    std::lock_guard<std::mutex> lock(m.mutex);
    // the connections that did not finish their closing handshake (a client that reads
    // nothing cannot): gone with the loop, websocketpp frees them with the endpoint
    for (auto& [h, client] : m.clients) m.totals.dropped += client.queue.Clear();
    m.clients.clear();
    m.subscribers.clear();
    clients_ = 0;
    lines = m.TakeLines(m.Now(), true);  // the counts not yet printed
  }
  if (!opt_.quiet) {
    for (const std::string& l : lines) std::fprintf(stderr, "%s\n", l.c_str());
  }
}

bool FoxgloveServer::HasSubscribers(uint32_t channel) const {
  Impl& m = *impl_;
  std::lock_guard<std::mutex> lock(m.mutex);
  const auto it = m.subscribers.find(channel);
  if (it == m.subscribers.end() || it->second <= 0) return false;
  // a latched channel is kept for later subscribers; otherwise only a client that may take it
  // counts: one over its bound drops it anyway, so the caller need not make it at all
  if (m.latched.count(channel)) return true;
  for (const auto& [h, client] : m.clients) {
    if (client.subscription_of.count(channel) && !client.closing && !client.queue.over()) {
      return true;
    }
  }
  return false;
}

void FoxgloveServer::Publish(uint32_t channel, uint64_t log_time_ns, const uint8_t* data,
                             std::size_t size) {
  Impl& m = *impl_;
  // the server's thread hands frames over when one lands in an empty queue; frames behind
  // others wait for the queue to move, which the thread sees on its own (kTick): a stalled
  // client costs the caller no wake-up of that thread
  bool wake = false;
  {
    std::lock_guard<std::mutex> lock(m.mutex);
    if (const auto l = m.latched.find(channel); l != m.latched.end()) {
      l->second = {log_time_ns, std::string(reinterpret_cast<const char*>(data), size)};
    }
    const double now = m.Now();
    for (auto& [h, client] : m.clients) {
      const auto s = client.subscription_of.find(channel);
      if (s == client.subscription_of.end() || client.closing) continue;
      const bool was_over = client.queue.over();
      if (!client.queue.AdmitData(kDataHeader + size, now)) {
        ++m.totals.dropped;
        if (!was_over) {
          m.Note(m.queue_notes,
                 "Foxglove client " + client.endpoint + ": send queue at its bound (" +
                     std::to_string(client.queue.limits().bound >> 20) +
                     " MiB): data dropped until it reads",
                 now);
        }
        continue;
      }
      std::string frame;
      foxglove::MessageDataFrame(s->second, log_time_ns, data, size, &frame);
      wake = wake || client.queue.waiting_frames() == 0;
      client.queue.Offer(Kind::kData, std::move(frame), now);
    }
  }
  if (wake) RequestPump();
}

void FoxgloveServer::BroadcastTime(uint64_t time_ns) {
  Impl& m = *impl_;
  bool wake = false;  // as in Publish
  {
    std::lock_guard<std::mutex> lock(m.mutex);
    if (m.clients.empty()) return;
    const std::string frame = foxglove::TimeFrame(time_ns);
    const double now = m.Now();
    for (auto& [h, client] : m.clients) {
      if (client.closing) continue;
      const uint64_t before = client.queue.counts().time_dropped;
      wake = wake || client.queue.waiting_frames() == 0;
      client.queue.Offer(Kind::kTime, frame, now);
      m.totals.time_dropped += client.queue.counts().time_dropped - before;
    }
  }
  if (wake) RequestPump();
}

}  // namespace towsim::app
