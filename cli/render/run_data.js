// A recorded run as the replay player holds it, and the state of its board at any moment: the
// decoding of the run data that `gizmo render` puts into the page (arrays as base64, docs/render.md)
// and the positions, velocities and flipper swings it implies. The player draws from it; a test
// loads it under node and compares the state after N events with `gizmo replay --event N`
// (tests/integration/player_state.mjs). No drawing and no page here.
"use strict";
const RunData = (function () {
  // ---- Reading the data -----------------------------------------------------------------------
  function bytesOf(text) {
    const raw = atob(text);
    const out = new Uint8Array(raw.length);
    for (let i = 0; i < raw.length; i++) out[i] = raw.charCodeAt(i);
    return out;
  }
  // Each array has its own buffer, so that every typed view is aligned.
  function arrayOf(Type, text) {
    const b = bytesOf(text);
    return new Type(b.buffer, 0, b.length / Type.BYTES_PER_ELEMENT);
  }

  function loadRun(r) {
    const ev = r.events;
    const run = {
      label: r.label, model: r.model, precision: r.precision, duration: r.duration,
      start: r.start_time || 0, first: r.first_event || 0, end: r.end_time, tolerance: r.tolerance, truncation: r.truncation, gizmoNames: r.gizmo_names,
      count: ev.count,
      time: arrayOf(Float64Array, ev.time), kind: arrayOf(Uint8Array, ev.kind),
      a: arrayOf(Int16Array, ev.a), b: arrayOf(Int16Array, ev.b), feature: arrayOf(Int16Array, ev.feature),
      accelerations: r.accelerations,
      balls: r.balls.map((b) => ({
        name: b.name, id: b.id, count: b.pieces,
        event: arrayOf(Int32Array, b.event), p: arrayOf(Float64Array, b.p), v: arrayOf(Float64Array, b.v),
        a: arrayOf(Uint16Array, b.a), logged: arrayOf(Uint8Array, b.logged),
      })),
      flippers: new Map(),
      notes: {
        patterns: r.notes.patterns,
        index: arrayOf(r.notes.index_bytes === 2 ? Uint16Array : Uint32Array, r.notes.index),
      },
    };
    for (const f of r.flippers) {
      run.flippers.set(f.id, {
        count: f.anchors, event: arrayOf(Int32Array, f.event),
        s0: arrayOf(Float32Array, f.s0), direction: arrayOf(Int8Array, f.direction),
      });
    }
    return run;
  }
  // Another engine's path: per ball the kept sample times and positions (render_path_overlay.hpp).
  function loadPath(p) {
    return {
      label: p.label, engine: p.engine, dt: p.dt, tolerance: p.tolerance, threshold: p.threshold, parting: p.parting,
      balls: p.balls.map((b) => ({ name: b.name, count: b.count, t: arrayOf(Float64Array, b.t), p: arrayOf(Float64Array, b.p) })),
    };
  }

  // ---- Searching sorted arrays ----------------------------------------------------------------
  // The number of entries of a[0..n) that are <= value.
  function countAtMost(a, n, value) {
    let lo = 0, hi = n;
    while (lo < hi) {
      const mid = (lo + hi) >>> 1;
      if (a[mid] <= value) lo = mid + 1; else hi = mid;
    }
    return lo;
  }
  // The number of entries of a[0..n) that are < value.
  function countBelow(a, n, value) {
    let lo = 0, hi = n;
    while (lo < hi) {
      const mid = (lo + hi) >>> 1;
      if (a[mid] < value) lo = mid + 1; else hi = mid;
    }
    return lo;
  }

  // ---- The state at a moment ------------------------------------------------------------------
  // A path's ball at time t: on the straight line between the samples around t, as the engine
  // moved it over that step (held at the ends before the first and after the last).
  function pathBallAt(ball, t) {
    const i = countAtMost(ball.t, ball.count, t) - 1;
    if (i < 0) return { x: ball.p[0], y: ball.p[1] };
    if (i >= ball.count - 1) return { x: ball.p[2 * i], y: ball.p[2 * i + 1] };
    const f = (t - ball.t[i]) / (ball.t[i + 1] - ball.t[i]);
    return {
      x: ball.p[2 * i] + f * (ball.p[2 * i + 2] - ball.p[2 * i]),
      y: ball.p[2 * i + 1] + f * (ball.p[2 * i + 3] - ball.p[2 * i + 1]),
    };
  }

  // A moment is a time and the number of events run by then; the number matters when several
  // events share one time (the state after the first of them is not the state after the last).
  function eventsBy(run, t) { return countAtMost(run.time, run.count, t); }

  // A piece from the start is anchored where the run starts: 0, or a branch log's first keyframe.
  function pieceTime(run, ball, i) { const e = ball.event[i]; return e < 0 ? run.start : run.time[e]; }

  // The ball's position in the simulator's own operations (Trajectory::positionAt), so that a
  // double run is drawn at exactly the positions it computed. Null before a spawned ball exists:
  // its first piece starts with the event that spawned it.
  function ballAt(run, ball, t, done) {
    if (ball.event[0] >= done) return null;
    const i = Math.max(0, countAtMost(ball.event, ball.count, done - 1) - 1);
    const acc = run.accelerations[ball.a[i]];
    const tau = t - pieceTime(run, ball, i);
    const half = 0.5;
    const h = half * tau * tau;
    return {
      x: ball.p[2 * i] + tau * ball.v[2 * i] + h * acc[0],
      y: ball.p[2 * i + 1] + tau * ball.v[2 * i + 1] + h * acc[1],
      vx: ball.v[2 * i] + tau * acc[0], vy: ball.v[2 * i + 1] + tau * acc[1],
      piece: i,
    };
  }

  // A flipper's swing progress at a moment, from its anchors.
  function flipperSwing(run, id, t, done) {
    const f = run.flippers.get(id);
    if (!f) return 0;
    const j = Math.max(0, countAtMost(f.event, f.count, done - 1) - 1);
    const t0 = f.event[j] < 0 ? run.start : run.time[f.event[j]];
    return f.s0[j] + f.direction[j] * (t - t0);
  }

  // The board after n events, as the player shows it when it has run n: the time of the n-th
  // event and each ball that exists then, with its position and velocity.
  function stateAfter(run, n) {
    const t = n > 0 ? run.time[n - 1] : run.start;
    const balls = [];
    for (const ball of run.balls) {
      const at = ballAt(run, ball, t, n);
      if (at) balls.push({ name: ball.name, x: at.x, y: at.y, vx: at.vx, vy: at.vy });
    }
    return { events: n, time: t, balls };
  }

  return { loadRun, loadPath, countAtMost, countBelow, pathBallAt, eventsBy, pieceTime, ballAt, flipperSwing, stateAfter };
})();
// Under node (the test), the module's exports; in the page, the global RunData.
if (typeof module === "object" && module.exports) module.exports = RunData;
