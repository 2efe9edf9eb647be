#pragma once
// Which command each vehicle follows (docs/contract.md §4). Pure logic on simulation time: no
// DDS, no clocks; the node feeds it the ActuatorCommand samples it takes and asks it, before
// each step, what to apply.
//
// Per vehicle:
//   - last writer wins: each valid command replaces the one held;
//   - a command with a NaN or infinite field is rejected (the held one stays), one beyond
//     the vehicle's limits is clamped; both are counted;
//   - failsafe (zero thrust, fins centred) once no valid command has come for
//     `command_timeout` of simulation time, and in lockstep mode when the command of a step
//     did not come in time; it ends with the next valid command. The timeout is armed by the
//     first command: a vehicle no controller ever commanded follows the scene (its initial
//     command and the script);
//   - lockstep: step k (from state k to k + 1) may start once every lockstep vehicle holds a
//     command answering step k. A vehicle that timed out is not waited for until its
//     commands resume.
// Each winch (docs/winch_dds.md) is one more entry, named by the winch (the one winch:
// kWinchName), with the same rules: its
// WinchCommand samples are checked against its limits (dds/winch_command.h), counted with the
// vehicles' commands, held; its failsafe holds the drum at speed 0; lockstep waits for it
// like for a vehicle.
// An external vessel (docs/vessels.md "External vessels") is one more entry, after the
// vehicles and the winch, whose "command" is its pose (nav_msgs/Odometry on
// rt/<ns>/<vessel>/pose_command, dds/vessel_pose_translator.h): checked (non-finite numbers,
// a quaternion that is not a rotation, foreign frames: rejected), counted with the commands,
// the newest by stamp held. A pose belongs to the state nearest its stamp: state
// k = n + round((stamp - t_n) / h) for a pose taken at state n. Lockstep step n waits for a
// pose of state n + 1 (or later), and "step -1" (before the initial state is published) for a
// pose of state 0. A vessel has no failsafe command: in failsafe (no pose for
// `command_timeout`, or a lockstep timeout) and whenever a step has no pose for its end, its
// last pose is carried forward by its rates (core/vessel_motion.h); the steps without their
// pose are counted (poses_missing), and the start of each run of them is the last event.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/vehicle_model.h"
#include "core/vessel_motion.h"
#include "dds/translators.h"
#include "dds/vessel_pose_translator.h"
#include "dds/winch_command.h"

namespace towsim::dds {

// slack on time comparisons (steps of a fixed h land on multiples of h only up to rounding) [s]
inline constexpr double kCommandTimeTolerance = 1e-9;

class CommandArbiter {
 public:
  struct Vehicle {
    Vehicle(std::string vehicle_name, CommandLimits command_limits, bool waited = true)
        : name(std::move(vehicle_name)), limits(command_limits), lockstep(waited) {}
    // a winch's entry, named by the winch (WinchParams::name; the one winch: kWinchName)
    static Vehicle Winch(const core::WinchParams& params, bool waited) {
      Vehicle w(params.name, {}, waited);
      w.winch = true;
      w.winch_params = params;
      return w;
    }
    // an external vessel's entry (its pose_command)
    static Vehicle Vessel(std::string name, bool waited) {
      Vehicle v(std::move(name), {}, waited);
      v.vessel = true;
      return v;
    }
    std::string name;
    CommandLimits limits;
    bool lockstep = true;  // lockstep mode waits for its commands
    bool winch = false;    // the winch's entry: WinchCommand within winch_params' limits
    bool vessel = false;   // an external vessel's entry: its pose
    core::WinchParams winch_params;
  };

  // command_timeout [s] of simulation time, > 0
  CommandArbiter(std::vector<Vehicle> vehicles, double command_timeout);

  // a sample for vehicle v taken at simulation time t [s]; returns the verdict (counted)
  CheckedCommand Receive(int v, const ActuatorCommandMsg& msg, double t);
  // a sample for the winch entry v (Vehicle::winch) taken at simulation time t [s] (counted)
  CheckedWinchCommand Receive(int v, const WinchCommandMsg& msg, double t);
  // a pose for the vessel entry v taken at state `step` (simulation time t [s], steps of h
  // [s]); counted; held if newer (by stamp) than the one held
  CheckedPose Receive(int v, const OdometryMsg& msg, double t, uint64_t step, double h);

  // enters failsafe every vehicle whose last valid command is `command_timeout` or more
  // before t; call at the start of every step. Returns how many entered failsafe.
  int CheckTimeouts(double t);

