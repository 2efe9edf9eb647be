#include "app/common/node_topics.h"

#include <utility>

#include "dds/environment_translator.h"
#include "dds/frames.h"
#include "dds/markers.h"
#include "dds/messages.h"
#include "dds/sensor_errors.h"
#include "dds/sensor_translators.h"
#include "dds/translators.h"
#include "io/csv_writer.h"

namespace towsim::app {
namespace {

using core::PublishRate;

// a state topic whose message `Holder` (a dds/translators.h *Message: its C struct in .msg)
// is filled by Translate(sim, body, step, holder)
template <class Holder, void (*Translate)(const core::Simulation&, int, uint64_t, Holder*)>
class Translated final : public StateTopic {
 public:
  Translated(const dds::Participant& participant, const TopicRow& row, const std::string& name,
             std::unique_ptr<Holder> holder, int body)
      : StateTopic(participant, row.spec().type, name, dds::QosOf(row.spec().qos), row.rate),
        holder_(std::move(holder)),
        body_(body) {}
  const void* Fill(const core::Simulation& sim, uint64_t step) override {
    Translate(sim, body_, step, holder_.get());
    return &holder_->msg;
  }

 private:
  std::unique_ptr<Holder> holder_;
  int body_;
};

// a sensor topic with errors (dds/sensor_errors.h): Translate builds the true message of each
// step, the sensor model turns it into what the sensor publishes
template <class Holder, void (*Translate)(const core::Simulation&, int, uint64_t, Holder*)>
class Modelled final : public StateTopic {
 public:
  Modelled(const dds::Participant& participant, const TopicRow& row, const std::string& name,
           std::unique_ptr<Holder> holder, int body, core::SensorModel model)
      : StateTopic(participant, row.spec().type, name, dds::QosOf(row.spec().qos), row.rate),
        holder_(std::move(holder)),
        body_(body),
        model_(std::move(model)) {}
  const void* Fill(const core::Simulation& sim, uint64_t step) override {
    return Sample(sim, step, true);
  }
  bool sampled() const override { return true; }
  const void* Sample(const core::Simulation& sim, uint64_t step, bool due) override {
    if (started_ && step == last_) return published_ ? &holder_->msg : nullptr;  // republished
    if (started_ && step < last_) model_.Restart();  // a reset: the run starts over
    started_ = true;
    last_ = step;
    Translate(sim, body_, step, holder_.get());
    published_ = dds::ApplySensorErrors(&model_, step, due, &holder_->msg);
    return published_ ? &holder_->msg : nullptr;
  }

 private:
  std::unique_ptr<Holder> holder_;
  int body_;
  core::SensorModel model_;
  bool started_ = false, published_ = false;
  uint64_t last_ = 0;
};

// a commanded vehicle's actuator state (dds/actuator_state_translator.h): the simulation's
// command and actuators with the node's flags of the vehicle, read when the message is filled
class ActuatorStateTopic final : public StateTopic {
 public:
  ActuatorStateTopic(const dds::Participant& participant, const TopicRow& row,
                     const std::string& name, const core::Simulation& sim, int vehicle,
                     const VehicleCommands& vehicles)
      : StateTopic(participant, row.spec().type, name, dds::QosOf(row.spec().qos), row.rate),
        message_(dds::FrdFrame(sim.body_name(sim.num_spheres() + vehicle))),
        vehicle_(vehicle),
        vehicles_(vehicles) {}
  const void* Fill(const core::Simulation& sim, uint64_t step) override {
    dds::ToActuatorState(sim, vehicle_, step, vehicles_.flags[vehicle_], &message_.msg);
    return &message_.msg;
  }

