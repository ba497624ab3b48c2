"""decode / encode against golden vectors worked out by hand (vectors.py)."""
import pytest

import robowire
from robowire import buwizz3, navbot, osp
from vectors import CASES, STATUS_54, STATUS_68, STATUS_68_FIELDS

MODULES = {"buwizz3": buwizz3, "navbot": navbot, "osp": osp}


@pytest.mark.parametrize("proto,direction,hexs,message,fields,kwargs", CASES, ids=[f"{c[0]}-{c[3]}-{len(c[2])}" for c in CASES])
def test_golden_decode(proto, direction, hexs, message, fields, kwargs):
    m = MODULES[proto]
    d = m.decode(bytes.fromhex(hexs), direction=direction) if direction else m.decode(bytes.fromhex(hexs))
    assert d["type"] == "message" and d["protocol"] == proto and d["message"] == message
    for name, want in fields.items():
        assert d["fields"][name] == want, name


@pytest.mark.parametrize("proto,direction,hexs,message,fields,kwargs", CASES, ids=[f"{c[0]}-{c[3]}-{len(c[2])}" for c in CASES])
def test_golden_encode(proto, direction, hexs, message, fields, kwargs):
    m = MODULES[proto]
    assert m.encode(message, **kwargs) == bytes.fromhex(hexs)
    # and from what decode returns
    d = m.decode(bytes.fromhex(hexs), direction=direction) if direction else m.decode(bytes.fromhex(hexs))
    assert m.encode(d) == bytes.fromhex(hexs)


def test_buwizz3_direction_from_command_byte_and_length():
    # 0x01 is only a notification, 0x30 only a command
    assert buwizz3.decode(STATUS_54)["message"] == "status"
    assert buwizz3.decode(bytes.fromhex("30 00 00 00 00 00 00 00 00"))["message"] == "set_motor_data"
    # 0x23: 1 byte is the command, 25 bytes the notification
    assert buwizz3.decode(b"\x23")["message"] == "read_accel_calibration"
    assert buwizz3.decode(b"\x23" + bytes(24))["message"] == "accel_calibration"
    # 0xAC with data is the notification; alone it could be either
    assert buwizz3.decode(b"\xac\x01")["message"] == "charger_settings"
    with pytest.raises(ValueError, match="direction='command' or direction='notification'") as e:
        buwizz3.decode(b"\xac")
    assert not isinstance(e.value, robowire.DecodeError)
    assert buwizz3.decode(b"\xac", direction="command")["message"] == "check_charger_settings"
    assert buwizz3.decode(b"\xac", direction="notification") == {
        "type": "message", "protocol": "buwizz3", "message": "charger_settings", "fields": {"data": ""}}


def test_status_whole_dict():
    d = buwizz3.decode(STATUS_68)
    assert d == {"type": "message", "protocol": "buwizz3", "message": "status", "fields": STATUS_68_FIELDS}
    # the 54-byte form: no PID block
    d54 = buwizz3.decode(STATUS_54)
    assert d54["fields"]["pid_state"] is None
    assert buwizz3.encode(d54) == STATUS_54
    # longer than 68 bytes (up to 129): the rest is ignored
    assert buwizz3.decode(STATUS_68 + bytes(61))["fields"] == STATUS_68_FIELDS


def test_status_flags_bits_by_hand():
    # 0x6D = 0110 1101: error, long_range_phy, battery bits 3-4 = 01 (low), charging, usb_connected
    s = bytearray(STATUS_54)
    s[1] = 0x6D
    bits = buwizz3.decode(bytes(s))["fields"]["flags_bits"]
    assert bits == {"error": True, "motion_wakeup": False, "long_range_phy": True, "battery": "low",
                    "charging": True, "usb_connected": True}


def test_bytes_like_inputs():
    frame = bytes.fromhex("FF AA 02 12 D2 04 00 00 55 77")
    want = {"type": "message", "protocol": "osp", "message": "voltage",
            "fields": {"centivolts": 1234, "centivolts_physical": {"value": 12.34, "unit": "V"}}}
    assert osp.decode(frame) == want
    assert osp.decode(bytearray(frame)) == want
    assert osp.decode(memoryview(b"xx" + frame)[2:]) == want


