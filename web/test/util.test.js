// The console's browser-free helpers, under Node.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { parseHex, toHex, powerFromPercent, logLines } from '../util.js';

test('parseHex reads the spellings of docs/cli.md', () => {
  for (const s of ['01 6D 50', '016d50', '0x01,0x6D,0x50', '0x1,0x6d,0x50', '01-6D-50', '(0x) 01-6D-50', '01:6D:50', '01\n6D 50'])
    assert.deepEqual([...parseHex(s)], [0x01, 0x6d, 0x50], s);
  assert.throws(() => parseHex('3'), /odd number/);
  assert.throws(() => parseHex('0h'), /not hex/);
});

test('powerFromPercent: raw = p x 127 / 100, half away from zero (docs/buwizz3.md)', () => {
  const cases = [[100, 127], [50, 64], [-50, -64], [1, 1], [99, 126], [-100, -127], [0, 0], [-1, -1]];
  for (const [p, raw] of cases) assert.equal(powerFromPercent(p), raw, `${p} %`);
  assert.throws(() => powerFromPercent(101), RangeError);
  assert.throws(() => powerFromPercent(-100.5), RangeError);
});

test('logLines: a # comment with the decoded JSON, then the hex line', () => {
  const bytes = new Uint8Array([0x32, 0x32]);
  assert.equal(toHex(bytes), '32 32');
  assert.equal(logLines({ time: 'T', direction: 'command', bytes, decoded: { message: 'set_data_period' } }),
    '# T command {"message":"set_data_period"}\n32 32\n');
  assert.equal(logLines({ time: 'T', direction: 'notification', bytes: new Uint8Array([1]), error: 'status: too short' }),
    '# T notification error: status: too short\n01\n');
});
