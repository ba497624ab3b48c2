// The package as users get it: `npm pack`, installed from the tarball into an
// empty directory with no network, imported from Node by its name.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { after, before, test } from 'node:test';

const js = fileURLToPath(new URL('..', import.meta.url));
const pkg = JSON.parse(readFileSync(join(js, 'package.json'), 'utf8'));
// an entry of "files" is there: a path, or a folder/*.ext pattern with at least one match
const present = (f) => {
  const m = f.match(/^(.*)\/\*(\.\w+)$/);
  return m ? existsSync(join(js, m[1])) && readdirSync(join(js, m[1])).some((n) => n.endsWith(m[2])) : existsSync(join(js, f));
};
const built = pkg.files.every(present);
const npm = (args, cwd) => execFileSync('npm', args, { cwd, encoding: 'utf8', env: { ...process.env, npm_config_audit: 'false', npm_config_fund: 'false', npm_config_update_notifier: 'false' } });

let dir;
let files;
before(() => {
  if (!built) return;
  dir = mkdtempSync(join(tmpdir(), 'robowire-pack-'));
  const [info] = JSON.parse(npm(['pack', '--json', '--pack-destination', dir], js));
  files = info.files.map((f) => f.path).sort();
  writeFileSync(join(dir, 'package.json'), '{"name":"user","private":true,"type":"module"}\n');
  npm(['install', '--offline', '--no-package-lock', join(dir, info.filename)], dir);
});
after(() => dir && rmSync(dir, { recursive: true, force: true }));

const skip = !built && `not built: ${pkg.files.filter((f) => !present(f)).join(', ')}`;

test('the tarball holds the files of package.json and no tests, sources or node_modules', { skip }, () => {
  for (const f of ['index.js', 'index.d.ts', 'lib/helpers.js', 'package.json']) assert.ok(files.includes(f), `${f} not in the tarball`);
  assert.deepEqual(files.filter((f) => /(^|\/)(test|gen|src|bench|examples|node_modules)\//.test(f)), []);
});

test('import from Node: every export of index.js is there and declared in index.d.ts', { skip }, () => {
  const script = `import * as rw from 'robowire';
const m = rw.buwizz3.decode(new Uint8Array([0x32, 0x32]));
console.log(JSON.stringify({ exports: Object.keys(rw).sort(), m, frame: Array.from(rw.buwizz3.encode('set_motor_data', { power: [64, -64, 0, 0, 0, 0] })) }));`;
  writeFileSync(join(dir, 'use.mjs'), script);
  const out = JSON.parse(execFileSync(process.execPath, ['use.mjs'], { cwd: dir, encoding: 'utf8' }));
  assert.ok(out.exports.includes('buwizz3') && out.exports.includes('RobowireError'), out.exports.join());
  assert.deepEqual(out.m, { type: 'message', protocol: 'buwizz3', message: 'set_data_period', fields: { period_ms: 50, period_ms_physical: { value: 50, unit: 'ms' } } });
  assert.deepEqual(out.frame, [0x30, 0x40, 0xc0, 0, 0, 0, 0, 0, 0]);  // 64 = 0x40, -64 = 0xC0
  const dts = readFileSync(join(dir, 'node_modules', 'robowire', 'index.d.ts'), 'utf8');
  for (const e of out.exports) assert.match(dts, new RegExp(`export declare (const|class) ${e}\\b`), `${e} not declared`);
});

test('TypeScript resolves the package\'s types by its name', { skip: (skip || !existsSync(join(js, 'node_modules', 'typescript'))) && (skip || 'node_modules missing (npm ci)') }, () => {
  writeFileSync(join(dir, 'use.ts'), `import { buwizz3, type Buwizz3 } from 'robowire';
const m: Buwizz3.Message = buwizz3.decode(new Uint8Array([0x32, 0x32]));
if (m.message === 'set_data_period') { const ms: number = m.fields.period_ms_physical.value; void ms; }
const raw: number = buwizz3.powerFromPercent(50); void raw;
`);
  const tsc = join(js, 'node_modules', 'typescript', 'bin', 'tsc');
  execFileSync(process.execPath, [tsc, '--strict', '--noEmit', '--target', 'es2022', '--module', 'nodenext', '--moduleResolution', 'nodenext', 'use.ts'], { cwd: dir, encoding: 'utf8' });
});

// A browser page that imports the installed package: Debian's chromium
// headless through the web console's playwright-core (web/: npm ci).
const chromiumPath = process.env.CHROMIUM ?? '/usr/bin/chromium';
const playwrightAt = join(js, '..', 'web', 'node_modules', 'playwright-core');
const noBrowser = (!existsSync(chromiumPath) && `no ${chromiumPath}`) || (!existsSync(playwrightAt) && 'web/node_modules missing (cd web && npm ci)');

test('import from a browser page (headless Chromium)', { skip: skip || noBrowser }, async () => {
  const { createRequire } = await import('node:module');
  const http = await import('node:http');
  const { chromium } = createRequire(join(js, '..', 'web', 'package.json'))('playwright-core');
  const root = join(dir, 'node_modules');
  const server = http.createServer((req, res) => {
    const p = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    if (p === '/') return res.writeHead(200, { 'content-type': 'text/html' }).end('<!doctype html><title>robowire</title>');
    const file = join(root, p);
    if (!file.startsWith(`${root}/`) || !existsSync(file)) return res.writeHead(404).end();
    res.writeHead(200, { 'content-type': 'text/javascript' }).end(readFileSync(file));
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  const browser = await chromium.launch({ executablePath: chromiumPath, args: ['--no-sandbox'] });
  try {
    const page = await browser.newPage();
    await page.goto(`http://127.0.0.1:${server.address().port}/`);
    const out = await page.evaluate(async () => {
      const { buwizz3 } = await import('/robowire/index.js');
      return { m: buwizz3.decode(new DataView(new Uint8Array([0x32, 0x32]).buffer)), frame: Array.from(buwizz3.encode('set_data_period', { period_ms: 50 })) };
    });
    assert.deepEqual(out.m, { type: 'message', protocol: 'buwizz3', message: 'set_data_period', fields: { period_ms: 50, period_ms_physical: { value: 50, unit: 'ms' } } });
    assert.deepEqual(out.frame, [0x32, 0x32]);
  } finally {
    await browser.close();
    server.close();
  }
});
