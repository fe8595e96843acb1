// The play page takes a saved log over (docs/play.md, "Taking over a log"), in headless Chromium
// with real input:
//   node take_over.mjs GIZMO PAGE PARENT_LOG OUT_DIR
// The page opens PARENT_LOG with its file button, is scrubbed on the log's timeline (a mouse
// press on it: the board shown there must be `gizmo replay --at`'s, bit for bit), takes over
// ("play from here": the board the game holds is the parent's at that tick end), is played with
// real keys, checked (the page's own check: the branch replays identical and is byte for byte
// the log `gizmo record --from` writes) and saved. Then it plays on, rewinds 5 s (a branch of
// the game so far), plays again, and saves both that branch and the log it took over. Natively:
// every log replays identical; `gizmo record --from PARENT --at T --keys K` writes each branch's
// very bytes; `gizmo diff` of parent and branch agrees up to the branch point and parts after.
import fs from "node:fs";
import path from "node:path";
import { checkInputs, fail, gizmoRun, gizmoRunAllowing, keyScript, nextDownload } from "./native.mjs";
import { Browser, KEYS, sleep } from "./webdriver.mjs";

const [gizmo, page, parentLog, outDir] = process.argv.slice(2);
if (!outDir) {
  console.error("usage: node take_over.mjs GIZMO PAGE PARENT_LOG OUT_DIR");
  process.exit(2);
}
const downloads = path.join(outDir, "downloads");
fs.rmSync(downloads, { recursive: true, force: true });
fs.mkdirSync(downloads, { recursive: true });
const known = [];
const say = (message) => console.log(`play take_over: ${message}`);
const run = (...args) => gizmoRun(gizmo, ...args);
const probe = (browser) => browser.run("return window.gizmoPlay.probe();");

// Every ball of `balls` (the page's, hex floats) where `gizmo replay LOG --at T --json` has it.
function sameBalls(log, t, balls, what) {
  const at = JSON.parse(run("replay", log, "--at", String(t), "--json"));
  if (at.balls.length !== balls.length) fail(`${what}: the log has ${at.balls.length} balls, the page ${balls.length}`);
  at.balls.forEach((b, i) => {
    for (const axis of ["x", "y", "vx", "vy"])
      if (b[axis].exact !== balls[i][axis]) fail(`${what}: ball ${b.name} ${axis} is ${b[axis].exact} in the log, ${balls[i][axis]} in the page`);
  });
  return at;
}

async function playKeys(browser, rounds) {
  for (let round = 0; round < rounds; round++) {
    for (const key of [KEYS.space, KEYS.q, KEYS.w]) {
      await sleep(120);
      await browser.key("down", key);
      await sleep(90);
      await browser.key("up", key);
    }
  }
  await sleep(200);
}

async function checkAndSave(browser, name) {
  await browser.click("#pause");
  const end = await probe(browser);
  await browser.click("#check");
  const checked = await browser.waitFor("const t = document.getElementById('log-status').textContent; return t.startsWith('Check at') && t;",
                                        60000, `the page's check of ${name}`);
  if (!/^Check at .*identical: .*byte for byte the log gizmo record --from writes of them; every ball at its end is where the game has it/.test(checked))
    fail(`the page's check of ${name}: ${checked}`);
  say(`the page's check of ${name}: ${checked}`);
  await browser.click("#save");
  await browser.waitFor("return !window.gizmoPlay.probe().busy;", 60000, "the log to be written");
  const file = path.join(outDir, name + ".gzlog");
  say(`saved ${await nextDownload(downloads, known, file)} as ${name}.gzlog`);
  return { end, file };
}

const browser = await Browser.start({ profileDir: path.join(outDir, "profile"), downloadDir: downloads });
let scrubbed, taken, first, beforeRewind, rewound, second, parentOfSecond, dropped;
try {
  await browser.open("file://" + path.resolve(page));
  await browser.waitFor("return window.gizmoPlay && window.gizmoPlay.ready;", 60000, "the play module to start");
  await browser.chooseFile("#open-log", path.resolve(parentLog));
  await browser.waitFor("const p = window.gizmoPlay.probe(); return p.shown !== null;", 30000, "the log to open");
  await browser.clickAcross("#timeline", 0.55);  // scrub: a press on the log's timeline
  await sleep(100);
  scrubbed = (await probe(browser)).shown;
  await browser.screenshot(path.join(outDir, "scrubbed.png"));
  await browser.click("#pause");  // paused, the game stays at the moment taken over until it resumes
  await browser.click("#take-over");
  taken = await probe(browser);
  await browser.click("#pause");
  if (!taken.branch || taken.shown)
    fail(`"play from here" did not take the log over: ${await browser.run("return document.getElementById('status').textContent;")}`);
  await browser.run("const s = document.getElementById('speed'); s.value = '2'; s.dispatchEvent(new Event('change'));");
  await playKeys(browser, 3);
  await browser.screenshot(path.join(outDir, "playing.png"));
  first = await checkAndSave(browser, "branch");
  await browser.click("#pause");  // resume
  await browser.waitFor(`return window.gizmoPlay.probe().time_value >= ${first.end.time_value + 6};`, 20000, "six more seconds of play");
  beforeRewind = await probe(browser);
  await browser.click("#rewind");
  rewound = await browser.waitFor("const p = window.gizmoPlay.probe(); return !p.busy && p.branch && p.branch.at !== " +
                                  `${taken.branch.at} && p;`, 30000, "the rewind");
  await playKeys(browser, 2);
  second = await checkAndSave(browser, "rewound");
  await browser.click("#save-parent");
  parentOfSecond = path.join(outDir, "before-rewind.gzlog");
  say(`saved ${await nextDownload(downloads, known, parentOfSecond)} (the log taken over by the rewind) as before-rewind.gzlog`);
  await browser.screenshot(path.join(outDir, "saved.png"));
  // A log file dropped on the page opens as one chosen with the button (a drop made by a script:
  // WebDriver has no drag of a file from outside the page).
  await browser.run(`const bytes = Uint8Array.from(atob(arguments[0]), (c) => c.charCodeAt(0));
    const files = new DataTransfer();
    files.items.add(new File([bytes], "dropped.gzlog"));
    document.getElementById("stage").dispatchEvent(new DragEvent("drop", { dataTransfer: files, bubbles: true, cancelable: true }));`,
    fs.readFileSync(second.file).toString("base64"));
  dropped = await browser.waitFor("const p = window.gizmoPlay.probe(); return p.shown && p.shown.name === 'dropped.gzlog' && p;",
                                  30000, "the dropped log to open");
} finally {
  await browser.quit();
}

