#!/usr/bin/env python3
"""Tests of the robowire command-line tool. Usage: test_cli.py PATH_TO_ROBOWIRE
Golden vectors are the unit tests' (worked out by hand from the documents);
physical values are worked out by hand from the documents' units.
Prints 'N passed, M failed' and exits 1 on any failure."""
import json, os, re, shutil, subprocess, sys, tempfile, time

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

# The golden vectors every test reads (tests/vectors/vectors.json, worked out by hand from the documents)
VECTORS_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "vectors", "vectors.json")
with open(VECTORS_PATH, encoding="utf-8") as fh:
    VECTORS = json.load(fh)

def encode_args(fields, hex_ints=False):
    """encode's name=value arguments: arrays and records flattened in order, bytes as hex, booleans true/false;
    hex_ints: integers 0 and up as 0x... (the tool reads both)."""
    def flat(v):
        if isinstance(v, dict) and set(v) == {"hex"}:
            return [v["hex"].replace(" ", "")]
        if isinstance(v, dict):
            return [e for x in v.values() for e in flat(x)]
        if isinstance(v, list):
            return [e for x in v for e in flat(x)]
        if isinstance(v, bool):
            return ["true" if v else "false"]
        if hex_ints and isinstance(v, int) and v >= 0:
            return [f"0x{v:X}"]
        return [str(v)]
    return [f"{k}={','.join(flat(v))}" for k, v in fields.items()]

# (protocol, direction, hex, message, fields that must match in JSON, encode arguments)
CASES = [(m["protocol"], m["direction"], m["hex"], m["message"], m["fields"], encode_args(m["encode"]))
         for m in VECTORS["messages"]]

def norm(h):
    return h.replace(" ", "").upper()

def close(a, b):
    return abs(a - b) < 1e-9 * max(1.0, abs(b))

def parse_json(out):
    try:
        return json.loads(out)
    except ValueError:
        return {}

for proto, direction, hexs, message, fields, enc in CASES:
    extra = ["--direction", direction] if direction else []
    # text
    rc, out, err = run("decode", proto, *hexs.split(), *extra)
    check(rc == 0 and out.splitlines()[0] == f"{proto} {message}", f"decode text {proto} {message}: {rc} {out!r} {err!r}")
    for name in fields:  # the raw fields by name (physical values and flag bits are shown next to them)
        if not name.endswith(("_physical", "_bits", "_text")):
            check(name in out, f"decode text {message} shows {name}")
    # JSON, parsed
    rc, out, err = run("decode", proto, hexs.replace(" ", ""), "--json", *extra)
    doc = parse_json(out)
    check(rc == 0 and doc.get("type") == "message" and doc.get("protocol") == proto and doc.get("message") == message,
          f"decode json {message}: {out!r} {err!r}")
    for name, want in fields.items():
        got = doc.get("fields", {}).get(name, "missing")
        check(got == want, f"json {message}.{name}: {got!r} != {want!r}")
    # BuWizz3 without --direction: the command byte (and for 0x23 / 0xAC the length) decides
    if proto == "buwizz3":
        rc, out, err = run("decode", proto, hexs, "--json")
        if hexs == "AC":  # check_charger_settings (1 byte) or charger_settings with no data (1 byte)
            check(rc == 2 and "--direction command or --direction notification" in err, f"AC needs a direction: {rc} {err!r}")
        else:
            check(rc == 0 and parse_json(out).get("message") == message, f"direction inferred for {message}: {rc} {out!r} {err!r}")
    # encode from field values gives the golden bytes; the result decodes to the same message
    rc, out, err = run("encode", proto, message, *enc)
    check(rc == 0 and norm(out.strip()) == norm(hexs), f"encode {message}: {rc} {out!r} {err!r}")
    rc2, out2, _ = run("decode", proto, out.strip(), "--json", *extra)
    check(rc2 == 0 and parse_json(out2).get("message") == message, f"round trip {message}")

# the same values with integers spelled in hex (brake_flags=0x21, angle=0x1234, pu_motors=0x30,...)
for m in VECTORS["messages"]:
    rc, out, err = run("encode", m["protocol"], m["message"], *encode_args(m["encode"], hex_ints=True))
    check(rc == 0 and norm(out.strip()) == norm(m["hex"]), f"encode {m['message']}, hex integers: {rc} {out!r} {err!r}")

# ---- direction: 0x23 with 25 bytes is the notification, 1 byte the command; a wrong --direction says which it is
rc, out, _ = run("decode", "buwizz3", "23")
check(rc == 0 and out.startswith("buwizz3 read_accel_calibration"), "0x23, 1 byte: command")
rc, out, err = run("decode", "buwizz3", "23 00 00")
check(rc == 1 and "accel_calibration (25 bytes)" in err and "3 bytes given" in err, f"0x23, 3 bytes: {err!r}")
rc, out, err = run("decode", "buwizz3", "01 02", "--direction", "command")
check(rc == 1 and err == "error: unknown key 0x01 at byte 0\nhint: 0x01 is the notification status\n", f"01 as a command: {err!r}")
rc, out, err = run("decode", "buwizz3", "--direction=notification", "AC")
check(rc == 0 and out.startswith("buwizz3 charger_settings"), f"--direction=notification: {rc} {err!r}")

# ---- hex spellings (one argument or several, line breaks)
for spelling in [["30 7F 81 00 40 C0 01 21 3F"], ["307f810040c001213f"], ["0x30,0x7F,0x81,0x00,0x40,0xC0,0x01,0x21,0x3F"],
                 ["30-7F-81-00-40-C0-01-21-3F"], ["(0x) 30-7F-81-00-40-C0-01-21-3F"], ["30:7F:81:00:40:C0:01:21:3F"],
                 ["30 7F 81\n00 40 C0\r\n01 21 3F\n"], "30 7F 81 00 40 C0 01 21 3F".split(), ["0x307F8100", "40C0", "01:21:3F"],
                 ["0x30,0x7F,0x81,0x0,0x40,0xC0,0x1,0x21,0x3F"], ["0x30 0x7f 0x81 0x0 0x40 0xc0 0x1 0x21 0x3f"]]:
    rc, out, err = run("decode", "buwizz3", *spelling)
    check(rc == 0 and out.startswith("buwizz3 set_motor_data"), f"hex spelling {spelling}: {rc} {err!r}")
rc, out, err = run("decode", "buwizz3", "0x30,0x1,0xF,0x0,0x0,0x0,0x0,0x3,0x0", "--json")
check(rc == 0 and parse_json(out).get("fields", {}).get("power") == [1, 15, 0, 0, 0, 0] and
      parse_json(out)["fields"].get("brake_flags") == 3, f"0x1 is one byte 01: {rc} {out!r} {err!r}")
# nRF Connect's copy of a status notification, no --direction
status_hex = ("01 6D 50 0A 14 1E 28 32 C8 23 F0 FF F0 7F 00 08 0B 0C 0D 0E 0F 7D 30 EC 4C FF 60 79 FE FF 31 64 B3 00 40 E2 01 00 "
              "4B FF 01 00 01 00 00 00 4C 7F FF FF FF FF FF 7F 00 00 00 3F 00 00 20 C0 00 00 4C 41 F9 2A")
rc, out, err = run("decode", "buwizz3", "(0x) " + status_hex.replace(" ", "-"))
check(rc == 0 and out.startswith("buwizz3 status"), f"nRF Connect status: {rc} {err!r}")
# bad hex: the character and its position (counted from 0 in the arguments joined by one space)
for args, text in [(["hello"], "'h' at character 0 is not a hex digit"), (["30 7G"], "'G' at character 4"),
                   (["30", "7G"], "'G' at character 4"), (["3 2 1 9"], "odd number of hex digits in \"3\" at character 0"),
                   (["307"], "odd number of hex digits in \"307\""), (["FF AA 0G"], "'G' at character 7"),
                   (["0x30,0x1,0x123"], "odd number of hex digits in \"0x123\" at character 9"), (["0x"], "\"0x\" at character 0")]:
    rc, out, err = run("decode", "buwizz3", *args)
    check(rc == 1 and "bad hex" in err and text in err and len(err.strip().splitlines()) == 1, f"bad hex {args}: {rc} {err!r}")

# ---- options: --opt=value, unknown options and bad values are usage errors naming the option
for args, name in [(["decode", "buwizz3", "30", "--jsn"], "--jsn"), (["monitor", "/dev/null", "--baud"], "--baud"),
                   (["monitor", "/dev/null", "--count", "abc"], "--count"), (["monitor", "/dev/null", "--timeout", "-1"], "--timeout"),
                   (["monitor", "/dev/null", "--baud", "1234"], "--baud"), (["decode", "buwizz3", "30", "--direction", "up"], "--direction"),
                   (["decode", "zigbee", "30"], "zigbee"), (["frobnicate"], "frobnicate")]:
    rc, out, err = run(*args)
    check(rc == 2 and name in err and out == "", f"usage error {args}: {rc} {err!r}")
