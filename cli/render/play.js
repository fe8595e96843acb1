// The play page (docs/play.md). The simulator is the play module (the core compiled to
// WebAssembly); this script turns keys into inputs, moves board time with the animation clock,
// draws the board with board_view.js (as the replay player does) and saves and checks the log.
//
// A frame advances the board time it aims at by the frame's duration times the speed (at most a
// quarter second, so that a hidden tab does not jump ahead); the module then runs every whole
// tick up to it. A key seen before a frame becomes an input at that frame's board time, which is
// always later than the board's present, so the board takes it exactly as a run that had it from
// the start would, and the log (board, model, tick, inputs, end) is all a replay needs.
//
// The page also opens a saved log (the file button, or a file dropped on the page): the module
// reads it and gives the log's board and its run as the replay player holds it (run_data.js),
// which the page scrubs on its timeline (timeline_view.js) and draws with board_view.js. "play
// from here" takes the log over at the moment shown (the module's startBranch, the code of
// `gizmo record --from`), "rewind 5 s" takes the game's own log over five seconds back; either
// way the game goes on as a branch, recorded live, and saves as a branch log.
"use strict";
(function () {
  let data = JSON.parse(document.getElementById("game-data").textContent);
  let board = data.board;
  const ui = {
    board: document.getElementById("board"), clock: document.getElementById("clock"),
    status: document.getElementById("status"), keys: document.getElementById("keys"),
    logStatus: document.getElementById("log-status"), pause: document.getElementById("pause"),
    restart: document.getElementById("restart"), speed: document.getElementById("speed"),
    save: document.getElementById("save"), check: document.getElementById("check"),
    probe: document.getElementById("probe"), openLog: document.getElementById("open-log"),
    takeOver: document.getElementById("take-over"), rewind: document.getElementById("rewind"),
    saveParent: document.getElementById("save-parent"), logView: document.getElementById("log-view"),
    scrub: document.getElementById("scrub"), timeline: document.getElementById("timeline"),
    touchKeys: document.getElementById("touch-keys"), branch: document.getElementById("branch"),
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
    busy: false,      // a log being written, joined or handed over: the game waits
    pauseAt: null,    // a board time at which to pause (set by a test)
    start: 0,         // where the game's log starts: 0, or the tick boundary a branch starts from
    branch: null,     // once a log is taken over: {parent, at (board time), event (the parent's)}
    parent: null,     // the log taken over: {name, bytes}, for "save the log taken over"
  };
  // A log the page opened, shown on its timeline while the game waits: null while playing.
  let shown = null;   // {name, run (run_data.js), start, end, t, done, bins, balls}

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
  let listened = new Map(data.keys.map((k) => [k.code, k]));

  // A key of the board going down or up, from the keyboard or a key button (source "key", or
  // the pointer's type: "touch", "pen", "mouse"): taken at the next frame's board time.
  function press(code, up, trusted, source) {
    if (up ? !game.held.has(code) : game.held.has(code)) return;
    if (up) game.held.delete(code); else game.held.add(code);
    if (!shown) game.pending.push({ code, up, trusted, source });
    showKeys();
  }
  function onKey(ev, up) {
    const code = boardKeyCode(ev);
    if (!listened.has(code)) return;
    ev.preventDefault();  // a board key never scrolls the page or presses a focused button
    if (ev.repeat) return;  // held down: one input, not one per repeat
    press(code, up, ev.isTrusted, "key");
  }
  window.addEventListener("keydown", (ev) => onKey(ev, false), true);
  window.addEventListener("keyup", (ev) => onKey(ev, true), true);
  // A key released while the page had no focus never sends its keyup: release it at the next frame.
  window.addEventListener("blur", () => {
    for (const code of game.held) if (!shown) game.pending.push({ code, up: true, trusted: false, source: "blur" });
    game.held.clear();
    showKeys();
  });

  // ---- Key buttons (a touch screen) ---------------------------------------------------------------
  // Each key the board listens to is also a button under the board: a finger (or a pen, or the
  // mouse) on it presses the key, lifting it releases the key. The button keeps the pointer while
  // it is down, so a finger that slides off still releases the key it pressed.
  function showTouchKeys() {
    ui.touchKeys.innerHTML = "";
    for (const k of data.keys) {
      const button = document.createElement("button");
      button.className = "touch-key";
      button.dataset.code = String(k.code);
      button.textContent = keyName(k.code);
      button.title = "key " + keyName(k.code) + " (touch and hold)";
      button.addEventListener("pointerdown", (ev) => {
        ev.preventDefault();
        button.setPointerCapture(ev.pointerId);
        press(k.code, false, ev.isTrusted, ev.pointerType || "pointer");
      });
      const release = (ev) => press(k.code, true, ev.isTrusted, ev.pointerType || "pointer");
      button.addEventListener("pointerup", release);
      button.addEventListener("pointercancel", release);
      button.addEventListener("contextmenu", (ev) => ev.preventDefault());  // a long press is a held key
      ui.touchKeys.appendChild(button);
    }
  }

  // ---- The simulator ----------------------------------------------------------------------------
  // Hands the keys seen to the board at the frame's board time, then runs the ticks up to it.
  function step() {
    const start = performance.now();
    while (game.pending.length && !game.stopped) {
      const k = game.pending[0];
      if (!game.api.key(k.code, k.up ? 1 : 0, game.target)) break;  // not after the present yet
      game.inputs.push({ code: k.code, up: k.up, time: game.target, trusted: k.trusted, source: k.source });
      game.pending.shift();
    }
    game.now = game.api.advance(game.target);
    game.events = game.api.events();
    takeChunks();
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
    if (shown) {
      view.timeline = BoardView.fitCanvas(ui.timeline, ui.timeline.clientWidth, ui.timeline.clientHeight);
      shown.bins = null;
    }
    draw();
  }
  function draw() {
    if (!view.ctx) return;
    if (shown) return drawShown();
    const ctx = BoardView.beginBoard(view, board);
    board.gizmos.forEach((g, i) => BoardView.drawGizmo(ctx, g, game.swings[i + 1] || 0));
    game.balls.forEach((b, i) => BoardView.drawBall(ctx, board, b, i, null));
    BoardView.endBoard(view);
    ui.clock.textContent = "t = " + game.now.toFixed(2) + " s\n" + game.events + " events\n" +
      game.fps.toFixed(0) + " frames/s · simulation " + game.simMs.toFixed(1) + " ms/frame";
  }
  function showKeys() {
    for (const b of ui.touchKeys.children) b.classList.toggle("held", game.held.has(Number(b.dataset.code)));
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
      if (!game.paused && !game.stopped && !shown && !game.busy) game.target += game.bench ? 1 / 60 : wall * Number(ui.speed.value);
      if (game.pauseAt !== null && game.target >= game.pauseAt) {  // a test's stop (gizmoPlay.pauseAt)
        game.target = Math.max(game.now, game.pauseAt);
        game.pauseAt = null;
        setPaused(true);
      }
      game.frameTimes.push(now);
      while (game.frameTimes.length && game.frameTimes[0] < now - 1000) game.frameTimes.shift();
      game.fps = game.frameTimes.length;
    }
    game.lastFrame = now;
    if (!shown && !game.busy) step();
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
    Object.assign(game, { target: 0, now: 0, events: 0, stopped: "", pending: [], inputs: [], start: 0, branch: null });
    game.held.clear();
    shown = null;
    store = newStore();
    ui.status.textContent = "";
    showMode();
    readBoard();
    showKeys();
  }

  // ---- A log opened, scrubbed and taken over ------------------------------------------------------
  // The page's game becomes the log's board (its keys, model and tick); the log is shown on its
  // timeline at its start, and the game waits until it is taken over.
  function openLogBytes(bytes, name) {
    handIn(bytes);
    if (!game.api.openLog(name)) {
      ui.logStatus.textContent = "Cannot open " + name + ": " + game.api.text();
      ui.logStatus.className = "bad";
      return false;
    }
    const opened = JSON.parse(game.api.text());
    store = newStore();
    data = opened.game;
    board = data.board;
    listened = new Map(data.keys.map((k) => [k.code, k]));
    const run = RunData.loadRun(opened.run);
    shown = { name, run, start: run.start, end: Math.max(run.end, run.start), t: run.start, done: 0, bins: null, balls: [] };
    Object.assign(game, { target: 0, now: 0, events: 0, stopped: "", pending: [], inputs: [], start: 0, branch: null,
                          parent: { name, bytes } });
    game.held.clear();
    game.names = [];
    ui.logStatus.textContent = "Opened " + name + ": " + (run.first + run.count) + " events to t = " +
      shown.end.toFixed(2) + " s" + (opened.branch ? ", a branch log" : "") + (opened.complete ? "" : " (" + run.truncation + ")") +
      ". Scrub its timeline, then play from any moment.";
    ui.logStatus.className = "good";
    ui.status.textContent = "";
    describe();
    showMode();
    layout();
    seekShown(shown.start);
    return true;
  }
  async function openLogFile(file) {
    if (file) openLogBytes(new Uint8Array(await file.arrayBuffer()), file.name);
  }
  function seekShown(t) {
    shown.t = Math.min(shown.end, Math.max(shown.start, t));
    shown.done = RunData.eventsBy(shown.run, shown.t);
    draw();
  }
  function drawShown() {
    const run = shown.run, t = shown.t, done = shown.done;
    const ctx = BoardView.beginBoard(view, board);
    board.gizmos.forEach((g, i) => BoardView.drawGizmo(ctx, g, RunData.flipperSwing(run, i + 1, t, done)));
    shown.balls = [];
    run.balls.forEach((ball, b) => {
      const at = RunData.ballAt(run, ball, t, done);
      if (!at) return;
      BoardView.drawBall(ctx, board, at, b, null);
      shown.balls.push({ name: ball.name, x: at.x, y: at.y, vx: at.vx, vy: at.vy });
    });
    BoardView.endBoard(view);
    const w = ui.timeline.clientWidth, h = ui.timeline.clientHeight;
    if (view.timeline && w > 0) {
      if (!shown.bins || shown.bins.length !== w * 3) shown.bins = TimelineView.bins(run, shown.end, w);
      TimelineView.draw(view.timeline, w, h, shown.bins, shown.end, t, []);
    }
    ui.scrub.value = String(Math.round(t / shown.end * 100000));
    ui.clock.textContent = "t = " + t.toFixed(4) + " s\n" + (run.first + done) + " / " + (run.first + run.count) +
      " events\n" + shown.name;
  }
  // The game goes on from the moment shown (rounded down to a tick end) as a branch of the log.
  function takeOver() {
    if (!shown) return false;
    if (!game.api.takeOver(shown.t, 0)) {
      ui.status.textContent = "Cannot play from here: " + game.api.text();
      return false;
    }
    const name = shown.name;
    shown = null;
    startBranch(name);
    return true;
  }
  // Five seconds back (to the game's start at the earliest): the game so far is written as a log
  // and taken over there; that log is kept, to be saved as the branch's parent.
  async function rewind(seconds) {
    if (shown || game.busy) return false;
    return busy(async () => {
      const log = await writeLog();
      if (!log) return false;
      const bytes = new Uint8Array(await log.blob.arrayBuffer());
      handIn(bytes);
      if (!game.api.takeOver(Math.max(game.start, log.time - seconds), 1)) {
        ui.status.textContent = "Cannot rewind: " + game.api.text();
        return false;
      }
      const name = logName(game.branch ? "-branch" : "");
      game.parent = { name, bytes };
      startBranch(name, log.time);
      return true;
    });
  }
  // The game goes on as the branch the module took (of a log opened, or, rewinding, of the game
  // itself as it was at board time `from`).
  function startBranch(parentName, from) {
    store = newStore();
    const now = game.api.now();
    Object.assign(game, { target: now, now, stopped: "", pending: [], inputs: [], start: game.api.startTime(),
                          branch: { parent: parentName, at: now, event: game.api.branchEvent(), from } });
    game.events = game.api.events();
    game.names = [];
    ui.status.textContent = "";
    showMode();
    layout();
    readBoard();
    describe();
  }
  function showMode() {
    ui.logView.hidden = !shown;
    ui.takeOver.disabled = !shown;
    ui.rewind.disabled = !!shown;
    ui.check.disabled = ui.save.disabled = !!shown;
    ui.saveParent.disabled = !game.parent || !game.branch;
    ui.branch.textContent = game.branch ? "A branch of " + game.branch.parent + ": taken over at t = " +
      game.branch.at.toFixed(2) + " s, after its event " + game.branch.event + "." : "";
  }

  // ---- The log ----------------------------------------------------------------------------------
  function two(n) { return String(n).padStart(2, "0"); }
  function logName(kind) {
    const d = new Date();  // the file's name only: nothing of the game depends on the clock
    const stem = data.title.replace(/ \(.*\)$/, "").replace(/\.[A-Za-z]+$/, "").replace(/-\d{8}-\d{6}$/, "")
      .replace(/[^A-Za-z0-9_-]+/g, "-") || "game";
    return stem + (kind || "") + "-" + d.getFullYear() + two(d.getMonth() + 1) + two(d.getDate()) + "-" +
      two(d.getHours()) + two(d.getMinutes()) + two(d.getSeconds()) + ".gzlog";
  }
  // The bytes of a log handed to the module (gp_buffer), to open, take over or check.
  function handIn(bytes) {
    const at = game.api.buffer(bytes.length);
    game.module.HEAPU8.set(bytes, at);
  }
  // While the page writes, joins and hands over a log (which waits for the browser's streams),
  // the game stands still, so that the log and the game stay one.
  async function busy(work) {
    game.busy = true;
    try {
      return await work();
    } finally {
      game.busy = false;
    }
  }
  // Writes the game so far as a log: the module writes its header, the chunks it still holds and
  // the end, and the page puts the chunks it took into their place. The log as a Blob, or null.
  async function writeLog() {
    const start = performance.now();
    const size = game.api.save();
    if (size < 0) {
      ui.logStatus.textContent = "The log could not be written: " + game.api.text();
      ui.logStatus.className = "bad";
      return null;
    }
    const at = game.api.saved();
    const bytes = game.module.HEAPU8.slice(at, at + size);
    const split = game.api.saveSplit();
    const note = game.api.text();
    const time = game.now;
    game.api.forgetSaved();
    const parts = split < 0 ? [bytes] : [bytes.subarray(0, split), ...storedChunks(store), bytes.subarray(split)];
    const blob = new Blob(parts, { type: "application/octet-stream" });
    return { blob, size: blob.size, time, ms: performance.now() - start, note };
  }
  function download(blob, name) {
    const link = document.createElement("a");
    link.href = URL.createObjectURL(blob);
    link.download = name;
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(link.href), 60000);
  }
  async function save() {
    if (game.busy) return null;
    return busy(async () => {
      const log = await writeLog();
      if (!log) return null;
      const name = logName(game.branch ? "-branch" : "");
      download(log.blob, name);
      ui.logStatus.textContent = "Saved " + name + ": " + log.size + " bytes, the game from " + game.start.toFixed(2) +
        " to " + log.time.toFixed(2) + " s" + (game.branch ? " (a branch of " + game.branch.parent + ")" : "") +
        ", written in " + log.ms.toFixed(0) + " ms." + (log.note ? " " + log.note : "");
      ui.logStatus.className = "good";
      return { name, size: log.size, time: log.time, ms: log.ms };
    });
  }
  function saveParent() {
    if (!game.parent) return null;
    download(new Blob([game.parent.bytes], { type: "application/octet-stream" }), game.parent.name);
    ui.logStatus.textContent = "Saved " + game.parent.name + ", the log taken over: " + game.parent.bytes.length + " bytes.";
    ui.logStatus.className = "good";
    return { name: game.parent.name, size: game.parent.bytes.length };
  }
  async function check() {
    if (game.busy) return null;
    return busy(async () => {
      ui.logStatus.textContent = "Checking…";
      ui.logStatus.className = "";
      const log = await writeLog();
      let result = -1, text = log ? "" : game.api.text();
      if (log) {
        handIn(new Uint8Array(await log.blob.arrayBuffer()));
        result = game.api.check(1);
        text = game.api.text();
        game.api.buffer(0);
      }
      ui.logStatus.textContent = "Check at t = " + game.now.toFixed(2) + " s: " + text;
      ui.logStatus.className = result === 1 ? "good" : "bad";
      return { identical: result === 1, text };
    });
  }

  // ---- The recording's closed chunks ------------------------------------------------------------
  // The module hands the page each chunk its Recorder closes (gp_take_chunks, at every frame) and
  // keeps only its place in the log's index. The page keeps them as Blobs, which the browser holds
  // in its own storage (on disk when large), out of the module's memory, so that the module's
  // memory stays bounded however long the game. A log written joins them back, in order. (They are
  // not compressed: gzip makes these records, mostly doubles, a fifth smaller, and at 64× the
  // browser's CompressionStream took longer than the game itself: docs/play.md, "Memory".)
  function newStore() { return { parts: [], bytes: 0, moduleMost: 0 }; }
  let store = newStore();
  function takeChunks() {
    const frames = [];
    for (let size; (size = game.api.takeChunks()) > 0;) {  // one chunk at a time
      const at = game.api.taken();
      frames.push(game.module.HEAPU8.slice(at, at + size));  // a copy: the module's goes back
      store.bytes += size;
      game.api.forgetTaken();
    }
    if (frames.length) store.parts.push(new Blob(frames));  // one Blob a frame
    store.moduleMost = Math.max(store.moduleMost, game.api.heldBytes());
  }
  // The chunks the page holds, in the order the module handed them over.
  function storedChunks(s) { return s.parts.slice(); }
  // What the game's recording holds: in the module (the chunks not yet handed over, the index,
  // the last log written, at most that after any frame) and in the page's Blobs; the chunks the
  // recording closed, and the size of the module's memory.
  function held() {
    const module = game.api.heldBytes();
    return { module, module_most: store.moduleMost, page: store.bytes, parts: store.parts.length,
             chunks: game.api.chunksClosed(), memory: game.module.HEAPU8.length,
             module_per_event: game.events > 0 ? module / game.events : 0,
             page_per_event: game.events > 0 ? store.bytes / game.events : 0 };
  }

  // ---- What the tests read --------------------------------------------------------------------
  // The board the page holds now, bit for bit (hex floats, as `gizmo replay --at --json` writes).
  function probe() {
    const hex = BoardView.hexFloat;
    return {
      time: hex(game.now), time_value: game.now, target: game.target, events: game.events, paused: game.paused,
      stopped: game.stopped, log_end: game.api.logEnd(), pending: game.pending.length, start: hex(game.start), branch: game.branch, busy: game.busy,
      held: held(),
      inputs: game.inputs.map((k) => ({ code: k.code, up: k.up, time: hex(k.time), time_value: k.time, trusted: k.trusted, source: k.source })),
      shown: shown && { name: shown.name, time: hex(shown.t), time_value: shown.t, events: shown.run.first + shown.done,
                        balls: shown.balls.map((b) => ({ name: b.name, x: hex(b.x), y: hex(b.y), vx: hex(b.vx), vy: hex(b.vy) })) },
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
    document.getElementById("title").textContent = data.title + (game.branch ? " (a branch)" : "");
    document.getElementById("summary").textContent = data.model + " model, double, ticks of " + data.max_tick +
      " s · " + board.gizmos.length + " gizmos" + (game.names.length ? ", " + game.names.length + " balls" : "");
    document.getElementById("warnings").textContent = data.board_warnings.join("  ");
    showTouchKeys();
    showKeys();
  }
  // FILE#max-memory=MB: the module's memory may grow to MB megabytes (at least its 16 to start
  // with) instead of WebAssembly's 2 GB, so that a test reaches, within seconds, what a game
  // reaches when the browser gives the module no more memory: the module's allocation fails where
  // it happens, and the game stops with its log saved up to its last complete chunk (docs/play.md,
  // "Memory"). The memory is the module's own (linked with IMPORTED_MEMORY), only given a ceiling.
  function moduleOptions(hash) {
    const m = /^#max-memory=(\d+)$/.exec(hash);
    if (!m) return {};
    const pages = (mb) => mb * 16;  // WebAssembly pages of 64 KiB
    const initial = pages(16);      // the module's INITIAL_MEMORY, emscripten's default
    return { wasmMemory: new WebAssembly.Memory({ initial, maximum: Math.max(initial, pages(Number(m[1]))) }) };
  }
  describe();
  layout();
  window.addEventListener("resize", layout);
  GizmoPlayModule(moduleOptions(window.location.hash)).then((m) => {
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
      check: m.cwrap("gp_check", "number", ["number"]),
      saveSplit: m.cwrap("gp_save_split", "number", []),
      takeChunks: m.cwrap("gp_take_chunks", "number", []),
      taken: m.cwrap("gp_taken", "number", []),
      forgetTaken: m.cwrap("gp_forget_taken", null, []),
      heldBytes: m.cwrap("gp_held_bytes", "number", []),
      chunksClosed: m.cwrap("gp_chunks_closed", "number", []),
      logEnd: m.cwrap("gp_log_end", "number", []),
      buffer: m.cwrap("gp_buffer", "number", ["number"]),
      openLog: m.cwrap("gp_open_log", "number", ["string"]),
      takeOver: m.cwrap("gp_take_over", "number", ["number", "number"]),
      now: m.cwrap("gp_now", "number", []),
      startTime: m.cwrap("gp_start_time", "number", []),
      branchEvent: m.cwrap("gp_branch_event", "number", []),
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
    for (const b of [ui.pause, ui.restart, ui.save, ui.check, ui.openLog]) b.disabled = false;
    showMode();
    // A clicked button keeps no focus, so that space (a board key) never presses it.
    for (const b of [ui.pause, ui.restart, ui.save, ui.check, ui.speed, ui.takeOver, ui.rewind, ui.saveParent])
      b.addEventListener("click", () => b.blur());
    ui.speed.addEventListener("change", () => ui.speed.blur());
    ui.pause.addEventListener("click", () => setPaused(!game.paused));
    ui.restart.addEventListener("click", restart);
    ui.save.addEventListener("click", save);
    ui.check.addEventListener("click", check);
    ui.takeOver.addEventListener("click", takeOver);
    ui.rewind.addEventListener("click", () => rewind(5));
    ui.saveParent.addEventListener("click", saveParent);
    ui.openLog.addEventListener("change", () => {
      openLogFile(ui.openLog.files[0]);
      ui.openLog.blur();
    });
    // A log file dropped anywhere on the page opens like one chosen with the button.
    window.addEventListener("dragover", (ev) => ev.preventDefault());
    window.addEventListener("drop", (ev) => {
      ev.preventDefault();
      if (ev.dataTransfer && ev.dataTransfer.files.length) openLogFile(ev.dataTransfer.files[0]);
    });
    // Scrubbing a log shown: its timeline (pressed and dragged) and the slider, as in the player.
    let dragging = false;
    ui.timeline.addEventListener("pointerdown", (ev) => {
      if (!shown) return;
      dragging = true;
      seekShown(TimelineView.timeAt(ui.timeline, ev, shown.end));
    });
    window.addEventListener("pointermove", (ev) => { if (dragging && shown) seekShown(TimelineView.timeAt(ui.timeline, ev, shown.end)); });
    window.addEventListener("pointerup", () => { dragging = false; });
    ui.scrub.addEventListener("input", () => { if (shown) seekShown(Number(ui.scrub.value) / 100000 * shown.end); });
    const pauseAt = (t) => { game.pauseAt = t; };
    window.gizmoPlay = { probe, save, saveParent, check, restart, setPaused, pauseAt, takeOver, rewind, ready: true,
                         bench: () => game.bench && game.bench.done && game.bench.result };
    readBoard();
    requestAnimationFrame(frame);
  }).catch((e) => {
    // WebAssembly exceptions (the module's -fwasm-exceptions) need a browser of 2022 or later.
    ui.clock.textContent = "";
    ui.status.textContent = "The simulator did not start in this browser: " + e;
  });
})();
