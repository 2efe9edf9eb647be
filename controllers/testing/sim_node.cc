#include "testing/sim_node.h"

#include <signal.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>

#include "common/laws.h"
#include "dds/dds.h"
#include "geometry_msgs.h"
#include "installed/installed_data.h"
#include "nav_msgs.h"
#include "testing/test_logs.h"
#include "towsim_msgs.h"
#include "wire/qos.h"
#include "wire/topic_names.h"

namespace towsim::testing {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
std::string DefaultLogDir(int domain) {
  std::string name = "towsim";
  if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info()) {
    name += std::string("_") + info->test_suite_name() + "_" + info->name();
  }
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
  }
  return ::testing::TempDir() + name + "_d" + std::to_string(domain);
}

// appends `sample` to `history`, or replaces the last one if it is of the same state: the
// paused / waiting node repeats its state, one sample per state is kept
template <typename Sample>
void AppendState(std::vector<Sample>& history, const Sample& sample) {
  if (!history.empty() && history.back().run == sample.run && history.back().t == sample.t) {
    history.back() = sample;
  } else {
    history.push_back(sample);
  }
}

// the sample's run: the RESETs seen on that topic (sim time going back)
struct RunCounter {
  int run = 0;
  double last_t = -1.0;
  int Next(double t) {
    if (t < last_t - 1e-9) ++run;
    last_t = t;
    return run;
  }
};

}  // namespace

struct SimNode::Impl {
  SimNodeOptions opt;
  std::unique_ptr<DomainLease> lease;
  std::string dds_uri;
  std::unique_ptr<wire::TopicNames> names;  // of SimNodeOptions::ns
  std::unique_ptr<Process> process;
  SceneInfo scene;
  dds_entity_t participant = 0, control_writer = 0;
  dds_listener_t* listener = nullptr;

  // what the listener fills, under `mutex`
  mutable std::mutex mutex;
  std::map<dds_entity_t, std::string> odom_readers, force_readers;  // reader -> body
  dds_entity_t status_reader = 0;
  std::map<dds_entity_t, std::string> cable_readers;  // reader -> cable
  std::map<std::string, std::vector<OdometrySample>> odom;
  std::map<std::string, std::vector<WrenchSample>> forces;
  std::map<std::string, RunCounter> odom_runs, force_runs;
  std::vector<StatusSample> statuses;
  std::map<std::string, CableSample> cables;                  // the latest, by cable
  std::map<std::string, std::vector<TensionSample>> tensions;  // by cable
  std::map<std::string, RunCounter> cable_runs;

  static void OnData(dds_entity_t reader, void* arg) { static_cast<Impl*>(arg)->Take(reader); }

  void Take(dds_entity_t reader) {
    void* samples[32] = {};
    dds_sample_info_t infos[32];
    for (;;) {
      const dds_return_t n = dds_take(reader, samples, infos, 32, 32);
      if (n <= 0) return;
      std::lock_guard<std::mutex> lock(mutex);
      for (int i = 0; i < n; ++i) {
        if (infos[i].valid_data) Store(reader, samples[i]);
      }
      dds_return_loan(reader, samples, n);
      if (n < 32) return;
    }
  }

  void Store(dds_entity_t reader, const void* sample) {
    if (reader == status_reader) {
      statuses.push_back(
          wire::DecodeStatus(*static_cast<const towsim_msgs_msg_dds__SimStatus_*>(sample)));
    } else if (const auto ct = cable_readers.find(reader); ct != cable_readers.end()) {
      CableSample c;
      static_cast<wire::CableState&>(c) =
          wire::DecodeCableState(*static_cast<const towsim_msgs_msg_dds__CableState_*>(sample));
      c.run = cable_runs[ct->second].Next(c.t);
      TensionSample top{c.run, c.t, -HUGE_VAL, 0};
      for (size_t k = 0; k < c.tension.size(); ++k) {
        if (c.tension[k] > top.max) top = {c.run, c.t, c.tension[k], int(k)};
      }
      tensions[ct->second].push_back(top);
      cables[ct->second] = std::move(c);
    } else if (const auto it = odom_readers.find(reader); it != odom_readers.end()) {
      OdometrySample o;
      static_cast<wire::Odometry&>(o) =
          wire::DecodeOdometry(*static_cast<const nav_msgs_msg_dds__Odometry_*>(sample));
      o.run = odom_runs[it->second].Next(o.t);
      const controllers::Euler e = controllers::EulerFromQuaternion(o.qx, o.qy, o.qz, o.qw);
      o.roll = e.roll;
      o.pitch = e.pitch;
      o.yaw = e.yaw;
      AppendState(odom[it->second], o);
    } else if (const auto jt = force_readers.find(reader); jt != force_readers.end()) {
      WrenchSample f;
      static_cast<wire::Wrench&>(f) =
          wire::DecodeWrench(*static_cast<const geometry_msgs_msg_dds__WrenchStamped_*>(sample));
      f.run = force_runs[jt->second].Next(f.t);
      AppendState(forces[jt->second], f);
    }
  }

