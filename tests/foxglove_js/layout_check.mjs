// The generated layout of a scene (docs/foxglove.md "A layout for any scene") against a live
// node of that scene, through the same independent client as live_check.mjs
// (@foxglove/ws-protocol, decoding with @foxglove/rosmsg2-serialization):
//   node layout_check.mjs SIM_NODE TOWSIM_FOXGLOVE SOURCE_DIR OUT_DIR DOMAIN SCENE
// SCENE relative to SOURCE_DIR. It starts and stops the processes itself (also when it fails):
//   1. towsim_foxglove --layout SCENE --output OUT_DIR/layout.json (the real generator);
//   2. sim_node --scene SCENE --mode fast --paused --foxglove 0 --duration kDuration on DOMAIN
//      (held through its lock file as towsim::testing::DomainLease holds an id);
//   3. this client: subscribes to every advertised channel, resumes the node (SimControl RESUME
//      through clientPublish on <ns>/sim_control) and decodes every message it gets until the
//      node's status says the run ended or the node exits (fast mode: the node drops what the
//      client cannot take, which leaves plenty of every topic).
// Then, for every panel of the layout: each topic it names (the 3D panel's `topics`, each
// plot path's topic, Teleop's `topic`) is an advertised channel; each plot path resolves to a
// finite number in at least one decoded message of its topic (a negative index counted from
// the end, Foxglove's message path syntax); the 3D panel's `followTf` is a child frame of the
// decoded /tf or /tf_static and its grid's frame a frame of that tree. The 3D panel's publish
// tools (`publish`: /move_base_simple/goal, /clicked_point, /initialpose) are topics Foxglove
// advertises, not the server: live_check.mjs checks that the server takes them.
// Exits 77 (ctest: skipped) when the node modules are missing: run `npm ci` in this folder.
import { mkdirSync, readFileSync, rmSync } from "node:fs";
import { join } from "node:path";

import { check, failures } from "../js_common/checks.mjs";
import { children, holdDomain, loadModules, resolvePath, splitPath, start, stopAll } from "./client_common.mjs";

const { WebSocket, FoxgloveClient, parseMessageDefinition, MessageReader, MessageWriter } = await loadModules();

const [simNode, bridgeExe, sourceDir, outDir, domainText, scene] = process.argv.slice(2);
const kDuration = 5; // [s] simulated: 50 rows of every topic at the scenes' 10 Hz
const kSettle = 300; // [ms] between the subscriptions and the RESUME (requests in order anyway)
const kTimeout = 90e3; // [ms] the whole check; a run that takes longer has hung
const kResume = 2; // towsim_msgs/SimControl RESUME
const kEnded = 3; // SimStatus.state from here on: the run ended (finished, stopped, failed)

rmSync(outDir, { recursive: true, force: true });
mkdirSync(outDir, { recursive: true });
const byTopic = new Map(); // topic -> [decoded message]
const deadline = setTimeout(() => {
  console.error("FAIL: timed out");
  console.error(`received: ${[...byTopic.entries()].map(([t, v]) => `${t} ${v.length}`).join(", ")}`);
  for (const c of children) console.error(`${c.name} stderr:\n${c.err}`);
  stopAll();
  process.exit(1);
}, kTimeout);

// the domain is inside the automatic range (200-231): held, so that automatic leases skip it
await holdDomain(Number(domainText));

// 1. the layout, by the real generator
const scenePath = join(sourceDir, scene);
const layoutPath = join(outDir, "layout.json");
const generator = start([bridgeExe, "--layout", scenePath, "--output", layoutPath], "towsim_foxglove --layout");
const generatorCode = await generator.exited;
if (!check(generatorCode === 0, `towsim_foxglove --layout ${scene}: exit ${generatorCode}: ${generator.err}`)) process.exit(1);
const layout = JSON.parse(readFileSync(layoutPath, "utf8"));

// 2. the node, paused until this client has subscribed
const node = start(
  [simNode, "--scene", scenePath, "--mode", "fast", "--paused", "--foxglove", "0",
    "--duration", String(kDuration), "--domain", domainText],
  "sim_node",
);
const url = await new Promise((resolve, reject) => {
  const poll = setInterval(() => {
    const m = node.out.match(/Foxglove at (ws:\/\/\S+)/);
    if (m) {
      clearInterval(poll);
      resolve(m[1]);
    } else if (node.exitCode !== null) {
      clearInterval(poll);
      reject(new Error(`sim_node exited ${node.exitCode}: ${node.err}`));
    }
  }, 20);
});

