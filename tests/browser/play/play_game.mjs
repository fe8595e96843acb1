// The play page in headless Chromium, played with real key events (docs/play.md, the tests):
//   node play_game.mjs SCENARIO GIZMO PAGE OUT_DIR
// SCENARIO `keys` (a board with flippers and an absorber): keys pressed and released on a
// schedule, a pause (the board must not move, and a key pressed then acts at the resumption), a
// probe of the board the page holds, more keys, the page's own Check, then Save. SCENARIO
// `crowded`: 30 s of board time at 4× speed, then Save. Either way the saved log must replay
// identical under the native `gizmo replay`, hold every input the page took (each from a trusted
// key event), and, for `keys`, place every ball at the probe's board time exactly where the page
// had it (`gizmo replay LOG --at T --json`, hex floats compared as text). Screenshots of the
// page while it plays go into OUT_DIR.
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import { Browser, KEYS, sleep } from "./webdriver.mjs";

const [scenario, gizmo, page, outDir] = process.argv.slice(2);
if (!["keys", "crowded"].includes(scenario) || !outDir) {
  console.error("usage: node play_game.mjs keys|crowded GIZMO PAGE OUT_DIR");
  process.exit(2);
}
const downloads = path.join(outDir, "downloads");
fs.rmSync(downloads, { recursive: true, force: true });
fs.mkdirSync(downloads, { recursive: true });

function fail(message) { throw new Error(message); }
function say(message) { console.log(`play ${scenario}: ${message}`); }
function gizmoRun(...args) {
  try {
    return execFileSync(gizmo, args, { encoding: "utf8", stdio: ["ignore", "pipe", "pipe"] });
  } catch (e) {
    fail(`gizmo ${args.join(" ")} exited ${e.status}:\n${e.stdout}\n${e.stderr}`);
  }
}
const probe = (browser) => browser.run("return window.gizmoPlay.probe();");

async function playKeys(browser) {
  const schedule = [  // [ms to wait first, direction, key]
    [400, "down", KEYS.space], [250, "up", KEYS.space], [150, "down", KEYS.q], [100, "down", KEYS.w],
    [250, "up", KEYS.q], [50, "up", KEYS.w], [100, "down", KEYS.delete], [80, "up", KEYS.delete],
  ];
  for (const [wait, direction, key] of schedule) {
    await sleep(wait);
    await browser.key(direction, key);
  }
  await sleep(200);
  await browser.screenshot(path.join(outDir, "playing.png"));

  // Paused: board time stands still, and a key pressed now is taken at that time.
  await browser.click("#pause");
  await sleep(100);
  const paused = await probe(browser);
  await sleep(400);
  const stillPaused = await probe(browser);
  if (!paused.paused || stillPaused.time !== paused.time || stillPaused.events !== paused.events)
    fail(`the board moved while paused: ${paused.time} (${paused.events} events), then ${stillPaused.time} (${stillPaused.events})`);
  await browser.key("down", KEYS.space);
  await browser.screenshot(path.join(outDir, "paused.png"));
  await browser.click("#pause");  // resume
  await sleep(300);
  await browser.key("up", KEYS.space);
  say(`paused at board time ${paused.time_value} s for 0.5 s of wall time: the board did not move`);

  for (let round = 0; round < 3; round++) {
    await sleep(200);
    await browser.key("down", KEYS.space);
    await sleep(120);
    await browser.key("up", KEYS.space);
  }
  await sleep(300);
  const seen = await probe(browser);  // the board at one moment, to find again in the log
  for (let round = 0; round < 2; round++) {
    await sleep(150);
    await browser.key("down", KEYS.q);
    await sleep(100);
    await browser.key("up", KEYS.q);
  }
  await sleep(300);
  await browser.screenshot(path.join(outDir, "later.png"));
  return seen;
}

async function playCrowded(browser) {
  await browser.run("const s = document.getElementById('speed'); s.value = '4'; s.dispatchEvent(new Event('change'));");
  let shot = false;
  for (;;) {
    const p = await probe(browser);
    if (p.stopped) fail(`the board stopped: ${p.stopped}`);
    if (!shot && p.time_value >= 10) {
      await browser.screenshot(path.join(outDir, "playing.png"));
      shot = true;
    }
    if (p.time_value >= 30) break;
    await sleep(100);
  }
  await browser.click("#pause");
  await browser.screenshot(path.join(outDir, "paused.png"));
  return null;
}

const browser = await Browser.start({
  profileDir: path.join(outDir, "profile"), downloadDir: downloads,
});
let seen, end, checked, saved;
try {
  await browser.open("file://" + path.resolve(page));
  await browser.waitFor("return window.gizmoPlay && window.gizmoPlay.ready;", 60000, "the play module to start");
  seen = scenario === "keys" ? await playKeys(browser) : await playCrowded(browser);
  if (scenario === "keys") await browser.click("#pause");
  end = await probe(browser);
  await browser.click("#check");
  checked = await browser.run("return document.getElementById('log-status').textContent;");
  await browser.click("#save");
  saved = await browser.waitFor(
    "return document.getElementById('log-status').className === 'good' && document.getElementById('log-status').textContent.startsWith('Saved') && document.getElementById('log-status').textContent;",
    60000, "the log to be saved");
  await browser.screenshot(path.join(outDir, "saved.png"));
} finally {
  // The download finishes in the background: wait for the file before the browser goes.
  for (let i = 0; i < 100 && !fs.readdirSync(downloads).some((f) => f.endsWith(".gzlog")); i++) await sleep(100);
  await browser.quit();
}

