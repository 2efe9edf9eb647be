// DDS Security (docs/security.md) with real processes over loopback DDS: sim_node, the test
// controller, the controllers, towsim_record and towsim_export, each with an identity made by
// scripts/security.sh in the test's own directory; participants of the test process itself
// play the intruders (no certificate, a certificate without the right to command). The
// references: the same run without security (bit-identical files), and what the node counts
// in its summary line (commands received). DDS domains 140-148 (tests/integration/README.md).

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "dds/dds.h"
#include "nav_msgs.h"
#include "temp_dir.h"
#include "testing/process.h"
#include "towsim_msgs.h"
#include "wire/security.h"

namespace towsim::testing {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const std::string kSource = TOWSIM_SOURCE_DIR;
const std::string kCase1 = kSource + "/config/scenes/case1_forward.yaml";
constexpr double kProcessTimeout = 60.0;  // [s] a process that takes longer has hung
constexpr double kRunSeconds = 5.0;       // simulated: 100 steps of case1 (h = 0.05 s)
constexpr int kSteps = 100;
constexpr int kCommandedBodies = 2;  // tow_vehicle and towfish take commands in case1
// what the test controller sends (thrust, rudder, elevator from t): a turn and a dive
const std::vector<std::string> kCommands = {"--command", "tow_vehicle@0=4500,0.05,0", "--command",
                                            "towfish@1=0,0,-0.1"};
// long enough for a secured discovery and handshake (~0.3 s on loopback) many times over
constexpr double kDiscoverySeconds = 2.0;

std::vector<std::string> Env() { return {"CYCLONEDDS_URI=" + std::string(TOWSIM_DDS_URI)}; }

void Sleep(double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); }

class SecurityTest : public ::testing::Test {
 protected:
  SecurityTest() { setenv("CYCLONEDDS_URI", TOWSIM_DDS_URI, 1); }

  // scripts/security.sh [options] KEYS identities...
  void MakeIdentities(const std::vector<std::string>& args, const fs::path& keys) {
    std::string command = kSource + "/scripts/security.sh";
    // options first, then DIR, then the identities
    std::vector<std::string> options, names;
    for (const std::string& a : args) (a.rfind("--", 0) == 0 ? options : names).push_back(a);
    for (const std::string& o : options) command += " '" + o + "'";
    command += " '" + keys.string() + "'";
    for (const std::string& n : names) command += " '" + n + "'";
    command += " 2>" + (tmp_.path() / "security_sh.err").string();
    ASSERT_EQ(std::system(command.c_str()), 0)
        << command << "\n"
        << ReadFile((tmp_.path() / "security_sh.err").string());
  }

  std::string Keys(const std::string& name) const { return (keys_ / name).string(); }
  std::string Log(const std::string& name) const { return (tmp_.path() / name).string(); }

  // sim_node on case1 in lockstep for kRunSeconds with the scene's script off
  std::vector<std::string> NodeArgs(int domain, const std::string& security,
                                    std::vector<std::string> extra = {}) const {
    std::vector<std::string> a = {TOWSIM_SIM_NODE,
                                  "--scene",
                                  kCase1,
                                  "--mode",
                                  "lockstep",
                                  "--duration",
                                  std::to_string(kRunSeconds),
                                  "--set",
                                  "script=[]",
                                  "--domain",
                                  std::to_string(domain)};
    if (!security.empty()) a.insert(a.end(), {"--security", security});
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  }
  std::vector<std::string> ControllerArgs(int domain, const std::string& security) const {
    std::vector<std::string> a = {TOWSIM_TEST_CONTROLLER, "--domain", std::to_string(domain)};
    a.insert(a.end(), kCommands.begin(), kCommands.end());
    if (!security.empty()) a.insert(a.end(), {"--security", security});
    return a;
  }

  // one lockstep run of the node and the test controller; the node's summary line
  std::string LockstepRun(int domain, const std::string& node_id, const std::string& ctl_id,
                          const fs::path& csv, std::vector<std::string> extra = {}) {
    extra.insert(extra.end(), {"--csv", csv.string()});
    Process node(NodeArgs(domain, node_id, extra), Log("node" + std::to_string(domain)), Env());
    Process controller(ControllerArgs(domain, ctl_id), Log("ctl" + std::to_string(domain)), Env());
    EXPECT_TRUE(node.Wait(kProcessTimeout)) << node.command_line();
    EXPECT_EQ(node.exit_code(), 0) << node.err();
    EXPECT_TRUE(controller.Wait(kProcessTimeout));
    EXPECT_EQ(controller.exit_code(), 0) << controller.err();
    return node.out();
  }

