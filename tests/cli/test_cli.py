#!/usr/bin/env python3
"""Tests of the robowire command-line tool. Usage: test_cli.py PATH_TO_ROBOWIRE
Golden vectors are the unit tests' (worked out by hand from the documents).
Prints 'N passed, M failed' and exits 1 on any failure."""
import json, os, shutil, subprocess, sys, tempfile, time

TOOL = sys.argv[1]
passed = failed = 0

def run(*args, stdin=None):
    p = subprocess.run([TOOL, *args], input=stdin, capture_output=True, timeout=30)
    return p.returncode, p.stdout.decode(), p.stderr.decode()

def check(cond, what):
    global passed, failed
    if cond:
        passed += 1
    else:
        failed += 1
        print("FAIL:", what)

# (protocol, direction, hex, message, fields that must match in JSON, encode arguments)
CASES = [
    ("buwizz3", "command", "20 4D 79 42 72 69 63 6B 00 00 00 00 00", "set_device_name", {"name": "MyBrick"}, ["name=MyBrick"]),
    ("buwizz3", "command", "21 01 2C 01 00 00 10 0E 00 00", "set_motion_wakeup",
     {"enabled": True, "idle_timeout_s": 300, "shallow_sleep_timeout_s": 3600},
     ["enabled=true", "idle_timeout_s=300", "shallow_sleep_timeout_s=3600"]),
    ("buwizz3", "command", "22 00 00 80 3F 00 00 80 BF 00 00 00 3F 00 00 00 00 00 00 20 C0 00 00 00 00",
     "set_accel_calibration", {"factors": [1, -1, 0.5, 0, -2.5, 0]}, ["factors=1,-1,0.5,0,-2.5,0"]),
    ("buwizz3", "command", "23", "read_accel_calibration", {}, []),
    ("buwizz3", "command", "30 7F 81 00 40 C0 01 21 3F", "set_motor_data",
     {"power": [127, -127, 0, 64, -64, 1], "brake_flags": 33, "lut_disable_flags": 63},
     ["power=127,-127,0,64,-64,1", "brake_flags=0x21", "lut_disable_flags=63"]),
    ("buwizz3", "command", "31 E8 03 00 00 18 FC FF FF 00 00 00 00 78 56 34 12 81 64 03 00", "set_motor_data_extended",
     {"reference": [1000, -1000, 0, 0x12345678], "power": [-127, 100], "brake_flags": 3},
     ["reference=1000,-1000,0,0x12345678", "power=-127,100", "brake_flags=3"]),
    ("buwizz3", "command", "32 32", "set_data_period", {"period_ms": 50}, ["period_ms=50"]),
    ("buwizz3", "command", "33 01 02 03 04 05 06 00 0D 64 FF 07 08", "set_ramp_rates",
     {"ramp_up": [1, 2, 3, 4, 5, 6], "ramp_down": [0, 13, 100, 255, 7, 8]},
     ["ramp_up=1,2,3,4,5,6", "ramp_down=0,13,100,255,7,8"]),
    ("buwizz3", "command", "34 0B", "set_motor_timeout", {"mode": 11}, ["mode=11"]),
    ("buwizz3", "command", "35 05", "activate_watchdog", {"timeout_s": 5}, ["timeout_s=5"]),
    ("buwizz3", "command", "36 FF 00 00 00 FF 00 00 00 FF 10 20 30 1F F0 08 55", "set_led_status",
     {"colors": [{"r": 255, "g": 0, "b": 0}, {"r": 0, "g": 255, "b": 0}, {"r": 0, "g": 0, "b": 255}, {"r": 16, "g": 32, "b": 48}],
      "blink": [{"frequency_hz": 1, "duty": 15}, {"frequency_hz": 15, "duty": 0}, {"frequency_hz": 0, "duty": 8}, {"frequency_hz": 5, "duty": 5}]},
     ["colors=255,0,0,0,255,0,0,0,255,16,32,48", "blink=1,15,15,0,0,8,5,5"]),
    ("buwizz3", "command", "36", "set_led_status", {"colors": None, "blink": None}, []),
    ("buwizz3", "command", "37 0B", "set_accel_lpf", {"setting": "hz_6_25"}, ["setting=hz_6_25"]),
    ("buwizz3", "command", "38 32 32 32 32 64 64", "set_current_limits", {"limit_raw": [50, 50, 50, 50, 100, 100]},
     ["limit_raw=50,50,50,50,100,100"]),
    ("buwizz3", "command", "40 10 02 00 C2 01 00", "set_uart_baudrate", {"channel": 2, "baudrate": 115200},
     ["channel=2", "baudrate=115200"]),
    ("buwizz3", "command", "50 10 14 15 00", "set_pu_port_function",
     {"function": ["pu_simple_pwm", "pu_speed_servo", "pu_position_servo", "generic_pwm"]},
     ["function=pu_simple_pwm,pu_speed_servo,pu_position_servo,generic_pwm"]),
    ("buwizz3", "command", "51 03", "enable_pid_reporting", {"port": 3}, ["port=3"]),
    ("buwizz3", "command", "52 FF FF FF FF 00 00 00 00 5A 00 00 00 FF FF FF 7F", "set_servo_reference",
     {"reference": [-1, 0, 90, 2147483647]}, ["reference=-1,0,90,2147483647"]),
    ("buwizz3", "command",
     "53 00 00 00 00 00 00 00 00 3F 00 00 00 00 00 00 80 3F 00 00 00 00 00 00 40 C0 00 00 A0 41 00 00 00 00 64 02 02 15",
     "set_pid_parameters", {"port": 0, "d_lp": 0.5, "kp": 1, "kd": -3, "lim_i": 20, "lim_out": 100, "mode": "pu_position_servo"},
     ["port=0", "d_lp=0.5", "kp=1", "kd=-3", "lim_i=20", "lim_out=100", "deadband_out=2", "deadband_out_boost=2",
      "mode=pu_position_servo"]),
    ("buwizz3", "command", "A1", "activate_shelf_mode", {}, []),
    ("buwizz3", "command", "AC", "check_charger_settings", {}, []),
    ("buwizz3", "notification", "23 00 00 80 3F 00 00 80 BF 00 00 00 3F 00 00 00 00 00 00 20 C0 00 00 00 00",
     "accel_calibration", {"factors": [1, -1, 0.5, 0, -2.5, 0]}, ["factors=1,-1,0.5,0,-2.5,0"]),
    ("buwizz3", "notification", "AC 01 02 03", "charger_settings", {"data": "01 02 03"}, ["data=010203"]),
    ("buwizz3", "notification",
     "01 73 50 0A 14 1E 28 32 C8 23 F0 FF F0 7F 00 08 0B 0C 0D 0E 0F 7D 30 EC 4C FF 60 79 FE FF 31 64 B3 00 40 E2 01 00 "
     "4B FF 01 00 01 00 00 00 4C 7F FF FF FF FF FF 7F 00 00 00 3F 00 00 20 C0 00 00 4C 41 F9 2A",
     "status", {"flags": 0x73, "battery_voltage_raw": 80, "accel_raw": [-16, 0x7FF0, 0x0800], "temperature_c": 35,
                "pid_state": {"process_value": 0.5, "error": -2.5, "output": 12.75, "integrator": -7, "motor_output": 42}},
     ["flags=0x73", "battery_voltage_raw=80", "motor_current_raw=10,20,30,40,50,200", "temperature_c=35",
      "accel_raw=-16,0x7FF0,0x0800", "bootloader_response=11,12,13,14,15", "charge_current_ma=125",
      "pu_motors=0x30,-20,-180,-100000,0x31,100,179,123456,0x4B,-1,1,1,0x4C,127,-1,2147483647",
      "pid_state=0.5,-2.5,12.75,-7,42"]),
    ("navbot", None, "55 AA 10 00 00 9C 64 37 FF 02 01 01 02 FB 05 00 00 00 00 00", "maneuver",
     {"roll": -100, "height": 100, "pitch": 55, "yaw": -1, "switch_a": "start_touch_panel", "switch_b": "mark",
      "switch_c": "lock", "switch_d": "ball_poise", "ball_x": -5, "ball_y": 5},
     ["roll=-100", "height=100", "pitch=55", "yaw=-1", "switch_a=start_touch_panel", "switch_b=mark", "switch_c=lock",
      "switch_d=ball_poise", "ball_x=-5", "ball_y=5"]),
    ("navbot", None, "55 AA 02 00 00 7B 22 61 22 3A 31 7D 00 00 00 00 00 00 00 00", "frame",
     {"command": 2, "remaining": 0}, ["command=2", "remaining=0", "payload=0x7B,0x22,0x61,0x22,0x3A,0x31,0x7D,0,0,0,0,0,0,0,0"]),
    ("osp", None, "FF AA 00 01 00 00 00 00 55 77", "request_device_type", {}, []),
    ("osp", None, "FF AA 00 11 02 00 00 00 55 77", "device_type", {"type": "obp1"}, ["type=obp1"]),
    ("osp", None, "FF AA 01 02 03 34 12 00 55 77", "set_angle", {"joint": 3, "angle": 0x1234}, ["joint=3", "angle=0x1234"]),
    ("osp", None, "FF AA 02 01 00 00 00 00 55 77", "request_soc", {}, []),
    ("osp", None, "FF AA 02 02 00 00 00 00 55 77", "request_voltage", {}, []),
    ("osp", None, "FF AA 02 03 00 00 00 00 55 77", "request_current", {}, []),
    ("osp", None, "FF AA 02 04 00 00 00 00 55 77", "request_status", {}, []),
    ("osp", None, "FF AA 02 11 FF FF 00 00 55 77", "soc", {"soc_raw": 65535}, ["soc_raw=65535"]),
    ("osp", None, "FF AA 02 12 D2 04 00 00 55 77", "voltage", {"centivolts": 1234}, ["centivolts=1234"]),
    ("osp", None, "FF AA 02 13 24 FA 00 00 55 77", "current", {"milliamps": -1500}, ["milliamps=-1500"]),
    ("osp", None, "FF AA 02 14 03 05 00 00 55 77", "status", {"state": "charging", "flags": 5}, ["state=charging", "flags=5"]),
]