say(`the page's check: ${checked}`);
if (!/identical/.test(checked) || !/every ball at its end is where the game has it/.test(checked))
  fail(`the page's own check did not find the log identical: ${checked}`);
say(saved);
const logs = fs.readdirSync(downloads).filter((f) => f.endsWith(".gzlog"));
if (logs.length !== 1) fail(`expected one downloaded log, found ${JSON.stringify(fs.readdirSync(downloads))}`);
if (!/^[A-Za-z0-9_-]+-\d{8}-\d{6}\.gzlog$/.test(logs[0])) fail(`the log's name ${logs[0]} is not NAME-YYYYMMDD-HHMMSS.gzlog`);
const log = path.join(outDir, "game.gzlog");
fs.copyFileSync(path.join(downloads, logs[0]), log);

// The native replay: identical, to the page's last moment.
const replayed = gizmoRun("replay", log);
if (!/^identical/.test(replayed)) fail(`gizmo replay: ${replayed}`);
say(`gizmo replay: ${replayed.trim()}`);
const summary = JSON.parse(gizmoRun("replay", log, "--at", String(end.time_value), "--json"));
if (summary.time.exact !== end.time) fail(`the log ends at ${summary.time.exact}, the page was at ${end.time}`);
if (summary.events !== end.events) fail(`the log has ${summary.events} events by its end, the page ran ${end.events}`);

// Every input the page took, from a real (trusted) key event, at the time the page gave it.
const inputs = gizmoRun("dump", log, "--kind", "input", "--exact", "--json").split("\n").filter((l) => l)
  .map((l) => JSON.parse(l)).filter((d) => d.type === "input");
// (An input taken at a board time the board has not reached yet is not part of the game so far.)
const taken = end.inputs.filter((k) => k.time_value <= end.time_value);
if (inputs.length !== taken.length) fail(`the log holds ${inputs.length} inputs, the page took ${taken.length} by its end`);
inputs.forEach((d, i) => {
  const k = taken[i];
  if (d.time.exact !== k.time || d.key !== k.code || d.direction !== (k.up ? "up" : "down"))
    fail(`input ${i}: the log has key ${d.key} ${d.direction} at ${d.time.exact}, the page took ${k.code} ${k.up ? "up" : "down"} at ${k.time}`);
});
if (taken.some((k) => !k.trusted)) fail("an input came from a key event the browser did not mark as trusted");
if (scenario === "keys" && inputs.length < 20) fail(`only ${inputs.length} inputs taken from the schedule's keys`);
if (inputs.length) say(`${inputs.length} inputs, each from a trusted key event, in the log at the page's board times`);

// The board the page showed at one moment, exactly where the log has it.
if (seen) {
  const at = JSON.parse(gizmoRun("replay", log, "--at", String(seen.time_value), "--json"));
  if (at.time.exact !== seen.time) fail(`gizmo replay --at gave time ${at.time.exact}, the page's was ${seen.time}`);
  if (at.balls.length !== seen.balls.length) fail(`the log has ${at.balls.length} balls, the page ${seen.balls.length}`);
  at.balls.forEach((b, i) => {
    const p = seen.balls[i];
    for (const axis of ["x", "y", "vx", "vy"])
      if (b[axis].exact !== p[axis]) fail(`ball ${b.name} at t = ${seen.time}: ${axis} is ${b[axis].exact} in the log, ${p[axis]} in the page`);
  });
  say(`at board time ${seen.time_value} s (${seen.time}) every ball is where the page had it, bit for bit`);
}
// The other native commands take the log as any other: the replay player, and (a short game)
// the certification of every decision.
gizmoRun("render", log, "-o", path.join(outDir, "replay.html"));
if (scenario === "keys") {
  const certified = gizmoRun("verify", log, "--certify");
  if (!/wrong decisions: 0/.test(certified)) fail(`gizmo verify --certify: ${certified}`);
  say(`gizmo verify --certify: ${certified.split("\n")[0]}`);
  // The game as the starting point of a campaign of variations (docs/fuzzing.md, "Fuzzing your
  // own board"): its board and key input, varied, under every property.
  const fuzzed = gizmoRun("fuzz", log, "--count", "8", "--seed", "1");
  if (!/^fuzz: variations of run [0-9a-f]{16}, seed 1, 8 of 8 cases, 6 properties .*, 0 failures/.test(fuzzed))
    fail(`gizmo fuzz LOG: ${fuzzed}`);
  say(`gizmo fuzz LOG: ${fuzzed.trim()}`);
}
console.log(`play ${scenario}: passed (${end.events} events over ${end.time_value} s; log and screenshots in ${outDir})`);
