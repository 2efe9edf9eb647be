// Decodes a towsim recording with independent readers and compares every value with what the
// node wrote to its own --csv files during the same run:
//   node decode_recording.mjs RUN.mcap CSV_DIR
// - @mcap/core: McapIndexedReader (magic, footer, summary) reading every message with every
//   chunk CRC validated; McapStreamReader (a linear read of every record, CRCs again); the
//   data section CRC recomputed here
// - @foxglove/rosmsg parses each channel's ros2msg schema (which must define every type it
//   uses); @foxglove/rosmsg2-serialization decodes every message of every channel with it
// - bodies.csv, cable.csv, forces.csv, status.csv of the node compared with the decoded
//   odometry, cable state, cable force and status messages, row by row in order. The CSV
//   prints 9 significant digits ("%.9g"), so a decoded value v and its CSV text c agree when
//   |v - c| <= 5e-9 |c| (half a unit in the 9th digit) + kAbs; Euler angles are computed
//   here from the quaternion, so they get kAbsAngle on top (float64 rounding of the formulas).
// - environment.csv of the node (the run has a current profile) compared with the decoded
//   <body>/environment messages (towsim_msgs/BodyEnvironment), row by row
// - the frames and markers (docs/frames.md): /tf, /tf_static and /towsim/markers decode with
//   their OFFICIAL ROS 2 Jazzy definitions (@foxglove/rosmsg-msgs-common, not the recording's
//   schemas) to the same values; every frame named by the markers and the odometry resolves to
//   `world` through /tf_static and /tf (the tree walked here, transforms composed here); /tf
//   carries the odometry's pose at the same stamp; the cable marker's points are the cable
//   state's positions in `world` (x_E = y_N, y_E = x_N, z_E = -z_N) at the same stamp.
// Exits 77 (ctest: skipped) when the node modules are missing: run `npm ci` in this folder.
import { existsSync, readFileSync } from "node:fs";
import { join } from "node:path";
import { isDeepStrictEqual } from "node:util";

import { check, failures, near, readCsv as readCsvFile } from "../js_common/checks.mjs";
import { linearRead, readableOf } from "./mcap_file.mjs";

let mcap, rosmsg, serialization, common;
try {
  mcap = await import("@mcap/core");
  rosmsg = await import("@foxglove/rosmsg");
  serialization = await import("@foxglove/rosmsg2-serialization");
  common = await import("@foxglove/rosmsg-msgs-common");
} catch (e) {
  console.error(`node modules not installed (run "npm ci" in tests/mcap_js): ${e.message}`);
  process.exit(77);
}
const { McapIndexedReader, McapStreamReader } = mcap;
const { parse: parseMessageDefinition } = rosmsg;
const { MessageReader } = serialization;

const [file, csvDir] = process.argv.slice(2);
const kAbsAngle = 1e-12; // [rad] Euler angles from the quaternion by another formula
const readCsv = (name) => readCsvFile(join(csvDir, name));

const bytes = new Uint8Array(readFileSync(file));
const readable = readableOf(bytes);
const reader = await McapIndexedReader.Initialize({ readable });
check(reader.header.profile === "ros2", `profile ${reader.header.profile}`);

// every channel: a ros2msg schema that parses completely, cdr messages
const decoders = new Map();
const topics = new Map();
for (const channel of reader.channelsById.values()) {
  const schema = reader.schemasById.get(channel.schemaId);
  check(schema !== undefined, `channel ${channel.topic} has a schema`);
  check(schema.encoding === "ros2msg", `${schema.name} encoding ${schema.encoding}`);
  check(channel.messageEncoding === "cdr", `${channel.topic} encoding ${channel.messageEncoding}`);
  const text = new TextDecoder().decode(schema.data);
  const definitions = parseMessageDefinition(text, { ros2: true });
  // every complex field type has its definition in the schema
  const names = new Set(definitions.map((d) => d.name).filter((n) => n !== undefined));
  for (const d of definitions) {
    for (const f of d.definitions) {
      if (f.isComplex) check(names.has(f.type), `${schema.name}: ${f.name} of type ${f.type} is defined`);
    }
  }
  decoders.set(channel.id, new MessageReader(definitions));
  topics.set(channel.id, { topic: channel.topic, type: schema.name });
}

