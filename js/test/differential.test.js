// Every file of the BuWizz3 fuzz corpora (fuzz/corpus/buwizz3_command,
// buwizz3_notification) decoded by the package and by the command-line tool
// (ROBOWIRE_CLI, `decode buwizz3 --file --json`): the same message object or
// the same error line; then 10000 seeded random frames per direction (byte 0
// one of the protocol's command bytes or any byte, 0..140 bytes long).
// Skipped when ROBOWIRE_CLI is not set.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';

import { buwizz3, RobowireError } from '../index.js';

const cli = process.env.ROBOWIRE_CLI;
const corpora = new URL('../../fuzz/corpus/', import.meta.url).pathname;

// The tool's --json line for each frame (one `decode --file` run).
function toolLines(inputs, direction) {
  const hex = inputs.map((b) => Array.from(b, (x) => x.toString(16).padStart(2, '0')).join(' ')).join('\n') + '\n';
  const file = join(mkdtempSync(join(tmpdir(), 'robowire-js-')), 'frames.txt');
  writeFileSync(file, hex);
  let out;
  try {
    out = execFileSync(cli, ['decode', 'buwizz3', '--file', file, '--json', '--direction', direction],
      { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'], maxBuffer: 1 << 28 });
  } catch (e) {
    out = e.stdout;  // exit status 1 when any line is an error
  }
  return out.trim().split('\n').map((l) => JSON.parse(l));
}
function agree(inputs, direction, what) {
  const lines = toolLines(inputs, direction);
  assert.equal(lines.length, inputs.length);
  let messages = 0;
  lines.forEach((expected, i) => {
    delete expected.line;
    if (expected.type === 'message') {
      assert.deepEqual(buwizz3.decode(inputs[i], { direction }), expected, `frame ${i}`);
      ++messages;
    } else {
      assert.throws(() => buwizz3.decode(inputs[i], { direction }),
        (e) => e instanceof RobowireError && e.message === expected.error, `frame ${i}: ${expected.error}`);
    }
  });
  console.log(`${what}: ${inputs.length} frames, ${messages} messages, ${inputs.length - messages} errors, 0 disagreements`);
}

const keys = [0x01, 0x20, 0x21, 0x22, 0x23, 0x30, 0x31, 0x32, 0x33, 0x34, 0x35, 0x36, 0x37, 0x38, 0x40, 0x50, 0x51,
  0x52, 0x53, 0xA1, 0xAC];
for (const direction of ['command', 'notification']) {
  test(`fuzz/corpus/buwizz3_${direction}: the package agrees with the tool`, { skip: !cli && 'ROBOWIRE_CLI not set' }, () => {
    const dir = join(corpora, `buwizz3_${direction}`);
    const inputs = readdirSync(dir).sort().map((f) => new Uint8Array(readFileSync(join(dir, f)))).filter((b) => b.length > 0);
    agree(inputs, direction, `fuzz/corpus/buwizz3_${direction}`);
  });
  test(`10000 random ${direction} frames: the package agrees with the tool`, { skip: !cli && 'ROBOWIRE_CLI not set' }, () => {
    let x = direction === 'command' ? 0x2545F491 : 0x9E3779B9;  // xorshift32, fixed seeds
    const next = () => ((x ^= x << 13), (x ^= x >>> 17), (x ^= x << 5), x >>> 0);
    const inputs = [];
    for (let i = 0; i < 10000; ++i) {
      const b = new Uint8Array(1 + (next() % 140));
      for (let j = 0; j < b.length; ++j) b[j] = next() & 0xff;
      b[0] = next() % 8 ? keys[next() % keys.length] : b[0];
      if (next() % 4 === 0) for (let j = 1; j < b.length; ++j) b[j] &= 0x3f;  // more values in range
      inputs.push(b);
    }
    agree(inputs, direction, `random ${direction} frames`);
  });
}
