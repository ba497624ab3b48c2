// The committed lib/*.js are what gen/generate.js writes from the committed
// schema.json, and schema.json is what the tool prints (`$ROBOWIRE_CLI list
// --json`; skipped when ROBOWIRE_CLI is not set).
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { generate, schemaModule } from '../gen/generate.js';

const here = new URL('..', import.meta.url).pathname;
const schemaText = readFileSync(`${here}schema.json`, 'utf8');
const schema = JSON.parse(schemaText);

test('lib/*.js are generated from schema.json', () => {
  for (const p of schema.protocols)
    assert.ok(generate(schema, p) === readFileSync(`${here}lib/${p.name}.js`, 'utf8'), `lib/${p.name}.js differs: run node gen/generate.js`);
  assert.ok(schemaModule(schema) === readFileSync(`${here}lib/schema.js`, 'utf8'), 'lib/schema.js differs: run node gen/generate.js');
});

test('schema.json is what the tool prints', { skip: !process.env.ROBOWIRE_CLI && 'ROBOWIRE_CLI not set' }, () => {
  const tool = execFileSync(process.env.ROBOWIRE_CLI, ['list', '--json'], { encoding: 'utf8' });
  assert.ok(tool === schemaText, 'schema.json differs: $ROBOWIRE_CLI list --json > js/schema.json');
});

test('the shipped code compiles nothing at run time (browsers\' CSP)', () => {
  for (const f of ['index.js', 'lib/runtime.js', ...schema.protocols.map((p) => `lib/${p.name}.js`)])
    assert.doesNotMatch(readFileSync(`${here}${f}`, 'utf8'), /new Function|\beval\(/, f);
});