// decode every message (chunk CRCs validated)
const byTopic = new Map();
const rawByTopic = new Map(); // the bytes of the frame and marker topics
const kVisualTopics = ["/tf", "/tf_static", "/towsim/markers"];
let count = 0;
for await (const m of reader.readMessages({ validateCrcs: true })) {
  const { topic, type } = topics.get(m.channelId);
  let value;
  try {
    value = decoders.get(m.channelId).readMessage(m.data);
  } catch (e) {
    check(false, `message ${count} on ${topic} (${type}) does not decode: ${e.message}`);
    continue;
  }
  if (!byTopic.has(topic)) byTopic.set(topic, []);
  byTopic.get(topic).push(value);
  if (kVisualTopics.includes(topic)) {
    if (!rawByTopic.has(topic)) rawByTopic.set(topic, { type, data: [] });
    rawByTopic.get(topic).data.push(m.data);
  }
  count += 1;
}
check(BigInt(count) === reader.statistics.messageCount, `decoded ${count} of ${reader.statistics.messageCount}`);

// linear read of every record, and the data section CRC (bytes before the DataEnd record)
const linear = linearRead(McapStreamReader, bytes);
check(linear.done && linear.messages === count, `stream reader: ${linear.messages} messages`);
check(linear.dataEnd !== undefined && linear.dataCrc === linear.dataEnd.dataSectionCrc, "data section CRC");

// the rosbag2 metadata record
check(reader.metadataIndexes.some((i) => i.name === "rosbag2"), "rosbag2 metadata record");

// --- decoded values against the node's CSV ---
// builtin_interfaces/Time: rosmsg2-serialization names the fields {sec, nsec} (ROS 1 style)
const stampSec = (t) => t.sec + 1e-9 * (t.nanosec ?? t.nsec);
const sceneInfo = (byTopic.get("/towsim/scene_info") ?? [])[0];
check(sceneInfo !== undefined, "scene_info recorded");
const bodies = sceneInfo ? sceneInfo.bodies : [];

// bodies.csv: per body, its rows in order = its odometry messages in order
const bodyRows = readCsv("bodies.csv");
let compared = 0;
for (const body of bodies) {
  const rows = bodyRows.filter((r) => r.body === body);
  const odom = byTopic.get(`/towsim/${body}/odom`) ?? [];
  check(rows.length > 0 && rows.length === odom.length, `${body}: ${rows.length} rows, ${odom.length} odometry messages`);
  for (let i = 0; i < Math.min(rows.length, odom.length); i++) {
    const r = rows[i];
    const o = odom[i];
    const p = o.pose.pose.position;
    const q = o.pose.pose.orientation;
    const v = o.twist.twist.linear;
    const w = o.twist.twist.angular;
    const what = `${body} row ${i}`;
    near(stampSec(o.header.stamp), r.t, `${what} t`, 1e-9);
    check(o.child_frame_id === `${body}_frd`, `${what} child_frame_id ${o.child_frame_id}`);
    check(o.header.frame_id === "world_ned", `${what} frame_id ${o.header.frame_id}`);
    near(p.x, r.x, `${what} x`);
    near(p.y, r.y, `${what} y`);
    near(p.z, r.z, `${what} z`);
    // ZYX Euler angles of q_WB (scalar last)
    const roll = Math.atan2(2 * (q.w * q.x + q.y * q.z), 1 - 2 * (q.x * q.x + q.y * q.y));
    const pitch = Math.asin(Math.max(-1, Math.min(1, 2 * (q.w * q.y - q.z * q.x))));
    const yaw = Math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
    near(roll, r.roll, `${what} roll`, kAbsAngle);
    near(pitch, r.pitch, `${what} pitch`, kAbsAngle);
    near(yaw, r.yaw, `${what} yaw`, kAbsAngle);
    near(v.x, r.u, `${what} u`);
    near(v.y, r.v, `${what} v`);
    near(v.z, r.w, `${what} w`);
    near(w.x, r.p, `${what} p`);
    near(w.y, r.q, `${what} q`);
    near(w.z, r.r, `${what} r`);
    compared += 1;
  }
}