rc, out, err = run("monitor", "/nonexistent/tty0", "--timeout=1")
check(rc == 1 and "cannot open /nonexistent/tty0: No such file or directory" in err, f"bad device: {rc} {err!r}")
rc, out, err = run("monitor", "/dev/null", "--timeout=0.2", "--count=5", "--json")
check(rc == 0 and [parse_json(l).get("type") for l in out.splitlines()] == ["counters"], f"monitor --opt=value: {rc} {out!r}")

# ---- JSON: physical values next to raw ones, flag bits, enum names, NAVBOT JSON text
rc, out, err = run("decode", "buwizz3", status_hex, "--json")
f = parse_json(out).get("fields", {})
check(f.get("battery_voltage_raw") == 80 and f.get("battery_voltage") == {"value": 13.0, "unit": "V"}, f"battery: {f.get('battery_voltage')}")
mc = f.get("motor_current", {})  # raw x 0.015 A: 10 20 30 40 50 200
check(mc.get("unit") == "A" and all(close(a, b) for a, b in zip(mc.get("value", []), [0.15, 0.3, 0.45, 0.6, 0.75, 3.0]))
      and len(mc.get("value", [])) == 6, f"motor current: {mc}")
check(f.get("temperature_c_physical") == {"value": 35, "unit": "degC"}, "temperature")
ac = f.get("accel", {})  # word x 0.488 mg: -16 -> -7.808
check(ac.get("unit") == "mg" and close(ac.get("value", [0])[0], -7.808), f"accel: {ac}")
check(f.get("pu_motors", [{}])[3].get("position_physical") == {"value": 2147483647, "unit": "deg"}, "record field physical")
check(f.get("flags") == 109 and f.get("flags_bits") == {"error": True, "motion_wakeup": False, "long_range_phy": True,
                                                         "battery": "low", "charging": True, "usb_connected": True},
      f"flag bits: {f.get('flags_bits')}")
rc, out, err = run("decode", "buwizz3", status_hex)
check("109 = error | long_range_phy | battery low | charging | usb_connected" in out, "flag bits, text")
check("13 V" in out and "battery_voltage_raw" in out, "physical value, text")
rc, out, _ = run("decode", "buwizz3", "30 7F 81 00 40 C0 01 21 3F", "--json")
f = parse_json(out).get("fields", {})
check(f.get("power_physical", {}).get("unit") == "%" and close(f["power_physical"]["value"][0], 100.0)
      and close(f["power_physical"]["value"][1], -100.0), f"power %: {f.get('power_physical')}")
check(f.get("brake_flags_bits", {}).get("port1") and f["brake_flags_bits"].get("port6") and not f["brake_flags_bits"].get("port2"),
      "port bits")
rc, out, _ = run("decode", "buwizz3", "30 7F 81 00 40 C0 01 21 3F")
check("33 = port1 | port6" in out and "63 = port1 | port2 | port3 | port4 | port5 | port6" in out, f"port bits text: {out!r}")
rc, out, _ = run("decode", "osp", "FF AA 02 14 03 05 00 00 55 77", "--json")
f = parse_json(out).get("fields", {})
check(f.get("state") == "charging" and f.get("flags_bits") == {"low_voltage": True, "high_voltage": False, "overheat": True,
                                                               "short_circuit": False}, f"osp status: {f}")
rc, out, _ = run("decode", "osp", "FF AA 02 14 03 05 00 00 55 77")
check("charging (0x03)" in out and "5 = low_voltage | overheat" in out, f"osp status text: {out!r}")
rc, out, _ = run("decode", "osp", "FF AA 02 12 D2 04 00 00 55 77", "--json")
f = parse_json(out).get("fields", {})
check(f.get("centivolts") == 1234 and f.get("centivolts_physical") == {"value": 12.34, "unit": "V"}, f"volts: {f}")
rc, out, _ = run("decode", "osp", "FF AA 02 11 FF FF 00 00 55 77", "--json")
check(parse_json(out).get("fields", {}).get("soc") == {"value": 100, "unit": "%"}, "soc %")
nav_json = "55 AA 02 00 00 7B 22 61 22 3A 31 7D 00 00 00 00 00 00 00 00"
rc, out, _ = run("decode", "navbot", nav_json, "--json")
check(parse_json(out).get("fields", {}).get("payload_text") == '{"a":1}', f"NAVBOT JSON payload text: {out!r}")
rc, out, _ = run("decode", "navbot", nav_json)
check('payload (text)  {"a":1}' in out and "payload         7B 22 61 22 3A 31 7D 00" in out and len(out.splitlines()) == 5,
      f"NAVBOT JSON payload, text output: {out!r}")

# ---- sign-magnitude NAVBOT frames: 0x8A is -118 to the robot (out of range), -10 in the document's spelling
rc, out, err = run("decode", "navbot", "55 AA 10 00 00 00 00 8A 00 01 00 00 00 00 00 00 00 00 00 00")
check(rc == 1 and err.startswith("error: maneuver.pitch: value out of range (valid -100..100 %) at byte 7\n")
      and "hint: pitch at byte 7 is -118 (0x8A)\n" in err and "0x8A = -118" in err and "0x8A = -10" in err,
      f"sign-magnitude hint: {err!r}")
rc, out, err = run("decode", "navbot", "55 AA 10 00 00 00 00 B2 00 01 00 00 00 00 00 00 00 00 00 00", "--json")
doc = parse_json(out)
check(rc == 0 and doc.get("fields", {}).get("pitch") == -78 and any("0xB2 = -50" in n for n in doc.get("notes", [])),
      f"sign-magnitude note: {out!r}")

# ---- errors: robowire::describe_error's line (the text C++ and Python give), then hints with the
# value given, the lengths given, the marker expected (worked out by hand from the documents)
BAD = [
    (["encode", "buwizz3", "set_motor_data", "power=-128,0,0,0,0,0"], 1,
     "set_motor_data.power: value out of range (valid -127..127 raw) at byte 1", ["power[0]=-128 given", "-127..127"]),
    (["encode", "buwizz3", "set_motor_data", "power=0,300,0,0,0,0"], 1,
     "set_motor_data.power: value out of range (valid -127..127 raw) at byte 2", ["power[1]=300 given"]),
    (["encode", "buwizz3", "set_data_period", "period_ms=10"], 1,
     "set_data_period.period_ms: value out of range (valid 20..255 ms) at byte 1", ["period_ms=10 given"]),
    (["encode", "buwizz3", "set_led_status", "colors=0,0,0,0,256,0,0,0,0,0,0,0"], 1,
     "set_led_status.colors: value out of range at byte 5", ["colors[1].g=256 given, valid 0..255"]),
    (["encode", "buwizz3", "set_device_name", "name=Thirteen char"], 1, "set_device_name.name: value out of range at byte 1",
     ["name=Thirteen char given"]),
    (["encode", "buwizz3", "set_motor_data", "power=10,20"], 1, "power: 2 values given, 6 expected (power=v1,...,v6)", []),
    (["encode", "buwizz3", "status", "pu_motors=1,2,3"], 1, "pu_motors: 3 values given, 16 expected (4 x [type, velocity, absolute_position, position])", []),
    (["encode", "navbot", "maneuver", "switch_a=jump"], 1, "maneuver.switch_a: value is not a valid code at byte 9",
     ["switch_a=jump given", "stop, start, start_touch_panel"]),
    (["encode", "buwizz3", "set_led_status", "blink=1,15,15,0,0,8,5,5"], 1,
     "set_led_status.colors: optional block present without the one before it at byte 1", ["give colors too"]),
    (["encode", "navbot", "maneuver", "pitch=1", "pitch=2"], 2, "field pitch given twice (pitch=1, pitch=2)", []),
    (["encode", "osp", "nosuch"], 2, "unknown message nosuch (robowire list osp)", []),
]
# decode errors from tests/vectors/vectors.json (code and offset: the line ends "at byte <offset>")
for v in VECTORS["errors"]:
    if not v["hex"]:
        continue  # no bytes: nothing to give on the command line
    extra = ["--direction", v["direction"]] if v["direction"] else []
    check(v["error"].endswith(f"at byte {v['offset']}"), f"vector {v['hex']}: its line ends at byte {v['offset']}")
    BAD.append((["decode", v["protocol"], v["hex"], *extra], 1, v["error"], v.get("cli_hints", []), "some"))
for args, status, line, hints, *some in BAD:
    exact = not some  # every hint line has one of the texts (the vectors' errors: each text is in one of them)
    rc, out, err = run(*args)
    lines = err.strip().splitlines()
    hinted = {next((i for i, l in enumerate(lines[1:]) if h in l), -1) for h in hints}  # the hint line each text is on
    check(rc == status and lines[:1] == ["error: " + line] and -1 not in hinted and (len(lines) == 1 + len(hinted) or not exact)
          and all(l.startswith("hint: ") for l in lines[1:]) and out == "",
          f"bad input {args}: {rc} {err!r}")
