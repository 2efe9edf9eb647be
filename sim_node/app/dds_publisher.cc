#include "app/dds_publisher.h"

#include <cmath>
#include <string>

namespace towsim::app {
namespace {

bool Due(uint64_t step, long stride, bool all) {
  return all || step % static_cast<uint64_t>(stride < 1 ? 1 : stride) == 0;
}

int64_t Nanoseconds(double s) { return static_cast<int64_t>(std::llround(s * 1e9)); }

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
      clock_(participant, clock_topic_, dds::StateQos()),
      cable_(participant, cable_topic_, dds::StateQos()),
      status_(participant, status_topic_, dds::StateQos()),
      scene_(participant, scene_topic_, dds::SceneInfoQos()),
      control_reader_(participant, control_topic_, dds::ControlQos()),
      waitset_(participant),
      cable_msg_(std::make_unique<dds::CableStateMessage>(dds::kWorldFrame, sim.num_nodes())) {
  for (int b = 0; b < sim.num_bodies(); ++b) {
    const std::string& name = sim.body_name(b);
    dds::Topic odom_topic(participant, &nav_msgs_msg_dds__Odometry__desc, names.odom(name));
    dds::Topic force_topic(participant, &geometry_msgs_msg_dds__WrenchStamped__desc,
                           names.cable_force(name));
    dds::Writer<dds::OdometryMsg> odom(participant, odom_topic, dds::StateQos());
    dds::Writer<dds::WrenchStampedMsg> force(participant, force_topic, dds::StateQos());
    bodies_.push_back(std::make_unique<BodyEndpoints>(BodyEndpoints{
        std::move(odom_topic), std::move(force_topic), std::move(odom), std::move(force),
        std::make_unique<dds::OdometryMessage>(dds::kWorldFrame, name),
        std::make_unique<dds::WrenchStampedMessage>(name), Recorded{}, Recorded{}}));
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
  waitset_.Attach(control_reader_.condition());
}

template <class T>
void NodeEndpoints::Emit(dds::Writer<T>& writer, const Recorded& recorded, const T& msg) {
  if (recording_ == nullptr) {
    writer.Write(msg);
    return;
  }
  // serialized once: these bytes go to DDS and into the recording
  const dds::CdrSample sample = dds::CdrSample::FromSample(*recorded.type, &msg);
  const dds_time_t now = dds_time();
  if (writer.matched()) {
    const dds_return_t rc = sample.Write(writer.get(), now);
    if (rc < 0) throw dds::DdsError("writing to " + writer.topic_name(), rc);
  }
  sample.CopyTo(&buffer_);
  recording_->Write(recorded.channel, static_cast<uint64_t>(now), static_cast<uint64_t>(now),
                    buffer_.data(), buffer_.size());
}

NodeEndpoints::Recorded NodeEndpoints::AddRecorded(const dds::Participant& participant,
                                                   const std::string& topic,
                                                   const dds_topic_descriptor_t* descriptor,
                                                   bool transient_local) {
  Recorded r;
  for (const auto& t : raw_types_) {
    if (t->descriptor() == descriptor) r.type = t.get();
  }
  if (r.type == nullptr) {
    raw_types_.push_back(std::make_unique<dds::RawType>(participant, descriptor));
    r.type = raw_types_.back().get();
  }
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
  for (size_t b = 0; b < bodies_.size(); ++b) {
    BodyEndpoints& e = *bodies_[b];
    if (Due(step, strides.odom, all) && Wanted(e.odom)) {
      dds::ToOdometry(sim, static_cast<int>(b), &e.odom_msg->msg);
      Emit(e.odom, e.odom_rec, e.odom_msg->msg);
    }
    if (Due(step, strides.cable_force, all) && Wanted(e.force)) {
      dds::ToCableForce(sim, static_cast<int>(b), &e.force_msg->msg);
      Emit(e.force, e.force_rec, e.force_msg->msg);
    }
  }
  for (size_t b = 0; b < sensors_.size(); ++b) {
    SensorEndpoints& s = *sensors_[b];
    if (!Due(step, strides.sensors, all)) break;
    if (Wanted(s.altitude)) {
      dds::ToAltitude(sim, static_cast<int>(b), &s.altitude_msg.msg);
      Emit(s.altitude, s.altitude_rec, s.altitude_msg.msg);
    }
    if (Wanted(s.pressure)) {
      dds::ToPressure(sim, static_cast<int>(b), &s.pressure_msg.msg);
      Emit(s.pressure, s.pressure_rec, s.pressure_msg.msg);
    }
  }
  if (Due(step, strides.cable_state, all) && Wanted(cable_)) {
    dds::ToCableState(sim, step, cable_msg_.get());
    Emit(cable_, cable_rec_, cable_msg_->msg);
  }
  if (Due(step, strides.clock, all) && Wanted(clock_)) {
    dds::ToClock(sim.time(), &clock_msg_);
    Emit(clock_, clock_rec_, clock_msg_);
  }
}

void NodeEndpoints::PublishStatus(const dds::StatusSample& sample) {
  if (!Wanted(status_)) return;
  dds::ToSimStatus(sample, &status_msg_);
  Emit(status_, status_rec_, status_msg_.msg);
}

void NodeEndpoints::PublishSceneInfo(const dds::SceneInfoSample& sample) {
  // transient local: written even without a reader, for late joiners
  dds::ToSceneInfo(sample, &scene_msg_);
  if (recording_ == nullptr) {
    scene_.Write(scene_msg_.msg);
    return;
  }
  const dds::CdrSample s = dds::CdrSample::FromSample(*scene_rec_.type, &scene_msg_.msg);
  const dds_time_t now = dds_time();
  const dds_return_t rc = s.Write(scene_.get(), now);
  if (rc < 0) throw dds::DdsError("writing to " + scene_.topic_name(), rc);
  s.CopyTo(&buffer_);
  recording_->Write(scene_rec_.channel, static_cast<uint64_t>(now), static_cast<uint64_t>(now),
                    buffer_.data(), buffer_.size());
}

void NodeEndpoints::Flush(double timeout) {
  dds_wait_for_acks(status_.get(), Nanoseconds(timeout));
}

void NodeEndpoints::WaitForInput(double timeout) {
  waitset_.Wait(Nanoseconds(timeout));
  if (recording_ != nullptr) recording_->FlushIfDue();  // idle: no Write() flushes
}

}  // namespace towsim::app
