// A Foxglove client for measurements (bench/foxglove_cost.sh), not a test: connects to a
// towsim_foxglove bridge, subscribes to every channel, waits `settle` seconds for the bridge's
// DDS readers to match, resumes a node started with --paused (SimControl RESUME through
// clientPublish), decodes every message and ends when the node's status says its run ended.
//   node subscribe_all.mjs URL [SETTLE_S]
// Prints: subscribe_all: N messages on M channels
import { WebSocket } from "ws";
import wsProtocol from "@foxglove/ws-protocol";
import { parse } from "@foxglove/rosmsg";
import { MessageReader, MessageWriter } from "@foxglove/rosmsg2-serialization";

const { FoxgloveClient } = wsProtocol;
const [url, settleText] = process.argv.slice(2);
const settle = 1000 * Number(settleText ?? 1);
const client = new FoxgloveClient({ ws: new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]) });
const channels = new Map();
let count = 0;
let resumed = false;
client.on("advertise", (list) => {
  for (const c of list) {
    const defs = parse(c.schema, { ros2: true });
    const sub = client.subscribe(c.id);
    channels.set(sub, { topic: c.topic, reader: new MessageReader(defs) });
    if (c.topic.endsWith("/sim_control") && !resumed) {
      resumed = true;
      const writer = new MessageWriter(defs);
      const ch = client.advertise({ topic: c.topic, encoding: "cdr", schemaName: c.schemaName });
      setTimeout(() => client.sendMessage(ch, writer.writeMessage({
        header: { stamp: { sec: 0, nanosec: 0 }, frame_id: "" }, command: 2, steps: 0, rate: 0 })), settle);
    }
  }
});
client.on("message", ({ subscriptionId, data }) => {
  const c = channels.get(subscriptionId);
  const v = c.reader.readMessage(new Uint8Array(data.buffer, data.byteOffset, data.byteLength));
  count += 1;
  if (c.topic.endsWith("/status") && v.state >= 3) {
    console.log(`subscribe_all: ${count} messages on ${channels.size} channels`);
    client.close();
    process.exit(0);
  }
});
