// Runs a Gizmoball scene in Box2D v3 (the box2d3-wasm package, pinned in package.json), one step
// at a time as `gizmo` asks (docs/verification.md, "One driver, two engines").
//   node run_scene.mjs        (standard input and output: one JSON object a line each way)
// The first line read is the scene that `gizmo crosscheck --engine box2d-v3` exports
// (verify/src/box2d3_scene.cpp): the bodies and shapes of the one mapping of gizmos
// (verify/src/box2d_mapping.cpp), the balls, gravity and the run's settings; the reply says which
// engine this is and where everything stands. Every further line is a step: the requests made
// between steps, in order (["v", ball, vx, vy] a ball's velocity, ["turn", body, ω] a
// kinematic body's angular velocity, ["hold", ball, x, y], ["release", ball, x, y, vx, vy]),
// then one step of the world; the reply is where the balls and the kinematic bodies stand and the
// contacts of the step. This program adds no geometry and no Gizmoball rule of its own: the core's
// rules between steps (keys, triggers, flipper and spinner schedules, absorbers, friction) are
// applied by gizmo's one driver, which speaks to Box2D 2.4 in process and to this program here.
// The line {"end": true, "ops": [...]} ends the run (the requests made after the last step). When the scene names a `trace_out` file, the run is also
// written there in the trace format that `gizmo crosscheck --trace` reads (trace_writer.mjs).
import { readFileSync, readSync, writeSync } from 'node:fs';

import { TraceWriter } from './trace_writer.mjs';

// The package's files by path: its exports name only the build that picks SIMD and threads.
const packageDir = new URL('./node_modules/box2d3-wasm/', import.meta.url);

function fail(message) {
  process.stderr.write(`run_scene.mjs: ${message}\n`);
  process.exit(2);
}

// Lines of standard input, read as they come (the writer waits for each reply).
let pending = '';
const chunk = Buffer.alloc(1 << 16);
function nextLine() {
  for (;;) {
    const end = pending.indexOf('\n');
    if (end >= 0) {
      const line = pending.slice(0, end);
      pending = pending.slice(end + 1);
      return line;
    }
    const n = readSync(0, chunk, 0, chunk.length, null);
    if (n === 0) return null;
    pending += chunk.toString('utf8', 0, n);
  }
}
const reply = (object) => writeSync(1, JSON.stringify(object) + '\n');

const first = nextLine();
if (first === null) fail('no scene on standard input');
let scene;
try {
  scene = JSON.parse(first);
} catch (e) {
  fail(`the scene: ${e.message}`);
}
if (scene.format !== 'gizmo-box2d-scene' || scene.version !== 3) fail('the scene is not a gizmo-box2d-scene of version 3');

// The single-threaded build: the same arithmetic on every machine (the "deluxe" build uses SIMD
// and threads where the host offers them).
const { default: Factory } = await import(new URL('build/dist/es/compat/Box2D.compat.mjs', packageDir));
const packageVersion = JSON.parse(readFileSync(new URL('package.json', packageDir), 'utf8')).version;
const b2 = await Factory();
const vec = ([x, y]) => new b2.b2Vec2(x, y);

const worldDef = b2.b2DefaultWorldDef();
worldDef.gravity = vec([0, scene.gravity]);
worldDef.enableSleep = false;  // a Gizmoball never sleeps
worldDef.enableContinuous = scene.continuous;
worldDef.restitutionThreshold = scene.restitution_threshold;
worldDef.hitEventThreshold = scene.rest_speed;
const world = b2.b2CreateWorld(worldDef);

// Box2D v3 mixes two shapes' coefficients of restitution by their maximum, unless the world has
// a restitution callback: this one gives a ball and a gizmo the gizmo's coefficient (flippers
// 0.95, spinners 0.9) and two balls 1, as the core does. A ball's material is marked 1.
const kBallMaterial = 1;
b2.b2World_SetRestitutionCallback(world, (restitutionA, materialA, restitutionB) =>
  materialA == kBallMaterial ? restitutionB : restitutionA);

function shapeDef(restitution, sensor, ball) {
  const def = b2.b2DefaultShapeDef();
  const material = def.material;
  material.friction = 0;  // Box2D's Coulomb friction off: the Gizmoball law is applied each step
  material.restitution = restitution;
  if (ball) material.userMaterialId = BigInt(kBallMaterial);
  def.material = material;
  def.isSensor = sensor;
  def.enableSensorEvents = sensor || ball;  // a sensor reports the balls that enter and leave it
  def.enableHitEvents = !sensor;
  return def;
}

