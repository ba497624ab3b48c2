// The console in headless Chromium (Debian's /usr/bin/chromium, one launch
// for every test) against fake devices (fake-devices.js). The device's
// frames are golden bytes from docs/buwizz3.md with the values worked out
// by hand; nothing here is produced by the code under test.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import http from 'node:http';
import { readFile, mkdtemp, writeFile } from 'node:fs/promises';
import { execFile } from 'node:child_process';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { installFakeDevices } from './fake-devices.js';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const types = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.css': 'text/css' };

// Serves web/ and js/ of the repository (file:// pages cannot import modules).
function serve() {
  const server = http.createServer(async (req, res) => {
    const p = path.normalize(decodeURIComponent(new URL(req.url, 'http://x').pathname));
    const file = path.join(root, p.endsWith('/') ? `${p}index.html` : p);
    if (!/^\/(web|js)\//.test(p) || !file.startsWith(root)) return res.writeHead(404).end();
    try {
      const body = await readFile(file);
      res.writeHead(200, { 'content-type': types[path.extname(file)] ?? 'application/octet-stream' }).end(body);
    } catch {
      res.writeHead(404).end();
    }
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(server)));
}

let server, browser, page, url;
const pageErrors = [];
const shots = process.env.ROBOWIRE_SCREENSHOTS;  // a directory: screenshots of the console are written there

before(async () => {
  server = await serve();
  url = `http://127.0.0.1:${server.address().port}/web/`;
  browser = await chromium.launch({ executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium', args: ['--no-sandbox'] });
  const context = await browser.newContext({ viewport: { width: 900, height: 1000 }, acceptDownloads: true });
  await context.addInitScript(installFakeDevices);
  page = await context.newPage();
  page.on('pageerror', (e) => pageErrors.push(e.message));
  await page.goto(url);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 20000 });
});
after(async () => {
  await browser?.close();
  server?.close();
});

const text = (sel) => page.locator(sel).textContent();
const writes = () => page.evaluate(() => window.fake.writes.map((w) => w.hex));
const notify = (hex) => page.evaluate((h) => window.fake.notify(h), hex);
async function slide(port, percent) {
  await page.locator(`#power-${port}`).evaluate((el, v) => {
    el.value = String(v);
    el.dispatchEvent(new Event('input', { bubbles: true }));
  }, percent);
}
async function until(what, check, ms = 5000) {
  const end = Date.now() + ms;
  for (;;) {
    const v = await check();
    if (v) return v;
    if (Date.now() > end) assert.fail(`timed out waiting for ${what}`);
    await new Promise((r) => setTimeout(r, 50));
  }
}

// Status report (docs/buwizz3.md "byte by byte"), 54 bytes:
// flags 0x18 (battery level 3), battery raw 80 -> 9 + 80 x 0.05 = 13.00 V,
// currents 10 20 30 40 100 200 x 0.015 A = 0.150 0.300 0.450 0.600 1.500 3.000 A,
// 25 degC, accel words 0x0800 0xF800 0x1000 = 2048 -2048 4096 x 0.488 mg
// = 0.999424 g, -0.999424 g, 1.998848 g.
const statusA = '01 18 50 0A 14 1E 28 64 C8 19 00 08 00 F8 00 10' + ' 00'.repeat(38);
// battery raw 100 -> 14.00 V; currents 0..5 x 0.015 A; accel 0, 0, 0x0800 -> 0.999 g
const statusB = '01 18 64 00 01 02 03 04 05 19 00 00 00 00 00 08' + ' 00'.repeat(38);
const truncated = '01 18 50 0A';
// For the screenshot only (nothing is checked): currents and accel that move.
function chartFrame(i) {
  const b = new Uint8Array(54);
  b[0] = 1; b[1] = 0x18; b[2] = 80 - Math.floor(i / 20); b[9] = 25;
  for (let p = 0; p < 6; p++) b[3 + p] = Math.round(40 + 35 * Math.sin(i / 8 + p));
  const dv = new DataView(b.buffer);
  dv.setInt16(10, Math.round(800 * Math.sin(i / 6)), true);
  dv.setInt16(12, Math.round(800 * Math.cos(i / 6)), true);
  dv.setInt16(14, 2048, true);
  return Array.from(b, (x) => x.toString(16).padStart(2, '0')).join(' ');
}  // a status cut after 4 bytes

test('BuWizz3: connect writes the data period, the motor timeout and the watchdog', async () => {
  assert.equal(statusA.split(' ').length, 54);
  await page.click('#connect');
  await until('connected', async () => (await text('#state')).startsWith('connected'));
  const req = await page.evaluate(() => window.fake.requests[0]);
  assert.deepEqual(req.optionalServices, ['500592d1-74fb-4481-88b3-9919b1676e93']);
  assert.equal(await page.evaluate(() => window.fake.service), '500592d1-74fb-4481-88b3-9919b1676e93');
  await until('three writes', async () => (await writes()).length >= 3);
  // 0x32 period 50 ms; 0x34 mode 1 (coast); 0x35 timeout 2 s
  assert.deepEqual((await writes()).slice(0, 3), ['32 32', '34 01', '35 02']);
  assert.equal(await page.evaluate(() => window.fake.writes[0].uuid), '50052901-74fb-4481-88b3-9919b1676e93');
});

test('BuWizz3: status values shown as the document gives them', async () => {
  await notify(statusA);
  await until('battery', async () => (await text('#battery')) === '13.00 V');
  const currents = [];
  for (let p = 1; p <= 6; p++) currents.push(await text(`#current-${p}`));
  assert.deepEqual(currents, ['0.150 A', '0.300 A', '0.450 A', '0.600 A', '1.500 A', '3.000 A']);
  assert.deepEqual([await text('#accel-x'), await text('#accel-y'), await text('#accel-z')], ['0.999 g', '-0.999 g', '1.999 g']);
  assert.equal(await text('#temperature'), '25 °C');
});

test('BuWizz3: a malformed notification is logged as an error and the stream goes on', async () => {
  await notify(truncated);
  await until('error row', async () => (await text('#error-count')) === '1');
  const row = await page.locator('#log .error').last().textContent();
  assert.match(row, /01 18 50 0A/);
  assert.match(row, /too short/);
  assert.equal(await text('#battery'), '13.00 V');  // the last good status stays
  await notify(statusB);
  await until('next status', async () => (await text('#battery')) === '14.00 V');
  const currents = [];
  for (let p = 1; p <= 6; p++) currents.push(await text(`#current-${p}`));
  assert.deepEqual(currents, ['0.000 A', '0.015 A', '0.030 A', '0.045 A', '0.060 A', '0.075 A']);
  assert.equal(await text('#accel-z'), '0.999 g');
  assert.equal(await text('#error-count'), '1');
});

test('BuWizz3: sliders send set_motor_data in raw power', async () => {
  const before = (await writes()).length;
  await slide(1, 50);    // 50 x 127 / 100 = 63.5 -> 64 = 0x40
  await until('motor write', async () => (await writes()).slice(before).includes('30 40 00 00 00 00 00 00 00'));
  await slide(2, 99);    // 125.73 -> 126 = 0x7E
  await slide(6, -100);  // -127 = 0x81
  await until('motor write', async () => (await writes()).slice(before).includes('30 40 7E 00 00 00 81 00 00'));
  if (shots) {
    for (let i = 0; i < 60; i++) await notify(chartFrame(i));  // something to chart
    await page.screenshot({ path: path.join(shots, 'console-buwizz3.png'), clip: { x: 0, y: 0, width: 880, height: 440 } });
  }
});

test('BuWizz3: the watchdog is kept alive within its 2 s', async () => {
  const connectedAt = await page.evaluate(() => window.fake.writes[0].t);
  await until('2.5 s connected', async () => (await page.evaluate(() => performance.now())) - connectedAt > 2500, 4000);
  const { times, now } = await page.evaluate(() => ({
    times: window.fake.writes.filter((w) => w.hex === '35 02').map((w) => w.t),
    now: performance.now(),
  }));
  assert.ok(times.length >= 3, `0x35 written ${times.length} times in 2.5 s`);
  for (let i = 1; i < times.length; i++) assert.ok(times[i] - times[i - 1] < 2000, `gap of ${times[i] - times[i - 1]} ms`);
  assert.ok(now - times.at(-1) < 2000);
});

test('BuWizz3: the saved log reads back with robowire decode --file', async (t) => {
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#save-log')]);
  const file = path.join(await mkdtemp(path.join(tmpdir(), 'robowire-web-')), 'log.txt');
  await download.saveAs(file);
  const lines = (await readFile(file, 'utf8')).split('\n');
  assert.ok(lines.includes('32 32') && lines.includes('01 18 50 0A') && lines.includes(statusA.trim()));
  assert.ok(lines.some((l) => l.startsWith('# ') && l.includes('error: ') && l.includes('too short')));
  if (!process.env.ROBOWIRE_CLI) return t.skip('ROBOWIRE_CLI is not set (the command-line tool to read the log back)');
  const { code, stdout, stderr } = await new Promise((resolve) =>
    execFile(process.env.ROBOWIRE_CLI, ['decode', 'buwizz3', '--file', file, '--json'], (err, out, errOut) =>
      resolve({ code: err ? err.code : 0, stdout: out, stderr: errOut })));
  assert.equal(code, 1, stderr);  // one frame is bad
  const records = stdout.trim().split('\n').map((l) => JSON.parse(l));
  const names = records.filter((r) => r.type === 'message').map((r) => r.message);
  assert.deepEqual(names.slice(0, 3), ['set_data_period', 'set_motor_timeout', 'activate_watchdog']);
  const statuses = records.filter((r) => r.message === 'status');
  assert.equal(statuses[0].fields.battery_voltage_raw, 80);
  assert.equal(statuses[1].fields.battery_voltage_raw, 100);
  assert.ok(names.includes('set_motor_data'));
  assert.match(stderr, /errors 1\b/);
  const logged = await page.evaluate(() => Number(document.getElementById('log-count').textContent));
  assert.match(stderr, new RegExp(`frames ${logged}\\b`));
});

test('hex box decodes pasted hex and reports bad hex', async () => {
  await page.selectOption('#hex-protocol', 'buwizz3');
  await page.fill('#hex-input', '0x30,0x40,0xC0,0x00,0x00,0x00,0x00,0x00,0x00');  // docs/javascript.md: power 64, -64
  await page.click('#hex-decode');
  const out = JSON.parse(await text('#hex-output'));
  assert.equal(out.message, 'set_motor_data');
  assert.deepEqual(out.fields.power, [64, -64, 0, 0, 0, 0]);
  await page.fill('#hex-input', '32 3');
  await page.click('#hex-decode');
  assert.match(await text('#hex-output'), /^error: bad hex: odd number/);
  await page.fill('#hex-input', '32 0A');  // period 10 ms: under 20
  await page.click('#hex-decode');
  assert.match(await text('#hex-output'), /^error: .*out of range/);
});

test('BuWizz3: Stop all sends zero power; Disconnect stops the keep-alive', async () => {
  const zero = '30 00 00 00 00 00 00 00 00';
  let n = (await writes()).length;
  await page.click('#stop');
  await until('zero power', async () => (await writes()).slice(n).includes(zero));
  assert.equal(await page.locator('#power-6').inputValue(), '0');
  await slide(3, 100);  // 127 = 0x7F
  await until('port 3', async () => (await writes()).slice(n).includes('30 00 00 7F 00 00 00 00 00'));
  n = (await writes()).length;
  await page.click('#disconnect');
  await until('zero power on disconnect', async () => (await writes()).slice(n).includes(zero));
  assert.equal(await page.evaluate(() => window.fake.connected), false);
  n = (await writes()).length;
  await new Promise((r) => setTimeout(r, 1500));  // more than one keep-alive period
  assert.deepEqual((await writes()).slice(n), []);
  assert.equal(await text('#state'), 'not connected');
});

// NAVBOT-ES02 and OSP run when the package has them (feature check in the page, as the console does).
const has = (name) => page.evaluate((n) => import('/js/index.js').then((m) => Boolean(m[n])), name);
async function reopen(protocol) {
  await page.goto(url);
  await page.waitForSelector('body[data-ready="true"]');
  await page.selectOption('#protocol', protocol);
}
// Opens the console on `protocol` and connects; without it in the package, checks the pane
// says so, skips the test and returns false.
async function connectOrSkip(t, protocol) {
  await reopen(protocol);
  if (!(await has(protocol))) {
    assert.match(await text('#support'), /not in this package build/);
    t.skip(`the package has no ${protocol} (the pane says "not in this package build", checked)`);
    return false;
  }
  await page.click('#connect');
  await until('connected', async () => (await text('#state')).startsWith('connected'));
  return true;
}

test('NAVBOT-ES02: notifications reassembled, decoded and logged', async (t) => {
  if (!(await connectOrSkip(t, 'navbot'))) return;
  const req = await page.evaluate(() => window.fake.requests.at(-1));
  assert.deepEqual(req.filters[0].services, ['6e400011-b5a3-f393-e0a9-e50e24dcca9e']);
  // docs/cli.md: a text frame, command 2, remaining 0, payload {"a":1}
  await page.evaluate(() => window.fake.notify('55 AA 02 00 00 7B 22 61 22 3A 31 7D 00 00 00 00 00 00 00 00', '6e400013-b5a3-f393-e0a9-e50e24dcca9e'));
  await until('logged frame', async () => (await text('#log-count')) === '1');
  assert.equal(await text('#error-count'), '0');
  // docs/cli.md: maneuver with pitch 0x8A = -118, out of -100..100
  await page.evaluate(() => window.fake.notify('55 AA 10 00 00 00 00 8A 00 01 00 00 00 00 00 00 00 00 00 00', '6e400013-b5a3-f393-e0a9-e50e24dcca9e'));
  await until('error row', async () => (await text('#error-count')) === '1');
  assert.match(await page.locator('#log .error').last().textContent(), /pitch/);
  if (shots) await page.screenshot({ path: path.join(shots, 'console-navbot.png'), clip: { x: 0, y: 0, width: 880, height: 440 } });
});

test('OSP: the serial stream at 115200 baud scanned, decoded and logged', async (t) => {
  if (!(await connectOrSkip(t, 'osp'))) return;
  assert.equal(await page.evaluate(() => window.fake.serialOptions.baudRate), 115200);
  // docs/osp.md: voltage 1260 cV (12.60 V) = FF AA 02 12 EC 04 00 00 55 77, split across two reads
  await page.evaluate(() => window.fake.serialData('FF AA 02 12 EC'));
  await page.evaluate(() => window.fake.serialData('04 00 00 55 77'));
  await until('voltage row', async () => /1260/.test(await text('#log')));
  assert.match(await text('#log'), /FF AA 02 12 EC 04 00 00 55 77/);  // the whole frame, not the last read
  // docs/cli.md: key 03 01 is unknown
  await page.evaluate(() => window.fake.serialData('FF AA 03 01 0A 0B 0C 0D 55 77'));
  await until('error row', async () => (await text('#error-count')) === '1');
  assert.match(await page.locator('#log .error').last().textContent(), /unknown key/);
  if (shots) await page.screenshot({ path: path.join(shots, 'console-osp.png'), clip: { x: 0, y: 0, width: 880, height: 440 } });
});

test('no uncaught error in the page', () => {
  assert.deepEqual(pageErrors, []);
});