// 3. the client
console.error(`connecting to ${url} (sim_node --foxglove, ${scene})`);
const client = new FoxgloveClient({ ws: new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]) });
const channels = new Map(); // subscription id -> {topic, reader}
const advertised = new Set();
let decodeFailures = 0;
let resumed = false;
const finished = new Promise((resolve) => {
  client.on("advertise", (list) => {
    for (const c of list) {
      advertised.add(c.topic);
      const definitions = parseMessageDefinition(c.schema, { ros2: true });
      channels.set(client.subscribe(c.id), { topic: c.topic, reader: new MessageReader(definitions) });
      if (c.topic.endsWith("/sim_control") && !resumed) {
        resumed = true;
        const control = client.advertise({ topic: c.topic, encoding: "cdr", schemaName: c.schemaName });
        const resume = new MessageWriter(definitions).writeMessage({
          header: { stamp: { sec: 0, nanosec: 0 }, frame_id: "" }, command: kResume, steps: 0, rate: 0 });
        setTimeout(() => client.sendMessage(control, resume), kSettle);
      }
    }
  });
  client.on("message", ({ subscriptionId, data }) => {
    const channel = channels.get(subscriptionId);
    let value;
    try {
      value = channel.reader.readMessage(new Uint8Array(data.buffer, data.byteOffset, data.byteLength));
    } catch (e) {
      decodeFailures += 1;
      check(false, `${channel.topic}: does not decode: ${e.message}`);
      return;
    }
    if (!byTopic.has(channel.topic)) byTopic.set(channel.topic, []);
    byTopic.get(channel.topic).push(value);
    if (channel.topic.endsWith("/status") && value.state >= kEnded) resolve();
  });
});
// the end of the run: its last status, or the node's exit (in fast mode the node outruns the
// client, and a slow client misses messages, the last status among them: docs/foxglove.md
// "Bounds")
await Promise.race([finished, node.exited]);
await new Promise((r) => setTimeout(r, 300)); // the last messages in flight
client.close();
const nodeCode = await node.exited;
clearTimeout(deadline);
check(nodeCode === 0, `sim_node exit ${nodeCode}${node.signal ? ` (signal ${node.signal})` : ""}: ${node.err}`);
check(resumed, "a sim_control channel to resume the node");
check(decodeFailures === 0, `${decodeFailures} messages failed to decode`);

// --- the layout against what was served ---
const named = new Set(); // every topic a panel names
let paths = 0;
let follows;
for (const [id, panel] of Object.entries(layout.configById)) {
  if (id.startsWith("3D!")) {
    for (const topic of Object.keys(panel.topics)) named.add(topic);
    const tf = [...(byTopic.get("/tf") ?? []), ...(byTopic.get("/tf_static") ?? [])].flatMap((m) => m.transforms);
    const childFrames = new Set(tf.map((t) => t.child_frame_id));
    const frames = new Set([...childFrames, ...tf.map((t) => t.header.frame_id)]);
    follows = panel.followTf;
    check(childFrames.has(panel.followTf), `layout ${id}: follows ${panel.followTf}, not a child frame of /tf or /tf_static (${[...childFrames]})`);
    check(frames.has(panel.layers.grid.frameId), `layout ${id}: grid in ${panel.layers.grid.frameId}, not a frame of the tf tree (${[...frames]})`);
  } else if (id.startsWith("Plot!")) {
    for (const { value } of panel.paths) {
      const { topic, fields } = splitPath(value);
      named.add(topic);
      const messages = byTopic.get(topic) ?? [];
      const found = messages.some((m) => {
        const v = resolvePath(m, fields);
        return typeof v === "number" && Number.isFinite(v);
      });
      check(found, `layout ${id}: ${value} is a finite number in none of the ${messages.length} messages of ${topic}`);
      paths += 1;
    }
  } else if (id.startsWith("Teleop!")) {
    named.add(panel.topic);
  } else {
    check(false, `layout: a panel this check does not know: ${id}`);
  }
}
for (const topic of named) check(advertised.has(topic), `layout names ${topic}: not advertised (${[...advertised]})`);
// a layout that names nothing would pass the checks above: the generator's panels are there
check(follows !== undefined && paths > 0, `layout has a 3D panel (${follows}) and plot paths (${paths})`);

if (failures() > 0) {
  console.error(`${failures()} failures`);
  process.exit(1);
}
let count = 0;
for (const v of byTopic.values()) count += v.length;
console.log(`ok: ${scene}: ${Object.keys(layout.configById).length} panels, ${named.size} topics named and advertised, ` +
  `${paths} plot paths resolved, follows ${follows}; ${count} messages on ${byTopic.size} topics decoded`);
process.exit(0); // ends the domain's lock holder too
