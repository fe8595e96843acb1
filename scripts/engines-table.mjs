// Prints docs/verification.md's table of Box2D 2.4 against Box2D v3 against gizmo on the study's
// scenes (fixtures/study/suite.txt), all measured in this one run: for each scene, our exact run
// and each engine at 1/60 and 1/480 s (bullets and continuous collision on), the collisions
// matched, the largest time error and the wall time per simulated second.
//   node scripts/engines-table.mjs BUILD_DIR
// Needs the box2d3-wasm package (scripts/setup.sh installs it).
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

if (process.argv.length !== 3) {
  process.stderr.write('usage: node scripts/engines-table.mjs BUILD_DIR\n');
  process.exit(2);
}
const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const gizmo = resolve(process.argv[2], 'cli', 'gizmo');
const suiteDir = join(root, 'fixtures', 'study');
const steps = ['1/60', '1/480'];

const scenes = [];
for (const line of readFileSync(join(suiteDir, 'suite.txt'), 'utf8').split('\n')) {
  const words = line.trim().split(/\s+/);
  if (words[0] !== 'scene') continue;
  const keys = words.find((w) => w.startsWith('keys='));
  scenes.push({ name: words[1], board: join(suiteDir, words[2]), seconds: words[3], keys: keys && join(suiteDir, keys.slice(5)) });
}

// One `gizmo crosscheck --json`, or the reason it refused the board.
function crosscheck(scene, engine) {
  const args = ['crosscheck', scene.board, '--time', scene.seconds, '--dt', steps.join(','), '--engine', engine, '--json'];
  if (scene.keys) args.push('--keys', scene.keys);
  try {
    return { report: JSON.parse(execFileSync(gizmo, args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] })) };
  } catch (e) {
    const why = String(e.stderr).split('\n').find((l) => l.startsWith('gizmo crosscheck: ')) ?? String(e.stderr);
    return { refused: why.replace('gizmo crosscheck: ', '') };
  }
}

const perSecond = (wall, seconds) => (wall / Number(seconds)).toExponential(1);
const time = (t) => (t === 0 ? '0' : t.toExponential(1));
const rows = [
  '| scene | s | ours: hits, wall/s | engine | dt | engine hits | matched | missed by engine | max time error s | wall/s |',
  '|---|---|---|---|---|---|---|---|---|---|',
];
for (const scene of scenes) {
  let ours = '';
  for (const engine of ['box2d-2.4', 'box2d-v3']) {
    const { report, refused } = crosscheck(scene, engine);
    if (refused) {
      rows.push(`| ${scene.name} | ${scene.seconds} | ${ours} | ${engine} | | refused: ${refused} | | | | |`);
      continue;
    }
    ours = `${report.ours.collisions}, ${perSecond(report.ours.wall_seconds, scene.seconds)}`;
    for (const s of report.steps) {
      const dt = steps[report.steps.indexOf(s)];
      rows.push(`| ${scene.name} | ${scene.seconds} | ${ours} | ${engine} | ${dt} | ${s.collisions} | ${s.matched} | ` +
                `${s.missed_by_engine} | ${time(s.max_time_error)} | ${perSecond(s.wall_seconds, scene.seconds)} |`);
    }
  }
}
process.stdout.write(rows.join('\n') + '\n');