  void SetUp() override {
    keys_ = tmp_.path() / "keys";
    MakeIdentities({"sim_node", "ctl:tow_vehicle,towfish", "fish:towfish", "viewer", "recorder"},
                   keys_);
  }

  test::TempDir tmp_;
  fs::path keys_;
};

// the node's count of commands received: "commands N (rejected ..."
long CommandsReceived(const std::string& summary) {
  std::smatch m;
  if (!std::regex_search(summary, m, std::regex("commands ([0-9]+) \\(rejected"))) return -1;
  return std::stol(m[1]);
}

void ExpectSameFile(const fs::path& a, const fs::path& b) {
  const std::string x = ReadFile(a.string()), y = ReadFile(b.string());
  EXPECT_FALSE(x.empty()) << a;
  EXPECT_TRUE(x == y) << a << " and " << b << " differ";
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// status.csv without its fifth column (wall_us: the wall time a step took; cable_length follows)
std::string WithoutWallTime(const std::string& csv) {
  std::istringstream in(csv);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    const std::size_t end = line.rfind(','), begin = line.rfind(',', end - 1);
    out += line.substr(0, begin) + line.substr(end) + "\n";
  }
  return out;
}

// a participant of this process (plain when `identity` is empty) that tries to take part
struct Intruder {
  Intruder(int domain, const std::string& identity)
      : participant(wire::CreateSecureParticipant(static_cast<uint32_t>(domain), identity)) {}
  ~Intruder() { dds_delete(participant); }

  dds_entity_t Topic(const dds_topic_descriptor_t* type, const std::string& name) {
    return dds_create_topic(participant, type, name.c_str(), nullptr, nullptr);
  }
  dds_entity_t Writer(const dds_topic_descriptor_t* type, const std::string& name) {
    const dds_entity_t t = Topic(type, name);
    return t < 0 ? t : dds_create_writer(participant, t, nullptr, nullptr);
  }
  // reliable, keep all: every sample the node sends it is kept
  dds_entity_t Reader(const dds_topic_descriptor_t* type, const std::string& name) {
    const dds_entity_t t = Topic(type, name);
    if (t < 0) return t;
    dds_qos_t* qos = dds_create_qos();
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
    dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
    const dds_entity_t r = dds_create_reader(participant, t, qos, nullptr);
    dds_delete_qos(qos);
    return r;
  }
  dds_entity_t StatusReader() {
    return Reader(&towsim_msgs_msg_dds__SimStatus__desc, "rt/towsim/status");
  }
  dds_entity_t CommandWriter(const std::string& body) {
    return Writer(&towsim_msgs_msg_dds__ActuatorCommand__desc, "rt/towsim/" + body + "/command");
  }
  // the names of the topics of every remote writer / reader discovered (builtin topics)
  std::vector<std::string> DiscoveredTopics() {
    std::vector<std::string> names;
    dds_instance_handle_t self = 0;
    dds_get_instance_handle(participant, &self);
    for (const dds_entity_t builtin :
         {DDS_BUILTIN_TOPIC_DCPSPUBLICATION, DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION}) {
      const dds_entity_t r = dds_create_reader(participant, builtin, nullptr, nullptr);
      void* samples[64] = {};
      dds_sample_info_t infos[64];
      const dds_return_t n = dds_read(r, samples, infos, 64, 64);
      for (int i = 0; i < n; ++i) {
        if (!infos[i].valid_data) continue;
        const auto* e = static_cast<const dds_builtintopic_endpoint_t*>(samples[i]);
        if (e->participant_instance_handle != self) {
          names.push_back(e->topic_name);
        }
      }
      if (n > 0) dds_return_loan(r, samples, n);
      dds_delete(r);
    }
    return names;
  }

  dds_entity_t participant;
};

int PublicationMatches(dds_entity_t writer) {
  dds_publication_matched_status_t s{};
  dds_get_publication_matched_status(writer, &s);
  return static_cast<int>(s.current_count);
}