// cable.csv: each cable state message gives its nodes' rows, in order
const cableRows = readCsv("cable.csv");
const cable = byTopic.get("/towsim/cable/state") ?? [];
const nodes = cable.length > 0 ? cable[0].positions.length : 0;
check(nodes > 0 && cableRows.length === cable.length * nodes, `cable: ${cableRows.length} rows, ${cable.length} x ${nodes}`);
// the scene info's cable list (its fields appended for networks, decoded by the recording's
// schema): the one cable, named "cable", with the node count of its state
if (sceneInfo) {
  check(isDeepStrictEqual(sceneInfo.cables, ["cable"]), `scene_info cables ${JSON.stringify(sceneInfo.cables)}`);
  check(sceneInfo.cable_node_counts?.length === 1 && sceneInfo.cable_node_counts[0] === nodes &&
        sceneInfo.cable_nodes === nodes, `scene_info cable_node_counts ${sceneInfo.cable_node_counts}, cable_nodes ${sceneInfo.cable_nodes}, ${nodes} nodes`);
}
cable.forEach((c, k) => {
  check(c.positions.length === nodes && c.tensions.length === nodes, `cable message ${k} sizes`);
  for (let i = 0; i < nodes && k * nodes + i < cableRows.length; i++) {
    const r = cableRows[k * nodes + i];
    const what = `cable message ${k} node ${i}`;
    check(Number(r.node) === i, `${what} node ${r.node}`);
    near(stampSec(c.header.stamp), r.t, `${what} t`, 1e-9);
    near(c.positions[i].x, r.x, `${what} x`);
    near(c.positions[i].y, r.y, `${what} y`);
    near(c.positions[i].z, r.z, `${what} z`);
    near(c.tensions[i], r.tension, `${what} tension`);
    compared += 1;
  }
});

// forces.csv: per body, its rows = its cable_force messages
const forceRows = readCsv("forces.csv");
for (const body of bodies) {
  const rows = forceRows.filter((r) => r.body === body);
  const forces = byTopic.get(`/towsim/${body}/cable_force`) ?? [];
  check(rows.length > 0 && rows.length === forces.length, `${body}: ${rows.length} force rows, ${forces.length} messages`);
  for (let i = 0; i < Math.min(rows.length, forces.length); i++) {
    const { force: f, torque: m } = forces[i].wrench;
    const r = rows[i];
    const what = `${body} force row ${i}`;
    near(stampSec(forces[i].header.stamp), r.t, `${what} t`, 1e-9);
    near(f.x, r.fx, `${what} fx`);
    near(f.y, r.fy, `${what} fy`);
    near(f.z, r.fz, `${what} fz`);
    near(m.x, r.mx, `${what} mx`);
    near(m.y, r.my, `${what} my`);
    near(m.z, r.mz, `${what} mz`);
    compared += 1;
  }
}

// status.csv: the status messages, the end-of-run repeat of the last step dropped
const statusRows = readCsv("status.csv");
const status = (byTopic.get("/towsim/status") ?? []).filter(
  (s, i, all) => i === 0 || s.step !== all[i - 1].step,
);
check(statusRows.length === status.length, `status: ${statusRows.length} rows, ${status.length} messages`);
for (let i = 0; i < Math.min(statusRows.length, status.length); i++) {
  const s = status[i];
  const r = statusRows[i];
  const what = `status row ${i}`;
  check(BigInt(s.step) === BigInt(r.step), `${what} step ${s.step} vs ${r.step}`);
  check(s.newton_iterations === Number(r.newton_iterations), `${what} newton_iterations`);
  near(s.sim_time, r.t, `${what} sim_time`);
  near(s.residual, r.residual, `${what} residual`);
  check(Math.round(s.step_wall_time * 1e6) === Number(r.wall_us), `${what} wall_us ${s.step_wall_time}`);
  compared += 1;
}
// environment.csv (the run has a current): per body, its rows = its environment messages
// (towsim_msgs/BodyEnvironment), the altitude NaN where the CSV field is empty (no seabed)
check(existsSync(join(csvDir, "environment.csv")), "environment.csv written (a scene with a sea)");
const envRows = existsSync(join(csvDir, "environment.csv")) ? readCsv("environment.csv") : [];
for (const body of bodies) {
  const rows = envRows.filter((r) => r.body === body);
  const env = byTopic.get(`/towsim/${body}/environment`) ?? [];
  check(rows.length > 0 && rows.length === env.length, `${body}: ${rows.length} environment rows, ${env.length} messages`);
  for (let i = 0; i < Math.min(rows.length, env.length); i++) {
    const e = env[i];
    const r = rows[i];
    const what = `${body} environment row ${i}`;
    near(stampSec(e.header.stamp), r.t, `${what} t`, 1e-9);
    check(e.header.frame_id === "world_ned", `${what} frame_id ${e.header.frame_id}`);
    near(e.wave_elevation, r.wave_elevation, `${what} wave_elevation`);
    if (r.altitude === "") check(Number.isNaN(e.altitude), `${what} altitude ${e.altitude} (no seabed: NaN)`);
    else near(e.altitude, r.altitude, `${what} altitude`);
    near(e.depth, r.depth, `${what} depth`);
    near(e.current.x, r.current_u, `${what} current_u`);
    near(e.current.y, r.current_v, `${what} current_v`);
    near(e.current.z, r.current_w, `${what} current_w`);
    compared += 1;
  }
}