def test_physical_values_by_hand():
    # BuWizz3 power: raw x 100/127 %; 127 -> 100 %, 64 -> 50.3937007874016 % (15 digits)
    d = buwizz3.decode(bytes.fromhex("30 7F 81 00 40 C0 01 21 3F"))["fields"]
    assert d["power_physical"] == {"value": [100.0, -100.0, 0.0, 50.3937007874016, -50.3937007874016, 0.78740157480315], "unit": "%"}
    assert d["brake_flags_bits"] == {"port1": True, "port2": False, "port3": False, "port4": False, "port5": False, "port6": True}
    # OSP current: mA x 0.001 A; SOC 65535 = 100 %
    assert osp.decode(bytes.fromhex("FF AA 02 13 24 FA 00 00 55 77"))["fields"]["milliamps_physical"] == {"value": -1.5, "unit": "A"}
    assert osp.decode(bytes.fromhex("FF AA 02 11 FF FF 00 00 55 77"))["fields"]["soc"] == {"value": 100.0, "unit": "%"}
    # blink duty: (raw + 1) / 16
    d = buwizz3.decode(bytes.fromhex("36 FF 00 00 00 FF 00 00 00 FF 10 20 30 1F F0 08 55"))["fields"]
    assert d["blink"][0] == {"frequency_hz": 1, "frequency_hz_physical": {"value": 1.0, "unit": "Hz"},
                             "duty": 15, "duty_physical": {"value": 16.0, "unit": "/16"}}


def test_navbot_sign_magnitude_note():
    # yaw -1 is 0xFF: the document's sample spelling would read it as -127
    d = navbot.decode(bytes.fromhex("55 AA 10 00 00 9C 64 37 FF 02 01 01 02 FB 05 00 00 00 00 00"))
    assert d["notes"] == [
        "roll at byte 5 is 0x9C = -100 (two's complement, what the robot reads); in the sign-magnitude spelling of the "
        "protocol document's samples 0x9C = -28",
        "yaw at byte 8 is 0xFF = -1 (two's complement, what the robot reads); in the sign-magnitude spelling of the "
        "protocol document's samples 0xFF = -127",
        "ball_x at byte 13 is 0xFB = -5 (two's complement, what the robot reads); in the sign-magnitude spelling of the "
        "protocol document's samples 0xFB = -123",
    ]
    assert "notes" not in navbot.decode(bytes.fromhex("55 AA 10 00 00 00 00 0A 00 01 00 00 00 00 00 00 00 00 00 00"))


def test_navbot_drive_forward_by_hand():
    # maneuver: 55 AA 10 00 00, roll 0, height 0, pitch -10 = 0xF6, yaw 0, switch_a start = 1, rest 0
    assert navbot.encode("maneuver", switch_a="start", pitch=-10) == bytes.fromhex(
        "55 AA 10 00 00 00 00 F6 00 01 00 00 00 00 00 00 00 00 00 00")


def test_defaults_are_the_structs():
    # fields not given keep the library's defaults: set_data_period 50 ms, PU ports simple PWM (0x10)
    assert buwizz3.encode("set_data_period") == b"\x32\x32"
    assert buwizz3.encode("set_pu_port_function") == bytes.fromhex("50 10 10 10 10")


def test_text_round_trip_and_decoding():
    assert buwizz3.encode("set_device_name", name="") == bytes.fromhex("20" + "00" * 12)
    assert buwizz3.encode("set_device_name", name="Twelve chars") == b"\x20Twelve chars"
    assert buwizz3.decode(b"\x20Twelve chars")["fields"]["name"] == "Twelve chars"


def test_tail_as_hex_text_or_bytes():
    for data in (b"\x01\x02\x03", bytearray(b"\x01\x02\x03"), "01 02 03", "010203"):
        assert buwizz3.encode("charger_settings", data=data) == bytes.fromhex("AC 01 02 03")


def test_presets_encode():
    # the document's speed servo column: out_lp 0.5, d_lp 0.5, speed_lp 0.9, kp 0.8, ki 0.06, kd -3,
    # lim_i 127, rate 0, lim_out 127, deadbands 2 2, mode 0x14; port 1 (index)
    d = buwizz3.speed_servo_preset(1)
    assert d["message"] == "set_pid_parameters"
    assert d["fields"]["port"] == 1 and d["fields"]["mode"] == "pu_speed_servo" and d["fields"]["lim_out"] == 127
    frame = buwizz3.encode(d)
    assert frame[:2] == b"\x53\x01" and frame[34:] == bytes([127, 2, 2, 0x14])
    assert frame[2:6] == bytes.fromhex("0000003F")  # 0.5f little-endian
    assert buwizz3.encode(buwizz3.default_current_limits()) == bytes.fromhex("38 32 32 32 32 64 64")
