// Simulation time per frame of the play page in headless Chromium (docs/play.md, the figures):
// the page opened at FILE#bench plays 600 frames of 1/60 s of board time each, drawn as in play,
// five times from the restart, timing the module's work in each frame (keys taken, ticks run,
// balls and flippers read); each frame's best round counts, and the page reports their median,
// 99th and 99.9th percentiles, worst (and which frame), mean, how many frames took over 2 ms, and
// the worst single frame of any round (raw, and which frame). performance.now() in a page
// opened from a file is coarsened by the browser (to 0.1 ms in Chromium, with jitter), which
// bounds how finely one frame is measured; the mean over 600 frames is finer.
//   node bench/play_frames.mjs [--frames N --rounds R] PAGE...   (default: 600 frames, five rounds)
import path from "node:path";
import os from "node:os";
import fs from "node:fs";
import { Browser } from "../tests/browser/play/webdriver.mjs";

const args = process.argv.slice(2);
let plan = "";
if (args[0] === "--frames" && args[2] === "--rounds" && /^\d+$/.test(args[1] || "") && /^\d+$/.test(args[3] || "")) {
  plan = `=${args[1]},${args[3]}`;
  args.splice(0, 4);
}
const pages = args;
if (!pages.length) {
  console.error("usage: node bench/play_frames.mjs [--frames N --rounds R] PAGE...");
  process.exit(2);
}
const scratch = fs.mkdtempSync(path.join(os.tmpdir(), "gizmo-play-bench-"));
const browser = await Browser.start({
  profileDir: path.join(scratch, "profile"), downloadDir: path.join(scratch, "downloads"),
});
try {
  console.log("page                          frames  board s   events  median ms  p99 ms  p99.9 ms  worst ms (frame)  mean ms  over 2 ms  raw worst ms (frame)");
  for (const page of pages) {
    await browser.open("file://" + path.resolve(page) + "#bench" + plan);
    const r = await browser.waitFor("return window.gizmoPlay && window.gizmoPlay.bench();", 1800000, "the bench's rounds of frames");
    console.log(`${path.basename(page).padEnd(29)} ${String(r.frames).padStart(6)} ${r.board_time.toFixed(2).padStart(8)} ` +
                `${String(r.events).padStart(8)} ${r.median_ms.toFixed(2).padStart(10)} ${r.p99_ms.toFixed(2).padStart(7)} ` +
                `${r.p999_ms.toFixed(2).padStart(9)} ${(r.worst_ms.toFixed(2) + " (" + r.worst_frame + ")").padStart(17)} ` +
                `${r.mean_ms.toFixed(3).padStart(8)} ${String(r.frames_over_2ms).padStart(10)} ` +
                `${(r.raw_worst_ms.toFixed(2) + " (" + r.raw_worst_frame + ")").padStart(20)}`);
  }
} finally {
  await browser.quit();
  fs.rmSync(scratch, { recursive: true, force: true });
}
