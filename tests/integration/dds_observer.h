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

#include "dds/dds.h"
#include "towsim_msgs.h"
#include "wire/decoders.h"
#include "wire/qos.h"
#include "wire/topic_names.h"

namespace towsim::testing {

// how long the observer waits for a status or a match [s]
inline constexpr double kObserverTimeout = 20.0;

// a status as wire/decoders.h decodes it, and when it came
struct Status : wire::SimStatus {
  std::chrono::steady_clock::time_point when;
};

// this test as a DDS participant: the node's status, control requests and raw commands
class Observer {
  using Clock = std::chrono::steady_clock;
  static double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

 public:
  Observer(int domain, const std::string& ns = "/towsim") : names_(ns) {
    participant_ = dds_create_participant(static_cast<dds_domainid_t>(domain), nullptr, nullptr);
    EXPECT_GT(participant_, 0) << dds_strretcode(participant_);
    // the status and control requests with a deep history: none is lost
    dds_qos_t* qos = wire::ProfileQos(wire::QosProfile::kState, 1000);
    status_reader_ = dds_create_reader(participant_, Topic(wire::Topic::kStatus, ""), qos, nullptr);
    control_writer_ =
        dds_create_writer(participant_, Topic(wire::Topic::kSimControl, ""), qos, nullptr);
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
      w = CommandWriter(wire::Topic::kCommand, body);
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
      winch_writer_ = CommandWriter(wire::Topic::kWinchCommand, "");
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
  const wire::TopicNames& names() const { return names_; }

  // a reader of `topic` of `owner` (wire/topic_names.h) that keeps `depth` samples
  dds_entity_t Reader(wire::Topic topic, const std::string& owner, int depth) {
    dds_qos_t* qos = wire::ProfileQos(wire::SpecOf(topic).qos, depth);
    const dds_entity_t r = dds_create_reader(participant_, Topic(topic, owner), qos, nullptr);
    dds_delete_qos(qos);
    return r;
  }

 private:
  // the topic `topic` of `owner` (wire/topic_names.h)
  dds_entity_t Topic(wire::Topic topic, const std::string& owner) {
    return dds_create_topic(participant_, wire::SpecOf(topic).type,
                            names_.Name(topic, owner).c_str(), nullptr, nullptr);
  }

  // a writer of commands (the QoS of the row, as a controller's) on `topic` of `owner`
  dds_entity_t CommandWriter(wire::Topic topic, const std::string& owner) {
    dds_qos_t* qos = wire::ProfileQos(wire::SpecOf(topic).qos);
    const dds_entity_t w = dds_create_writer(participant_, Topic(topic, owner), qos, nullptr);
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
        Status s;
        static_cast<wire::SimStatus&>(s) =
            wire::DecodeStatus(*static_cast<const towsim_msgs_msg_dds__SimStatus_*>(samples[i]));
        s.when = Clock::now();
        statuses_.push_back(std::move(s));
      }
      dds_return_loan(status_reader_, samples, n);
      if (n < 64) return;
    }
  }

  wire::TopicNames names_;
  dds_entity_t participant_ = 0, status_reader_ = 0, control_writer_ = 0;
  std::map<std::string, dds_entity_t> command_writers_;
  dds_entity_t winch_writer_ = 0;
  std::vector<Status> statuses_;
};

}  // namespace towsim::testing
