// BuWizz3 decode and encode against the golden vectors, hand-computed
// physical values and every error path the package adds; run: node --test test/
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { buwizz3, RobowireError } from '../index.js';
import { bytes, cases, status68 } from './vectors.js';

for (const [direction, hex, message, fields, encodeFields] of cases) {
  test(`decode ${message} ${hex.slice(0, 20)}`, () => {
    const m = buwizz3.decode(bytes(hex), { direction });
    assert.equal(m.type, 'message');
    assert.equal(m.protocol, 'buwizz3');
    assert.equal(m.message, message);
    for (const [k, v] of Object.entries(fields)) assert.deepEqual(m.fields[k], v, k);
  });
  test(`encode ${message} ${hex.slice(0, 20)}`, () => {
    assert.deepEqual(buwizz3.encode(message, encodeFields), bytes(hex));
  });
}

test('status: physical values from the document (9 V + raw x 0.05 V, raw x 0.015 A, degC)', () => {
  const m = buwizz3.decode(bytes(status68), { direction: 'notification' });
  assert.equal(m.message, 'status');
  assert.equal(m.fields.battery_voltage_raw, 80);
  assert.deepEqual(m.fields.battery_voltage, { value: 13, unit: 'V' });
  assert.deepEqual(m.fields.motor_current_raw, [10, 20, 30, 40, 50, 200]);
  assert.deepEqual(m.fields.motor_current, { value: [0.15, 0.3, 0.45, 0.6, 0.75, 3], unit: 'A' });
  assert.equal(m.fields.temperature_c, 35);
  assert.equal(m.fields.flags, 0x73);
  assert.deepEqual(buwizz3.decode(bytes(status68).subarray(0, 54)).fields.pid_state, null);
});

test('decode takes ArrayBuffer and DataView too, and the direction decides 0x23 and 0xAC', () => {
  const b = bytes('32 32');
  assert.equal(buwizz3.decode(b.buffer).fields.period_ms, 50);
  assert.equal(buwizz3.decode(new DataView(b.buffer)).fields.period_ms, 50);
  assert.equal(buwizz3.decode(bytes('AC'), { direction: 'notification' }).message, 'charger_settings');
  assert.equal(buwizz3.decode(bytes('AC'), { direction: 'command' }).message, 'check_charger_settings');
  assert.equal(buwizz3.decode(bytes('23')).message, 'read_accel_calibration');
});

test('encode takes what decode returns', () => {
  const frame = bytes('36 FF 00 00 00 FF 00 00 00 FF 10 20 30 1F F0 08 55');
  assert.deepEqual(buwizz3.encode(buwizz3.decode(frame)), frame);
  const status = bytes(status68);
  assert.deepEqual(buwizz3.encode(buwizz3.decode(status, { direction: 'notification' })), status);
});

function throws(fn, expected) {
  assert.throws(fn, (e) => {
    assert.ok(e instanceof RobowireError, `${e}`);
    for (const [k, v] of Object.entries(expected)) assert.deepEqual(e[k], v, k);
    return true;
  });
}

test('decode errors: the tool\'s line, code, offset, field, message', () => {
  // docs/cli.md's example: period 10 ms is below the document's 20..255 ms
  throws(() => buwizz3.decode(bytes('32 0A')), {
    message: 'set_data_period.period_ms: value out of range (valid 20..255 ms) at byte 1',
    code: 'value_out_of_range', offset: 1, field: 'period_ms', messageName: 'set_data_period',
  });
  // power -128 is outside -127..127
  throws(() => buwizz3.decode(bytes('30 80 00 00 00 00 00 00 00')), {
    code: 'value_out_of_range', offset: 1, field: 'power', messageName: 'set_motor_data',
  });
  // a status cut inside its PID block (54 or 68..129 bytes)
  throws(() => buwizz3.decode(bytes(status68).subarray(0, 60)), {
    message: 'status.pid_state: length matches no form of the message (54 or 68..129 bytes) at byte 54',
    code: 'bad_length', offset: 54, field: 'pid_state', messageName: 'status',
  });
  throws(() => buwizz3.decode(bytes('01 00')), { code: 'too_short', field: null, messageName: 'status' });
  throws(() => buwizz3.decode(bytes('7E 00')), {
    message: 'unknown key 0x7E at byte 0',
    code: 'unknown_message', offset: 0, messageName: null,
  });
  throws(() => buwizz3.decode(new Uint8Array(0)), { code: 'too_short', offset: 0 });
  // 0xAC alone fits the command and the notification: a usage error, no code
  throws(() => buwizz3.decode(bytes('AC')), { code: null, offset: null });
  assert.throws(() => buwizz3.decode([0x32, 0x32]), TypeError);
  assert.throws(() => buwizz3.decode(bytes('32 32'), { direction: 'up' }), TypeError);
});

test('encode errors: range, count, names, types', () => {
  throws(() => buwizz3.encode('set_data_period', { period_ms: 10 }), {
    message: 'set_data_period.period_ms: value out of range (valid 20..255 ms) at byte 1',
    code: 'value_out_of_range', offset: 1, field: 'period_ms', messageName: 'set_data_period',
  });
  throws(() => buwizz3.encode('set_motor_data', { power: [10, 20] }), {
    message: 'power: 2 values given, 6 expected (power=v1,...,v6)', code: null,
  });
  throws(() => buwizz3.encode('set_motor_data', { pwr: [0, 0, 0, 0, 0, 0] }), { code: null, messageName: 'set_motor_data' });
  throws(() => buwizz3.encode('no_such_message', {}), { code: null, messageName: null });
  throws(() => buwizz3.encode('set_led_status', { colors: [{ r: 1, x: 2 }, {}, {}, {}] }), { code: null });
  throws(() => buwizz3.encode({ protocol: 'osp', message: 'voltage', fields: {} }), { code: null });
  assert.throws(() => buwizz3.encode('set_motor_data', { power: 5 }), TypeError);
  assert.throws(() => buwizz3.encode(42), TypeError);
});
