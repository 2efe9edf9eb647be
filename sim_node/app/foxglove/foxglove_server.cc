#include "app/foxglove/foxglove_server.h"

#include <chrono>
#include <stdexcept>
#include <websocketpp/config/asio_no_tls.hpp>
#include <websocketpp/server.hpp>

namespace towsim::app {
namespace {

using WsServer = websocketpp::server<websocketpp::config::asio>;
using Handle = websocketpp::connection_hdl;

struct Client {
  std::map<uint32_t, uint32_t> subscription_of;            // channel -> subscription id
  std::map<uint32_t, uint32_t> channel_of;                 // subscription id -> channel
  std::map<uint32_t, foxglove::ClientChannel> advertised;  // client channel id -> channel
};

}  // namespace

struct FoxgloveServer::Impl {
  WsServer ws;
  std::thread thread;
  mutable std::mutex mutex;  // channels, clients, subscriber counts
  std::vector<foxglove::Channel> channels;
  std::map<uint32_t, int> subscribers;  // channel -> subscriptions of every client
  std::map<uint32_t, std::pair<uint64_t, std::string>> latched;  // channel -> (time, payload)
  std::map<Handle, Client, std::owner_less<Handle>> clients;
  std::string session_id;
  bool running = false;
  std::string frame;  // reused by Publish (under mutex)

  void Send(Handle h, const std::string& payload, websocketpp::frame::opcode::value op) {
    websocketpp::lib::error_code ec;
    ws.send(h, payload, op, ec);  // errors: the connection is closing
  }
};

FoxgloveServer::FoxgloveServer(Options options)
    : impl_(std::make_unique<Impl>()), opt_(std::move(options)) {
  impl_->session_id = std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(
                                         std::chrono::system_clock::now().time_since_epoch())
                                         .count());
}

FoxgloveServer::~FoxgloveServer() { Stop(); }

uint32_t FoxgloveServer::AddChannel(const std::string& topic, const std::string& schema_name,
                                    const std::string& schema, bool latched) {
  std::vector<Handle> to;
  foxglove::Channel c;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    c = {static_cast<uint32_t>(impl_->channels.size() + 1), topic, schema_name, schema};
    impl_->channels.push_back(c);
    if (latched) impl_->latched[c.id] = {0, std::string()};
    for (const auto& [h, client] : impl_->clients) to.push_back(h);
  }
  const std::string advertise = foxglove::AdvertiseJson({c});
  for (const Handle& h : to) impl_->Send(h, advertise, websocketpp::frame::opcode::text);
  return c.id;
}

