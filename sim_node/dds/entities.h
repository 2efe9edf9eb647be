#pragma once
// RAII wrappers for the Cyclone DDS C API: each class owns one dds_entity_t and deletes it
// (and so its children) when it goes away. Creation failures throw DdsError with the call
// that failed and Cyclone's return-code text; Cyclone itself logs the details (bad config
// file, port range of a domain id, ...) on stderr.
//
//   Participant p(/*domain=*/41, /*config=*/"");          // config "": $CYCLONEDDS_URI
//   Topic t(p, &nav_msgs_msg_dds__Odometry__desc, "rt/towsim/towfish/odom");
//   Writer<nav_msgs_msg_dds__Odometry_> w(p, t, StateQos());
//   if (w.matched()) w.Write(msg);   // build and serialize only for a subscriber

#include <atomic>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "dds/dds.h"
#include "dds/qos.h"
#include "wire/security.h"

namespace towsim::dds {

class DdsError : public std::runtime_error {
 public:
  // what() = "<action>: <Cyclone's text for code>"
  DdsError(const std::string& action, dds_return_t code);
  dds_return_t code() const { return code_; }

 private:
  dds_return_t code_;
};

// Owns a handle; move-only. Deleting an entity deletes its children too; deleting a child
// whose parent is already gone is harmless (Cyclone returns an error, ignored).
class Entity {
 public:
  Entity() = default;
  explicit Entity(dds_entity_t handle) : handle_(handle) {}
  ~Entity() { Reset(); }
  Entity(Entity&& other) noexcept : handle_(std::exchange(other.handle_, 0)) {}
  Entity& operator=(Entity&& other) noexcept {
    if (this != &other) {
      Reset();
      handle_ = std::exchange(other.handle_, 0);
    }
    return *this;
  }
  Entity(const Entity&) = delete;
  Entity& operator=(const Entity&) = delete;

  dds_entity_t get() const { return handle_; }
  bool valid() const { return handle_ > 0; }
  void Reset();

 private:
  dds_entity_t handle_ = 0;
};

// A domain participant. With a non-empty `config` (what CYCLONEDDS_URI would hold: a
// file:// URI or XML), the domain is created from it explicitly; otherwise Cyclone reads
// $CYCLONEDDS_URI. Its USER_DATA is "enclave=/;" (a ROS 2 participant, wire/ros_graph.h). With a
// non-empty `security` (--security DIR/NAME, wire/security.h) the participant runs DDS Security
// with that identity. Throws DdsError (e.g. a domain id whose ports are out of range, an unreadable
// config file) or wire::SecurityError (wire/security.h: a missing file, or the plugins refused the
// identity, with Cyclone's reason).
class Participant {
 public:
  Participant(uint32_t domain_id, const std::string& config, const std::string& security = "",
              wire::Admit admit = wire::Admit::kAuthenticated);
  dds_entity_t get() const { return participant_.get(); }
  uint32_t domain_id() const { return domain_id_; }

 private:
  uint32_t domain_id_;
  Entity domain_;  // explicit domain (config given); destroyed after the participant
  Entity participant_;
};

class Topic {
 public:
  Topic(const Participant& participant, const dds_topic_descriptor_t* descriptor,
        const std::string& name);
  dds_entity_t get() const { return topic_.get(); }
  const std::string& name() const { return name_; }

 private:
  Entity topic_;
  std::string name_;
};

// the number of readers matched with a writer, kept by Cyclone's publication-matched listener
// (called on its discovery thread) so that asking costs one atomic load, not an entity lock:
// the node asks every writer every step (docs/benchmarks.md, "Lockstep at the speed of the
// wire")
class MatchCount {
 public:
  // a listener for dds_create_writer (the caller deletes it after the call); it writes to
  // this object, which must outlive the writer
  dds_listener_t* NewListener();
  int current() const { return current_.load(std::memory_order_relaxed); }

