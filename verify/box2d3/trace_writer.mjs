// The run of run_scene.mjs written as a gizmo trace (docs/verification.md, "Any engine's run"):
// JSON lines, the header, then the balls after each step as this program has them and the
// contacts it reported, so that `gizmo crosscheck BOARD --trace FILE` reads a real engine's own
// output. Written under a temporary name and renamed when whole; a run that does not end
// properly leaves no file.
import { closeSync, openSync, renameSync, unlinkSync, writeSync } from 'node:fs';

export class TraceWriter {
  // `path` the file to write; `engine` the header's name; `ballNames` and `bodyNames` in the
  // scene's order.
  constructor(path, engine, ballNames, bodyNames) {
    this.path = path;
    this.temporary = `${path}.partial-${process.pid}`;
    this.ballNames = ballNames;
    this.bodyNames = bodyNames;
    this.fd = openSync(this.temporary, 'w');
    this.text = '';
    // Steps not yet written (their contacts may still come), the contacts not yet written (in
    // time order, equal times in the order reported), and the last step's contacts, not yet
    // decided (an absorber's capture is the driver's decision, known by the next request).
    this.steps = [];
    this.contacts = [];
    this.undecided = [];
    this.whole = false;
    process.on('exit', () => {
      if (!this.whole) this.discard();
    });
    this.line({ format: 'gizmo-trace', version: 1, engine, contacts: true });
  }

  // The balls at time 0, as the scene built them.
  start(balls) {
    this.steps.push({ t: 0, balls });
  }

  // Step k (from k·dt) ended at t1 with the balls as given ([x, y, vx, vy, held] each) and the
  // contacts it reported ([kind, ball, other is a ball, other, t, x, y]).
  step(t1, balls, contacts) {
    this.steps.push({ t: t1, balls });
    this.undecided = contacts;
  }

  // The next request's operations: they decide the last step's contacts. A hit is a contact; a
  // ball entering a sensor is a capture when the driver then holds that ball (its first entry in
  // the step: the driver captures a ball once); a ball leaving a sensor is not a contact.
  decide(ops) {
    const held = new Set(ops.filter((op) => op[0] === 'hold').map((op) => op[1]));
    for (const c of this.undecided) {
      const [kind, ball, otherIsBall, other, t, x, y] = c;
      if (kind === 'enter' && !held.delete(ball)) continue;
      if (kind === 'exit') continue;
      this.contacts.push({ t, ball: this.ballNames[ball], other: otherIsBall ? this.ballNames[other] : this.bodyNames[other], x, y });
    }
    this.undecided = [];
    // Stable: of equal times, the one reported first stays first, as in the driver's record.
    this.contacts.sort((a, b) => a.t - b.t);
    // A later step's contact lies at or after the start of the step before it (a contact of a
    // ball stopped short is placed there): every step before the last can be written.
    this.flush(this.steps.length - 1);
  }

  // The run is over (`ops` the requests made after the last step, which decide its contacts):
  // everything is written and the file takes its name.
  finish(ops) {
    this.decide(ops);
    this.flush(this.steps.length);
    this.write();
    closeSync(this.fd);
    renameSync(this.temporary, this.path);
    this.whole = true;
  }

  discard() {
    try {
      closeSync(this.fd);
    } catch {}
    try {
      unlinkSync(this.temporary);
    } catch {}
  }

  flush(count) {
    const steps = this.steps.splice(0, Math.max(0, count));
    for (const { t, balls } of steps) {
      const out = {};
      balls.forEach(([x, y, vx, vy, held], i) => {
        out[this.ballNames[i]] = held ? { x, y, vx, vy, held: true } : { x, y, vx, vy };
      });
      let n = 0;
      while (n < this.contacts.length && this.contacts[n].t <= t) ++n;
      this.line(t === 0 ? { t, balls: out } : { t, balls: out, contacts: this.contacts.splice(0, n) });
    }
    if (this.text.length > 1 << 16) this.write();
  }

  line(object) {
    this.text += JSON.stringify(object) + '\n';
  }

  write() {
    writeSync(this.fd, this.text);
    this.text = '';
  }
}
