"""The examples in examples/python: the BuWizz3 example against a fake bleak
client, the OSP monitor over a socat pty pair, mypy --strict on both."""
import json
import os
import shutil
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from vectors import STATUS_54

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parent.parent / "examples" / "python"
APPLICATION_UUID = "50052901-74fb-4481-88b3-9919b1676e93"  # decisions.md: 0x2901 in the service UUID


def run_example(name, *args, env=None, timeout=60):
    return subprocess.run([sys.executable, str(EXAMPLES / name), *args], capture_output=True, text=True,
                          timeout=timeout, env={**os.environ, **(env or {})})


def test_buwizz3_example_with_fake_bleak(tmp_path):
    log = tmp_path / "log"
    notify = ",".join([
        "99",                   # no such notification: reported, ignored
        "23" + "00" * 24,       # accel_calibration: not a status, ignored
        STATUS_54.hex(),        # battery raw 80: 9 V + 80 x 0.05 V = 13 V; flags 0x73: battery medium
    ])
    p = run_example("buwizz3_drive.py", "AA:BB:CC:DD:EE:FF", "--seconds", "0", "--power", "50",
                    env={"PYTHONPATH": os.pathsep.join([str(HERE / "fake_bleak"), os.environ.get("PYTHONPATH", "")]),
                         "FAKE_BLEAK_LOG": str(log), "FAKE_BLEAK_NOTIFY": notify})
    assert p.returncode == 0, p.stderr
    assert p.stdout == "battery 13.00 V (13000 mV, medium)\n"
    assert "notification not understood: unknown key 0x99 at byte 0" in p.stderr
    entries = [json.loads(line) for line in log.read_text().splitlines()]
    assert entries == [
        ["connect", "AA:BB:CC:DD:EE:FF"],
        ["start_notify", APPLICATION_UUID],
        ["write", APPLICATION_UUID, "3232", True],                    # 0x32 period 50 ms
        ["write", APPLICATION_UUID, "3040c0000000000000", False],     # 50 % = 64 of 127, port 2 backwards
        ["write", APPLICATION_UUID, "30" + "00" * 8, True],           # stop
        ["stop_notify", APPLICATION_UUID],
        ["disconnect"],
    ]


def test_buwizz3_example_without_bleak():
    p = run_example("buwizz3_drive.py", "AA:BB:CC:DD:EE:FF", "--seconds", "0")
    if p.returncode == 0:
        pytest.skip("bleak is installed")
    assert p.returncode == 2 and "needs bleak" in p.stderr


# OBP-1 battery: request -> answer, worked out by hand from the OSP document
ANSWERS = {
    bytes.fromhex("FF AA 02 02 00 00 00 00 55 77"): bytes.fromhex("FF AA 02 12 D2 04 00 00 55 77"),  # 1234 cV = 12.34 V
    bytes.fromhex("FF AA 02 03 00 00 00 00 55 77"): bytes.fromhex("FF AA 02 13 24 FA 00 00 55 77"),  # -1500 mA
    bytes.fromhex("FF AA 02 01 00 00 00 00 55 77"): bytes.fromhex("FF AA 02 11 FF FF 00 00 55 77"),  # 65535 = 100 %
    bytes.fromhex("FF AA 02 04 00 00 00 00 55 77"): bytes.fromhex("FF AA 02 14 03 05 00 00 55 77"),  # charging, flags 5
}


def fake_battery(path, stop):
    import serial
    with serial.Serial(str(path), 115200, timeout=0.05) as port:
        pending = b""
        while not stop.is_set():
            pending += port.read(64)
            while len(pending) >= 10:
                request, pending = pending[:10], pending[10:]
                port.write(b"\x00" + ANSWERS.get(request, b""))  # a noise byte before each answer


def test_osp_monitor_over_pty(tmp_path):
    if not shutil.which("socat"):
        pytest.skip("socat is not installed")
    pytest.importorskip("serial")
    a, b = tmp_path / "a", tmp_path / "b"
    socat = subprocess.Popen(["socat", f"pty,raw,echo=0,link={a}", f"pty,raw,echo=0,link={b}"])
    stop = threading.Event()
    device = threading.Thread(target=fake_battery, args=(b, stop), daemon=True)
    try:
        for _ in range(400):  # socat makes the two links
            if a.exists() and b.exists():
                break
            time.sleep(0.05)
        assert a.exists() and b.exists(), "socat made no pty pair"
        device.start()
        p = run_example("osp_battery_monitor.py", str(a), "--count", "4", "--interval", "2", timeout=30)
        assert p.returncode == 0, p.stderr
        assert p.stdout.splitlines() == [
            "voltage 12.34 V",
            "current -1.500 A",
            "state of charge 100.0 %",
            "status charging (low_voltage, overheat)",
        ]
        assert "frames 4, skipped bytes 4" in p.stderr
    finally:
        stop.set()
        if device.is_alive():
            device.join(timeout=10)
        socat.terminate()
        socat.wait(timeout=10)


def mypy(*args, cwd=None):
    pytest.importorskip("mypy")
    return subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", str(HERE.parent / "build" / "mypy-cache"), *args],
                          capture_output=True, text=True, cwd=cwd, timeout=300)


def test_examples_pass_mypy_strict():
    p = mypy("--config-file", str(EXAMPLES / "mypy.ini"), str(EXAMPLES / "buwizz3_drive.py"), str(EXAMPLES / "osp_battery_monitor.py"))
    assert p.returncode == 0, p.stdout + p.stderr


def test_stubs_catch_wrong_names(tmp_path):
    script = tmp_path / "wrong.py"
    script.write_text(
        "from robowire import navbot, osp\n"
        "navbot.encode('maneuver', pich=5)\n"          # misspelled field
        "osp.encode('request_voltag')\n"               # misspelled message
        "navbot.encode('maneuver', switch_a='jump')\n"  # not an enum name
        "navbot.encode('maneuver', pitch=-10, switch_a='start')\n")  # right
    p = mypy("--strict", str(script))
    errors = [line for line in p.stdout.splitlines() if ": error:" in line]
    assert [e.split(":")[1] for e in errors] == ["2", "3", "4"], p.stdout