  // a reader of `topic` (of `owner`, wire/topic_names.h) with the QoS of its row; a kState
  // reader keeps `depth` samples
  dds_entity_t Reader(wire::Topic topic, const std::string& owner, int depth, bool listen) {
    const wire::TopicSpec& spec = wire::SpecOf(topic);
    const std::string name = names->Name(topic, owner);
    const dds_entity_t t = dds_create_topic(participant, spec.type, name.c_str(), nullptr, nullptr);
    if (t < 0) Fail("topic " + name + ": " + dds_strretcode(t));
    dds_qos_t* qos = wire::ProfileQos(spec.qos, depth);
    const dds_entity_t r = dds_create_reader(participant, t, qos, listen ? listener : nullptr);
    dds_delete_qos(qos);
    if (r < 0) Fail("reader " + name + ": " + dds_strretcode(r));
    return r;
  }

  [[noreturn]] void Fail(const std::string& what) const {
    std::string text = "SimNode: " + what;
    if (process) {
      text += "\n  " + process->command_line() + "\n--- sim_node stdout ---\n" + process->out() +
              "--- sim_node stderr ---\n" + process->err();
    }
    throw std::runtime_error(text);
  }

  void Control(uint8_t command, uint32_t steps, double rate) {
    const Clock::time_point begin = Clock::now();
    for (;;) {
      dds_publication_matched_status_t m{};
      dds_get_publication_matched_status(control_writer, &m);
      if (m.current_count > 0) break;
      if (Seconds(Clock::now() - begin) > opt.startup_timeout) {
        Fail("the node's sim_control reader did not match");
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    towsim_msgs_msg_dds__SimControl_ c{};
    c.header.frame_id = const_cast<char*>("");
    c.command = command;
    c.steps = steps;
    c.rate = rate;
    const dds_return_t rc = dds_write(control_writer, &c);
    if (rc < 0) Fail(std::string("writing a SimControl request: ") + dds_strretcode(rc));
  }

  NodeResult Result() const {
    NodeResult r;
    r.exit_code = process->exit_code();
    std::stringstream out(process->out());
    std::string line;
    while (std::getline(out, line)) {
      if (line.rfind("sim_node: ", 0) == 0 && line.find(" steps, ") != std::string::npos) {
        r.summary = line;
      }
    }
    return r;
  }
};

SimNode::SimNode(SimNodeOptions options) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.opt = std::move(options);
  const SimNodeOptions& o = m.opt;
  m.lease =
      o.domain < 0 ? std::make_unique<DomainLease>() : std::make_unique<DomainLease>(o.domain);
  const int domain = m.lease->id();
  const bool own_log_dir = m.opt.log_dir.empty();
  if (own_log_dir) m.opt.log_dir = DefaultLogDir(domain);
  fs::remove_all(o.log_dir);
  fs::create_directories(o.log_dir);
  if (own_log_dir) RemoveAfterPassingTest(o.log_dir);
  m.names = std::make_unique<wire::TopicNames>(o.ns);

  // the project's loopback configuration, for this process and the node
  const std::string xml = o.data_dir + "/cyclonedds.xml";
  if (!fs::is_regular_file(xml))
    m.Fail("no DDS configuration " + xml + " (SimNodeOptions::data_dir)");
  m.dds_uri = "file://" + xml;
  setenv("CYCLONEDDS_URI", m.dds_uri.c_str(), 1);

  m.participant = dds_create_participant(static_cast<dds_domainid_t>(domain), nullptr, nullptr);
  if (m.participant < 0) {
    m.Fail("creating a DDS participant on domain " + std::to_string(domain) + ": " +
           dds_strretcode(m.participant));
  }
  m.listener = dds_create_listener(&m);
  dds_lset_data_available(m.listener, &Impl::OnData);
  const dds_entity_t scene_reader = m.Reader(wire::Topic::kSceneInfo, "", 1, false);
  {
    std::lock_guard<std::mutex> lock(m.mutex);
    m.status_reader = m.Reader(wire::Topic::kStatus, "", 1000, true);
    // the one cable's state from the start; a network's other cables after scene_info
    m.cable_readers[m.Reader(wire::Topic::kCableState, wire::kOneCable, 1000, true)] =
        wire::kOneCable;
  }
  {
    const wire::TopicSpec& control = wire::SpecOf(wire::Topic::kSimControl);
    const dds_entity_t topic =
        dds_create_topic(m.participant, control.type,
                         m.names->Name(wire::Topic::kSimControl).c_str(), nullptr, nullptr);
    dds_qos_t* qos = wire::ProfileQos(control.qos);
    m.control_writer = dds_create_writer(m.participant, topic, qos, nullptr);
    dds_delete_qos(qos);
    if (m.control_writer < 0)
      m.Fail("sim_control writer: " + std::string(dds_strretcode(m.control_writer)));
  }

  // a bare scene name finds data_dir/scenes/NAME[.yaml], as an installed sim_node does
  const std::string scene =
      installed::ResolveInstalled(o.scene, installed::kScenes, fs::path(o.data_dir));
  std::vector<std::string> argv = {
      o.sim_node,    "--scene", scene,     "--mode", o.mode, "--domain", std::to_string(domain),
      "--namespace", o.ns,      "--paused"};
  auto number = [](double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
  };
  argv.insert(argv.end(), {"--duration", number(o.duration)});
  if (o.mode == "realtime") argv.insert(argv.end(), {"--rate", number(o.rate)});
  for (const std::string& s : o.set) argv.insert(argv.end(), {"--set", s});
  if (o.csv) argv.insert(argv.end(), {"--csv", csv_dir()});
  if (o.fail_on_failsafe) argv.push_back("--fail-on-failsafe");
  if (o.lockstep_timeout >= 0.0) {
    argv.insert(argv.end(), {"--lockstep-timeout", number(o.lockstep_timeout)});
  }
  argv.insert(argv.end(), o.extra_args.begin(), o.extra_args.end());
  m.process = std::make_unique<Process>(argv, o.log_dir + "/sim_node",
                                        std::vector<std::string>{"CYCLONEDDS_URI=" + m.dds_uri});

  // scene_info: the bodies
  const Clock::time_point begin = Clock::now();
  auto check_alive = [&](const std::string& waiting_for) {
    if (!m.process->running()) {
      m.Fail("sim_node exited (code " + std::to_string(m.process->exit_code()) + ") before " +
             waiting_for);
    }
    if (Seconds(Clock::now() - begin) > o.startup_timeout) {
      m.Fail("no " + waiting_for + " within " + number(o.startup_timeout) + " s");
    }
  };
  for (bool have = false; !have;) {
    void* samples[1] = {nullptr};
    dds_sample_info_t info;
    const dds_return_t n = dds_take(scene_reader, samples, &info, 1, 1);
    if (n > 0 && info.valid_data) {
      m.scene =
          wire::DecodeSceneInfo(*static_cast<const towsim_msgs_msg_dds__SceneInfo_*>(samples[0]));
      have = true;
    }
    if (n > 0) dds_return_loan(scene_reader, samples, n);
    if (!have) {
      check_alive("scene_info");
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  {
    std::lock_guard<std::mutex> lock(m.mutex);
    for (const std::string& b : m.scene.bodies) {
      m.odom_readers[m.Reader(wire::Topic::kOdom, b, 1000, true)] = b;
      m.force_readers[m.Reader(wire::Topic::kCableForce, b, 1000, true)] = b;
    }
    for (const std::string& c : m.scene.cables) {
      if (c == wire::kOneCable) continue;
      m.cable_readers[m.Reader(wire::Topic::kCableState, c, 1000, true)] = c;
    }
  }
  // the step-0 state of every body (repeated by the paused node) and a status
  for (;;) {
    bool all = status().has_value();
    for (const std::string& b : m.scene.bodies) all = all && odometry(b).has_value();
    if (all) break;
    check_alive("first state of every body");
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (!o.start_paused) Resume();
}

SimNode::~SimNode() {
  Impl& m = *impl_;
  if (m.process && m.process->running()) {
    m.process->Signal(SIGINT);
    m.process->Wait(5.0);
  }
  if (m.participant > 0) dds_delete(m.participant);  // the listener stops first
  if (m.listener != nullptr) dds_delete_listener(m.listener);
}

int SimNode::domain() const { return impl_->lease->id(); }
const std::string& SimNode::ns() const { return impl_->opt.ns; }
const SceneInfo& SimNode::scene_info() const { return impl_->scene; }
std::string SimNode::dds_uri() const { return impl_->dds_uri; }
const std::string& SimNode::log_dir() const { return impl_->opt.log_dir; }
std::string SimNode::csv_dir() const { return impl_->opt.log_dir + "/csv"; }
std::string SimNode::command_line() const { return impl_->process->command_line(); }
std::string SimNode::log() const {
  return "--- " + impl_->process->command_line() + " (stdout) ---\n" + impl_->process->out() +
         "--- stderr ---\n" + impl_->process->err();
}

std::optional<OdometrySample> SimNode::odometry(const std::string& body) const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  const auto it = impl_->odom.find(body);
  if (it == impl_->odom.end() || it->second.empty()) return std::nullopt;
  return it->second.back();
}
std::optional<CableSample> SimNode::cable_state(const std::string& cable) const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  const auto it = impl_->cables.find(cable);
  if (it == impl_->cables.end()) return std::nullopt;
  return it->second;
}
std::optional<WrenchSample> SimNode::cable_force(const std::string& body) const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  const auto it = impl_->forces.find(body);
  if (it == impl_->forces.end() || it->second.empty()) return std::nullopt;
  return it->second.back();
}
std::optional<StatusSample> SimNode::status() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  if (impl_->statuses.empty()) return std::nullopt;
  return impl_->statuses.back();
}
std::vector<OdometrySample> SimNode::odometry_history(const std::string& body) const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  const auto it = impl_->odom.find(body);
  return it == impl_->odom.end() ? std::vector<OdometrySample>{} : it->second;
}
std::vector<WrenchSample> SimNode::cable_force_history(const std::string& body) const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  const auto it = impl_->forces.find(body);
  return it == impl_->forces.end() ? std::vector<WrenchSample>{} : it->second;
}
std::vector<StatusSample> SimNode::status_history() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->statuses;
}
std::vector<SimNode::TensionSample> SimNode::max_tension_history(const std::string& cable) const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  const auto it = impl_->tensions.find(cable);
  return it == impl_->tensions.end() ? std::vector<TensionSample>{} : it->second;
}

