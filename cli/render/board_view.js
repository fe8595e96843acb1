// The board as both pages draw it: the replay player of `gizmo render` and the play page of
// `gizmo play` (docs/render.md, docs/play.md). One module, so that a board looks the same in
// both: the canvas fitted to the screen, the board's frame, each gizmo from the core's own
// geometry (the drawing JSON of render_board_drawing.cpp), a flipper at its swing, a ball; and
// the exact text of a double, with which both pages report what they drew to their tests.
"use strict";
const BoardView = (function () {
  const SWING_TIME = 1 / 12;  // docs/physics.md §2: a flipper swings a quarter turn in 1/12 s
  const QUARTER = Math.PI / 2;
  const BALL_COLOURS = ["#f4f4f4", "#ffe066", "#7fd1ff", "#ff9ecb", "#a5ffb0", "#ffb27a"];

  // A canvas of width × height CSS pixels, sharp on a high-density screen; its context draws in
  // CSS pixels.
  function fitCanvas(canvas, width, height) {
    const ratio = window.devicePixelRatio || 1;
    canvas.style.width = width + "px";
    canvas.style.height = height + "px";
    canvas.width = Math.max(1, Math.round(width * ratio));
    canvas.height = Math.max(1, Math.round(height * ratio));
    const ctx = canvas.getContext("2d");
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    return ctx;
  }

  // The board canvas fitted into `stage` (a square as large as it allows); view.scale maps board
  // units (L) to CSS pixels, with a margin of view.margin L around the board.
  function fitBoard(canvas, stage, board, view) {
    const side = Math.max(120, Math.min(stage.clientWidth, stage.clientHeight));
    view.ctx = fitCanvas(canvas, side, side);
    view.side = side;
    view.scale = side / (board.size + 2 * view.margin);
  }

  // Clears the canvas and draws the empty board; the context is left in board units (save()d:
  // endBoard restores it).
  function beginBoard(view, board) {
    const ctx = view.ctx;
    ctx.save();
    ctx.clearRect(0, 0, view.side, view.side);
    ctx.translate(view.margin * view.scale, view.margin * view.scale);
    ctx.scale(view.scale, view.scale);
    ctx.fillStyle = "#141a23";
    ctx.fillRect(0, 0, board.size, board.size);
    ctx.lineWidth = 0.06;
    ctx.strokeStyle = "#8a93a6";
    ctx.strokeRect(0, 0, board.size, board.size);
    return ctx;
  }
  function endBoard(view) { view.ctx.restore(); }

  // A flipper's bar direction at swing progress s ∈ [0, 1/12] (quarter turns from +x toward +y).
  function flipperAngle(g, s) {
    return g.rest_quarter * QUARTER + g.forward_sign * 6 * Math.PI * Math.min(SWING_TIME, Math.max(0, s));
  }

  // One gizmo, by its figure and in its colour (each kind's drawing file says: cli/kinds/STEM.hpp);
  // a flipper at swing progress s, a cross turned for s seconds (arm 0 from +x toward +y at its
  // rate).
  function drawGizmo(ctx, g, s) {
    if (g.figure === "flipper") {
      const theta = flipperAngle(g, s);
      ctx.strokeStyle = g.colour;
      ctx.lineCap = "round";
      ctx.lineWidth = 2 * g.radius;
      ctx.beginPath();
      ctx.moveTo(g.pivot[0], g.pivot[1]);
      ctx.lineTo(g.pivot[0] + g.length * Math.cos(theta), g.pivot[1] + g.length * Math.sin(theta));
      ctx.stroke();
      ctx.fillStyle = "#7a4c0c";
      ctx.beginPath();
      ctx.arc(g.pivot[0], g.pivot[1], 0.07, 0, 2 * Math.PI);
      ctx.fill();
      return;
    }
    if (g.figure === "cross") {
      ctx.strokeStyle = g.colour;
      ctx.lineCap = "round";
      ctx.lineWidth = 2 * g.radius;
      ctx.beginPath();
      for (const a of [g.rate * s, g.rate * s + QUARTER]) {
        const dx = g.length * Math.cos(a), dy = g.length * Math.sin(a);
        ctx.moveTo(g.centre[0] - dx, g.centre[1] - dy);
        ctx.lineTo(g.centre[0] + dx, g.centre[1] + dy);
      }
      ctx.stroke();
      return;
    }
    if (g.figure === "cell-outline") {  // nothing meets it: an outline of its cell
      ctx.strokeStyle = g.colour;
      ctx.lineWidth = 0.06;
      ctx.setLineDash([0.15, 0.1]);
      ctx.beginPath();
      g.polygon.forEach((p, i) => (i ? ctx.lineTo(p[0], p[1]) : ctx.moveTo(p[0], p[1])));
      ctx.closePath();
      ctx.stroke();
      ctx.setLineDash([]);
      return;
    }
    ctx.fillStyle = g.colour;
    ctx.beginPath();
    if (g.centre) ctx.arc(g.centre[0], g.centre[1], g.radius, 0, 2 * Math.PI);
    else g.polygon.forEach((p, i) => (i ? ctx.lineTo(p[0], p[1]) : ctx.moveTo(p[0], p[1])));
    ctx.closePath();
    ctx.fill();
  }

  function ballColour(b) { return BALL_COLOURS[b % BALL_COLOURS.length]; }

  // The b-th ball at `at` ({x, y}), filled; or, with ring, only its outline in `ring`'s colour
  // (a second run laid over the first).
  function drawBall(ctx, board, at, b, ring) {
    ctx.beginPath();
    ctx.arc(at.x, at.y, board.ball_radius, 0, 2 * Math.PI);
    if (!ring) {
      ctx.fillStyle = ballColour(b);
      ctx.fill();
      ctx.lineWidth = 0.03;
      ctx.strokeStyle = "#222";
      ctx.stroke();
    } else {
      ctx.lineWidth = 0.07;
      ctx.strokeStyle = ring;
      ctx.stroke();
    }
  }

  // A double as C's %a prints it (the `exact` texts of gizmo's JSON): the tests compare bits.
  function hexFloat(x) {
    if (Number.isNaN(x)) return "nan";
    if (!Number.isFinite(x)) return x > 0 ? "inf" : "-inf";
    const view = new DataView(new ArrayBuffer(8));
    view.setFloat64(0, x);
    const hi = view.getUint32(0), lo = view.getUint32(4);
    const sign = hi >>> 31 ? "-" : "";
    const biased = (hi >>> 20) & 0x7ff;
    const digits = ((hi & 0xfffff).toString(16).padStart(5, "0") + lo.toString(16).padStart(8, "0")).replace(/0+$/, "");
    if (biased === 0 && digits === "") return sign + "0x0p+0";
    const exponent = (biased === 0 ? 1 : biased) - 1023;
    return sign + "0x" + (biased === 0 ? "0" : "1") + (digits ? "." + digits : "") + "p" + (exponent >= 0 ? "+" : "") + exponent;
  }

  return { SWING_TIME, fitCanvas, fitBoard, beginBoard, endBoard, flipperAngle, drawGizmo, ballColour, drawBall, hexFloat };
})();
