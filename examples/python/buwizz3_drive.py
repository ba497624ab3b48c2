#!/usr/bin/env python3
"""Drive a BuWizz3 over Bluetooth LE with bleak (pip install bleak).

Connects, enables notifications, sets the status period to 50 ms, drives
ports 1 and 2 in opposite directions for a few seconds, prints the battery
from the status reports, then stops the motors.

    python3 buwizz3_drive.py AA:BB:CC:DD:EE:FF [--seconds 3] [--power 50]
"""
from __future__ import annotations

import argparse
import asyncio
import sys
from typing import Any

import robowire
from robowire import buwizz3


def battery_line(status: dict[str, Any]) -> str:
    fields = status["fields"]
    volts = fields["battery_voltage"]["value"]
    millivolts = buwizz3.battery_millivolts(fields["battery_voltage_raw"])
    level = fields["flags_bits"]["battery"]
    return f"battery {volts:.2f} V ({millivolts} mV, {level})"


async def drive(address: str, seconds: float, power_percent: int) -> int:
    try:
        from bleak import BleakClient  # imported here: the rest of the example needs no BLE stack
    except ImportError:
        print("this example needs bleak: pip install bleak", file=sys.stderr)
        return 2

    statuses: asyncio.Queue[dict[str, Any]] = asyncio.Queue()

    def on_notification(_characteristic: Any, data: bytearray) -> None:
        try:
            message = buwizz3.decode(bytes(data), direction="notification")
        except robowire.DecodeError as e:
            print(f"notification not understood: {e}", file=sys.stderr)
            return
        if message["message"] == "status":
            statuses.put_nowait(message)

    # power is -127..127 on the wire: 100 % is 127
    raw = round(power_percent * 127 / 100)
    channel = buwizz3.application_uuid
    async with BleakClient(address) as client:
        await client.start_notify(channel, on_notification)
        await client.write_gatt_char(channel, buwizz3.encode("set_data_period", period_ms=50), response=True)
        await client.write_gatt_char(channel, buwizz3.encode("set_motor_data", power=[raw, -raw, 0, 0, 0, 0]), response=False)
        try:
            status = await asyncio.wait_for(statuses.get(), timeout=max(seconds, 1.0))
            print(battery_line(status))
        except asyncio.TimeoutError:
            print("no status report received", file=sys.stderr)
        await asyncio.sleep(seconds)
        await client.write_gatt_char(channel, buwizz3.encode("set_motor_data", power=[0] * 6), response=True)
        await client.stop_notify(channel)
    return 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else None)
    parser.add_argument("address", help="the BuWizz3's Bluetooth address (or its ID on macOS)")
    parser.add_argument("--seconds", type=float, default=3.0, help="how long to drive (default 3)")
    parser.add_argument("--power", type=int, default=50, help="motor power in %% (default 50)")
    args = parser.parse_args()
    if not -100 <= args.power <= 100:
        parser.error("--power: -100..100")
    return asyncio.run(drive(args.address, args.seconds, args.power))


if __name__ == "__main__":
    sys.exit(main())