void FoxgloveServer::Start() {
  Impl& m = *impl_;
  m.ws.clear_access_channels(websocketpp::log::alevel::all);
  m.ws.clear_error_channels(websocketpp::log::elevel::all);
  m.ws.init_asio();
  m.ws.set_reuse_addr(true);
  m.ws.set_validate_handler([&m](Handle h) {
    WsServer::connection_ptr con = m.ws.get_con_from_hdl(h);
    const std::string p = foxglove::ChooseSubprotocol(con->get_requested_subprotocols());
    if (p.empty()) return false;  // not a Foxglove client
    con->select_subprotocol(p);
    return true;
  });
  m.ws.set_open_handler([this, &m](Handle h) {
    // small messages at the step rate: no Nagle delay (a lockstep client waits for each one)
    asio::error_code nodelay_ec;
    m.ws.get_con_from_hdl(h)->get_raw_socket().set_option(asio::ip::tcp::no_delay(true),
                                                          nodelay_ec);
    std::string advertise;
    {
      std::lock_guard<std::mutex> lock(m.mutex);
      m.clients[h] = Client{};
      advertise = foxglove::AdvertiseJson(m.channels);
    }
    ++clients_;
    m.Send(h, foxglove::ServerInfoJson(opt_.name, m.session_id), websocketpp::frame::opcode::text);
    m.Send(h, advertise, websocketpp::frame::opcode::text);
  });
  m.ws.set_close_handler([this, &m](Handle h) {
    std::lock_guard<std::mutex> lock(m.mutex);
    const auto it = m.clients.find(h);
    if (it == m.clients.end()) return;
    for (const auto& [channel, sub] : it->second.subscription_of) --m.subscribers[channel];
    m.clients.erase(it);
    --clients_;
  });
  m.ws.set_message_handler([this, &m](Handle h, WsServer::message_ptr msg) {
    using websocketpp::frame::opcode::text;
    if (msg->get_opcode() == websocketpp::frame::opcode::binary) {
      const std::string& p = msg->get_payload();
      foxglove::ClientData data;
      std::string error;
      foxglove::ClientChannel channel;
      bool known = false;
      if (foxglove::ParseClientBinary(reinterpret_cast<const uint8_t*>(p.data()), p.size(), &data,
                                      &error)) {
        std::lock_guard<std::mutex> lock(m.mutex);
        const auto c = m.clients.find(h);
        if (c != m.clients.end()) {
          const auto a = c->second.advertised.find(data.channel);
          known = a != c->second.advertised.end();
          if (known) channel = a->second;
        }
        if (!known) error = "client channel " + std::to_string(data.channel) + " not advertised";
      }
      ++client_messages_;
      if (error.empty() && on_publish_) error = on_publish_(channel, data.data, data.size);
      if (!error.empty()) {
        ++client_rejected_;
        m.Send(h, foxglove::StatusJson(foxglove::StatusLevel::kError, error), text);
      }
      return;
    }
    const foxglove::ClientRequest r = foxglove::ParseClientText(msg->get_payload());
    std::vector<std::string> errors;
    std::vector<std::string> frames;  // latched messages for the new subscriptions
    {
      std::lock_guard<std::mutex> lock(m.mutex);
      const auto c = m.clients.find(h);
      if (c == m.clients.end()) return;
      Client& client = c->second;
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
              const auto l = m.latched.find(channel);
              if (l != m.latched.end() && !l->second.second.empty()) {
                std::string frame;
                foxglove::MessageDataFrame(
                    sub, l->second.first, reinterpret_cast<const uint8_t*>(l->second.second.data()),
                    l->second.second.size(), &frame);
                frames.push_back(std::move(frame));
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
          break;
      }
    }
    for (const std::string& f : frames) m.Send(h, f, websocketpp::frame::opcode::binary);
    for (const std::string& e : errors) {
      m.Send(h, foxglove::StatusJson(foxglove::StatusLevel::kError, e), text);
    }
  });

  websocketpp::lib::error_code ec;
  const asio::ip::address address = asio::ip::make_address(opt_.address, ec);
  if (ec) throw std::runtime_error("address " + opt_.address + ": " + ec.message());
  m.ws.listen(asio::ip::tcp::endpoint(address, opt_.port), ec);
  if (ec) {
    throw std::runtime_error("listening on " + opt_.address + ":" + std::to_string(opt_.port) +
                             ": " + ec.message());
  }
  m.ws.start_accept(ec);
  if (ec) throw std::runtime_error("accepting connections: " + ec.message());
  asio::error_code aec;
  const auto local = m.ws.get_local_endpoint(aec);
  port_ = aec ? opt_.port : local.port();
  m.running = true;
  m.thread = std::thread([&m] { m.ws.run(); });
}

void FoxgloveServer::Stop() {
  Impl& m = *impl_;
  if (!m.running) return;
  m.running = false;
  websocketpp::lib::error_code ec;
  m.ws.stop_listening(ec);
  std::vector<Handle> open;
  {
    std::lock_guard<std::mutex> lock(m.mutex);
    for (const auto& [h, client] : m.clients) open.push_back(h);
  }
  for (const Handle& h : open) m.ws.close(h, websocketpp::close::status::going_away, "", ec);
  // the closing handshakes get a moment, then the loop ends
  for (int i = 0; i < 50 && clients_.load() > 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  m.ws.stop();
  if (m.thread.joinable()) m.thread.join();
}

bool FoxgloveServer::HasSubscribers(uint32_t channel) const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  const auto it = impl_->subscribers.find(channel);
  return it != impl_->subscribers.end() && it->second > 0;
}

void FoxgloveServer::Publish(uint32_t channel, uint64_t log_time_ns, const uint8_t* data,
                             std::size_t size) {
  Impl& m = *impl_;
  std::lock_guard<std::mutex> lock(m.mutex);
  if (const auto l = m.latched.find(channel); l != m.latched.end()) {
    l->second = {log_time_ns, std::string(reinterpret_cast<const char*>(data), size)};
  }
  for (const auto& [h, client] : m.clients) {
    const auto s = client.subscription_of.find(channel);
    if (s == client.subscription_of.end()) continue;
    websocketpp::lib::error_code ec;
    WsServer::connection_ptr con = m.ws.get_con_from_hdl(h, ec);
    if (ec || con->get_buffered_amount() > kMaxBuffered) {
      ++dropped_;
      continue;
    }
    foxglove::MessageDataFrame(s->second, log_time_ns, data, size, &m.frame);
    m.Send(h, m.frame, websocketpp::frame::opcode::binary);
    ++sent_;
  }
}

void FoxgloveServer::BroadcastTime(uint64_t time_ns) {
  Impl& m = *impl_;
  const std::string frame = foxglove::TimeFrame(time_ns);
  std::lock_guard<std::mutex> lock(m.mutex);
  for (const auto& [h, client] : m.clients) m.Send(h, frame, websocketpp::frame::opcode::binary);
}

}  // namespace towsim::app
