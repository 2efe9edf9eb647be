// An independent Foxglove client of a live towsim node (docs/foxglove.md), built on
// @foxglove/ws-protocol (FoxgloveClient) over the `ws` WebSocket, decoding with
// @foxglove/rosmsg + @foxglove/rosmsg2-serialization from the schemas the server advertises:
//   node live_check.mjs SIM_NODE TOWSIM_FOXGLOVE SOURCE_DIR OUT_DIR DOMAIN [in-node] [winch]
// It starts and stops the processes itself (also when it fails):
//   1. sim_node: Case 1 in lockstep for 10 s without its script, --csv OUT_DIR/csv;
//   2. towsim_foxglove --domain DOMAIN --port 0 (a free port, read from its first line); or,
//      with `in-node`, no bridge: sim_node --foxglove 0 serves the same itself;
//   3. this client: serverInfo (clientPublish, time, cdr), every channel cdr / ros2msg,
//      subscribes to all of them and decodes every message; it is the lockstep controller of
//      both vehicles through clientPublish (ActuatorCommand answering each status step): zero
//      thrust up to kThrustStep, then 4165 N. At kBadStep it first sends a malformed command
//      (truncated CDR: the bridge rejects and counts it, an error status comes back) and a
//      NaN thrust (the node rejects and counts it: SimStatus.commands_rejected). At
//      kTeleopStep the tow vehicle's answer is a geometry_msgs/Twist, as Foxglove's Teleop panel
//      sends (the bridge turns it into the command answering the newest status).
// Then: the odometry decoded from the WebSocket equals the node's bodies.csv row for row
// (every CSV row at t > 0 has its message; 9 significant digits, as decode_recording.mjs);
// the tow vehicle at rest until the thrust comes and moving after it; time messages are
// /clock's stamps; the bridge's summary counts the malformed message.
// With `winch`, Case 1 gets a winch at the cable's start (--set cable.winch, 150 m to 260 m,
// 1 m/s, 0.5 m/s^2) and this client is also the winch's lockstep controller through
// clientPublish on /towsim/winch/command (towsim_msgs/msg/WinchCommand, docs/winch_dds.md):
// speed 0 up to kWinchStep, then 1 m/s; at kBadStep a truncated WinchCommand (the bridge
// rejects it) and a NaN speed (the node rejects it) first. Then paid_out_length in the decoded
// CableState equals the node's winch.csv row for row, and at the end the drum's kinematics:
// 200 m + v^2 / (2 a) + v (T - t_on - v / a) = 204 m. Without `winch`, advertising
// /towsim/winch/command is refused (an error status names the topic).
// As Foxglove's 3D panel does when it opens, the client also advertises /move_base_simple/goal,
// /clicked_point and /initialpose and sends a clicked point: taken and ignored, no error status
// names them (docs/foxglove.md "Publishing from Foxglove").
// Exits 77 (ctest: skipped) when the node modules are missing: run `npm ci` in this folder.
import { mkdirSync, readFileSync, rmSync } from "node:fs";
import { join } from "node:path";

import { check, failures, near, readCsv } from "../js_common/checks.mjs";
import { children, loadModules, resolvePath, splitPath, start, stopAll } from "./client_common.mjs";

const { WebSocket, FoxgloveClient, parseMessageDefinition, MessageReader, MessageWriter } = await loadModules();