rc, out, err = run("encode", "osp", "soc", "nosuch=1")
check(rc == 2 and "unknown field nosuch" in err and "soc_raw" in err, f"unknown field: {err!r}")
# the same bad input gives the same line in the tool's text and JSON output as in C++ and Python
rc, out, err = run("decode", "osp", "FF AA 03 01 0A 0B 0C 0D 55 77", "--json")
doc = parse_json(out)
check(rc == 1 and doc.get("type") == "error" and doc.get("error") == "unknown key 0x03 0x01 at byte 2"
      and doc.get("hints") == ["DEV 03 CMD 01 params 0A 0B 0C 0D"], f"decode --json error: {out!r}")
# bytes that are no OSP frame (the length and a start marker wrong): osp::decode's error, bad_header at byte 0, in
# osp::frame's line (bytes 2 and 3 name no message), then the byte expected and the length given
noise_hints = ["hint: byte 0 is 0x00, expected 0xFF (frames are FF AA DEV CMD P1..P4 55 77)", "hint: 5 bytes given (a frame is 10 bytes)"]
rc, out, err = run("decode", "osp", "00 11 37 FF 22")
check(rc == 1 and out == "" and err.splitlines() == ["error: frame: bad header byte at byte 0", *noise_hints],
      f"decode osp, 5 bytes of noise: {rc} {err!r}")
rc, out, err = run("decode", "osp", "--file", "-", stdin=b"00 11 37 FF 22\n")
check(rc == 1 and out == "" and err.splitlines()[:3] == ["error: line 1: frame: bad header byte at byte 0",
                                                          *[h.replace("hint: ", "hint: line 1: ") for h in noise_hints]],
      f"decode osp --file, a line of noise: {rc} {err!r}")
rc, out, err = run("decode", "osp", "FF AA 37 FF 22")  # the markers right, bytes 2 and 3 no DEV and CMD: osp::frame's line
check(rc == 1 and out == "" and err.splitlines() == ["error: frame: input too short (10 bytes) at byte 5", "hint: 5 bytes given"],
      f"decode osp, 5 bytes, no message's key: {rc} {err!r}")
rc, out, err = run("decode", "osp", "00 11 37 FF 22", "--json")
check(rc == 1 and parse_json(out).get("error") == "frame: bad header byte at byte 0"
      and parse_json(out).get("hints") == [h[6:] for h in noise_hints], f"decode osp --json, 5 bytes of noise: {out!r}")

# ---- list
rc, out, _ = run("list")
check(rc == 0 and all(m in out for m in ["set_pid_parameters", "maneuver", "request_soc", "charger_settings"]), "list")
check(" 1 bytes" not in out and "read_accel_calibration     23       1 byte\n" in out, "singular byte")
check("1, 13 or 17 bytes" in out and "54 or 68..129 bytes" in out and "25 bytes" in out, f"exact lengths")
rc, out, _ = run("list", "buwizz3", "--fields")
check(rc == 0 and "reference_rate_limit" in out and "@30" in out and "-127..127" in out, "list --fields")
check("pu_motors=4 x 4 = 16 values in this order: type, velocity, absolute_position, position" in out
      and "pu_motors[i].position" in out and "@26+8i" in out, "record expanded (pu_motors)")
check("pid_state=5 values in this order: process_value, error, output, integrator, motor_output" in out
      and "pid_state.motor_output" in out and "@67" in out, "record expanded (pid_state)")
check("bit 3-4 battery (empty/low/medium/full)" in out, "flag bits listed")
rc, out, _ = run("list", "navbot", "--fields")
check("stop, start, start_touch_panel" in out and "osp" not in out, "list navbot")

# ---- help
rc, out, _ = run("--help")
check(rc == 0 and "monitor" in out and "Exit status" in out, "--help")
rc, out, _ = run("decode", "--help")
check(rc == 0 and "Usage" in out and "--direction" in out, "decode --help")
rc, out, err = run()
check(rc == 2 and "Usage" in err, "no arguments")

# ---- scan: frames with noise, binary from stdin; hex text files, detected or forced
stream = bytes.fromhex("00 55 77 FF FF AA 01 02 03 04 05 06 07 08 FF AA 02 11 FF AA 00 00 55 77 FF AA 02 12 D2 04 00 00 55 77"
                       " FF AA 03 01 0A 0B 0C 0D 55 77")
rc, out, err = run("scan", "osp", "-", stdin=stream)
check(rc == 0 and out.count("osp soc") == 1 and out.count("osp voltage") == 1 and "frames 3," in out
      and "osp frame FF AA 03 01 0A 0B 0C 0D 55 77: unknown key 0x03 0x01 at byte 2\n" in out and "read as binary" in out, f"scan: {out!r}")
rc, out, err = run("scan", "osp", "--json", stdin=stream)
lines = [parse_json(l) for l in out.splitlines()]
check([l.get("type") for l in lines] == ["message", "message", "error", "counters"], f"scan --json: only JSON lines: {out!r}")
check([l.get("message") for l in lines[:2]] == ["soc", "voltage"] and lines[2].get("bytes") == "FF AA 03 01 0A 0B 0C 0D 55 77"
      and lines[3].get("frames") == 3 and lines[3].get("input") == "binary", f"scan --json: {lines}")
# a scan's error record carries the hints decode gives for the same frame (DEV, CMD and parameters: bytes 2, 3, 4-7)
check(lines[2].get("hints") == ["DEV 03 CMD 01 params 0A 0B 0C 0D"], f"scan --json error hints: {lines[2]}")
rc, out, err = run("scan", "osp", "-", stdin=stream)
check("unknown key 0x03 0x01 at byte 2\nhint: DEV 03 CMD 01 params 0A 0B 0C 0D\n" in out, f"scan error hints: {out!r}")
drc, dout, derr = run("decode", "osp", "--json", "FF AA 03 01 0A 0B 0C 0D 55 77")
check(parse_json(dout).get("hints") == lines[2].get("hints"), f"scan and decode hints: {dout!r}")
check(lines[1].get("fields", {}).get("centivolts_physical") == {"value": 12.34, "unit": "V"}, "scan --json physical value")
# --format: the same bytes as --json and as the default; the formats' names checked; not with --json
check(run("scan", "osp", "--format", "json", stdin=stream) == run("scan", "osp", "--json", stdin=stream), "scan --format json")
check(run("scan", "osp", "--format", "text", stdin=stream) == run("scan", "osp", stdin=stream), "scan --format text")
for args in (["decode", "osp", "FF AA 02 12 D2 04 00 00 55 77"], ["decode", "osp", "FF AA 03 01 0A 0B 0C 0D 55 77"]):
    check(run(*args, "--format", "json") == run(*args, "--json"), f"{args} --format json")
    check(run(*args, "--format", "text") == run(*args), f"{args} --format text")
check(run("decode", "osp", "FF AA 02 12 D2 04 00 00 55 77", "--format", "json")[1] != run("decode", "osp", "FF AA 02 12 D2 04 00 00 55 77")[1],
      "--format json differs from text")
rc, out, err = run("decode", "osp", "FF AA 02 12 D2 04 00 00 55 77", "--format", "yaml")
check(rc == 2 and "yaml" in err and out == "", f"--format yaml: {rc} {err!r}")
rc, out, err = run("scan", "osp", "--format", "json", "--json", stdin=stream)
check(rc == 2 and "excludes" in err, f"--format with --json: {err!r}")
d = tempfile.mkdtemp()
text_path = os.path.join(d, "dump.txt")
with open(text_path, "w") as fh:
    fh.write("FF AA 02 12 D2 04 00 00 55 77\nFF-AA-02-14-03-05-00-00-55-77\n")
rc, out, err = run("scan", "osp", text_path)
check(rc == 0 and "osp voltage" in out and "osp status" in out and "frames 2," in out and "read as hex text" in out
      and "hex text" in err, f"scan hex text: {out!r} {err!r}")
rc, out, err = run("scan", "osp", text_path, "--json")
lines = [parse_json(l) for l in out.splitlines()]
check([l.get("type") for l in lines] == ["message", "message", "counters"] and lines[-1].get("input") == "hex text", f"{out!r}")
rc, out, err = run("scan", "osp", "--binary", text_path)
check(rc == 0 and "frames 0," in out and "read as binary" in out and "--hex" in err, f"scan --binary on text: {out!r} {err!r}")
rc, out, err = run("scan", "osp", "--hex", "-", stdin=b"FF AA 02 12 D2 04 00 00 55 77")
check(rc == 0 and "osp voltage" in out, "scan --hex from stdin")
bin_path = os.path.join(d, "frame.bin")
with open(bin_path, "wb") as fh:
    fh.write(bytes.fromhex("FF AA 02 12 D2 04 00 00 55 77"))
rc, out, err = run("decode", "osp", "--file", bin_path)
check(rc == 0 and out.startswith("osp voltage") and "as binary" in err, f"decode --file binary: {err!r}")
one_path = os.path.join(d, "frame.txt")
with open(one_path, "w") as fh:
    fh.write("(0x) FF-AA-02-12-D2-04-00-00-55-77\n")
rc, out, err = run("decode", "osp", f"--file={one_path}", "--json")
check(rc == 0 and parse_json(out).get("message") == "voltage" and "read as hex lines" in err, f"decode --file hex text: {err!r}")
shutil.rmtree(d)

