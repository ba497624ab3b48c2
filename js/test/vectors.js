// Golden vectors worked out by hand from the BuWizz3 API document
// (/specs: buwizz3-api-v3.22), the same frames as the CLI and Python tests
// (python/tests/vectors.py). Nothing here was produced by running robowire.

// [direction, hex frame, message, raw field values that must match, encode fields]
export const cases = [
  ['command', '20 4D 79 42 72 69 63 6B 00 00 00 00 00', 'set_device_name', { name: 'MyBrick' }, { name: 'MyBrick' }],
  ['command', '21 01 2C 01 00 00 10 0E 00 00', 'set_motion_wakeup',
    { enabled: true, idle_timeout_s: 300, shallow_sleep_timeout_s: 3600 },
    { enabled: true, idle_timeout_s: 300, shallow_sleep_timeout_s: 3600 }],
  ['command', '22 00 00 80 3F 00 00 80 BF 00 00 00 3F 00 00 00 00 00 00 20 C0 00 00 00 00', 'set_accel_calibration',
    { factors: [1, -1, 0.5, 0, -2.5, 0] }, { factors: [1, -1, 0.5, 0, -2.5, 0] }],
  ['command', '23', 'read_accel_calibration', {}, {}],
  ['command', '30 7F 81 00 40 C0 01 21 3F', 'set_motor_data',
    { power: [127, -127, 0, 64, -64, 1], brake_flags: 33, lut_disable_flags: 63 },
    { power: [127, -127, 0, 64, -64, 1], brake_flags: 0x21, lut_disable_flags: 63 }],
  ['command', '31 E8 03 00 00 18 FC FF FF 00 00 00 00 78 56 34 12 81 64 03 00', 'set_motor_data_extended',
    { reference: [1000, -1000, 0, 0x12345678], power: [-127, 100], brake_flags: 3 },
    { reference: [1000, -1000, 0, 0x12345678], power: [-127, 100], brake_flags: 3 }],
  ['command', '32 32', 'set_data_period', { period_ms: 50 }, { period_ms: 50 }],
  ['command', '33 01 02 03 04 05 06 00 0D 64 FF 07 08', 'set_ramp_rates',
    { ramp_up: [1, 2, 3, 4, 5, 6], ramp_down: [0, 13, 100, 255, 7, 8] },
    { ramp_up: [1, 2, 3, 4, 5, 6], ramp_down: [0, 13, 100, 255, 7, 8] }],
  ['command', '34 0B', 'set_motor_timeout', { mode: 11 }, { mode: 11 }],
  ['command', '35 05', 'activate_watchdog', { timeout_s: 5 }, { timeout_s: 5 }],
  ['command', '36 FF 00 00 00 FF 00 00 00 FF 10 20 30 1F F0 08 55', 'set_led_status',
    { colors: [{ r: 255, g: 0, b: 0 }, { r: 0, g: 255, b: 0 }, { r: 0, g: 0, b: 255 }, { r: 16, g: 32, b: 48 }] },
    { colors: [{ r: 255 }, { g: 255 }, { b: 255 }, { r: 16, g: 32, b: 48 }],
      blink: [{ frequency_hz: 1, duty: 15 }, { frequency_hz: 15, duty: 0 }, { duty: 8 }, { frequency_hz: 5, duty: 5 }] }],
  ['command', '36', 'set_led_status', { colors: null, blink: null }, {}],
  ['command', '37 0B', 'set_accel_lpf', { setting: 'hz_6_25' }, { setting: 'hz_6_25' }],
  ['command', '38 32 32 32 32 64 64', 'set_current_limits', { limit_raw: [50, 50, 50, 50, 100, 100] },
    { limit_raw: [50, 50, 50, 50, 100, 100] }],
  ['command', '40 10 02 00 C2 01 00', 'set_uart_baudrate', { channel: 2, baudrate: 115200 }, { channel: 2, baudrate: 115200 }],
  ['command', '50 10 14 15 00', 'set_pu_port_function',
    { function: ['pu_simple_pwm', 'pu_speed_servo', 'pu_position_servo', 'generic_pwm'] },
    { function: ['pu_simple_pwm', 0x14, 'pu_position_servo', 'generic_pwm'] }],
  ['command', '51 03', 'enable_pid_reporting', { port: 3 }, { port: 3 }],
  ['command', '52 FF FF FF FF 00 00 00 00 5A 00 00 00 FF FF FF 7F', 'set_servo_reference',
    { reference: [-1, 0, 90, 2147483647] }, { reference: [-1, 0, 90, 2147483647] }],
  ['command', '53 00 00 00 00 00 00 00 00 3F 00 00 00 00 00 00 80 3F 00 00 00 00 00 00 40 C0 00 00 A0 41 00 00 00 00 64 02 02 15',
    'set_pid_parameters', { port: 0, d_lp: 0.5, kp: 1, kd: -3, lim_i: 20, lim_out: 100, mode: 'pu_position_servo' },
    { port: 0, d_lp: 0.5, kp: 1, kd: -3.0, lim_i: 20, lim_out: 100, deadband_out: 2, deadband_out_boost: 2, mode: 'pu_position_servo' }],
  ['command', 'A1', 'activate_shelf_mode', {}, {}],
  ['command', 'AC', 'check_charger_settings', {}, {}],
  ['notification', '23 00 00 80 3F 00 00 80 BF 00 00 00 3F 00 00 00 00 00 00 20 C0 00 00 00 00', 'accel_calibration',
    { factors: [1, -1, 0.5, 0, -2.5, 0] }, { factors: [1, -1, 0.5, 0, -2.5, 0] }],
  ['notification', 'AC 01 02 03', 'charger_settings', { data: '01 02 03' }, { data: new Uint8Array([1, 2, 3]) }],
];

// BuWizz3 status, 68 bytes (with the PID block): flags 0x73, battery raw 80
// (9 V + 80 x 0.05 V = 13 V), motor currents 10..200 (x 0.015 A), 35 degC,
// accel words -16 / 0x7FF0 / 0x0800, bootloader response 0B 0C 0D 0E 0F,
// charge 125 mA, four PU motors, PID state.
export const status68 =
  '01 73 50 0A 14 1E 28 32 C8 23 F0 FF F0 7F 00 08 0B 0C 0D 0E 0F 7D 30 EC 4C FF 60 79 FE FF 31 64 B3 00 40 E2 01 00 ' +
  '4B FF 01 00 01 00 00 00 4C 7F FF FF FF FF FF 7F 00 00 00 3F 00 00 20 C0 00 00 4C 41 F9 2A';

export function bytes(hex) {
  return Uint8Array.from(hex.split(/\s+/).filter(Boolean), (b) => parseInt(b, 16));
}