int SubscriptionMatches(dds_entity_t reader) {
  dds_subscription_matched_status_t s{};
  dds_get_subscription_matched_status(reader, &s);
  return static_cast<int>(s.current_count);
}

// a command that would be clamped and counted if the node took it
towsim_msgs_msg_dds__ActuatorCommand_ RogueCommand(uint64_t step) {
  towsim_msgs_msg_dds__ActuatorCommand_ c{};
  c.header.frame_id = const_cast<char*>("rogue");
  c.step = step;
  c.thrust = 1e6;
  c.rudder = 1.0;
  return c;
}

// waits up to kMatchSeconds for `done()`; its last value
constexpr double kMatchSeconds = 20.0;  // a secured match takes well under a second
template <class F>
bool WaitFor(F done) {
  const Clock::time_point until = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                     std::chrono::duration<double>(kMatchSeconds));
  while (!done() && Clock::now() < until) Sleep(0.01);
  return done();
}

// while `node` runs: a rogue command every 2 ms on `command` (stamped with every step in
// turn), every status `status` can take, and the most readers any of `watched` matched
struct Rogue {
  long statuses = 0;
  int most_matches = 0;
};
Rogue RogueWhileRunning(Process& node, dds_entity_t command, dds_entity_t status,
                        const std::vector<dds_entity_t>& watched) {
  Rogue r;
  for (uint64_t k = 0; node.running() && k < 100000; ++k) {
    const auto c = RogueCommand(k % (kSteps + 1));
    dds_write(command, &c);
    void* samples[16] = {};
    dds_sample_info_t infos[16];
    const dds_return_t n = dds_take(status, samples, infos, 16, 16);
    if (n > 0) {
      r.statuses += n;
      dds_return_loan(status, samples, n);
    }
    for (const dds_entity_t w : watched) {
      r.most_matches = std::max(r.most_matches, PublicationMatches(w));
    }
    Sleep(0.002);
  }
  return r;
}

// the run ends well and the node counted the authorised controller's commands, nothing else
void ExpectTheControllersCommandsOnly(Process& node, Process& controller) {
  ASSERT_TRUE(node.Wait(kProcessTimeout));
  EXPECT_EQ(node.exit_code(), 0) << node.err();
  ASSERT_TRUE(controller.Wait(kProcessTimeout));
  EXPECT_EQ(controller.exit_code(), 0) << controller.err();
  EXPECT_EQ(CommandsReceived(node.out()), kSteps * kCommandedBodies) << node.out();
  EXPECT_NE(node.out().find("rejected 0, clamped 0"), std::string::npos) << node.out();
}

// domains 140 (without security) and 141 (with): same commands, the same files bit for bit
TEST_F(SecurityTest, SecurityAuthorisedControllerDrivesLockstepBitIdenticalToUnsecured) {
  const fs::path plain = tmp_.path() / "plain", secured = tmp_.path() / "secured";
  const std::string a = LockstepRun(140, "", "", plain);
  const std::string b = LockstepRun(141, Keys("sim_node"), Keys("ctl"), secured);
  EXPECT_EQ(CommandsReceived(a), kSteps * kCommandedBodies) << a;
  EXPECT_EQ(CommandsReceived(b), kSteps * kCommandedBodies) << b;
  for (const char* f : {"bodies.csv", "cable.csv", "forces.csv"}) {
    ExpectSameFile(plain / f, secured / f);
  }
  // the command took effect: the tow vehicle turned (rudder 0.05 rad for 5 s)
  EXPECT_NE(ReadFile((secured / "bodies.csv").string()).find("tow_vehicle"), std::string::npos);
}

// domain 142: a participant without a certificate discovers none of the node's topics, and
// its commands do not reach the node (the node counts the authorised controller's only)
TEST_F(SecurityTest, SecurityParticipantWithoutCertificateSeesNothingAndCommandsNothing) {
  constexpr int kDomain = 142;
  Intruder intruder(kDomain, "");
  const dds_entity_t command = intruder.CommandWriter("tow_vehicle");
  const dds_entity_t status = intruder.StatusReader();
  ASSERT_GT(command, 0);
  ASSERT_GT(status, 0);
  Process node(NodeArgs(kDomain, Keys("sim_node")), Log("node"), Env());
  Sleep(kDiscoverySeconds);
  EXPECT_EQ(PublicationMatches(command), 0);
  EXPECT_EQ(SubscriptionMatches(status), 0);
  EXPECT_TRUE(intruder.DiscoveredTopics().empty());
  Process controller(ControllerArgs(kDomain, Keys("ctl")), Log("ctl"), Env());
  const Rogue rogue = RogueWhileRunning(node, command, status, {command});
  EXPECT_EQ(rogue.statuses, 0);  // the node's status never came
  EXPECT_EQ(rogue.most_matches, 0);
  ExpectTheControllersCommandsOnly(node, controller);
  EXPECT_TRUE(intruder.DiscoveredTopics().empty());
}