# ---- logs: decode --file and scan, line by line, with line numbers; nRF Connect logs as the apps write them
# nRF Connect for Android (its log lines: level letter, time with milliseconds, then Nordic's BLE library's
# "Notification received from <uuid>, value: (0x) 01-02", "Data written to <uuid>, value: ...",
# "Data written to descr. <uuid>, ..."; service lists and other entries carry no frame).
APP = "50052901-74fb-4481-88b3-9919b1676e93"  # BuWizz3 application characteristic
status_dashes = status_hex.replace(" ", "-")
android_log = "\n".join([
    "nRF Connect, 2026-03-14",
    "BuWizz (D4:37:A1:0C:55:2E)",
    "V 10:12:03.117 Connecting to D4:37:A1:0C:55:2E...",
    "D 10:12:03.118 gatt = device.connectGatt(autoConnect = false, TRANSPORT_LE, preferred PHY = LE 1M)",
    "D 10:12:03.702 [Callback] Connection state changed with status: 0 and new state: CONNECTED (2)",
    "I 10:12:03.702 Connected to D4:37:A1:0C:55:2E",
    "V 10:12:03.731 Discovering services...",
    "D 10:12:03.731 gatt.discoverServices()",
    "I 10:12:04.310 Services discovered",
    "V 10:12:04.340 Generic Access (0x1800)",
    "- Device Name [R] (0x2A00)",
    "Unknown Service (500592d1-74fb-4481-88b3-9919b1676e93)",
    f"- Unknown Characteristic [N W] ({APP})",
    "Client Characteristic Configuration (0x2902)",
    "I 10:12:05.120 Read Response received from 00002a00-0000-1000-8000-00805f9b34fb, value: (0x) 42-75-57-69-7A-7A-33, \"BuWizz3\"",
    "D 10:12:06.514 gatt.writeDescriptor(00002902-0000-1000-8000-00805f9b34fb, value=0x0100)",
    "I 10:12:06.601 Data written to descr. 00002902-0000-1000-8000-00805f9b34fb, value: (0x) 01-00",
    f"I 10:12:06.655 Notification received from {APP}, value: (0x) {status_dashes}",    # line 18
    f"V 10:12:09.001 Writing characteristic {APP} (WRITE REQUEST)",
    f"D 10:12:09.001 gatt.writeCharacteristic({APP}, value=0x307F810040C001213F)",
    f"I 10:12:09.072 Data written to {APP}, value: (0x) 30-7F-81-00-40-C0-01-21-3F",  # line 21
    f"I 10:12:09.300 Data written to {APP}, value: (0x) 30-80-00-00-00-00-00-00-00",  # line 22: -128
    f"I 10:12:09.500 Notification received from {APP}, value: (0x) AC",               # line 23: charger_settings
    f"I 10:12:09.600 Data written to {APP}, value: (0x) AC",                           # line 24: check_charger_settings
    f"I 10:12:09.700 Data written to {APP}, value: (0x) 32-32, \"22\"",              # line 25: as text too
]) + "\n"
rc, out, err = run("decode", "--file", "-", stdin=android_log.encode())
check(rc == 1 and "line 18 (device to host): buwizz3 status" in out and "line 21 (host to device): buwizz3 set_motor_data" in out
      and "line 23 (device to host): buwizz3 charger_settings" in out
      and "line 24 (host to device): buwizz3 check_charger_settings" in out
      and "line 25 (host to device): buwizz3 set_data_period" in out and "period_ms  50 ms" in out
      and "error: 2026-03-14T10:12:09.300 line 22: set_motor_data.power: value out of range (valid -127..127 raw) at byte 1\n" in err
      and "hint: 2026-03-14T10:12:09.300 line 22: power[0] at byte 1 is -128 (0x80)\n" in err
      and "read as nRF Connect (Android) log: lines 25, frames 6, decoded 5, errors 1" in err
      and "other characteristics 1" in err, f"Android log: {rc} {out!r} {err!r}")
rc, out, err = run("decode", "buwizz3", "--file", "-", "--json", stdin=android_log.encode())
docs = [parse_json(l) for l in out.splitlines()]
check([(d.get("type"), d.get("line"), d.get("direction"), d.get("message")) for d in docs] ==
      [("message", 18, "device_to_host", "status"), ("message", 21, "host_to_device", "set_motor_data"),
       ("error", 22, "host_to_device", None), ("message", 23, "device_to_host", "charger_settings"),
       ("message", 24, "host_to_device", "check_charger_settings"), ("message", 25, "host_to_device", "set_data_period")]
      and docs[0].get("uuid") == APP and docs[0]["fields"].get("battery_voltage_raw") == 80
      and docs[2].get("bytes") == "30 80 00 00 00 00 00 00 00", f"Android log --json: {rc} {out!r}")
rc, out, err = run("decode", "navbot", "--file", "-", stdin=android_log.encode())
check(rc == 1 and out == "" and "error: 2026-03-14T10:12:05.120 line 15: frame: bad header byte at byte 0" in err
      and "other characteristics 6" in err,
      f"navbot on a BuWizz3 log: the BuWizz3 characteristic's lines are skipped: {rc} {err!r}")
# decode's error lines on stderr carry the log line's time before its number, as scan's do (docs/cli.md, Time);
# a line without a time (a bare hex line) has its number only
timed = f"nRF Connect, 2026-03-14\nI 10:12:09.300 Data written to {APP}, value: (0x) 30-80-00-00-00-00-00-00-00\n30 80 00 00 00 00 00 00 00\n"
rc, out, err = run("decode", "buwizz3", "--file", "-", stdin=timed.encode())
check(rc == 1 and out == "" and err.splitlines()[:4] == [
          "error: 2026-03-14T10:12:09.300 line 2: set_motor_data.power: value out of range (valid -127..127 raw) at byte 1",
          "hint: 2026-03-14T10:12:09.300 line 2: power[0] at byte 1 is -128 (0x80)",
          "error: line 3: set_motor_data.power: value out of range (valid -127..127 raw) at byte 1",
          "hint: line 3: power[0] at byte 1 is -128 (0x80)"],
      f"decode --file: error lines carry the log line's time: {rc} {err!r}")
# a log line given as the argument; a log with bare hex lines pasted in
rc, out, err = run("decode", "buwizz3", f"I 10:12:09.700 Data written to {APP}, value: (0x) 32-32")
check(rc == 0 and out.startswith("10:12:09.700 line 1 (host to device): buwizz3 set_data_period"), f"log line argument: {rc} {out!r} {err!r}")
mixed = f"I 13:40:29.880 Notification received from {APP}, value: (0x) AC\n30 7F 81 00 40 C0 01 21 3F\n32 32\n"
rc, out, err = run("decode", "--file", "-", "--json", stdin=mixed.encode())
check(rc == 2 and "line 2: which protocol?" in err, f"mixed log without protocol: {rc} {err!r}")
rc, out, err = run("decode", "buwizz3", "--file", "-", "--json", stdin=mixed.encode())
check(rc == 0 and [(d.get("line"), d.get("message")) for d in map(parse_json, out.splitlines())] ==
      [(1, "charger_settings"), (2, "set_motor_data"), (3, "set_data_period")], f"mixed log: {rc} {out!r} {err!r}")
# a device whose characteristic robowire does not know: decoded with the protocol given, skipped without one
other_log = "I 09:00:00.000 Connected to D4:37:A1:0C:55:2E\n" \
            "I 09:00:01.000 Data written to 0000ffe1-0000-1000-8000-00805f9b34fb, value: (0x) 32-32\n"
rc, out, err = run("decode", "buwizz3", "--file", "-", stdin=other_log.encode())
check(rc == 0 and out.startswith("09:00:01.000 line 2 (host to device): buwizz3 set_data_period"), f"unknown UUID, protocol given: {rc} {out!r} {err!r}")
rc, out, err = run("decode", "--file", "-", stdin=other_log.encode())
check(rc == 1 and "no frame in stdin: 2 lines" in err and "1 value of another characteristic: 0000ffe1-0000-1000-8000-00805f9b34fb" in err,
      f"unknown UUID, no protocol: {rc} {err!r}")

# nRF Connect for Desktop: the log file's "2026-...Z INFO Attribute value changed, handle: 0x10, value (0x): ..."
# and the log panel's "11:44:40.906<TAB>Attribute value written, ...". A value the app writes comes twice (changed,
# then written): one frame, host to device. CCCD writes (01-00) carry no frame. No UUIDs: the protocol is needed.
desktop_log = "\n".join([
    "2026-03-14T10:14:58.102Z INFO Connecting to device",
    "2026-03-14T10:14:58.870Z INFO Connected to device D4:37:A1:0C:55:2E: interval: 7.5ms, timeout: 4000ms, latency: 0",
    "2026-03-14T10:15:01.004Z INFO Attribute value changed, handle: 0x11, value (0x): 01-00",
    "2026-03-14T10:15:01.010Z INFO Attribute value written, handle: 0x11, value (0x): 01-00",
    f"2026-03-14T10:15:02.331Z INFO Attribute value changed, handle: 0x10, value (0x): {status_dashes}",  # line 5
    "2026-03-14T10:15:03.120Z INFO Attribute value changed, handle: 0x10, value (0x): 32-32",
    "2026-03-14T10:15:03.127Z INFO Attribute value written, handle: 0x10, value (0x): 32-32",  # line 7
]) + "\n"
rc, out, err = run("decode", "--file", "-", stdin=desktop_log.encode())
check(rc == 2 and out == "" and err.startswith("error: 2026-03-14T10:15:02.331 line 5: which protocol?") and "attribute handles" in err
      and len(err.strip().splitlines()) == 1, f"desktop log without protocol: {rc} {err!r}")
