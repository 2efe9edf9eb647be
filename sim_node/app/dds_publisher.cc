#include "app/dds_publisher.h"

#include <cmath>
#include <string>

#include "io/ros2_schemas.h"

namespace towsim::app {
namespace {

bool Due(uint64_t step, long stride, bool all) {
  return all || step % static_cast<uint64_t>(stride < 1 ? 1 : stride) == 0;
}

int64_t Nanoseconds(double s) { return static_cast<int64_t>(std::llround(s * 1e9)); }

// simulation time as a Foxglove log time [ns] (negative times as 0)
uint64_t SimNs(double t) { return t > 0.0 ? static_cast<uint64_t>(std::llround(t * 1e9)) : 0; }

}  // namespace

NodeEndpoints::SensorEndpoints::SensorEndpoints(const dds::Participant& participant,
                                                const dds::TopicNames& names,
                                                const std::string& body)
    : altitude_topic(participant, &sensor_msgs_msg_dds__Range__desc, names.altitude(body)),
      pressure_topic(participant, &sensor_msgs_msg_dds__FluidPressure__desc, names.pressure(body)),
      altitude(participant, altitude_topic, dds::StateQos()),
      pressure(participant, pressure_topic, dds::StateQos()),
      altitude_msg(body),
      pressure_msg(body) {}

NodeEndpoints::NodeEndpoints(const dds::Participant& participant, const dds::TopicNames& names,
                             const core::Simulation& sim, const std::vector<int>& command_vehicles)
    : clock_topic_(participant, &rosgraph_msgs_msg_dds__Clock__desc, names.clock()),
      cable_topic_(participant, &towsim_msgs_msg_dds__CableState__desc, names.cable_state()),
      status_topic_(participant, &towsim_msgs_msg_dds__SimStatus__desc, names.status()),
      scene_topic_(participant, &towsim_msgs_msg_dds__SceneInfo__desc, names.scene_info()),
      control_topic_(participant, &towsim_msgs_msg_dds__SimControl__desc, names.sim_control()),
      tf_topic_(participant, &tf2_msgs_msg_dds__TFMessage__desc, names.tf()),
      tf_static_topic_(participant, &tf2_msgs_msg_dds__TFMessage__desc, names.tf_static()),
      markers_topic_(participant, &visualization_msgs_msg_dds__MarkerArray__desc, names.markers()),
      clock_(participant, clock_topic_, dds::StateQos()),
      cable_(participant, cable_topic_, dds::StateQos()),
      status_(participant, status_topic_, dds::StateQos()),
      scene_(participant, scene_topic_, dds::SceneInfoQos()),
      tf_(participant, tf_topic_, dds::StateQos()),
      tf_static_(participant, tf_static_topic_, dds::SceneInfoQos()),
      markers_(participant, markers_topic_, dds::StateQos()),
      control_reader_(participant, control_topic_, dds::ControlQos()),
      waitset_(participant),
      cable_msg_(std::make_unique<dds::CableStateMessage>(dds::kWorldFrame,
                                                          dds::MaxCableNodes(sim))),
      tf_msg_(dds::BodyTransforms(sim)),
      tf_static_msg_(dds::StaticTransforms(sim)),
      markers_msg_(std::make_unique<dds::SceneMarkers>(sim)),
      names_(names) {
  for (int b = 0; b < sim.num_bodies(); ++b) body_names_.push_back(sim.body_name(b));
  for (int b = 0; b < sim.num_bodies(); ++b) {
    const std::string& name = sim.body_name(b);
    dds::Topic odom_topic(participant, &nav_msgs_msg_dds__Odometry__desc, names.odom(name));
    dds::Topic force_topic(participant, &geometry_msgs_msg_dds__WrenchStamped__desc,
                           names.cable_force(name));
    dds::Writer<dds::OdometryMsg> odom(participant, odom_topic, dds::StateQos());
    dds::Writer<dds::WrenchStampedMsg> force(participant, force_topic, dds::StateQos());
    bodies_.push_back(std::make_unique<BodyEndpoints>(BodyEndpoints{
        std::move(odom_topic), std::move(force_topic), std::move(odom), std::move(force),
        std::make_unique<dds::OdometryMessage>(dds::kWorldFrame, dds::FrdFrame(name)),
        std::make_unique<dds::WrenchStampedMessage>(dds::FrdFrame(name)), Recorded{}, Recorded{}}));
  }
  for (int b = 0; b < sim.num_bodies(); ++b) {
    sensors_.push_back(std::make_unique<SensorEndpoints>(participant, names, sim.body_name(b)));
  }
  const int num_spheres = sim.num_spheres();
  for (int v : command_vehicles) {
    command_topics_.emplace_back(participant, &towsim_msgs_msg_dds__ActuatorCommand__desc,
                                 names.command(sim.body_name(num_spheres + v)));
    command_readers_.push_back(std::make_unique<dds::Reader<dds::ActuatorCommandMsg>>(
        participant, command_topics_.back(), dds::CommandQos()));
    waitset_.Attach(command_readers_.back()->condition());
  }
  if (sim.has_winch()) {
    winch_topic_ = std::make_unique<dds::Topic>(participant, &towsim_msgs_msg_dds__WinchCommand__desc,
                                                names.winch_command());
    winch_reader_ = std::make_unique<dds::Reader<dds::WinchCommandMsg>>(participant, *winch_topic_,
                                                                        dds::CommandQos());
    waitset_.Attach(winch_reader_->condition());
  }
  waitset_.Attach(control_reader_.condition());
}

template <class T>
void NodeEndpoints::Emit(dds::Writer<T>& writer, const Recorded& recorded, const T& msg) {
  const bool served = Served(recorded);
  if (recording_ == nullptr && !served) {
    writer.Write(msg);
    return;
  }
  // serialized once: these bytes go to DDS, into the recording and to Foxglove
  const dds::CdrSample sample = dds::CdrSample::FromSample(*recorded.type, &msg);
  const dds_time_t now = dds_time();
  if (writer.matched()) {
    const dds_return_t rc = sample.Write(writer.get(), now);
    if (rc < 0) throw dds::DdsError("writing to " + writer.topic_name(), rc);
  }
  sample.CopyTo(&buffer_);
  if (recording_ != nullptr) {
    recording_->Write(recorded.channel, static_cast<uint64_t>(now), static_cast<uint64_t>(now),
                      buffer_.data(), buffer_.size());
  }
  if (served) fox_->Publish(recorded.fox, sim_ns_, buffer_.data(), buffer_.size());
}

template <class T>
void NodeEndpoints::EmitAlways(dds::Writer<T>& writer, const Recorded& recorded, const T& msg) {
  if (recording_ == nullptr && fox_ == nullptr) {
    writer.Write(msg);
    return;
  }
  const dds::CdrSample s = dds::CdrSample::FromSample(*recorded.type, &msg);
  const dds_time_t now = dds_time();
  const dds_return_t rc = s.Write(writer.get(), now);
  if (rc < 0) throw dds::DdsError("writing to " + writer.topic_name(), rc);
  s.CopyTo(&buffer_);
  if (recording_ != nullptr) {
    recording_->Write(recorded.channel, static_cast<uint64_t>(now), static_cast<uint64_t>(now),
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
    r->fox = server->AddChannel(RosTopicName(dds_topic), type, io::Ros2MsgSchema(type), latched);
  };
  add(scene_.topic_name(), &towsim_msgs_msg_dds__SceneInfo__desc, &scene_rec_, true);
  add(clock_.topic_name(), &rosgraph_msgs_msg_dds__Clock__desc, &clock_rec_, false);
  add(status_.topic_name(), &towsim_msgs_msg_dds__SimStatus__desc, &status_rec_, false);
  add(cable_.topic_name(), &towsim_msgs_msg_dds__CableState__desc, &cable_rec_, false);
  add(tf_static_.topic_name(), &tf2_msgs_msg_dds__TFMessage__desc, &tf_static_rec_, true);
  add(tf_.topic_name(), &tf2_msgs_msg_dds__TFMessage__desc, &tf_rec_, false);
  add(markers_.topic_name(), &visualization_msgs_msg_dds__MarkerArray__desc, &markers_rec_, false);
  for (auto& b : bodies_) {
    add(b->odom.topic_name(), &nav_msgs_msg_dds__Odometry__desc, &b->odom_rec, false);
    add(b->force.topic_name(), &geometry_msgs_msg_dds__WrenchStamped__desc, &b->force_rec, false);
  }
  // the inbound topics as channels too, so that Foxglove's Publish panel knows their schemas
  // (no messages: what the node takes is not echoed)
  for (const char* type : {"towsim_msgs/msg/ActuatorCommand", "towsim_msgs/msg/SimControl"}) {
    const bool control = std::string(type).find("SimControl") != std::string::npos;
    if (control) {
      server->AddChannel(RosTopicName(control_topic_.name()), type, io::Ros2MsgSchema(type));
      continue;
    }
    for (const dds::Topic& t : command_topics_) {
      server->AddChannel(RosTopicName(t.name()), type, io::Ros2MsgSchema(type));
    }
  }
  if (winch_topic_) {
    const char* type = "towsim_msgs/msg/WinchCommand";
    server->AddChannel(RosTopicName(winch_topic_->name()), type, io::Ros2MsgSchema(type));
  }
  // clients publish through writers of the node's participant: its own readers take them
  fox_commands_ =
      std::make_unique<FoxgloveCommands>(participant, names_, body_names_, "sim_node", false);
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

void NodeEndpoints::StartRecording(const dds::Participant& participant, McapRecording* recording) {
  recording_ = recording;
  if (recording_ == nullptr) return;
  scene_rec_ = AddRecorded(participant, scene_.topic_name(), &towsim_msgs_msg_dds__SceneInfo__desc,
                           /*transient_local=*/true);
  clock_rec_ =
      AddRecorded(participant, clock_.topic_name(), &rosgraph_msgs_msg_dds__Clock__desc, false);
  status_rec_ =
      AddRecorded(participant, status_.topic_name(), &towsim_msgs_msg_dds__SimStatus__desc, false);
  cable_rec_ =
      AddRecorded(participant, cable_.topic_name(), &towsim_msgs_msg_dds__CableState__desc, false);
  tf_static_rec_ = AddRecorded(participant, tf_static_.topic_name(),
                               &tf2_msgs_msg_dds__TFMessage__desc, /*transient_local=*/true);
  tf_rec_ = AddRecorded(participant, tf_.topic_name(), &tf2_msgs_msg_dds__TFMessage__desc, false);
  markers_rec_ = AddRecorded(participant, markers_.topic_name(),
                             &visualization_msgs_msg_dds__MarkerArray__desc, false);
  for (auto& b : bodies_) {
    b->odom_rec =
        AddRecorded(participant, b->odom.topic_name(), &nav_msgs_msg_dds__Odometry__desc, false);
    b->force_rec = AddRecorded(participant, b->force.topic_name(),
                               &geometry_msgs_msg_dds__WrenchStamped__desc, false);
  }
  for (auto& s : sensors_) {
    s->altitude_rec = AddRecorded(participant, s->altitude.topic_name(),
                                  &sensor_msgs_msg_dds__Range__desc, false);
    s->pressure_rec = AddRecorded(participant, s->pressure.topic_name(),
                                  &sensor_msgs_msg_dds__FluidPressure__desc, false);
  }
}

void NodeEndpoints::PublishState(const core::Simulation& sim, uint64_t step,
                                 const PublishStrides& strides, bool all) {
  sim_ns_ = SimNs(sim.time());
  for (size_t b = 0; b < bodies_.size(); ++b) {
    BodyEndpoints& e = *bodies_[b];
    if (Due(step, strides.odom, all) && Wanted(e.odom, e.odom_rec)) {
      dds::ToOdometry(sim, static_cast<int>(b), &e.odom_msg->msg);
      Emit(e.odom, e.odom_rec, e.odom_msg->msg);
    }
    if (Due(step, strides.cable_force, all) && Wanted(e.force, e.force_rec)) {
      dds::ToCableForce(sim, static_cast<int>(b), &e.force_msg->msg);
      Emit(e.force, e.force_rec, e.force_msg->msg);
    }
  }
  if (Due(step, strides.odom, all) && Wanted(tf_, tf_rec_)) {
    dds::ToBodyTransforms(sim, tf_msg_.get());
    Emit(tf_, tf_rec_, tf_msg_->msg);
  }
  if (Due(step, strides.markers, all) && Wanted(markers_, markers_rec_)) {
    markers_msg_->Update(sim);
    Emit(markers_, markers_rec_, markers_msg_->msg);
  }
  for (size_t b = 0; b < sensors_.size(); ++b) {
    SensorEndpoints& s = *sensors_[b];
    if (!Due(step, strides.sensors, all)) break;
    if (Wanted(s.altitude, s.altitude_rec)) {
      dds::ToAltitude(sim, static_cast<int>(b), &s.altitude_msg.msg);
      Emit(s.altitude, s.altitude_rec, s.altitude_msg.msg);
    }
    if (Wanted(s.pressure, s.pressure_rec)) {
      dds::ToPressure(sim, static_cast<int>(b), &s.pressure_msg.msg);
      Emit(s.pressure, s.pressure_rec, s.pressure_msg.msg);
    }
  }
  if (Due(step, strides.cable_state, all) && Wanted(cable_, cable_rec_)) {
    dds::ToCableState(sim, step, cable_msg_.get());
    Emit(cable_, cable_rec_, cable_msg_->msg);
  }
  if (Due(step, strides.clock, all) && Wanted(clock_, clock_rec_)) {
    dds::ToClock(sim.time(), &clock_msg_);
    Emit(clock_, clock_rec_, clock_msg_);
  }
  if (fox_ != nullptr && fox_->clients() > 0 && Due(step, strides.clock, all)) {
    fox_->BroadcastTime(sim_ns_);  // the `time` capability
  }
}

void NodeEndpoints::PublishStatus(const dds::StatusSample& sample) {
  sim_ns_ = SimNs(sample.sim_time);
  if (fox_commands_) fox_commands_->SetStatusStep(sample.step);  // what Teleop answers
  if (!Wanted(status_, status_rec_)) return;
  dds::ToSimStatus(sample, &status_msg_);
  Emit(status_, status_rec_, status_msg_.msg);
}

void NodeEndpoints::PublishSceneInfo(const dds::SceneInfoSample& sample) {
  // transient local: written even without a reader, for late joiners
  dds::ToSceneInfo(sample, &scene_msg_);
  sim_ns_ = SimNs(sample.time);
  EmitAlways(scene_, scene_rec_, scene_msg_.msg);
  // the static frames with it (also after a reset: the stamp of the new run)
  for (int i = 0; i < tf_static_msg_->size(); ++i) {
    tf_static_msg_->transform(i).header.stamp = scene_msg_.msg.header.stamp;
  }
  EmitAlways(tf_static_, tf_static_rec_, tf_static_msg_->msg);
}

std::vector<dds_entity_t> NodeEndpoints::readers() const {
  std::vector<dds_entity_t> out;
  for (const auto& r : command_readers_) out.push_back(r->get());
  if (winch_reader_) out.push_back(winch_reader_->get());
  out.push_back(control_reader_.get());
  return out;
}

std::vector<dds_entity_t> NodeEndpoints::writers() const {
  std::vector<dds_entity_t> out = {clock_.get(), cable_.get(),     status_.get(), scene_.get(),
                                   tf_.get(),    tf_static_.get(), markers_.get()};
  for (const auto& b : bodies_) {
    out.push_back(b->odom.get());
    out.push_back(b->force.get());
  }
  for (const auto& s : sensors_) {
    out.push_back(s->altitude.get());
    out.push_back(s->pressure.get());
  }
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
