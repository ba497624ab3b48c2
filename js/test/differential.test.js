// The generated codecs against the C++ library through the command-line
// tool (ROBOWIRE_CLI; one `decode <protocol> --file --json` process per
// batch): every file of fuzz/corpus/* of the protocol, then seeded random
// frames (a message's key with random field values at one of its lengths,
// the same mutated, random bytes). Messages: the same object; errors: the
// same code, offset and line; each message encoded again decodes to the
// same object. ROBOWIRE_DIFF_FRAMES frames per protocol
// (default 20000). Skipped when ROBOWIRE_CLI is not set.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';

import { buwizz3, navbot, osp, RobowireError, schema } from '../index.js';

const cli = process.env.ROBOWIRE_CLI;
const total = Number(process.env.ROBOWIRE_DIFF_FRAMES ?? 20000);
const corpora = new URL('../../fuzz/corpus/', import.meta.url).pathname;
const codecs = { buwizz3, navbot, osp };
const hexOf = (b) => Array.from(b, (x) => x.toString(16).padStart(2, '0')).join(' ');

// The tool's --json line for each frame (one process per batch).
function toolLines(protocol, inputs, direction) {
  const dir = mkdtempSync(join(tmpdir(), 'robowire-js-'));
  const file = join(dir, 'frames.txt');
  writeFileSync(file, `${inputs.map(hexOf).join('\n')}\n`);
  const args = ['decode', protocol, '--file', file, '--json'];
  if (direction) args.push('--direction', direction);
  let out;
  try {
    out = execFileSync(cli, args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'], maxBuffer: 1 << 30 });
  } catch (e) {
    out = e.stdout;  // exit status 1 when any line is an error
  } finally {
    rmSync(dir, { recursive: true });
  }
  return out.trim().split('\n').map((l) => JSON.parse(l));
}
const errorCodes = new Map(schema.errors.map((e) => [e.text, e.name]));
// The number of frames on which the package and the tool disagree (the first few printed).
function disagreements(protocol, inputs, direction) {
  const lines = toolLines(protocol, inputs, direction);
  assert.equal(lines.length, inputs.length);
  let bad = 0, messages = 0;
  lines.forEach((expected, i) => {
    delete expected.line;
    delete expected.notes;  // the tool's remarks on a message (NAVBOT sign-magnitude), not decoded fields
    let got;
    try {
      got = codecs[protocol].decode(inputs[i], { direction });
    } catch (e) {
      if (!(e instanceof RobowireError)) throw e;
      got = e;
    }
    let same;
    if (expected.type === 'message') {
      ++messages;
      try {
        assert.deepEqual(got, expected);
        // and encode takes it back: what it encodes decodes to the same message
        // (not text with bytes that are not UTF-8: decode made them U+FFFD)
        if (!JSON.stringify(got).includes('\uFFFD'))
          assert.deepEqual(codecs[protocol].decode(codecs[protocol].encode(got), { direction }), expected);
        same = true;
      } catch {
        same = false;
      }
    } else {
      // the line ends "<text> at byte N": the code and offset come from it
      const m = /: ([^:]*?)(?: \([^)]*\))* at byte (\d+)$|^(.*) at byte (\d+)$/.exec(expected.error);
      const text = m && (m[1] ?? m[3]);
      // a BuWizz3 byte 0 used both ways, the length no help: the tool's advice names its option
      const usage = / given: add --direction command or --direction notification$/;
      if (usage.test(expected.error)) {
        same = got instanceof RobowireError && got.code === null &&
          got.message === expected.error.replace(usage, " given: pass the direction ('command' or 'notification')");
      } else same = got instanceof RobowireError && got.message === expected.error &&
        got.offset === Number(m[2] ?? m[4]) && (!errorCodes.has(text) || got.code === errorCodes.get(text));
    }
    if (!same && ++bad <= 5)
      console.log(`${protocol} ${hexOf(inputs[i])}:\n  tool ${JSON.stringify(expected)}\n  js   ${got instanceof Error ? got.message : JSON.stringify(got)}`);
  });
  console.log(`${protocol}${direction ? ` ${direction}` : ''}: ${inputs.length} frames, ${messages} messages, ${inputs.length - messages} errors, ${bad} disagreements`);
  return bad;
}

// xorshift32 with a fixed seed per protocol
function rng(seed) {
  let x = seed;
  return () => ((x ^= x << 13), (x ^= x >>> 17), (x ^= x << 5), x >>> 0);
}
function randomFrames(p, direction, count, next) {
  const messages = p.messages.filter((m) => !direction || m.direction === direction);
  const frames = [];
  for (let i = 0; i < count; ++i) {
    const m = messages[next() % messages.length];
    const [lo, hi] = m.lengths[next() % m.lengths.length];
    const kind = next() % 8;
    let n = lo + (next() % (hi - lo + 1));
    if (kind === 0) n = next() % (m.max_input + 8);  // any length
    const b = new Uint8Array(n);
    for (let j = 0; j < n; ++j) b[j] = next() & 0xff;
    if (next() % 2) for (let j = 0; j < n; ++j) b[j] &= [0x01, 0x03, 0x0f, 0x3f, 0x7f, 0xff][next() % 6];  // values in range
    if (kind !== 1) {  // the message's fixed bytes (and the frame's), mostly
      for (const x of [...(p.frame?.fixed ?? []), ...m.fixed]) if (x.offset < n) b[x.offset] = x.value;
      if (kind === 2 && n > 0) b[next() % n] ^= 1 << (next() % 8);  // one bit flipped
    }
    frames.push(b);
  }
  return frames;
}

const seeds = { buwizz3: 0x2545F491, navbot: 0x9E3779B9, osp: 0x85EBCA6B };
for (const p of schema.protocols) {
  // BuWizz3: each direction given, and none (byte 0 and the length decide)
  const directions = p.name === 'buwizz3' ? ['command', 'notification', undefined] : [undefined];
  const skip = !cli && 'ROBOWIRE_CLI not set';
  test(`fuzz/corpus/${p.name}*: the package agrees with the tool`, { skip }, () => {
    const dirs = readdirSync(corpora).filter((d) => d.startsWith(p.name) || d === `diff_${p.name}` || d === `roundtrip_${p.name}`);
    for (const direction of directions) {
      const inputs = dirs.flatMap((d) => readdirSync(join(corpora, d)).sort()
        .map((f) => new Uint8Array(readFileSync(join(corpora, d, f))))).filter((b) => b.length > 0 && b.length < 4096);
      assert.equal(disagreements(p.name, inputs, direction), 0);
    }
  });
  test(`${total} random ${p.name} frames: the package agrees with the tool`, { skip }, () => {
    const next = rng(seeds[p.name]);
    let bad = 0;
    for (const direction of directions) {
      const share = Math.ceil(total / directions.length);
      for (let done = 0; done < share; done += 100000)
        bad += disagreements(p.name, randomFrames(p, direction, Math.min(100000, share - done), next).filter((b) => b.length > 0), direction);
    }
    assert.equal(bad, 0);
  });
}