const [simNode, bridgeExe, sourceDir, outDir, domainText, ...flags] = process.argv.slice(2);
const inNode = flags.includes("in-node");
const withWinch = flags.includes("winch");
const kDuration = 10; // [s] simulated
const kThrustStep = 20; // the first step answered with thrust
const kBadStep = 60; // the step whose answer is preceded by a malformed and a NaN command
const kTeleopStep = 80; // the step the tow vehicle is answered with a Twist (Teleop panel)
const kThrust = 4165; // [N] Case 1
const kBadAnswerDelay = 200; // [ms] between the NaN command and the good one
const kTimeout = 60e3; // [ms] the whole check; a run that takes longer has hung
const kAtRest = 0.05; // [m/s] |u| of the tow vehicle before any thrust (the cable's pull)
const kMoving = 0.5; // [m/s] u after 7 s of 4165 N (Case 1 reaches 6 m/s)
// the winch (`winch`): the drum from 200 m, at kWinchSpeed from kWinchStep
const kWinch = "{min_length: 150, max_length: 260, max_speed: 1, max_acceleration: 0.5}";
const kWinchStep = 100; // t = 5 s
const kWinchSpeed = 1; // [m/s], the drum's max_speed
const kWinchAcceleration = 0.5; // [m/s^2]
const kWinchSpeedMode = 0; // WinchCommand.SPEED
// the drum's length is the exact integral of its piecewise constant acceleration (trapezoids
// of the speed, which ramps by a h a step): round-off only
const kLengthRelTol = 1e-12;

rmSync(outDir, { recursive: true, force: true });
mkdirSync(outDir, { recursive: true });
const deadline = setTimeout(() => {
  console.error("FAIL: timed out");
  console.error(`received: ${[...byTopic.entries()].map(([t, v]) => `${t} ${v.length}`).join(", ")}; ` +
    `statuses ${JSON.stringify(statuses)}; steps answered ${answered.size}`);
  for (const c of children) console.error(`${c.name} stderr:\n${c.err}`);
  stopAll();
  process.exit(1);
}, kTimeout);

const node = start(
  [simNode, "--scene", join(sourceDir, "config/scenes/case1_forward.yaml"), "--mode", "lockstep",
    "--duration", String(kDuration), "--domain", domainText, "--csv", join(outDir, "csv"),
    "--set", "script=[]", ...(inNode ? ["--foxglove", "0"] : []),
    ...(withWinch ? ["--set", `cable.winch=${kWinch}`] : [])],
  "sim_node",
);
const bridge = inNode ? node : start([bridgeExe, "--domain", domainText, "--port", "0"], "towsim_foxglove");
const url = await new Promise((resolve, reject) => {
  const poll = setInterval(() => {
    const m = bridge.out.match(inNode ? /Foxglove at (ws:\/\/\S+)/ : /serving (ws:\/\/[^ ]+) /);
    if (m) {
      clearInterval(poll);
      resolve(m[1]);
    } else if (bridge.exitCode !== null) {
      clearInterval(poll);
      reject(new Error(`towsim_foxglove exited ${bridge.exitCode}: ${bridge.err}`));
    }
  }, 20);
});

// --- the client ---
console.error(`connecting to ${url} (${inNode ? "sim_node --foxglove" : "towsim_foxglove"})`);
const client = new FoxgloveClient({ ws: new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]) });
let serverInfo;
const channels = new Map(); // channel id -> {topic, reader}
const subscriptions = new Map(); // subscription id -> channel id
const byTopic = new Map(); // topic -> [{timestamp, value}]
const times = [];
const statuses = [];
let trailingSize = 0; // the size of the command sent with 8 bytes after it
let decodeFailures = 0;
const commandChannels = new Map(); // body -> client channel id
let commandWriter;
let teleopChannel;
let winchChannel;
let winchWriter;
let panelAdvertised = false;
// the 3D panel's publish tools (its "publish" settings in the layout) and their schemas
const kPanelTopics = {
  "/move_base_simple/goal": "geometry_msgs/msg/PoseStamped",
  "/clicked_point": "geometry_msgs/msg/PointStamped",
  "/initialpose": "geometry_msgs/msg/PoseWithCovarianceStamped",
};
// a geometry_msgs/msg/PointStamped, as the panel's point tool sends it
const clickedPoint = new MessageWriter(parseMessageDefinition(
  "std_msgs/Header header\ngeometry_msgs/Point point\n" +
  "================================================================================\n" +
  "MSG: std_msgs/Header\nbuiltin_interfaces/Time stamp\nstring frame_id\n" +
  "================================================================================\n" +
  "MSG: geometry_msgs/Point\nfloat64 x\nfloat64 y\nfloat64 z\n", { ros2: true }))
  .writeMessage({ header: { stamp: { sec: 1, nanosec: 0 }, frame_id: "world" }, point: { x: 1, y: 2, z: 3 } });
