// Runs a Gizmoball scene in Box2D v3 (the box2d3-wasm package, pinned in package.json) and writes
// the run as a trace (docs/verification.md, "Any engine's run") on standard output.
//   node run_scene.mjs SCENE.json
// The scene is what `gizmo crosscheck --engine box2d-v3` exports (verify/src/box2d3_scene.cpp):
// the bodies and shapes of the one mapping of gizmos (verify/src/box2d_mapping.cpp), the balls,
// gravity, the friction law's constants and the run's settings. This program adds no geometry of
// its own; it builds what the scene says, steps it, and reports where the balls are after each
// step and the hits Box2D reports (hit events: contacts that begin faster than the rest speed).
import { readFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';

// The package's files by path: its exports name only the build that picks SIMD and threads.
const packageDir = new URL('./node_modules/box2d3-wasm/', import.meta.url);

function fail(message) {
  process.stderr.write(`run_scene.mjs: ${message}\n`);
  process.exit(2);
}

if (process.argv.length !== 3) fail('usage: node run_scene.mjs SCENE.json');
let scene;
try {
  scene = JSON.parse(readFileSync(process.argv[2], 'utf8'));
} catch (e) {
  fail(`${process.argv[2]}: ${e.message}`);
}
if (scene.format !== 'gizmo-box2d-scene' || scene.version !== 1) fail(`${process.argv[2]}: not a gizmo-box2d-scene of version 1`);

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

// Box2D mixes two shapes' coefficients of restitution by their maximum; a ball's is 1 (two balls
// bounce elastically), so the scene holds only gizmos whose coefficient is 1 (the exporter refuses
// the others).
function shapeDef(restitution, sensor) {
  const def = b2.b2DefaultShapeDef();
  const material = def.material;
  material.friction = 0;  // Box2D's Coulomb friction off: the Gizmoball law is applied each step
  material.restitution = restitution;
  def.material = material;
  def.isSensor = sensor;
  def.enableHitEvents = !sensor;
  return def;
}

const nameOfShape = new Map();  // a shape's index1: the name of its gizmo or ball
function addPart(body, def, part, name) {
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
  nameOfShape.set(id.index1, name);
}

for (const body of scene.bodies) {
  const def = b2.b2DefaultBodyDef();
  def.type = body.kinematic ? b2.b2BodyType.b2_kinematicBody : b2.b2BodyType.b2_staticBody;
  def.position = vec(body.origin);
  def.rotation = b2.b2MakeRot(body.angle);
  const id = b2.b2CreateBody(world, def);
  for (const part of body.parts) addPart(id, shapeDef(body.restitution, body.sensor), part, body.name);
}

const balls = scene.balls.map((ball) => {
  const def = b2.b2DefaultBodyDef();
  def.type = b2.b2BodyType.b2_dynamicBody;
  def.position = vec([ball.x, ball.y]);
  def.linearVelocity = vec([ball.vx, ball.vy]);
  def.isBullet = scene.bullets;
  const locks = def.motionLocks;
  locks.angularZ = true;  // fixed rotation
  def.motionLocks = locks;
  const id = b2.b2CreateBody(world, def);
  addPart(id, shapeDef(1, false), { kind: 'circle', centre: [0, 0], radius: ball.radius }, ball.name);
  return { name: ball.name, id, from: [0, 0], to: [0, 0], previous: null };
});
const ballByName = new Map(balls.map((b) => [b.name, b]));

// The Gizmoball friction law (docs/physics.md §4, the core's Ball::frictionApplied), before Box2D
// adds gravity, as the Box2D 2.4 bridge applies it.
function frictionApplied([vx, vy], dt) {
  if (scene.mu === 0 && scene.mu2 === 0) return [vx, vy];
  let factor = 1 - scene.mu * dt;
  if (scene.mu2 !== 0) factor -= scene.mu2 * Math.hypot(vx, vy) * dt;
  if (factor < 0) factor = 0;
  return [factor * vx, factor * vy];
}

const fraction = (ball, [x, y]) => {
  const px = ball.to[0] - ball.from[0], py = ball.to[1] - ball.from[1];
  const l2 = px * px + py * py;
  if (l2 === 0) return 0;
  return Math.min(1, Math.max(0, ((x - ball.from[0]) * px + (y - ball.from[1]) * py) / l2));
};

// A vector handed back by the library, read and its handle freed (the step loop makes millions).
const read = (handle) => {
  const xy = [handle.x, handle.y];
  handle.delete();
  return xy;
};

const state = (ball) => {
  const [x, y] = read(b2.b2Body_GetPosition(ball.id)), [vx, vy] = read(b2.b2Body_GetLinearVelocity(ball.id));
  return { x, y, vx, vy };
};

const dt = scene.dt, n = scene.sub_steps;
const steps = [{ t: 0, balls: Object.fromEntries(balls.map((b) => [b.name, state(b)])), contacts: [] }];
const started = performance.now();
const count = Math.ceil(scene.duration / dt - 1e-9);
for (let k = 0; k < count; ++k) {
  const t0 = k * dt;
  for (const ball of balls) {
    const now = state(ball);
    const v = frictionApplied([now.vx, now.vy], dt);
    const velocity = vec(v);
    b2.b2Body_SetLinearVelocity(ball.id, velocity);
    velocity.delete();
    ball.from = [now.x, now.y];
    // Where n sub-steps of semi-implicit Euler take it, unhindered.
    ball.to = [now.x + dt * v[0], now.y + dt * v[1] + dt * dt * scene.gravity * (n + 1) / (2 * n)];
  }
  b2.b2World_Step(world, dt, n);
  const step = { t: (k + 1) * dt, balls: {}, contacts: [] };
  for (const ball of balls) {
    const s = state(ball);
    step.balls[ball.name] = s;
    ball.alpha = fraction(ball, [s.x, s.y]);
  }
  // A hit: the first hit event of its pair in this step. Box2D does not say when within the step
  // the contact began. A ball that its continuous collision stopped short in the step before
  // (and that hit nothing then) met the contact there, at the fraction of that step's straight
  // path where it stopped; otherwise the contact is placed at the fraction of this step's path
  // where the ball stands after it.
  const events = b2.b2World_GetContactEvents(world);
  const seen = new Set();
  for (let i = 0; i < events.hitCount; ++i) {
    const hit = events.GetHitEvent(i);
    let a = nameOfShape.get(hit.shapeIdA.index1), b = nameOfShape.get(hit.shapeIdB.index1);
    hit.delete();
    if (!ballByName.has(a)) [a, b] = [b, a];
    if (!ballByName.has(a)) continue;
    if (ballByName.has(b) && b < a) [a, b] = [b, a];
    if (seen.has(`${a}\u0000${b}`)) continue;
    seen.add(`${a}\u0000${b}`);
    const ball = ballByName.get(a);
    const earlier = ball.previous;
    const at = earlier && earlier.cut && !earlier.hit ? earlier : { t0, t1: step.t, alpha: ball.alpha, from: ball.from, to: ball.to };
    const contact = {
      t: Math.min(at.t0 + at.alpha * dt, at.t1),  // t0 + dt may round past the step's end
      ball: a,
      other: b,
      x: at.from[0] + at.alpha * (at.to[0] - at.from[0]),
      y: at.from[1] + at.alpha * (at.to[1] - at.from[1]),
    };
    (at === earlier ? steps[steps.length - 1] : step).contacts.push(contact);
    ball.hit = true;
  }
  events.delete();
  for (const ball of balls) {
    ball.previous = { t0, t1: step.t, alpha: ball.alpha, from: ball.from, to: ball.to, cut: ball.alpha < 1 - 1e-4, hit: ball.hit === true };
    ball.hit = false;
  }
  steps.push(step);
}
const wallSeconds = (performance.now() - started) / 1000;

const header = { format: 'gizmo-trace', version: 1, engine: `Box2D v3 (box2d3-wasm ${packageVersion})`, contacts: true, wall_seconds: wallSeconds };
const lines = [JSON.stringify(header)];
for (const step of steps) {
  step.contacts.sort((p, q) => p.t - q.t);
  lines.push(JSON.stringify(step));
}
process.stdout.write(lines.join('\n') + '\n');
