// The play page when its module's memory runs short (docs/play.md, "Memory"), in headless Chromium:
//   node memory_short.mjs GIZMO PAGE MAX_MB OUT_DIR
// The page (of the crowded board, at gizmo play's model and tick) is opened as PAGE#max-memory=MAX_MB,
// so the module's memory may grow to MAX_MB only, and played at 64×: an allocation of the
// module fails within seconds, where a long game would meet the browser's limit. The page must say
// that its memory ran short, the board must stop there (board time and events stand still), and
// "save log" must download a log. Natively that log is the game cut off after its last complete
// chunk: byte for byte the start of the log `gizmo record` writes of the same board to the same
// end, and the native reader finds it cut off after N complete chunks (those the page closed); `gizmo replay`
// replays every decision it holds identically, says where it is cut off, and exits 2.
import { spawnSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import { fail, gizmoRun, nextDownload } from "./native.mjs";
import { Browser, sleep } from "./webdriver.mjs";

const [gizmo, page, maxMb, out] = process.argv.slice(2);
const outDir = out && path.resolve(out);
if (!outDir || !/^\d+$/.test(maxMb)) {
  console.error("usage: node memory_short.mjs GIZMO PAGE MAX_MB OUT_DIR");
  process.exit(2);
}
function say(message) { console.log(`play memory_short: ${message}`); }
const downloads = path.join(outDir, "downloads");
fs.rmSync(downloads, { recursive: true, force: true });
fs.mkdirSync(downloads, { recursive: true });
const probe = (browser) => browser.run("return window.gizmoPlay.probe();");
const text = (browser, id) => browser.run(`return document.getElementById('${id}').textContent;`);

const log = path.join(outDir, "game.gzlog");
const browser = await Browser.start({ profileDir: path.join(outDir, "profile"), downloadDir: downloads });
let stop, saved;
try {
  await browser.open("file://" + path.resolve(page) + "#max-memory=" + maxMb);
  await browser.waitFor("return window.gizmoPlay && window.gizmoPlay.ready;", 60000, "the play module to start");
  await browser.run("const s = document.getElementById('speed'); s.value = '64'; s.dispatchEvent(new Event('change'));");
  stop = await browser.waitFor("const p = window.gizmoPlay.probe(); return p.stopped && p;", 120000,
                               `the module's memory (at most ${maxMb} MB) to run short`);
  const status = await text(browser, "status");
  say(`stopped at board time ${stop.time_value} s after ${stop.events} events, ${stop.held.chunks} chunks closed, ` +
      `the module's memory ${stop.held.memory} bytes, ${stop.held.module} of them held for the recording: "${status}"`);
  if (stop.stopped !== "the page's memory ran short") fail(`the board stopped for another reason: ${stop.stopped}`);
  if (status !== "The board stopped: the page's memory ran short. Save the log to keep the game up to here.")
    fail(`the page says: ${status}`);
  if (!(stop.held.memory <= Number(maxMb) * 2 ** 20)) fail(`the module's memory grew to ${stop.held.memory} bytes`);
  if (!(stop.held.chunks >= 2)) fail(`only ${stop.held.chunks} chunks closed before the memory ran short: a higher MAX_MB`);
  await sleep(500);
  const later = await probe(browser);
  say(`then: the module holds ${later.held.module} bytes for the recording, the page ${later.held.page} in ${later.held.parts} Blobs`);
  if (later.time !== stop.time || later.events !== stop.events || later.target !== stop.target)
    fail(`the board went on after it stopped: ${stop.time} (${stop.events} events), then ${later.time} (${later.events})`);
  await browser.screenshot(path.join(outDir, "stopped.png"));
  await browser.click("#save");
  saved = await browser.waitFor("const s = document.getElementById('log-status'); return s.className && s.textContent;",
                                60000, "the log to be saved");
  say(saved);
  if (!saved.startsWith("Saved")) fail(`the log was not saved: ${saved}`);
  if (!saved.endsWith(" memory ran short: the log holds the game up to its last complete chunk"))
    fail(`the page did not say the log is cut at its last complete chunk: ${saved}`);
  await nextDownload(downloads, [], log);
} finally {
  await browser.quit();
}

// The game from time 0 recorded natively to the end the page's log has in its header: its bytes
// must begin with the page's whole log, which must end where that log's chunk N ends.
const bytes = fs.readFileSync(log);
const whole = path.join(outDir, "native.gzlog");
gizmoRun(gizmo, "record", "fixtures/boards/play/crowded-100-balls.txt", "--time", String(stop.log_end), "--max-tick", "0.01",
         "-o", whole);
const native = fs.readFileSync(whole);
if (!(bytes.length < native.length) || Buffer.compare(bytes, native.subarray(0, bytes.length)) !== 0)
  fail(`the page's log (${bytes.length} bytes) is not the start of gizmo record's (${native.length} bytes)`);
say(`the page's log is the first ${bytes.length} of ${native.length} bytes of gizmo record's log of the same game`);

// The native reader: every decision of the complete chunks replays identically, then it says where
// the log stops, exit 2.
const replay = spawnSync(gizmo, ["replay", log], { encoding: "utf8" });
const cut = `the log is cut off after a chunk, before its index (byte ${bytes.length} of ${bytes.length}); ` +
  `its ${stop.held.chunks} complete chunks are read`;
say(`gizmo replay (exit ${replay.status}): ${replay.stdout.trim()} / ${replay.stderr.trim()}`);
if (replay.status !== 2) fail(`gizmo replay exited ${replay.status}, not 2`);
if (replay.stderr !== `gizmo replay: ${log}: ${cut}\n`) fail(`gizmo replay said on stderr: ${replay.stderr}`);
const lines = replay.stdout.split("\n");
const done = /^identical: (\d+) events replay exactly as recorded \(double, ballistic; compared: every record\)$/.exec(lines[0]);
if (!done || lines[1] !== `note: ${cut}; every decision it holds replays identically`)
  fail(`gizmo replay said: ${replay.stdout}`);
if (!(Number(done[1]) > 0 && Number(done[1]) < stop.events)) fail(`the log's chunks hold ${done[1]} of ${stop.events} events`);
say(`passed (${done[1]} of the game's ${stop.events} events in the log's ${stop.held.chunks} chunks; files in ${outDir})`);
