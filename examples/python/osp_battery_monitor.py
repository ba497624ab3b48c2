#!/usr/bin/env python3
"""Watch an OSP OBP-1 battery on a serial port with pyserial (Debian: python3-serial).

Asks the battery for its voltage, current, state of charge and status once
a second and prints the answers in volts, amps and percent.

    python3 osp_battery_monitor.py /dev/ttyUSB0 [--baud 115200] [--published-firmware] [--count N]
"""
from __future__ import annotations

import argparse
import sys
import time
from typing import Any

import serial  # pyserial

from robowire import osp

# the four questions, encoded once
REQUESTS = [osp.encode("request_voltage"), osp.encode("request_current"), osp.encode("request_soc"), osp.encode("request_status")]


def describe(message: dict[str, Any], scale: osp.scale) -> str:
    fields = message["fields"]
    name = message["message"]
    if name == "voltage":
        return f"voltage {osp.volts(fields['centivolts'], scale):.2f} V"
    if name == "current":
        return f"current {osp.amps(fields['milliamps'], scale):.3f} A"
    if name == "soc":
        return f"state of charge {osp.soc_percent(fields['soc_raw'], scale):.1f} %"
    if name == "status":
        flags = [bit for bit, on in fields["flags_bits"].items() if on]
        return f"status {fields['state']}" + (f" ({', '.join(flags)})" if flags else "")
    return f"{name} {fields}"


def monitor(port: serial.Serial, scale: osp.scale, count: int, interval: float) -> int:
    scanner = osp.Scanner()
    answers = 0
    while count <= 0 or answers < count:
        for request in REQUESTS:
            port.write(request)
        deadline = time.monotonic() + interval
        while time.monotonic() < deadline and (count <= 0 or answers < count):
            for item in scanner.feed(port.read(port.in_waiting or 1)):
                if item["type"] == "error":
                    print(f"bad frame {item['bytes']}: {item['error']}", file=sys.stderr)
                    continue
                print(describe(item, scale), flush=True)
                answers += 1
    print(f"frames {scanner.frames}, skipped bytes {scanner.skipped_bytes}", file=sys.stderr)
    return 0


def main() -> int:
    parser = argparse.ArgumentParser(description="Watch an OSP OBP-1 battery on a serial port.")
    parser.add_argument("device", help="serial device, e.g. /dev/ttyUSB0")
    parser.add_argument("--baud", type=int, default=115200)
    parser.add_argument("--published-firmware", action="store_true",
                        help="read values as the published OBP-1 firmware sends them (mV, SOC 10000 = 100 %%)")
    parser.add_argument("--count", type=int, default=0, help="stop after N answers (default: run until Ctrl-C)")
    parser.add_argument("--interval", type=float, default=1.0, help="seconds between requests (default 1)")
    args = parser.parse_args()
    scale = osp.scale.published_firmware if args.published_firmware else osp.scale.document
    with serial.Serial(args.device, args.baud, timeout=0.1) as port:
        try:
            return monitor(port, scale, args.count, args.interval)
        except KeyboardInterrupt:
            return 0


if __name__ == "__main__":
    sys.exit(main())
