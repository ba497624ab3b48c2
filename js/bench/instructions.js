// Instructions per call of the package and of the hand-written DataView codec
// (handwritten.js): decode of the 68-byte BuWizz3 status, encode of
// set_motor_data. Each figure is the difference between two runs under
// Valgrind (callgrind) with the same warm-up, one with K more calls
// (Node --single-threaded, a fixed 16 MB young generation), so start-up and
// compilation cancel out; each pair runs 3 times and the median is kept. The
// garbage collector still moves a figure by up to 4 % between runs. --check
// fails (exit 1) when the package takes more than LIMIT times the
// hand-written code's instructions.
//   node bench/instructions.js [--check [LIMIT]]   (LIMIT: default 1.05)
//   needs valgrind; about 6 minutes
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';

import { buwizz3 } from '../index.js';
import { bytes, status68 } from '../test/vectors.js';
import { decodeStatus, encodeSetMotorData } from './handwritten.js';

const args = process.argv.slice(2);
if (args.includes('-h') || args.includes('--help')) {
  console.log('node bench/instructions.js [--check [LIMIT]]: instructions per call, package / hand-written (callgrind; LIMIT default 1.05)');
  process.exit(0);
}

const WARM = { decode: 20000, encode: 200000 };
const MORE = { decode: 50000, encode: 400000 };

if (args[0] === '--child') {  // --child ROUTE OP K: warm up, then K more calls
  const [route, op, k] = args.slice(1);
  const frame = bytes(status68);
  const motor = { power: [64, -64, 127, -127, 0, 1], brake_flags: 0x21, lut_disable_flags: 0 };
  const hand = route === 'hand';
  const f = op === 'decode'
    ? (hand ? () => decodeStatus(frame) : () => buwizz3.decode(frame, { direction: 'notification' }))
    : (hand ? () => encodeSetMotorData(motor) : () => buwizz3.encode('set_motor_data', motor));
  let sink = 0;
  for (let i = 0; i < WARM[op]; ++i) sink += f() ? 1 : 0;
  for (let i = 0; i < Number(k); ++i) sink += f() ? 1 : 0;
  if (sink !== WARM[op] + Number(k)) process.exit(3);
  process.exit(0);
}

const self = fileURLToPath(import.meta.url);
function collected(route, op, k) {
  const r = spawnSync('valgrind', ['--tool=callgrind', '--callgrind-out-file=/dev/null', process.execPath,
    '--single-threaded', '--min-semi-space-size=16', '--max-semi-space-size=16', self, '--child', route, op, String(k)], { encoding: 'utf8' });
  const m = /Collected : (\d+)/.exec(r.stderr ?? '');
  if (r.status !== 0 || !m) throw new Error(`valgrind run failed (${route} ${op} ${k}): ${r.error ?? r.stderr.slice(-400)}`);
  return Number(m[1]);
}
const perCall = (route, op) => {
  const runs = [0, 1, 2].map(() => (collected(route, op, MORE[op]) - collected(route, op, 0)) / MORE[op]);
  return runs.sort((a, b) => a - b)[1];
};

const check = args.indexOf('--check');
const limit = check >= 0 && args[check + 1] ? Number(args[check + 1]) : 1.05;
let worst = 0;
console.log('| operation | hand-written | package | ratio |\n|---|---|---|---|');
for (const [op, label] of [['decode', 'status decode (68 bytes)'], ['encode', 'set_motor_data encode']]) {
  const hand = perCall('hand', op);
  const pkg = perCall('package', op);
  worst = Math.max(worst, pkg / hand);
  console.log(`| ${label} | ${Math.round(hand).toLocaleString('en')} | ${Math.round(pkg).toLocaleString('en')} | ${(pkg / hand).toFixed(2)}x |`);
}
if (check >= 0) {
  const ok = worst <= limit;
  console.log(`check: package at most ${limit}x the hand-written code: ${ok ? 'ok' : `no (${worst.toFixed(3)}x)`}`);
  process.exit(ok ? 0 : 1);
}
