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

import { osp } from '../index.js';

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
