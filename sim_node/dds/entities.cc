#include "dds/entities.h"

#include <memory>

#include "wire/ros_graph.h"

namespace towsim::dds {

DdsError::DdsError(const std::string& action, dds_return_t code)
    : std::runtime_error(action + ": " + dds_strretcode(code)), code_(code) {}

dds_listener_t* MatchCount::NewListener() {
  dds_listener_t* listener = dds_create_listener(this);
  dds_lset_publication_matched(listener, &MatchCount::OnMatched);
  return listener;
}

void MatchCount::OnMatched(dds_entity_t, const dds_publication_matched_status_t status,
                           void* self) {
  static_cast<MatchCount*>(self)->current_.store(static_cast<int>(status.current_count),
                                                 std::memory_order_relaxed);
}

void Entity::Reset() {
  if (handle_ > 0) dds_delete(handle_);
  handle_ = 0;
}

Participant::Participant(uint32_t domain_id, const std::string& config, const std::string& security,
                         wire::Admit admit)
    : domain_id_(domain_id) {
  const std::string where = "DDS domain " + std::to_string(domain_id);
  if (!config.empty()) {
    const dds_entity_t d = dds_create_domain(domain_id, config.c_str());
    if (d < 0) throw DdsError("creating " + where + " from " + config, d);
    domain_ = Entity(d);
  }
  // USER_DATA "enclave=/;", as every ROS 2 participant has (wire/ros_graph.h)
  std::unique_ptr<dds_qos_t, decltype(&dds_delete_qos)> qos(wire::NewParticipantQos(),
                                                            &dds_delete_qos);
  if (!security.empty()) {
    participant_ = Entity(wire::CreateSecureParticipant(domain_id, security, qos.get(), admit));
    return;
  }
  const dds_entity_t p = dds_create_participant(domain_id, qos.get(), nullptr);
  if (p < 0) throw DdsError("creating a participant in " + where, p);
  participant_ = Entity(p);
}

Topic::Topic(const Participant& participant, const dds_topic_descriptor_t* descriptor,
             const std::string& name)
    : name_(name) {
  const dds_entity_t t =
      dds_create_topic(participant.get(), descriptor, name.c_str(), nullptr, nullptr);
  if (t < 0) throw DdsError("creating topic " + name, t);
  topic_ = Entity(t);
}

WaitSet::WaitSet(const Participant& participant) {
  const dds_entity_t w = dds_create_waitset(participant.get());
  if (w < 0) throw DdsError("creating a waitset", w);
  waitset_ = Entity(w);
}

void WaitSet::Attach(dds_entity_t condition) {
  const dds_return_t rc = dds_waitset_attach(waitset_.get(), condition, condition);
  if (rc < 0) throw DdsError("attaching a condition to a waitset", rc);
}

int WaitSet::Wait(int64_t timeout_ns) {
  const dds_return_t n = dds_waitset_wait(waitset_.get(), nullptr, 0, timeout_ns);
  return n < 0 ? 0 : static_cast<int>(n);
}

}  // namespace towsim::dds