rc, out, err = run("decode", "buwizz3", "--file", "-", stdin=desktop_log.encode())
check(rc == 0 and "line 5 (device to host): buwizz3 status" in out and "line 7 (host to device): buwizz3 set_data_period" in out
      and "line 6" not in out and "decoded 2, errors 0" in err and "nRF Connect (desktop) log" in err, f"desktop log: {rc} {out!r} {err!r}")
panel = "11:44:40.906\tAttribute value changed, handle: 0x10, value (0x): 32-32\n11:44:40.911\tAttribute value written, handle: 0x10, value (0x): 32-32\n"
rc, out, err = run("decode", "buwizz3", "--file", "-", "--json", stdin=panel.encode())
check(rc == 0 and [(d.get("line"), d.get("direction"), d.get("handle")) for d in map(parse_json, out.splitlines())]
      == [(2, "host_to_device", "0x10")], f"desktop log panel: {rc} {out!r}")

# hex lines: one frame a line, comments and blank lines skipped, errors with their line numbers
hex_lines = "# frames from a capture\n30 7F 81 00 40 C0 01 21 3F\n\n0x32,0x32\n32 0G\n33\n"
rc, out, err = run("decode", "buwizz3", "--file", "-", stdin=hex_lines.encode())
check(rc == 1 and out.startswith("line 2: buwizz3 set_motor_data") and "line 4: buwizz3 set_data_period" in out
      and "error: line 5: bad hex: 'G' at character 4" in err and "error: line 6: set_ramp_rates: input too short (13 bytes) at byte 1" in err
      and "read as hex lines: lines 6, frames 4, decoded 2, errors 2" in err, f"hex lines: {rc} {out!r} {err!r}")
# a bad digit in a logged value is reported as in a hex line: the character and its place in the value (after "(0x) ")
for name, data, want in [
        ("hex line", "32-3G\n", ["error: line 1: bad hex: 'G' at character 4 is not a hex digit"]),
        ("Android log", f"I 10:12:09.072 Data written to {APP}, value: (0x) 32-3G\n"
                        f"I 10:12:09.073 Data written to {APP}, value: (0x) 32-G3, \"2G\"\n",
         ["error: 10:12:09.072 line 1: bad hex: 'G' at character 4 is not a hex digit",
          "error: 10:12:09.073 line 2: bad hex: 'G' at character 3 is not a hex digit"]),
        ("desktop log", "2026-03-14T10:15:03.127Z INFO Attribute value written, handle: 0x10, value (0x): 32-3G\n",
         ["error: 2026-03-14T10:15:03.127 line 1: bad hex: 'G' at character 4 is not a hex digit"])]:
    rc, out, err = run("decode", "buwizz3", "--file", "-", stdin=data.encode())
    check(rc == 1 and out == "" and err.splitlines()[:-1] == want, f"bad hex digit in a {name}: {rc} {err!r}")
# a log line given as an argument is a whole line: no "no line end" remark
rc, out, err = run("decode", "buwizz3", f"I 10:12:09.072 Data written to {APP}, value: (0x) 32-3G")
check(rc == 1 and out == "" and err.splitlines()[:1] == ["error: 10:12:09.072 line 1: bad hex: 'G' at character 4 is not a hex digit"]
      and "line end" not in err, f"bad hex digit in a log line argument: {rc} {err!r}")
rc, out, err = run("decode", "--file", "-", stdin=b"30 7F 81 00 40 C0 01 21 3F\n")
check(rc == 2 and "line 1: which protocol?" in err, f"hex lines without protocol: {rc} {err!r}")
rc, out, err = run("decode", "30", "7F")
check(rc == 2 and "30" in err, f"decode without protocol: {rc} {err!r}")
rc, out, err = run("decode", "osp", "--file", "-", stdin=b"# nothing\n\n")
check(rc == 1 and "no frame in stdin: 2 lines" in err, f"no frame: {rc} {err!r}")

# text rows of one message type with and without its optional block (a 68-byte status, the
# 54-byte form without pid_state, the 68-byte form again): each record as decode prints the frame alone
forms = [status_dashes, status_dashes[:54 * 3 - 1], status_dashes]
log = "nRF Connect, 2026-03-14\n" + "".join(f"I 10:12:0{i}.000 Notification received from {APP}, value: (0x) {v}\n"
                                            for i, v in enumerate(forms))
rc, out, err = run("decode", "buwizz3", "--file", "-", stdin=log.encode())
records = re.split(r"^2026-03-14T10:12:0\d\.000 line \d \(device to host\): ", out, flags=re.M)[1:]
alone = [run("decode", "buwizz3", v.replace("-", ""))[1] for v in forms]
check(rc == 0 and len(records) == 3 and records == alone and "  pid_state  " in alone[1]
      and "pid_state.output" in alone[0], f"text rows with and without an optional block: {out!r}")

# scan buwizz3: the same, errors in line on stdout, counters last
rc, out, err = run("scan", "buwizz3", "-", stdin=android_log.encode())
last = out.strip().splitlines()[-1]
check(rc == 0 and "line 22: error: set_motor_data.power: value out of range (valid -127..127 raw) at byte 1" in out and last.startswith("lines 25, frames 6, decoded 5, errors 1")
      and last.endswith("stdin read as nRF Connect (Android) log"), f"scan buwizz3: {rc} {last!r}")
# its hint lines follow the error, as decode gives them (power[0] is byte 1, 0x80 = -128 as int8)
check("line 22: error: set_motor_data.power: value out of range (valid -127..127 raw) at byte 1\n"
      "2026-03-14T10:12:09.300 line 22: hint: power[0] at byte 1 is -128 (0x80)\n" in out, f"scan buwizz3 hints: {out!r}")
rc, out, err = run("scan", "buwizz3", "-", "--json", stdin=android_log.encode())
errors = [parse_json(l) for l in out.splitlines() if '"type":"error"' in l]
check(len(errors) == 1 and errors[0].get("line") == 22 and errors[0].get("hints") == ["power[0] at byte 1 is -128 (0x80)"],
      f"scan buwizz3 --json hints: {errors}")
rc, out, err = run("scan", "buwizz3", "-", stdin=bytes.fromhex("30 7F 81 00 40 C0 01 21 3F"))
check(rc == 1 and "reads text" in err and "binary" in err, f"scan buwizz3 binary: {rc} {err!r}")

# scan navbot: multi-frame messages reassembled across lines, per direction (the robot echoes what it receives)
NW, NN = "6e400012-b5a3-f393-e0a9-e50e24dcca9e", "6e400013-b5a3-f393-e0a9-e50e24dcca9e"
def navbot_frames(text):  # the document's layout: 55 AA command remaining 00, 15 payload bytes, the last zero-padded
    b = text.encode()
    parts = [b[i:i + 15] for i in range(0, len(b), 15)]
    return ["-".join(f"{x:02X}" for x in bytes([0x55, 0xAA, 0x02, len(parts) - 1 - i, 0]) + p + bytes(15 - len(p)))
            for i, p in enumerate(parts)]
a = navbot_frames('{"type":"get_device_info"}')                          # 26 bytes: 2 frames
b = navbot_frames('{"type":"set_name","name":"NAVBOT-ES02 kitchen"}')  # 48 bytes: 4 frames
w = lambda t, v: f"I 11:02:{t} Data written to {NW}, value: (0x) {v}"
nt = lambda t, v: f"I 11:02:{t} Notification received from {NN}, value: (0x) {v}"
navbot_log = "\n".join([
    "nRF Connect, 2026-03-14", "NAVBOT-ES02 (C8:2E:18:4A:01:7F)", "I 11:02:00.100 Connected to C8:2E:18:4A:01:7F",
    w("01.000", a[0]), w("01.040", a[1]),                       # lines 4-5: complete
    nt("01.060", a[0]), nt("01.080", a[1]), nt("01.081", a[1]),  # lines 6-7 complete (echo), 8 duplicate
    w("02.000", b[0]), w("02.040", b[1]), w("02.045", b[0]),     # 9, 10, 11: restarted
    w("02.050", b[1]), w("02.060", b[2]), w("02.070", b[3]),     # 12-14: complete (lines 11-14)
    w("03.000", b[0]), w("03.010", b[2]),                       # 15, 16: a frame lost
    w("04.000", "55-AA-10-00-00-00-00-F6-00-01-00-00-00-00-00-00-00-00-00-00"),  # 17: maneuver pitch -10
]) + "\n"
rc, out, err = run("scan", "navbot", "-", stdin=navbot_log.encode())
check(rc == 0 and 'line 5: navbot reassembly: message complete, 2 frames (lines 4-5), command 0x02, 26 bytes of JSON: {"type":"get_device_info"}' in out
      and "line 7: navbot reassembly: message complete, 2 frames (lines 6-7)" in out
      and "line 8: navbot reassembly: duplicate" in out and "line 11: navbot reassembly: the sender started the message over" in out
      and 'line 14: navbot reassembly: message complete, 4 frames (lines 11-14), command 0x02, 48 bytes of JSON: {"type":"set_name","name":"NAVBOT-ES02 kitchen"}' in out
      and "line 16: navbot reassembly: frame out of sequence at byte 3: remaining 1 after 3, frames were lost; "
          "the partial message (line 15) is dropped" in out
      and "line 17 (host to device): navbot maneuver" in out and "pitch     -10 %" in out
      and "messages reassembled 3, duplicates 1, restarted 1" in out and "reassembly errors 1" in out, f"scan navbot: {rc} {out!r}")