// domain 143: a valid identity that may read but command nothing reads the outputs; its
// command writer is refused (no writer, so no match), the node counts nothing from it
TEST_F(SecurityTest, SecurityIdentityWithoutCommandPermissionIsRefused) {
  constexpr int kDomain = 143;
  Intruder viewer(kDomain, Keys("viewer"));
  const dds_entity_t status = viewer.StatusReader();
  ASSERT_GT(status, 0);
  const dds_entity_t command = viewer.CommandWriter("tow_vehicle");
  EXPECT_EQ(command, DDS_RETCODE_NOT_ALLOWED_BY_SECURITY) << dds_strretcode(command);
  const dds_entity_t control =
      viewer.Writer(&towsim_msgs_msg_dds__SimControl__desc, "rt/towsim/sim_control");
  EXPECT_EQ(control, DDS_RETCODE_NOT_ALLOWED_BY_SECURITY) << dds_strretcode(control);

  Process node(NodeArgs(kDomain, Keys("sim_node")), Log("node"), Env());
  // authenticated: its reader of the node's status matches
  EXPECT_TRUE(WaitFor([&] { return SubscriptionMatches(status) == 1; }));
  Process controller(ControllerArgs(kDomain, Keys("ctl")), Log("ctl"), Env());
  ExpectTheControllersCommandsOnly(node, controller);
  // and it read the status
  void* samples[1] = {};
  dds_sample_info_t info;
  const dds_return_t n = dds_take(status, samples, &info, 1, 1);
  EXPECT_EQ(n, 1);
  if (n > 0) dds_return_loan(status, samples, n);
}

// domain 144: an identity granted the towfish may command it, not the tow vehicle; a
// controller started with it for the tow vehicle stops with the refusal
TEST_F(SecurityTest, SecurityTowfishOnlyControllerCannotCommandTheTowVehicle) {
  constexpr int kDomain = 144;
  Intruder fish(kDomain, Keys("fish"));
  const dds_entity_t towfish = fish.CommandWriter("towfish");
  ASSERT_GT(towfish, 0) << dds_strretcode(towfish);
  const dds_entity_t tow_vehicle = fish.CommandWriter("tow_vehicle");
  EXPECT_EQ(tow_vehicle, DDS_RETCODE_NOT_ALLOWED_BY_SECURITY) << dds_strretcode(tow_vehicle);

  Process node(NodeArgs(kDomain, Keys("sim_node")), Log("node"), Env());
  // the towfish command writer matches the node's reader
  EXPECT_TRUE(WaitFor([&] { return PublicationMatches(towfish) == 1; }));
  Process runner(
      {TOWSIM_MANEUVER_RUNNER, "--maneuver", "case1", "--body", "tow_vehicle", "--domain",
       std::to_string(kDomain), "--timeout", "10", "--security", Keys("fish")},
      Log("runner"), Env());
  ASSERT_TRUE(runner.Wait(kProcessTimeout));
  EXPECT_NE(runner.exit_code(), 0);
  EXPECT_NE(runner.err().find("command writer: Not Allowed By Security"), std::string::npos)
      << runner.err();
  node.Signal(SIGTERM);
  ASSERT_TRUE(node.Wait(kProcessTimeout));
  EXPECT_EQ(CommandsReceived(node.out()), 0) << node.out();
}

