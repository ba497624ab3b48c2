// Every file of the BuWizz3 fuzz corpora (fuzz/corpus/buwizz3_command,
// buwizz3_notification) decoded by the package and by the command-line tool
// (ROBOWIRE_CLI, `decode buwizz3 --file --json`): the same message object or
// the same error line. Skipped when ROBOWIRE_CLI is not set.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';

import { buwizz3, RobowireError } from '../index.js';

const cli = process.env.ROBOWIRE_CLI;
const corpora = new URL('../../fuzz/corpus/', import.meta.url).pathname;

for (const direction of ['command', 'notification']) {
  test(`fuzz/corpus/buwizz3_${direction}: the package agrees with the tool`, { skip: !cli && 'ROBOWIRE_CLI not set' }, () => {
    const dir = join(corpora, `buwizz3_${direction}`);
    const inputs = readdirSync(dir).sort().map((f) => new Uint8Array(readFileSync(join(dir, f)))).filter((b) => b.length > 0);
    const hex = inputs.map((b) => Array.from(b, (x) => x.toString(16).padStart(2, '0')).join(' ')).join('\n') + '\n';
    const file = join(mkdtempSync(join(tmpdir(), 'robowire-js-')), 'frames.txt');
    writeFileSync(file, hex);
    let out;
    try {
      out = execFileSync(cli, ['decode', 'buwizz3', '--file', file, '--json', '--direction', direction], { encoding: 'utf8' });
    } catch (e) {
      out = e.stdout;  // exit status 1 when any line is an error
    }
    const lines = out.trim().split('\n').map((l) => JSON.parse(l));
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
    console.log(`buwizz3_${direction}: ${inputs.length} frames, ${messages} messages, ${inputs.length - messages} errors, 0 disagreements`);
  });
}