const last = (byTopic.get("/towsim/status") ?? []).at(-1);
check(last !== undefined && last.state === 3, `last status state ${last?.state} (3 = finished)`);

// /clock: one per published step, increasing
const clock = byTopic.get("/clock") ?? [];
check(clock.length > 0, "clock messages");
for (let i = 1; i < clock.length; i++) {
  if (!check(stampSec(clock[i].clock) > stampSec(clock[i - 1].clock), `clock ${i} increases`)) break;
}

// --- frames and markers ---
// the official definitions of a type and its dependencies, root first
const jazzy = (common.ros2jazzy ?? common.default.ros2jazzy);
function officialDefinitions(type) {
  const name = type.replace("/msg/", "/");
  const out = [];
  const seen = new Set();
  const visit = (n) => {
    if (seen.has(n)) return;
    seen.add(n);
    const d = jazzy[n];
    check(d !== undefined, `official definition of ${n}`);
    if (d === undefined) return;
    out.push(d);
    for (const f of d.definitions) if (f.isComplex) visit(f.type);
  };
  visit(name);
  return out;
}
for (const topic of kVisualTopics) {
  const raw = rawByTopic.get(topic);
  if (!check(raw !== undefined && raw.data.length > 0, `${topic} recorded`)) continue;
  const official = new MessageReader(officialDefinitions(raw.type));
  raw.data.forEach((d, i) => {
    let value;
    try {
      value = official.readMessage(d);
    } catch (e) {
      check(false, `${topic} message ${i}: official ${raw.type} does not decode it: ${e.message}`);
      return;
    }
    check(isDeepStrictEqual(value, byTopic.get(topic)[i]), `${topic} message ${i}: official and recorded definitions decode alike`);
  });
}
const stampKey = (t) => `${t.sec}.${t.nanosec ?? t.nsec}`;
// quaternions [x, y, z, w]: Hamilton product and rotation of a vector
const qmul = (a, b) => [
  a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
  a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
  a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
  a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2],
];
const qrot = (q, v) => {
  const p = qmul(qmul(q, [v[0], v[1], v[2], 0]), [-q[0], -q[1], -q[2], q[3]]);
  return [p[0], p[1], p[2]];
};
// the tree: child -> {parent, t, q} from /tf_static (all) and the last /tf at or before `stamp`
const statics = (byTopic.get("/tf_static") ?? []).flatMap((m) => m.transforms);
const tfs = byTopic.get("/tf") ?? [];
const edgeOf = (ts) => ({
  parent: ts.header.frame_id,
  t: [ts.transform.translation.x, ts.transform.translation.y, ts.transform.translation.z],
  q: [ts.transform.rotation.x, ts.transform.rotation.y, ts.transform.rotation.z, ts.transform.rotation.w],
});
function treeAt(stamp) {
  const tree = new Map();
  for (const s of statics) tree.set(s.child_frame_id, edgeOf(s));
  const tf = tfs.find((m) => m.transforms.length > 0 && stampKey(m.transforms[0].header.stamp) === stamp);
  if (tf) for (const s of tf.transforms) tree.set(s.child_frame_id, edgeOf(s));
  return { tree, found: tf !== undefined };
}
// the pose of `frame` in `world`: composed up the tree; undefined if it does not get there
function inWorld(tree, frame) {
  let t = [0, 0, 0];
  let q = [0, 0, 0, 1];
  for (let f = frame, hops = 0; f !== "world"; hops++) {
    const e = tree.get(f);
    if (e === undefined || hops > 20) return undefined;
    // X_parent_frame = X_parent_f * X_f_frame
    const r = qrot(e.q, t);
    t = [e.t[0] + r[0], e.t[1] + r[1], e.t[2] + r[2]];
    q = qmul(e.q, q);
    f = e.parent;
  }
  return { t, q };
}
const kAbsPos = 1e-9; // [m] float64 rounding over a 3-edge chain of ~200 m
check(statics.some((s) => s.header.frame_id === "world" && s.child_frame_id === "world_ned"), "world -> world_ned static");
let framesResolved = 0;
const markers = byTopic.get("/towsim/markers") ?? [];
const cableByStamp = new Map(cable.map((c) => [stampKey(c.header.stamp), c]));
for (const [k, ma] of markers.entries()) {
  const stamp = stampKey(ma.markers[0].header.stamp);
  const { tree, found } = treeAt(stamp);
  check(found, `markers ${k}: a /tf at its stamp ${stamp}`);
  for (const mk of ma.markers) {
    check(inWorld(tree, mk.header.frame_id) !== undefined, `markers ${k} ${mk.ns}/${mk.id}: frame ${mk.header.frame_id} resolves to world`);
    framesResolved += 1;
  }
  const line = ma.markers.find((mk) => mk.ns === "cable");
  const c = cableByStamp.get(stamp);
  if (check(line !== undefined && c !== undefined, `markers ${k}: cable marker and cable state at ${stamp}`)) {
    const X = inWorld(tree, line.header.frame_id);
    check(line.points.length === c.positions.length, `markers ${k}: ${line.points.length} cable points`);
    line.points.forEach((p, i) => {
      // the node in world (ENU) from world_ned through the static edge world -> world_ned
      const ned = c.positions[i];
      const w = inWorld(tree, "world_ned");
      const r = qrot(w.q, [ned.x, ned.y, ned.z]);
      const expect = [w.t[0] + r[0], w.t[1] + r[1], w.t[2] + r[2]];
      // the marker's point in world
      const pr = qrot(X.q, [p.x, p.y, p.z]);
      const got = [X.t[0] + pr[0], X.t[1] + pr[1], X.t[2] + pr[2]];
      for (let a = 0; a < 3; a++) {
        check(Math.abs(got[a] - expect[a]) <= kAbsPos, `markers ${k} cable point ${i}[${a}]: ${got[a]} vs ${expect[a]}`);
      }
    });
    compared += 1;
  }
}
check(markers.length > 0 && framesResolved > 0, "marker frames resolved");
// odometry: frames, and /tf at the same stamp carries the same pose
for (const body of bodies) {
  for (const [i, o] of (byTopic.get(`/towsim/${body}/odom`) ?? []).entries()) {
    const { tree, found } = treeAt(stampKey(o.header.stamp));
    check(found, `${body} odom ${i}: a /tf at its stamp`);
    check(inWorld(tree, o.header.frame_id) !== undefined && inWorld(tree, o.child_frame_id) !== undefined,
      `${body} odom ${i}: ${o.header.frame_id} and ${o.child_frame_id} resolve to world`);
    const e = tree.get(o.child_frame_id);
    const p = o.pose.pose.position;
    const q = o.pose.pose.orientation;
    check(e !== undefined && e.parent === o.header.frame_id &&
      isDeepStrictEqual(e.t, [p.x, p.y, p.z]) && isDeepStrictEqual(e.q, [q.x, q.y, q.z, q.w]),
      `${body} odom ${i}: /tf holds the odometry's pose exactly`);
    framesResolved += 1;
  }
}
for (const body of bodies) {
  for (const [i, f] of (byTopic.get(`/towsim/${body}/cable_force`) ?? []).entries()) {
    check(f.header.frame_id === `${body}_frd`, `${body} cable_force ${i} frame ${f.header.frame_id}`);
  }
}

if (failures() > 0) {
  console.error(`${failures()} failures`);
  process.exit(1);
}
console.log(
  `ok: ${count} messages on ${topics.size} topics decoded, ${compared} CSV rows matched, ` +
    `${framesResolved} frames resolved to world, ` +
    `${reader.chunkIndexes.length} chunks`,
);
