// Every file of the BuWizz3 fuzz corpora (fuzz/corpus/buwizz3_command,
// buwizz3_notification) decoded by the package and by the command-line tool
// (ROBOWIRE_CLI, `decode buwizz3 --file --json`): the same message object or
// the same error line; then 10000 seeded random frames per direction (a
// message's command byte and one of its valid lengths, mostly; random bytes).
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

for (const direction of ['command', 'notification']) {
  test(`fuzz/corpus/buwizz3_${direction}: the package agrees with the tool`, { skip: !cli && 'ROBOWIRE_CLI not set' }, () => {
    const dir = join(corpora, `buwizz3_${direction}`);
    const inputs = readdirSync(dir).sort().map((f) => new Uint8Array(readFileSync(join(dir, f)))).filter((b) => b.length > 0);
    agree(inputs, direction, `fuzz/corpus/buwizz3_${direction}`);
  });
  test(`10000 random ${direction} frames: the package agrees with the tool`, { skip: !cli && 'ROBOWIRE_CLI not set' }, () => {
    let x = direction === 'command' ? 0x2545F491 : 0x9E3779B9;  // xorshift32, fixed seeds
    const next = () => ((x ^= x << 13), (x ^= x >>> 17), (x ^= x << 5), x >>> 0);
    // the direction's messages and their valid lengths, from the tool's tables
    const schema = JSON.parse(execFileSync(cli, ['list', '--json', 'buwizz3'], { encoding: 'utf8' }));
    const messages = schema.protocols[0].messages.filter((m) => m.direction === direction);
    const inputs = [];
    for (let i = 0; i < 10000; ++i) {
      const m = messages[next() % messages.length];
      const [lo, hi] = m.lengths[next() % m.lengths.length];
      let n = lo + (next() % (hi - lo + 1));
      if (next() % 8 === 0) n = next() % 140;  // any length
      const b = new Uint8Array(Math.max(n, 1));
      for (let j = 0; j < b.length; ++j) b[j] = next() & 0xff;
      if (next() % 8) b[0] = m.key[0];  // else any first byte
      if (next() % 2) for (let j = 1; j < b.length; ++j) b[j] &= 0x3f;  // more values in range
      inputs.push(b);
    }
    agree(inputs, direction, `random ${direction} frames`);
  });
}