  // lockstep: every lockstep vehicle that is waited for holds a command answering `step`,
  // every such vessel a pose of state step + 1 or later; step -1: the vessels' poses of state
  // 0 (the vehicles are not waited for)
  bool ReadyFor(int64_t step) const;
  // the vehicles ReadyFor is waiting for (names), for messages
  std::vector<int> Missing(int64_t step) const;
  // lockstep: the wait for `step` timed out: every missing vehicle that has sent a command
  // before, valid or rejected, enters failsafe and is no longer waited for; with
  // `unheard_too`, a vehicle never heard from too (else it is still waited for: its
  // controller may not have started yet). Returns how many timed out.
  int TimeOut(int64_t step, bool unheard_too = false);

  // The command vehicle v must be given before the next step, if any: the failsafe command
  // on every step of a failsafe (so that no script overrides it), a newly received command
  // once. Returns false if nothing is to be set.
  bool Take(int v, core::VehicleCommand* command);
  // the same for the winch entry v: speed 0 on every step of a failsafe
  bool Take(int v, core::WinchCommand* command);
  // the same for the vessel entry v: a newly received pose, once (nothing in failsafe: the
  // last pose is carried forward), its stamp t [s] and the state it belongs to
  bool Take(int v, core::VesselPose* pose, double* t, int64_t* state);

  // before step `step` (state step -> step + 1): every vessel entry without a pose of state
  // step + 1 or later is counted in poses_missing() (its last pose is carried forward);
  // returns how many of them had their pose at the step before (late(v) says which: a run of
  // late steps starts, the node says so once)
  int CountMissingPoses(uint64_t step);
  // vessel entry v had no pose for the end of the last step counted
  bool late(int v) const { return state_[v].late; }

  // back to the start: no command held, nothing in failsafe, counters zero
  void Reset();

  int size() const { return static_cast<int>(vehicles_.size()); }
  const Vehicle& vehicle(int v) const { return vehicles_[v]; }
  bool failsafe(int v) const { return state_[v].failsafe; }
  bool commanded(int v) const { return state_[v].has_command; }
  const core::VehicleCommand& held(int v) const { return state_[v].held; }
  std::vector<std::string> failsafe_names() const;

  uint64_t received() const { return received_; }
  uint64_t rejected() const { return rejected_; }
  uint64_t clamped() const { return clamped_; }
  uint64_t failsafe_count() const { return failsafe_count_; }  // failsafe entries
  uint64_t lockstep_timeouts() const { return lockstep_timeouts_; }
  // steps an external vessel took without a pose for their end (CountMissingPoses)
  uint64_t poses_missing() const { return poses_missing_; }
  // the last clamp / reject / failsafe, for the status message
  const std::string& last_event() const { return last_event_; }
  // why the last entry that entered failsafe did ("no command for 0.5 s of simulation time",
  // "lockstep: no command for step 12 in time"); empty if none since the start (or reset)
  const std::string& last_failsafe_reason() const { return last_failsafe_reason_; }

 private:
  struct State {
    bool has_command = false;  // a valid command came since the start (or reset)
    bool heard = false;        // any command came, valid or rejected
    core::VehicleCommand held;
    core::WinchCommand held_winch;  // the winch's entry
    uint64_t held_step = 0;  // the step the held command answers
    double last_time = 0.0;  // simulation time it came [s]
    bool failsafe = false;
    bool waited_for = true;  // lockstep: false after a lockstep timeout until commands resume
    bool fresh = false;      // held not yet given to the simulation
    // a vessel's entry: the pose held, its stamp [s], the state it belongs to (-1: none)
    core::VesselPose held_pose;
    double held_pose_time = 0.0;
    int64_t held_state = -1;
    bool late = false;  // no pose for the end of the last step counted
  };
  void EnterFailsafe(int v, const std::string& why);
  // entry v holds what `step` needs (ReadyFor's rule for one entry, whether waited for or not)
  bool Answers(int v, int64_t step) const;
  // Take's rule for either kind of command held in s
  template <class Command>
  static bool TakeHeld(State& s, const Command& held, Command* command);
  // counts a checked sample of entry v; true if it is to be held
  bool Count(int v, CheckedCommand::Verdict verdict, const std::string& reason, uint64_t step,
             double t);

  std::vector<Vehicle> vehicles_;
  std::vector<State> state_;
  double command_timeout_;
  uint64_t received_ = 0, rejected_ = 0, clamped_ = 0, failsafe_count_ = 0;
  uint64_t lockstep_timeouts_ = 0;
  uint64_t poses_missing_ = 0;
  std::string last_event_;
  std::string last_failsafe_reason_;
};

}  // namespace towsim::dds
