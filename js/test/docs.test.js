// docs/javascript.md's figures and examples match the package.
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { test } from 'node:test';
import { gzipSync } from 'node:zlib';

import { buwizz3 } from '../index.js';
import { cases } from './vectors.js';

const doc = readFileSync(new URL('../../docs/javascript.md', import.meta.url), 'utf8');

test('the package size and its gzipped size (within 3 %)', () => {
  const m = doc.match(/`index\.js` and `lib\/\*\.js` are (\d+) KB \((\d+) KB gzipped file by file\)/);
  assert.ok(m, 'size sentence not found');
  const dir = new URL('../lib/', import.meta.url);
  const files = [new URL('../index.js', import.meta.url), ...readdirSync(dir).filter((f) => f.endsWith('.js')).map((f) => new URL(f, dir))]
    .map((u) => readFileSync(u));
  const near = (actual, kb, what) => assert.ok(Math.abs(actual / 1000 - kb) <= kb * 0.03, `${what}: ${actual} bytes, docs say ${kb} KB`);
  near(files.reduce((n, f) => n + f.length, 0), Number(m[1]), 'package');
  near(files.reduce((n, f) => n + gzipSync(f, { level: 9 }).length, 0), Number(m[2]), 'gzipped');
});

test('the bundled, minified size and its gzipped size (within 3 %)', async (t) => {
  const m = doc.match(/Bundled and minified as an app's bundler does it \(esbuild,[^)]*\): (\d+) KB, (\d+) KB gzipped/);
  assert.ok(m, 'bundle size sentence not found');
  let esbuild;
  try {
    esbuild = await import('esbuild');
  } catch {
    t.skip('esbuild not installed (npm ci)');
    return;
  }
  const r = await esbuild.build({ entryPoints: [new URL('../index.js', import.meta.url).pathname], bundle: true, minify: true, format: 'esm', write: false });
  const out = r.outputFiles[0].contents;
  const near = (actual, kb, what) => assert.ok(Math.abs(actual / 1000 - kb) <= kb * 0.03, `${what}: ${actual} bytes, docs say ${kb} KB`);
  near(out.length, Number(m[1]), 'bundle');
  near(gzipSync(out, { level: 9 }).length, Number(m[2]), 'bundle gzipped');
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

test('the differential check\'s default and the corpora it names', () => {
  assert.match(doc, /and 20000 seeded random frames per protocol/);
  assert.match(readFileSync(new URL('differential.test.js', import.meta.url), 'utf8'), /ROBOWIRE_DIFF_FRAMES \?\? 20000/);
});