// The scrubbed moment: the board the page drew from the log's run data, where the log has it.
sameBalls(parentLog, scrubbed.time_value, scrubbed.balls, "the scrubbed moment");
say(`scrubbed to t = ${scrubbed.time_value} s (${scrubbed.events} events): every ball drawn where gizmo replay --at has it, bit for bit`);
// Taken over: the game's board at the tick end, the parent's there.
const at = sameBalls(parentLog, taken.time_value, taken.balls, "the board taken over");
if (at.events !== taken.events) fail(`taken over at ${taken.time}: the page has run ${taken.events} events, the parent ${at.events}`);
if (!(taken.time_value <= scrubbed.time_value)) fail(`taken over at ${taken.time_value} s, after the moment shown ${scrubbed.time_value} s`);
say(`taken over at t = ${taken.time_value} s after event ${taken.branch.event}: the game's board is the parent's there, bit for bit`);

// Each branch natively: identical; the inputs the page took after its branch point; the bytes
// `gizmo record --from` writes of the parent, point and keys; parted from its parent after the point.
function checkBranch(name, parent, log, startProbe, end) {
  const replayed = run("replay", log);
  if (!/^identical/.test(replayed)) fail(`gizmo replay ${name}: ${replayed}`);
  const inputs = end.inputs.filter((k) => k.time_value <= end.time_value);
  checkInputs(gizmo, log, inputs, startProbe.branch.at);
  const keys = path.join(outDir, name + ".keys");
  fs.writeFileSync(keys, keyScript(inputs));
  const again = path.join(outDir, name + "-again.gzlog");
  run("record", "--from", parent, "--at", String(startProbe.branch.at), "--keys", keys, "--time", String(end.time_value), "-o", again);
  if (!fs.readFileSync(again).equals(fs.readFileSync(log)))
    fail(`${name}: gizmo record --from ${path.basename(parent)} --at ${startProbe.branch.at} with the page's keys does not write the page's bytes`);
  // gizmo diff exits 1 when the logs part.
  const diff = JSON.parse(gizmoRunAllowing([1], gizmo, "diff", parent, log, "--json"));
  const point = startProbe.branch.at;
  const parting = Math.min(diff.first ? diff.first.time.value : Infinity, diff.second ? diff.second.time.value : Infinity);
  if (!diff.parted || !(diff.matched > 0) || !(parting >= point))
    fail(`${name}: gizmo diff ${path.basename(parent)} ${path.basename(log)} does not part after the branch point ` +
         `(${point} s): ${JSON.stringify(diff).slice(0, 600)}`);
  say(`${name}: gizmo diff: alike for ${diff.matched} decisions from decision ${diff.first_decision}, ` +
      `parting at decision ${diff.first_decision + diff.matched} (t = ${parting} s, after the branch point at ${point} s): ${diff.where}`);
  return { replayed: replayed.trim(), inputs: inputs.length, diff };
}
const one = checkBranch("branch", parentLog, first.file, taken, first.end);
say(`branch: gizmo replay: ${one.replayed}; ${one.inputs} inputs; byte for byte gizmo record --from's`);
run("replay", parentOfSecond);
const two = checkBranch("rewound", parentOfSecond, second.file, rewound, second.end);
// Five seconds back from the moment of the click (a little after the probe before it), rounded
// down to a tick end of the log's 0.01 s.
const { at: back, from } = rewound.branch;
if (!(from >= beforeRewind.time_value && back <= from - 5 && back > from - 5 - 0.0100001))
  fail(`rewound to ${back} s from ${from} s (the probe before at ${beforeRewind.time_value} s): not five seconds back`);
say(`rewound from t = ${from} s to ${back} s: gizmo replay: ${two.replayed}; ${two.inputs} inputs; byte for byte gizmo record --from's`);
// The dropped branch log shown from its start: the board where the log has it there.
sameBalls(second.file, dropped.shown.time_value, dropped.shown.balls, "the dropped log at its start");
say(`a branch log dropped on the page opens at its start, t = ${dropped.shown.time_value} s, every ball where the log has it`);
console.log("play take_over: passed");
