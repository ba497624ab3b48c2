#!/usr/bin/env python3
"""Benchmark of the robowire package: decode of the 68-byte BuWizz3 status
to a dict and encode of set_motor_data (0x30) from keywords, against a
careful pure-Python `struct` codec of the same two messages with the same
checks and the same dict, in the same run; and the command-line tool
through subprocess when it is given (--cli PATH or ROBOWIRE_CLI).

    python3 python/bench.py [--cli build/tools/robowire] [--seconds 0.5]

Prints microseconds per call (best of 5 runs) and the ratio to pure Python.
"""
from __future__ import annotations

import argparse
import os
import struct
import subprocess
import sys
import timeit
from typing import Any

# this directory holds robowire's sources (without the compiled part): import the installed package
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != os.path.dirname(os.path.abspath(__file__))]
from robowire import buwizz3  # noqa: E402

STATUS_68 = bytes.fromhex(
    "01 73 50 0A 14 1E 28 32 C8 23 F0 FF F0 7F 00 08 0B 0C 0D 0E 0F 7D 30 EC 4C FF 60 79 FE FF 31 64 B3 00 40 E2 01 00 "
    "4B FF 01 00 01 00 00 00 4C 7F FF FF FF FF FF 7F 00 00 00 3F 00 00 20 C0 00 00 4C 41 F9 2A")

# ---------------------------------------------------------------- pure Python, by hand
_HEAD = struct.Struct("<BB6BB3h5BB")            # flags .. charge current (bytes 1..21)
_MOTOR = struct.Struct("<Bbhi")                  # one PU motor (8 bytes)
_PID = struct.Struct("<fffbb")                   # PID block (14 bytes)
_BATTERY = ("empty", "low", "medium", "full")


def _tidy(v: float) -> float:
    return float(f"{v:.15g}")


def py_decode_status(data: bytes) -> dict[str, Any]:
    n = len(data)
    if n == 0 or data[0] != 0x01:
        raise ValueError("status: wrong command byte for this message at byte 0")
    if n < 54:
        raise ValueError(f"status: input too short (54 or 68..129 bytes) at byte {n}")
    if n > 129:
        raise ValueError("status: input too long (54 or 68..129 bytes) at byte 129")
    if 54 < n < 68:
        raise ValueError("status.pid_state: length matches no form of the message (54 or 68..129 bytes) at byte 54")
    h = _HEAD.unpack_from(data, 1)
    flags, battery = h[0], h[1]
    currents = list(h[2:8])
    accel = list(h[9:12])
    motors = []
    for i in range(4):
        t, velocity, absolute, position = _MOTOR.unpack_from(data, 22 + 8 * i)
        motors.append({"type": t, "velocity": velocity, "absolute_position": absolute,
                       "absolute_position_physical": {"value": float(absolute), "unit": "deg"},
                       "position": position, "position_physical": {"value": float(position), "unit": "deg"}})
    pid = None
    if n >= 68:
        pv, err, out, integrator, motor_output = _PID.unpack_from(data, 54)
        pid = {"process_value": pv, "error": err, "output": out, "integrator": integrator, "motor_output": motor_output}
    fields = {
        "flags": flags,
        "flags_bits": {"error": bool(flags & 1), "motion_wakeup": bool(flags & 2), "long_range_phy": bool(flags & 4),
                       "battery": _BATTERY[(flags >> 3) & 3], "charging": bool(flags & 32), "usb_connected": bool(flags & 64)},
        "battery_voltage_raw": battery,
        "battery_voltage": {"value": _tidy(battery * 0.05 + 9.0), "unit": "V"},
        "motor_current_raw": currents,
        "motor_current": {"value": [_tidy(c * 0.015) for c in currents], "unit": "A"},
        "temperature_c": h[8],
        "temperature_c_physical": {"value": float(h[8]), "unit": "degC"},
        "accel_raw": accel,
        "accel": {"value": [_tidy(a * 0.488) for a in accel], "unit": "mg"},
        "bootloader_response": {"command": h[12], "code": h[13], "data": list(h[14:17])},
        "charge_current_ma": h[17],
        "charge_current_ma_physical": {"value": float(h[17]), "unit": "mA"},
        "pu_motors": motors,
        "pid_state": pid,
    }
    return {"type": "message", "protocol": "buwizz3", "message": "status", "fields": fields}