def norm(h):
    return h.replace(" ", "").upper()

for proto, direction, hexs, message, fields, enc in CASES:
    extra = ["--direction", direction] if direction else []
    # text
    rc, out, err = run("decode", proto, *hexs.split(), *extra)
    check(rc == 0 and out.splitlines()[0] == f"{proto} {message}", f"decode text {proto} {message}: {rc} {out!r} {err!r}")
    for name in fields:
        check(name in out, f"decode text {message} shows {name}")
    # JSON, parsed
    rc, out, err = run("decode", proto, hexs.replace(" ", ""), "--json", *extra)
    try:
        doc = json.loads(out)
    except ValueError:
        doc = {}
    check(rc == 0 and doc.get("protocol") == proto and doc.get("message") == message, f"decode json {message}: {out!r} {err!r}")
    for name, want in fields.items():
        got = doc.get("fields", {}).get(name, "missing")
        check(got == want, f"json {message}.{name}: {got!r} != {want!r}")
    # encode from field values gives the golden bytes; the result decodes to the same message
    rc, out, err = run("encode", proto, message, *enc)
    check(rc == 0 and norm(out.strip()) == norm(hexs), f"encode {message}: {rc} {out!r} {err!r}")
    rc2, out2, _ = run("decode", proto, out.strip(), "--json", *extra)
    check(rc2 == 0 and json.loads(out2 or "{}").get("message") == message, f"round trip {message}")

