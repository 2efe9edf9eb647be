#include "app/node/dds_publisher.h"

#include <cmath>
#include <string>
#include <utility>

#include "io/ros2_schemas.h"

namespace towsim::app {
namespace {

int64_t Nanoseconds(double s) { return static_cast<int64_t>(std::llround(s * 1e9)); }

// simulation time as a Foxglove log time [ns] (negative times as 0)
uint64_t SimNs(double t) { return t > 0.0 ? static_cast<uint64_t>(std::llround(t * 1e9)) : 0; }

}  // namespace

NodeEndpoints::NodeEndpoints(const dds::Participant& participant, const wire::TopicNames& names,
                             const core::Simulation& sim, const std::vector<int>& command_vehicles,
                             const std::vector<int>& external_vessels)
    : status_topic_(participant, &towsim_msgs_msg_dds__SimStatus__desc,
                    names.Name(wire::Topic::kStatus)),
      scene_topic_(participant, &towsim_msgs_msg_dds__SceneInfo__desc,
                   names.Name(wire::Topic::kSceneInfo)),
      control_topic_(participant, &towsim_msgs_msg_dds__SimControl__desc,
                     names.Name(wire::Topic::kSimControl)),
      tf_static_topic_(participant, &tf2_msgs_msg_dds__TFMessage__desc,
                       names.Name(wire::Topic::kTfStatic)),
      status_(participant, status_topic_, dds::StateQos()),
      scene_(participant, scene_topic_, dds::SceneInfoQos()),
      tf_static_(participant, tf_static_topic_, dds::SceneInfoQos()),
      control_reader_(participant, control_topic_, dds::ControlQos()),
      waitset_(participant),
      tf_static_msg_(dds::StaticTransforms(sim)),
      names_(names) {
  for (int b = 0; b < sim.num_bodies(); ++b) body_names_.push_back(sim.body_name(b));
  vehicles_.commanded.assign(sim.num_vehicles(), false);
  vehicles_.flags.assign(sim.num_vehicles(), dds::ActuatorFlags{});
  for (int v : command_vehicles) vehicles_.commanded[v] = true;
  // the state topics (app/common/node_topics.h): each body's, then the node's, /clock last
  const std::vector<TopicRow>& table = NodeTopicTable();
  for (int b = 0; b < sim.num_bodies(); ++b) {
    for (const TopicRow& row : table) {
      if (!row.per_body()) continue;
      std::unique_ptr<StateTopic> topic =
          row.make(participant, row, names.Name(row.topic, body_names_[b]), sim, b, vehicles_);
      if (topic != nullptr) state_.push_back({std::move(topic), {}});  // else not in this scene
    }
  }
  for (bool clock : {false, true}) {
    for (const TopicRow& row : table) {
      if (row.per_body()) continue;
      if ((row.rate == core::PublishRate::kClock) != clock) continue;
      // a per-cable row once per cable (Model::cables order), named by the cable
      const int owners = row.per_cable() ? sim.num_cables() : 1;
      for (int c = 0; c < owners; ++c) {
        const std::string name = row.per_cable() ? names.Name(row.topic, sim.cable_name(c))
                                                 : names.Name(row.topic);
        std::unique_ptr<StateTopic> topic =
            row.make(participant, row, name, sim, row.per_cable() ? c : -1, vehicles_);
        if (topic != nullptr) state_.push_back({std::move(topic), {}});
      }
    }
  }
  const int num_spheres = sim.num_spheres();
  for (int v : command_vehicles) {
    command_topics_.emplace_back(participant, &towsim_msgs_msg_dds__ActuatorCommand__desc,
                                 names.Name(wire::Topic::kCommand, sim.body_name(num_spheres + v)));
    command_readers_.push_back(std::make_unique<dds::Reader<dds::ActuatorCommandMsg>>(
        participant, command_topics_.back(), dds::CommandQos()));
    waitset_.Attach(command_readers_.back()->condition());
  }
  const int first_vessel = num_spheres + sim.num_vehicles();
  for (int v : external_vessels) {
    pose_topics_.emplace_back(
        participant, &nav_msgs_msg_dds__Odometry__desc,
        names.Name(wire::Topic::kPoseCommand, sim.body_name(first_vessel + v)));
    pose_readers_.push_back(std::make_unique<dds::Reader<dds::OdometryMsg>>(
        participant, pose_topics_.back(), dds::CommandQos()));
    waitset_.Attach(pose_readers_.back()->condition());
  }
  for (int w = 0; w < sim.num_winches(); ++w) {
    winch_topics_.push_back(
        std::make_unique<dds::Topic>(participant, &towsim_msgs_msg_dds__WinchCommand__desc,
                                     names.Name(wire::Topic::kWinchCommand, sim.winch_name(w))));
    winch_readers_.push_back(std::make_unique<dds::Reader<dds::WinchCommandMsg>>(
        participant, *winch_topics_.back(), dds::CommandQos()));
    waitset_.Attach(winch_readers_.back()->condition());
  }
  waitset_.Attach(control_reader_.condition());
}

template <class T>
void NodeEndpoints::Emit(dds::Writer<T>& writer, const Recorded& recorded, const void* msg) {
  const bool served = Served(recorded);
  if (recording_ == nullptr && !served) {
    writer.WriteRaw(msg);
    return;
  }
  // serialized once: these bytes go to DDS, into the recording and to Foxglove
  const dds::CdrSample sample = dds::CdrSample::FromSample(*recorded.type, msg);
  const dds_time_t now = dds_time();
  if (writer.matched()) {
    const dds_return_t rc = sample.Write(writer.get(), now);
    if (rc < 0) throw dds::DdsError("writing to " + writer.topic_name(), rc);
  }
  sample.CopyTo(&buffer_);
  if (recording_ != nullptr) {
    recording_->Write(recorded.channel, RecordLogTime(now), static_cast<uint64_t>(now),
                      buffer_.data(), buffer_.size());
  }
  if (served) fox_->Publish(recorded.fox, sim_ns_, buffer_.data(), buffer_.size());
}

template <class T>
void NodeEndpoints::EmitAlways(dds::Writer<T>& writer, const Recorded& recorded, const void* msg) {
  if (recording_ == nullptr && fox_ == nullptr) {
    writer.WriteRaw(msg);
    return;
  }
  const dds::CdrSample s = dds::CdrSample::FromSample(*recorded.type, msg);
  const dds_time_t now = dds_time();
  const dds_return_t rc = s.Write(writer.get(), now);
  if (rc < 0) throw dds::DdsError("writing to " + writer.topic_name(), rc);
  s.CopyTo(&buffer_);
  if (recording_ != nullptr) {
    recording_->Write(recorded.channel, RecordLogTime(now), static_cast<uint64_t>(now),
                      buffer_.data(), buffer_.size());
  }
  // latched: kept for the clients that subscribe later
  if (fox_ != nullptr) fox_->Publish(recorded.fox, sim_ns_, buffer_.data(), buffer_.size());
}

const dds::RawType* NodeEndpoints::TypeOf(const dds::Participant& participant,
                                          const dds_topic_descriptor_t* descriptor) {
  for (const auto& t : raw_types_) {
    if (t->descriptor() == descriptor) return t.get();
  }
  raw_types_.push_back(std::make_unique<dds::RawType>(participant, descriptor));
  return raw_types_.back().get();
}

void NodeEndpoints::StartFoxglove(const dds::Participant& participant, FoxgloveServer* server) {
  fox_ = server;
  auto add = [&](const std::string& dds_topic, const dds_topic_descriptor_t* descriptor,
                 Recorded* r, bool latched) {
    r->type = TypeOf(participant, descriptor);  // the recording's, if it has one
    const std::string type = io::Ros2TypeName(descriptor->m_typename);
    r->fox =
        server->AddChannel(wire::RosTopicName(dds_topic), type, io::Ros2MsgSchema(type), latched);
  };
  add(scene_.topic_name(), &towsim_msgs_msg_dds__SceneInfo__desc, &scene_rec_, true);
  add(status_.topic_name(), &towsim_msgs_msg_dds__SimStatus__desc, &status_rec_, false);
  add(tf_static_.topic_name(), &tf2_msgs_msg_dds__TFMessage__desc, &tf_static_rec_, true);
  for (Published& p : state_) {
    add(p.topic->writer().topic_name(), p.topic->type(), &p.recorded, false);
  }
  // the inbound topics as channels too, so that Foxglove's Publish panel knows their schemas
  // (no messages: what the node takes is not echoed)
  for (const char* type : {"towsim_msgs/msg/ActuatorCommand", "towsim_msgs/msg/SimControl"}) {
    const bool control = std::string(type).find("SimControl") != std::string::npos;
    if (control) {
      server->AddChannel(wire::RosTopicName(control_topic_.name()), type, io::Ros2MsgSchema(type));
      continue;
    }
    for (const dds::Topic& t : command_topics_) {
      server->AddChannel(wire::RosTopicName(t.name()), type, io::Ros2MsgSchema(type));
    }
  }
  std::vector<std::string> winches;
  for (const auto& topic : winch_topics_) {
    const char* type = "towsim_msgs/msg/WinchCommand";
    server->AddChannel(wire::RosTopicName(topic->name()), type, io::Ros2MsgSchema(type));
    winches.push_back(*names_.Owner(wire::Topic::kWinchCommand, topic->name()));
  }
  // clients publish through writers of the node's participant: its own readers take them
  fox_commands_ = std::make_unique<FoxgloveCommands>(participant, names_, body_names_, winches);
  fox_commands_->Attach(server);
}

NodeEndpoints::Recorded NodeEndpoints::AddRecorded(const dds::Participant& participant,
                                                   const std::string& topic,
                                                   const dds_topic_descriptor_t* descriptor,
                                                   bool transient_local) {
  Recorded r;
  r.type = TypeOf(participant, descriptor);
  r.channel = recording_->AddTopic(topic, descriptor->m_typename, transient_local);
  return r;
}

void NodeEndpoints::StartRecording(const dds::Participant& participant, McapRecording* recording,
                                   bool wall_time) {
  recording_ = recording;
  record_wall_time_ = wall_time;
  if (recording_ == nullptr) return;
  scene_rec_ = AddRecorded(participant, scene_.topic_name(), &towsim_msgs_msg_dds__SceneInfo__desc,
                           /*transient_local=*/true);
  status_rec_ =
      AddRecorded(participant, status_.topic_name(), &towsim_msgs_msg_dds__SimStatus__desc, false);
  tf_static_rec_ = AddRecorded(participant, tf_static_.topic_name(),
                               &tf2_msgs_msg_dds__TFMessage__desc, /*transient_local=*/true);
  for (Published& p : state_) {
    const uint32_t fox = p.recorded.fox;  // a Foxglove channel added before
    p.recorded = AddRecorded(participant, p.topic->writer().topic_name(), p.topic->type(), false);
    p.recorded.fox = fox;
  }
}

void NodeEndpoints::PublishState(const core::Simulation& sim, uint64_t step,
                                 const core::PublishStrides& strides, bool all) {
  sim_ns_ = SimNs(sim.time());
  for (Published& p : state_) {
    StateTopic& t = *p.topic;
    if (t.sampled()) {
      // a sensor with errors: stepped every step, listened to or not (node_topics.h)
      const void* msg = t.Sample(sim, step, strides.Due(t.rate(), step, false));
      if (msg != nullptr && Wanted(t.writer(), p.recorded)) Emit(t.writer(), p.recorded, msg);
      continue;
    }
    if (!strides.Due(t.rate(), step, all) || !Wanted(t.writer(), p.recorded)) continue;
    Emit(t.writer(), p.recorded, t.Fill(sim, step));
  }
  if (fox_ != nullptr && fox_->clients() > 0 && strides.Due(core::PublishRate::kClock, step, all)) {
    fox_->BroadcastTime(sim_ns_);  // the `time` capability
  }
}

void NodeEndpoints::PublishStatus(const dds::StatusSample& sample) {
  sim_ns_ = SimNs(sample.sim_time);
  if (fox_commands_) fox_commands_->SetStatusStep(sample.step);  // what Teleop answers
  if (!Wanted(status_, status_rec_)) return;
  dds::ToSimStatus(sample, &status_msg_);
  Emit(status_, status_rec_, &status_msg_.msg);
}

void NodeEndpoints::PublishSceneInfo(const dds::SceneInfoSample& sample) {
  // transient local: written even without a reader, for late joiners
  dds::ToSceneInfo(sample, &scene_msg_);
  sim_ns_ = SimNs(sample.time);
  EmitAlways(scene_, scene_rec_, &scene_msg_.msg);
  // the static frames with it (also after a reset: the stamp of the new run)
  for (int i = 0; i < tf_static_msg_->size(); ++i) {
    tf_static_msg_->transform(i).header.stamp = scene_msg_.msg.header.stamp;
  }
  EmitAlways(tf_static_, tf_static_rec_, &tf_static_msg_->msg);
}

std::vector<dds_entity_t> NodeEndpoints::readers() const {
  std::vector<dds_entity_t> out;
  for (const auto& r : command_readers_) out.push_back(r->get());
  for (const auto& r : pose_readers_) out.push_back(r->get());
  for (const auto& r : winch_readers_) out.push_back(r->get());
  out.push_back(control_reader_.get());
  return out;
}

std::vector<dds_entity_t> NodeEndpoints::writers() const {
  std::vector<dds_entity_t> out = {status_.get(), scene_.get(), tf_static_.get()};
  for (const Published& p : state_) out.push_back(p.topic->writer().get());
  return out;
}

void NodeEndpoints::Flush(double timeout) {
  dds_wait_for_acks(status_.get(), Nanoseconds(timeout));
}

void NodeEndpoints::WaitForInput(double timeout) {
  waitset_.Wait(Nanoseconds(timeout));
  if (recording_ != nullptr) recording_->FlushIfDue();  // idle: no Write() flushes
}

}  // namespace towsim::app
