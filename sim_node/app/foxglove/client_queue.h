#pragma once
// What a Foxglove server holds for one client, and the one bound on it (docs/foxglove.md,
// "Bounds"; docs/faults.md). Policy only: no sockets, no clocks (times are passed in [s]);
// tests/unit/foxglove_client_queue_test.cc.
//
// Every frame for a client (data, time, serverInfo, advertisements, status replies, pongs)
// goes through its queue and costs its size plus kFrameOverhead bytes (the queue entry and the
// WebSocket library's message around it). What the client holds is
//   queued() = waiting (in this queue) + handed (given to the library, not yet taken by its
//              writer) + writing (the batch its writer took last, perhaps still being written)
// and queued() <= Limits::bound at all times:
//  - a data frame (also the latched message a new subscription gets) is dropped and counted
//    when it would take queued() past bound - reserve;
//  - a time frame replaces the time frame waiting, if there is one (the older time is dropped
//    and counted: only the newest time matters), and may take the reserve;
//  - a status reply or a pong spends a token of the client's reply budget (replies_per_second,
//    at most reply_burst saved up); without one, or without room, it is suppressed and counted;
//  - serverInfo and an advertisement must fit; if one does not, the client is to be closed.
// A client is over the bound from the first frame refused for room until queued() falls below
// half the bound; one that stays over it for close_after seconds is to be closed (ShouldClose,
// CloseReason): it reads nothing, or too little to ever catch up (a reconnection starts it
// afresh on the live data). That its writer took a batch is no sign of reading: the kernel's
// send buffer of the socket grows (up to net.ipv4.tcp_wmem's maximum) while nothing is read.
//
// The library (websocketpp) writes in batches: its writer takes every frame handed to it so
// far once the previous write has completed. HandOver gives frames to the library while what
// it gave and the writer has not yet taken stays within `window` (at least one frame); the
// library's buffered amount (the payload bytes handed and not yet taken, 0 once the writer took
// them) tells when the writer took them, and so that the batch before them was written.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>

namespace towsim::app::foxglove {

// the bounds of a ClientQueue (docs/foxglove.md, "Bounds")
struct QueueLimits {
  std::size_t bound = 8u << 20;      // [bytes] everything queued for the client
  std::size_t reserve = 64u << 10;   // [bytes] of `bound` that data may not take
  std::size_t window = 256u << 10;   // [bytes] handed to the library and not yet taken
  double close_after = 10.0;         // [s] over the bound this long: closed
  double replies_per_second = 10.0;  // status replies and pongs, sustained
  double reply_burst = 20.0;         // ... saved up at most
};

class ClientQueue {
 public:
  // [bytes] counted for each frame beyond its size: our entry (a std::string and its kind) and
  // websocketpp's message (header, payload and extension strings, shared_ptr, queue slot)
  static constexpr std::size_t kFrameOverhead = 256;

  enum class Kind {
    kData,     // Message Data (binary)
    kTime,     // Time (binary)
    kControl,  // serverInfo, advertise (text)
    kReply,    // status replies (text)
    kPong,     // the answer to a ping (its payload)
  };

  using Limits = QueueLimits;

  enum class Result {
    kQueued,      // (a time frame: also when it replaced the one waiting)
    kDropped,     // data without room: dropped, counted
    kSuppressed,  // a reply or pong without a token or room: not sent, counted
    kNoRoom,      // control without room: the client is to be closed
  };

  struct Counts {
    uint64_t data_dropped = 0;        // data frames refused for room
    uint64_t time_dropped = 0;        // time frames replaced by a newer one (or without room)
    uint64_t replies_suppressed = 0;  // replies and pongs beyond the budget or without room
  };

  struct Frame {
    Kind kind = Kind::kData;
    std::string bytes;
  };

  explicit ClientQueue(Limits limits = Limits());

  // true if a data frame of `size` bytes fits; if not, it is counted as dropped (and the client
  // is over the bound from `now`). Check before building the frame.
  bool AdmitData(std::size_t size, double now);
  // queues `bytes` of `kind` (data: AdmitData first)
  Result Offer(Kind kind, std::string bytes, double now);

  // hands waiting frames to the library, oldest first, each through send(const Frame&);
  // `buffered` is the library's buffered amount for this client now
  template <typename Send>
  void HandOver(std::size_t buffered, Send&& send);

  // the client stayed over the bound for close_after seconds, or control did not fit
  bool ShouldClose(double now) const;
  std::string CloseReason(double now) const;  // at most 123 bytes (a WebSocket close reason)
  // the client is being closed: nothing waiting is sent any more; returns the data frames
  // that were waiting
  uint64_t Clear();
  // over the bound (since the first frame refused for room, until queued() falls below half
  // the bound)
  bool over() const { return over_since_.has_value(); }

  std::size_t queued() const { return waiting_ + handed_ + writing_; }
  std::size_t waiting_frames() const { return frames_.size(); }
  const Counts& counts() const { return counts_; }
  const Limits& limits() const { return limits_; }

  static std::size_t Cost(std::size_t size) { return size + kFrameOverhead; }

 private:
  void Over(double now);
  bool TakeReplyToken(double now);
  void Push(Kind kind, std::string bytes);
  // the writer took what was handed (buffered == 0 after frames with payload were handed)
  void Taken(std::size_t buffered);

  Limits limits_;
  std::deque<Frame> frames_;                            // waiting
  std::size_t waiting_ = 0, handed_ = 0, writing_ = 0;  // [bytes] as Cost() counts them
  std::size_t handed_payload_ = 0;   // payload bytes handed since the writer last took them
  uint64_t popped_ = 0;              // frames handed over so far
  std::optional<uint64_t> time_at_;  // the waiting time frame, as popped_ + its position
  std::optional<double> over_since_;
  bool close_now_ = false;  // control did not fit
  double tokens_;
  std::optional<double> tokens_at_;
  Counts counts_;
};

template <typename Send>
void ClientQueue::HandOver(std::size_t buffered, Send&& send) {
  Taken(buffered);
  while (!frames_.empty()) {
    const std::size_t cost = Cost(frames_.front().bytes.size());
    if (handed_ > 0 && handed_ + cost > limits_.window) break;
    send(static_cast<const Frame&>(frames_.front()));
    handed_ += cost;
    handed_payload_ += frames_.front().bytes.size();
    waiting_ -= cost;
    frames_.pop_front();
    ++popped_;
  }
  if (over_since_ && queued() < limits_.bound / 2) {
    over_since_.reset();
  }
}

}  // namespace towsim::app::foxglove