 private:
  static void OnMatched(dds_entity_t writer, const dds_publication_matched_status_t status,
                        void* self);
  std::atomic<int> current_{0};
};

// a writer of samples of the generated C type T (void: of the topic's type, given as a
// pointer to its C struct, WriteRaw)
template <class T>
class Writer {
 public:
  Writer(const Participant& participant, const Topic& topic, const Qos& qos)
      : topic_name_(topic.name()), match_(std::make_unique<MatchCount>()) {
    dds_listener_t* listener = match_->NewListener();
    const dds_entity_t w = dds_create_writer(participant.get(), topic.get(), qos.get(), listener);
    dds_delete_listener(listener);
    if (w < 0) throw DdsError("creating a writer for " + topic_name_, w);
    writer_ = Entity(w);
  }
  Writer(Writer&&) = default;
  // (no move assignment: it would free the listener's count before deleting the old writer)
  Writer& operator=(Writer&&) = delete;

  // at least one reader matched: worth building and serializing a sample
  bool matched() const { return match_->current() > 0; }
  int matched_count() const {
    dds_publication_matched_status_t status{};
    if (dds_get_publication_matched_status(writer_.get(), &status) < 0) return 0;
    return static_cast<int>(status.current_count);
  }

  // throws DdsError if Cyclone refuses the sample
  template <class U = T>
  void Write(const U& sample) {
    static_assert(std::is_same_v<U, T>, "a sample of the writer's type");
    WriteRaw(&sample);
  }
  // `sample` points to a C struct of the topic's type; throws DdsError
  void WriteRaw(const void* sample) {
    const dds_return_t rc = dds_write(writer_.get(), sample);
    if (rc < 0) throw DdsError("writing to " + topic_name_, rc);
  }

  dds_entity_t get() const { return writer_.get(); }
  const std::string& topic_name() const { return topic_name_; }

 private:
  std::string topic_name_;
  std::unique_ptr<MatchCount> match_;  // on the heap: the listener keeps its address
  Entity writer_;                      // deleted first (members in reverse order)
};

// a reader of samples of the generated C type T, with a read condition (unread samples) to
// attach to a WaitSet
template <class T>
class Reader {
 public:
  Reader(const Participant& participant, const Topic& topic, const Qos& qos)
      : topic_name_(topic.name()) {
    const dds_entity_t r = dds_create_reader(participant.get(), topic.get(), qos.get(), nullptr);
    if (r < 0) throw DdsError("creating a reader for " + topic_name_, r);
    reader_ = Entity(r);
    const dds_entity_t c = dds_create_readcondition(r, DDS_NOT_READ_SAMPLE_STATE);
    if (c < 0) throw DdsError("creating a read condition for " + topic_name_, c);
    condition_ = Entity(c);
  }

  // Takes every available sample, oldest first, and calls f(sample, info) for each one with
  // valid data (loaned memory: valid during the call only). Returns the number passed to f.
  template <class F>
  int TakeEach(F&& f) {
    constexpr int kBatch = 16;
    int delivered = 0;
    for (;;) {
      void* samples[kBatch] = {};
      dds_sample_info_t infos[kBatch];
      const dds_return_t n = dds_take(reader_.get(), samples, infos, kBatch, kBatch);
      if (n <= 0) break;
      for (int i = 0; i < n; ++i) {
        if (!infos[i].valid_data) continue;
        f(*static_cast<const T*>(samples[i]), infos[i]);
        ++delivered;
      }
      dds_return_loan(reader_.get(), samples, n);
      if (n < kBatch) break;
    }
    return delivered;
  }

  // the number of matched writers
  int matched_count() const {
    dds_subscription_matched_status_t status{};
    if (dds_get_subscription_matched_status(reader_.get(), &status) < 0) return 0;
    return static_cast<int>(status.current_count);
  }

  dds_entity_t get() const { return reader_.get(); }
  dds_entity_t condition() const { return condition_.get(); }
  const std::string& topic_name() const { return topic_name_; }

 private:
  std::string topic_name_;
  Entity reader_;
  Entity condition_;  // deleted before the reader (members in reverse order)
};

class WaitSet {
 public:
  explicit WaitSet(const Participant& participant);
  // wake Wait() when `condition` triggers (a Reader's condition())
  void Attach(dds_entity_t condition);
  // blocks until a condition triggers or `timeout` [ns] elapses; returns the number of
  // triggered conditions (0: timeout)
  int Wait(int64_t timeout_ns);

 private:
  Entity waitset_;
};

}  // namespace towsim::dds
