"""decode / encode against golden vectors worked out by hand (vectors.py)."""
import pytest

import robowire
from robowire import buwizz3, navbot, osp
from vectors import CASES, ENCODE_ALSO, STATUS_54, STATUS_68, STATUS_68_FIELDS

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


@pytest.mark.parametrize("proto,hexs,message,kwargs", ENCODE_ALSO, ids=[f"{c[0]}-{c[2]}" for c in ENCODE_ALSO])
def test_golden_encode_other_spellings(proto, hexs, message, kwargs):
    # record fields left out are 0; an enumerator may be given as its number
    assert MODULES[proto].encode(message, **kwargs) == bytes.fromhex(hexs)


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


def test_advertisement_by_hand():
    # manufacturer data 4E 05 'B' 'W' 03 22 34 12: firmware 3.22, serial low 16 bits 0x1234
    adv = bytes.fromhex("02 01 06 09 FF 4E 05 42 57 03 22 34 12")
    # scan response: the service UUID on air (93 6E ... 05 50), and a name that is not UTF-8
    scan = bytes.fromhex("11 07 93 6E 67 B1 19 99 B3 88 81 44 FB 74 D1 92 05 50") + bytes([4, 0x09, 0x42, 0x57, 0xFF])
    assert buwizz3.parse_advertisement(adv, scan) == {
        "mode": "application", "firmware_version": (0x03, 0x22), "serial_low16": 0x1234,
        "has_manufacturer_data": True, "has_service_uuid": True, "local_name": "BW\ufffd"}
    # bootloader mode: 'B' 'L' instead of the version, serial 0
    assert buwizz3.parse_advertisement(bytes.fromhex("09 FF 4E 05 42 57 42 4C 00 00"))["mode"] == "bootloader"
    assert buwizz3.parse_advertisement(bytes.fromhex("02 01 06")) is None
    assert navbot.matches_advertisement(b"\x0f\x09navbot_es02-1A") and not navbot.matches_advertisement(b"\x05\x09abcd")
    assert navbot.is_navbot_name("navbot_es02-7F") and not navbot.is_navbot_name("navbot_es02-")


def test_uuids_from_the_document():
    # decisions.md: service 500592d1-..., characteristics substitute 2901, 8000, 3901..3904 for 92d1
    tail = "-74fb-4481-88b3-9919b1676e93"
    assert buwizz3.service_uuid == "500592d1" + tail
    assert buwizz3.application_uuid == "50052901" + tail and buwizz3.bootloader_uuid == "50058000" + tail
    assert [buwizz3.uart_characteristic(n) for n in (1, 4)] == ["50053901" + tail, "50053904" + tail]
    assert navbot.service_uuid == "6e400011-b5a3-f393-e0a9-e50e24dcca9e"
    assert (navbot.write_uuid[:8], navbot.notify_uuid[:8]) == ("6e400012", "6e400013")


def test_unit_helpers_by_hand():
    assert buwizz3.battery_volts(80) == pytest.approx(13.0) and buwizz3.battery_millivolts(80) == 13000
    assert buwizz3.motor_amps(200) == pytest.approx(3.0) and buwizz3.motor_milliamps(200) == 3000
    assert buwizz3.accel_count(-16) == -1 and buwizz3.accel_micro_g(2048) == 999424
    assert buwizz3.accel_milli_g(2048) == pytest.approx(999.424) and buwizz3.accel_milli_g_rounded(-16) == -8
    assert buwizz3.lpf_hz("hz_6_25") == 6.25 and buwizz3.lpf_hz(0b0010) == 50.0 and buwizz3.lpf_from_hz(100) == "hz_100"
    # 100 / (T x 7.8125): 1 s -> 12.8 -> 13; 0.1 s -> 128
    assert buwizz3.ramp_rate_from_seconds(1.0) == 13 and buwizz3.ramp_rate_from_seconds(0.1) == 128
    assert buwizz3.ramp_seconds(0) == 0.0 and buwizz3.ramp_seconds(128) == pytest.approx(0.1)
    assert buwizz3.current_limit_raw(1500) == 50 and buwizz3.current_limit_raw(1500, step_ma=35) == 43
    assert buwizz3.current_limit_ma(100) == 3000.0
    # K_LP = 1 - Ts / (Ts + 1 / (2 pi f)), Ts = 0.01 s; f = 10 Hz: 1 - 0.01 / (0.01 + 0.0159155) = 1 - 0.38587 = 0.61413
    assert buwizz3.k_lp_from_cutoff(10.0) == pytest.approx(0.61413, abs=1e-5)
    assert osp.volts(1234) == pytest.approx(12.34) and osp.millivolts(1234) == 12340
    assert osp.millivolts(12600, osp.scale.published_firmware) == 12600
    assert osp.volts(12600, scale=osp.scale.published_firmware) == pytest.approx(12.6)
    assert osp.amps(-1500) == pytest.approx(-1.5) and osp.milliamps(-1500) == -1500
    # SOC: 65535 = 100 % (document), 10000 = 100 % (published firmware); 32768 -> 5000.08 -> 5000 bp
    assert osp.soc_percent(65535) == pytest.approx(100.0) and osp.soc_basis_points(32768) == 5000
    assert osp.soc_percent(5000, osp.scale.published_firmware) == pytest.approx(50.0)
    assert osp.soc_from_percent(100.0) == 65535 and osp.soc_from_basis_points(5000) == 32768
    assert osp.voltage_from_millivolts(12345) == 1235  # rounded to 10 mV
    # ARM-1 angle: 16384 = pi; 0xC000 is -16384 to the published firmware
    assert osp.angle_to_radians(16384) == pytest.approx(3.141592653589793)
    assert osp.angle_count(0xC000) == 0xC000 and osp.angle_count(0xC000, osp.scale.published_firmware) == -16384
    assert osp.angle_from_radians(-3.141592653589793, osp.scale.published_firmware) == 0xC000
