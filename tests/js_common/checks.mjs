// What the JavaScript checks (tests/mcap_js/decode_recording.mjs, tests/foxglove_js/
// live_check.mjs) share, with no node module of its own: the failure count, the comparison of
// a decoded number with the node's CSV text, and a CSV file as rows of named fields.
import { readFileSync } from "node:fs";

// the CSV prints 9 significant digits ("%.9g", sim_node/io/csv_writer.h): a decoded value v and
// its CSV text c agree when |v - c| <= kRelCsv |c| + abs
export const kRelCsv = 5e-9; // half a unit in the 9th significant digit
export const kAbs = 1e-300; // exact zeros print as 0

let failureCount = 0;

// counts a failed check and prints the first 20; returns ok
export function check(ok, what) {
  if (!ok) {
    failureCount += 1;
    if (failureCount <= 20) console.error(`FAIL: ${what}`);
  }
  return ok;
}

export function failures() {
  return failureCount;
}

// the decoded value v against the CSV text (kRelCsv, plus `abs` for values computed here)
export function near(v, csvText, what, abs = kAbs) {
  const c = Number(csvText);
  return check(Math.abs(Number(v) - c) <= kRelCsv * Math.abs(c) + abs, `${what}: ${v} vs CSV ${csvText}`);
}

// the rows of a CSV file (a header line, no quoted fields) as objects keyed by the header
export function readCsv(path) {
  const lines = readFileSync(path, "utf8").trim().split("\n");
  const header = lines.shift().split(",");
  return lines.map((l) => Object.fromEntries(l.split(",").map((v, i) => [header[i], v])));
}