_MOTOR_DATA = struct.Struct("<B6bBB")
_MOTOR_DATA_FIELDS = {"power", "brake_flags", "lut_disable_flags"}


def py_encode_set_motor_data(**fields: Any) -> bytes:
    for name in fields:
        if name not in _MOTOR_DATA_FIELDS:
            raise KeyError(f"unknown field set_motor_data.{name}")
    power = fields.get("power", [0] * 6)
    brake = fields.get("brake_flags", 0)
    lut = fields.get("lut_disable_flags", 0)
    if not isinstance(power, (list, tuple)):
        raise TypeError("set_motor_data.power: expected a list of 6 values")
    if len(power) != 6:
        raise ValueError(f"set_motor_data.power: {len(power)} values given, 6 expected")
    for i, p in enumerate(power):
        if not isinstance(p, int):
            raise TypeError(f"set_motor_data.power[{i}]: expected an int")
        if not -127 <= p <= 127:
            raise ValueError(f"set_motor_data.power: value out of range (valid -127..127 raw) at byte {1 + i}")
    for name, v, offset in (("brake_flags", brake, 7), ("lut_disable_flags", lut, 8)):
        if not isinstance(v, int):
            raise TypeError(f"set_motor_data.{name}: expected an int")
        if not 0 <= v <= 63:
            raise ValueError(f"set_motor_data.{name}: value out of range (valid 0..63) at byte {offset}")
    return _MOTOR_DATA.pack(0x30, *power, brake, lut)


# ---------------------------------------------------------------- measuring
def per_call_us(fn: Any, seconds: float) -> float:
    timer = timeit.Timer(fn)
    number, _ = timer.autorange()
    number = max(1, int(number * seconds / 0.2))
    return min(timer.repeat(repeat=5, number=number)) / number * 1e6


def main() -> int:
    parser = argparse.ArgumentParser(description="robowire Python benchmark")
    parser.add_argument("--cli", default=os.environ.get("ROBOWIRE_CLI"), help="the robowire tool, for the subprocess row")
    parser.add_argument("--seconds", type=float, default=0.5, help="time per measurement (default 0.5)")
    args = parser.parse_args()

    # the two implementations agree before they are timed
    assert buwizz3.decode(STATUS_68) == py_decode_status(STATUS_68)
    kwargs = {"power": [64, -64, 0, 0, 0, 0], "brake_flags": 3}
    assert buwizz3.encode("set_motor_data", **kwargs) == py_encode_set_motor_data(**kwargs)

    rows = []
    py_dec = per_call_us(lambda: py_decode_status(STATUS_68), args.seconds)
    rw_dec = per_call_us(lambda: buwizz3.decode(STATUS_68), args.seconds)
    py_enc = per_call_us(lambda: py_encode_set_motor_data(power=[64, -64, 0, 0, 0, 0], brake_flags=3), args.seconds)
    rw_enc = per_call_us(lambda: buwizz3.encode("set_motor_data", power=[64, -64, 0, 0, 0, 0], brake_flags=3), args.seconds)
    rows.append(("decode status (68 B) -> dict", rw_dec, py_dec))
    rows.append(("encode set_motor_data from keywords", rw_enc, py_enc))

    print(f"{'case':40} {'robowire us':>12} {'pure Python us':>15} {'ratio':>7}")
    for name, rw, py in rows:
        print(f"{name:40} {rw:12.2f} {py:15.2f} {rw / py:7.2f}")
    if args.cli:
        cli = lambda: subprocess.run([args.cli, "decode", "buwizz3", STATUS_68.hex(), "--json"],  # noqa: E731
                                     capture_output=True, check=True)
        t = timeit.Timer(cli)
        cli_us = min(t.repeat(repeat=3, number=20)) / 20 * 1e6
        print(f"{'decode status via the CLI (subprocess)':40} {cli_us:12.0f} {'':>15} {cli_us / rw_dec:6.0f}x robowire")
    return 0


if __name__ == "__main__":
    sys.exit(main())