 private:
  dds::ActuatorStateMessage message_;
  int vehicle_;
  const VehicleCommands& vehicles_;
};

// /clock has no strings to own
struct ClockHolder {
  dds::ClockMsg msg{};
};

// the translators, in the form Translated takes
void Odometry(const core::Simulation& sim, int b, uint64_t, dds::OdometryMessage* m) {
  dds::ToOdometry(sim, b, &m->msg);
}
void CableForce(const core::Simulation& sim, int b, uint64_t, dds::WrenchStampedMessage* m) {
  dds::ToCableForce(sim, b, &m->msg);
}
void Altitude(const core::Simulation& sim, int b, uint64_t, dds::RangeMessage* m) {
  dds::ToAltitude(sim, b, &m->msg);
}
void Pressure(const core::Simulation& sim, int b, uint64_t, dds::FluidPressureMessage* m) {
  dds::ToPressure(sim, b, &m->msg);
}
void Environment(const core::Simulation& sim, int b, uint64_t step,
                 dds::BodyEnvironmentMessage* m) {
  dds::ToBodyEnvironment(sim, b, step, &m->msg);
}
void CableState(const core::Simulation& sim, int c, uint64_t step, dds::CableStateMessage* m) {
  dds::ToCableState(sim, step, m, c);
}
// a cable end's force (the row's End: 0 start, 1 end) of cable c
template <int End>
void EndForce(const core::Simulation& sim, int c, uint64_t, dds::WrenchStampedMessage* m) {
  dds::ToCableEndForce(sim, End, c, &m->msg);
}
void Clock(const core::Simulation& sim, int, uint64_t, ClockHolder* m) {
  dds::ToClock(sim.time(), &m->msg);
}
void Transforms(const core::Simulation& sim, int, uint64_t, dds::TransformsMessage* m) {
  dds::ToBodyTransforms(sim, m);
}
void Markers(const core::Simulation& sim, int, uint64_t, dds::SceneMarkers* m) { m->Update(sim); }

template <class Holder, void (*Translate)(const core::Simulation&, int, uint64_t, Holder*)>
std::unique_ptr<StateTopic> Make(const dds::Participant& participant, const TopicRow& row,
                                 const std::string& name, std::unique_ptr<Holder> holder,
                                 int body) {
  return std::make_unique<Translated<Holder, Translate>>(participant, row, name, std::move(holder),
                                                         body);
}

// a body's sensor topic: Modelled when the scene gives the sensor errors, else Translated (the
// true value, as without sensor keys)
template <class Holder, void (*Translate)(const core::Simulation&, int, uint64_t, Holder*)>
std::unique_ptr<StateTopic> MakeSensor(const dds::Participant& participant, const TopicRow& row,
                                       const std::string& name, std::unique_ptr<Holder> holder,
                                       const core::Simulation& sim, int body, dds::Sensor sensor) {
  const core::SensorErrors* errors =
      dds::FindSensorErrors(sim.model(), sim.body_name(body), sensor);
  if (errors == nullptr) {
    return Make<Holder, Translate>(participant, row, name, std::move(holder), body);
  }
  return std::make_unique<Modelled<Holder, Translate>>(
      participant, row, name, std::move(holder), body,
      dds::MakeSensorModel(*errors, sensor, sim.model().time.step));
}

// the force topic of end End of cable c where forces.csv has its row (dds::HasEndForce), in the
// frame of its support (world_ned) or of its body (<b>_frd); nullptr elsewhere
template <int End>
std::unique_ptr<StateTopic> MakeEndForce(const dds::Participant& participant, const TopicRow& row,
                                         const std::string& name, const core::Simulation& sim,
                                         int c, const VehicleCommands&) {
  if (!dds::HasEndForce(sim, End, c)) return nullptr;
  const int body = sim.EndBody(End, c);
  return Make<dds::WrenchStampedMessage, EndForce<End>>(
      participant, row, name,
      std::make_unique<dds::WrenchStampedMessage>(
          body < 0 ? std::string(dds::kWorldFrame) : dds::FrdFrame(sim.body_name(body))),
      c);
}

std::vector<TopicRow> BuildTable() {
  using P = const dds::Participant&;
  using S = const core::Simulation&;
  using N = const std::string&;
  using V = const VehicleCommands&;
  using T = wire::Topic;
  return {
      {T::kClock, PublishRate::kClock,
       [](P p, const TopicRow& row, N name, S, int, V) {
         return Make<ClockHolder, Clock>(p, row, name, std::make_unique<ClockHolder>(), -1);
       }},
      {T::kCableState, PublishRate::kCableState,
       [](P p, const TopicRow& row, N name, S sim, int c, V) {
         return Make<dds::CableStateMessage, CableState>(
             p, row, name,
             std::make_unique<dds::CableStateMessage>(dds::kWorldFrame, dds::MaxCableNodes(sim, c)),
             c);
       }},
      // the held ends' forces, with the bodies' cable_force (forces.csv's rows)
      {T::kCableStartForce, PublishRate::kCableForce, &MakeEndForce<0>},
      {T::kCableEndForce, PublishRate::kCableForce, &MakeEndForce<1>},
      // /tf: the same state as the odometry, at its rate
      {T::kTf, PublishRate::kOdom,
       [](P p, const TopicRow& row, N name, S sim, int, V) {
         return Make<dds::TransformsMessage, Transforms>(p, row, name, dds::BodyTransforms(sim),
                                                         -1);
       }},
      {T::kMarkers, PublishRate::kMarkers,
       [](P p, const TopicRow& row, N name, S sim, int, V) {
         return Make<dds::SceneMarkers, Markers>(p, row, name,
                                                 std::make_unique<dds::SceneMarkers>(sim), -1);
       }},
      {T::kOdom, PublishRate::kOdom,
       [](P p, const TopicRow& row, N name, S sim, int b, V) {
         return MakeSensor<dds::OdometryMessage, Odometry>(
             p, row, name,
             std::make_unique<dds::OdometryMessage>(dds::kWorldFrame,
                                                    dds::FrdFrame(sim.body_name(b))),
             sim, b, dds::Sensor::kOdometry);
       }},
      {T::kCableForce, PublishRate::kCableForce,
       [](P p, const TopicRow& row, N name, S sim, int b, V) {
         return Make<dds::WrenchStampedMessage, CableForce>(
             p, row, name,
             std::make_unique<dds::WrenchStampedMessage>(dds::FrdFrame(sim.body_name(b))), b);
       }},
      {T::kAltitude, PublishRate::kSensors,
       [](P p, const TopicRow& row, N name, S sim, int b, V) {
         return MakeSensor<dds::RangeMessage, Altitude>(
             p, row, name, std::make_unique<dds::RangeMessage>(sim.body_name(b)), sim, b,
             dds::Sensor::kAltimeter);
       }},
      {T::kPressure, PublishRate::kSensors,
       [](P p, const TopicRow& row, N name, S sim, int b, V) {
         return MakeSensor<dds::FluidPressureMessage, Pressure>(
             p, row, name, std::make_unique<dds::FluidPressureMessage>(sim.body_name(b)), sim, b,
             dds::Sensor::kPressure);
       }},
      // the sea at each body, as environment.csv: only in a scene with waves, a current or a
      // seabed (io::HasSea; a calm scene's node has no such topic)
      {T::kEnvironment, PublishRate::kSensors,
       [](P p, const TopicRow& row, N name, S sim, int b, V) -> std::unique_ptr<StateTopic> {
         if (!io::HasSea(sim.model().environment)) return nullptr;
         return Make<dds::BodyEnvironmentMessage, Environment>(
             p, row, name, std::make_unique<dds::BodyEnvironmentMessage>(dds::kWorldFrame), b);
       }},
      // a vehicle's command in force and actuator states, as actuators.csv, at the odometry's
      // rate: only for the vehicles that take commands (those with a command topic)
      {T::kActuatorState, PublishRate::kOdom,
       [](P p, const TopicRow& row, N name, S sim, int b, V vehicles)
           -> std::unique_ptr<StateTopic> {
         const int v = b - sim.num_spheres();
         if (v < 0 || v >= sim.num_vehicles() ||
             v >= static_cast<int>(vehicles.commanded.size()) || !vehicles.commanded[v]) {
           return nullptr;
         }
         return std::make_unique<ActuatorStateTopic>(p, row, name, sim, v, vehicles);
       }},
  };
}

}  // namespace

StateTopic::StateTopic(const dds::Participant& participant, const dds_topic_descriptor_t* type,
                       const std::string& name, const dds::Qos& qos, core::PublishRate rate)
    : type_(type),
      rate_(rate),
      topic_(participant, type, name),
      writer_(participant, topic_, qos) {}

const std::vector<TopicRow>& NodeTopicTable() {
  static const std::vector<TopicRow> table = BuildTable();
  return table;
}

}  // namespace towsim::app
