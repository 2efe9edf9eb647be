#include "app/foxglove/client_queue.h"

#include <algorithm>
#include <cstdio>
#include <utility>

namespace towsim::app::foxglove {

ClientQueue::ClientQueue(Limits limits) : limits_(limits), tokens_(limits.reply_burst) {}

void ClientQueue::Over(double now) {
  if (!over_since_) over_since_ = now;
}

bool ClientQueue::AdmitData(std::size_t size, double now) {
  if (queued() + Cost(size) + limits_.reserve <= limits_.bound) return true;
  ++counts_.data_dropped;
  Over(now);
  return false;
}

bool ClientQueue::TakeReplyToken(double now) {
  // a token bucket: replies_per_second tokens a second, at most reply_burst saved up
  if (tokens_at_) {
    tokens_ = std::min(limits_.reply_burst,
                       tokens_ + std::max(0.0, now - *tokens_at_) * limits_.replies_per_second);
  }
  tokens_at_ = now;
  if (tokens_ < 1.0) return false;
  tokens_ -= 1.0;
  return true;
}

void ClientQueue::Push(Kind kind, std::string bytes) {
  waiting_ += Cost(bytes.size());
  frames_.push_back(Frame{kind, std::move(bytes)});
}

ClientQueue::Result ClientQueue::Offer(Kind kind, std::string bytes, double now) {
  const std::size_t cost = Cost(bytes.size());
  const bool fits = queued() + cost <= limits_.bound;
  switch (kind) {
    case Kind::kData:
      if (queued() + cost + limits_.reserve > limits_.bound) {
        ++counts_.data_dropped;
        Over(now);
        return Result::kDropped;
      }
      break;
    case Kind::kTime:
      if (time_at_ && *time_at_ >= popped_) {  // one waits: the newest time replaces it
        std::string& waiting = frames_[static_cast<std::size_t>(*time_at_ - popped_)].bytes;
        waiting_ = waiting_ - Cost(waiting.size()) + cost;
        waiting = std::move(bytes);
        ++counts_.time_dropped;
        return Result::kQueued;
      }
      if (!fits) {  // only when data filled the reserve's complement and replies the reserve
        ++counts_.time_dropped;
        Over(now);
        return Result::kDropped;
      }
      time_at_ = popped_ + frames_.size();
      break;
    case Kind::kReply:
    case Kind::kPong:
      if (!fits) {
        ++counts_.replies_suppressed;
        Over(now);
        return Result::kSuppressed;
      }
      if (!TakeReplyToken(now)) {
        ++counts_.replies_suppressed;
        return Result::kSuppressed;
      }
      break;
    case Kind::kControl:
      if (!fits) {
        close_now_ = true;
        Over(now);
        return Result::kNoRoom;
      }
      break;
  }
  Push(kind, std::move(bytes));
  return Result::kQueued;
}

void ClientQueue::Taken(std::size_t buffered) {
  if (buffered != 0 || handed_payload_ == 0) return;
  // the writer took every frame handed; it takes only after its previous write completed
  writing_ = handed_;
  handed_ = 0;
  handed_payload_ = 0;
}

bool ClientQueue::ShouldClose(double now) const {
  return close_now_ || (over_since_ && now - *over_since_ >= limits_.close_after);
}

std::string ClientQueue::CloseReason(double now) const {
  char text[124];
  const double mib = static_cast<double>(limits_.bound) / (1u << 20);
  if (close_now_) {
    std::snprintf(text, sizeof text, "an advertisement did not fit the send queue (%g MiB)", mib);
  } else {
    std::snprintf(text, sizeof text,
                  "send queue at its bound (%g MiB) for %.0f s: the client reads nothing", mib,
                  over_since_ ? now - *over_since_ : 0.0);
  }
  return text;
}

uint64_t ClientQueue::Clear() {
  uint64_t data = 0;
  for (const Frame& f : frames_) data += f.kind == Kind::kData ? 1 : 0;
  frames_.clear();
  waiting_ = 0;
  time_at_.reset();
  return data;
}

}  // namespace towsim::app::foxglove
