// osp.Scanner against `robowire scan osp --binary --json` (ROBOWIRE_CLI; one
// process per stream): every file of fuzz/corpus/osp_scanner and osp_decode
// one after the other, then a seeded random stream (frames, broken frames,
// noise), fed to the scanner in random chunks. The same records in the same
// order and the same counters. Skipped when ROBOWIRE_CLI is not set.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';

import { navbot, osp } from '../index.js';

const cli = process.env.ROBOWIRE_CLI;
const skip = !cli && 'ROBOWIRE_CLI not set';
const corpora = new URL('../../fuzz/corpus/', import.meta.url).pathname;

function tool(stream) {
  const dir = mkdtempSync(join(tmpdir(), 'robowire-js-'));
  try {
    writeFileSync(join(dir, 'stream.bin'), stream);
    const out = execFileSync(cli, ['scan', 'osp', join(dir, 'stream.bin'), '--binary', '--json'],
      { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'], maxBuffer: 1 << 30 });
    return out.trim().split('\n').map((l) => JSON.parse(l));
  } finally {
    rmSync(dir, { recursive: true });
  }
}
function agree(stream, seed) {
  const expected = tool(stream);
  const counters = expected.pop();
  assert.equal(counters.type, 'counters');
  for (const r of expected) delete r.hints;  // the tool's hints
  let x = seed;
  const next = () => ((x ^= x << 13), (x ^= x >>> 17), (x ^= x << 5), x >>> 0);
  const s = new osp.Scanner();
  const got = [];
  for (let i = 0; i < stream.length;) {
    const n = 1 + (next() % 40);
    got.push(...s.push(stream.subarray(i, i + n)));
    i += n;
  }
  assert.equal(got.length, expected.length);
  got.forEach((r, i) => assert.deepEqual(r, expected[i], `record ${i}`));
  assert.deepEqual(s.counters, { frames: counters.frames, skipped_bytes: counters.skipped_bytes, false_starts: counters.false_starts });
  return `${stream.length} bytes, ${got.length} frames, ${s.counters.false_starts} false starts`;
}

test('osp.Scanner: fuzz/corpus/osp_scanner and osp_decode as one stream', { skip }, () => {
  const files = ['osp_scanner', 'osp_decode'].flatMap((d) => readdirSync(join(corpora, d)).sort().map((f) => readFileSync(join(corpora, d, f))));
  console.log(agree(new Uint8Array(Buffer.concat(files)), 0x1234567));
});

test('osp.Scanner: a random stream of frames, broken frames and noise', { skip }, () => {
  let x = 0x9E3779B9;
  const next = () => ((x ^= x << 13), (x ^= x >>> 17), (x ^= x << 5), x >>> 0);
  const keys = [[2, 0x14], [1, 0x01], [3, 0x01]];  // status, set_angle, a key no message has
  const bytes = [];
  for (let i = 0; i < 20000; ++i) {
    const k = keys[next() % keys.length];
    const f = [0xff, 0xaa, k[0], k[1], next() & 0xff, next() & 3, next() & 0xff, next() & 0x7f, 0x55, 0x77];
    const kind = next() % 6;
    if (kind === 0) f[next() % 10] = next() & 0xff;  // one byte changed
    if (kind === 1) f.length = next() % 10;  // cut short
    if (kind === 2) for (let j = next() % 5; j > 0; --j) bytes.push([0xff, 0xaa, 0x55, 0x77, next() & 0xff][next() % 5]);  // noise
    bytes.push(...f);
  }
  console.log(agree(new Uint8Array(bytes), 0x7654321));
});

// navbot.Reassembler against `robowire scan navbot --json` over hex lines, one frame a line.
function toolLines(lines) {
  const dir = mkdtempSync(join(tmpdir(), 'robowire-js-'));
  try {
    writeFileSync(join(dir, 'frames.txt'), `${lines.map((b) => Array.from(b, (x) => x.toString(16).padStart(2, '0')).join(' ')).join('\n')}\n`);
    const out = execFileSync(cli, ['scan', 'navbot', join(dir, 'frames.txt'), '--json'],
      { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'], maxBuffer: 1 << 30 });
    return out.trim().split('\n').map((l) => JSON.parse(l));
  } finally {
    rmSync(dir, { recursive: true });
  }
}
function agreeFrames(frames) {
  const expected = toolLines(frames);
  const counters = expected.pop();
  const r = new navbot.Reassembler();
  const got = [];
  frames.forEach((f, i) => {
    for (const rec of r.push(f)) got.push({ ...rec, line: i + 1 });
  });
  for (const e of expected) {
    delete e.hints;
    delete e.notes;
  }
  assert.equal(got.length, expected.length);
  got.forEach((rec, i) => assert.deepEqual(rec, expected[i], `record ${i}`));
  for (const k of Object.keys(r.counters)) assert.equal(r.counters[k], counters[k], k);
  return `${frames.length} frames, ${r.counters.messages_reassembled} messages reassembled, ${r.counters.reassembly_errors} reassembly errors`;
}

test('navbot.Reassembler: fuzz/corpus/navbot_reassembler and navbot_frame cut into 20-byte frames', { skip }, () => {
  const frames = [];
  for (const d of ['navbot_reassembler', 'navbot_frame'])
    for (const f of readdirSync(join(corpora, d)).sort()) {
      const b = new Uint8Array(readFileSync(join(corpora, d, f)));
      for (let i = 0; i < b.length; i += 20) frames.push(b.subarray(i, i + 20));
    }
  console.log(agreeFrames(frames.filter((f) => f.length > 0)));
});

test('navbot.Reassembler: random messages, lost, repeated and interleaved frames', { skip }, () => {
  let x = 0x2545F491;
  const next = () => ((x ^= x << 13), (x ^= x >>> 17), (x ^= x << 5), x >>> 0);
  const frames = [];
  while (frames.length < 20000) {
    const n = next() % 40;
    const payload = Uint8Array.from({ length: n }, () => (next() % 4 ? 0x20 + (next() % 90) : next() & 0xff));
    const message = next() % 5 === 0 ? [navbot.encode('maneuver', { pitch: next() % 100 })] : navbot.fragment(payload, { command: [1, 2, 3][next() % 3] });
    for (const f of message) {
      const kind = next() % 20;
      if (kind === 0) continue;  // lost
      frames.push(f);
      if (kind === 1) frames.push(f);  // repeated
      if (kind === 2) frames.push(f.subarray(0, next() % 20));  // cut short
      if (kind === 3) { const g = f.slice(); g[next() % 20] ^= 1 << (next() % 8); frames.push(g); }  // one bit flipped
    }
  }
  console.log(agreeFrames(frames.filter((f) => f.length > 0)));
});

test('navbot.fragment: the document\'s JSON request in frames (remaining counts down, zero padding)', () => {
  // 26 bytes of {"type":"get_device_info"}: two frames, remaining 1 then 0; bytes 0-4: 55 AA 02 rem 00
  const frames = navbot.fragment('{"type":"get_device_info"}');
  assert.equal(frames.length, 2);
  assert.deepEqual(Array.from(frames[0].subarray(0, 6)), [0x55, 0xAA, 0x02, 0x01, 0x00, 0x7B]);
  assert.deepEqual(Array.from(frames[1].subarray(0, 5)), [0x55, 0xAA, 0x02, 0x00, 0x00]);
  assert.deepEqual(Array.from(frames[1].subarray(16)), [0, 0, 0, 0]);  // 11 payload bytes, then padding
  assert.equal(navbot.fragment(new Uint8Array(0)).length, 1);
  assert.equal(navbot.fragment(new Uint8Array(15 * 256)).length, 256);
  assert.throws(() => navbot.fragment(new Uint8Array(15 * 256 + 1)), (e) => e.code === 'capacity_exceeded');
  assert.deepEqual(navbot.fragment('maneuver', { pitch: 10 }), [navbot.encode('maneuver', { pitch: 10 })]);
});