# hex spellings
for spelling in ["30 7F 81 00 40 C0 01 21 3F", "307F810040C001213F", "0x30,0x7F,0x81,0x00,0x40,0xC0,0x01,0x21,0x3F",
                 "30-7F-81-00-40-C0-01-21-3F"]:
    rc, out, _ = run("decode", "buwizz3", spelling)
    check(rc == 0 and "set_motor_data" in out, f"hex spelling {spelling}")

# bad input: one line naming the problem and the byte offset, exit status 1
BAD = [
    (["decode", "buwizz3", "30 80 00 00 00 00 00 00 00"], "value out of range at byte 1"),
    (["decode", "buwizz3", "30 00"], "input too short at byte 2"),
    (["decode", "buwizz3", "99"], "unknown message at byte 0"),
    (["decode", "buwizz3", "37 04"], "value is not a valid code at byte 1"),
    (["decode", "navbot", "55 AA 10 00 00 00 00 00 8A 00 01 00 00 00 00 00 00 00 00 00 00 00"], "transcription error"),
    (["decode", "navbot", "55 AA 10 00 00 00 00 8A 00 01 00 00 00 00 00 00 00 00 00 00"], "value out of range at byte 7"),
    (["decode", "osp", "FF AA 02 14 01 00 00 00 55 00"], "bad trailer byte at byte 9"),
    (["decode", "osp", "FF AA 03 01 0A 0B 0C 0D 55 77"], "DEV 03 CMD 01 params 0A 0B 0C 0D"),
    (["decode", "osp", "FF AA 0G"], "at byte 6"),
    (["encode", "buwizz3", "set_motor_data", "power=-128,0,0,0,0,0"], "value out of range at byte 1"),
    (["encode", "buwizz3", "set_motor_data", "power=300,0,0,0,0,0"], "value out of range"),
    (["encode", "buwizz3", "set_data_period", "period_ms=10"], "value out of range at byte 1"),
    (["encode", "navbot", "maneuver", "switch_a=jump"], "unknown name"),
]
for args, text in BAD:
    rc, out, err = run(*args)
    check(rc == 1 and text in err and len(err.strip().splitlines()) == 1, f"bad input {args}: {rc} {err!r}")