// Every shape's owner by its index1: {ball: index} or {body: index}.
const ownerOfShape = new Map();
function addPart(body, def, part, owner) {
  let id;
  if (part.kind === 'polygon') {
    id = b2.b2CreatePolygonShape(body, def, b2.b2MakePolygon(b2.b2ComputeHull(part.points.map(vec)), part.radius));
  } else if (part.kind === 'circle') {
    const circle = new b2.b2Circle();
    circle.center = vec(part.centre);
    circle.radius = part.radius;
    id = b2.b2CreateCircleShape(body, def, circle);
  } else if (part.kind === 'edge') {
    // An edge rounded by the skin: a capsule of the skin's radius.
    const capsule = new b2.b2Capsule();
    capsule.center1 = vec(part.points[0]);
    capsule.center2 = vec(part.points[1]);
    capsule.radius = part.radius;
    id = b2.b2CreateCapsuleShape(body, def, capsule);
  } else {
    fail(`unknown part kind '${part.kind}'`);
  }
  ownerOfShape.set(id.index1, owner);
}

const kinematic = [];  // [body index, body id]
scene.bodies.forEach((body, index) => {
  const def = b2.b2DefaultBodyDef();
  def.type = body.kinematic ? b2.b2BodyType.b2_kinematicBody : b2.b2BodyType.b2_staticBody;
  def.position = vec(body.origin);
  def.rotation = b2.b2MakeRot(body.angle);
  const id = b2.b2CreateBody(world, def);
  for (const part of body.parts) addPart(id, shapeDef(body.restitution, body.sensor, false), part, { body: index });
  if (body.kinematic) kinematic.push([index, id]);
});

const balls = scene.balls.map((ball, index) => {
  const def = b2.b2DefaultBodyDef();
  def.type = b2.b2BodyType.b2_dynamicBody;
  def.position = vec([ball.x, ball.y]);
  def.linearVelocity = vec([ball.vx, ball.vy]);
  def.isBullet = scene.bullets;
  const locks = def.motionLocks;
  locks.angularZ = true;  // fixed rotation
  def.motionLocks = locks;
  const id = b2.b2CreateBody(world, def);
  addPart(id, shapeDef(1, false, true), { kind: 'circle', centre: [0, 0], radius: ball.radius }, { ball: index });
  return { name: ball.name, index, id, v: [ball.vx, ball.vy], held: false, muted: false, from: [0, 0], to: [0, 0], previous: null };
});

// A vector or rotation handed back by the library, read and its handle freed (a run makes millions).
const read = (handle) => {
  const xy = [handle.x, handle.y];
  handle.delete();
  return xy;
};
const angleOf = (id) => {
  const rotation = b2.b2Body_GetRotation(id);
  const angle = b2.b2Rot_GetAngle(rotation);
  rotation.delete();
  return angle;
};
const stateOf = (ball) => [...read(b2.b2Body_GetPosition(ball.id)), ...read(b2.b2Body_GetLinearVelocity(ball.id)), ball.held ? 1 : 0];
const where = () => ({ balls: balls.map(stateOf), angles: kinematic.map(([index, id]) => [index, angleOf(id)]) });

const setVelocity = (ball, v) => {
  const velocity = vec(v);
  b2.b2Body_SetLinearVelocity(ball.id, velocity);
  velocity.delete();
  ball.v = v;
};
const setPosition = (ball, p) => {
  const position = vec(p), rotation = b2.b2MakeRot(0);
  b2.b2Body_SetTransform(ball.id, position, rotation);
  position.delete();
  rotation.delete();
};

const dt = scene.dt, n = scene.sub_steps;
const apply = {
  v: ([i, vx, vy]) => setVelocity(balls[i], [vx, vy]),
  turn: ([body, omega]) => b2.b2Body_SetAngularVelocity(kinematic.find(([index]) => index === body)[1], omega),
  hold: ([i, x, y]) => {
    const ball = balls[i];
    setPosition(ball, [x, y]);
    b2.b2Body_Disable(ball.id);
    // Disabling it ends its sensor overlaps at the next step: the driver's doing, not the ball
    // leaving, so that end is not reported (as Box2D 2.4's muted callbacks are not).
    ball.held = ball.muted = true;
  },
  release: ([i, x, y, vx, vy]) => {
    const ball = balls[i];
    b2.b2Body_Enable(ball.id);
    setPosition(ball, [x, y]);
    setVelocity(ball, [vx, vy]);
    ball.held = ball.muted = false;
  },
};

const fraction = (ball, [x, y]) => {
  const px = ball.to[0] - ball.from[0], py = ball.to[1] - ball.from[1];
  const l2 = px * px + py * py;
  if (l2 === 0) return 0;
  return Math.min(1, Math.max(0, ((x - ball.from[0]) * px + (y - ball.from[1]) * py) / l2));
};

// Where a contact of `ball` met in the step from t0 is placed. Box2D does not say when within the
// step it began. A ball that its continuous collision stopped short in the step before (and that
// hit nothing then) met the contact there, at the fraction of that step's straight path where it
// stopped; otherwise the contact is placed at the fraction of this step's path where the ball
// stands after it.
function placed(ball, t0, t1) {
  const earlier = ball.previous;
  const at = earlier && earlier.cut && !earlier.hit ? earlier : { t0, alpha: ball.alpha, from: ball.from, to: ball.to };
  return [
    Math.min(at.t0 + at.alpha * dt, t1),  // at.t0 + dt may round past the step's end
    at.from[0] + at.alpha * (at.to[0] - at.from[0]),
    at.from[1] + at.alpha * (at.to[1] - at.from[1]),
  ];
}

