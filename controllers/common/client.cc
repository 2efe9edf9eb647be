#include "common/client.h"

#include <signal.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "common/laws.h"
#include "dds/dds.h"
#include "nav_msgs.h"
#include "sensor_msgs.h"
#include "towsim_msgs.h"
#include "wire/qos.h"
#include "wire/ros_graph.h"
#include "wire/topic_names.h"

namespace towsim::controllers {
namespace {

using Clock = std::chrono::steady_clock;
std::atomic<bool> g_stop{false};

extern "C" void OnStopSignal(int) { g_stop.store(true); }

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

dds_entity_t Check(dds_entity_t e, const std::string& what) {
  if (e < 0) throw std::runtime_error(what + ": " + dds_strretcode(e));
  return e;
}

// the namespace of --namespace: "" is the root, "towsim" is /towsim
std::string RootedNamespace(const std::string& ns) {
  if (ns.empty()) return "/";
  return ns[0] == '/' ? ns : "/" + ns;
}

}  // namespace

std::string CableLogColumns(const CableSample& cable) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double top = cable.tension.empty() ? nan : cable.tension.front();
  const double end = cable.tension.empty() ? nan : cable.tension.back();
  char text[96];
  std::snprintf(text, sizeof text, " %.6f %.6f %.6f", cable.t, top, end);
  return text;
}

std::string RequireDdsUri() {
  const char* uri = std::getenv("CYCLONEDDS_URI");
  if (uri == nullptr || *uri == '\0') {
    throw std::runtime_error(
        "CYCLONEDDS_URI is not set: export "
        "CYCLONEDDS_URI=file://<towsim>/config/cyclonedds.xml, or for an installed towsim "
        "file://<prefix>/share/towsim/cyclonedds.xml (loopback DDS configuration)");
  }
  return uri;
}

