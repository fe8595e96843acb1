// The play module's core under node against the native core, in one run (docs/play.md, the
// figures): events per second of the same board, model, tick and board time, simulated by
// `gizmo run BOARD --time S --json` natively (its wall_seconds: building the board and
// simulating) and by the play module (gp_load and one gp_advance to S, timed around both),
// without recording, as `gizmo run` simulates; then the module as the page runs it, recording
// every decision as it goes (the last column, against native `gizmo run`).
// Each side runs ROUNDS times (default 20) and its fastest round counts: on a shared machine a
// round can also hold time the system gave to other processes (a slice of 10 to 20 ms, as long as
// a whole run of the spec example), and the module's first rounds also hold V8's compilation of
// the WebAssembly, which a page pays once when it loads. The module's time includes reading the
// board's text, which the native one does not (under a millisecond).
//   node bench/play_speed.mjs GIZMO MODULE [ROUNDS]
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import { createRequire } from "node:module";
import path from "node:path";

const [gizmo, modulePath, roundsText] = process.argv.slice(2);
if (!gizmo || !modulePath) {
  console.error("usage: node bench/play_speed.mjs GIZMO MODULE [ROUNDS]");
  process.exit(2);
}
const rounds = Number(roundsText || 20);
const fixtures = path.join(path.dirname(new URL(import.meta.url).pathname), "..", "fixtures", "boards");
const cases = [
  { name: "spec example, 60 s", board: path.join(fixtures, "spec-example.txt"), seconds: 60 },
  { name: "crowded (100 balls), 10 s", board: path.join(fixtures, "play", "crowded-100-balls.txt"), seconds: 10 },
];
const MAX_TICK = 0.05;  // gizmo run's default

const module = await createRequire(import.meta.url)(path.resolve(modulePath))();
const load = module.cwrap("gp_load", "number", ["string", "string", "string", "number", "number", "number"]);
const advance = module.cwrap("gp_advance", "number", ["number"]);
const events = module.cwrap("gp_events", "number", []);
const text = module.cwrap("gp_text", "string", []);

console.log("board                        native events  native ev/s   wasm events  wasm ev/s    wasm/native  recording/native");
for (const c of cases) {
  const boardText = fs.readFileSync(c.board, "utf8");
  let native = null, wasm = null, recording = null;
  for (let r = 0; r < rounds; r++) {
    const out = JSON.parse(execFileSync(gizmo, ["run", c.board, "--time", String(c.seconds), "--max-tick", String(MAX_TICK), "--json"],
                                        { encoding: "utf8" }));
    const n = { events: out.events.total, seconds: out.wall_seconds };
    if (!native || n.seconds < native.seconds) native = n;

    for (const record of [0, 1]) {
      const start = performance.now();
      if (!load(boardText, path.basename(c.board), "", 1, MAX_TICK, record)) throw new Error(text());
      advance(c.seconds);
      const w = { events: events(), seconds: (performance.now() - start) / 1000 };
      if (record === 0 && (!wasm || w.seconds < wasm.seconds)) wasm = w;
      if (record === 1 && (!recording || w.seconds < recording.seconds)) recording = w;
    }
  }
  if (native.events !== wasm.events) throw new Error(`${c.name}: native ran ${native.events} events, wasm ${wasm.events}`);
  const nativeRate = native.events / native.seconds, wasmRate = wasm.events / wasm.seconds;
  console.log(`${c.name.padEnd(28)} ${String(native.events).padStart(13)} ${nativeRate.toExponential(3).padStart(12)} ` +
              `${String(wasm.events).padStart(12)} ${wasmRate.toExponential(3).padStart(10)} ${(wasmRate / nativeRate).toFixed(3).padStart(13)} ` +
              `${(recording.events / recording.seconds / nativeRate).toFixed(3).padStart(17)}`);
}

// Saving a game of ten minutes of board time on the spec example (ticks of 0.01 s, the page's
// default), as "save log" does: the header, then the chunks recorded while the game ran, into the
// module's memory, then copied out.
const save = module.cwrap("gp_save", "number", []);
const saved = module.cwrap("gp_saved", "number", []);
const forgetSaved = module.cwrap("gp_forget_saved", null, []);
const specText = fs.readFileSync(cases[0].board, "utf8");
let best = null;
for (let r = 0; r < 3; r++) {
  if (!load(specText, "spec-example.txt", "", 1, 0.01, 1)) throw new Error(text());
  advance(600);
  const start = performance.now();
  const bytes = save();
  const at = saved();
  const copy = module.HEAPU8.slice(at, at + bytes);  // as the page copies it out
  const ms = performance.now() - start;
  forgetSaved();
  if (copy.length !== bytes) throw new Error("the log was not copied out");
  if (!best || ms < best.ms) best = { ms, bytes, events: events() };
}
console.log(`saving 600 s of the spec example (${best.events} events): ${best.ms.toFixed(0)} ms, ${best.bytes} bytes (best of 3)`);

