#include "common/client.h"

#include <signal.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include "common/dds_qos.h"
#include "common/laws.h"
#include "dds/dds.h"
#include "dds/ros_graph.h"
#include "nav_msgs.h"
#include "sensor_msgs.h"
#include "towsim_msgs.h"

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

double StampSeconds(int32_t sec, uint32_t nanosec) { return sec + 1e-9 * nanosec; }

}  // namespace

std::string TopicPrefix(const std::string& ns) {
  if (ns.empty() || ns == "/") return "rt/";
  return ns[0] == '/' ? "rt" + ns + "/" : "rt/" + ns + "/";
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

struct LockstepClient::Impl {
  ClientOptions opt;
  dds_entity_t participant = 0;
  dds_entity_t status_reader = 0, odom_reader = 0, command_writer = 0;
  dds_entity_t waitset = 0;
  dds_entity_t altitude_reader = 0;  // 0: not subscribed
  std::unique_ptr<dds::RosGraphNode> graph;  // the ROS 2 node <ns>/<name>
  double step_size = 0.05;
  // the latest odometry taken
  nav_msgs_msg_dds__Odometry_ odom{};
  bool have_odom = false;
  double odom_time = -1.0;
  // after a RESET (a new run id): the time of the new run's first status; odometry stamped
  // later is the old run's, still queued (the node publishes a step's odometry before its
  // status), and is dropped until a sample of the new run comes; < 0 otherwise
  double reset_time = -1.0;

  void TakeOdom() {
    void* os[16] = {};
    dds_sample_info_t oi[16];
    const dds_return_t k = dds_take(odom_reader, os, oi, 16, 16);
    for (int j = 0; j < k; ++j) {
      if (!oi[j].valid_data) continue;
      const auto* o = static_cast<const nav_msgs_msg_dds__Odometry_*>(os[j]);
      const double t = StampSeconds(o->header.stamp.sec, o->header.stamp.nanosec);
      if (reset_time >= 0.0) {
        if (t > reset_time + 1e-9) continue;  // the old run's
        reset_time = -1.0;
      }
      if (t >= odom_time || !have_odom) {  // a RESET goes back in time: see below
        odom = *o;
        odom.header.frame_id = nullptr;
        odom.child_frame_id = nullptr;
        odom_time = t;
        have_odom = true;
      }
    }
    if (k > 0) dds_return_loan(odom_reader, os, k);
  }

  // the newest altimeter range stamped at most t (a RESET's old run has later stamps)
  float altitude_range = 0.0f;
  double altitude_time = -1.0;
  void TakeAltitude(double t) {
    void* rs[16] = {};
    dds_sample_info_t ri[16];
    const dds_return_t k = dds_take(altitude_reader, rs, ri, 16, 16);
    for (int j = 0; j < k; ++j) {
      if (!ri[j].valid_data) continue;
      const auto* r = static_cast<const sensor_msgs_msg_dds__Range_*>(rs[j]);
      const double stamp = StampSeconds(r->header.stamp.sec, r->header.stamp.nanosec);
      if (stamp > t + 1e-9) continue;
      if (stamp >= altitude_time) {
        altitude_range = r->range;
        altitude_time = stamp;
      }
    }
    if (k > 0) dds_return_loan(altitude_reader, rs, k);
  }
};

LockstepClient::LockstepClient(const ClientOptions& options) : impl_(new Impl) {
  Impl& m = *impl_;
  m.opt = options;
  RequireDdsUri();
  if (options.body.empty()) throw std::runtime_error("no body to command (--body)");
  const std::string prefix = TopicPrefix(options.ns);
  // a ROS 2 participant: USER_DATA enclave=/; (dds/ros_graph.h)
  dds_qos_t* participant_qos = towsim::dds::NewParticipantQos();
  try {
    if (options.security.empty()) {
      m.participant =
          Check(dds_create_participant(options.domain, participant_qos, nullptr),
                "creating the DDS participant (domain " + std::to_string(options.domain) + ")");
    } else {
      m.participant =
          towsim::dds::CreateSecureParticipant(options.domain, options.security, participant_qos);
    }
  } catch (...) {
    dds_delete_qos(participant_qos);
    throw;
  }
  dds_delete_qos(participant_qos);
  dds_qos_t* state_qos = ReliableQos(16, false);
  dds_qos_t* command_qos = ReliableQos(kCommandDepth, false);
  dds_qos_t* scene_qos = ReliableQos(1, true);
  try {
    const dds_entity_t scene_topic =
        Check(dds_create_topic(m.participant, &towsim_msgs_msg_dds__SceneInfo__desc,
                               (prefix + "scene_info").c_str(), nullptr, nullptr),
              "scene_info topic");
    const dds_entity_t scene_reader = Check(
        dds_create_reader(m.participant, scene_topic, scene_qos, nullptr), "scene_info reader");
    const dds_entity_t status_topic =
        Check(dds_create_topic(m.participant, &towsim_msgs_msg_dds__SimStatus__desc,
                               (prefix + "status").c_str(), nullptr, nullptr),
              "status topic");
    m.status_reader =
        Check(dds_create_reader(m.participant, status_topic, state_qos, nullptr), "status reader");
    const dds_entity_t odom_topic =
        Check(dds_create_topic(m.participant, &nav_msgs_msg_dds__Odometry__desc,
                               (prefix + options.body + "/odom").c_str(), nullptr, nullptr),
              "odom topic");
    m.odom_reader =
        Check(dds_create_reader(m.participant, odom_topic, state_qos, nullptr), "odom reader");
    const dds_entity_t command_topic =
        Check(dds_create_topic(m.participant, &towsim_msgs_msg_dds__ActuatorCommand__desc,
                               (prefix + options.body + "/command").c_str(), nullptr, nullptr),
              "command topic");
    m.command_writer = Check(dds_create_writer(m.participant, command_topic, command_qos, nullptr),
                             "command writer");
    if (options.altitude) {
      const dds_entity_t altitude_topic =
          Check(dds_create_topic(m.participant, &sensor_msgs_msg_dds__Range__desc,
                                 (prefix + options.body + "/altitude").c_str(), nullptr, nullptr),
                "altitude topic");
      m.altitude_reader = Check(
          dds_create_reader(m.participant, altitude_topic, state_qos, nullptr), "altitude reader");
    }
    // the controller as a ROS 2 node <ns>/<name> with these endpoints (ros2 node list)
    m.graph = std::make_unique<dds::RosGraphNode>(
        m.participant, options.ns, options.name,
        m.altitude_reader != 0
            ? std::vector<dds_entity_t>{scene_reader, m.status_reader, m.odom_reader,
                                        m.altitude_reader}
            : std::vector<dds_entity_t>{scene_reader, m.status_reader, m.odom_reader},
        std::vector<dds_entity_t>{m.command_writer});

    // the node's scene: the body must take commands
    const Clock::time_point begin = Clock::now();
    bool known = false;
    while (!known) {
      if (Stopping(options)) break;
      void* samples[1] = {nullptr};
      dds_sample_info_t info;
      const dds_return_t n = dds_take(scene_reader, samples, &info, 1, 1);
      if (n > 0 && info.valid_data) {
        const auto* s = static_cast<const towsim_msgs_msg_dds__SceneInfo_*>(samples[0]);
        m.step_size = s->step_size;
        std::string names;
        for (uint32_t i = 0; i < s->commanded_bodies._length; ++i) {
          names += std::string(i ? ", " : "") + s->commanded_bodies._buffer[i];
          if (options.body == s->commanded_bodies._buffer[i]) known = true;
        }
        if (!known) {
          const std::string scene = s->scene;
          dds_return_loan(scene_reader, samples, n);
          throw std::runtime_error("body " + options.body + " takes no commands in scene " + scene +
                                   " (commanded bodies: " + names + ")");
        }
      }
      if (n > 0) dds_return_loan(scene_reader, samples, n);
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
      dds_get_subscription_matched_status(m.odom_reader, &sm);
      if (pm.current_count > 0 && sm.current_count > 0) break;
      if (Seconds(Clock::now() - begin) > options.timeout) {
        throw std::runtime_error("the node's command reader / odometry writer did not match");
      }
      dds_sleepfor(DDS_MSECS(5));
    }
    m.waitset = Check(dds_create_waitset(m.participant), "waitset");
    const dds_entity_t cond =
        Check(dds_create_readcondition(m.status_reader, DDS_ANY_STATE), "read condition");
    Check(dds_waitset_attach(m.waitset, cond, 0), "waitset attach");
  } catch (...) {
    dds_delete_qos(state_qos);
    dds_delete_qos(command_qos);
    dds_delete_qos(scene_qos);
    dds_delete(m.participant);
    delete impl_;
    throw;
  }
  dds_delete_qos(state_qos);
  dds_delete_qos(command_qos);
  dds_delete_qos(scene_qos);
}

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
    const towsim_msgs_msg_dds__SimStatus_* s = nullptr;
    for (int i = 0; i < n; ++i) {
      if (infos[i].valid_data) s = static_cast<const towsim_msgs_msg_dds__SimStatus_*>(samples[i]);
    }
    bool done = false;
    if (s != nullptr) {
      const bool terminal = s->state == towsim_msgs_msg_dds__SimStatus_Constants_STATE_FINISHED ||
                            s->state == towsim_msgs_msg_dds__SimStatus_Constants_STATE_FAILED ||
                            s->state == towsim_msgs_msg_dds__SimStatus_Constants_STATE_STOPPED;
      const bool new_run = run_id != s->run_id;
      const bool fresh = new_run || last_step != s->step;
      if (terminal) {
        done = true;
      } else if (fresh) {
        const double t = s->sim_time;
        if (new_run) {
          m.odom_time = -1.0;
          m.have_odom = false;
          m.altitude_time = -1.0;
          if (!run_id.empty()) m.reset_time = t;  // a RESET, not the first run seen
        }
        // the odometry of this step (published before the status); the latest one after a
        // short wait otherwise
        const Clock::time_point wait_begin = Clock::now();
        for (;;) {
          m.TakeOdom();
          if (m.have_odom && m.odom_time >= t - 1e-9) break;
          if (Seconds(Clock::now() - wait_begin) > 0.5 || Stopping(m.opt)) break;
          dds_sleepfor(DDS_USECS(50));
        }
        if (m.have_odom) {
          const auto& o = m.odom;
          const auto& pq = o.pose.pose.orientation;
          BodyState b;
          b.step = s->step;
          b.t = t;
          b.x = o.pose.pose.position.x;
          b.y = o.pose.pose.position.y;
          b.z = o.pose.pose.position.z;
          const Euler e = EulerFromQuaternion(pq.x, pq.y, pq.z, pq.w);
          b.roll = e.roll;
          b.pitch = e.pitch;
          b.yaw = e.yaw;
          b.u = o.twist.twist.linear.x;
          b.v = o.twist.twist.linear.y;
          b.w = o.twist.twist.linear.z;
          b.p = o.twist.twist.angular.x;
          b.q = o.twist.twist.angular.y;
          b.r = o.twist.twist.angular.z;
          const Vec3 vw = BodyToWorld(pq.x, pq.y, pq.z, pq.w, {b.u, b.v, b.w});
          b.x_dot = vw.x;
          b.y_dot = vw.y;
          b.z_dot = vw.z;
          b.dt = (new_run || t <= last_time) ? m.step_size : t - last_time;
          if (m.altitude_reader != 0) {
            // the range of this step (published with the odometry, before the status)
            const Clock::time_point altitude_begin = Clock::now();
            for (;;) {
              m.TakeAltitude(t);
              if (m.altitude_time >= t - 1e-9) break;
              if (Seconds(Clock::now() - altitude_begin) > 0.5 || Stopping(m.opt)) break;
              dds_sleepfor(DDS_USECS(50));
            }
            if (m.altitude_time >= t - 1e-9) b.altitude = m.altitude_range;
          }
          const Actuation a = law(b);
          towsim_msgs_msg_dds__ActuatorCommand_ cmd{};
          cmd.header.stamp = s->header.stamp;
          cmd.header.frame_id = const_cast<char*>(m.opt.body.c_str());
          cmd.step = s->step;
          cmd.thrust = a.thrust;
          cmd.rudder = a.rudder;
          cmd.elevator = a.elevator;
          const dds_return_t rc = dds_write(m.command_writer, &cmd);
          if (rc < 0) {
            std::fprintf(stderr, "%s: error: writing a command: %s\n", who.c_str(),
                         dds_strretcode(rc));
            dds_return_loan(m.status_reader, samples, n);
            return 1;
          }
          run_id = s->run_id;
          last_step = s->step;
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