rc, out, err = run("scan", "navbot", "-", "--json", stdin=navbot_log.encode())
docs = [parse_json(l) for l in out.splitlines()]
re_ = [(d["line"], d["outcome"]) for d in docs if d.get("type") == "reassembly"]
check(re_ == [(4, "need_more"), (5, "complete"), (6, "need_more"), (7, "complete"), (8, "duplicate"), (9, "need_more"),
              (10, "need_more"), (11, "restarted"), (12, "need_more"), (13, "need_more"), (14, "complete"), (15, "need_more"),
              (16, "error")]
      and [d for d in docs if d.get("outcome") == "complete"][2].get("lines") == [11, 12, 13, 14]
      and [d for d in docs if d.get("outcome") == "complete"][0].get("text") == '{"type":"get_device_info"}'
      and docs[-1].get("type") == "counters" and docs[-1].get("messages_reassembled") == 3 and docs[-1].get("frames") == 14,
      f"scan navbot --json: {re_} {docs[-1]}")
# the lines of a message are the lines its frames are on: a range only where they follow each other (here the
# robot's echo of each written frame, on the notify characteristic, comes between them)
c = navbot_frames('{"type":"get_device_info"}')
d = navbot_frames('{"type":"set_name","name":"NAVBOT-ES02 kitchen"}')
echoed = "\n".join(["nRF Connect, 2026-03-14",
                     w("01.000", c[0]), nt("01.010", c[0]), w("01.020", c[1]),                       # lines 2, 4: complete
                     w("02.000", d[0]), nt("02.010", d[0]), w("02.020", d[1]), w("02.030", d[3])]) + "\n"  # 5, 7, 8: d[2] lost
rc, out, err = run("scan", "navbot", "-", stdin=echoed.encode())
check(rc == 0 and '2026-03-14T11:02:01.020 line 4: navbot reassembly: message complete, 2 frames (lines 2, 4), command 0x02, '
                  '26 bytes of JSON: {"type":"get_device_info"}\n' in out
      and "2026-03-14T11:02:02.030 line 8: navbot reassembly: frame out of sequence at byte 3: remaining 0 after 2, frames were "
          "lost; the partial message (lines 5, 7) is dropped\n" in out, f"scan navbot: lines of a message with echoes between: {out!r}")
# a long message with an echo after each frame: the first three lines, "...", the last
e = navbot_frames('{"type":"set_name","name":"' + "N" * 120 + '"}')  # 149 bytes: 10 frames
long_log = "".join(f"{w(f'05.{2 * i:03}', f)}\n{nt(f'05.{2 * i + 1:03}', f)}\n" for i, f in enumerate(e))
rc, out, err = run("scan", "navbot", "-", stdin=long_log.encode())
check(rc == 0 and len(e) == 10 and "line 19: navbot reassembly: message complete, 10 frames (lines 1, 3, 5, ..., 19), command 0x02" in out
      and "line 20: navbot reassembly: message complete, 10 frames (lines 2, 4, 6, ..., 20), command 0x02" in out,
      f"scan navbot: lines of a long message: {out!r}")