// geometry_msgs/Twist as Foxglove's Teleop panel sends it, with the official definitions
const twistWriter = new MessageWriter(parseMessageDefinition(
  "geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n================================================================================\nMSG: geometry_msgs/Vector3\nfloat64 x\nfloat64 y\nfloat64 z\n",
  { ros2: true }));
const answered = new Set();

function winchCommand(step, speed) {
  return { header: { stamp: { sec: 0, nanosec: 0 }, frame_id: "" }, step: BigInt(step), mode: kWinchSpeedMode, value: speed };
}

function command(step, thrust) {
  return {
    header: { stamp: { sec: 0, nanosec: 0 }, frame_id: "" },
    step: BigInt(step),
    thrust,
    rudder: 0,
    elevator: 0,
  };
}

const finished = new Promise((resolve) => {
  client.on("serverInfo", (info) => (serverInfo = info));
  client.on("status", (s) => statuses.push(s));
  client.on("time", (t) => times.push(t.timestamp));
  client.on("advertise", (list) => {
    if (!panelAdvertised) {
      panelAdvertised = true;
      for (const [topic, schemaName] of Object.entries(kPanelTopics)) {
        const id = client.advertise({ topic, encoding: "cdr", schemaName });
        if (topic === "/clicked_point") client.sendMessage(id, clickedPoint);
      }
    }
    if (!withWinch && winchChannel === undefined) {
      // a scene without a winch: its command topic is refused (an error status names it)
      winchChannel = client.advertise({ topic: "/towsim/winch/command", encoding: "cdr", schemaName: "towsim_msgs/msg/WinchCommand" });
    }
    for (const c of list) {
      check(c.encoding === "cdr" && c.schemaEncoding === "ros2msg", `${c.topic}: encoding ${c.encoding} / ${c.schemaEncoding}`);
      const definitions = parseMessageDefinition(c.schema, { ros2: true });
      channels.set(c.id, { topic: c.topic, reader: new MessageReader(definitions), schemaName: c.schemaName });
      subscriptions.set(client.subscribe(c.id), c.id);
      const m = c.topic.match(/^\/towsim\/([^/]+)\/command$/);
      // winch/command is the winch's own command type, not a body's (docs/winch_dds.md)
      if (m && m[1] === "winch") {
        check(c.schemaName === "towsim_msgs/msg/WinchCommand", `${c.topic} schema ${c.schemaName}`);
        if (withWinch) {
          winchWriter = new MessageWriter(definitions);
          winchChannel = client.advertise({ topic: c.topic, encoding: "cdr", schemaName: c.schemaName });
        }
      } else if (m) {
        check(c.schemaName === "towsim_msgs/msg/ActuatorCommand", `${c.topic} schema ${c.schemaName}`);
        commandWriter = new MessageWriter(definitions);
        commandChannels.set(m[1], client.advertise({ topic: c.topic, encoding: "cdr", schemaName: c.schemaName }));
        if (m[1] === "tow_vehicle") {
          teleopChannel = client.advertise({ topic: c.topic, encoding: "cdr", schemaName: "geometry_msgs/msg/Twist" });
        }
      }
    }
  });
  client.on("message", ({ subscriptionId, timestamp, data }) => {
    const channel = channels.get(subscriptions.get(subscriptionId));
    let value;
    try {
      value = channel.reader.readMessage(new Uint8Array(data.buffer, data.byteOffset, data.byteLength));
    } catch (e) {
      decodeFailures += 1;
      check(false, `${channel.topic}: does not decode: ${e.message}`);
      return;
    }
    if (!byTopic.has(channel.topic)) byTopic.set(channel.topic, []);
    byTopic.get(channel.topic).push({ timestamp, value });
    if (channel.topic !== "/towsim/status") return;
    // the lockstep controller: answer each step once, both vehicles
    const step = Number(value.step);
    if (value.state === 3 || value.state === 4 || value.state === 5) resolve();
    if (value.state !== 0 && value.state !== 2) return; // running or waiting
    if (answered.has(step) || commandWriter === undefined || commandChannels.size < 2) return;
    if (withWinch && winchWriter === undefined) return;
    answered.add(step);
    const thrust = step >= kThrustStep ? kThrust : 0;
    const answer = () => {
      if (step === kTeleopStep - 1) {
        // the bridge makes it the command answering the newest status: this step
        client.sendMessage(teleopChannel, twistWriter.writeMessage({
          linear: { x: thrust, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } }));
      } else if (step === kTeleopStep) {
        // a NaN thrust, rejected by the bridge (it once became the kept thrust of every later
        // Twist: the vehicle went to failsafe), then a turn that keeps the thrust set above
        client.sendMessage(teleopChannel, twistWriter.writeMessage({
          linear: { x: NaN, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } }));
        client.sendMessage(teleopChannel, twistWriter.writeMessage({
          linear: { x: 0, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 1e-3 } }));
        // a valid command with 8 bytes after it: malformed, once forwarded
        const good = commandWriter.writeMessage(command(step, 0));
        trailingSize = good.length;
        const longer = new Uint8Array(good.length + 8);
        longer.set(good);
        client.sendMessage(commandChannels.get("towfish"), longer);
      } else {
        client.sendMessage(commandChannels.get("tow_vehicle"), commandWriter.writeMessage(command(step, thrust)));
      }
      client.sendMessage(commandChannels.get("towfish"), commandWriter.writeMessage(command(step, 0)));
      if (withWinch) {
        client.sendMessage(winchChannel, winchWriter.writeMessage(winchCommand(step, step >= kWinchStep ? kWinchSpeed : 0)));
      }
    };
    if (step !== kBadStep) {
      answer();
      return;
    }
    const good = commandWriter.writeMessage(command(step, thrust));
    client.sendMessage(commandChannels.get("tow_vehicle"), good.subarray(0, 12)); // truncated
    client.sendMessage(commandChannels.get("tow_vehicle"), commandWriter.writeMessage(command(step, NaN)));
    if (withWinch) {
      client.sendMessage(winchChannel, winchWriter.writeMessage(winchCommand(step, 0)).subarray(0, 12)); // truncated
      client.sendMessage(winchChannel, winchWriter.writeMessage(winchCommand(step, NaN)));
    }
    // the answer after the node took the NaN command (its reader keeps the newest command only)
    setTimeout(answer, kBadAnswerDelay);
  });
});
await finished;
// the last messages in flight
await new Promise((r) => setTimeout(r, 300));
client.close();
if (!inNode) bridge.kill("SIGTERM");
const [nodeCode, bridgeCode] = await Promise.all([node.exited, bridge.exited]);
clearTimeout(deadline);
check(nodeCode === 0, `sim_node exit ${nodeCode}${node.signal ? ` (signal ${node.signal})` : ""}: ${node.err}`);
check(bridgeCode === 0, `towsim_foxglove exit ${bridgeCode}${bridge.signal ? ` (signal ${bridge.signal})` : ""}: ${bridge.err}`);