// domain 145: refused at start, exit 2, the message names the file and the reason
TEST_F(SecurityTest, SecurityTamperedPermissionsAndExpiredCertificateAreRefusedAtStart) {
  constexpr int kDomain = 145;
  // one byte of the signed permissions changed: "towfish" -> "towfisH"
  fs::copy(keys_ / "fish", keys_ / "tampered", fs::copy_options::recursive);
  const fs::path p7s = keys_ / "tampered/permissions.p7s";
  std::string doc = ReadFile(p7s.string());
  const size_t at = doc.find("towfish/command");
  ASSERT_NE(at, std::string::npos);
  doc[at + 6] = 'H';
  std::ofstream(p7s, std::ios::binary) << doc;
  // an expired certificate; permissions of another permissions CA
  MakeIdentities({"--expired", "old:towfish"}, keys_);
  const fs::path other = tmp_.path() / "other_keys";
  MakeIdentities({"fish:towfish"}, other);
  fs::copy(keys_ / "fish", keys_ / "foreign", fs::copy_options::recursive);
  fs::copy_file(other / "fish/permissions.p7s", keys_ / "foreign/permissions.p7s",
                fs::copy_options::overwrite_existing);

  struct Case {
    std::string identity, file, reason;
  };
  const std::vector<Case> cases = {
      {Keys("tampered"), (keys_ / "tampered/permissions.p7s").string(),
       "its signature does not verify against " + (keys_ / "permissions_ca.pem").string()},
      {Keys("old"), (keys_ / "old/cert.pem").string(), "certificate has expired"},
      {Keys("foreign"), (keys_ / "foreign/permissions.p7s").string(),
       "its signature does not verify against"},
      {Keys("nobody"), "no such directory", ""},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.identity);
    Process node(NodeArgs(kDomain, c.identity), Log("node"), Env());
    ASSERT_TRUE(node.Wait(kProcessTimeout));
    EXPECT_EQ(node.exit_code(), 2);
    const std::string err = node.err();
    EXPECT_NE(err.find("sim_node: error: --security " + c.identity + ": " + c.file),
              std::string::npos)
        << err;
    EXPECT_NE(err.find(c.reason), std::string::npos) << err;
    if (c.identity != Keys("nobody")) {
      EXPECT_NE(err.find("Cyclone refused the participant"), std::string::npos) << err;
    }
  }
  // the other programs stop the same way
  Process depth({TOWSIM_TOWFISH_DEPTH, "--hold", "--domain", std::to_string(kDomain), "--security",
                 Keys("old")},
                Log("depth"), Env());
  Process rec({TOWSIM_RECORD, "--output", Log("rec.mcap"), "--domain", std::to_string(kDomain),
               "--security", Keys("tampered")},
              Log("rec"), Env());
  ASSERT_TRUE(depth.Wait(kProcessTimeout));
  ASSERT_TRUE(rec.Wait(kProcessTimeout));
  EXPECT_EQ(depth.exit_code(), 2);
  EXPECT_NE(depth.err().find("certificate has expired"), std::string::npos) << depth.err();
  EXPECT_EQ(rec.exit_code(), 2);
  EXPECT_NE(rec.err().find("permissions.p7s: its signature does not verify"), std::string::npos)
      << rec.err();
}

// domains 146 (without security: the node's CSV) and 147 (secured node, controller and
// towsim_record): the exported recording equals the unsecured run's CSV
TEST_F(SecurityTest, SecurityRecordedSecuredRunExportsTheSameCsvAsAnUnsecuredRun) {
  // every topic at the CSV output rate, as towsim_export expects (docs/recording.md)
  const std::vector<std::string> rates = {
      "--set", "publish.odom=10",        "--set", "publish.cable_force=10",
      "--set", "publish.cable_state=10", "--set", "publish.status=10"};
  const fs::path plain = tmp_.path() / "plain";
  LockstepRun(146, "", "", plain, rates);

  constexpr int kDomain = 147;
  const std::string mcap = Log("secured.mcap");
  Process rec({TOWSIM_RECORD, "--output", mcap, "--domain", std::to_string(kDomain), "--quiet",
               "--security", Keys("recorder")},
              Log("rec"), Env());
  Process node(NodeArgs(kDomain, Keys("sim_node"), rates), Log("node"), Env());
  WaitFor([&] { return rec.err().find("towsim_record: recording") != std::string::npos; });
  ASSERT_NE(rec.err().find("towsim_record: recording"), std::string::npos) << rec.err();
  Sleep(kDiscoverySeconds);  // the recorder's readers match the node's writers
  Process controller(ControllerArgs(kDomain, Keys("ctl")), Log("ctl"), Env());
  ASSERT_TRUE(node.Wait(kProcessTimeout));
  EXPECT_EQ(node.exit_code(), 0) << node.err();
  ASSERT_TRUE(rec.Wait(kProcessTimeout));
  EXPECT_EQ(rec.exit_code(), 0) << rec.err();
  ASSERT_TRUE(controller.Wait(kProcessTimeout));

  const fs::path exported = tmp_.path() / "exported";
  Process exp({TOWSIM_EXPORT, mcap, "--csv", exported.string()}, Log("export"), Env());
  ASSERT_TRUE(exp.Wait(kProcessTimeout));
  ASSERT_EQ(exp.exit_code(), 0) << exp.err();
  for (const char* f : {"bodies.csv", "cable.csv", "forces.csv"})
    ExpectSameFile(plain / f, exported / f);
  // status.csv: the node writes every 10 Hz row, lockstep publishes the status of every step;
  // each row of the node's (without wall_us, the wall time of a step) is among the exported
  const std::vector<std::string> node_rows =
      Lines(WithoutWallTime(ReadFile((plain / "status.csv").string())));
  const std::vector<std::string> exported_rows =
      Lines(WithoutWallTime(ReadFile((exported / "status.csv").string())));
  EXPECT_EQ(exported_rows.size(), 1u + kSteps + 1u);  // header, steps 0..100
  EXPECT_EQ(node_rows.size(), 1u + 51u);              // header, t = 0, 0.1, ..., 5
  for (const std::string& row : node_rows) {
    EXPECT_NE(std::find(exported_rows.begin(), exported_rows.end(), row), exported_rows.end())
        << row;
  }
}

