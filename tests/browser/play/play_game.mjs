// The play page in headless Chromium, played with real key events (docs/play.md, the tests):
//   node play_game.mjs SCENARIO GIZMO PAGE OUT_DIR
// SCENARIO `keys` (a board with flippers and an absorber): keys pressed and released on a
// schedule, a pause (the board must not move, and a key pressed then acts at the resumption), a
// probe of the board the page holds, more keys, the page's own Check, then Save. SCENARIO
// `touch`: the same board played by touching the page's key buttons (pointerType "touch"), a
// probe, Check and Save. SCENARIO `crowded`: 30 s of board time at 4× speed, then Save. Either way the saved log must replay
// identical under the native `gizmo replay`, hold every input the page took (each from a trusted
// key event), and, for `keys`, place every ball at the probe's board time exactly where the page
// had it (`gizmo replay LOG --at T --json`, hex floats compared as text). Screenshots of the
// page while it plays go into OUT_DIR.
import fs from "node:fs";
import path from "node:path";
import { checkInputs, fail, gizmoRun as run } from "./native.mjs";
import { Browser, KEYS, sleep } from "./webdriver.mjs";

const [scenario, gizmo, page, outDir] = process.argv.slice(2);
const LONG_SECONDS = Number(process.env.GIZMO_PLAY_LONG_SECONDS || 60);
if (!["keys", "touch", "crowded", "long"].includes(scenario) || !outDir) {
  console.error("usage: node play_game.mjs keys|touch|crowded|long GIZMO PAGE OUT_DIR");
  process.exit(2);
}
const downloads = path.join(outDir, "downloads");
fs.rmSync(downloads, { recursive: true, force: true });
fs.mkdirSync(downloads, { recursive: true });

function say(message) { console.log(`play ${scenario}: ${message}`); }
const gizmoRun = (...args) => run(gizmo, ...args);
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

// The board's keys as the page's buttons, touched with a finger (touch and pointer events of
// pointerType "touch"), as on a phone or a tablet: the spec example's space, Q, W and Delete.
async function playTouch(browser) {
  const button = (code) => `.touch-key[data-code="${code}"]`;
  const schedule = [  // [ms to wait first, key code, ms held]
    [400, 32, 250], [150, 81, 150], [100, 87, 200], [100, 127, 120], [200, 32, 150], [200, 81, 100],
  ];
  for (const [wait, code, hold] of schedule) {
    await sleep(wait);
    await browser.touch(button(code), hold);
  }
  await sleep(300);
  const seen = await probe(browser);
  await browser.touch(button(87), 150);
  await sleep(300);
  await browser.screenshot(path.join(outDir, "playing.png"));
  return seen;
}

// A long game of the crowded board at 64×, which the page pauses at LONG_SECONDS of board time
// (60 s by default; GIZMO_PLAY_LONG_SECONDS says otherwise). The bytes the module holds for the
// recording, measured by the page after every frame, must stay bounded: under 4 MB however long
// the game, as the page takes each chunk as it closes (before, the module kept every chunk: the
// bytes the page now holds).
let memory = null;
async function playLong(browser) {
  await browser.run(`window.gizmoPlay.pauseAt(${LONG_SECONDS});
    const s = document.getElementById('speed'); s.value = '64'; s.dispatchEvent(new Event('change'));`);
  const end = await browser.waitFor("const p = window.gizmoPlay.probe(); return (p.paused || p.stopped) && p;", 300000,
                                    `${LONG_SECONDS} s of board time`);
  if (end.stopped) fail(`the board stopped: ${end.stopped}`);
  const { held } = end;
  memory = { ...held, events: end.events, time: end.time_value };
  if (!(held.module_most < 4e6)) fail(`the module held up to ${held.module_most} bytes for the recording: not bounded`);
  if (!(held.page > 10 * held.module_most)) fail(`the page holds ${held.page} bytes of chunks, the module up to ${held.module_most}`);
  say(`${end.events} events over ${end.time_value.toFixed(1)} s of board time: the page holds ${held.parts} Blobs of ` +
      `${held.page} bytes of chunks (${held.page_per_event.toFixed(2)} per event: what the module held before), the module ` +
      `${held.module} bytes (${held.module_per_event.toFixed(4)} per event; at most ${held.module_most} after a frame)`);
  await browser.screenshot(path.join(outDir, "paused.png"));
  return null;
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
  seen = scenario === "keys" ? await playKeys(browser) : scenario === "touch" ? await playTouch(browser)
    : scenario === "long" ? await playLong(browser) : await playCrowded(browser);
  if (scenario === "keys" || scenario === "touch") await browser.click("#pause");
  end = await probe(browser);
  if (scenario !== "long") {  // (a long game's check runs it twice more in the page: the native replay below does)
    await browser.click("#check");
    checked = await browser.waitFor("const t = document.getElementById('log-status').textContent; return t.startsWith('Check at') && t;",
                                    60000, "the page's check");
  }
  await browser.click("#save");
  saved = await browser.waitFor(
    "return document.getElementById('log-status').className === 'good' && document.getElementById('log-status').textContent.startsWith('Saved') && document.getElementById('log-status').textContent;",
    60000, "the log to be saved");
  await browser.screenshot(path.join(outDir, "saved.png"));
} finally {
  // The download finishes in the background: wait for the file before the browser goes.
  for (let i = 0; i < 300 && !fs.readdirSync(downloads).some((f) => f.endsWith(".gzlog")); i++) await sleep(100);
  await browser.quit();
}

if (scenario !== "long") {
  say(`the page's check: ${checked}`);
  if (!/identical/.test(checked) || !/every ball at its end is where the game has it/.test(checked))
    fail(`the page's own check did not find the log identical: ${checked}`);
}
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
// (An input taken at a board time the board has not reached yet is not part of the game so far.)
const taken = end.inputs.filter((k) => k.time_value <= end.time_value);
const inputs = checkInputs(gizmo, log, taken);
if (scenario === "keys" && inputs < 20) fail(`only ${inputs} inputs taken from the schedule's keys`);
if (scenario === "touch" && (inputs !== 14 || taken.some((k) => k.source !== "touch")))
  fail(`the touches gave ${inputs} inputs, from ${[...new Set(taken.map((k) => k.source))].join(", ")}; expected 14, all from touch`);
if (inputs) say(`${inputs} inputs, each from a trusted ${scenario === "touch" ? "touch on a key button" : "key event"}, in the log at the page's board times`);

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
if (scenario !== "long") gizmoRun("render", log, "-o", path.join(outDir, "replay.html"));
if (memory) fs.writeFileSync(path.join(outDir, "memory.json"), JSON.stringify(memory, null, 2) + "\n");
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
