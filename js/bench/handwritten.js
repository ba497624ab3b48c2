// A careful hand-written DataView decoder of the BuWizz3 status and encoder
// of set_motor_data, with the library's checks (status: byte 0 = 0x01, 54 or
// 68..129 bytes; set_motor_data: power -127..127, flag bytes 0..0x3F) and
// the same output object as the package (the tool's JSON: physical values
// rounded to 15 digits, flag bits, NaN as null). The yardstick of bench.js.
const tidy = (v) => Number(v.toPrecision(15));
const f32 = (dv, o) => {
  const v = dv.getFloat32(o, true);
  return Number.isFinite(v) ? v : null;
};
const batteryNames = ['empty', 'low', 'medium', 'full'];
const ports = (v) => ({
  port1: (v & 1) !== 0, port2: (v & 2) !== 0, port3: (v & 4) !== 0,
  port4: (v & 8) !== 0, port5: (v & 16) !== 0, port6: (v & 32) !== 0,
});

export class HandError extends Error {
  constructor(code, offset) {
    super(`${code} at byte ${offset}`);
    this.code = code;
    this.offset = offset;
  }
}

export function decodeStatus(b) {
  const n = b.length;
  if (n < 1) throw new HandError('too_short', 0);
  if (b[0] !== 0x01) throw new HandError('bad_command', 0);
  if (n < 54) throw new HandError('too_short', n);
  if (n > 129) throw new HandError('too_long', 129);
  if (n > 54 && n < 68) throw new HandError('bad_length', 54);
  const dv = new DataView(b.buffer, b.byteOffset, n);
  const flags = b[1];
  const current = [b[3], b[4], b[5], b[6], b[7], b[8]];
  const accel = [dv.getInt16(10, true), dv.getInt16(12, true), dv.getInt16(14, true)];
  const motors = [];
  for (let i = 0, o = 22; i < 4; ++i, o += 8) {
    const abs = dv.getInt16(o + 2, true), pos = dv.getInt32(o + 4, true);
    motors.push({
      type: b[o], velocity: dv.getInt8(o + 1),
      absolute_position: abs, absolute_position_physical: { value: abs, unit: 'deg' },
      position: pos, position_physical: { value: pos, unit: 'deg' },
    });
  }
  const pid = n >= 68 ? {
    process_value: f32(dv, 54), error: f32(dv, 58), output: f32(dv, 62),
    integrator: dv.getInt8(66), motor_output: dv.getInt8(67),
  } : null;
  return {
    type: 'message', protocol: 'buwizz3', message: 'status',
    fields: {
      flags,
      flags_bits: {
        error: (flags & 1) !== 0, motion_wakeup: (flags & 2) !== 0, long_range_phy: (flags & 4) !== 0,
        battery: batteryNames[(flags >> 3) & 3], charging: (flags & 32) !== 0, usb_connected: (flags & 64) !== 0,
      },
      battery_voltage_raw: b[2],
      battery_voltage: { value: tidy(9 + b[2] * 0.05), unit: 'V' },
      motor_current_raw: current,
      motor_current: { value: current.map((c) => tidy(c * 0.015)), unit: 'A' },
      temperature_c: b[9],
      temperature_c_physical: { value: b[9], unit: 'degC' },
      accel_raw: accel,
      accel: { value: accel.map((a) => tidy(a * 0.488)), unit: 'mg' },
      bootloader_response: { command: b[16], code: b[17], data: [b[18], b[19], b[20]] },
      charge_current_ma: b[21],
      charge_current_ma_physical: { value: b[21], unit: 'mA' },
      pu_motors: motors,
      pid_state: pid,
    },
  };
}

// Like the package's encode: a name that is no field (nor a key its decode adds) is an error, not ignored.
export function encodeSetMotorData(f) {
  for (const k in f) {
    if (k !== 'power' && k !== 'brake_flags' && k !== 'lut_disable_flags' && k !== 'brake_flags_bits' && k !== 'lut_disable_flags_bits'
      && k !== 'power_bits' && k !== 'power_text' && k !== 'power_physical' && k !== 'brake_flags_text' && k !== 'lut_disable_flags_text') {
      throw new HandError('unknown_field', 0);  // the package: a usage error naming the field
    }
  }
  const { power = [0, 0, 0, 0, 0, 0], brake_flags = 0, lut_disable_flags = 0 } = f;
  if (power.length !== 6) throw new HandError('bad_length', 1);
  const out = new Uint8Array(9);
  out[0] = 0x30;
  for (let i = 0; i < 6; ++i) {
    const p = power[i];
    if (!Number.isInteger(p) || p < -127 || p > 127) throw new HandError('value_out_of_range', 1 + i);
    out[1 + i] = p & 0xff;
  }
  if (!Number.isInteger(brake_flags) || brake_flags < 0 || brake_flags > 0x3f) throw new HandError('value_out_of_range', 7);
  if (!Number.isInteger(lut_disable_flags) || lut_disable_flags < 0 || lut_disable_flags > 0x3f)
    throw new HandError('value_out_of_range', 8);
  out[7] = brake_flags;
  out[8] = lut_disable_flags;
  return out;
}

export { ports };
