// sim_node/app/foxglove/client_queue and note_throttle: the one bound on what a Foxglove server
// holds for a client and the policy at it (docs/foxglove.md "Bounds"), and the throttled notes
// of a flood. The "library" here is a model of websocketpp's send queue: its buffered amount
// is the payload handed and not yet taken by its writer; a stalled client's writer never takes.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/foxglove/client_queue.h"
#include "app/foxglove/note_throttle.h"

namespace towsim::app::foxglove {
namespace {

using Kind = ClientQueue::Kind;
using Result = ClientQueue::Result;

// websocketpp's send queue as HandOver sees it: payload bytes handed and not yet taken
struct Library {
  std::size_t buffered = 0;
  std::vector<ClientQueue::Frame> sent;
  void Hand(ClientQueue* q) {
    q->HandOver(buffered, [this](const ClientQueue::Frame& f) {
      buffered += f.bytes.size();
      sent.push_back(f);
    });
  }
  void WriterTakes() { buffered = 0; }
};

QueueLimits Small() {
  QueueLimits l;
  l.bound = 64 * 1024;
  l.reserve = 4 * 1024;
  l.window = 8 * 1024;
  l.close_after = 10.0;
  l.replies_per_second = 10.0;
  l.reply_burst = 20.0;
  return l;
}

std::string Bytes(std::size_t n, char c = 'd') { return std::string(n, c); }

TEST(FoxgloveClientQueue, AStalledClientHoldsAtMostTheBoundWhateverIsOffered) {
  // every kind of frame, random sizes and order, for a client whose writer took the first
  // batch and then nothing (it stopped reading): queued() never exceeds the bound, and what
  // the library was handed never exceeds two windows plus two frames
  const QueueLimits l = Small();
  ClientQueue q(l);
  Library lib;
  std::mt19937 rng(29);
  std::uniform_int_distribution<int> kind(0, 9), size(1, 3000);
  std::size_t handed_bytes = 0, max_queued = 0;
  double t = 0.0;
  for (int i = 0; i < 20000; ++i) {
    t += 1e-3;
    const int k = kind(rng);
    if (k < 6) {
      const std::size_t n = static_cast<std::size_t>(size(rng));
      if (q.AdmitData(n, t)) {
        EXPECT_EQ(q.Offer(Kind::kData, Bytes(n), t), Result::kQueued);
      }
    } else if (k < 8) {
      q.Offer(Kind::kTime, Bytes(9, 't'), t);
    } else if (k < 9) {
      q.Offer(Kind::kReply, Bytes(200, 'r'), t);
    } else {
      q.Offer(Kind::kPong, Bytes(static_cast<std::size_t>(size(rng)) % 126, 'p'), t);
    }
    lib.Hand(&q);
    if (i == 10) lib.WriterTakes();  // the first batch went into the socket; then nothing
    max_queued = std::max(max_queued, q.queued());
    ASSERT_LE(q.queued(), l.bound) << "after frame " << i;
  }
  for (const auto& f : lib.sent) handed_bytes += ClientQueue::Cost(f.bytes.size());
  EXPECT_LE(handed_bytes, 2 * (l.window + ClientQueue::Cost(3000)));
  EXPECT_GT(max_queued, l.bound - l.reserve - ClientQueue::Cost(3000));  // it did fill
  EXPECT_GT(q.counts().data_dropped, 0u);
  EXPECT_LE(q.waiting_frames(), l.bound / ClientQueue::kFrameOverhead);
}

TEST(FoxgloveClientQueue, DataIsDroppedAtTheBoundLessTheReserveAndCounted) {
  const QueueLimits l = Small();
  ClientQueue q(l);
  const std::size_t n = 1000, cost = ClientQueue::Cost(n);
  const std::size_t fit = (l.bound - l.reserve) / cost;  // data frames that fit (nothing handed)
  for (std::size_t i = 0; i < fit; ++i) {
    ASSERT_TRUE(q.AdmitData(n, 0.0)) << i;
    q.Offer(Kind::kData, Bytes(n), 0.0);
  }
  EXPECT_FALSE(q.AdmitData(n, 0.0));
  EXPECT_EQ(q.Offer(Kind::kData, Bytes(n), 0.0), Result::kDropped);
  EXPECT_EQ(q.counts().data_dropped, 2u);
  EXPECT_EQ(q.queued(), fit * cost);
  EXPECT_TRUE(q.over());
  // the reserve still takes a time frame and replies
  EXPECT_EQ(q.Offer(Kind::kTime, Bytes(9, 't'), 0.0), Result::kQueued);
  EXPECT_EQ(q.Offer(Kind::kReply, Bytes(100, 'r'), 0.0), Result::kQueued);
}

TEST(FoxgloveClientQueue, OnlyTheNewestTimeFrameWaits) {
  ClientQueue q(Small());
  Library lib;
  q.Offer(Kind::kData, Bytes(100), 0.0);
  q.Offer(Kind::kTime, "time 1", 0.0);
  q.Offer(Kind::kData, Bytes(100), 0.0);
  for (int i = 2; i <= 1000; ++i) q.Offer(Kind::kTime, "time " + std::to_string(i), 0.0);
  EXPECT_EQ(q.waiting_frames(), 3u);
  EXPECT_EQ(q.counts().time_dropped, 999u);
  lib.Hand(&q);
  ASSERT_EQ(lib.sent.size(), 3u);
  EXPECT_EQ(lib.sent[1].kind, Kind::kTime);
  EXPECT_EQ(lib.sent[1].bytes, "time 1000");  // the oldest were dropped, the newest sent
  // once handed, the next time frame waits on its own again
  q.Offer(Kind::kTime, "time 1001", 0.0);
  q.Offer(Kind::kTime, "time 1002", 0.0);
  EXPECT_EQ(q.waiting_frames(), 1u);
  EXPECT_EQ(q.counts().time_dropped, 1000u);
}

TEST(FoxgloveClientQueue, RepliesAndPongsAreRateLimited) {
  // a token bucket of 10 a second with 20 saved up: a flood of 1000 replies in 10 s gets
  // 20 + 10 x 10 = 120 through (to one token: the refill of the last step may or may not count)
  ClientQueue q(Small());
  Library lib;
  int queued = 0;
  for (int i = 0; i < 1000; ++i) {
    const double t = i * 0.01;
    if (q.Offer(i % 2 ? Kind::kReply : Kind::kPong, Bytes(50, 'r'), t) == Result::kQueued) {
      ++queued;
    }
    lib.Hand(&q);
    lib.WriterTakes();  // a client that reads: the bound is not what limits
  }
  EXPECT_NEAR(queued, 20 + 10 * 10, 1);
  EXPECT_EQ(q.counts().replies_suppressed, static_cast<uint64_t>(1000 - queued));
}

TEST(FoxgloveClientQueue, HandOverKeepsTheLibraryWithinAWindow) {
  const QueueLimits l = Small();
  ClientQueue q(l);
  Library lib;
  const std::size_t n = 1000, cost = ClientQueue::Cost(n);
  for (int i = 0; i < 40; ++i) q.Offer(Kind::kData, Bytes(n), 0.0);
  lib.Hand(&q);
  const std::size_t per_window = l.window / cost;
  EXPECT_EQ(lib.sent.size(), per_window);
  lib.Hand(&q);  // not taken yet: nothing more
  EXPECT_EQ(lib.sent.size(), per_window);
  lib.WriterTakes();  // the writer took the batch (it is being written): one more window
  lib.Hand(&q);
  EXPECT_EQ(lib.sent.size(), 2 * per_window);
  EXPECT_EQ(q.queued(), 40 * cost);  // waiting + handed + the batch being written
  lib.WriterTakes();                 // it took the second: the first was written
  lib.Hand(&q);
  EXPECT_EQ(q.queued(), (40 - per_window) * cost);
  // a frame larger than the window goes on its own when nothing is handed
  ClientQueue big(l);
  Library lib2;
  big.Offer(Kind::kData, Bytes(3 * l.window), 0.0);
  big.Offer(Kind::kData, Bytes(10), 0.0);
  lib2.Hand(&big);
  EXPECT_EQ(lib2.sent.size(), 1u);
}

TEST(FoxgloveClientQueue, AClientOverTheBoundIsClosedAfterCloseAfterUnlessItCatchesUp) {
  const QueueLimits l = Small();
  const std::size_t n = 1000;
  auto fill = [&](ClientQueue* q, Library* lib, double t) {
    while (q->AdmitData(n, t)) q->Offer(Kind::kData, Bytes(n), t);
    lib->Hand(q);
  };
  {  // reads nothing: over from t = 1, closed at t = 11
    ClientQueue q(l);
    Library lib;
    lib.Hand(&q);
    fill(&q, &lib, 1.0);
    EXPECT_TRUE(q.over());
    EXPECT_FALSE(q.ShouldClose(10.9));
    fill(&q, &lib, 5.0);  // still over: since t = 1
    EXPECT_TRUE(q.ShouldClose(11.0));
    EXPECT_EQ(q.CloseReason(11.0),
              "send queue at its bound (0.0625 MiB) for 10 s: the client reads nothing");
    const std::size_t waiting = q.waiting_frames();  // data only
    EXPECT_EQ(q.Clear(), waiting);
    EXPECT_EQ(q.waiting_frames(), 0u);
  }
  {  // reads, but too little to get below half the bound: closed all the same
    ClientQueue q(l);
    Library lib;
    fill(&q, &lib, 1.0);
    for (double t = 1.0; t < 11.0; t += 1.0) {
      lib.WriterTakes();  // a batch a second
      fill(&q, &lib, t);
      EXPECT_TRUE(q.over());
    }
    EXPECT_TRUE(q.ShouldClose(11.0));
  }
  {  // catches up: below half the bound, no longer over
    ClientQueue q(l);
    Library lib;
    fill(&q, &lib, 1.0);
    while (q.queued() >= l.bound / 2) {
      lib.WriterTakes();
      lib.Hand(&q);
    }
    EXPECT_FALSE(q.over());
    EXPECT_FALSE(q.ShouldClose(30.0));
  }
  {  // an advertisement that does not fit: closed at once
    ClientQueue q(l);
    EXPECT_EQ(q.Offer(Kind::kControl, Bytes(l.bound), 0.0), Result::kNoRoom);
    EXPECT_TRUE(q.ShouldClose(0.0));
  }
}

TEST(FoxgloveNoteThrottle, TenInFullThenACountPerInterval) {
  NoteThrottle n("prog", "things refused", 10, 10.0);
  std::vector<std::string> lines;
  // 100 events a second for 35 s
  for (int i = 0; i < 3500; ++i) {
    const double t = i * 0.01;
    if (auto l = n.Event(t, "thing " + std::to_string(i))) lines.push_back(*l);
    if (auto l = n.Flush(t)) lines.push_back(*l);
  }
  ASSERT_EQ(lines.size(), 10u + 3u);  // 10 in full, then one line each 10 s after the 11th
  EXPECT_EQ(lines[0], "prog: thing 0");
  EXPECT_EQ(lines[9], "prog: thing 9 (further ones: a count every 10 s)");
  // every event is in a line or in the count of one
  uint64_t counted = 10;
  for (std::size_t i = 10; i < lines.size(); ++i) {
    unsigned long long more = 0, all = 0;
    ASSERT_EQ(std::sscanf(lines[i].c_str(), "prog: %llu more things refused in the last 10 s (%llu",
                          &more, &all),
              2)
        << lines[i];
    counted += more;
    EXPECT_EQ(all, counted) << lines[i];
  }
  // 100 a second: 1000 or 1001 a line (an interval may hold the events at both its ends)
  EXPECT_NEAR(static_cast<double>(counted), 10 + 3 * 1000, 3);
  // the rest at the end
  const auto last = n.Flush(35.0, true);
  ASSERT_TRUE(last.has_value());
  EXPECT_NE(last->find("(3500 in all; the last: thing 3499)"), std::string::npos) << *last;
  EXPECT_FALSE(n.Flush(36.0, true).has_value());
}

}  // namespace
}  // namespace towsim::app::foxglove
