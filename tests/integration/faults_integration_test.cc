// The faults found by hostile testing, each reproduced through the real binaries (sim_node,
// towsim_record, towsim_export, towsim_replay, the controllers) and, where DDS is involved,
// over loopback DDS (domains 120-139, tests/integration/README.md). Before the fixes these
// runs hung, lost data with exit 0, or ran what was not asked; each test states the finding.

#include <fcntl.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "dds_observer.h"
#include "io/mcap_reader.h"
#include "testing/process.h"

namespace towsim::testing {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const std::string kSource = TOWSIM_SOURCE_DIR;
const std::string kUri = TOWSIM_DDS_URI;
const std::string kCatenary = kSource + "/config/scenes/catenary.yaml";
const std::string kSteadyTow = kSource + "/config/scenes/steady_tow.yaml";
const std::string kCase1 = kSource + "/config/scenes/case1_forward.yaml";
constexpr double kProcessTimeout = 60.0;  // [s] a run that takes longer has hung
// a refused input is refused before any work: well within this on a loaded machine [s]
constexpr double kRefusalTimeout = 10.0;

constexpr uint8_t kFailed = towsim_msgs_msg_dds__SimStatus_Constants_STATE_FAILED;

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
void Sleep(double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); }

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// a directory of the test's own (removed at the end), for logs and files
class FaultsTest : public ::testing::Test {
 public:
  std::string Log(const std::string& name) const { return (dir_ / ("log_" + name)).string(); }

