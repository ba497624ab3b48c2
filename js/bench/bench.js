// Decode of the 68-byte BuWizz3 status to an object and encode of
// set_motor_data from an object, two ways in one run: the package (JavaScript
// generated from the tables, lib/buwizz3.js) and a hand-written DataView
// codec (handwritten.js). Checks first that both give the same object and
// bytes, then prints ns per call and the ratio to the hand-written code (the
// fastest of 9 interleaved rounds: the least disturbed by other processes).
// A benchmark, not a test: nothing fails on the figures.
//   node bench/bench.js [--rounds N]
import assert from 'node:assert/strict';

import { buwizz3 } from '../index.js';
import { bytes, status68 } from '../test/vectors.js';
import { decodeStatus, encodeSetMotorData } from './handwritten.js';

const frame = bytes(status68);
const motor = { power: [64, -64, 127, -127, 0, 1], brake_flags: 0x21, lut_disable_flags: 0 };
const routes = {
  'hand-written DataView': { decode: (b) => decodeStatus(b), encode: (f) => encodeSetMotorData(f) },
  'generated (package)': {
    decode: (b) => buwizz3.decode(b, { direction: 'notification' }),
    encode: (f) => buwizz3.encode('set_motor_data', f),
  },
};
const expected = routes['generated (package)'];
for (const [name, r] of Object.entries(routes)) {
  assert.deepEqual(r.decode(frame), expected.decode(frame), name);
  assert.deepEqual(r.encode(motor), expected.encode(motor), name);
  assert.throws(() => r.decode(frame.subarray(0, 60)), (e) => e.code === 'bad_length', name);
  assert.throws(() => r.encode({ power: [0, 0, 128, 0, 0, 0] }), (e) => e.code === 'value_out_of_range' && e.offset === 3, name);
  assert.throws(() => r.encode({ powr: [0, 0, 0, 0, 0, 0] }), (e) => /powr|unknown_field/.test(`${e.message} ${e.code}`), name);
}

const roundsArg = process.argv.indexOf('--rounds');
const rounds = roundsArg > 0 ? Number(process.argv[roundsArg + 1]) : 9;
let sink = 0;
function time(fn, arg) {
  let n = 1000;
  for (;;) {  // grow the batch to about 50 ms
    const t0 = process.hrtime.bigint();
    for (let i = 0; i < n; ++i) sink ^= fn(arg) ? 1 : 0;
    const ns = Number(process.hrtime.bigint() - t0);
    if (ns > 50e6) return ns / n;
    n *= 2;
  }
}
const results = {};
for (let r = 0; r < rounds; ++r)
  for (const [name, route] of Object.entries(routes))
    for (const task of ['decode', 'encode']) {
      const key = `${name}|${task}`;
      (results[key] ??= []).push(time(route[task], task === 'decode' ? frame : motor));
    }
const best = (a) => Math.min(...a);
console.log(`node ${process.version}, ${rounds} rounds; fastest ns per call (ratio to hand-written)`);
console.log('| route | status decode (68 bytes) | set_motor_data encode |');
console.log('|---|---|---|');
const base = (task) => best(results[`hand-written DataView|${task}`]);
for (const name of Object.keys(routes)) {
  const cell = (task) => {
    const m = best(results[`${name}|${task}`]);
    return `${m.toFixed(0)} ns (${(m / base(task)).toFixed(2)}x)`;
  };
  console.log(`| ${name} | ${cell('decode')} | ${cell('encode')} |`);
}
if (sink === 2) console.log('');  // keeps the results alive
