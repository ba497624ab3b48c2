// The BuWizz3 helpers (lib/helpers.js) against values from the BuWizz3
// document and worked out by hand, and against the command-line tool where
// it computes the same (ROBOWIRE_CLI; skipped when it is not set).
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { test } from 'node:test';

import { RobowireError, buwizz3, schema } from '../index.js';
import { parseAdvertisement, percentFromPower, powerFromPercent, uuids } from '../lib/helpers.js';

const cli = process.env.ROBOWIRE_CLI;
const bytes = (hex) => Uint8Array.from(hex.trim().split(/\s+/).filter(Boolean), (h) => parseInt(h, 16));
const ascii = (s) => Array.from(s, (c) => c.charCodeAt(0).toString(16)).join(' ');

test('powerFromPercent: p x 127 / 100, half away from zero (worked out by hand)', () => {
  const cases = [
    [100, 127], [-100, -127], [0, 0],
    [50, 64], [-50, -64],      // 63.5: the only whole percentages that land on a half
    [1, 1], [-1, -1],          // 1.27
    [2, 3], [-2, -3],          // 2.54
    [10, 13], [99, 126],       // 12.7; 125.73 (the web console's 99 % is 7E)
    [0.4, 1], [0.39, 0],       // 0.508; 0.4953
    [12.5, 16], [-12.5, -16],  // 15.875
    [49.6, 63], [49.62, 63], [49.61, 63], [50.4, 64],  // 62.992, 63.0174, 63.0047, 64.008
  ];
  for (const [p, raw] of cases) assert.equal(powerFromPercent(p), raw, `${p} %`);
  assert.ok(Object.is(powerFromPercent(-0.39), 0), '-0.4953 rounds to 0, not -0');
  assert.ok(Object.is(powerFromPercent(-0), 0), '-0 % is 0');
});

test('powerFromPercent equals the integer formula (|p| x 127 + 50) / 100 for every whole percentage', () => {
  for (let p = -100; p <= 100; p++) {
    const m = Math.floor((Math.abs(p) * 127 + 50) / 100);
    assert.equal(powerFromPercent(p), p < 0 ? -m : m, `${p} %`);
  }
});

test('powerFromPercent: out of range and wrong types', () => {
  for (const p of [100.001, -100.001, 101, -128, NaN, Infinity, -Infinity]) {
    assert.throws(() => powerFromPercent(p), { name: 'RangeError', message: `powerFromPercent: percent must be within -100..100, got ${p}` });
  }
  for (const p of ['50', null, undefined, 50n, [50]]) {
    assert.throws(() => powerFromPercent(p), (e) => e instanceof TypeError && /powerFromPercent: percent must be a number/.test(e.message), String(p));
  }
});

test('percentFromPower: raw x 100 / 127 (worked out by hand)', () => {
  assert.equal(percentFromPower(127), 100);
  assert.equal(percentFromPower(-127), -100);
  assert.equal(percentFromPower(0), 0);
  assert.ok(Math.abs(percentFromPower(64) - 50.3937007874) < 1e-9);     // 6400 / 127
  assert.ok(Math.abs(percentFromPower(1) - 0.787401574803) < 1e-11);    // 100 / 127
  assert.ok(Math.abs(percentFromPower(-128) + 100.787401574803) < 1e-11);  // int8, as the C++ takes it
  for (const raw of [128, -129, 1.5, NaN, Infinity]) {
    assert.throws(() => percentFromPower(raw), { name: 'RangeError', message: `percentFromPower: raw must be an integer within -128..127, got ${raw}` });
  }
  for (const raw of ['1', null, 1n]) assert.throws(() => percentFromPower(raw), TypeError);
});

test('percentFromPower inverts powerFromPercent within half a step (100 / 127 / 2 %)', () => {
  for (let raw = -127; raw <= 127; raw++) assert.equal(powerFromPercent(percentFromPower(raw)), raw, `raw ${raw}`);
  for (let p = -100; p <= 100; p += 0.25) assert.ok(Math.abs(percentFromPower(powerFromPercent(p)) - p) <= 50 / 127 + 1e-12, `${p} %`);
});

test('percentFromPower agrees with the tool\'s physical value of set_motor_data.power', { skip: !cli && 'ROBOWIRE_CLI not set' }, () => {
  const raws = [];
  for (let raw = -127; raw <= 127; raw++) raws.push(raw);
  while (raws.length % 6) raws.push(0);
  for (let i = 0; i < raws.length; i += 6) {
    const six = raws.slice(i, i + 6);
    const hex = ['30', ...six.map((r) => (r & 0xff).toString(16).padStart(2, '0')), '00', '00'].join(' ');  // 9 bytes
    const out = JSON.parse(execFileSync(cli, ['decode', 'buwizz3', '--json', hex], { encoding: 'utf8' }));
    assert.equal(out.fields.power_physical.unit, '%');
    // the tool prints raw x (100 / 127) to 15 significant digits: equal to 1e-12 %
    out.fields.power_physical.value.forEach((v, k) => assert.ok(Math.abs(v - percentFromPower(six[k])) < 1e-12, `${hex}: ${v}`));
  }
});