const engine = `Box2D v3 (box2d3-wasm ${packageVersion})`;
let trace = null;
if (typeof scene.trace_out === 'string') {
  try {
    trace = new TraceWriter(scene.trace_out, engine, scene.balls.map((b) => b.name), scene.bodies.map((b) => b.name));
  } catch (e) {
    fail(`cannot write the trace ${scene.trace_out}: ${e.message}`);
  }
}
const start = where();
trace?.start(start.balls);
reply({ engine, ...start });
// Steps are taken in order from time 0: step k runs from k·dt to (k + 1)·dt, the times the
// driver samples.
let k = 0;
for (let line = nextLine(); line !== null; line = nextLine(), ++k) {
  const request = JSON.parse(line);
  if (request.end) {
    try {
      trace?.finish(request.ops);
    } catch (e) {
      fail(`cannot write the trace ${scene.trace_out}: ${e.message}`);
    }
    reply({ end: true, steps: k, trace_out: trace ? scene.trace_out : null });
    process.exit(0);
  }
  trace?.decide(request.ops);
  for (const op of request.ops) apply[op[0]](op.slice(1));
  const t0 = request.t0, t1 = (k + 1) * dt;
  if (t0 !== k * dt) fail(`step ${k} starts at ${t0} s, not at ${k * dt} s`);
  for (const ball of balls) {
    if (ball.held) continue;
    const [x, y] = read(b2.b2Body_GetPosition(ball.id));
    ball.from = [x, y];
    // Where n sub-steps of semi-implicit Euler take it, unhindered.
    ball.to = [x + dt * ball.v[0], y + dt * ball.v[1] + dt * dt * scene.gravity * (n + 1) / (2 * n)];
  }
  b2.b2World_Step(world, dt, n);
  const state = where();
  for (const ball of balls) ball.alpha = ball.held ? 0 : fraction(ball, state.balls[ball.index]);
  const contacts = [];
  // A hit: the first hit event of its pair in this step; of two balls, the one whose name sorts
  // first is named first, and the position is its centre.
  const events = b2.b2World_GetContactEvents(world);
  const seen = new Set();
  for (let i = 0; i < events.hitCount; ++i) {
    const hit = events.GetHitEvent(i);
    let a = ownerOfShape.get(hit.shapeIdA.index1), b = ownerOfShape.get(hit.shapeIdB.index1);
    hit.delete();
    if (a.ball === undefined) [a, b] = [b, a];
    if (a.ball === undefined) continue;
    if (b.ball !== undefined && balls[b.ball].name < balls[a.ball].name) [a, b] = [b, a];
    const key = b.ball !== undefined ? `b${b.ball}` : `g${b.body}`;
    if (seen.has(`${a.ball} ${key}`)) continue;
    seen.add(`${a.ball} ${key}`);
    const ball = balls[a.ball];
    contacts.push(['hit', a.ball, b.ball !== undefined ? 1 : 0, b.ball ?? b.body, ...placed(ball, t0, t1)]);
    ball.hit = true;
  }
  events.delete();
  // A ball entering or leaving an absorber's sensor.
  const sensors = b2.b2World_GetSensorEvents(world);
  for (let i = 0; i < sensors.beginCount; ++i) {
    const e = sensors.GetBeginEvent(i);
    const sensor = ownerOfShape.get(e.sensorShapeId.index1), visitor = ownerOfShape.get(e.visitorShapeId.index1);
    if (visitor.ball === undefined) continue;
    balls[visitor.ball].muted = false;
    contacts.push(['enter', visitor.ball, 0, sensor.body, ...placed(balls[visitor.ball], t0, t1)]);
  }
  for (let i = 0; i < sensors.endCount; ++i) {
    const e = sensors.GetEndEvent(i);
    const sensor = ownerOfShape.get(e.sensorShapeId.index1), visitor = ownerOfShape.get(e.visitorShapeId.index1);
    if (visitor.ball === undefined) continue;
    const ball = balls[visitor.ball];
    if (ball.muted) {
      ball.muted = false;
      continue;
    }
    contacts.push(['exit', visitor.ball, 0, sensor.body, ...placed(ball, t0, t1)]);
  }
  sensors.delete();
  // A held ball has no path in this step: a hit in the step after its release is placed there.
  for (const ball of balls) {
    ball.previous = ball.held ? null
      : { t0, alpha: ball.alpha, from: ball.from, to: ball.to, cut: ball.alpha < 1 - 1e-4, hit: ball.hit === true };
    ball.hit = false;
  }
  trace?.step(t1, state.balls, contacts);
  reply({ ...state, contacts });
}
