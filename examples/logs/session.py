#!/usr/bin/env python3
"""Writes a sample nRF Connect for Android log of a BuWizz3 session: the app
connects, turns notifications on, sets a 50 ms report period, then drives two
motors for several minutes while the brick reports its status at 20 Hz; the
battery runs down (and sags under load), the motor currents follow the
drive commands, the temperature rises.

    examples/logs/session.py [--minutes 5] [--lines N] [-o session.txt]

--lines: write exactly N status notifications instead (benchmarks, tests).
The frames are packed here by hand from the document's layout (68-byte 0x01
status), not by robowire. The values are made up but plausible; the file
is the sample session of docs/python.md.
"""
import argparse
import math
import random
import struct
import sys

APP = "50052901-74fb-4481-88b3-9919b1676e93"  # the BuWizz3 application characteristic


def dashes(b: bytes) -> str:
    return "-".join(f"{x:02X}" for x in b)


def status(flags: int, volts: float, amps: list, temp_c: int, accel_mg: list) -> bytes:
    """0x01 status: flags, battery (9 V + raw x 50 mV), 6 currents (raw x 15 mA), temperature,
    3 x int16 accelerometer words (x 0.488 mg), bootloader 5 bytes, charge current,
    4 x 8-byte PoweredUp motor blocks, PID state (3 x f32, 2 x i8)."""
    raw_v = max(0, min(255, round((volts - 9.0) / 0.05)))
    raw_i = [max(0, min(255, round(a / 0.015))) for a in amps]
    words = [max(-32768, min(32767, round(a / 0.488))) & ~0xF for a in accel_mg]  # 12-bit, left-aligned
    frame = struct.pack("<BBB6BB3h5sB", 0x01, flags, raw_v, *raw_i, temp_c, *words, bytes(5), 0)
    frame += bytes(32)  # no PoweredUp motors
    frame += struct.pack("<fffbb", 0.0, 0.0, 0.0, 0, 0)
    assert len(frame) == 68
    return frame


def stamp(ms: int) -> str:
    return f"{ms // 3600000 % 24:02d}:{ms // 60000 % 60:02d}:{ms // 1000 % 60:02d}.{ms % 1000:03d}"


def write(out, n: int) -> None:
    rng = random.Random(7)
    t = (14 * 3600 + 3 * 60 + 12) * 1000 + 118
    out.write("nRF Connect, 2026-03-14\nBuWizz (D4:37:A1:0C:55:2E)\n")
    for text in ["V {} Connecting to D4:37:A1:0C:55:2E...", "I {} Connected to D4:37:A1:0C:55:2E",
                 "I {} Services discovered",
                 "I {} Data written to descr. 00002902-0000-1000-8000-00805f9b34fb, value: (0x) 01-00"]:
        out.write(text.format(stamp(t)) + "\n")
        t += rng.randint(40, 600)
    out.write(f"I {stamp(t)} Data written to {APP}, value: (0x) 32-32\n")  # report every 50 ms
    t += 80
    # drive phases: (seconds, power of motor 1, power of motor 2 in percent), stretched to the log's length
    phases = [(20, 0, 0), (35, 60, 60), (25, 100, -40), (30, 30, 30), (15, 0, 0), (40, 80, 80),
              (20, -70, 70), (35, 100, 100), (25, 40, 0), (55, 65, 65)]
    total = sum(p[0] for p in phases)
    capacity_s = max(n / 20, 1)
    phase_end, k = 0.0, -1
    temp = 27.0
    for i in range(n):
        s = i / 20
        while s >= phase_end * capacity_s / total:
            k = (k + 1) % len(phases)
            phase_end += phases[k][0]
            p1, p2 = phases[k][1], phases[k][2]
            cmd = struct.pack("<B6bBB", 0x30, round(p1 * 1.27), round(p2 * 1.27), 0, 0, 0, 0, 0, 0)
            out.write(f"I {stamp(t)} Data written to {APP}, value: (0x) {dashes(cmd)}\n")
            t += 3
        p1, p2 = phases[k][1], phases[k][2]
        amps = [0.0] * 6
        for m, p in ((0, p1), (1, p2)):
            if p:
                load = 0.12 + 1.35 * (abs(p) / 100) ** 1.5
                amps[m] = max(0.0, load * (1 + 0.08 * math.sin(s * 2.1 + m)) + rng.gauss(0, 0.03))
        soc = 1 - s / capacity_s  # state of charge over the session
        open_circuit = 11.3 + 1.2 * soc - 0.25 * (1 - soc) ** 3
        volts = open_circuit - 0.35 * sum(amps) + rng.gauss(0, 0.01)
        temp += (27 + 9 * sum(amps) - temp) / 2400
        accel = [rng.gauss(0, 40) + 200 * (p1 - p2) / 100, rng.gauss(0, 40), 1000 + rng.gauss(0, 30)]
        flags = (3 if soc > 0.6 else 2 if soc > 0.25 else 1) << 3
        frame = status(flags, volts, amps, round(temp), accel)
        out.write(f"I {stamp(t)} Notification received from {APP}, value: (0x) {dashes(frame)}\n")
        t += 50
    out.write(f"I {stamp(t)} Disconnected\n")


def main() -> int:
    a = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    a.add_argument("--minutes", type=float, default=5.0)
    a.add_argument("--lines", type=int, help="status notifications (default: 20 a second for --minutes)")
    a.add_argument("-o", "--output", default="-")
    args = a.parse_args()
    n = args.lines if args.lines is not None else round(args.minutes * 60 * 20)
    if args.output == "-":
        write(sys.stdout, n)
    else:
        with open(args.output, "w") as fh:
            write(fh, n)
    return 0


if __name__ == "__main__":
    sys.exit(main())