void InstallStopHandlers() {
  struct sigaction sa {};
  sa.sa_handler = OnStopSignal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

bool StopRequested() { return g_stop.load(); }

namespace {
// a stop signal, or the caller's own stop flag
bool Stopping(const ClientOptions& o) { return StopRequested() || (o.stop && o.stop->load()); }
}  // namespace

// waits on `ws` (samples of its one reader) up to `budget` [s] from `begin`, at most 0.1 s at a
// time (a stop request ends it); no polling. False when the budget is spent.
static bool WaitForSamples(dds_entity_t ws, Clock::time_point begin, double budget) {
  const double left = budget - Seconds(Clock::now() - begin);
  if (!(left > 0.0)) return false;
  dds_waitset_wait(ws, nullptr, 0, static_cast<dds_duration_t>(1e9 * std::min(left, 0.1)));
  return true;
}

// a waitset on `reader`'s samples alone: a sample of another reader must not end its wait
static dds_entity_t WaitsetOf(dds_entity_t participant, dds_entity_t reader) {
  const dds_entity_t ws = Check(dds_create_waitset(participant), "waitset");
  const dds_entity_t c = Check(dds_create_readcondition(reader, DDS_ANY_STATE), "read condition");
  Check(dds_waitset_attach(ws, c, 0), "waitset attach");
  return ws;
}

// takes what `reader` has queued, up to 16 samples (a second call takes more), and calls
// fn(sample, its stamp [s]) for each valid one, oldest first
template <class Msg, class Fn>
void TakeQueued(dds_entity_t reader, Fn fn) {
  void* samples[16] = {};
  dds_sample_info_t infos[16];
  const dds_return_t k = dds_take(reader, samples, infos, 16, 16);
  for (int j = 0; j < k; ++j) {
    if (!infos[j].valid_data) continue;
    const auto* m = static_cast<const Msg*>(samples[j]);
    fn(*m, wire::StampSeconds(m->header.stamp));
  }
  if (k > 0) dds_return_loan(reader, samples, k);
}

// takes from `track` (OdomTrack, AltitudeTrack: Take(t), Has(t), its waitset) until it has the
// sample of the step at time t, or 0.5 s of wall time passed (then it keeps the latest)
template <class Track>
void WaitForStep(Track* track, double t, const ClientOptions& opt) {
  const Clock::time_point begin = Clock::now();
  for (;;) {
    track->Take(t);
    if (track->Has(t)) break;
    if (Stopping(opt) || !WaitForSamples(track->waitset, begin, 0.5)) break;
  }
}

// the newest odometry of one body taken from its reader
struct OdomTrack {
  dds_entity_t reader = 0;
  dds_entity_t waitset = 0;  // on `reader`
  wire::Odometry odom;
  bool have = false;
  double time = -1.0;
  // after a RESET (a new run id): the time of the new run's first status; odometry stamped
  // later is the old run's, still queued (the node publishes a step's odometry before its
  // status), and is dropped until a sample of the new run comes; < 0 otherwise
  double reset_time = -1.0;

  void NewRun(bool reset, double t) {
    time = -1.0;
    have = false;
    if (reset) reset_time = t;
  }

  void Take(double /*t*/) {
    TakeQueued<nav_msgs_msg_dds__Odometry_>(reader, [this](const auto& o, double t) {
      if (reset_time >= 0.0) {
        if (t > reset_time + 1e-9) return;  // the old run's
        reset_time = -1.0;
      }
      if (t >= time || !have) {  // a RESET goes back in time: see below
        odom = wire::DecodeOdometry(o);
        time = t;
        have = true;
      }
    });
  }

  bool Has(double t) const { return have && time >= t - 1e-9; }
  // takes until the odometry of time t came, or 0.5 s of wall time (then the latest)
  void WaitFor(double t, const ClientOptions& opt) { WaitForStep(this, t, opt); }
};

// the newest altimeter range (sensor_msgs/Range) stamped at most the step answered, taken from
// its reader (a RESET's old run has later stamps)
struct AltitudeTrack {
  dds_entity_t reader = 0;   // 0: not subscribed
  dds_entity_t waitset = 0;  // on `reader`
  float range = 0.0f;
  double time = -1.0;

  void NewRun() { time = -1.0; }

  void Take(double t) {
    TakeQueued<sensor_msgs_msg_dds__Range_>(reader, [this, t](const auto& r, double stamp) {
      if (stamp > t + 1e-9 || stamp < time) return;
      range = r.range;
      time = stamp;
    });
  }

  bool Has(double t) const { return time >= t - 1e-9; }
  // takes until the range of time t came, or 0.5 s of wall time
  void WaitFor(double t, const ClientOptions& opt) { WaitForStep(this, t, opt); }
};

struct LockstepClient::Impl {
  ClientOptions opt;
  dds_entity_t participant = 0;
  dds_entity_t status_reader = 0, command_writer = 0;
  dds_entity_t waitset = 0;
  dds_entity_t winch_writer = 0;              // 0: no winch commands
  dds_entity_t cable_reader = 0;              // 0: not subscribed
  std::unique_ptr<wire::RosGraphNode> graph;  // the ROS 2 node <ns>/<name>
  double step_size = 0.05;
  WinchInfo winch;
  OdomTrack own, observed;  // the commanded body's odometry, ClientOptions::observe's
  AltitudeTrack altitude;   // with ClientOptions::altitude

  // the newest cable state stamped at most t (a RESET's old run has later stamps)
  CableSample cable;
  void TakeCable(double t) {
    void* cs[4] = {};
    dds_sample_info_t ci[4];
    for (;;) {
      const dds_return_t k = dds_take(cable_reader, cs, ci, 4, 4);
      for (int j = 0; j < k; ++j) {
        if (!ci[j].valid_data) continue;
        const auto* c = static_cast<const towsim_msgs_msg_dds__CableState_*>(cs[j]);
        const double stamp = wire::StampSeconds(c->header.stamp);
        if (stamp > t + 1e-9 || stamp < cable.t) continue;
        cable = wire::DecodeCableState(*c);
      }
      if (k > 0) dds_return_loan(cable_reader, cs, k);
      if (k < 4) break;
    }
  }
};

LockstepClient::LockstepClient(const ClientOptions& options) : impl_(new Impl) {
  Impl& m = *impl_;
  m.opt = options;
  RequireDdsUri();
  if (options.body.empty()) throw std::runtime_error("no body to command (--body)");
  const wire::TopicNames names(RootedNamespace(options.ns));
  // a ROS 2 participant: USER_DATA enclave=/; (wire/ros_graph.h)
  dds_qos_t* participant_qos = wire::NewParticipantQos();
  try {
    if (options.security.empty()) {
      m.participant =
          Check(dds_create_participant(options.domain, participant_qos, nullptr),
                "creating the DDS participant (domain " + std::to_string(options.domain) + ")");
    } else {
      m.participant =
          wire::CreateSecureParticipant(options.domain, options.security, participant_qos);
    }
  } catch (...) {
    dds_delete_qos(participant_qos);
    throw;
  }
  dds_delete_qos(participant_qos);
  // the readers of the node's state keep a few samples (the step answered may not be the newest)
  dds_qos_t* state_qos = wire::ProfileQos(wire::QosProfile::kState, 16);
  dds_qos_t* cable_qos = wire::ProfileQos(wire::QosProfile::kState, 4);
  try {
    std::vector<dds_entity_t> readers, writers;
    // a reader or writer of `topic` (of `owner`, wire/topic_names.h), with the QoS of its row
    // (`qos`: a deeper reader history)
    auto endpoint = [&](bool writer, wire::Topic topic, const std::string& owner,
                        const dds_qos_t* qos = nullptr) {
      const wire::TopicSpec& spec = wire::SpecOf(topic);
      const std::string name = names.Name(topic, owner);
      const dds_entity_t t =
          Check(dds_create_topic(m.participant, spec.type, name.c_str(), nullptr, nullptr),
                name + " topic");
      dds_qos_t* own = qos == nullptr ? wire::ProfileQos(spec.qos) : nullptr;
      const dds_qos_t* q = qos == nullptr ? own : qos;
      const dds_entity_t e = writer ? dds_create_writer(m.participant, t, q, nullptr)
                                    : dds_create_reader(m.participant, t, q, nullptr);
      if (own != nullptr) dds_delete_qos(own);
      Check(e, name + (writer ? " writer" : " reader"));
      (writer ? writers : readers).push_back(e);
      return e;
    };
    const dds_entity_t scene_reader = endpoint(false, wire::Topic::kSceneInfo, "");
    m.status_reader = endpoint(false, wire::Topic::kStatus, "", state_qos);
    m.own.reader = endpoint(false, wire::Topic::kOdom, options.body, state_qos);
    m.command_writer = endpoint(true, wire::Topic::kCommand, options.body);
    if (options.altitude) {
      m.altitude.reader = endpoint(false, wire::Topic::kAltitude, options.body, state_qos);
    }
    if (options.winch) m.winch_writer = endpoint(true, wire::Topic::kWinchCommand, "");
    if (options.cable) {
      m.cable_reader = endpoint(false, wire::Topic::kCableState, options.cable_name, cable_qos);
    }
    if (!options.observe.empty()) {
      m.observed.reader = endpoint(false, wire::Topic::kOdom, options.observe, state_qos);
    }
    // the controller as a ROS 2 node <ns>/<name> with these endpoints (ros2 node list)
    m.graph = std::make_unique<wire::RosGraphNode>(m.participant, options.ns, options.name, readers,
                                                   writers);

    // the node's scene: the body must take commands
    const Clock::time_point begin = Clock::now();
    bool known = false;
    while (!known) {
      if (Stopping(options)) break;
      void* samples[1] = {nullptr};
      dds_sample_info_t info;
      const dds_return_t n = dds_take(scene_reader, samples, &info, 1, 1);
      std::optional<wire::SceneInfo> s;
      if (n > 0 && info.valid_data) {
        s = wire::DecodeSceneInfo(*static_cast<const towsim_msgs_msg_dds__SceneInfo_*>(samples[0]));
      }
      if (n > 0) dds_return_loan(scene_reader, samples, n);
      if (s) {
        m.step_size = s->step_size;
        m.winch.present = s->has_winch;
        m.winch.min_length = s->winch_min_length;
        m.winch.max_length = s->winch_max_length;
        m.winch.max_speed = s->winch_max_speed;
        m.winch.max_acceleration = s->winch_max_acceleration;
        std::string bodies;
        for (size_t i = 0; i < s->commanded_bodies.size(); ++i) {
          bodies += std::string(i ? ", " : "") + s->commanded_bodies[i];
          if (options.body == s->commanded_bodies[i]) known = true;
        }
        if (!known) {
          throw std::runtime_error("body " + options.body + " takes no commands in scene " +
                                   s->scene + " (commanded bodies: " + bodies + ")");
        }
        // the cable read must exist (a node that does not list its cables has the one cable)
        const std::vector<std::string> cables =
            s->cables.empty() ? std::vector<std::string>{wire::kOneCable} : s->cables;
        if (options.cable &&
            std::find(cables.begin(), cables.end(), options.cable_name) == cables.end()) {
          std::string list;
          for (const std::string& c : cables) list += (list.empty() ? "" : ", ") + c;
          throw std::runtime_error("scene " + s->scene + " has no cable " + options.cable_name +
                                   " (cables: " + list + ")");
        }
        if (options.winch && !m.winch.present) {
          throw std::runtime_error(
              "scene " + s->scene + " has no winch (cable.winch) to command on " +
              names.Name(wire::Topic::kWinchCommand).substr(names.prefix().size()));
        }
      }
      if (!known) {
        if (Seconds(Clock::now() - begin) > options.timeout) {
          throw std::runtime_error("no scene_info from a node on domain " +
                                   std::to_string(options.domain) + ", namespace " + options.ns);
        }
        dds_sleepfor(DDS_MSECS(10));
      }
    }
    // the node must hear the first command: wait until the writer and the odom reader matched
    for (;;) {
      if (Stopping(options)) break;
      dds_publication_matched_status_t pm;
      dds_subscription_matched_status_t sm;
      dds_get_publication_matched_status(m.command_writer, &pm);
      dds_get_subscription_matched_status(m.own.reader, &sm);
      bool matched = pm.current_count > 0 && sm.current_count > 0;
      if (m.winch_writer != 0) {
        dds_get_publication_matched_status(m.winch_writer, &pm);
        matched = matched && pm.current_count > 0;
      }
      if (matched) break;
      if (Seconds(Clock::now() - begin) > options.timeout) {
        throw std::runtime_error("the node's command reader / odometry writer did not match");
      }
      dds_sleepfor(DDS_MSECS(5));
    }
    m.waitset = Check(dds_create_waitset(m.participant), "waitset");
    const dds_entity_t cond =
        Check(dds_create_readcondition(m.status_reader, DDS_ANY_STATE), "read condition");
    Check(dds_waitset_attach(m.waitset, cond, 0), "waitset attach");
    m.own.waitset = WaitsetOf(m.participant, m.own.reader);
    if (m.observed.reader != 0) m.observed.waitset = WaitsetOf(m.participant, m.observed.reader);
    if (m.altitude.reader != 0) m.altitude.waitset = WaitsetOf(m.participant, m.altitude.reader);
  } catch (...) {
    dds_delete_qos(state_qos);
    dds_delete_qos(cable_qos);
    dds_delete(m.participant);
    delete impl_;
    throw;
  }
  dds_delete_qos(state_qos);
  dds_delete_qos(cable_qos);
}

const WinchInfo& LockstepClient::winch() const { return impl_->winch; }

LockstepClient::~LockstepClient() {
  dds_delete(impl_->participant);
  delete impl_;
}

int LockstepClient::Run(const Law& law) {
  Impl& m = *impl_;
  const std::string& who = m.opt.name;
  std::string run_id;
  uint64_t last_step = ~0ULL;
  double last_time = 0.0;
  Clock::time_point last_progress = Clock::now();
  while (!Stopping(m.opt)) {
    dds_waitset_wait(m.waitset, nullptr, 0, DDS_MSECS(100));
    void* samples[16] = {};
    dds_sample_info_t infos[16];
    const dds_return_t n = dds_take(m.status_reader, samples, infos, 16, 16);
    if (n < 0) {
      std::fprintf(stderr, "%s: error: taking the status: %s\n", who.c_str(), dds_strretcode(n));
      return 1;
    }
    // only the newest status matters
    const towsim_msgs_msg_dds__SimStatus_* newest = nullptr;
    for (int i = 0; i < n; ++i) {
      if (infos[i].valid_data) {
        newest = static_cast<const towsim_msgs_msg_dds__SimStatus_*>(samples[i]);
      }
    }
    bool done = false;
    if (newest != nullptr) {
      const wire::SimStatus s = wire::DecodeStatus(*newest);
      const bool new_run = run_id != s.run_id;
      const bool fresh = new_run || last_step != s.step;
      if (s.terminal()) {
        done = true;
      } else if (fresh) {
        const double t = s.t;
        if (new_run) {
          // a RESET, not the first run seen: the old run's samples still queued are dropped
          m.own.NewRun(!run_id.empty(), t);
          m.observed.NewRun(!run_id.empty(), t);
          m.altitude.NewRun();
          m.cable = CableSample{};
        }
        // the odometry of this step (published before the status); the latest one after a
        // short wait otherwise
        m.own.WaitFor(t, m.opt);
        if (m.own.have) {
          const wire::Odometry& o = m.own.odom;
          BodyState b;
          b.step = s.step;
          b.t = t;
          b.x = o.x;
          b.y = o.y;
          b.z = o.z;
          const Euler e = EulerFromQuaternion(o.qx, o.qy, o.qz, o.qw);
          b.roll = e.roll;
          b.pitch = e.pitch;
          b.yaw = e.yaw;
          b.u = o.u;
          b.v = o.v;
          b.w = o.w;
          b.p = o.p;
          b.q = o.q;
          b.r = o.r;
          const Vec3 vw = BodyToWorld(o.qx, o.qy, o.qz, o.qw, {b.u, b.v, b.w});
          b.x_dot = vw.x;
          b.y_dot = vw.y;
          b.z_dot = vw.z;
          b.dt = (new_run || t <= last_time) ? m.step_size : t - last_time;
          if (m.altitude.reader != 0) {
            // the range of this step (published with the odometry, before the status)
            m.altitude.WaitFor(t, m.opt);
            if (m.altitude.Has(t)) b.altitude = m.altitude.range;
          }
          if (m.observed.reader != 0) {
            m.observed.WaitFor(t, m.opt);
            if (m.observed.have && m.observed.time >= t - 1e-9) {
              const wire::Odometry& op = m.observed.odom;
              const Euler oe = EulerFromQuaternion(op.qx, op.qy, op.qz, op.qw);
              b.observed = {true, op.x, op.y, op.z, oe.roll, oe.pitch, oe.yaw};
            }
          }
          if (m.cable_reader != 0) {
            m.TakeCable(t);
            b.cable = m.cable;
          }
          const Actuation a = law(b);
          towsim_msgs_msg_dds__ActuatorCommand_ cmd{};
          cmd.header.stamp = newest->header.stamp;
          cmd.header.frame_id = const_cast<char*>(m.opt.body.c_str());
          cmd.step = s.step;
          cmd.thrust = a.thrust;
          cmd.rudder = a.rudder;
          cmd.elevator = a.elevator;
          dds_return_t rc = dds_write(m.command_writer, &cmd);
          if (rc >= 0 && m.winch_writer != 0) {
            towsim_msgs_msg_dds__WinchCommand_ w{};
            w.header = cmd.header;
            w.header.frame_id = const_cast<char*>("");
            w.step = s.step;
            w.mode = a.winch.mode == WinchDemand::Mode::kLength
                         ? towsim_msgs_msg_dds__WinchCommand_Constants_LENGTH
                         : towsim_msgs_msg_dds__WinchCommand_Constants_SPEED;
            w.value = a.winch.value;
            rc = dds_write(m.winch_writer, &w);
          }
          if (rc < 0) {
            std::fprintf(stderr, "%s: error: writing a command: %s\n", who.c_str(),
                         dds_strretcode(rc));
            dds_return_loan(m.status_reader, samples, n);
            return 1;
          }
          run_id = s.run_id;
          last_step = s.step;
          last_time = t;
          ++answered_;
          last_progress = Clock::now();
        }
      }
    }
    if (n > 0) dds_return_loan(m.status_reader, samples, n);
    if (done) return 0;
    if (Seconds(Clock::now() - last_progress) > m.opt.timeout) {
      std::fprintf(stderr, "%s: error: no new step from the node for %g s\n", who.c_str(),
                   m.opt.timeout);
      return 1;
    }
  }
  return 0;
}

}  // namespace towsim::controllers
