"""Golden vectors: frames and field values worked out by hand from the
protocol documents (the same vectors as tests/cli/test_cli.py and the C++
unit tests), with the physical values computed by hand from the documents'
units. Nothing here was produced by running robowire."""

# (protocol, direction, hex frame, message, raw field values that must match, encode keywords)
CASES = [
    ("buwizz3", "command", "20 4D 79 42 72 69 63 6B 00 00 00 00 00", "set_device_name", {"name": "MyBrick"}, {"name": "MyBrick"}),
    ("buwizz3", "command", "21 01 2C 01 00 00 10 0E 00 00", "set_motion_wakeup",
     {"enabled": True, "idle_timeout_s": 300, "shallow_sleep_timeout_s": 3600},
     {"enabled": True, "idle_timeout_s": 300, "shallow_sleep_timeout_s": 3600}),
    ("buwizz3", "command", "22 00 00 80 3F 00 00 80 BF 00 00 00 3F 00 00 00 00 00 00 20 C0 00 00 00 00",
     "set_accel_calibration", {"factors": [1, -1, 0.5, 0, -2.5, 0]}, {"factors": [1, -1, 0.5, 0, -2.5, 0]}),
    ("buwizz3", "command", "23", "read_accel_calibration", {}, {}),
    ("buwizz3", "command", "30 7F 81 00 40 C0 01 21 3F", "set_motor_data",
     {"power": [127, -127, 0, 64, -64, 1], "brake_flags": 33, "lut_disable_flags": 63},
     {"power": [127, -127, 0, 64, -64, 1], "brake_flags": 0x21, "lut_disable_flags": 63}),
    ("buwizz3", "command", "31 E8 03 00 00 18 FC FF FF 00 00 00 00 78 56 34 12 81 64 03 00", "set_motor_data_extended",
     {"reference": [1000, -1000, 0, 0x12345678], "power": [-127, 100], "brake_flags": 3},
     {"reference": [1000, -1000, 0, 0x12345678], "power": [-127, 100], "brake_flags": 3}),
    ("buwizz3", "command", "32 32", "set_data_period", {"period_ms": 50}, {"period_ms": 50}),
    ("buwizz3", "command", "33 01 02 03 04 05 06 00 0D 64 FF 07 08", "set_ramp_rates",
     {"ramp_up": [1, 2, 3, 4, 5, 6], "ramp_down": [0, 13, 100, 255, 7, 8]},
     {"ramp_up": [1, 2, 3, 4, 5, 6], "ramp_down": [0, 13, 100, 255, 7, 8]}),
    ("buwizz3", "command", "34 0B", "set_motor_timeout", {"mode": 11}, {"mode": 11}),
    ("buwizz3", "command", "35 05", "activate_watchdog", {"timeout_s": 5}, {"timeout_s": 5}),
    ("buwizz3", "command", "36 FF 00 00 00 FF 00 00 00 FF 10 20 30 1F F0 08 55", "set_led_status",
     {"colors": [{"r": 255, "g": 0, "b": 0}, {"r": 0, "g": 255, "b": 0}, {"r": 0, "g": 0, "b": 255}, {"r": 16, "g": 32, "b": 48}]},
     {"colors": [{"r": 255}, {"g": 255}, {"b": 255}, {"r": 16, "g": 32, "b": 48}],
      "blink": [{"frequency_hz": 1, "duty": 15}, {"frequency_hz": 15, "duty": 0}, {"duty": 8}, {"frequency_hz": 5, "duty": 5}]}),
    ("buwizz3", "command", "36", "set_led_status", {"colors": None, "blink": None}, {}),
    ("buwizz3", "command", "37 0B", "set_accel_lpf", {"setting": "hz_6_25"}, {"setting": "hz_6_25"}),
    ("buwizz3", "command", "38 32 32 32 32 64 64", "set_current_limits", {"limit_raw": [50, 50, 50, 50, 100, 100]},
     {"limit_raw": [50, 50, 50, 50, 100, 100]}),
    ("buwizz3", "command", "40 10 02 00 C2 01 00", "set_uart_baudrate", {"channel": 2, "baudrate": 115200},
     {"channel": 2, "baudrate": 115200}),
    ("buwizz3", "command", "50 10 14 15 00", "set_pu_port_function",
     {"function": ["pu_simple_pwm", "pu_speed_servo", "pu_position_servo", "generic_pwm"]},
     {"function": ["pu_simple_pwm", 0x14, "pu_position_servo", "generic_pwm"]}),
    ("buwizz3", "command", "51 03", "enable_pid_reporting", {"port": 3}, {"port": 3}),
    ("buwizz3", "command", "52 FF FF FF FF 00 00 00 00 5A 00 00 00 FF FF FF 7F", "set_servo_reference",
     {"reference": [-1, 0, 90, 2147483647]}, {"reference": [-1, 0, 90, 2147483647]}),
    ("buwizz3", "command",
     "53 00 00 00 00 00 00 00 00 3F 00 00 00 00 00 00 80 3F 00 00 00 00 00 00 40 C0 00 00 A0 41 00 00 00 00 64 02 02 15",
     "set_pid_parameters", {"port": 0, "d_lp": 0.5, "kp": 1, "kd": -3, "lim_i": 20, "lim_out": 100, "mode": "pu_position_servo"},
     {"port": 0, "d_lp": 0.5, "kp": 1, "kd": -3.0, "lim_i": 20, "lim_out": 100, "deadband_out": 2, "deadband_out_boost": 2,
      "mode": "pu_position_servo"}),
    ("buwizz3", "command", "A1", "activate_shelf_mode", {}, {}),
    ("buwizz3", "command", "AC", "check_charger_settings", {}, {}),
    ("buwizz3", "notification", "23 00 00 80 3F 00 00 80 BF 00 00 00 3F 00 00 00 00 00 00 20 C0 00 00 00 00",
     "accel_calibration", {"factors": [1, -1, 0.5, 0, -2.5, 0]}, {"factors": [1, -1, 0.5, 0, -2.5, 0]}),
    ("buwizz3", "notification", "AC 01 02 03", "charger_settings", {"data": "01 02 03"}, {"data": b"\x01\x02\x03"}),
    ("navbot", None, "55 AA 10 00 00 9C 64 37 FF 02 01 01 02 FB 05 00 00 00 00 00", "maneuver",
     {"roll": -100, "height": 100, "pitch": 55, "yaw": -1, "switch_a": "start_touch_panel", "switch_b": "mark",
      "switch_c": "lock", "switch_d": "ball_poise", "ball_x": -5, "ball_y": 5},
     {"roll": -100, "height": 100, "pitch": 55, "yaw": -1, "switch_a": "start_touch_panel", "switch_b": 1,
      "switch_c": "lock", "switch_d": "ball_poise", "ball_x": -5, "ball_y": 5}),
    ("navbot", None, "55 AA 02 00 00 7B 22 61 22 3A 31 7D 00 00 00 00 00 00 00 00", "frame",
     {"command": 2, "remaining": 0, "payload_text": '{"a":1}'},
     {"command": 2, "remaining": 0, "payload": [0x7B, 0x22, 0x61, 0x22, 0x3A, 0x31, 0x7D, 0, 0, 0, 0, 0, 0, 0, 0]}),
    ("osp", None, "FF AA 00 01 00 00 00 00 55 77", "request_device_type", {}, {}),
    ("osp", None, "FF AA 00 11 02 00 00 00 55 77", "device_type", {"type": "obp1"}, {"type": "obp1"}),
    ("osp", None, "FF AA 01 02 03 34 12 00 55 77", "set_angle", {"joint": 3, "angle": 0x1234}, {"joint": 3, "angle": 0x1234}),
    ("osp", None, "FF AA 02 01 00 00 00 00 55 77", "request_soc", {}, {}),
    ("osp", None, "FF AA 02 02 00 00 00 00 55 77", "request_voltage", {}, {}),
    ("osp", None, "FF AA 02 03 00 00 00 00 55 77", "request_current", {}, {}),
    ("osp", None, "FF AA 02 04 00 00 00 00 55 77", "request_status", {}, {}),
    ("osp", None, "FF AA 02 11 FF FF 00 00 55 77", "soc", {"soc_raw": 65535}, {"soc_raw": 65535}),
    ("osp", None, "FF AA 02 12 D2 04 00 00 55 77", "voltage", {"centivolts": 1234}, {"centivolts": 1234}),
    ("osp", None, "FF AA 02 13 24 FA 00 00 55 77", "current", {"milliamps": -1500}, {"milliamps": -1500}),
    ("osp", None, "FF AA 02 14 03 05 00 00 55 77", "status", {"state": "charging", "flags": 5}, {"state": "charging", "flags": 5}),
]