// --- checks ---
check(serverInfo !== undefined, "serverInfo received");
if (serverInfo) {
  check(serverInfo.capabilities.includes("clientPublish") && serverInfo.capabilities.includes("time"), `capabilities ${serverInfo.capabilities}`);
  check(serverInfo.supportedEncodings?.includes("cdr"), `supportedEncodings ${serverInfo.supportedEncodings}`);
}
const topics = new Set([...channels.values()].map((c) => c.topic));
for (const t of ["/clock", "/tf", "/tf_static", "/towsim/markers", "/towsim/status", "/towsim/scene_info",
  "/towsim/cable/state", "/towsim/sim_control", "/towsim/tow_vehicle/odom", "/towsim/tow_vehicle/command",
  "/towsim/towfish/odom", "/towsim/towfish/cable_force", "/towsim/tow_vehicle/actuator_state",
  "/towsim/towfish/actuator_state"]) {
  check(topics.has(t), `channel ${t} advertised`);
}
// the bridge's command channel carries the commands on DDS (this client's among them); the
// node's own server advertises it for its schema only
for (const t of ["/clock", "/tf", "/tf_static", "/towsim/markers", "/towsim/cable/state", "/towsim/tow_vehicle/odom",
  "/towsim/tow_vehicle/actuator_state", ...(inNode ? [] : ["/towsim/tow_vehicle/command"])]) {
  check((byTopic.get(t) ?? []).length > 0, `messages on ${t}`);
}
check(decodeFailures === 0, `${decodeFailures} messages failed to decode`);