std::optional<StatusSample> SimNode::WaitForStatus(
    const std::function<bool(const StatusSample&)>& pred, double timeout) {
  const Clock::time_point begin = Clock::now();
  size_t seen = 0;
  for (;;) {
    const std::vector<StatusSample> all = status_history();
    for (; seen < all.size(); ++seen) {
      if (pred(all[seen])) return all[seen];
    }
    if (Seconds(Clock::now() - begin) > timeout) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

void SimNode::Pause() { impl_->Control(towsim_msgs_msg_dds__SimControl_Constants_PAUSE, 0, 0.0); }
void SimNode::Resume() { impl_->Control(towsim_msgs_msg_dds__SimControl_Constants_RESUME, 0, 0.0); }
void SimNode::Step(uint32_t steps) {
  impl_->Control(towsim_msgs_msg_dds__SimControl_Constants_STEP, steps, 0.0);
}
void SimNode::Reset() { impl_->Control(towsim_msgs_msg_dds__SimControl_Constants_RESET, 0, 0.0); }
void SimNode::SetRate(double rate) {
  impl_->Control(towsim_msgs_msg_dds__SimControl_Constants_SET_RATE, 0, rate);
}

NodeResult SimNode::Wait(double timeout) {
  if (!impl_->process->Wait(timeout)) return NodeResult{};
  return impl_->Result();
}

NodeResult SimNode::Stop(double timeout) {
  impl_->process->Signal(SIGINT);
  if (!impl_->process->Wait(timeout)) {
    impl_->process->Signal(SIGKILL);
    impl_->process->Wait(5.0);
    NodeResult r = impl_->Result();
    r.exit_code = -1;
    return r;
  }
  return impl_->Result();
}

}  // namespace towsim::testing
