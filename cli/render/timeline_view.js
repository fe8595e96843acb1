// The whole run's timeline as both pages draw it: the replay player of `gizmo render` and the
// play page of `gizmo play` when it shows a log it opened (docs/render.md, docs/play.md). One
// column per pixel and three lanes (collisions; other notable events; friction ticks,
// recalculations and ends of tick): a column shows a lane's mark when any event of that lane
// falls in it, so every event is marked however many there are. The run is run_data.js's.
"use strict";
const TimelineView = (function () {
  const KIND_COLOUR = ["#ff5a5a", "#c77dff", "#4dd0e1", "#ffb74d", "#5a6577", "#81c784", "#6f7d94", "#3b4454"];
  const KIND_LANE = [0, 1, 1, 1, 2, 1, 2, 2];  // collisions, other notable events, routine events
  const PARTING_COLOUR = "#ff3b3b";

  // Per column and lane: 1 + the first kind seen there (a collision wins), or 0.
  function bins(run, endTime, width) {
    const out = new Uint16Array(width * 3);
    for (let k = 0; k < run.count; k++) {
      const kind = run.kind[k];
      const col = Math.min(width - 1, Math.floor(run.time[k] / endTime * width));
      const slot = col * 3 + KIND_LANE[kind];
      if (!out[slot] || kind === 0) out[slot] = kind + 1;
    }
    return out;
  }
  function laneY(lane, height) { return 4 + lane * (height - 8) / 3; }

  // Dashed red lines at the times where the run parts from another, x(t) giving each one's column.
  function markParting(ctx, x, h, partings) {
    if (!partings.length) return;
    ctx.strokeStyle = PARTING_COLOUR;
    ctx.setLineDash([4, 3]);
    ctx.lineWidth = 2;
    ctx.beginPath();
    for (const t of partings) {
      ctx.moveTo(x(t), 0);
      ctx.lineTo(x(t), h);
    }
    ctx.stroke();
    ctx.setLineDash([]);
  }

  // The timeline of w × h CSS pixels from 0 to endTime, its lanes from `columns` (bins()), the
  // partings marked, and the present t as a white bar.
  function draw(ctx, w, h, columns, endTime, t, partings) {
    ctx.clearRect(0, 0, w, h);
    ctx.fillStyle = "#151b24";
    ctx.fillRect(0, 0, w, h);
    const laneH = (h - 8) / 3 - 2;
    for (let col = 0; col < w; col++)
      for (let lane = 0; lane < 3; lane++) {
        const kind = columns[col * 3 + lane] - 1;
        if (kind < 0) continue;
        ctx.fillStyle = KIND_COLOUR[kind];
        ctx.fillRect(col, laneY(lane, h), 1, laneH);
      }
    markParting(ctx, (x) => x / endTime * w, h, partings);
    ctx.fillStyle = "#ffffff";
    ctx.fillRect(Math.round(t / endTime * w) - 1, 0, 2, h);
  }

  // The board time under a pointer event on the timeline's canvas.
  function timeAt(canvas, ev, endTime) {
    const rect = canvas.getBoundingClientRect();
    return (ev.clientX - rect.left) / rect.width * endTime;
  }

  return { KIND_COLOUR, KIND_LANE, PARTING_COLOUR, bins, markParting, draw, timeAt };
})();
