// The replay player. It reads the run data that `gizmo render` put into the page (arrays as
// base64, docs/render.md; decoded by run_data.js, which also gives the state at a moment), and
// draws the board at any moment: each ball on its true path (the pieces p + v·τ + ½·a·τ² the
// log's states anchor), each flipper on its swing. The page fetches
// nothing. A page opened as FILE#event=N shows the board after N events and writes what it drew
// into #probe, which the browser test compares with `gizmo replay --event N`. Another engine's
// path (Box2D's, from a path file) can be laid over the run: a polyline through its step positions.
// The board, its gizmos and balls are drawn by board_view.js, which the play page shares.
"use strict";
(function () {
  // ---- Reading the data -----------------------------------------------------------------------
  const startedAt = performance.now();
  const data = JSON.parse(document.getElementById("run-data").textContent);
  const names = data.names;
  const board = data.board;

  const { loadRun, loadPath, countAtMost, countBelow, pathBallAt, eventsBy, ballAt, flipperSwing } = RunData;
  const runs = data.runs.map(loadRun);
  const main = runs[0];
  const path = data.path ? loadPath(data.path) : null;
  // Where the run parts from what it is compared with, for the timelines: a second log (the first
  // differing decision) or a path (the first step further apart than its threshold).
  const partings = [];
  if (data.parting) partings.push(data.parting.time);
  if (path && path.parting) partings.push(path.parting.time);
  // The page's text and the base64 strings are not needed once decoded: a million-event run keeps
  // about 90 MB of them alive otherwise, and a larger heap makes every garbage collection slower.
  data.runs = null;
  if (data.path) data.path = null;
  document.getElementById("run-data").remove();
  const endTime = Math.max(...runs.map((r) => r.end), 1e-9);
  // A branch log's run starts at its first keyframe: the player goes no earlier.
  const startTime = Math.min(...runs.map((r) => r.start));

  // ---- Text -----------------------------------------------------------------------------------
  const hexFloat = BoardView.hexFloat;
  function num(x) { return Number.isInteger(x) ? String(x) : x.toPrecision(17).replace(/0+$/, ""); }
  // A step size as people write it: 1/240 s rather than 0.0041666666666666666 s.
  function stepText(dt) {
    const n = Math.round(1 / dt);
    return (n > 1 && Math.abs(n * dt - 1) < 1e-9 ? "1/" + n : num(dt)) + " s";
  }
  function short(x) { return (Math.abs(x) < 1e-12 ? 0 : x).toFixed(4); }
  // A spawned ball is not among the board's gizmos: its track has its name.
  function gizmoName(run, id) {
    if (id < 0) return "none";
    if (run.gizmoNames[id]) return run.gizmoNames[id];
    const ball = run.balls.find((b) => b.id === id);
    return ball ? ball.name : "#" + id;
  }
  function esc(s) { return String(s).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;"); }

  // ---- Colours --------------------------------------------------------------------------------
  const { KIND_COLOUR, KIND_LANE, PARTING_COLOUR } = TimelineView;  // timeline_view.js, shared with the play page
  const SECOND_RUN = "#ff8c42";
  const PATH_COLOUR = "#40c4ff";

  // ---- The player's state ---------------------------------------------------------------------
  const ui = {
    board: document.getElementById("board"), timeline: document.getElementById("timeline"),
    zoom: document.getElementById("zoom"), play: document.getElementById("play"),
    speed: document.getElementById("speed"), filter: document.getElementById("filter"),
    seek: document.getElementById("seek"), eventNumber: document.getElementById("event-number"),
    clock: document.getElementById("clock"), details: document.getElementById("details"),
    probe: document.getElementById("probe"),
  };
  const state = { t: startTime, done: 0, playing: false, selected: -1, zoomSpan: 0.25, lastFrame: 0, drawn: [], pathDrawn: [] };

  function seekTime(t) {
    state.t = Math.min(endTime, Math.max(startTime, t));
    state.done = eventsBy(main, state.t);
    redraw();
  }
  // The board after n events: at the time of the n-th, with exactly n run.
  function seekEvents(n) {
    n = Math.min(main.count, Math.max(0, Math.floor(n)));
    state.done = n;
    state.t = n > 0 ? main.time[n - 1] : main.start;
    redraw();
  }
  function selectEvent(k) {
    if (k < 0 || k >= main.count) return;
    state.selected = k;
    seekEvents(k + 1);
    showDetails(k);
  }
  function passes(k) {
    const f = ui.filter.value;
    if (f === "collision") return main.kind[k] === 0;
    if (f === "notable") return KIND_LANE[main.kind[k]] !== 2;
    return true;
  }
  function stepEvent(direction) {
    pause();
    let k = direction > 0 ? state.done : state.done - 2;
    while (k >= 0 && k < main.count && !passes(k)) k += direction;
    if (k >= 0 && k < main.count) selectEvent(k);
  }
  function play() {
    if (state.t >= endTime) seekTime(0);
    state.playing = true;
    state.lastFrame = performance.now();
    ui.play.textContent = "pause";
    requestAnimationFrame(frame);
  }
  function pause() { state.playing = false; ui.play.textContent = "play"; }
  function frame(now) {
    if (!state.playing) return;
    const dt = Math.min(0.25, (now - state.lastFrame) / 1000);  // a hidden tab does not jump ahead
    state.lastFrame = now;
    seekTime(state.t + dt * Number(ui.speed.value));
    if (state.t >= endTime) { pause(); return; }
    requestAnimationFrame(frame);
  }

  // ---- Drawing the board ----------------------------------------------------------------------
  const view = { scale: 1, margin: 0.3 };
  const fitCanvas = BoardView.fitCanvas;
  function layout() {
    BoardView.fitBoard(ui.board, document.getElementById("stage"), board, view);
    view.timeline = fitCanvas(ui.timeline, ui.timeline.clientWidth, ui.timeline.clientHeight);
    view.zoom = fitCanvas(ui.zoom, ui.zoom.clientWidth, ui.zoom.clientHeight);
    view.bins = null;
    redraw();
  }

  function drawBoard() {
    const ctx = BoardView.beginBoard(view, board);
    board.gizmos.forEach((g, i) => BoardView.drawGizmo(ctx, g, flipperSwing(main, i + 1, state.t, state.done)));
    state.drawn = [];
    runs.forEach((run, r) => {
      const done = r === 0 ? state.done : eventsBy(run, state.t);
      run.balls.forEach((ball, b) => {
        drawTrail(ctx, run, ball, r, b);
        const at = ballAt(run, ball, state.t, done);
        if (!at) return;
        BoardView.drawBall(ctx, board, at, b, r === 0 ? null : SECOND_RUN);
        if (r === 0) state.drawn.push({ name: ball.name, x: at.x, y: at.y, vx: at.vx, vy: at.vy });
      });
    });
    state.pathDrawn = [];
    if (path) {
      path.balls.forEach((ball) => {
        drawPathTrail(ctx, ball);
        const at = pathBallAt(ball, state.t);
        ctx.beginPath();
        ctx.arc(at.x, at.y, board.ball_radius, 0, 2 * Math.PI);
        ctx.lineWidth = 0.07;
        ctx.strokeStyle = PATH_COLOUR;
        ctx.stroke();
        state.pathDrawn.push({ name: ball.name, x: at.x, y: at.y });
      });
      drawPathParting(ctx);
    }
    drawHits(ctx);
    BoardView.endBoard(view);
  }

  // The path's last half second: the kept step positions in it, and the interpolated ends. A
  // trail never takes more than TRAIL_POINTS of them, so that a frame's cost stays bounded.
  const TRAIL_POINTS = 2000;
  function drawPathTrail(ctx, ball) {
    const from = Math.max(0, state.t - TRAIL_SECONDS);
    if (state.t <= from) return;
    const first = countAtMost(ball.t, ball.count, from), last = countBelow(ball.t, ball.count, state.t);
    const stride = Math.max(1, Math.ceil((last - first) / TRAIL_POINTS));
    const start = pathBallAt(ball, from), end = pathBallAt(ball, state.t);
    ctx.beginPath();
    ctx.moveTo(start.x, start.y);
    for (let i = first; i < last; i += stride) ctx.lineTo(ball.p[2 * i], ball.p[2 * i + 1]);
    ctx.lineTo(end.x, end.y);
    strokeTrail(ctx, PATH_COLOUR, 0.45, 0.06);
  }

  // From the moment the runs part on: a red line between where each had the ball, with a ring at
  // both ends, so that the place stays marked while the runs go on apart.
  function drawPathParting(ctx) {
    const p = path.parting;
    if (!p || state.t < p.time) return;
    ctx.strokeStyle = PARTING_COLOUR;
    ctx.lineWidth = 0.05;
    ctx.beginPath();
    ctx.moveTo(p.ours[0], p.ours[1]);
    ctx.lineTo(p.theirs[0], p.theirs[1]);
    ctx.stroke();
    for (const at of [p.ours, p.theirs]) {
      ctx.beginPath();
      ctx.arc(at[0], at[1], 0.1, 0, 2 * Math.PI);
      ctx.stroke();
    }
  }

  function ballColour(r, b) { return r === 0 ? BoardView.ballColour(b) : SECOND_RUN; }

  // The last half second of each ball's path, sampled on its true pieces.
  const TRAIL_SECONDS = 0.5, TRAIL_SAMPLES = 48;
  function drawTrail(ctx, run, ball, r, b) {
    const from = Math.max(0, state.t - TRAIL_SECONDS);
    if (state.t <= from) return;
    ctx.beginPath();
    let drawn = false;
    for (let s = 0; s <= TRAIL_SAMPLES; s++) {
      const t = s === TRAIL_SAMPLES ? state.t : from + (state.t - from) * s / TRAIL_SAMPLES;
      const done = s === TRAIL_SAMPLES && r === 0 ? state.done : eventsBy(run, t);
      const at = ballAt(run, ball, t, done);
      if (!at) continue;
      if (drawn) ctx.lineTo(at.x, at.y); else ctx.moveTo(at.x, at.y);
      drawn = true;
    }
    strokeTrail(ctx, ballColour(r, b), 0.35, 0.08);
  }
  // A trail is drawn see-through, so that the balls and the board stay visible under it.
  function strokeTrail(ctx, colour, alpha, width) {
    ctx.strokeStyle = colour;
    ctx.globalAlpha = alpha;
    ctx.lineWidth = width;
    ctx.lineJoin = "round";
    ctx.stroke();
    ctx.globalAlpha = 1;
  }

  // A ring where each recent collision happened, fading over 0.2 s.
  function drawHits(ctx) {
    const fade = 0.2;
    for (let k = state.done - 1, shown = 0; k >= 0 && shown < 64 && main.time[k] > state.t - fade; k--) {
      if (main.kind[k] !== 0) continue;
      for (const ball of main.balls) {
        const i = countAtMost(ball.event, ball.count, k) - 1;
        if (i < 0 || ball.event[i] !== k || !ball.logged[i]) continue;
        ctx.globalAlpha = 1 - (state.t - main.time[k]) / fade;
        ctx.strokeStyle = KIND_COLOUR[0];
        ctx.lineWidth = 0.06;
        ctx.beginPath();
        ctx.arc(ball.p[2 * i], ball.p[2 * i + 1], board.ball_radius + 0.12, 0, 2 * Math.PI);
        ctx.stroke();
        shown++;
      }
    }
    ctx.globalAlpha = 1;
  }

  // ---- The timelines --------------------------------------------------------------------------
  // The whole run (timeline_view.js), then the moments around the current time.
  function drawTimeline() {
    const w = ui.timeline.clientWidth, h = ui.timeline.clientHeight;
    if (!view.bins || view.bins.length !== w * 3) view.bins = TimelineView.bins(main, endTime, w);
    TimelineView.draw(view.timeline, w, h, view.bins, endTime, state.t, partings);
  }
  function markParting(ctx, x, h) { TimelineView.markParting(ctx, x, h, partings); }

  // The moments around the current time: each event its own tick, the selected one outlined.
  const MAX_TICKS = 5000;
  function zoomWindow() { return [state.t - state.zoomSpan / 2, state.t + state.zoomSpan / 2]; }
  function drawZoom() {
    const ctx = view.zoom, w = ui.zoom.clientWidth, h = ui.zoom.clientHeight;
    const [from, to] = zoomWindow();
    const x = (t) => (t - from) / (to - from) * w;
    ctx.clearRect(0, 0, w, h);
    ctx.fillStyle = "#111720";
    ctx.fillRect(0, 0, w, h);
    const first = countBelow(main.time, main.count, from), last = countAtMost(main.time, main.count, to);
    const laneH = (h - 18) / 3 - 2;
    const dense = last - first > MAX_TICKS;
    for (let k = first; k < last; k += dense ? Math.ceil((last - first) / MAX_TICKS) : 1) {
      ctx.fillStyle = KIND_COLOUR[main.kind[k]];
      ctx.fillRect(Math.floor(x(main.time[k])), 4 + KIND_LANE[main.kind[k]] * (h - 18) / 3, dense ? 1 : 2, laneH);
    }
    if (state.selected >= first && state.selected < last) {
      ctx.strokeStyle = "#ffffff";
      ctx.lineWidth = 1;
      ctx.strokeRect(Math.floor(x(main.time[state.selected])) - 2, 2, 6, h - 16);
    }
    markParting(ctx, x, h);
    ctx.fillStyle = "#ffffff";
    ctx.fillRect(Math.round(x(state.t)), 0, 1, h);
    ctx.fillStyle = "#8893a5";
    ctx.font = "11px system-ui, sans-serif";
    ctx.fillText(from.toFixed(4) + " s", 4, h - 3);
    const label = (dense ? "every " + Math.ceil((last - first) / MAX_TICKS) + "th of " : "") + (last - first) +
      " events in " + num(+(to - from).toPrecision(3)) + " s (wheel to zoom)";
    ctx.fillText(label, w / 2 - ctx.measureText(label).width / 2, h - 3);
    const right = to.toFixed(4) + " s";
    ctx.fillText(right, w - 4 - ctx.measureText(right).width, h - 3);
  }

  // ---- Text beside the board --------------------------------------------------------------------
  function drawClock() {
    ui.clock.textContent = "t = " + state.t.toFixed(6) + " s · " + (main.first + state.done) + " / " + (main.first + main.count) + " events";
    ui.seek.value = String(Math.round(state.t / endTime * 100000));
    if (document.activeElement !== ui.eventNumber) ui.eventNumber.value = String(main.first + state.done);
  }

  // One report made while an event ran: [decision type, rule, x, y] (render_run_track.hpp).
  function noteText(run, note) {
    const [typeNumber, rule, x, y] = note;
    const type = names.decisions[typeNumber];
    if (type === "trigger") return "trigger " + esc(gizmoName(run, x)) + " → " + esc(gizmoName(run, y));
    if (type === "action") return "action " + esc(gizmoName(run, x));
    if (type === "input") return "input key " + x + (y ? " up" : " down");
    const other = y >= 0 ? " with " + esc(gizmoName(run, y)) : "";
    return "rule " + esc(names.rules[rule]) + ": " + esc(gizmoName(run, x)) + other;
  }

  function showDetails(k) {
    const run = main;
    const kind = names.kinds[run.kind[k]];
    const rows = [["time", num(run.time[k]) + " s"], ["exact time", hexFloat(run.time[k])], ["kind", kind]];
    if (kind !== "input") {
      if (run.a[k] >= 0) rows.push(["a", esc(gizmoName(run, run.a[k]))]);
      if (run.b[k] >= 0) rows.push(["b", esc(gizmoName(run, run.b[k]))]);
      if (kind === "collision") rows.push(["feature", run.feature[k]]);
    }
    let html = "<h2>Event " + k + " (after it: " + (k + 1) + " events)</h2><table>" +
      rows.map((r) => "<tr><td>" + r[0] + "</td><td>" + r[1] + "</td></tr>").join("") + "</table>";
    // The balls the event changed: their recorded state, and the velocity they arrived with.
    for (const ball of run.balls) {
      const touched = run.a[k] === ball.id || (run.b[k] === ball.id && kind !== "input");
      const i = countAtMost(ball.event, ball.count, k) - 1;
      const own = i >= 0 && ball.event[i] === k && ball.logged[i] === 1;
      if (!touched && !own) continue;
      html += "<h2>" + esc(ball.name) + "</h2>";
      if (!own) {
        html += "<p class=\"note\">Its recorded state at this event is left out of the page: the path drawn stays within " +
          run.tolerance + " L of it. <code>gizmo dump LOG --from " + num(run.time[k]) + " --to " + num(run.time[k]) +
          "</code> shows it.</p>";
        continue;
      }
      const before = i > 0 ? ballAt(run, ball, run.time[k], k) : null;
      html += "<table><tr><td>position</td><td>" + num(ball.p[2 * i]) + ", " + num(ball.p[2 * i + 1]) + "</td></tr>" +
        (before ? "<tr><td>velocity before</td><td>" + short(before.vx) + ", " + short(before.vy) + " <span class=\"note\">(from the path)</span></td></tr>" : "") +
        "<tr><td>velocity after</td><td>" + num(ball.v[2 * i]) + ", " + num(ball.v[2 * i + 1]) + "</td></tr></table>";
    }
    const reports = run.notes.patterns[run.notes.index[k]];
    if (reports.length) html += "<h2>Reports while it ran</h2><ul>" + reports.map((n) => "<li>" + noteText(run, n) + "</li>").join("") + "</ul>";
    if (data.parting) {
      const p = data.parting;
      html += "<h2>Compared with " + esc(runs[1].label) + "</h2><p>" +
        (run.time[k] < p.time ? "Before the runs part." : run.time[k] === p.time ? "Where the runs part." : "After the runs part.") + "</p>";
    }
    if (path) {
      const p = path.parting;
      html += "<h2>Compared with " + esc(path.label) + "</h2><p>" +
        (!p ? "The runs stay within " + path.threshold + " L of each other." :
          run.time[k] < p.time ? "Before the runs part." : "After the runs part (t = " + p.time.toFixed(6) + " s).") + "</p>";
    }
    ui.details.innerHTML = html;
  }

  function describe() {
    document.getElementById("title").textContent = runs.map((r) => r.label).concat(path ? [path.label] : []).join("  vs  ");
    const parts = runs.map((r, i) =>
      (runs.length > 1 ? (i ? "second (rings): " : "first: ") : "") + r.model + " model, " + r.precision + ", " +
      r.count + " events over " + num(r.end) + " s" + (r.tolerance > 0 ? ", paths within " + r.tolerance + " L" : ""));
    if (path) {
      parts.push("path (blue rings): " + path.engine + ", a step every " + stepText(path.dt) +
        (path.tolerance > 0 ? ", drawn within " + path.tolerance + " L" : ""));
    }
    document.getElementById("summary").textContent = parts.join(" · ");
    const warnings = runs.filter((r) => r.truncation).map((r) => r.label + ": " + r.truncation);
    if (data.parting) {
      const p = data.parting;
      warnings.push("The runs part at t = " + num(p.time) + " s after " + p.matched_decisions + " alike decisions: " + p.where + ".");
    } else if (runs.length > 1) {
      warnings.push("The runs never part: every decision is alike.");
    }
    if (path && path.parting) {
      const p = path.parting;
      warnings.push("The runs part at t = " + p.time.toFixed(6) + " s: " + path.label + " has " + p.ball + " " +
        p.distance.toFixed(4) + " L from where ours has it (more than " + path.threshold + " L; red on the board and the timelines).");
    } else if (path) {
      warnings.push("The runs stay within " + path.threshold + " L of each other at every step of " + path.label + ".");
    }
    document.getElementById("warnings").textContent = warnings.join("  ");
    const legend = document.getElementById("legend");
    const items = [];
    runs.forEach((run, r) => run.balls.forEach((ball, b) => {
      items.push("<li><span class=\"swatch" + (r ? " ring" : "") + "\" style=\"background:" + ballColour(r, b) +
        ";border-color:" + ballColour(r, b) + "\"></span>" + esc(ball.name) + (runs.length > 1 ? " (" + esc(run.label) + ")" : "") + "</li>");
    }));
    if (path) {
      path.balls.forEach((ball) => items.push("<li><span class=\"swatch ring\" style=\"border-color:" + PATH_COLOUR +
        "\"></span>" + esc(ball.name) + " (" + esc(path.label) + ")</li>"));
    }
    names.kinds.forEach((kind, i) => items.push("<li><span class=\"swatch\" style=\"background:" + KIND_COLOUR[i] +
      ";border-radius:2px\"></span>" + esc(kind) + "</li>"));
    legend.innerHTML = items.join("");
  }

  // What the page drew, for a test to read: the board after state.done events, bit for bit.
  function writeProbe() {
    ui.probe.textContent = JSON.stringify({
      events: main.first + state.done, time: hexFloat(state.t),
      balls: state.drawn.map((b) => ({ name: b.name, x: hexFloat(b.x), y: hexFloat(b.y), x_value: b.x, y_value: b.y })),
      path: state.pathDrawn.map((b) => ({ name: b.name, x_value: b.x, y_value: b.y })),
      parting: path && path.parting ? path.parting.time : null,
    });
  }

  // Everything is drawn at once on every change: a page read right after it loads (the browser
  // test) already shows the moment it asked for.
  function redraw() {
    if (!view.ctx) return;
    drawBoard();
    drawTimeline();
    drawZoom();
    drawClock();
  }

  // ---- Input ----------------------------------------------------------------------------------
  function timeFromTimeline(ev) { return TimelineView.timeAt(ui.timeline, ev, endTime); }
  let dragging = false;
  ui.timeline.addEventListener("pointerdown", (ev) => { dragging = true; pause(); seekTime(timeFromTimeline(ev)); });
  window.addEventListener("pointermove", (ev) => { if (dragging) seekTime(timeFromTimeline(ev)); });
  window.addEventListener("pointerup", () => { dragging = false; });
  ui.zoom.addEventListener("click", (ev) => {
    const rect = ui.zoom.getBoundingClientRect();
    const [from, to] = zoomWindow();
    const t = from + (ev.clientX - rect.left) / rect.width * (to - from);
    // The nearest event, if one is within a few pixels; else just go to that time.
    const k = countAtMost(main.time, main.count, t);
    let best = -1;
    for (const c of [k - 1, k]) if (c >= 0 && c < main.count && (best < 0 || Math.abs(main.time[c] - t) < Math.abs(main.time[best] - t))) best = c;
    pause();
    if (best >= 0 && Math.abs(main.time[best] - t) / (to - from) * rect.width <= 6) selectEvent(best);
    else seekTime(t);
  });
  ui.zoom.addEventListener("wheel", (ev) => {
    ev.preventDefault();
    state.zoomSpan = Math.min(endTime * 2, Math.max(1e-7, state.zoomSpan * (ev.deltaY > 0 ? 1.25 : 0.8)));
    redraw();
  }, { passive: false });
  ui.seek.addEventListener("input", () => { pause(); seekTime(Number(ui.seek.value) / 100000 * endTime); });
  ui.eventNumber.addEventListener("change", () => {
    pause();
    const n = Number(ui.eventNumber.value) - main.first;  // a branch log's events are counted from its parent's start
    if (n >= 1) selectEvent(n - 1); else seekEvents(0);
  });
  ui.play.addEventListener("click", () => (state.playing ? pause() : play()));
  document.getElementById("prev").addEventListener("click", () => stepEvent(-1));
  document.getElementById("next").addEventListener("click", () => stepEvent(+1));
  document.addEventListener("keydown", (ev) => {
    if (ev.target instanceof HTMLInputElement || ev.target instanceof HTMLSelectElement) return;
    if (ev.key === " ") { ev.preventDefault(); state.playing ? pause() : play(); }
    else if (ev.key === "ArrowRight") { ev.preventDefault(); stepEvent(+1); }
    else if (ev.key === "ArrowLeft") { ev.preventDefault(); stepEvent(-1); }
  });
  window.addEventListener("resize", layout);

  // ---- Start ----------------------------------------------------------------------------------
  // FILE#event=N opens the board after N events (and shows event N − 1); FILE#time=S at S seconds.
  // A branch log's events are numbered as in its parent: N counts from the parent's start.
  function openFragment() {
    const m = /^#(event|time)=([0-9.eE+-]+)$/.exec(window.location.hash);
    if (!m) return;
    const value = Number(m[2]) - (m[1] === "event" ? main.first : 0);
    if (m[1] === "time") seekTime(value);
    else if (value >= 1 && value <= main.count) selectEvent(value - 1);
    else seekEvents(value);
  }
  // FILE#bench draws 300 moments spread over the run, as playback would, and writes how long the
  // drawing took into #probe (docs/render.md: how smooth a large run plays). ready_ms counts from
  // the moment the browser began loading the page (performance.now()'s origin), so it includes
  // reading the HTML; load_ms only the script's own start: decoding the data and the first drawing.
  // Each moment is drawn in five rounds and its best time counts: on a shared machine one drawing
  // can also hold the time the system gave to other processes, which says nothing about the page
  // (that worst single drawing is raw_max_ms).
  function bench() {
    const MOMENTS = 300, ROUNDS = 5;
    const best = new Array(MOMENTS).fill(Infinity);
    let rawMax = 0;
    for (let round = 0; round < ROUNDS; round++) {
      for (let i = 0; i < MOMENTS; i++) {
        const start = performance.now();
        seekTime(endTime * (i + 0.5) / MOMENTS);
        const took = performance.now() - start;
        best[i] = Math.min(best[i], took);
        rawMax = Math.max(rawMax, took);
      }
    }
    const worst = best.indexOf(Math.max(...best));
    best.sort((x, y) => x - y);
    ui.probe.textContent = JSON.stringify({
      ready_ms: loadedAt, load_ms: loadedAt - startedAt, frames: MOMENTS, rounds: ROUNDS,
      median_ms: best[MOMENTS >> 1], p99_ms: best[Math.floor(MOMENTS * 0.99)], max_ms: best[MOMENTS - 1],
      max_at_s: endTime * (worst + 0.5) / MOMENTS, raw_max_ms: rawMax,
    });
  }
  describe();
  layout();
  const loadedAt = performance.now();
  openFragment();
  writeProbe();
  if (window.location.hash === "#bench") bench();
  window.addEventListener("hashchange", () => { openFragment(); writeProbe(); });
})();
