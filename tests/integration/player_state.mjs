// The replay player's state at a moment (cli/render/run_data.js), under node, against the native
// replay: for each board, a log is recorded and rendered at tolerance 0 (every piece of each path
// kept, docs/render.md, "Large runs"), the page's run data is decoded by the
// module the page runs, and the board after N events (each ball's name, position and velocity, and
// the time) must be exactly what `gizmo replay LOG --event N --json` says, for N at the start, at
// the end and in between; and the same for a branch of each log taken halfway (gizmo record --from).
//   node player_state.mjs GIZMO RUN_DATA_JS WORK_DIR BOARD SECONDS [BOARD SECONDS...]
import { execFileSync } from "node:child_process";
import { createRequire } from "node:module";
import fs from "node:fs";
import path from "node:path";

const [gizmo, moduleFile, work, ...boards] = process.argv.slice(2);
const RunData = createRequire(import.meta.url)(path.resolve(moduleFile));
fs.mkdirSync(work, { recursive: true });
let failures = 0;
const fail = (what) => { console.error(`FAIL ${what}`); failures++; };
const run = (...args) =>
  execFileSync(gizmo, args, { encoding: "utf8", maxBuffer: 1 << 28, stdio: ["ignore", "pipe", "ignore"] });

// The page's state after k of the log's events (counted from the log's start, or a branch log's)
// against `gizmo replay --event` of the same event, which counts from the parent's start.
function check(name, log, page) {
  run("render", log, "-o", page, "--tolerance", "0");  // every piece kept: the drawn state is the run's
  const html = fs.readFileSync(page, "utf8");
  const open = '<script id="run-data" type="application/json">';
  const from = html.indexOf(open) + open.length;
  const data = JSON.parse(html.slice(from, html.indexOf("</script>", from)));
  const runData = RunData.loadRun(data.runs[0]);
  const n = runData.count;
  const moments = [...new Set([0, 1, 2, Math.floor(n / 3), Math.floor(n / 2), n - 1, n])].filter((k) => k >= 0 && k <= n);
  for (const k of moments) {
    const ours = RunData.stateAfter(runData, k);
    const theirs = JSON.parse(run("replay", log, "--event", String(runData.first + k), "--json"));
    const where = `${name} after ${k} events`;
    if (ours.time !== theirs.time.value) fail(`${where}: time ${ours.time}, gizmo replay ${theirs.time.value}`);
    if (ours.balls.length !== theirs.balls.length) {
      fail(`${where}: ${ours.balls.length} balls, gizmo replay ${theirs.balls.length}`);
      continue;
    }
    ours.balls.forEach((b, j) => {
      const t = theirs.balls[j];
      if (b.name !== t.name) fail(`${where}: ball ${j} is ${b.name}, gizmo replay's ${t.name}`);
      for (const axis of ["x", "y", "vx", "vy"])
        if (b[axis] !== t[axis].value) fail(`${where}: ${b.name}.${axis} ${b[axis]}, gizmo replay ${t[axis].value}`);
    });
  }
  console.log(`${name}: ${moments.length} moments of ${n} events agree with gizmo replay --event`);
  return n;
}

for (let i = 0; i < boards.length; i += 2) {
  const board = boards[i], seconds = boards[i + 1], name = path.basename(board);
  const log = path.join(work, name + ".gzlog");
  run("record", board, "--time", seconds, "-o", log);
  const n = check(name, log, path.join(work, name + ".html"));
  // A branch taken halfway, with no keys: drawn from its first keyframe on.
  const branch = path.join(work, name + ".branch.gzlog");
  run("record", "--from", log, "--event", String(Math.floor(n / 2)), "-o", branch);
  check(name + " (branch)", branch, path.join(work, name + ".branch.html"));
}
process.exit(failures === 0 ? 0 : 1);