// odometry against bodies.csv
const stampSec = (t) => t.sec + 1e-9 * (t.nanosec ?? t.nsec);
const stampNs = (t) => BigInt(t.sec) * 1000000000n + BigInt(t.nanosec ?? t.nsec);
const rows = readCsv(join(outDir, "csv/bodies.csv"));
let compared = 0;
for (const body of ["tow_vehicle", "towfish"]) {
  const odom = new Map();
  for (const { timestamp, value } of byTopic.get(`/towsim/${body}/odom`) ?? []) {
    check(timestamp === stampNs(value.header.stamp), `${body} odom log time ${timestamp} is its stamp`);
    odom.set(stampSec(value.header.stamp).toFixed(6), value);
  }
  for (const r of rows.filter((r) => r.body === body && Number(r.t) > 0)) {
    const o = odom.get(Number(r.t).toFixed(6));
    if (!check(o !== undefined, `${body} t = ${r.t}: an odometry message`)) continue;
    check(o.child_frame_id === `${body}_frd` && o.header.frame_id === "world_ned", `${body} frames`);
    const p = o.pose.pose.position;
    const v = o.twist.twist.linear;
    const w = o.twist.twist.angular;
    for (const [val, key] of [[p.x, "x"], [p.y, "y"], [p.z, "z"], [v.x, "u"], [v.y, "v"], [v.z, "w"], [w.x, "p"], [w.y, "q"], [w.z, "r"]]) {
      near(val, r[key], `${body} t = ${r.t} ${key}`);
    }
    compared += 1;
  }
}
check(compared >= 2 * 10 * kDuration, `${compared} CSV rows compared`);

// actuator states against actuators.csv (docs/topics.md "Actuator state"): the first message of
// each stamp (a lockstep wait republishes a step), every row of both vehicles after t = 0
const actuatorRows = readCsv(join(outDir, "csv/actuators.csv"));
let actuatorsCompared = 0;
for (const body of ["tow_vehicle", "towfish"]) {
  const states = new Map();
  for (const { value } of byTopic.get(`/towsim/${body}/actuator_state`) ?? []) {
    const key = stampSec(value.header.stamp).toFixed(6);
    if (!states.has(key)) states.set(key, value);
  }
  for (const r of actuatorRows.filter((r) => r.body === body && Number(r.t) > 0)) {
    const a = states.get(Number(r.t).toFixed(6));
    if (!check(a !== undefined, `${body} t = ${r.t}: an actuator_state message`)) continue;
    check(a.header.frame_id === `${body}_frd`, `${body} actuator_state frame ${a.header.frame_id}`);
    for (const key of ["thrust_command", "rudder_command", "elevator_command", "thrust", "rudder", "elevator"]) {
      near(a[key], r[key], `${body} t = ${r.t} ${key}`);
    }
    check(Number(a.failsafe) === Number(r.failsafe), `${body} t = ${r.t} failsafe ${a.failsafe}`);
    check(a.source === 2, `${body} t = ${r.t} source ${a.source} (SOURCE_DDS: the client's commands)`);
    actuatorsCompared += 1;
  }
}
check(actuatorsCompared >= 2 * 10 * kDuration, `${actuatorsCompared} actuators.csv rows compared`);

