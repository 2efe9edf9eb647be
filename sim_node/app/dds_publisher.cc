#include "app/dds_publisher.h"

#include <cmath>

namespace towsim::app {
namespace {

bool Due(uint64_t step, long stride, bool all) {
  return all || step % static_cast<uint64_t>(stride < 1 ? 1 : stride) == 0;
}

int64_t Nanoseconds(double s) { return static_cast<int64_t>(std::llround(s * 1e9)); }

}  // namespace

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
        std::make_unique<dds::WrenchStampedMessage>(name)}));
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

void NodeEndpoints::PublishState(const core::Simulation& sim, uint64_t step,
                                 const PublishStrides& strides, bool all) {
  for (size_t b = 0; b < bodies_.size(); ++b) {
    BodyEndpoints& e = *bodies_[b];
    if (Due(step, strides.odom, all) && e.odom.matched()) {
      dds::ToOdometry(sim, static_cast<int>(b), &e.odom_msg->msg);
      e.odom.Write(e.odom_msg->msg);
    }
    if (Due(step, strides.cable_force, all) && e.force.matched()) {
      dds::ToCableForce(sim, static_cast<int>(b), &e.force_msg->msg);
      e.force.Write(e.force_msg->msg);
    }
  }
  if (Due(step, strides.cable_state, all) && cable_.matched()) {
    dds::ToCableState(sim, step, cable_msg_.get());
    cable_.Write(cable_msg_->msg);
  }
  if (Due(step, strides.clock, all) && clock_.matched()) {
    dds::ToClock(sim.time(), &clock_msg_);
    clock_.Write(clock_msg_);
  }
}

void NodeEndpoints::PublishStatus(const dds::StatusSample& sample) {
  if (!status_.matched()) return;
  dds::ToSimStatus(sample, &status_msg_);
  status_.Write(status_msg_.msg);
}

void NodeEndpoints::PublishSceneInfo(const dds::SceneInfoSample& sample) {
  // transient local: written even without a reader, for late joiners
  dds::ToSceneInfo(sample, &scene_msg_);
  scene_.Write(scene_msg_.msg);
}

void NodeEndpoints::Flush(double timeout) {
  dds_wait_for_acks(status_.get(), Nanoseconds(timeout));
}

void NodeEndpoints::WaitForInput(double timeout) { waitset_.Wait(Nanoseconds(timeout)); }

}  // namespace towsim::app
