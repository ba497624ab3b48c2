"""robowire.schema() against the documents, and the Python package against
the command-line tool: the same tables (list --json) and the same JSON line."""
import json
import subprocess

import pytest

import robowire
from robowire import buwizz3, navbot, osp
from vectors import CASES, STATUS_68

MODULES = {"buwizz3": buwizz3, "navbot": navbot, "osp": osp}


def message(proto, name):
    entry = robowire.schema(proto)["protocols"][0]
    return next(m for m in entry["messages"] if m["name"] == name)


def test_schema_shape():
    s = robowire.schema()
    assert s["format"] == 1
    assert [p["name"] for p in s["protocols"]] == ["buwizz3", "navbot", "osp"]
    assert buwizz3.schema() == s["protocols"][0] and osp.schema() == s["protocols"][2]
    names = [m["name"] for m in s["protocols"][1]["messages"]]
    assert names == ["maneuver", "frame"]


def test_schema_against_the_documents():
    # BuWizz3 0x30 set motor data: 9 bytes, 6 x i8 power -127..127 at byte 1, flags at 7 and 8 (bits 0-5)
    m = message("buwizz3", "set_motor_data")
    assert (m["direction"], m["key"], m["lengths"]) == ("command", [0x30], [[9, 9]])
    power = m["fields"][0]
    assert (power["name"], power["offset"], power["type"], power["count"], power["valid"]) == \
        ("power", 1, "i8", 6, {"min": -127, "max": 127})
    assert power["unit"]["name"] == "%" and power["unit"]["scale"] == pytest.approx(100 / 127)
    assert [b["name"] for b in m["fields"][1]["flag_bits"]] == ["port1", "port2", "port3", "port4", "port5", "port6"]
    # status: 54 or 68..129 bytes; battery 9 V + raw x 0.05 V at byte 2; 4 PU motors of 8 bytes at 22
    m = message("buwizz3", "status")
    assert (m["direction"], m["lengths"]) == ("notification", [[54, 54], [68, 129]])
    by_name = {f["name"]: f for f in m["fields"]}
    assert by_name["battery_voltage_raw"]["unit"] == {"name": "V", "scale": 0.05, "offset": 9.0, "raw_is_physical": False}
    pu = by_name["pu_motors"]
    assert (pu["offset"], pu["count"], pu["element_size"], pu["type"]) == (22, 4, 8, "record")
    assert [f["name"] for f in pu["record"]["fields"]] == ["type", "velocity", "absolute_position", "position"]
    assert by_name["pid_state"]["optional"] and by_name["pid_state"]["offset"] == 54
    battery = [b for b in by_name["flags"]["flag_bits"] if b["name"] == "battery"][0]
    assert (battery["lo"], battery["width"], battery["values"]) == (3, 2, ["empty", "low", "medium", "full"])
    # 0x37 LPF: the eight settings of the document
    setting = message("buwizz3", "set_accel_lpf")["fields"][0]
    assert {e["name"]: e["value"] for e in setting["enum"]} == {
        "hz_0_781": 0b1000, "hz_1_563": 0b1001, "hz_3_125": 0b1010, "hz_6_25": 0b1011,
        "hz_12_5": 0b0000, "hz_25": 0b0001, "hz_50": 0b0010, "hz_100": 0b0011}
    # blink byte: frequency bits 7-4, duty bits 3-0
    blink = message("buwizz3", "set_led_status")["fields"][1]["record"]["fields"]
    assert [(f["name"], f["bits"]) for f in blink] == [("frequency_hz", {"lo": 4, "width": 4}), ("duty", {"lo": 0, "width": 4})]
    # OSP: DEV CMD keys, 10-byte frames
    m = message("osp", "status")
    assert (m["key"], m["lengths"]) == ([0x02, 0x14], [[10, 10]])
    assert [(f["offset"], f["name"]) for f in message("osp", "set_angle")["fields"]] == [(4, "joint"), (5, "angle")]
    # NAVBOT maneuver: pitch at byte 7, -100..100 %
    pitch = [f for f in message("navbot", "maneuver")["fields"] if f["name"] == "pitch"][0]
    assert (pitch["offset"], pitch["valid"], pitch["unit"]["name"]) == (7, {"min": -100, "max": 100}, "%")


def test_protocols_from_the_descriptors():
    assert robowire.protocols == ["buwizz3", "navbot", "osp"]
    assert [p["name"] for p in robowire.schema()["protocols"]] == robowire.protocols
    with pytest.raises(KeyError, match=r"unknown protocol 'foo' \(buwizz3, navbot, osp\)"):
        robowire.schema("foo")


def test_error_codes():
    assert robowire.error_codes["value_out_of_range"] == "value out of range"
    assert robowire.error_codes["bad_length"] == "length matches no form of the message"
    # the codes after bad_json too: the count comes from the library's table
    assert robowire.error_codes["not_handled"] == "message not handled"
    assert len(robowire.error_codes) == 19 and "ok" not in robowire.error_codes


def test_schema_lists_every_error_code():
    errors = robowire.schema()["errors"]
    assert errors[0] == {"code": 0, "name": "ok", "text": "ok"}
    assert errors[-1] == {"code": 19, "name": "not_handled", "text": "message not handled"}
    assert [e["code"] for e in errors] == list(range(20))
    assert {e["name"]: e["text"] for e in errors if e["name"] != "ok"} == robowire.error_codes