// the vehicle responds to the commands sent through the WebSocket
const u = (t) => Number(rows.find((r) => r.body === "tow_vehicle" && Math.abs(Number(r.t) - t) < 1e-6)?.u);
const h = 0.05; // case1_forward's time.step [s]
check(Math.abs(u(kThrustStep * h)) < kAtRest, `at rest before the thrust: u = ${u(kThrustStep * h)}`);
check(u(kDuration) > kMoving, `moving after the thrust: u = ${u(kDuration)}`);

// the NaN command: rejected and counted by the node; the malformed one: by the bridge
const last = (byTopic.get("/towsim/status") ?? []).at(-1)?.value;
const kBad = withWinch ? 2 : 1; // the NaN / malformed commands sent: the thrust's, the winch's
check(last !== undefined && Number(last.commands_rejected) === kBad, `node: commands_rejected ${last?.commands_rejected}`);
// the Teleop Twist answered its step: no lockstep timeout, no failsafe
check(last !== undefined && Number(last.lockstep_timeouts) === 0 && Number(last.failsafe_count) === 0,
  `lockstep timeouts ${last?.lockstep_timeouts}, failsafes ${last?.failsafe_count}`);
check(statuses.some((s) => s.level === 2 && /malformed/.test(s.message)), `an error status for the malformed command (${JSON.stringify(statuses)})`);
// the NaN Twist and the command with trailing bytes: rejected by the bridge, each on its own
const nanTwist = "rejected: malformed geometry_msgs/msg/Twist on /towsim/tow_vehicle/command (52 bytes): linear.x is not finite (nan)";
const trailing = `rejected: malformed towsim_msgs/msg/ActuatorCommand on /towsim/towfish/command (${trailingSize + 8} bytes): 8 bytes after the ${trailingSize}-byte sample (only padding to a multiple of 4 may follow)`;
for (const text of [nanTwist, trailing]) {
  check(statuses.some((s) => s.level === 2 && s.message.includes(text)), `an error status "${text}" (${JSON.stringify(statuses)})`);
}
const kMalformed = kBad + 2; // the truncated ones, the NaN Twist, the trailing bytes
if (inNode) {
  check((node.err.match(/sim_node: Foxglove client \S+: rejected: malformed/g) ?? []).length === kMalformed, `sim_node's notes of the malformed commands: ${node.err}`);
} else {
  check(new RegExp(`malformed ${kMalformed}\\)`).test(bridge.out), `bridge summary: ${bridge.out.trim().split("\n").at(-1)}`);
}
// the 3D panel's advertisements and its clicked point: taken, no error status names them
for (const topic of Object.keys(kPanelTopics)) {
  check(!statuses.some((s) => s.message.includes(topic)), `no status about ${topic} (${JSON.stringify(statuses)})`);
}
if (!withWinch) {
  check(statuses.some((s) => s.level === 2 && /advertise \/towsim\/winch\/command: not a topic clients may publish on/.test(s.message)),
    `an error status refusing /towsim/winch/command without a winch (${JSON.stringify(statuses)})`);
}
if (withWinch) {
  check(statuses.some((s) => s.level === 2 && /malformed towsim_msgs\/msg\/WinchCommand on \/towsim\/winch\/command/.test(s.message)),
    `an error status for the malformed WinchCommand (${JSON.stringify(statuses)})`);
  check(/winch at step \d+: command rejected: speed is NaN/.test(node.err), `the node's note of the NaN winch speed: ${node.err}`);
  // paid_out_length over the WebSocket against the node's winch.csv, and the drum's kinematics
  const cable = new Map();
  for (const { value } of byTopic.get("/towsim/cable/state") ?? []) {
    check(value.positions.length === value.node_count, `CableState: ${value.positions.length} positions, node_count ${value.node_count}`);
    cable.set(stampSec(value.header.stamp).toFixed(6), value);
  }
  const winchLines = readFileSync(join(outDir, "csv/winch.csv"), "utf8").trim().split("\n");
  // the node's winch.csv: the state's five columns, then the command's appended
  check(winchLines.shift() === "t,paid_out_length,winch_speed,drum_tension,node_count,command_mode,command_value,failsafe", "winch.csv header");
  let winchCompared = 0;
  for (const line of winchLines) {
    const [t, length, speed, , nodes] = line.split(",");
    if (Number(t) === 0) continue;
    const c = cable.get(Number(t).toFixed(6));
    if (!check(c !== undefined, `t = ${t}: a CableState message`)) continue;
    near(c.paid_out_length, length, `t = ${t} paid_out_length`);
    near(c.winch_speed, speed, `t = ${t} winch_speed`);
    check(c.node_count === Number(nodes), `t = ${t} node_count ${c.node_count} vs CSV ${nodes}`);
    winchCompared += 1;
  }
  check(winchCompared >= 10 * kDuration, `${winchCompared} winch.csv rows compared`);
  const tOn = kWinchStep * h;
  const expected = 200 + kWinchSpeed ** 2 / (2 * kWinchAcceleration) +
    kWinchSpeed * (kDuration - tOn - kWinchSpeed / kWinchAcceleration);
  const end = cable.get(kDuration.toFixed(6));
  check(end !== undefined && Math.abs(end.paid_out_length - expected) <= kLengthRelTol * expected,
    `paid_out_length at ${kDuration} s: ${end?.paid_out_length}, expected ${expected}`);
  const before = cable.get(tOn.toFixed(6)); // the state the command of step kWinchStep answers
  check(before !== undefined && before.paid_out_length === 200, `paid_out_length before the winch command: ${before?.paid_out_length}`);
  check(inNode || (byTopic.get("/towsim/winch/command") ?? []).length > 0, "messages on /towsim/winch/command (the bridge's DDS traffic)");
  console.error(`winch: paid_out_length ${end?.paid_out_length} m at ${kDuration} s (expected ${expected}), ${winchCompared} winch.csv rows matched`);
}

