// What the Foxglove clients (live_check.mjs, layout_check.mjs) share: the node modules (exit
// 77, ctest's skip, when `npm ci` has not run in this folder), child processes that die with
// the check, a DDS domain held as the C++ tests hold theirs, and Foxglove's message paths
// resolved in a decoded message (docs/foxglove.md).
import { spawn } from "node:child_process";
import { tmpdir } from "node:os";
import { join } from "node:path";

// @foxglove/ws-protocol (FoxgloveClient over `ws`), @foxglove/rosmsg (ros2msg schemas) and
// @foxglove/rosmsg2-serialization (CDR); exits 77 when they are missing
export async function loadModules() {
  try {
    const ws = await import("ws");
    const wsProtocol = await import("@foxglove/ws-protocol");
    const rosmsg = await import("@foxglove/rosmsg");
    const serialization = await import("@foxglove/rosmsg2-serialization");
    return {
      WebSocket: ws.default ?? ws.WebSocket,
      // CommonJS from ESM
      FoxgloveClient: (wsProtocol.FoxgloveClient ? wsProtocol : wsProtocol.default).FoxgloveClient,
      parseMessageDefinition: rosmsg.parse,
      MessageReader: serialization.MessageReader,
      MessageWriter: serialization.MessageWriter,
    };
  } catch (e) {
    console.error(`node modules not installed (run "npm ci" in tests/foxglove_js): ${e.message}`);
    process.exit(77);
  }
}

// the processes started here; every one still running is killed when this process exits
export const children = [];
export function start(argv, name, stdin = "ignore") {
  const child = spawn(argv[0], argv.slice(1), { stdio: [stdin, "pipe", "pipe"] });
  child.out = "";
  child.err = "";
  child.stdout.on("data", (d) => (child.out += d));
  child.stderr.on("data", (d) => (child.err += d));
  child.exited = new Promise((resolve) => child.on("exit", (code, signal) => {
    child.signal = signal;
    resolve(code ?? 128);
  }));
  child.name = name;
  children.push(child);
  return child;
}
export function stopAll() {
  for (const c of children) if (c.exitCode === null) c.kill("SIGKILL");
}
process.on("exit", stopAll);

// a plot path "<topic>.<field>[.<field>...]" (a field may carry an index, `tensions[0]`) as
// its topic and its field path; the topic is everything before the first dot (topic names
// hold none)
export function splitPath(value) {
  const dot = value.indexOf(".");
  return { topic: value.slice(0, dot), fields: value.slice(dot + 1) };
}

// the value a field path names in a decoded message, undefined where it names nothing; an
// index counts from the end when negative (Foxglove's message path syntax)
export function resolvePath(message, fields) {
  let v = message;
  for (const part of fields.split(".")) {
    const m = part.match(/^(\w+)(?:\[(-?\d+)\])?$/);
    if (m === null) return undefined;
    v = v?.[m[1]];
    if (m[2] !== undefined) v = v?.at?.(Number(m[2]));
  }
  return v;
}

// holds DDS domain `id` as towsim::testing::DomainLease does (wire/domain_lock.h): an exclusive
// flock on <TOWSIM_DOMAIN_LOCK_DIR or the temp dir>/towsim-dds-domain-<id>.lock, here by
// util-linux flock(1) in a child that lives as long as this check, so that automatic leases of
// other tests skip the id; resolves once held, rejects when another process holds it
export async function holdDomain(id) {
  const dir = process.env.TOWSIM_DOMAIN_LOCK_DIR || tmpdir();
  const file = join(dir, `towsim-dds-domain-${id}.lock`);
  // flock(1) runs its command as a child holding the lock too: `cat` on a pipe from this
  // process, which ends when this process does, however it ends
  const holder = start(["flock", "--nonblock", file, "-c", "echo held; exec cat > /dev/null"], `flock ${file}`, "pipe");
  const held = await new Promise((resolve) => {
    const poll = setInterval(() => {
      if (holder.out.includes("held") || holder.exitCode !== null) {
        clearInterval(poll);
        resolve(holder.out.includes("held"));
      }
    }, 10);
  });
  if (!held) throw new Error(`DDS domain ${id} is held by another process (lock ${file}): ${holder.err}`);
}
