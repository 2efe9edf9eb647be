// Opens an MCAP file written by towsim's McapWriter with an independent reader, @mcap/core
// (the reader Foxglove uses), and checks it:
//   node check_mcap.mjs FILE N        (FILE as written by write_fixture FILE N)
// - McapIndexedReader: magic, footer, summary CRC; profile "ros2"; schemas "ros2msg";
//   channels "cdr"; statistics; every chunk CRC (validateCrcs) while reading every message in
//   log-time order, with the payload pattern of write_fixture.cc
// - McapStreamReader: a linear read of every record (chunk CRCs again), same message count
// - the DataEnd CRC, recomputed here over the bytes before the DataEnd record
// Exits 77 (ctest: skipped) when the node modules are missing: run `npm ci` in this folder.
import { readFileSync } from "node:fs";

import { linearRead, readableOf } from "./mcap_file.mjs";

let mcap;
try {
  mcap = await import("@mcap/core");
} catch (e) {
  console.error(`@mcap/core not installed (run "npm ci" in tests/mcap_js): ${e.message}`);
  process.exit(77);
}
const { McapIndexedReader, McapStreamReader } = mcap;

const [file, nArg] = process.argv.slice(2);
const n = Number(nArg);
const kT0 = 1700000000000000000n;
const kMs = 1000000n;
let failures = 0;

function check(ok, what) {
  if (!ok) {
    failures += 1;
    console.error(`FAIL: ${what}`);
  }
}

const bytes = new Uint8Array(readFileSync(file));
const readable = readableOf(bytes);

// indexed read
const reader = await McapIndexedReader.Initialize({ readable });
check(reader.header.profile === "ros2", `profile ${reader.header.profile}`);
check(reader.header.library === "towsim", `library ${reader.header.library}`);
check(reader.schemasById.size === 2, `schemas ${reader.schemasById.size}`);
for (const s of reader.schemasById.values()) check(s.encoding === "ros2msg", `schema ${s.name}`);
const clock = [...reader.schemasById.values()].find((s) => s.name === "rosgraph_msgs/msg/Clock");
check(
  clock && new TextDecoder().decode(clock.data).includes("\nMSG: builtin_interfaces/Time\n"),
  "Clock schema with its dependency",
);
check(reader.channelsById.size === 3, `channels ${reader.channelsById.size}`);
for (const c of reader.channelsById.values()) {
  check(c.messageEncoding === "cdr", `channel ${c.topic} encoding ${c.messageEncoding}`);
}
const stats = reader.statistics;
check(stats !== undefined, "statistics present");
check(stats.messageCount === BigInt(n), `statistics messageCount ${stats.messageCount}`);
check(stats.chunkCount === reader.chunkIndexes.length, `chunkCount ${stats.chunkCount}`);
check(stats.messageStartTime === kT0, `messageStartTime ${stats.messageStartTime}`);
check(stats.messageEndTime === kT0 + BigInt(n - 1) * kMs, `messageEndTime`);
check(reader.metadataIndexes.length === 1, "one metadata record");

const counts = new Map();
let i = 0;
for await (const m of reader.readMessages({ validateCrcs: true })) {
  const t = kT0 + BigInt(i) * kMs;
  const view = new DataView(m.data.buffer, m.data.byteOffset, m.data.byteLength);
  if (m.logTime !== t || m.publishTime !== t - 5n || view.getUint32(4, true) !== i ||
      m.data[8] !== m.channelId || m.data.byteLength !== 9 + (i % 37) ||
      m.channelId !== [...reader.channelsById.keys()][i % 3]) {
    check(false, `message ${i}: channel ${m.channelId}, log time ${m.logTime}`);
    break;
  }
  counts.set(m.channelId, (counts.get(m.channelId) ?? 0) + 1);
  i += 1;
}
check(i === n, `indexed reader read ${i} messages, expected ${n}`);
for (const [id, count] of stats.channelMessageCounts) {
  check(BigInt(counts.get(id) ?? 0) === count, `channel ${id}: ${counts.get(id)} vs ${count}`);
}

// linear read of every record, and the data section CRC (@mcap/core does not check it)
const linear = linearRead(McapStreamReader, bytes);
check(linear.done, "stream reader reached the end");
check(linear.messages === n, `stream reader read ${linear.messages} messages`);
check(linear.dataEnd !== undefined && linear.footer !== undefined, "DataEnd and Footer records");
check(linear.dataEndOpcode === 0x0f, "DataEnd record right before the summary");
check(
  linear.dataEnd !== undefined && linear.dataCrc === linear.dataEnd.dataSectionCrc,
  `data CRC ${linear.dataCrc} vs ${linear.dataEnd?.dataSectionCrc}`,
);

if (failures > 0) process.exit(1);
console.log(`ok: ${n} messages, ${reader.chunkIndexes.length} chunks, ${counts.size} channels`);