def test_cli_list_json_is_the_schema(cli):
    out = subprocess.run([cli, "list", "--json"], capture_output=True, text=True, check=True).stdout
    assert json.loads(out) == robowire.schema()
    out = subprocess.run([cli, "list", "osp", "--json"], capture_output=True, text=True, check=True).stdout
    assert json.loads(out) == robowire.schema("osp")


@pytest.mark.parametrize("proto,direction,hexs,name,fields,kwargs", CASES + [("buwizz3", None, STATUS_68.hex(), "status", {}, {})],
                         ids=[f"{c[0]}-{c[3]}-{len(c[2])}" for c in CASES] + ["buwizz3-status68"])
def test_decode_is_the_cli_json_line(cli, proto, direction, hexs, name, fields, kwargs):
    args = [cli, "decode", proto, hexs, "--json"] + (["--direction", direction] if direction else [])
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    m = MODULES[proto]
    mine = m.decode(bytes.fromhex(hexs), direction=direction) if direction else m.decode(bytes.fromhex(hexs))
    assert mine == json.loads(out)


@pytest.mark.parametrize("proto,hexs", [
    ("buwizz3", "32 0A"), ("buwizz3", "37 05"), ("navbot", "55 AA 10 00 00 00 00 8A 00 01 00 00 00 00 00 00 00 00 00 00"),
    ("osp", "FF AA 00 11 07 00 00 00 55 77"),
])
def test_decode_errors_name_what_the_cli_names(cli, proto, hexs):
    p = subprocess.run([cli, "decode", proto, hexs, "--json"], capture_output=True, text=True)
    assert p.returncode == 1
    cli_error = json.loads(p.stdout)["error"]
    with pytest.raises(robowire.DecodeError) as e:
        MODULES[proto].decode(bytes.fromhex(hexs))
    # both name the error, the byte and the field
    assert f"at byte {e.value.offset}" in cli_error and e.value.field in cli_error


def test_schema_version_2_against_the_documents():
    s = robowire.schema()
    assert (s["format"], s["schema_version"]) == (1, 2)
    bw, nb, op = s["protocols"]
    # BuWizz3: byte 0 is the command; 0x40 UART baudrate setup carries "0x40 - send command" at byte 1,
    # which the dispatcher does not read: the key is byte 0 alone
    # one characteristic, 0x2901 in the service UUID 500592d1-74fb-4481-88b3-9919b1676e93, write + notify
    assert [(c["uuid"], c["carries"]) for c in bw["characteristics"]] == [
        ("50052901-74fb-4481-88b3-9919b1676e93", "both")]
    assert bw["key_offsets"] == [0] and message("buwizz3", "set_uart_baudrate")["key"] == [0x40]
    # NAVBOT: 55 AA then the command byte (index 2); write 6E400012, notify 6E400013
    assert nb["key_offsets"] == [2] and message("navbot", "maneuver")["key"] == [0x10]
    assert [(c["uuid"], c["carries"]) for c in nb["characteristics"]] == [
        ("6e400012-b5a3-f393-e0a9-e50e24dcca9e", "to_device"),
        ("6e400013-b5a3-f393-e0a9-e50e24dcca9e", "from_device")]
    assert nb["frame"]["name"] == "frame" and nb["frame"]["lengths"] == [[20, 20]]
    assert [(b["offset"], b["value"]) for b in nb["frame"]["fixed"]] == [(0, 0x55), (1, 0xAA)]
    # OSP: FF AA DEV CMD P1..P4 55 77 on a serial line, no GATT
    assert (op["key_offsets"], op["characteristics"], op["stream"]) == ([2, 3], [], "scanner")
    assert [(b["offset"], b["value"]) for b in op["frame"]["fixed"]] == [(0, 0xFF), (1, 0xAA), (8, 0x55), (9, 0x77)]
    # physical values: battery_voltage_raw -> battery_voltage; a bool is 0 or 1
    status = {f["name"]: f for f in message("buwizz3", "status")["fields"]}
    assert status["battery_voltage_raw"]["physical"] == "battery_voltage"
    assert status["flags"]["physical"] is None
    bools = [f for m in bw["messages"] for f in m["fields"] if f["value"] == "bool"]
    assert bools and all(f["valid"] == {"min": 0, "max": 1} for f in bools)
    assert "15 significant digits" in s["output"]["physical"]
    # unit helpers (docs/buwizz3.md, docs/osp.md): percent x 127 / 100 half away from zero (50 % -> 64,
    # -50 % -> -64), error at the first power byte; OSP voltage mV / 10 half away from zero, error at P1
    helpers = {h["name"]: h for p in (bw, op) for h in p["unit_helpers"]}
    power = helpers["power_from_percent"]
    assert (power["message"], power["field"], power["rounding"]) == ("set_motor_data", "power", "half_away_from_zero")
    assert power["input"] == {"unit": "%", "range": {"of": "input", "min": -100, "max": 100}}
    assert power["error"] == {"code": "value_out_of_range", "offset": 1}
    volt = helpers["obp1::voltage_from_millivolts"]
    assert (volt["field"], volt["rounding"], volt["error"]["offset"]) == ("centivolts", "half_away_from_zero", 4)
    assert helpers["obp1::soc_from_basis_points"]["input"]["range"] == {"of": "input", "min": 0, "max": 10000}