test('uuids: the document\'s service UUID (printed on-air, least significant byte first) and characteristics', () => {
  const onAir = '93:6E:67:B1:19:99:B3:88:81:44:FB:74:D1:92:05:50';  // the BuWizz3 document
  const h = onAir.split(':').reverse().join('').toLowerCase();
  assert.equal(uuids.service, `${h.slice(0, 8)}-${h.slice(8, 12)}-${h.slice(12, 16)}-${h.slice(16, 20)}-${h.slice(20)}`);
  assert.equal(uuids.service, '500592d1-74fb-4481-88b3-9919b1676e93');
  // the document's table: Application 0x2901, Bootloader 0x8000, UART ch. 1-4 0x3901-0x3904, all Write + Notify
  assert.deepEqual(
    [uuids.application, uuids.bootloader, ...uuids.uart].map((c) => [c.uuid, c.direction]),
    [
      ['50052901-74fb-4481-88b3-9919b1676e93', 'both'],
      ['50058000-74fb-4481-88b3-9919b1676e93', 'both'],
      ['50053901-74fb-4481-88b3-9919b1676e93', 'both'],
      ['50053902-74fb-4481-88b3-9919b1676e93', 'both'],
      ['50053903-74fb-4481-88b3-9919b1676e93', 'both'],
      ['50053904-74fb-4481-88b3-9919b1676e93', 'both'],
    ]);
  assert.ok(Object.isFrozen(uuids) && Object.isFrozen(uuids.application) && Object.isFrozen(uuids.uart));
});

test('uuids.application is the characteristic the tool reads BuWizz3 from in an nRF Connect log', { skip: !cli && 'ROBOWIRE_CLI not set' }, () => {
  const log = (uuid) => `I 10:12:06.655 Data written to ${uuid}, value: (0x) 32-32\n`;
  const out = execFileSync(cli, ['decode', '--file', '-', '--json'], { input: log(uuids.application.uuid), encoding: 'utf8' });
  const m = JSON.parse(out.trim().split('\n')[0]);
  assert.equal(m.protocol, 'buwizz3');
  assert.equal(m.message, 'set_data_period');
  assert.equal(m.uuid, uuids.application.uuid);
});

// The document's Figure 1, with its manufacturer data as decisions.md reads
// it: advertisement = flags, complete local name, manufacturer data
// 4E 05 'B' 'W' x y serialLSB serialMSB; scan response = the service UUID
// (incomplete list of 128-bit UUIDs, AD type 0x06, on-air order).
const flags = '02 01 06';
const name = `08 09 ${ascii('BuWizz3')}`;
const manufacturer = (xy, serial) => `09 FF 4E 05 42 57 ${xy} ${serial}`;
const serviceOnAir = '93 6E 67 B1 19 99 B3 88 81 44 FB 74 D1 92 05 50';
const scan = `11 06 ${serviceOnAir}`;

test('parseAdvertisement: application mode, firmware 3.22, serial 0x1234, name, service UUID', () => {
  const adv = bytes(`${flags} ${name} ${manufacturer('03 22', '34 12')}`);
  assert.deepEqual(parseAdvertisement(adv, bytes(scan)), {
    mode: 'application', firmware_version: [3, 0x22], serial_low16: 0x1234,
    has_manufacturer_data: true, has_service_uuid: true, local_name: 'BuWizz3',
  });
  assert.deepEqual(parseAdvertisement(adv), {
    mode: 'application', firmware_version: [3, 0x22], serial_low16: 0x1234,
    has_manufacturer_data: true, has_service_uuid: false, local_name: 'BuWizz3',
  });
  assert.deepEqual(parseAdvertisement(adv.buffer, new DataView(bytes(scan).buffer)).has_service_uuid, true);
});

test('parseAdvertisement: bootloader mode ("BL", serial 0)', () => {
  assert.deepEqual(parseAdvertisement(bytes(manufacturer('42 4C', '00 00'))), {
    mode: 'bootloader', firmware_version: [0, 0], serial_low16: 0,
    has_manufacturer_data: true, has_service_uuid: false, local_name: null,
  });
});

test('parseAdvertisement: the service UUID alone, in either list type, anywhere in the list', () => {
  const other = '00 11 22 33 44 55 66 77 88 99 AA BB CC DD EE FF';
  for (const adv of [scan, `11 07 ${serviceOnAir}`, `21 07 ${other} ${serviceOnAir}`]) {
    assert.deepEqual(parseAdvertisement(bytes(adv)), {
      mode: 'unknown', firmware_version: [0, 0], serial_low16: 0,
      has_manufacturer_data: false, has_service_uuid: true, local_name: null,
    }, adv);
  }
});