# ---- monitor: a real pseudo-terminal pair from socat, a writer sending frames mixed with noise
def monitor(json_mode):
    d = tempfile.mkdtemp()
    a, b = os.path.join(d, "a"), os.path.join(d, "b")
    socat = subprocess.Popen(["socat", f"pty,raw,echo=0,link={a}", f"pty,raw,echo=0,link={b}"],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    for _ in range(100):
        if os.path.exists(a) and os.path.exists(b):
            break
        time.sleep(0.05)
    mon = subprocess.Popen([TOOL, "monitor", a, "--baud=115200", "--count", "4", "--timeout", "10"] + (["--json"] if json_mode else []),
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    time.sleep(0.5)
    with open(b, "wb", buffering=0) as w:
        for chunk in [b"\x00\x13\xff", bytes.fromhex("FF AA 02 12 D2 04 00 00 55 77"), b"\xff\xaa\x55\x77noise",
                      bytes.fromhex("FF AA 02 14 03 05 00 00"), bytes.fromhex("55 77 FF AA 00 11 02 00 00 00 55 77"),
                      bytes.fromhex("FF AA 03 01 0A 0B 0C 0D 55 77")]:
            w.write(chunk)
            time.sleep(0.05)
        out, err = mon.communicate(timeout=15)
    socat.terminate()
    shutil.rmtree(d, ignore_errors=True)
    return mon.returncode, out.decode(), err.decode()

if shutil.which("socat"):
    rc, out, err = monitor(False)
    check(rc == 0 and "osp voltage" in out and "osp status" in out and "osp device_type" in out and "unknown key 0x03 0x01 at byte 2" in out
          and "frames 4," in out, f"monitor over a pty: {out!r} {err!r}")
    rc, out, err = monitor(True)
    lines = [parse_json(l) for l in out.splitlines()]
    check(rc == 0 and [l.get("type") for l in lines] == ["message", "message", "message", "error", "counters"]
          and [l.get("message") for l in lines[:3]] == ["voltage", "status", "device_type"] and lines[-1].get("frames") == 4,
          f"monitor --json over a pty: {out!r} {err!r}")
else:
    check(False, "socat is not installed")

# ---- logs at scale: streamed line by line, time in every record, CSV, bad input costs its line only
import csv, io, select
td = tempfile.mkdtemp()
def tmp(name, data):
    path = os.path.join(td, name)
    with open(path, "wb") as fh:
        fh.write(data if isinstance(data, bytes) else data.encode())
    return path

# streaming: the first line's record comes out of a pipe before the second line is written
p = subprocess.Popen([TOOL, "decode", "buwizz3", "--file", "-"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                     stderr=subprocess.PIPE)
p.stdin.write(f"nRF Connect, 2026-03-14\nI 10:12:06.655 Notification received from {APP}, value: (0x) {status_dashes}\n".encode())
p.stdin.flush()
ready, _, _ = select.select([p.stdout], [], [], 10)
first = os.read(p.stdout.fileno(), 200).decode() if ready else ""
p.stdin.write(f"I 10:12:07.000 Data written to {APP}, value: (0x) 32-32\n".encode())
p.stdin.close()
rest = p.stdout.read().decode()
p.wait(timeout=10)
check(first.startswith("2026-03-14T10:12:06.655 line 2 (device to host): buwizz3 status") and "line 3 (host to device)" in rest
      and p.returncode == 0, f"streamed from a pipe: {first!r} {rest[-200:]!r}")

# memory: the peak RSS does not grow with the input (20 k and 200 k lines within 2 MB of each other, both under 20 MB)
def peak_rss_kb(path, *extra):
    with tempfile.NamedTemporaryFile("r") as t:
        subprocess.run(["/usr/bin/time", "-o", t.name, "-f", "%M", TOOL, "decode", "buwizz3", "--file", path, *extra],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=120)
        return int(t.read().split()[-1])
status_line = f"I 10:12:06.655 Notification received from {APP}, value: (0x) {status_dashes}\n"
small = tmp("small.log", "nRF Connect, 2026-03-14\n" + status_line * 20000)
big = tmp("big.log", "nRF Connect, 2026-03-14\n" + status_line * 200000)
if os.path.exists("/usr/bin/time"):
    for extra in ([], ["--json"]):
        a, b = peak_rss_kb(small, *extra), peak_rss_kb(big, *extra)
        check(b < 20 * 1024 and b - a < 2048, f"peak RSS {extra}: {a} KB at 20 k lines, {b} KB at 200 k lines")
else:
    check(False, "/usr/bin/time is not installed")
os.remove(big)

# time: the header's date, midnight rollover, ISO 8601 with milliseconds; --since / --until
roll = "nRF Connect, 2026-03-14\n" + "".join(f"I {t} Data written to {APP}, value: (0x) 32-32\n"
                                              for t in ["23:59:59.900", "00:00:00.100", "00:00:01.000"])
rc, out, err = run("decode", "buwizz3", "--file", "-", "--json", stdin=roll.encode())
check(rc == 0 and [parse_json(l).get("time") for l in out.splitlines()] ==
      ["2026-03-14T23:59:59.900", "2026-03-15T00:00:00.100", "2026-03-15T00:00:01.000"], f"time, rollover: {out!r}")
rc, out, err = run("decode", "buwizz3", "--file", "-", "--since", "2026-03-15T00:00:00.100", "--until", "2026-03-15T00:00:00.999",
                   stdin=roll.encode())
check(rc == 0 and out.startswith("2026-03-15T00:00:00.100 line 3 (host to device): buwizz3 set_data_period")
      and "line 2" not in out and "line 4" not in out and "outside time range 2" in err, f"--since/--until: {out!r} {err!r}")
# each line is counted once, the first that applies: without frame, other characteristics, outside time range, frames
ranged = "\n".join(["nRF Connect, 2026-03-14",
                     "I 10:12:05.120 Read Response received from 00002a00-0000-1000-8000-00805f9b34fb, value: (0x) 42-75, \"Bu\"",
                     f"I 10:12:08.000 Data written to {APP}, value: (0x) 32-32",
                     f"I 10:12:09.700 Data written to {APP}, value: (0x) 32-32"]) + "\n"
rc, out, err = run("decode", "buwizz3", "--file", "-", "--since", "10:12:09", stdin=ranged.encode())
check(rc == 0 and out.startswith("2026-03-14T10:12:09.700 line 4 (host to device): buwizz3 set_data_period")
      and err == "stdin: read as nRF Connect (Android) log: lines 4, frames 1, decoded 1, errors 0, lines without frame 1, "
                 "other characteristics 1, outside time range 1\n", f"summary: another characteristic outside the range: {rc} {err!r}")
rc, out, err = run("decode", "--file", "-", stdin=ranged.replace("42-75", "42-7G").encode())  # never a candidate, whatever its bytes
check(rc == 0 and err.endswith("lines 4, frames 2, decoded 2, errors 0, lines without frame 1, other characteristics 1\n"),
      f"summary: a bad value of another characteristic: {rc} {err!r}")
rc, out, err = run("decode", "buwizz3", "--file", "-", "--since", "25:00", stdin=roll.encode())
check(rc == 2 and "--since" in err, f"bad --since: {rc} {err!r}")
rc, out, err = run("decode", "buwizz3", "--file", "-", "--json", stdin=desktop_log.encode())
check([parse_json(l).get("time") for l in out.splitlines()] == ["2026-03-14T10:15:02.331", "2026-03-14T10:15:03.127"],
      f"desktop log times: {out!r}")
rc, out, err = run("decode", "buwizz3", "--file", "-", "--json", stdin=panel.encode())
check(parse_json(out).get("time") == "11:44:40.911", f"desktop panel: time of day only: {out!r}")
rc, out, err = run("decode", "buwizz3", "--file", "-", "--json", stdin=b"32 32\n")
check(rc == 0 and parse_json(out).get("line") == 1 and "time" not in parse_json(out), f"hex line: no time: {out!r}")

# CSV: one table per message, physical values with the unit in the header, time and line first
rc, out, err = run("decode", "buwizz3", "--file", "-", "--format", "csv", "--message", "status", stdin=android_log.encode())
rows = list(csv.reader(io.StringIO(out)))
head = rows[0] if rows else []
row = dict(zip(head, rows[1])) if len(rows) > 1 else {}
check(rc == 1 and len(rows) == 2 and head[:3] == ["time", "line", "direction"] and row.get("time") == "2026-03-14T10:12:06.655"
      and row.get("line") == "18" and row.get("battery_voltage[V]") == "13" and row.get("motor_current_0[A]") == "0.15"
      and row.get("motor_current_5[A]") == "3" and row.get("accel_0[mg]") == "-7.808" and row.get("temperature_c[degC]") == "35"
      and row.get("pu_motors_3.position[deg]") == "2147483647" and row.get("pid_state.output") == "12.75",
      f"CSV status: {rc} {out!r}")
buf = io.StringIO()
csv.writer(buf, lineterminator="\n").writerows(rows)
check(buf.getvalue() == out, "CSV round-trips through Python's csv")
rc, out, err = run("decode", "buwizz3", "20 4D 79 2C 22 42 22 00 00 00 00 00 00", "--direction", "command", "--format", "csv",
                   "--message", "set_device_name")
rows = list(csv.reader(io.StringIO(out)))
check(rc == 0 and rows == [["time", "line", "direction", "name"], ["", "", "", 'My,"B"']], f"CSV quoting: {out!r}")
outdir = os.path.join(td, "csv")
os.mkdir(outdir)
rc, out, err = run("decode", "buwizz3", "--file", "-", "--format", "csv", "--out-dir", outdir, stdin=android_log.encode())
check(sorted(os.listdir(outdir)) == ["buwizz3_charger_settings.csv", "buwizz3_check_charger_settings.csv",
                                     "buwizz3_set_data_period.csv", "buwizz3_set_motor_data.csv", "buwizz3_status.csv"]
      and out == "" and "wrote " in err, f"CSV --out-dir: {os.listdir(outdir)} {err!r}")
# --out-dir DIR that does not exist yet is created, its parents too; one that cannot be is an error before any decoding
newdir = os.path.join(td, "new", "csv")
rc, out, err = run("decode", "buwizz3", "--file", "-", "--format", "csv", "--out-dir", newdir, "--message", "status",
                   stdin=android_log.encode())
check(os.path.isdir(newdir) and os.listdir(newdir) == ["buwizz3_status.csv"] and out == ""
      and "wrote " + os.path.join(newdir, "buwizz3_status.csv") + "\n" in err and "cannot open" not in err,
      f"CSV --out-dir created when missing: {rc} {err!r}")
blocker = tmp("blocker", "a file, not a directory\n")
rc, out, err = run("decode", "buwizz3", "--file", "-", "--format", "csv", "--out-dir", os.path.join(blocker, "csv"),
                   stdin=android_log.encode())
check(rc == 1 and out == "" and err.startswith(f"error: --out-dir {os.path.join(blocker, 'csv')}: cannot create the directory: ")
      and len(err.splitlines()) == 1, f"CSV --out-dir that cannot be created: {rc} {err!r}")
rc, out, err = run("decode", "buwizz3", "--file", "-", "--format", "csv", stdin=android_log.encode())
check(rc == 2 and "--message" in err and out == "", f"CSV needs --message or --out-dir: {rc} {err!r}")

# bad input: one stray control byte costs its line, not the file
stray = ["FF AA 02 12 D2 04 00 00 55 77"] * 1000
stray[499] = "FF AA 02 12 D2\x0104 00 00 55 77"
stray_path = tmp("stray.txt", "\n".join(stray) + "\n")
rc, out, err = run("scan", "osp", stray_path, "--json")
last = parse_json(out.splitlines()[-1])
check(rc == 0 and last.get("frames") == 999 and last.get("lines_skipped") == 1 and last.get("input") == "hex text"
      and any(parse_json(l).get("line") == 500 and "control byte 0x01" in parse_json(l).get("error", "") for l in out.splitlines()),
      f"scan osp, a stray byte: {rc} {last}")
rc, out, err = run("decode", "osp", "--file", stray_path)
check(rc == 1 and out.count("osp voltage") == 999 and "error: line 500: not text: control byte 0x01 at character 14" in err
      and "decoded 999, errors 1" in err, f"decode --file, a stray byte: {rc} {err!r}")
# CR, LF and CRLF all end a line
for name, data in [("CR", "32 32\r30 7F 81 00 40 C0 01 21 3F\r32 32\r"), ("mixed", "32 32\r\n30 7F 81 00 40 C0 01 21 3F\n32 32\r")]:
    rc, out, err = run("decode", "buwizz3", "--file", "-", "--json", stdin=data.encode())
    check(rc == 0 and [(d.get("line"), d.get("message")) for d in map(parse_json, out.splitlines())] ==
          [(1, "set_data_period"), (2, "set_motor_data"), (3, "set_data_period")], f"{name} line ends: {out!r} {err!r}")
# a directory, an unreadable file, a closed stdin: an error, exit 1
for args in (["decode", "buwizz3", "--file", td], ["scan", "osp", td], ["scan", "navbot", td]):
    rc, out, err = run(*args)
    check(rc == 1 and "is a directory" in err and out == "", f"{args[:2]} on a directory: {rc} {err!r}")
rc, out, err = run("scan", "osp", "/proc/self/mem")
check(rc == 1 and "cannot read /proc/self/mem" in err, f"a read error: {rc} {err!r}")
for args in (["scan", "osp", "-"], ["decode", "buwizz3", "--file", "-"]):
    p = subprocess.run(["sh", "-c", 'exec "$0" "$@" <&-', TOOL, *args], capture_output=True, timeout=30)
    check(p.returncode == 1 and b"stdin is closed" in p.stderr, f"{args[:2]} with stdin closed: {p.returncode} {p.stderr!r}")
# an empty file is empty
empty = tmp("empty.txt", b"")
rc, out, err = run("decode", "buwizz3", "--file", empty)
check(rc == 1 and "no frame in " + empty + ": it is empty" in err and "binary" not in err, f"empty file: {rc} {err!r}")
rc, out, err = run("scan", "osp", empty, "--json")
check(rc == 0 and parse_json(out).get("input") == "empty" and parse_json(out).get("frames") == 0, f"scan an empty file: {out!r}")
# long values are shortened in messages
big_hex = "AB" * 61440
rc, out, err = run("encode", "buwizz3", "charger_settings", "data=" + big_hex)
check(rc == 1 and "(122880 characters)" in err and len(err) < 400, f"a 120 KB data= value: {len(err)} {err[:120]!r}")
rc, out, err = run("decode", "buwizz3", "--file", "-", stdin=("32 32\n" + "A" * 60001 + "\n").encode())
check(rc == 1 and "line 2: bad hex: odd number of hex digits" in err and "(60001 characters)" in err and len(err) < 600,
      f"a 60 KB bad hex line: {len(err)} {err[:120]!r}")
# NUL bytes, invalid UTF-8, a 1 MB line, a truncated last line: the line named, the rest decoded
for name, data, text in [
        ("NUL", b"32 32\n32\x0032\n32 32\n", "line 2: not text: control byte 0x00 at character 2"),
        ("invalid UTF-8", b"32 32\n32 \xc3\x28 32\n32 32\n", "line 2: bad hex: byte 0xC3 at character 3"),
        ("1 MB line", b"32 32\n" + b"32" * (1 << 19) + b"\n32 32\n", "line 2: line too long: 1048576 bytes"),
        ("truncated", b"32 32\n32 32\n30 7F 81 00 4", "line 3: bad hex: odd number of hex digits in \"4\""),
]:
    rc, out, err = run("decode", "buwizz3", "--file", "-", stdin=data)
    check(rc == 1 and text in err and len(err) < 600 and out.count("buwizz3 set_data_period") == 2, f"{name}: {rc} {err[:300]!r}")
    rc, out, err = run("decode", "buwizz3", "--file", "-", "--json", stdin=data)
    docs = [parse_json(l) for l in out.splitlines()]
    errors = [f"line {d.get('line')}: {d.get('error')}" for d in docs if d.get("type") == "error"]
    check(rc == 1 and len(errors) == 1 and text in errors[0] and len(out) < 2000 and all(docs)
          and sum(d.get("message") == "set_data_period" for d in docs) == 2, f"{name} --json: {rc} {errors!r}")
# every command that reads a file, for every protocol: no bad input answered with silence and exit 0
VALID = {"osp": "FF AA 02 12 D2 04 00 00 55 77", "buwizz3": "32 32",
         "navbot": "55 AA 10 00 00 00 00 00 00 01 00 00 00 00 00 00 00 00 00 00"}
READERS = [(["decode", p, "--file"], p) for p in VALID] + [(["scan", p], p) for p in VALID]
for cmd, proto in READERS:
    name = " ".join(cmd[:2])
    good = VALID[proto]
    # a directory, a file that cannot be opened, a read error, a closed stdin: exit 1 and the reason
    for path, why in [(td, "is a directory"), (os.path.join(td, "missing.txt"), "No such file or directory"),
                      ("/proc/self/mem", "cannot read /proc/self/mem")]:
        rc, out, err = run(*cmd, path)
        check(rc == 1 and why in err and out == "", f"{name} {path}: {rc} {err!r}")
    p_ = subprocess.run(["sh", "-c", 'exec "$0" "$@" <&-', TOOL, *cmd, "-"], capture_output=True, timeout=30)
    check(p_.returncode == 1 and b"stdin is closed" in p_.stderr, f"{name} with stdin closed: {p_.returncode} {p_.stderr!r}")
    # an empty file is empty, not binary
    rc, out, err = run(*cmd, empty)
    check("binary" not in out + err and ("empty" in out + err), f"{name} an empty file: {rc} {out!r} {err!r}")
    # CR, LF and CRLF each end a line; a stray control byte costs its line only
    for ends in ("\r", "\n", "\r\n"):
        lines = [good, good[:5] + "\x01" + good[5:], good]
        rc, out, err = run(*cmd, tmp("ends.txt", ends.join(lines) + ends), "--json")
        docs = [parse_json(l) for l in out.splitlines()]
        msgs = [d.get("line") for d in docs if d.get("type") == "message"]
        errs = [d for d in docs if d.get("type") == "error"]
        check(msgs == [1, 3] and len(errs) == 1 and errs[0].get("line") == 2 and "control byte 0x01" in errs[0].get("error", "")
              and (rc == 0 if cmd[0] == "scan" else rc == 1), f"{name} line ends {ends!r}: {rc} {out!r} {err!r}")
rc, out, err = run("decode", "buwizz3", "--file", "-", "--json", stdin=b"32 32\n32 \xc3\x28 32\n")
check(parse_json(out.splitlines()[-1]).get("line") == 2 and "0xC3" in parse_json(out.splitlines()[-1]).get("error", ""),
      f"invalid UTF-8: a valid JSON error line: {out!r}")
shutil.rmtree(td)

# ---- shared vectors (tests/vectors/vectors.json): decode errors in JSON, OSP frames in noise, NAVBOT multi-frame messages
for v in VECTORS["errors"]:
    if v["hex"]:
        extra = ["--direction", v["direction"]] if v["direction"] else []
        rc, out, err = run("decode", v["protocol"], v["hex"], "--json", *extra)
        doc = parse_json(out)
        check(rc == 1 and doc.get("type") == "error" and doc.get("error") == v["error"]
              and all(any(h in n for n in doc.get("hints", [])) for h in v.get("cli_hints", [])), f"decode --json error {v['hex']}: {out!r}")
for v in VECTORS["osp_scan"]:
    rc, out, err = run("scan", "osp", "--json", stdin=bytes.fromhex(v["hex"]))
    docs = [parse_json(l) for l in out.splitlines()]
    got = [{"message": d.get("message"), "fields": {k: d.get("fields", {}).get(k) for k in w["fields"]}} if "message" in w
           else {"error": d.get("error"), "bytes": d.get("bytes")} for d, w in zip(docs, v["records"])]
    want = [{"message": w["message"], "fields": w["fields"]} if "message" in w else {"error": w["error"], "bytes": w["bytes"]}
            for w in v["records"]]
    check(rc == 0 and len(docs) == len(want) + 1 and got == want and docs[-1].get("frames") == len(want),
          f"scan osp {v['hex']}: {out!r}")
for v in VECTORS["navbot_multiframe"]:
    rc, out, err = run("scan", "navbot", "--json", "-", stdin="".join(f + "\n" for f in v["frames"]).encode())
    docs = [parse_json(l) for l in out.splitlines() if parse_json(l).get("type") == "reassembly"]
    if len(v["frames"]) == 1:  # a message of one frame is decoded as it is, no reassembly
        docs = [{"outcome": "complete", "text": d.get("fields", {}).get("payload_text")} for d in map(parse_json, out.splitlines())
                if d.get("message") == "frame"]
    check(rc == 0 and [d.get("outcome") for d in docs] == v["outcomes"] and docs[-1].get("text") == v["text"],
          f"scan navbot {v['text']}: {out!r} {err!r}")
for v in VECTORS["navbot_reassembly"]:
    rc, out, err = run("scan", "navbot", "--json", "-", stdin="".join(f + "\n" for f in v["frames"]).encode())
    docs = [parse_json(l) for l in out.splitlines() if parse_json(l).get("type") == "reassembly"]
    errors = [d.get("error", "") for d in docs if d.get("outcome") == "error"]
    check([d.get("outcome") for d in docs] == v["outcomes"] and all(t == d.get("text") for d in docs if d.get("outcome") == "complete"
                                                                    for t in [v["text"]])
          and all(f"at byte {v['error']['offset']}" in e for e in errors), f"scan navbot {v['source']}: {out!r} {err!r}")

# ---- the examples in docs/cli.md and README.md are what the tool prints ("..." stands for the rest)
import shlex
root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")

def examples(lines, indent):
    found, cur = [], None
    for line in lines:
        if line.startswith(indent + "$ robowire "):
            cur = (line[len(indent) + 2:], [])
            found.append(cur)
        elif cur is not None and line.startswith(indent) and line.strip() and not line.startswith("```"):
            cur[1].append(line[len(indent):])
        else:
            cur = None
    return found

def check_examples(where, found):
    check(len(found) >= 3, f"{where}: examples found")
    for cmd, want in found:
        if not want:
            continue  # a command shown without output (a device)
        rc, out, err = run(*shlex.split(cmd)[1:])
        got = out.splitlines() + err.splitlines()
        if "..." in [w.strip() for w in want]:
            n = [w.strip() for w in want].index("...")
            ok = got[:n] == want[:n]
        else:
            ok = got == want
        check(ok, f"{where}: {cmd}: {got!r} != {want!r}")

with open(os.path.join(root, "docs", "cli.md")) as fh:
    doc = fh.read()
check_examples("docs/cli.md", examples(doc.split("## EXAMPLES")[1].split("\n## ")[0].splitlines(), "    "))
with open(os.path.join(root, "README.md")) as fh:
    readme = fh.read()
block = readme.split("The demo ends with the command-line tool")[1].split("```")[1]
check_examples("README.md", examples(block.splitlines(), ""))

print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