// domain 148: a DIR made with --open-outputs and a scene with security.open_outputs: a
// participant without a certificate reads the outputs, its commands still reach nothing; the
// controller (DIR/governance.p7s, admitting authenticated participants only) drives as before.
// Without --open-outputs the node refuses the scene key at start.
TEST_F(SecurityTest, SecurityOpenOutputsLetAViewerWithoutCertificateReadButNotCommand) {
  constexpr int kDomain = 148;
  const std::vector<std::string> open = {"--set", "security.open_outputs=true"};
  {
    Process node(NodeArgs(kDomain, Keys("sim_node"), open), Log("closed_node"), Env());
    ASSERT_TRUE(node.Wait(kProcessTimeout));
    EXPECT_EQ(node.exit_code(), 2);
    EXPECT_NE(node.err().find((keys_ / "governance_open.p7s").string() + ": no such file"),
              std::string::npos)
        << node.err();
  }
  const fs::path keys = tmp_.path() / "open_keys";
  MakeIdentities({"--open-outputs", "sim_node", "ctl:tow_vehicle,towfish"}, keys);
  Intruder viewer(kDomain, "");
  const dds_entity_t status = viewer.StatusReader();
  const dds_entity_t command = viewer.CommandWriter("tow_vehicle");
  // forged odometry and run control: refused by the controller (its governance admits
  // authenticated participants only) and by the node (protected payloads)
  const dds_entity_t odom =
      viewer.Writer(&nav_msgs_msg_dds__Odometry__desc, "rt/towsim/tow_vehicle/odom");
  const dds_entity_t control =
      viewer.Writer(&towsim_msgs_msg_dds__SimControl__desc, "rt/towsim/sim_control");
  ASSERT_GT(status, 0);
  ASSERT_GT(command, 0);
  ASSERT_GT(odom, 0);
  ASSERT_GT(control, 0);
  Process node(NodeArgs(kDomain, (keys / "sim_node").string(), open), Log("node"), Env());
  EXPECT_TRUE(WaitFor([&] { return SubscriptionMatches(status) == 1; }));
  Sleep(kDiscoverySeconds);
  EXPECT_EQ(PublicationMatches(command), 0);
  Process controller(ControllerArgs(kDomain, (keys / "ctl").string()), Log("ctl"), Env());
  const Rogue rogue = RogueWhileRunning(node, command, status, {command, odom, control});
  EXPECT_EQ(rogue.most_matches, 0);  // through the whole run
  const long statuses = rogue.statuses;
  ExpectTheControllersCommandsOnly(node, controller);
  // the viewer watched the run: the status of every step (lockstep publishes each one) and
  // of the end
  EXPECT_GE(statuses, kSteps + 1);
  std::printf("[ security ] the viewer without a certificate took %ld statuses of %d steps\n",
              statuses, kSteps);
}

}  // namespace
}  // namespace towsim::testing