# BuWizz3 status, 68 bytes (with the PID block): flags 0x73, battery raw 80,
# motor currents 10..200, 35 degC, accel words -16 / 0x7FF0 / 0x0800,
# bootloader response 0B 0C 0D 0E 0F, charge 125 mA, four PU motors, PID state.
STATUS_68 = bytes.fromhex(
    "01 73 50 0A 14 1E 28 32 C8 23 F0 FF F0 7F 00 08 0B 0C 0D 0E 0F 7D 30 EC 4C FF 60 79 FE FF 31 64 B3 00 40 E2 01 00 "
    "4B FF 01 00 01 00 00 00 4C 7F FF FF FF FF FF 7F 00 00 00 3F 00 00 20 C0 00 00 4C 41 F9 2A")
STATUS_54 = STATUS_68[:54]

# The whole decoded status, fields worked out by hand:
#  battery 9 V + 80 x 0.05 V = 13 V; currents raw x 0.015 A; accel word x 0.488 mg
#  (-16 -> -7.808, 32752 -> 15982.976, 2048 -> 999.424); flags 0x73 = 0111 0011:
#  error, motion_wakeup, battery bits 3-4 = 10 (medium), charging, usb_connected.
STATUS_68_FIELDS = {
    "flags": 0x73,
    "flags_bits": {"error": True, "motion_wakeup": True, "long_range_phy": False, "battery": "medium",
                   "charging": True, "usb_connected": True},
    "battery_voltage_raw": 80,
    "battery_voltage": {"value": 13.0, "unit": "V"},
    "motor_current_raw": [10, 20, 30, 40, 50, 200],
    "motor_current": {"value": [0.15, 0.3, 0.45, 0.6, 0.75, 3.0], "unit": "A"},
    "temperature_c": 35,
    "temperature_c_physical": {"value": 35.0, "unit": "degC"},
    "accel_raw": [-16, 32752, 2048],
    "accel": {"value": [-7.808, 15982.976, 999.424], "unit": "mg"},
    "bootloader_response": {"command": 11, "code": 12, "data": [13, 14, 15]},
    "charge_current_ma": 125,
    "charge_current_ma_physical": {"value": 125.0, "unit": "mA"},
    "pu_motors": [
        {"type": 0x30, "velocity": -20, "absolute_position": -180, "absolute_position_physical": {"value": -180.0, "unit": "deg"},
         "position": -100000, "position_physical": {"value": -100000.0, "unit": "deg"}},
        {"type": 0x31, "velocity": 100, "absolute_position": 179, "absolute_position_physical": {"value": 179.0, "unit": "deg"},
         "position": 123456, "position_physical": {"value": 123456.0, "unit": "deg"}},
        {"type": 0x4B, "velocity": -1, "absolute_position": 1, "absolute_position_physical": {"value": 1.0, "unit": "deg"},
         "position": 1, "position_physical": {"value": 1.0, "unit": "deg"}},
        {"type": 0x4C, "velocity": 127, "absolute_position": -1, "absolute_position_physical": {"value": -1.0, "unit": "deg"},
         "position": 2147483647, "position_physical": {"value": 2147483647.0, "unit": "deg"}},
    ],
    "pid_state": {"process_value": 0.5, "error": -2.5, "output": 12.75, "integrator": -7, "motor_output": 42},
}
