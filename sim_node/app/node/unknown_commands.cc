#include "app/node/unknown_commands.h"

#include <utility>

#include "dds/qos.h"

namespace towsim::app {

UnknownCommands::UnknownCommands(const dds::Participant& participant, const std::string& ns,
                                 std::vector<std::string> known)
    : participant_(participant), names_(ns), known_(known.begin(), known.end()) {
  const dds_entity_t r =
      dds_create_reader(participant.get(), DDS_BUILTIN_TOPIC_DCPSPUBLICATION, nullptr, nullptr);
  if (r < 0) throw dds::DdsError("creating a reader of DCPSPublication", r);
  publications_ = dds::Entity(r);
}

int UnknownCommands::Poll() {
  // writers announced since the last call: an ActuatorCommand writer on a body's command topic
  constexpr int kBatch = 16;
  for (;;) {
    void* samples[kBatch] = {};
    dds_sample_info_t infos[kBatch];
    const dds_return_t n = dds_take(publications_.get(), samples, infos, kBatch, kBatch);
    if (n <= 0) break;
    for (int i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      const auto* e = static_cast<const dds_builtintopic_endpoint_t*>(samples[i]);
      const std::string topic = e->topic_name != nullptr ? e->topic_name : "";
      const std::string type = e->type_name != nullptr ? e->type_name : "";
      if (type != towsim_msgs_msg_dds__ActuatorCommand__desc.m_typename) continue;
      const std::optional<std::string> owner = names_.Owner(wire::Topic::kCommand, topic);
      if (!owner) continue;
      const std::string& body = *owner;
      if (known_.count(body) || watched_names_.count(body)) continue;
      watched_names_.insert(body);
      Watched w;
      w.body = body;
      w.topic = std::make_unique<dds::Topic>(participant_,
                                             &towsim_msgs_msg_dds__ActuatorCommand__desc, topic);
      // keep-all: every sample counts
      dds::Qos qos = dds::CommandQos();
      dds_qset_history(qos.get(), DDS_HISTORY_KEEP_ALL, 0);
      w.reader =
          std::make_unique<dds::Reader<dds::ActuatorCommandMsg>>(participant_, *w.topic, qos);
      watched_.push_back(std::move(w));
    }
    dds_return_loan(publications_.get(), samples, n);
    if (n < kBatch) break;
  }
  int taken = 0;
  for (Watched& w : watched_) {
    const int k = w.reader->TakeEach([](const dds::ActuatorCommandMsg&, const auto&) {});
    if (k > 0) {
      taken += k;
      last_event_ =
          w.body + ": command rejected (no body " + w.body + " that takes commands in this scene)";
    }
  }
  count_ += static_cast<std::uint64_t>(taken);
  return taken;
}

}  // namespace towsim::app
