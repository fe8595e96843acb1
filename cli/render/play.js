// The play page (docs/play.md). The simulator is the play module (the core compiled to
// WebAssembly); this script turns keys into inputs, moves board time with the animation clock,
// draws the board with board_view.js (as the replay player does) and saves and checks the log.
//
// A frame advances the board time it aims at by the frame's duration times the speed (at most a
// quarter second, so that a hidden tab does not jump ahead); the module then runs every whole
// tick up to it. A key seen before a frame becomes an input at that frame's board time, which is
// always later than the board's present, so the board takes it exactly as a run that had it from
// the start would, and the log (board, model, tick, inputs, end) is all a replay needs.
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("game-data").textContent);
  const board = data.board;
  const ui = {
    board: document.getElementById("board"), clock: document.getElementById("clock"),
    status: document.getElementById("status"), keys: document.getElementById("keys"),
    logStatus: document.getElementById("log-status"), pause: document.getElementById("pause"),
    restart: document.getElementById("restart"), speed: document.getElementById("speed"),
    save: document.getElementById("save"), check: document.getElementById("check"),
    probe: document.getElementById("probe"),
  };
  const view = { scale: 1, margin: 0.3 };
  const game = {
    api: null, module: null,
    target: 0, now: 0, events: 0, paused: false, stopped: "",
    pending: [],      // keys seen, not yet given to the board: {code, up, trusted}
    inputs: [],       // keys given: {code, up, time}
    held: new Set(),  // key codes down now
    balls: [], names: [], swings: [],
    lastFrame: null, frameTimes: [], fps: 0,
    simMs: 0,         // the last frame's simulation time
    bench: null,
  };

  // ---- Keys ---------------------------------------------------------------------------------------
  // A key event's code as board files write it (Java's key codes, Gizmoball's KeyConnect): letters
  // by their upper-case code, digits by theirs, and the named keys of the board reader.
  const NAMED_KEYS = {
    Space: 32, Enter: 10, NumpadEnter: 10, Tab: 9, Escape: 27, Delete: 127, Backspace: 8,
    ShiftLeft: 16, ShiftRight: 16, ControlLeft: 17, ControlRight: 17, AltLeft: 18, AltRight: 18,
    ArrowLeft: 37, ArrowUp: 38, ArrowRight: 39, ArrowDown: 40, Home: 36, End: 35, Insert: 155,
  };
  function boardKeyCode(ev) {
    const c = ev.code || "";
    if (/^Key[A-Z]$/.test(c)) return c.charCodeAt(3);
    if (/^Digit[0-9]$/.test(c)) return c.charCodeAt(5);
    const f = /^F([0-9]+)$/.exec(c);
    if (f && Number(f[1]) >= 1 && Number(f[1]) <= 12) return 111 + Number(f[1]);
    if (c in NAMED_KEYS) return NAMED_KEYS[c];
    if (ev.key && ev.key.length === 1) {  // no code (some virtual keyboards): the character
      const k = ev.key.toUpperCase();
      if (k === " ") return 32;
      if (/^[A-Z0-9]$/.test(k)) return k.charCodeAt(0);
    }
    return -1;
  }
  function keyName(code) {
    for (const [name, c] of Object.entries(NAMED_KEYS)) if (c === code) return name.replace(/(Left|Right)$/, "");
    if ((code >= 65 && code <= 90) || (code >= 48 && code <= 57)) return String.fromCharCode(code);
    if (code >= 112 && code <= 123) return "F" + (code - 111);
    return "key " + code;
  }
  const listened = new Map(data.keys.map((k) => [k.code, k]));

  function onKey(ev, up) {
    const code = boardKeyCode(ev);
    if (!listened.has(code)) return;
    ev.preventDefault();  // a board key never scrolls the page or presses a focused button
    if (ev.repeat) return;  // held down: one input, not one per repeat
    if (up ? !game.held.has(code) : game.held.has(code)) return;
    if (up) game.held.delete(code); else game.held.add(code);
    game.pending.push({ code, up, trusted: ev.isTrusted });
    showKeys();
  }
  window.addEventListener("keydown", (ev) => onKey(ev, false), true);
  window.addEventListener("keyup", (ev) => onKey(ev, true), true);
  // A key released while the page had no focus never sends its keyup: release it at the next frame.
  window.addEventListener("blur", () => {
    for (const code of game.held) game.pending.push({ code, up: true, trusted: false });
    game.held.clear();
    showKeys();
  });

  // ---- The simulator ----------------------------------------------------------------------------
  // Hands the keys seen to the board at the frame's board time, then runs the ticks up to it.
  function step() {
    const start = performance.now();
    while (game.pending.length && !game.stopped) {
      const k = game.pending[0];
      if (!game.api.key(k.code, k.up ? 1 : 0, game.target)) break;  // not after the present yet
      game.inputs.push({ code: k.code, up: k.up, time: game.target, trusted: k.trusted });
      game.pending.shift();
    }
    game.now = game.api.advance(game.target);
    game.events = game.api.events();
    readBoard();
    game.simMs = performance.now() - start;
  }
  function readBoard() {
    const m = game.module;
    if (game.api.ballCount() !== game.names.length) game.names = game.api.names().split("\n").filter((s) => s);
    const n = game.names.length;
    const at = game.api.balls() >> 3;
    const balls = m.HEAPF64.subarray(at, at + 4 * n);
    game.balls = [];
    for (let i = 0; i < n; i++) game.balls.push({ x: balls[4 * i], y: balls[4 * i + 1], vx: balls[4 * i + 2], vy: balls[4 * i + 3] });
    const gizmos = board.gizmos.length + 1;
    const swings = game.api.swings() >> 3;
    game.swings = Array.from(m.HEAPF64.subarray(swings, swings + gizmos));
    const stopped = game.api.stopped();
    if (stopped && !game.stopped) {
      game.stopped = stopped;
      ui.status.textContent = "The board stopped: " + stopped + ". Save the log to keep the game up to here.";
    }
  }

  // ---- Drawing ----------------------------------------------------------------------------------
  function layout() {
    BoardView.fitBoard(ui.board, document.getElementById("stage"), board, view);
    draw();
  }
  function draw() {
    if (!view.ctx) return;
    const ctx = BoardView.beginBoard(view, board);
    board.gizmos.forEach((g, i) => BoardView.drawGizmo(ctx, g, game.swings[i + 1] || 0));
    game.balls.forEach((b, i) => BoardView.drawBall(ctx, board, b, i, null));
    BoardView.endBoard(view);
    ui.clock.textContent = "t = " + game.now.toFixed(2) + " s\n" + game.events + " events\n" +
      game.fps.toFixed(0) + " frames/s · simulation " + game.simMs.toFixed(1) + " ms/frame";
  }
  function showKeys() {
    ui.keys.innerHTML = "";
    if (!data.keys.length) ui.keys.innerHTML = "<li class=\"hint\">This board listens to no key.</li>";
    for (const k of data.keys) {
      const li = document.createElement("li");
      if (game.held.has(k.code)) li.className = "held";
      const kbd = document.createElement("kbd");
      kbd.textContent = keyName(k.code);
      li.appendChild(kbd);
      const parts = [];
      if (k.down.length) parts.push("down: " + k.down.join(", "));
      if (k.up.length) parts.push("up: " + k.up.join(", "));
      li.appendChild(document.createTextNode(parts.join(" · ")));
      ui.keys.appendChild(li);
    }
  }

  // ---- The animation clock ----------------------------------------------------------------------
  function frame(now) {
    if (game.lastFrame !== null) {
      const wall = Math.min(0.25, (now - game.lastFrame) / 1000);
      if (!game.paused && !game.stopped) game.target += game.bench ? 1 / 60 : wall * Number(ui.speed.value);
      game.frameTimes.push(now);
      while (game.frameTimes.length && game.frameTimes[0] < now - 1000) game.frameTimes.shift();
      game.fps = game.frameTimes.length;
    }
    game.lastFrame = now;
    step();
    draw();
    if (game.bench) benchFrame();
    requestAnimationFrame(frame);
  }

  function setPaused(paused) {
    game.paused = paused;
    ui.pause.textContent = paused ? "resume" : "pause";
    ui.status.textContent = game.stopped ? ui.status.textContent : paused ? "Paused: keys pressed now act when the game resumes." : "";
  }
  function restart() {
    game.api.restart();
    Object.assign(game, { target: 0, now: 0, events: 0, stopped: "", pending: [], inputs: [] });
    game.held.clear();
    ui.status.textContent = "";
    readBoard();
    showKeys();
  }

  // ---- The log ----------------------------------------------------------------------------------
  function two(n) { return String(n).padStart(2, "0"); }
  function logName() {
    const d = new Date();  // the file's name only: nothing of the game depends on the clock
    const stem = data.title.replace(/ \(.*\)$/, "").replace(/\.[A-Za-z]+$/, "").replace(/[^A-Za-z0-9_-]+/g, "-") || "game";
    return stem + "-" + d.getFullYear() + two(d.getMonth() + 1) + two(d.getDate()) + "-" +
      two(d.getHours()) + two(d.getMinutes()) + two(d.getSeconds()) + ".gzlog";
  }
  // Writes the game so far as a log (in the module's memory) and copies it out: its bytes, or null.
  function writeLog() {
    const start = performance.now();
    const size = game.api.save();
    if (size < 0) {
      ui.logStatus.textContent = "The log could not be written: " + game.api.text();
      ui.logStatus.className = "bad";
      return null;
    }
    const at = game.api.saved();
    const bytes = game.module.HEAPU8.slice(at, at + size);
    const ms = performance.now() - start;
    return { bytes, ms, note: game.api.text() };
  }
  function save() {
    const log = writeLog();
    game.api.forgetSaved();
    if (!log) return null;
    const name = logName();
    const link = document.createElement("a");
    link.href = URL.createObjectURL(new Blob([log.bytes], { type: "application/octet-stream" }));
    link.download = name;
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(link.href), 60000);
    ui.logStatus.textContent = "Saved " + name + ": " + log.bytes.length + " bytes, the game from 0 to " +
      game.now.toFixed(2) + " s, written in " + log.ms.toFixed(0) + " ms." + (log.note ? " " + log.note : "");
    ui.logStatus.className = "good";
    return { name, size: log.bytes.length, time: game.now, ms: log.ms };
  }
  function check() {
    const size = game.api.save();
    let result = -1, text = game.api.text();
    if (size >= 0) {
      result = game.api.check();
      text = game.api.text();
    }
    game.api.forgetSaved();
    ui.logStatus.textContent = "Check at t = " + game.now.toFixed(2) + " s: " + text;
    ui.logStatus.className = result === 1 ? "good" : "bad";
    return { identical: result === 1, text };
  }

  // ---- What the tests read --------------------------------------------------------------------
  // The board the page holds now, bit for bit (hex floats, as `gizmo replay --at --json` writes).
  function probe() {
    const hex = BoardView.hexFloat;
    return {
      time: hex(game.now), time_value: game.now, target: game.target, events: game.events, paused: game.paused,
      stopped: game.stopped, pending: game.pending.length,
      inputs: game.inputs.map((k) => ({ code: k.code, up: k.up, time: hex(k.time), time_value: k.time, trusted: k.trusted })),
      balls: game.balls.map((b, i) => ({ name: game.names[i], x: hex(b.x), y: hex(b.y), vx: hex(b.vx), vy: hex(b.vy) })),
    };
  }
  // FILE#bench: 600 frames of 1/60 s of board time each, drawn as in play, in five rounds from the
  // restart (no keys: every round makes the same frames); each frame's best time over the rounds
  // counts, so that a frame does not also hold the time a shared machine gave to other processes
  // (the worst single frame of any round is raw_worst_ms). The simulation's time per frame, median
  // and worst, goes into #probe (docs/play.md, the figures). FILE#bench=FRAMES,ROUNDS plays other
  // counts (36000,1: ten minutes of board time, once).
  function benchPlan(hash) {
    const m = /^#bench(?:=(\d+),(\d+))?$/.exec(hash);
    if (!m) return null;
    return m[1] ? { frames: Math.max(1, Number(m[1])), rounds: Math.max(1, Number(m[2])) } : { frames: 600, rounds: 5 };
  }
  function benchFrame() {
    const b = game.bench;
    if (b.done) return;
    b.best[b.frame] = Math.min(b.best[b.frame], game.simMs);
    if (game.simMs > b.rawWorst) {
      b.rawWorst = game.simMs;
      b.rawWorstFrame = b.frame;
    }
    if (++b.frame < b.frames) return;
    b.result = b.result || { board_time: game.now, events: game.events };
    b.frame = 0;
    if (++b.round < b.rounds) {
      restart();
      return;
    }
    b.done = true;
    const sorted = b.best.slice().sort((x, y) => x - y);
    Object.assign(b.result, {
      frames: b.frames, rounds: b.rounds, median_ms: sorted[b.frames >> 1], worst_ms: sorted[b.frames - 1],
      p99_ms: sorted[Math.floor(b.frames * 0.99)], p999_ms: sorted[Math.floor(b.frames * 0.999)],
      mean_ms: sorted.reduce((sum, x) => sum + x, 0) / b.frames,
      frames_over_2ms: sorted.filter((x) => x > 2).length, worst_frame: b.best.indexOf(sorted[b.frames - 1]),
      raw_worst_ms: b.rawWorst, raw_worst_frame: b.rawWorstFrame,
    });
    ui.probe.textContent = JSON.stringify(b.result);
  }

  // ---- Start ------------------------------------------------------------------------------------
  function describe() {
    document.getElementById("title").textContent = data.title;
    document.getElementById("summary").textContent = data.model + " model, double, ticks of " + data.max_tick +
      " s · " + board.gizmos.length + " gizmos" + (game.names.length ? ", " + game.names.length + " balls" : "");
    document.getElementById("warnings").textContent = data.board_warnings.join("  ");
    showKeys();
  }
  describe();
  layout();
  window.addEventListener("resize", layout);
  GizmoPlayModule().then((m) => {
    game.module = m;
    game.api = {
      load: m.cwrap("gp_load", "number", ["string", "string", "string", "number", "number", "number"]),
      restart: m.cwrap("gp_restart", null, []),
      key: m.cwrap("gp_key", "number", ["number", "number", "number"]),
      advance: m.cwrap("gp_advance", "number", ["number"]),
      events: m.cwrap("gp_events", "number", []),
      stopped: m.cwrap("gp_stopped", "string", []),
      text: m.cwrap("gp_text", "string", []),
      names: m.cwrap("gp_ball_names", "string", []),
      balls: m.cwrap("gp_balls", "number", []),
      ballCount: m.cwrap("gp_ball_count", "number", []),
      swings: m.cwrap("gp_swings", "number", []),
      save: m.cwrap("gp_save", "number", []),
      saved: m.cwrap("gp_saved", "number", []),
      forgetSaved: m.cwrap("gp_forget_saved", null, []),
      check: m.cwrap("gp_check", "number", []),
    };
    if (!game.api.load(data.board_text, data.title, data.board_warnings.join("\n"), data.model === "classic" ? 0 : 1,
                       data.max_tick, 1)) {
      ui.status.textContent = "The board does not load: " + game.api.text();
      return;
    }
    game.names = game.api.names().split("\n").filter((s) => s);
    describe();
    const plan = benchPlan(window.location.hash);
    if (plan)
      game.bench = { ...plan, best: new Array(plan.frames).fill(Infinity), frame: 0, round: 0, rawWorst: 0, rawWorstFrame: 0, done: false, result: null };
    for (const b of [ui.pause, ui.restart, ui.save, ui.check]) b.disabled = false;
    // A clicked button keeps no focus, so that space (a board key) never presses it.
    for (const b of [ui.pause, ui.restart, ui.save, ui.check, ui.speed]) b.addEventListener("click", () => b.blur());
    ui.speed.addEventListener("change", () => ui.speed.blur());
    ui.pause.addEventListener("click", () => setPaused(!game.paused));
    ui.restart.addEventListener("click", restart);
    ui.save.addEventListener("click", save);
    ui.check.addEventListener("click", check);
    window.gizmoPlay = { probe, save, check, restart, setPaused, ready: true, bench: () => game.bench && game.bench.done && game.bench.result };
    readBoard();
    requestAnimationFrame(frame);
  }).catch((e) => {
    // WebAssembly exceptions (the module's -fwasm-exceptions) need a browser of 2022 or later.
    ui.clock.textContent = "";
    ui.status.textContent = "The simulator did not start in this browser: " + e;
  });
})();
