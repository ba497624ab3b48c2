// docs/javascript.md's figures and examples match the package.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';
import { gzipSync } from 'node:zlib';

import { buwizz3 } from '../index.js';
import { cases } from './vectors.js';

const doc = readFileSync(new URL('../../docs/javascript.md', import.meta.url), 'utf8');

test('the module size and its gzipped size (within 3 %)', () => {
  const m = doc.match(/`dist\/robowire_wasm\.mjs` is (\d+) KB \((\d+) KB gzipped\)/);
  assert.ok(m, 'size sentence not found');
  const file = readFileSync(new URL('../dist/robowire_wasm.mjs', import.meta.url));
  const near = (actual, kb, what) => assert.ok(Math.abs(actual / 1000 - kb) <= kb * 0.03, `${what}: ${actual} bytes, docs say ${kb} KB`);
  near(file.length, Number(m[1]), 'module');
  near(gzipSync(file, { level: 9 }).length, Number(m[2]), 'gzipped');
  assert.ok(doc.includes(`no ${m[2]} KB module to load`), 'the choice names the gzipped size');
});

test('the number of golden vectors', () => {
  assert.match(doc, new RegExp(`the ${cases.length} BuWizz3 golden vectors`));
});

test('the first example', () => {
  assert.match(doc, /\/\/ Uint8Array\(9\) \[48, 64, 192, 0, 0, 0, 0, 0, 0\]/);
  assert.deepEqual(buwizz3.encode('set_motor_data', { power: [64, -64, 0, 0, 0, 0] }), new Uint8Array([48, 64, 192, 0, 0, 0, 0, 0, 0]));
  assert.deepEqual(buwizz3.decode(new Uint8Array([0x32, 0x32])), {
    type: 'message', protocol: 'buwizz3', message: 'set_data_period',
    fields: { period_ms: 50, period_ms_physical: { value: 50, unit: 'ms' } },
  });
});

test('the number of frames of the differential check', async () => {
  const { readdirSync, statSync } = await import('node:fs');
  const corpus = (d) => {
    const dir = new URL(`../../fuzz/corpus/${d}/`, import.meta.url);
    return readdirSync(dir).filter((f) => statSync(new URL(f, dir)).size > 0).length;
  };
  const n = corpus('buwizz3_command') + corpus('buwizz3_notification');
  assert.match(doc, new RegExp(`\\(${n} frames\\)`));
  assert.match(doc, new RegExp(`${n + 20000} frames, 0 disagreements`));
});