 protected:
  static void SetUpTestSuite() { setenv("CYCLONEDDS_URI", kUri.c_str(), 1); }
  void SetUp() override {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("towsim_faults_" + std::string(info->name()) + "_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }

  // runs argv to its end (kill after `timeout`)
  int Run(const std::vector<std::string>& argv, const std::string& log, std::string* out,
          std::string* err, double timeout = kProcessTimeout) {
    Process p(argv, Log(log));
    const bool exited = p.Wait(timeout);
    EXPECT_TRUE(exited) << p.command_line() << " did not end within " << timeout << " s";
    if (out) *out = p.out();
    if (err) *err = p.err();
    return exited ? p.exit_code() : -1;
  }
  std::string WriteFile(const std::string& name, const std::string& text) const {
    std::ofstream(Path(name)) << text;
    return Path(name);
  }

  fs::path dir_;
};

std::vector<std::string> Node(const std::string& scene, const std::string& mode,
                              std::vector<std::string> extra = {}) {
  std::vector<std::string> a = {TOWSIM_SIM_NODE, "--scene", scene, "--mode", mode};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

std::vector<std::string> WithDomain(std::vector<std::string> a, int domain) {
  a.insert(a.end(), {"--domain", std::to_string(domain)});
  return a;
}

// ---------------------------------------------------------------------------------------------
// Scene loading: `--scene /dev/zero` read until memory ran out (bare std::bad_alloc), a FIFO
// blocked forever, a 50 MB file took minutes and gigabytes, a second YAML document was ignored.

TEST_F(FaultsTest, SceneFilesThatAreNotRegularOrTooLargeAreRefusedBeforeParsing) {
  std::string out, err;
  // a device
  EXPECT_EQ(Run(Node("/dev/zero", "offline"), "zero", &out, &err, kRefusalTimeout), 2);
  EXPECT_TRUE(Contains(err, "scene = /dev/zero")) << err;
  EXPECT_TRUE(Contains(err, "not a regular file")) << err;
  // a FIFO nobody writes to
  const std::string fifo = Path("scene.fifo");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  EXPECT_EQ(Run(Node(fifo, "offline"), "fifo", &out, &err, kRefusalTimeout), 2);
  EXPECT_TRUE(Contains(err, "not a regular file")) << err;
  // 16 MB + 1 byte (sparse: costs no disk)
  const std::string big = Path("big.yaml");
  {
    std::ofstream f(big);
    f << "name: big\n";
  }
  fs::resize_file(big, (16u << 20) + 1);
  EXPECT_EQ(Run(Node(big, "offline"), "big", &out, &err, kRefusalTimeout), 2);
  EXPECT_TRUE(Contains(err, "16777217 bytes: larger than the limit of 16777216 bytes (16 MB)"))
      << err;
  // a model file that is a device
  const std::string scene = WriteFile("model_zero.yaml",
                                      "name: m\n"
                                      "time: {step: 0.05, duration: 1, output_rate: 10}\n"
                                      "cable: {length: 10, elements: 2, diameter: 0.02, "
                                      "density: 1300, youngs_modulus: 1.0e9,\n"
                                      "        start: {fixed: [0, 0, 0]}, end: {body: b}}\n"
                                      "bodies:\n"
                                      "  b: {model: /dev/zero, position: [0, 0, 10]}\n");
  EXPECT_EQ(Run(Node(scene, "offline"), "model", &out, &err, kRefusalTimeout), 2);
  EXPECT_TRUE(Contains(err, "bodies.b.model = /dev/zero (model_zero.yaml:6)")) << err;
  EXPECT_TRUE(Contains(err, "not a regular file")) << err;
}

TEST_F(FaultsTest, MultiDocumentSceneIsRefused) {
  const std::string text = ReadFile(kCatenary);
  const long lines = std::count(text.begin(), text.end(), '\n');
  const std::string scene = WriteFile("two.yaml", text + "---\nname: second\n");
  std::string out, err;
  EXPECT_EQ(Run(Node(scene, "offline"), "two", &out, &err, kRefusalTimeout), 2);
  // the second document starts on the line after the separator
  EXPECT_TRUE(
      Contains(err, "two.yaml = <2 YAML documents> (two.yaml:" + std::to_string(lines + 2) + ")"))
      << err;
  EXPECT_TRUE(Contains(err, "a file must hold one YAML document")) << err;
}

// ---------------------------------------------------------------------------------------------
// E, density or diameter of 1e300 gave exit 3 "initial accelerations could not be computed"
// without naming a key.

TEST_F(FaultsTest, CableMaterialOutsidePhysicalRangesNamesTheKey) {
  struct Case {
    std::string set, message;
  };
  const std::vector<Case> cases = {
      {"cable.youngs_modulus=1e300",
       "cable.youngs_modulus = 1e300 (--set): must be <= 1e+13 Pa (the stiffest material, "
       "diamond, is 1.2e12)"},
      {"cable.density=1e300",
       "cable.density = 1e300 (--set): must be <= 100000 kg/m^3 (the densest material, osmium, "
       "is 2.26e4)"},
      {"cable.diameter=1e300", "cable.diameter = 1e300 (--set): must be <= 10 m"},
  };
  for (const Case& c : cases) {
    std::string out, err;
    EXPECT_EQ(
        Run(Node(kCatenary, "offline", {"--set", c.set}), "range", &out, &err, kRefusalTimeout), 2)
        << c.set;
    EXPECT_TRUE(Contains(err, c.message)) << err;
  }
}

// ---------------------------------------------------------------------------------------------
// `--rate 1e-12` ran unpaced; `--duration 5e17` and `time.step: 1e-300` ran 0 steps with exit 0.

TEST_F(FaultsTest, RateAndStepCountOutsideTheirBoundsAreRefused) {
  std::string out, err;
  EXPECT_EQ(
      Run(Node(kCatenary, "realtime", {"--rate", "1e-12"}), "rate", &out, &err, kRefusalTimeout),
      2);
  EXPECT_TRUE(Contains(err, "--rate 1e-12: the rate must be a number >= 1e-3 and <= 1e6")) << err;
  EXPECT_EQ(Run(Node(kCatenary, "offline", {"--duration", "5e17"}), "duration", &out, &err,
                kRefusalTimeout),
            2);
  EXPECT_TRUE(Contains(err, "--duration 5e+17: must be <= 1e12 steps of time.step = 0.05 s"))
      << err;
  EXPECT_EQ(Run(Node(kCatenary, "offline", {"--set", "time.step=1e-300"}), "step", &out, &err,
                kRefusalTimeout),
            2);
  EXPECT_TRUE(Contains(err, "time.step = 1e-300 (--set): must be >= time.duration / 1e12")) << err;
}

// SET_RATE 1e-300 was taken (the node then ran unpaced): refused, the rate kept, the status
// says why. Domain 120.
TEST_F(FaultsTest, SetRateOutsideItsBoundsIsRefusedAndTheRateKept) {
  constexpr int kDomain = 120;
  Observer watch(kDomain);
  Process node(
      WithDomain(Node(kCatenary, "realtime", {"--rate", "2", "--duration", "30"}), kDomain),
      Log("node"));
  Status running;
  ASSERT_TRUE(watch.WaitFor([](const Status& s) { return s.step > 0; }, &running)) << node.err();
  EXPECT_EQ(running.rate, 2.0);
  watch.Control(towsim_msgs_msg_dds__SimControl_Constants_SET_RATE, 0, 1e-300);
  Status refused;
  ASSERT_TRUE(watch.WaitFor(
      [](const Status& s) { return Contains(s.message, "SET_RATE 1e-300: the rate must be"); },
      &refused))
      << node.err();
  EXPECT_EQ(refused.rate, 2.0);
  node.Signal(SIGINT);
  ASSERT_TRUE(node.Wait(kProcessTimeout));
  EXPECT_EQ(node.exit_code(), 0) << node.err();
}

// ---------------------------------------------------------------------------------------------
// `towfish_depth --depth nan` was accepted and sent NaN; `hello_controller abc` ran on domain
// 0. Each refuses its bad arguments (exit 2) before it creates a DDS participant.

TEST_F(FaultsTest, ControllersValidateTheirOwnArguments) {
  struct Case {
    std::vector<std::string> argv;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{TOWSIM_TOWFISH_DEPTH, "--depth", "nan"}, "--depth nan: must be a finite number"},
      {{TOWSIM_TOWFISH_DEPTH, "--depth", "inf"}, "--depth inf: must be a finite number"},
      {{TOWSIM_TOWFISH_DEPTH, "--depth", "-5"}, "--depth -5: must be >= 0"},
      {{TOWSIM_TOWFISH_DEPTH, "--depth", "20", "--kp", "nan"}, "--kp nan: must be a finite"},
      {{TOWSIM_TOWFISH_DEPTH, "--depth", "20", "--timeout", "inf"}, "--timeout inf: must be a"},
      {{TOWSIM_TOWFISH_DEPTH, "--depth", "20", "--max-elevator-deg", "-5"},
       "--max-elevator-deg -5: must be > 0 and <= 90"},
      {{TOWSIM_TOWFISH_DEPTH, "--hold", "--domain", "233"},
       "--domain 233: must be >= 0 and <= 232"},
      {{TOWSIM_MANEUVER_RUNNER, "--maneuver", "case1", "--timeout", "nan"},
       "--timeout nan: must be a finite number"},
      {{TOWSIM_HELLO_CONTROLLER, "abc"}, "domain = abc: must be a number from 0 to 232"},
      {{TOWSIM_HELLO_CONTROLLER, "0", "nan"}, "thrust_N = nan: must be a number from"},
      {{TOWSIM_HELLO_CONTROLLER, "0", "4165", "inf"}, "heading_deg = inf: must be a number from"},
  };
  for (const Case& c : cases) {
    std::string out, err;
    EXPECT_EQ(Run(c.argv, "controller", &out, &err, kRefusalTimeout), 2) << c.argv.back();
    EXPECT_TRUE(Contains(err, c.message)) << err;
  }
}

// ---------------------------------------------------------------------------------------------
// `--domain 232` ran although Cyclone could not open port 65536+: with config/cyclonedds.xml
// (MaxAutoParticipantIndex 120) the last domain with all its ports is 231.

TEST_F(FaultsTest, DomainWithoutPortsIsRefused) {
  std::string out, err;
  EXPECT_EQ(Run(WithDomain(Node(kCatenary, "fast", {"--duration", "1"}), 232), "domain", &out, &err,
                kRefusalTimeout),
            2);
  EXPECT_TRUE(Contains(err, "--domain 232: its ports go up to 65651 > 65535")) << err;
  EXPECT_TRUE(Contains(err, "MaxAutoParticipantIndex 120): the domain id must be <= 231")) << err;
}

// ---------------------------------------------------------------------------------------------
// One NaN hung a lockstep run: the towfish's controller sent only NaN commands (rejected), and
// a vehicle never validly commanded was waited for without limit. Now it is failsafe after the
// lockstep timeout (1 s) and the run completes. Domain 125.

TEST_F(FaultsTest, RejectedCommandsDoNotHangALockstepRun) {
  constexpr int kDomain = 125;
  Process node(
      WithDomain(Node(kCase1, "lockstep", {"--duration", "1", "--set", "script=[]"}), kDomain),
      Log("node"));
  Process controller({TOWSIM_TEST_CONTROLLER, "--domain", std::to_string(kDomain), "--command",
                      "towfish@0=nan,nan,nan"},
                     Log("controller"));
  ASSERT_TRUE(node.Wait(kProcessTimeout)) << "the node hung: " << node.err();
  EXPECT_EQ(node.exit_code(), 0) << node.err();
  ASSERT_TRUE(controller.Wait(kProcessTimeout));
  EXPECT_EQ(controller.exit_code(), 0) << controller.err();
  // 20 steps (1 s at h = 0.05); the towfish timed out once and stayed in failsafe
  const std::string out = node.out();
  EXPECT_TRUE(Contains(out, "lockstep, 20 steps")) << out;
  EXPECT_TRUE(Contains(out, "failsafes 1,")) << out;
  EXPECT_TRUE(Contains(out, "lockstep timeouts 1,")) << out;
  EXPECT_TRUE(Contains(node.err(), "towfish: failsafe (lockstep: no valid command for step 0"))
      << node.err();
}

// ---------------------------------------------------------------------------------------------
// Ctrl-C was ignored during the static solve (10 s for 2000 elements). The solve asks for the
// stop request before every iteration: the node ends within one iteration (~0.1 s here for
// 2000 elements; kStopMargin for a loaded machine) instead of after the whole solve (~7 s).

constexpr double kStopMargin = 2.0;  // [s]

TEST_F(FaultsTest, SigintStopsTheStaticSolve) {
  for (const std::string mode : {"offline", "fast"}) {
    Process node(WithDomain(Node(kCatenary, mode, {"--set", "cable.elements=2000"}), 131),
                 Log(mode));
    Sleep(1.0);  // handlers installed, the solve under way
    ASSERT_TRUE(node.running()) << node.err();
    node.Signal(SIGINT);
    const Clock::time_point sent = Clock::now();
    ASSERT_TRUE(node.Wait(kProcessTimeout));
    EXPECT_LT(Seconds(Clock::now() - sent), kStopMargin) << mode;
    EXPECT_EQ(node.exit_code(), mode == "offline" ? 130 : 0) << node.err();
    EXPECT_TRUE(Contains(node.err(), "stopped during the static solve after")) << node.err();
  }
}

// ---------------------------------------------------------------------------------------------
// Two writers on one .mcap both exited 0 and ruined the file. A recording is created
// exclusively (exit 2 if it exists, unless --overwrite) and locked while written. Domains 121,
// 122.

TEST_F(FaultsTest, ExistingRecordingIsRefusedUnlessOverwrite) {
  constexpr int kDomain = 121;
  const std::string file = WriteFile("old.mcap", "an older recording");
  std::string out, err;
  EXPECT_EQ(Run(WithDomain(Node(kCatenary, "fast", {"--duration", "1", "--record", file}), kDomain),
                "node", &out, &err),
            2);
  EXPECT_TRUE(Contains(err, "--record " + file + ": " + file +
                                " exists: a recording is not replaced (--overwrite replaces it)"))
      << err;
  EXPECT_EQ(ReadFile(file), "an older recording");
  EXPECT_EQ(Run({TOWSIM_RECORD, "--output", file, "--domain", std::to_string(kDomain)}, "rec", &out,
                &err, kRefusalTimeout),
            2);
  EXPECT_TRUE(Contains(err, "--output " + file + ": " + file + " exists")) << err;
  EXPECT_EQ(ReadFile(file), "an older recording");
  // --overwrite replaces it with a complete recording
  EXPECT_EQ(
      Run(WithDomain(Node(kCatenary, "fast", {"--duration", "1", "--record", file, "--overwrite"}),
                     kDomain),
          "node2", &out, &err),
      0)
      << err;
  EXPECT_EQ(Run({TOWSIM_EXPORT, file, "--info"}, "info", &out, &err), 0) << err;
  EXPECT_TRUE(Contains(out, "/towsim/status")) << out;
}

TEST_F(FaultsTest, SecondWriterOnARecordingIsRefused) {
  constexpr int kDomain = 122;
  const std::string file = Path("run.mcap");
  Observer watch(kDomain);
  Process first(WithDomain(Node(kSteadyTow, "realtime", {"--record", file}), kDomain),
                Log("first"));
  ASSERT_TRUE(watch.WaitFor([](const Status& s) { return s.step > 0; }, nullptr)) << first.err();
  std::string out, err;
  // neither another node nor a recorder, even with --overwrite
  EXPECT_EQ(Run(WithDomain(Node(kCatenary, "fast",
                                {"--duration", "1", "--record", file, "--overwrite", "--namespace",
                                 "/second"}),
                           kDomain),
                "second", &out, &err),
            2);
  EXPECT_TRUE(Contains(err, file + " is being written by another process")) << err;
  EXPECT_EQ(Run({TOWSIM_RECORD, "--output", file, "--overwrite", "--domain",
                 std::to_string(kDomain), "--duration", "1"},
                "rec", &out, &err),
            2);
  EXPECT_TRUE(Contains(err, file + " is being written by another process")) << err;
  first.Signal(SIGINT);
  ASSERT_TRUE(first.Wait(kProcessTimeout));
  EXPECT_EQ(first.exit_code(), 0) << first.err();
  // the first writer's file is complete: every CRC holds, no recovery needed
  EXPECT_EQ(Run({TOWSIM_EXPORT, file, "--info"}, "info", &out, &err), 0) << err;
}

// ---------------------------------------------------------------------------------------------
// Disk full while recording or writing CSV in a DDS mode: the node exited 1 with no summary
// and no final status, so controllers waited 30 s for a step that never came. An output
// failure ends the run (docs/command_line.md "Exit codes"): the last SimStatus is FAILED with
// the reason, the summary is printed, exit 1; the controller ends at once. At start, a full
// disk is exit 1 too (it was 2, "bad input"). A small tmpfs of the test's own is the full disk.

// a tmpfs of `kilobytes` mounted on a directory, unmounted at the end (the test runs as root,
// as CI does)
class SmallDisk {
 public:
  SmallDisk(const std::string& dir, int kilobytes) : dir_(dir) {
    fs::create_directories(dir);
    const std::string options = "size=" + std::to_string(kilobytes) + "k";
    mounted_ = mount("towsim_faults", dir.c_str(), "tmpfs", 0, options.c_str()) == 0;
    if (!mounted_) error_ = std::strerror(errno);
  }
  ~SmallDisk() {
    if (mounted_) umount2(dir_.c_str(), MNT_DETACH);
  }
  bool mounted() const { return mounted_; }
  const std::string& error() const { return error_; }
  // fills it up: a file of every byte left
  void Fill() const {
    std::FILE* f = std::fopen((dir_ + "/filler").c_str(), "w");
    ASSERT_NE(f, nullptr);
    const std::string block(4096, 'x');
    while (std::fwrite(block.data(), 1, block.size(), f) == block.size() && std::fflush(f) == 0) {
    }
    std::fclose(f);
  }

 private:
  std::string dir_;
  bool mounted_ = false;
  std::string error_;
};

TEST_F(FaultsTest, DiskFullAtStartIsExit1) {
  const SmallDisk disk(Path("disk"), 64);
  ASSERT_TRUE(disk.mounted()) << "mount tmpfs: " << disk.error() << " (the test needs root)";
  disk.Fill();
  std::string out, err;
  EXPECT_EQ(Run(Node(kCatenary, "offline", {"--csv", Path("disk/csv")}), "offline", &out, &err), 1);
  EXPECT_TRUE(Contains(err, "No space left on device")) << err;
  EXPECT_EQ(
      Run(WithDomain(
              Node(kCatenary, "fast", {"--duration", "1", "--record", Path("disk/run.mcap")}), 132),
          "fast", &out, &err),
      1);
  EXPECT_TRUE(Contains(err, "--record " + Path("disk/run.mcap"))) << err;
  EXPECT_TRUE(Contains(err, "No space left on device")) << err;
}

// the node with its output on a 256 KiB disk, a controller in lockstep: the node ends FAILED
// when the output fills the disk; `what` is "--record" or "--csv"
void DiskFullEndsTheRun(FaultsTest* test, const std::string& what, int domain,
                        const std::string& path) {
  Observer watch(domain);
  Process node(WithDomain(Node(kCase1, "lockstep", {what, path, "--set", "script=[]"}), domain),
               test->Log("node"));
  Process controller({TOWSIM_TEST_CONTROLLER, "--domain", std::to_string(domain)},
                     test->Log("controller"));
  ASSERT_TRUE(node.Wait(kProcessTimeout)) << node.err();
  EXPECT_EQ(node.exit_code(), 1) << node.err();
  // the summary line, and the failure on stderr
  EXPECT_TRUE(Contains(node.out(), "sim_node: case1_forward: lockstep, ")) << node.out();
  EXPECT_TRUE(Contains(node.err(), "output failed: ")) << node.err();
  EXPECT_TRUE(Contains(node.err(), "No space left on device")) << node.err();
  // the controller saw the end (it would have waited its 30 s timeout and exited 1)
  const Clock::time_point ended = Clock::now();
  ASSERT_TRUE(controller.Wait(kProcessTimeout));
  EXPECT_LT(Seconds(Clock::now() - ended), 5.0);
  EXPECT_EQ(controller.exit_code(), 0) << controller.err();
  // the last status: FAILED with the reason
  Status last;
  ASSERT_TRUE(watch.WaitFor([](const Status& s) { return s.state == kFailed; }, &last));
  EXPECT_TRUE(Contains(last.message, "output failed: ")) << last.message;
  EXPECT_TRUE(Contains(last.message, "No space left on device")) << last.message;
}

TEST_F(FaultsTest, DiskFullWhileRecordingEndsTheRunFailed) {
  const SmallDisk disk(Path("disk"), 256);
  ASSERT_TRUE(disk.mounted()) << "mount tmpfs: " << disk.error() << " (the test needs root)";
  DiskFullEndsTheRun(this, "--record", 123, Path("disk/run.mcap"));
}

TEST_F(FaultsTest, DiskFullWhileWritingCsvEndsTheRunFailed) {
  const SmallDisk disk(Path("disk"), 256);
  ASSERT_TRUE(disk.mounted()) << "mount tmpfs: " << disk.error() << " (the test needs root)";
  DiskFullEndsTheRun(this, "--csv", 124, Path("disk/csv"));
}

// a sweep whose folder fills the disk: its error was glued to the progress line
// ("... about 0m03s left   towsim_sweep: error: ..."); now it starts on its own line
TEST_F(FaultsTest, SweepDiskFullErrorStartsOnItsOwnLine) {
  const SmallDisk disk(Path("disk"), 256);
  ASSERT_TRUE(disk.mounted()) << "mount tmpfs: " << disk.error() << " (the test needs root)";
  const std::string file = WriteFile("sweep.yaml", "scene: " + kCase1 +
                                                       "\nduration: 400\nparameters:\n"
                                                       "  cable.elements: [10, 11, 12, 13, 14]\n");
  std::string out, err;
  EXPECT_EQ(Run({TOWSIM_SWEEP, file, "--out", Path("disk/sweep"), "--workers", "1"}, "sweep", &out,
                &err),
            1);
  // the progress line was drawn, then ended before the error (the first case's status)
  EXPECT_TRUE(Contains(err, "[towsim_sweep] 0/5 cases done, 0 failed, 1 running, about -- left"))
      << err;
  EXPECT_TRUE(Contains(err, "left   \ntowsim_sweep: error: " +
                                Path("disk/sweep/case_0000/case_status.txt.tmp") +
                                ": write failed (disk full?)\n"))
      << err;
}

// ---------------------------------------------------------------------------------------------
// `towsim_export --recover` on a file with one flipped byte in chunk 2 exited 0 with the rows of
// chunk 1 only; a flipped header length recovered nothing, also with exit 0. Now every intact
// chunk is kept, the skipped byte ranges are on stderr with their message counts, and the exit
// code is 4. towsim_replay --recover the same. Domains 126 (the run), 127 (the replay).

// the number of rows in a CSV file, without the header
long CsvRows(const std::string& path) {
  const std::string text = ReadFile(path);
  return static_cast<long>(std::count(text.begin(), text.end(), '\n')) - 1;
}

TEST_F(FaultsTest, RecoverKeepsEveryIntactChunkAndReportsTheLoss) {
  // 3 s of wall time: a chunk every 0.5 s
  const std::string good = Path("good.mcap");
  std::string out, err;
  ASSERT_EQ(Run(WithDomain(Node(kSteadyTow, "realtime",
                                {"--rate", "20", "--duration", "60", "--record", good}),
                           126),
                "node", &out, &err),
            0)
      << err;
  const io::McapReader intact = io::McapReader::Open(good);
  ASSERT_GE(intact.chunk_indexes().size(), 4u);
  // the reference: the intact file's export, and the odometry messages of chunk 2
  ASSERT_EQ(Run({TOWSIM_EXPORT, good, "--csv", Path("good")}, "export_good", &out, &err), 0) << err;
  const long good_rows = CsvRows(Path("good/bodies.csv"));
  const io::McapChunkIndex chunk = intact.chunk_indexes()[1];
  uint64_t odom_in_chunk = 0, all_in_chunk = 0;
  for (const io::McapMessage& m : intact.ReadMessages()) {
    if (m.log_time < chunk.message_start_time || m.log_time > chunk.message_end_time) continue;
    ++all_in_chunk;
    odom_in_chunk += Contains(intact.channels().at(m.channel_id).topic, "/odom");
  }
  ASSERT_GT(odom_in_chunk, 0u);

  // one flipped byte in the middle of chunk 2
  std::string bytes = ReadFile(good);
  bytes[chunk.chunk_start_offset + chunk.chunk_length / 2] ^= 0x10;
  const std::string damaged = WriteFile("damaged.mcap", bytes);
  EXPECT_EQ(Run({TOWSIM_EXPORT, damaged, "--csv", Path("damaged"), "--recover"}, "export_damaged",
                &out, &err),
            4);
  EXPECT_TRUE(Contains(err, "skipped bytes " + std::to_string(chunk.chunk_start_offset) + "-" +
                                std::to_string(chunk.chunk_start_offset + chunk.chunk_length)))
      << err;
  EXPECT_TRUE(Contains(err, std::to_string(all_in_chunk) + " messages by its message indexes"))
      << err;
  EXPECT_TRUE(Contains(err, "chunk CRC mismatch")) << err;
  // every row but those of the damaged chunk's odometry
  EXPECT_EQ(CsvRows(Path("damaged/bodies.csv")), good_rows - static_cast<long>(odom_in_chunk));

  // a flipped header length: everything after the header is recovered
  std::string header = ReadFile(good);
  header[9] ^= 0x40;
  const std::string bad_header = WriteFile("header.mcap", header);
  EXPECT_EQ(Run({TOWSIM_EXPORT, bad_header, "--csv", Path("header"), "--recover"}, "export_header",
                &out, &err),
            4);
  EXPECT_TRUE(Contains(err, "skipped bytes 8-")) << err;
  EXPECT_EQ(CsvRows(Path("header/bodies.csv")), good_rows);

  // the replay of the damaged file sends every message of the intact chunks
  const uint64_t total = intact.statistics().message_count;
  EXPECT_EQ(Run({TOWSIM_REPLAY, damaged, "--fast", "--recover", "--delay", "0", "--quiet",
                 "--domain", "127"},
                "replay", &out, &err),
            4);
  EXPECT_TRUE(Contains(out, "towsim_replay: " + std::to_string(total - all_in_chunk) + " messages"))
      << out;
  EXPECT_TRUE(Contains(err, "skipped bytes " + std::to_string(chunk.chunk_start_offset))) << err;
  // without --recover it is refused, as before
  EXPECT_EQ(Run({TOWSIM_REPLAY, damaged, "--fast", "--domain", "127"}, "replay_plain", &out, &err),
            2);
}

// ---------------------------------------------------------------------------------------------
// An 8-byte file (the MCAP magic alone): towsim_replay --recover exited 4, towsim_export
// --recover 2. Nothing survives, so both refuse it as bad input (2), saying so. Domain 127.

TEST_F(FaultsTest, RecoverWithNothingToRecoverIsBadInputForBothTools) {
  const std::string magic = WriteFile("magic.mcap", std::string("\x89MCAP0\r\n", 8));
  const std::string expected = magic + ": nothing to recover: no intact chunk (no message " +
                               "survives the 1 byte ranges skipped)";
  std::string out, err;
  EXPECT_EQ(Run({TOWSIM_EXPORT, magic, "--csv", Path("magic"), "--recover"}, "export_magic", &out,
                &err),
            2);
  EXPECT_TRUE(Contains(err, "towsim_export: error: " + expected)) << err;
  EXPECT_FALSE(fs::exists(Path("magic")));
  EXPECT_EQ(Run({TOWSIM_REPLAY, magic, "--fast", "--recover", "--delay", "0", "--domain", "127"},
                "replay_magic", &out, &err),
            2);
  EXPECT_TRUE(Contains(err, "towsim_replay: error: " + expected)) << err;
  // eight bytes that are not the magic: not an MCAP file, 2 for both as before
  const std::string junk = WriteFile("junk.mcap", "01234567");
  EXPECT_EQ(Run({TOWSIM_EXPORT, junk, "--info", "--recover"}, "export_junk", &out, &err), 2);
  EXPECT_TRUE(Contains(err, "not an MCAP file: bad leading magic")) << err;
  EXPECT_EQ(Run({TOWSIM_REPLAY, junk, "--recover", "--domain", "127"}, "replay_junk", &out, &err),
            2);
  EXPECT_TRUE(Contains(err, "not an MCAP file: bad leading magic")) << err;
}

// ---------------------------------------------------------------------------------------------
// Two sim_nodes on the same domain and namespace both ran: controllers drove both, status
// samples interleaved. The second is refused (exit 2, naming the first's run id), or runs with
// --allow-another-node and a warning in the status; the first reports it too. Domain 128.

TEST_F(FaultsTest, SecondNodeInTheNamespaceIsRefusedOrWarned) {
  constexpr int kDomain = 128;
  Observer watch(kDomain);
  Process first(WithDomain(Node(kSteadyTow, "realtime"), kDomain), Log("first"));
  Status running;
  ASSERT_TRUE(watch.WaitFor([](const Status& s) { return s.step > 0; }, &running)) << first.err();
  std::string out, err;
  EXPECT_EQ(
      Run(WithDomain(Node(kCatenary, "fast", {"--duration", "1"}), kDomain), "second", &out, &err),
      2);
  EXPECT_TRUE(Contains(err, "another sim_node runs on DDS domain 128, namespace /towsim (run id " +
                                running.run_id + ")"))
      << err;
  EXPECT_TRUE(Contains(err, "--allow-another-node")) << err;
  // another namespace is another system
  EXPECT_EQ(
      Run(WithDomain(Node(kCatenary, "fast", {"--duration", "1", "--namespace", "/b"}), kDomain),
          "other_ns", &out, &err),
      0)
      << err;
  // run anyway (1 s of wall time, for the first node and the observer to see it): warned in
  // its status and summary, and the first node warns too
  EXPECT_EQ(Run(WithDomain(Node(kCatenary, "realtime", {"--duration", "1", "--allow-another-node"}),
                           kDomain),
                "allowed", &out, &err),
            0)
      << err;
  EXPECT_TRUE(Contains(out, "other nodes in the namespace: run id " + running.run_id)) << out;
  Status warned;
  EXPECT_TRUE(watch.WaitFor(
      [&](const Status& s) {
        return s.run_id != running.run_id &&
               Contains(s.message, "warning: another node runs on DDS domain 128") &&
               Contains(s.message, running.run_id);
      },
      &warned));
  EXPECT_TRUE(watch.WaitFor(
      [&](const Status& s) {
        return s.run_id == running.run_id && Contains(s.message, "warning: another node runs");
      },
      nullptr));
  first.Signal(SIGINT);
  ASSERT_TRUE(first.Wait(kProcessTimeout));
  EXPECT_EQ(first.exit_code(), 0) << first.err();
  EXPECT_TRUE(Contains(first.out(), "other nodes in the namespace: run id catenary-"))
      << first.out();
}

// ---------------------------------------------------------------------------------------------
// A command on an unknown body's topic (ghost/command) was ignored without a word, although
// ActuatorCommand.msg says rejected commands are counted. Now counted as received and
// rejected, named in the status and the summary. Domain 130.

TEST_F(FaultsTest, CommandsOnAnUnknownBodysTopicAreCountedAsRejected) {
  constexpr int kDomain = 130;
  Observer watch(kDomain);
  Process node(WithDomain(Node(kSteadyTow, "realtime"), kDomain), Log("node"));
  ASSERT_TRUE(watch.WaitFor([](const Status& s) { return s.step > 0; }, nullptr)) << node.err();
  // the node's reader for it matches (the observer waits for that), then three commands; the
  // steady tow's towfish is a sphere: it takes no commands either
  // (one at a time: the writer keeps the last sample only)
  Status counted;
  for (uint64_t i = 1; i <= 4; ++i) {
    watch.Command(i <= 3 ? "ghost" : "towfish", 0, 100.0, 0.0, 0.0);
    ASSERT_TRUE(watch.WaitFor([i](const Status& s) { return s.commands_rejected == i; }, &counted))
        << node.err();
  }
  EXPECT_EQ(counted.commands_received, 4u);
  EXPECT_TRUE(Contains(counted.message, "command rejected (no body ")) << counted.message;
  node.Signal(SIGINT);
  ASSERT_TRUE(node.Wait(kProcessTimeout));
  EXPECT_TRUE(Contains(node.out(), "commands 4 (rejected 4, clamped 0)")) << node.out();
  EXPECT_TRUE(Contains(node.err(),
                       "ghost: command rejected (no body ghost that takes commands in this scene)"))
      << node.err();
}

// ---------------------------------------------------------------------------------------------
// A cable stretched beyond any material ran without a word. The largest strain beyond 20 % is
// reported on stderr, in the summary and (DDS) in the status. The reference: E = 4e6 Pa gives
// EA = 4e6 Pa x pi (0.0205 m)^2 = 5.28e3 N; the weights alone (half the cable's 712 N in water
// and the sphere's 2.07 kN) would stretch it by 46 %, below the 50 % the scene loader refuses,
// and towing pulls it beyond 20 % within 0.3 s (23 %; 25 % at 5 s). The shipped E = 7e8 Pa stays
// at 1e-4 and gets no warning. Domain 133.

TEST_F(FaultsTest, ExtremeCableStrainIsReported) {
  std::string out, err;
  ASSERT_EQ(
      Run(Node(kSteadyTow, "offline", {"--duration", "5", "--set", "cable.youngs_modulus=4e6"}),
          "offline", &out, &err),
      0)
      << err;
  EXPECT_TRUE(Contains(out, ", max cable strain ")) << out;
  EXPECT_TRUE(Contains(out, "extreme (> 0.2)")) << out;
  EXPECT_TRUE(Contains(err, "warning: cable strain ")) << err;
  EXPECT_TRUE(Contains(err, "check cable.youngs_modulus")) << err;
  ASSERT_EQ(Run(Node(kSteadyTow, "offline", {"--duration", "5"}), "shipped", &out, &err), 0) << err;
  EXPECT_FALSE(Contains(out, "cable strain")) << out;
  EXPECT_FALSE(Contains(err, "cable strain")) << err;

  constexpr int kDomain = 133;
  Observer watch(kDomain);
  Process node(
      WithDomain(Node(kSteadyTow, "realtime", {"--rate", "5", "--set", "cable.youngs_modulus=4e6"}),
                 kDomain),
      Log("node"));
  Status warned;
  ASSERT_TRUE(watch.WaitFor(
      [](const Status& s) { return Contains(s.message, "warning: cable strain "); }, &warned))
      << node.err();
  node.Signal(SIGINT);
  ASSERT_TRUE(node.Wait(kProcessTimeout));
  EXPECT_EQ(node.exit_code(), 0) << node.err();
  EXPECT_TRUE(Contains(node.out(), "extreme (> 0.2)")) << node.out();
}

}  // namespace
}  // namespace towsim::testing
