// What the play page's browser tests share: the native gizmo run on the logs the page saved, the
// downloads waited for, and the check that a log holds exactly the inputs the page took.
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import { sleep } from "./webdriver.mjs";

export function fail(message) { throw new Error(message); }

// Runs the native gizmo; its standard output, or a failure with everything it said when it exits
// with another code than those `allowed`.
export function gizmoRunAllowing(allowed, gizmo, ...args) {
  try {
    return execFileSync(gizmo, args, { encoding: "utf8", stdio: ["ignore", "pipe", "pipe"] });
  } catch (e) {
    if (allowed.includes(e.status)) return e.stdout;
    fail(`gizmo ${args.join(" ")} exited ${e.status}:\n${e.stdout}\n${e.stderr}`);
  }
}
export function gizmoRun(gizmo, ...args) { return gizmoRunAllowing([], gizmo, ...args); }

// The next .gzlog to land in `dir` that is not among `known` (names), copied to `to`; its name.
export async function nextDownload(dir, known, to) {
  for (let i = 0; i < 200; i++) {
    const fresh = fs.readdirSync(dir).filter((f) => f.endsWith(".gzlog") && !known.includes(f));
    if (fresh.length > 1) fail(`expected one new download, found ${JSON.stringify(fresh)}`);
    if (fresh.length === 1) {
      fs.copyFileSync(path.join(dir, fresh[0]), to);
      known.push(fresh[0]);
      return fresh[0];
    }
    await sleep(100);
  }
  fail(`no log was downloaded into ${dir}`);
}

// The log's inputs from `from` (a board time, exclusive) on, against the page's inputs `taken`
// ({code, up, time (hex), trusted}): the same keys, directions and board times, to the bit.
export function checkInputs(gizmo, log, taken, from = -Infinity) {
  const inputs = gizmoRun(gizmo, "dump", log, "--kind", "input", "--exact", "--json").split("\n").filter((l) => l)
    .map((l) => JSON.parse(l)).filter((d) => d.type === "input" && d.time.value > from);
  if (inputs.length !== taken.length) fail(`${log} holds ${inputs.length} inputs, the page took ${taken.length}`);
  inputs.forEach((d, i) => {
    const k = taken[i];
    if (d.time.exact !== k.time || d.key !== k.code || d.direction !== (k.up ? "up" : "down"))
      fail(`input ${i}: the log has key ${d.key} ${d.direction} at ${d.time.exact}, the page took ${k.code} ${k.up ? "up" : "down"} at ${k.time}`);
  });
  if (taken.some((k) => !k.trusted)) fail("an input came from an event the browser did not mark as trusted");
  return inputs.length;
}

// A key script (`gizmo record --keys`) of the page's inputs: the board times as the page's doubles.
export function keyScript(taken) {
  return taken.map((k) => `${k.time_value} ${k.up ? "up" : "down"} ${k.code}\n`).join("");
}