test('parseAdvertisement: not a BuWizz3 is null', () => {
  const notBuWizz = [
    '',
    `${flags} ${name}`,                                   // a name alone says nothing
    '09 FF 4C 00 42 57 03 22 34 12',                       // another company
    '09 FF 4E 05 42 58 03 22 34 12',                       // not 'B' 'W'
    '08 FF 4E 05 42 57 03 22 34',                          // 7 bytes of data: too short
    `11 06 ${serviceOnAir.replace('93', '94')}`,           // another UUID
    `12 06 00 ${serviceOnAir}`,                            // the UUID off the 16-byte grid
    `11 03 ${serviceOnAir}`,                               // not a 128-bit UUID list
    `${flags} 00 ${manufacturer('03 22', '34 12')}`,       // a zero length ends the data
  ];
  for (const hex of notBuWizz) assert.equal(parseAdvertisement(bytes(hex)), null, hex);
});

test('parseAdvertisement: the last manufacturer data and the last name count; names keep 29 bytes', () => {
  const adv = bytes(`${manufacturer('03 22', '34 12')} 03 09 41 42 ${manufacturer('42 4C', '00 00')} 02 08 43`);
  const r = parseAdvertisement(adv);
  assert.equal(r.mode, 'bootloader');
  assert.equal(r.local_name, 'C');
  const long = 'ABCDEFGHIJKLMNOPQRSTUVWXYZ0123';  // 30 characters
  assert.equal(parseAdvertisement(bytes(`1F 09 ${ascii(long)} ${scan}`)).local_name, long.slice(0, 29));
  assert.equal(parseAdvertisement(bytes(`03 09 FF 41 ${scan}`)).local_name, '\uFFFDA');  // not UTF-8: replaced
});

test('parseAdvertisement: a length past the end is bad_length at its byte', () => {
  const err = (offset) => (e) => {
    assert.ok(e instanceof RobowireError, String(e));
    assert.deepEqual([e.code, e.offset, e.field, e.messageName], ['bad_length', offset, null, null]);
    assert.equal(e.message, `advertisement: length matches no form of the message at byte ${offset}`);
    return true;
  };
  assert.throws(() => parseAdvertisement(bytes(`${flags} 05 09 41`)), err(3));
  assert.throws(() => parseAdvertisement(bytes(`${manufacturer('03 22', '34 12')} 01`).subarray(0, 9)), err(0));
  // scan response offsets count after the advertisement (10 bytes)
  const adv = bytes(manufacturer('03 22', '34 12'));
  assert.throws(() => parseAdvertisement(adv, bytes('02 01 06 03 09 41')), err(10 + 3));
  // the advertisement's error wins
  assert.throws(() => parseAdvertisement(bytes('03 09'), bytes('05')), err(0));
});

test('parseAdvertisement: bytes only', () => {
  for (const v of [[2, 1, 6], '020106', null, 5]) {
    assert.throws(() => parseAdvertisement(v), { name: 'TypeError', message: 'parseAdvertisement: advertisement must be a Uint8Array, ArrayBuffer or DataView' });
  }
  assert.throws(() => parseAdvertisement(bytes(flags), 'x'), { name: 'TypeError', message: 'parseAdvertisement: scanResponse must be a Uint8Array, ArrayBuffer or DataView' });
  assert.equal(parseAdvertisement(bytes(flags), null), null);
});

test('docs/javascript.md: the helpers\' examples give what they say', async () => {
  const { readFileSync } = await import('node:fs');
  const doc = readFileSync(new URL('../../docs/javascript.md', import.meta.url), 'utf8');
  const fns = { powerFromPercent, percentFromPower };
  const examples = [...doc.matchAll(/buwizz3\.(powerFromPercent|percentFromPower)\((-?[\d.]+)\);\s*\/\/ (-?[\d.]+)/g)];
  assert.equal(examples.length, 3);
  for (const [, fn, arg, result] of examples) assert.equal(fns[fn](Number(arg)), Number(result), `${fn}(${arg})`);
  assert.match(doc, new RegExp(`buwizz3\\.uuids\\.application\\.uuid;\\s*// '${uuids.application.uuid}'`));
  assert.match(doc, /\(99 -> 126, 1 -> 1, 100 -> 127\)/);
  assert.deepEqual([99, 1, 100].map(powerFromPercent), [126, 1, 127]);
});

test('powerFromPercent follows the schema\'s unit helper (range, rounding)', () => {
  const rule = schema.protocols.find((p) => p.name === 'buwizz3').unit_helpers.find((h) => h.name === 'power_from_percent');
  const { min, max } = rule.input.range;
  assert.equal(buwizz3.powerFromPercent(min), -127);
  assert.equal(buwizz3.powerFromPercent(max), 127);
  assert.throws(() => buwizz3.powerFromPercent(max + 1e-9), RangeError);
  assert.throws(() => buwizz3.powerFromPercent(min - 1e-9), RangeError);
  assert.equal(rule.rounding, 'half_away_from_zero');
  assert.equal(buwizz3.powerFromPercent(50), 64);    // 63.5 -> 64
  assert.equal(buwizz3.powerFromPercent(-50), -64);  // -63.5 -> -64
});