// time messages: the simulation time of /clock
const clocks = new Set((byTopic.get("/clock") ?? []).map(({ value }) => stampNs(value.clock)));
check(times.length > 0 && times.every((t) => clocks.has(t)), `${times.length} time messages, all /clock stamps`);
for (let i = 1; i < times.length; i++) if (!check(times[i] >= times[i - 1], `time ${i} not decreasing`)) break;

// the layout (config/foxglove/towsim.json): every plotted path resolves to a number in the
// messages decoded here, the 3D panel follows a frame of /tf, Teleop drives a command topic
const layout = JSON.parse(readFileSync(join(sourceDir, "config/foxglove/towsim.json"), "utf8"));
for (const [id, panel] of Object.entries(layout.configById)) {
  if (id.startsWith("Plot!")) {
    for (const { value } of panel.paths) {
      const { topic, fields } = splitPath(value);
      // a negative index counts from the end (Foxglove's message path syntax)
      const v = resolvePath((byTopic.get(topic) ?? []).at(-1)?.value, fields);
      check(typeof v === "number" && Number.isFinite(v), `layout ${id}: ${value} = ${v}`);
    }
  }
  if (id.startsWith("3D!")) {
    const frames = new Set((byTopic.get("/tf") ?? []).flatMap(({ value }) => value.transforms.map((t) => t.child_frame_id)));
    (byTopic.get("/tf_static") ?? []).forEach(({ value }) => value.transforms.forEach((t) => frames.add(t.child_frame_id)));
    check(frames.has(panel.followTf), `layout ${id}: follows ${panel.followTf}`);
    check(panel.layers.grid.frameId === "world", `layout ${id}: grid in world`);
  }
  if (id.startsWith("Teleop!")) check(commandChannels.has(panel.topic.split("/")[2]), `layout ${id}: ${panel.topic}`);
}

if (failures() > 0) {
  console.error(`${failures()} failures`);
  process.exit(1);
}
let count = 0;
for (const v of byTopic.values()) count += v.length;
console.log(`ok: ${count} messages on ${byTopic.size} topics decoded, ${compared} CSV rows matched, ` +
  `${answered.size} steps commanded through clientPublish, ${times.length} time messages`);
