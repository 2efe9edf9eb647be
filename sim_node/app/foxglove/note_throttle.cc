#include "app/foxglove/note_throttle.h"

#include <cstdio>
#include <utility>

namespace towsim::app::foxglove {

NoteThrottle::NoteThrottle(std::string program, std::string what, int in_full, double interval)
    : program_(std::move(program)),
      what_(std::move(what)),
      in_full_(in_full),
      interval_(interval) {}

std::optional<std::string> NoteThrottle::Event(double now, const std::string& note) {
  ++events_;
  if (events_ <= static_cast<uint64_t>(in_full_)) {
    std::string line = program_ + ": " + note;
    if (events_ == static_cast<uint64_t>(in_full_)) {
      line +=
          " (further ones: a count every " + std::to_string(static_cast<int>(interval_)) + " s)";
    }
    return line;
  }
  if (unprinted_ == 0) interval_start_ = now;  // an interval starts with its first event
  ++unprinted_;
  last_ = note;
  return Flush(now);
}

std::optional<std::string> NoteThrottle::Flush(double now, bool all) {
  if (unprinted_ == 0 || !interval_start_ || (!all && now - *interval_start_ < interval_)) {
    return std::nullopt;
  }
  char head[160];
  std::snprintf(head, sizeof head,
                "%s: %llu more %s in the last %.0f s (%llu in all; the last: ", program_.c_str(),
                static_cast<unsigned long long>(unprinted_), what_.c_str(), now - *interval_start_,
                static_cast<unsigned long long>(events_));
  unprinted_ = 0;
  interval_start_ = now;
  return std::string(head) + last_ + ")";
}

}  // namespace towsim::app::foxglove