rc, _, err = run("encode", "osp", "nosuch")
check(rc == 2 and "unknown message" in err, "unknown message name")
rc, _, err = run("encode", "osp", "soc", "nosuch=1")
check(rc == 2 and "unknown field" in err, "unknown field name")

# list
rc, out, _ = run("list")
check(rc == 0 and all(m in out for m in ["set_pid_parameters", "maneuver", "request_soc", "charger_settings"]), "list")
rc, out, _ = run("list", "buwizz3", "--fields")
check(rc == 0 and "reference_rate_limit" in out and "@30" in out and "-127..127" in out, "list --fields")
rc, out, _ = run("--help")
check(rc == 0 and "robowire monitor" in out, "--help")
rc, out, _ = run("decode", "--help")
check(rc == 0 and "usage" in out, "decode --help")

# scan: frames with noise, from stdin
stream = bytes.fromhex("00 55 77 FF FF AA 01 02 03 04 05 06 07 08 FF AA 02 11 FF AA 00 00 55 77 FF AA 02 12 D2 04 00 00 55 77")
rc, out, _ = run("scan", "osp", "-", stdin=stream)
check(rc == 0 and out.count("osp soc") == 1 and out.count("osp voltage") == 1 and "frames 2," in out, f"scan: {out!r}")
rc, out, _ = run("scan", "osp", "--json", stdin=stream)
lines = [json.loads(l) for l in out.splitlines() if l.startswith("{")]
check([l["message"] for l in lines] == ["soc", "voltage"], "scan --json")

# monitor: a real pseudo-terminal pair from socat, a writer sending frames mixed with noise
if shutil.which("socat"):
    d = tempfile.mkdtemp()
    a, b = os.path.join(d, "a"), os.path.join(d, "b")
    socat = subprocess.Popen(["socat", f"pty,raw,echo=0,link={a}", f"pty,raw,echo=0,link={b}"],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    for _ in range(100):
        if os.path.exists(a) and os.path.exists(b):
            break
        time.sleep(0.05)
    mon = subprocess.Popen([TOOL, "monitor", a, "--baud", "115200", "--count", "3", "--timeout", "10"],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    time.sleep(0.5)
    with open(b, "wb", buffering=0) as w:
        for chunk in [b"\x00\x13\xff", bytes.fromhex("FF AA 02 12 D2 04 00 00 55 77"), b"\xff\xaa\x55\x77noise",
                      bytes.fromhex("FF AA 02 14 03 05 00 00"), bytes.fromhex("55 77 FF AA 00 11 02 00 00 00 55 77")]:
            w.write(chunk)
            time.sleep(0.05)
        out, err = mon.communicate(timeout=15)
    socat.terminate()
    out = out.decode()
    check(mon.returncode == 0 and "osp voltage" in out and "osp status" in out and "osp device_type" in out
          and "frames 3," in out, f"monitor over a pty: {out!r} {err!r}")
else:
    check(False, "socat is not installed")

print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
