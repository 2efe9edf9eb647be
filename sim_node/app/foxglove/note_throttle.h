#pragma once
// The stderr notes of a server under a flood (docs/faults.md): the first `in_full` events each
// get a line of their own, later ones a count per `interval` seconds,
//   towsim_foxglove: 5234 more Foxglove client messages refused in the last 10 s (5244 in all;
//   the last: client 127.0.0.1:40312: unsupported operation "x")
// so that a client sending a bad frame as fast as it can costs a line every 10 s, not one per
// frame. Policy only (times passed in [s]); tests/unit/foxglove_client_queue_test.cc.

#include <cstdint>
#include <optional>
#include <string>

namespace towsim::app::foxglove {

class NoteThrottle {
 public:
  // `program` and `what` name the lines: "<program>: <n> more <what> in the last ..."
  NoteThrottle(std::string program, std::string what, int in_full = 10, double interval = 10.0);

  // an event at `now` with its note; returns the line to print now, if any
  std::optional<std::string> Event(double now, const std::string& note);
  // the count line of an interval that has ended with events not printed, if any (call it now
  // and then: a flood that stops still gets its count); `all`: also of the running interval
  // (at the end)
  std::optional<std::string> Flush(double now, bool all = false);

  uint64_t events() const { return events_; }

 private:
  std::string program_, what_;
  int in_full_;
  double interval_;
  uint64_t events_ = 0;
  uint64_t unprinted_ = 0;  // events since the last line
  std::optional<double> interval_start_;
  std::string last_;
};

}  // namespace towsim::app::foxglove
