// index.d.ts: generated from the tables (gen/dts.js) and committed; checked
// by tsc --strict against the examples, against what the tool decodes from
// the fuzz corpora and against the golden vectors' encode fields.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { test } from 'node:test';

import { generate, loadSchema } from '../gen/dts.js';
import { cases, status68 } from './vectors.js';

const js = fileURLToPath(new URL('..', import.meta.url));
const cli = process.env.ROBOWIRE_CLI;
const haveSchema = existsSync(join(js, 'schema.json')) || Boolean(cli);
const tscPath = join(js, 'node_modules', 'typescript', 'bin', 'tsc');
const haveTsc = existsSync(tscPath);
const tscFlags = ['--strict', '--noEmit', '--target', 'es2022', '--module', 'nodenext', '--moduleResolution', 'nodenext'];

function tsc(files) {
  try {
    execFileSync(process.execPath, [tscPath, ...tscFlags, ...files], { cwd: js, encoding: 'utf8' });
    return '';
  } catch (e) {
    return `${e.stdout}${e.stderr}` || String(e);
  }
}

test('index.d.ts is what gen/dts.js makes of the tables', { skip: !haveSchema && 'no js/schema.json and ROBOWIRE_CLI not set' }, () => {
  const want = generate(loadSchema());
  const have = readFileSync(join(js, 'index.d.ts'), 'utf8');
  assert.ok(have === want, 'index.d.ts differs from the tables: run `node gen/dts.js` in js/');
});

test('tsc --strict: index.d.ts and examples/*.ts', { skip: !haveTsc && 'node_modules missing (npm ci)' }, () => {
  const examples = readdirSync(join(js, 'examples')).filter((f) => f.endsWith('.ts')).map((f) => join('examples', f));
  assert.ok(examples.length >= 2, 'examples/*.ts');
  assert.equal(tsc(['index.d.ts', ...examples]), '');
});

// One TypeScript file that assigns each object to the declared type: tsc
// rejects a missing key, a key the type does not have and a wrong type.
function checkTyped(lines) {
  const dir = mkdtempSync(join(js, '.dts-check-'));
  try {
    const file = join(dir, 'check.ts');
    writeFileSync(file, [`import { buwizz3, type Buwizz3, type Navbot, type Osp } from '../index.js';`, 'void buwizz3;', ...lines].join('\n'));
    return tsc([file]);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

const corpusFrames = (protocol) => {
  const root = join(js, '..', 'fuzz', 'corpus');
  const hex = [];
  for (const d of readdirSync(root).filter((d) => d.includes(protocol))) {
    for (const f of readdirSync(join(root, d))) {
      const b = readFileSync(join(root, d, f));
      if (b.length && statSync(join(root, d, f)).isFile()) hex.push(b.toString('hex'));
    }
  }
  return hex;
};

test('every message the tool decodes from the fuzz corpora and the golden vectors has its declared type',
  { skip: (!cli && 'ROBOWIRE_CLI not set') || (!haveTsc && 'node_modules missing (npm ci)') }, () => {
    const schema = loadSchema();
    const lines = [];
    for (const p of schema.protocols) {
      const frames = corpusFrames(p.name);
      if (p.name === 'buwizz3') {
        // as nRF Connect log lines, which carry the direction (a lone AC needs it)
        const uuid = '50052901-74fb-4481-88b3-9919b1676e93';
        const line = (d, h) => `I 10:00:00.000 ${d === 'command' ? 'Data written to' : 'Notification received from'} ${uuid}, value: (0x) ${h.replaceAll(' ', '-')}`;
        frames.push(...cases.map(([d, h]) => line(d, h)), line('notification', status68.trim()));
      }
      const dir = mkdtempSync(join(tmpdir(), 'robowire-dts-'));
      let out;
      try {
        writeFileSync(join(dir, 'frames.txt'), `${frames.join('\n')}\n`);
        out = execFileSync(cli, ['decode', p.name, '--file', join(dir, 'frames.txt'), '--json'],
          { encoding: 'utf8', maxBuffer: 64 << 20, stdio: ['ignore', 'pipe', 'ignore'] });
      } catch (e) {
        out = e.stdout;  // exit status 1: some frames are errors
      } finally {
        rmSync(dir, { recursive: true, force: true });
      }
      const seen = new Set();
      const ns = p.name[0].toUpperCase() + p.name.slice(1);
      for (const line of out.split('\n').filter(Boolean)) {
        const r = JSON.parse(line);
        if (r.type !== 'message') continue;
        const { type, protocol, message, fields, notes } = r;
        const m = notes ? { type, protocol, message, fields, notes } : { type, protocol, message, fields };
        const text = JSON.stringify(m);
        if (seen.has(text)) continue;
        seen.add(text);
        lines.push(`export const m${lines.length}: ${ns}.Message = ${text};`);
      }
      const kinds = new Set([...seen].map((t) => JSON.parse(t).message));
      const missing = p.messages.map((m) => m.name).filter((n) => !kinds.has(n));
      assert.deepEqual(missing, [], `${p.name}: messages never decoded, so never checked`);
    }
    // what encode takes: the golden vectors' encode fields
    for (const [, , message, , encodeFields] of cases) {
      const ts = JSON.stringify(encodeFields, (k, v) => (v instanceof Uint8Array ? `@bytes[${v}]` : v))
        .replace(/"@bytes\[([\d,]*)\]"/g, 'new Uint8Array([$1])');
      lines.push(`buwizz3.encode(${JSON.stringify(message)}, ${ts});`);
    }
    assert.equal(checkTyped(lines), '');
  });

test('tsc rejects what the declarations forbid', { skip: !haveTsc && 'node_modules missing (npm ci)' }, () => {
  const bad = [
    `const a: Buwizz3.SetDataPeriod = { period_ms: 50, period_ms_physical: { value: 50, unit: 'ms' }, extra: 1 };`,
    `const b: Buwizz3.SetDataPeriod = { period_ms: 50 };`,
    `const c: Buwizz3.Message = { type: 'message', protocol: 'buwizz3', message: 'set_data_period', fields: { period_ms: '50' } };`,
    `buwizz3.encode('set_motor_data', { power: [1, 2, 3] });`,
    `buwizz3.encode('no_such_message', {});`,
    `buwizz3.encode('set_data_period', { period: 50 });`,
    `function f(m: Buwizz3.Message) { if (m.message === 'status') { const v: number = m.fields.pid_state.error; void v; } }`,
    `const e: Navbot.MessageName = 'nope';`,
    `const o: Osp.Inputs['device_type'] = { type: 'no_such_type' };`,
  ];
  for (const line of bad) assert.notEqual(checkTyped([line]), '', line);
});
