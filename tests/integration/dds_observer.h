#pragma once
// The integration tests as a DDS participant (tests/integration/README.md): the node's status
// (every sample, oldest first), SimControl requests and raw ActuatorCommands on any topic (and
// raw WinchCommands).
// Needs CYCLONEDDS_URI (the tests set it to config/cyclonedds.xml).

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "common/dds_qos.h"
#include "dds/dds.h"
#include "towsim_msgs.h"

namespace towsim::testing {

// how long the observer waits for a status or a match [s]
inline constexpr double kObserverTimeout = 20.0;

struct Status {
  using Clock = std::chrono::steady_clock;
  std::string run_id, mode, message;
  uint8_t state = 0, health = 0;
  uint64_t step = 0;
  double sim_time = 0.0, rate = 0.0;
  std::vector<std::string> failsafe_bodies;
  uint64_t failsafe_count = 0, received = 0, rejected = 0, clamped = 0, lockstep_timeouts = 0;
  Clock::time_point when;
};

// the node's state QoS (controllers/common/dds_qos.h) with a reader history of `depth`
inline dds_qos_t* ReliableQos(int depth) { return controllers::ReliableQos(depth, false); }

// this test as a DDS participant: the node's status, control requests and raw commands
class Observer {
  using Clock = std::chrono::steady_clock;
  static double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

 public:
  Observer(int domain, const std::string& ns = "/towsim")
      : prefix_(ns == "/" ? "rt/" : "rt" + ns + "/") {
    participant_ = dds_create_participant(static_cast<dds_domainid_t>(domain), nullptr, nullptr);
    EXPECT_GT(participant_, 0) << dds_strretcode(participant_);
    dds_qos_t* qos = ReliableQos(1000);
    const dds_entity_t status_topic =
        dds_create_topic(participant_, &towsim_msgs_msg_dds__SimStatus__desc,
                         (prefix_ + "status").c_str(), nullptr, nullptr);
    status_reader_ = dds_create_reader(participant_, status_topic, qos, nullptr);
    const dds_entity_t control_topic =
        dds_create_topic(participant_, &towsim_msgs_msg_dds__SimControl__desc,
                         (prefix_ + "sim_control").c_str(), nullptr, nullptr);
    control_writer_ = dds_create_writer(participant_, control_topic, qos, nullptr);
    dds_delete_qos(qos);
  }
  ~Observer() { dds_delete(participant_); }

  // every status received so far, oldest first
  const std::vector<Status>& statuses() {
    Poll();
    return statuses_;
  }

  // waits for a status that satisfies `pred` (among all received, oldest first)
  bool WaitFor(const std::function<bool(const Status&)>& pred, Status* found,
               double timeout = kObserverTimeout) {
    const Clock::time_point start = Clock::now();
    size_t seen = 0;
    for (;;) {
      Poll();
      for (; seen < statuses_.size(); ++seen) {
        if (pred(statuses_[seen])) {
          if (found != nullptr) *found = statuses_[seen];
          return true;
        }
      }
      if (Seconds(Clock::now() - start) > timeout) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }

  void Control(uint8_t command, uint32_t steps = 0, double rate = 0.0) {
    ASSERT_TRUE(Matched(control_writer_)) << "the node's sim_control reader did not match";
    towsim_msgs_msg_dds__SimControl_ m{};
    m.header.frame_id = const_cast<char*>("");
    m.command = command;
    m.steps = steps;
    m.rate = rate;
    ASSERT_EQ(dds_write(control_writer_, &m), 0);
  }

  void Command(const std::string& body, uint64_t step, double thrust, double rudder,
               double elevator) {
    dds_entity_t& w = command_writers_[body];
    if (w == 0) {
      w = CommandWriter(&towsim_msgs_msg_dds__ActuatorCommand__desc, body + "/command");
    }
    ASSERT_TRUE(Matched(w)) << "the node's command reader of " << body << " did not match";
    towsim_msgs_msg_dds__ActuatorCommand_ m{};
    m.header.frame_id = const_cast<char*>(body.c_str());
    m.step = step;
    m.thrust = thrust;
    m.rudder = rudder;
    m.elevator = elevator;
    ASSERT_EQ(dds_write(w, &m), 0);
  }

  // a raw WinchCommand on rt/<ns>/winch/command (mode: towsim_msgs WinchCommand SPEED / LENGTH
  // or any other number)
  void WinchCommand(uint64_t step, uint8_t mode, double value) {
    if (winch_writer_ == 0) {
      winch_writer_ = CommandWriter(&towsim_msgs_msg_dds__WinchCommand__desc, "winch/command");
    }
    ASSERT_TRUE(Matched(winch_writer_)) << "the node's winch command reader did not match";
    towsim_msgs_msg_dds__WinchCommand_ m{};
    m.header.frame_id = const_cast<char*>("");
    m.step = step;
    m.mode = mode;
    m.value = value;
    ASSERT_EQ(dds_write(winch_writer_, &m), 0);
  }

  dds_entity_t participant() const { return participant_; }
  const std::string& prefix() const { return prefix_; }

 private:
  // a writer of commands (reliable, depth 1, as a controller's) on rt/<ns>/<name>
  dds_entity_t CommandWriter(const dds_topic_descriptor_t* type, const std::string& name) {
    dds_qos_t* qos = ReliableQos(1);
    const dds_entity_t t =
        dds_create_topic(participant_, type, (prefix_ + name).c_str(), nullptr, nullptr);
    const dds_entity_t w = dds_create_writer(participant_, t, qos, nullptr);
    dds_delete_qos(qos);
    return w;
  }

  static bool Matched(dds_entity_t writer) {
    const Clock::time_point start = Clock::now();
    for (;;) {
      dds_publication_matched_status_t m{};
      dds_get_publication_matched_status(writer, &m);
      if (m.current_count > 0) return true;
      if (Seconds(Clock::now() - start) > kObserverTimeout) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }

  void Poll() {
    void* samples[64] = {};
    dds_sample_info_t infos[64];
    for (;;) {
      const dds_return_t n = dds_take(status_reader_, samples, infos, 64, 64);
      if (n <= 0) return;
      for (int i = 0; i < n; ++i) {
        if (!infos[i].valid_data) continue;
        const auto* m = static_cast<const towsim_msgs_msg_dds__SimStatus_*>(samples[i]);
        Status s;
        s.run_id = m->run_id;
        s.mode = m->mode;
        s.message = m->message;
        s.state = m->state;
        s.health = m->health;
        s.step = m->step;
        s.sim_time = m->sim_time;
        s.rate = m->rate;
        for (uint32_t k = 0; k < m->failsafe_bodies._length; ++k) {
          s.failsafe_bodies.push_back(m->failsafe_bodies._buffer[k]);
        }
        s.failsafe_count = m->failsafe_count;
        s.received = m->commands_received;
        s.rejected = m->commands_rejected;
        s.clamped = m->commands_clamped;
        s.lockstep_timeouts = m->lockstep_timeouts;
        s.when = Clock::now();
        statuses_.push_back(s);
      }
      dds_return_loan(status_reader_, samples, n);
      if (n < 64) return;
    }
  }

  std::string prefix_;
  dds_entity_t participant_ = 0, status_reader_ = 0, control_writer_ = 0;
  std::map<std::string, dds_entity_t> command_writers_;
  dds_entity_t winch_writer_ = 0;
  std::vector<Status> statuses_;
};

}  // namespace towsim::testing
