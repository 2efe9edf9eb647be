// What the MCAP checks (check_mcap.mjs, decode_recording.mjs) share: a file's bytes as the
// readable of McapIndexedReader, the linear read with McapStreamReader, and the data section
// CRC, which @mcap/core does not check itself.

// CRC-32 (IEEE, reflected 0xEDB88320), written here: Debian 12's Node 18 has no zlib.crc32
const kCrcTable = Array.from({ length: 256 }, (_, n) => {
  let c = n;
  for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});
export function crc32(data) {
  let c = 0xffffffff;
  for (const byte of data) c = kCrcTable[(c ^ byte) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

// the file's bytes as McapIndexedReader.Initialize({ readable }) wants them
export function readableOf(bytes) {
  return {
    size: async () => BigInt(bytes.byteLength),
    read: async (offset, size) => bytes.subarray(Number(offset), Number(offset + size)),
  };
}

// every record read in order with chunk CRCs validated (McapStreamReader, passed in: the
// callers import @mcap/core themselves so that a missing module is a skip), and the data
// section CRC recomputed over the bytes before the DataEnd record (13 bytes before the summary)
export function linearRead(McapStreamReader, bytes) {
  const stream = new McapStreamReader({ validateCrcs: true });
  stream.append(bytes);
  let messages = 0;
  let dataEnd;
  let footer;
  for (let r; (r = stream.nextRecord()); ) {
    if (r.type === "Message") messages += 1;
    if (r.type === "DataEnd") dataEnd = r;
    if (r.type === "Footer") footer = r;
  }
  const result = { done: stream.done(), messages, dataEnd, footer };
  if (dataEnd !== undefined && footer !== undefined) {
    result.dataEndOffset = Number(footer.summaryStart) - 13;
    result.dataEndOpcode = bytes[result.dataEndOffset];
    result.dataCrc = crc32(bytes.subarray(0, result.dataEndOffset));
  }
  return result;
}
