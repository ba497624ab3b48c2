// Encode's rules for values that are not plain valid numbers (the
// generated encoders' slow path): defaults, booleans, numeric text, enum
// names and codes, -0, values above 2^31, and the order of the errors.
// Bytes worked out by hand from docs/buwizz3.md, navbot.md and osp.md.
import assert from 'node:assert/strict';
import test from 'node:test';

import { buwizz3, navbot, osp } from '../index.js';

const u8 = (...x) => new Uint8Array(x);

test('defaults, booleans, numeric text, -0', () => {
  assert.deepEqual(buwizz3.encode('set_motor_data', {}), u8(0x30, 0, 0, 0, 0, 0, 0, 0, 0));
  assert.deepEqual(buwizz3.encode('set_motor_data', { power: ['5', -0, true, false, null, '-1'] }),
    u8(0x30, 5, 0, 1, 0, 0, 0xff, 0, 0));
  // enabled true; idle 4294967295 s = FF FF FF FF; shallow 2^31 = 00 00 00 80
  assert.deepEqual(buwizz3.encode('set_motion_wakeup', { enabled: true, idle_timeout_s: 4294967295, shallow_sleep_timeout_s: 2147483648 }),
    u8(0x21, 1, 0xff, 0xff, 0xff, 0xff, 0, 0, 0, 0x80));
  // OSP voltage: -2 V = -200 cV = 0xFF38 little-endian
  assert.deepEqual(osp.encode('voltage', { centivolts: -200 }), u8(0xff, 0xaa, 2, 0x12, 0x38, 0xff, 0, 0, 0x55, 0x77));
});

test('enums by name and by code; the first value by default', () => {
  // set_accel_lpf: hz_50 is 2, the first value hz_0_781 is 8
  assert.deepEqual(buwizz3.encode('set_accel_lpf', { setting: 'hz_50' }), u8(0x37, 2));
  assert.deepEqual(buwizz3.encode('set_accel_lpf', { setting: 10 }), u8(0x37, 10));
  assert.deepEqual(buwizz3.encode('set_accel_lpf', {}), u8(0x37, 8));
  for (const setting of ['hz_7', 4, '2'])
    assert.throws(() => buwizz3.encode('set_accel_lpf', { setting }), { code: 'invalid_enum', offset: 1, field: 'setting' });
  assert.throws(() => buwizz3.encode('set_accel_lpf', { setting: 2.5 }), TypeError);
  assert.throws(() => navbot.encode('maneuver', { switch_b: 'lock' }), { code: 'invalid_enum', offset: 10, field: 'switch_b' });
});

test('errors: type, range, then order (unknown keys first, then fields in order)', () => {
  assert.throws(() => buwizz3.encode('set_motor_data', { power: [0, 0, 0, 1.5, 0, 0] }), { name: 'TypeError', message: 'encode: power[3]: an integer expected, not 1.5' });
  assert.throws(() => buwizz3.encode('set_motor_data', { power: [0, 0, 0, 0, 'x', 0] }), { name: 'TypeError', message: 'encode: power[4]: an integer expected, not x' });
  assert.throws(() => buwizz3.encode('set_motor_data', { power: [0, 0, 0, 0, 0, -128] }), {
    code: 'value_out_of_range', offset: 6, field: 'power[5]',
    message: 'set_motor_data.power: value out of range (valid -127..127 raw) at byte 6' });
  assert.throws(() => buwizz3.encode('set_motor_data', { power: [0, 0, 0, 0, 0, 200], extra: 1 }), {
    code: null, message: 'unknown field extra (fields: power, brake_flags, lut_disable_flags)' });
  assert.throws(() => buwizz3.encode('set_motor_data', { brake_flags: 64, power: [0, 0, 0, 0, 0, 200] }), { offset: 6 });
  assert.throws(() => buwizz3.encode('set_motion_wakeup', { idle_timeout_s: 4294967296 }), { code: 'value_out_of_range', offset: 2 });
  assert.throws(() => buwizz3.encode('set_motion_wakeup', { idle_timeout_s: 9 }), { code: 'value_out_of_range', offset: 2 });
  assert.throws(() => buwizz3.encode('set_led_status', { blink: [{}, { duty: 16 }, {}, {}] }), { code: 'value_out_of_range', offset: 14, field: 'blink[1].duty' });
});
