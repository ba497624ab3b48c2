"""Every error path: DecodeError / EncodeError with code, offset, field and
describe_error's text (worked out by hand from its documented format),
TypeError / KeyError / ValueError for calls that are wrong in shape."""
import pytest

import robowire
from robowire import DecodeError, EncodeError, buwizz3, navbot, osp
from vectors import ERRORS, STATUS_68


def decode_error(fn, *args, **kwargs):
    with pytest.raises(DecodeError) as e:
        fn(*args, **kwargs)
    return e.value


def encode_error(fn, *args, **kwargs):
    with pytest.raises(EncodeError) as e:
        fn(*args, **kwargs)
    return e.value


def test_errors_are_value_errors():
    assert issubclass(DecodeError, ValueError) and issubclass(EncodeError, ValueError)
    assert not issubclass(DecodeError, EncodeError) and not issubclass(EncodeError, DecodeError)


MODULES = {"buwizz3": buwizz3, "navbot": navbot, "osp": osp}


@pytest.mark.parametrize("v", ERRORS, ids=[f"{v['protocol']}-{v['code']}-{v['hex'][:14]}" for v in ERRORS])
def test_decode_errors(v):
    """tests/vectors/vectors.json's errors: code, offset, field, message, describe_error's line."""
    m = MODULES[v["protocol"]]
    kwargs = {"direction": v["direction"]} if v["direction"] else {}
    e = decode_error(m.decode, bytes.fromhex(v["hex"]), **kwargs)
    assert (e.code, e.offset, e.field, e.message, str(e)) == (v["code"], v["offset"], v["field"], v["message"], v["error"])
    assert v["code"] in robowire.error_codes


def test_decode_error_notes():
    """What describe_error's line leaves out comes as notes (the tool's hints)."""
    e = decode_error(navbot.decode, bytes.fromhex("55 AA 02 00"))
    assert e.notes == ["NAVBOT frames are 20 bytes"]
    e = decode_error(osp.decode, bytes.fromhex("FF AA 00 11 07 00 00 00 55 77"))
    assert e.notes == ["DEV 00 CMD 11 params 07 00 00 00"]
    e = decode_error(osp.decode, bytes.fromhex("FF AA 03 01 0A 0B 0C 0D 55 77"))
    assert e.notes == ["DEV 03 CMD 01 params 0A 0B 0C 0D"]


def test_navbot_22_byte_sample_explained():
    e = decode_error(navbot.decode, bytes(22))  # markers are checked before the length
    assert (e.code, e.offset) == ("bad_header", 0)
    e = decode_error(navbot.decode, bytes.fromhex("55 AA 10 00 00" + "00" * 17))
    assert e.code == "too_long" and e.offset == 20
    assert "the protocol document's sample frames have 2 extra bytes" in e.notes[0]


def test_navbot_error_notes():
    e = decode_error(navbot.decode, bytes.fromhex("55 AA 10 00 00 00 00 8A 00 01 00 00 00 00 00 00 00 00 00 00"))
    assert e.notes == ["pitch at byte 7 is 0x8A = -118 (two's complement, what the robot reads); in the sign-magnitude "
                       "spelling of the protocol document's samples 0x8A = -10"]


def test_buwizz3_unknown_and_wrong_direction():
    e = decode_error(buwizz3.decode, b"\x99")
    assert (e.code, e.offset, str(e), e.notes) == ("unknown_message", 0, "unknown key 0x99 at byte 0",
                                                   ["0x99 is no BuWizz3 command or notification"])
    e = decode_error(buwizz3.decode, STATUS_68, direction="command")
    assert (e.code, str(e), e.notes) == ("unknown_message", "unknown key 0x01 at byte 0", ["0x01 is the notification status"])
    e = decode_error(buwizz3.decode, b"\x30" + bytes(8), direction="notification")
    assert (e.code, str(e), e.notes) == ("unknown_message", "unknown key 0x30 at byte 0", ["0x30 is the command set_motor_data"])
    # 0x23 with a length neither direction takes: decoded as the command, both named
    e = decode_error(buwizz3.decode, b"\x23\x00")
    assert str(e) == "read_accel_calibration: input too long (1 byte) at byte 1"
    assert e.code == "too_long" and e.notes == ["0x23 is the command read_accel_calibration (1 byte) and the notification "
                                                "accel_calibration (25 bytes); 2 bytes given"]
    with pytest.raises(ValueError, match="direction"):
        buwizz3.decode(b"\x01", direction="up")
    with pytest.raises(ValueError, match="buwizz3 only"):
        osp.decode(bytes(10), direction="command")
    with pytest.raises(ValueError, match="buwizz3 only"):
        navbot.decode(bytes(20), direction="command")


@pytest.mark.parametrize("module,message,kwargs,code,offset,field,text", [
    (navbot, "maneuver", {"pitch": 200}, "value_out_of_range", 7, "pitch", "maneuver.pitch: value out of range (valid -100..100 %) at byte 7"),
    (navbot, "maneuver", {"height": -1}, "value_out_of_range", 6, "height", "maneuver.height: value out of range (valid 0..100 %) at byte 6"),
    (navbot, "maneuver", {"switch_a": "jump"}, "invalid_enum", 9, "switch_a", "maneuver.switch_a: value is not a valid code at byte 9"),
    (navbot, "maneuver", {"switch_d": 7}, "invalid_enum", 12, "switch_d", "maneuver.switch_d: value is not a valid code at byte 12"),
    (buwizz3, "set_motor_data", {"power": [0, 0, -128, 0, 0, 0]}, "value_out_of_range", 3, "power",
     "set_motor_data.power: value out of range (valid -127..127 raw) at byte 3"),
    (buwizz3, "set_motor_data", {"brake_flags": 0x40}, "value_out_of_range", 7, "brake_flags",
     "set_motor_data.brake_flags: value out of range (valid 0..63) at byte 7"),
    (buwizz3, "set_data_period", {"period_ms": 10}, "value_out_of_range", 1, "period_ms",
     "set_data_period.period_ms: value out of range (valid 20..255 ms) at byte 1"),
    (buwizz3, "set_data_period", {"period_ms": 2 ** 70}, "value_out_of_range", 1, "period_ms",
     "set_data_period.period_ms: value out of range (valid 20..255 ms) at byte 1"),
    (buwizz3, "set_motion_wakeup", {"enabled": 2}, "value_out_of_range", 1, "enabled",
     "set_motion_wakeup.enabled: value out of range (valid 0..1) at byte 1"),
    (buwizz3, "set_device_name", {"name": "Thirteen char"}, "value_out_of_range", 1, "name",
     "set_device_name.name: value out of range at byte 1"),
    # the offset is the first absent block's (encoded_size in core/detail/encode.hpp)
    (buwizz3, "set_led_status", {"blink": [{}, {}, {}, {}]}, "missing_field", 1, "colors",
     "set_led_status.colors: optional block present without the one before it at byte 1"),
    (buwizz3, "set_led_status", {"colors": [{}, {"g": 256}, {}, {}]}, "value_out_of_range", 5, "colors.g",
     "set_led_status.colors: value out of range at byte 5"),
    (buwizz3, "charger_settings", {"data": bytes(129)}, "capacity_exceeded", 1, "data",
     "charger_settings.data: capacity exceeded at byte 1"),
    (buwizz3, "set_accel_calibration", {"factors": [1e39, 0, 0, 0, 0, 0]}, "value_out_of_range", 1, "factors",
     "set_accel_calibration.factors: value out of range at byte 1"),
    (osp, "set_angle", {"angle": 65536}, "value_out_of_range", 5, "angle",
     "set_angle.angle: value out of range (valid 0..65535 raw) at byte 5"),
])
def test_encode_errors(module, message, kwargs, code, offset, field, text):
    e = encode_error(module.encode, message, **kwargs)
    assert (e.code, e.offset, e.field, e.message, str(e)) == (code, offset, field, message, text)


def test_encode_error_notes():
    """What the line cannot say (a text's capacity, a record member's range, a float) comes as a note."""
    assert encode_error(buwizz3.encode, "set_device_name", name="Thirteen char").notes == ["name holds up to 12 bytes of UTF-8"]
    assert encode_error(buwizz3.encode, "set_led_status", colors=[{}, {"g": 256}, {}, {}]).notes == ["colors.g: valid 0..255"]
    assert encode_error(buwizz3.encode, "set_accel_calibration", factors=[1e39] + [0] * 5).notes == ["factors holds a 32-bit float"]


@pytest.mark.parametrize("module,args,kwargs,exc,words", [
    (navbot, ("maneuver",), {"pitch": "fast"}, TypeError, "maneuver.pitch: expected an int, got str"),
    (navbot, ("maneuver",), {"pitch": 1.5}, TypeError, "maneuver.pitch: expected an int, got float"),
    (navbot, ("maneuver",), {"switch_a": 1.0}, TypeError, "maneuver.switch_a: expected a name (str) or code (int), got float"),
    (buwizz3, ("set_motor_data",), {"power": 5}, TypeError, "set_motor_data.power: expected a list of 6 values, got int"),
    (buwizz3, ("set_motor_data",), {"power": [1, 2]}, ValueError, "set_motor_data.power: 2 values given, 6 expected"),
    (buwizz3, ("set_motor_data",), {"power": [1, 2, 3, 4, 5, "6"]}, TypeError, "set_motor_data.power[5]: expected an int, got str"),
    (buwizz3, ("set_led_status",), {"colors": [1, 2, 3, 4]}, TypeError, "set_led_status.colors[0]: expected a dict of rgb fields, got int"),
    (buwizz3, ("set_device_name",), {"name": b"abc"}, TypeError, "set_device_name.name: expected a str, got bytes"),
    (buwizz3, ("set_accel_calibration",), {"factors": [0, 0, 0, 0, 0, "x"]}, TypeError, "expected a float, got str"),
    (buwizz3, ("set_motion_wakeup",), {"enabled": "yes"}, TypeError, "set_motion_wakeup.enabled: expected a bool, got str"),
    (buwizz3, ("charger_settings",), {"data": 5}, TypeError, "charger_settings.data: expected bytes or hex text, got int"),
    (buwizz3, ("charger_settings",), {"data": "0x zz"}, ValueError, "charger_settings.data: not hex bytes"),
    (navbot, ("maneuver",), {"speed": 3}, KeyError, "unknown field maneuver.speed (fields of maneuver: roll, height, pitch"),
    (buwizz3, ("set_led_status",), {"colors": [{"red": 1}, {}, {}, {}]}, KeyError, "unknown field set_led_status.colors[0].red (fields of rgb: r, g, b)"),
    (buwizz3, ("status",), {"battery_voltage": 13.0}, KeyError, "encode takes the raw value"),
    (navbot, ("jump",), {}, KeyError, "unknown message jump of navbot (messages: maneuver, frame)"),
    (osp, ("status",), {"state": "charging", "flag": 1}, KeyError, "unknown field status.flag"),
    (osp, (42,), {}, TypeError, "expected a message name (str) or a dict"),
    (osp, ({"message": "status"},), {"flags": 1}, TypeError, "not both"),
    (osp, ({"fields": {}},), {}, KeyError, "no \"message\""),
    (osp, ({"message": "status", "protocol": "navbot", "fields": {}},), {}, ValueError, "a navbot message given to osp.encode"),
])
def test_shape_errors(module, args, kwargs, exc, words):
    with pytest.raises(exc) as e:
        module.encode(*args, **kwargs)
    assert not isinstance(e.value, (EncodeError, DecodeError))
    assert words in str(e.value)


def test_decode_needs_bytes():
    with pytest.raises(TypeError, match=r"bytes.fromhex"):
        osp.decode("FF AA 02 12 D2 04 00 00 55 77")
    with pytest.raises(TypeError, match="got int"):
        navbot.decode(5)


def test_encode_dict_ignores_what_decode_adds():
    d = osp.decode(bytes.fromhex("FF AA 02 14 03 05 00 00 55 77"))
    d["fields"]["flags_bits"]["overheat"] = False  # only the raw value counts
    assert osp.encode(d) == bytes.fromhex("FF AA 02 14 03 05 00 00 55 77")
    d["fields"]["flags"] = 1
    assert osp.encode(d) == bytes.fromhex("FF AA 02 14 03 01 00 00 55 77")


def test_unit_helper_errors():
    e = encode_error(buwizz3.ramp_rate_from_seconds, 0)
    assert (e.code, e.offset) == ("value_out_of_range", 1)
    e = encode_error(buwizz3.current_limit_raw, 7680)  # 256 steps of 30 mA
    assert e.code == "value_out_of_range"
    assert buwizz3.current_limit_raw(7649) == 255  # 254.97 steps, rounded
    e = encode_error(buwizz3.lpf_from_hz, 40.0)
    assert e.code == "invalid_enum"
    e = encode_error(buwizz3.lpf_hz, "hz_40")
    assert e.code == "invalid_enum"
    e = encode_error(buwizz3.uart_characteristic, 5)
    assert e.code == "value_out_of_range"
    e = encode_error(osp.soc_from_basis_points, 10001)
    assert (e.code, e.offset) == ("value_out_of_range", 4)
    e = encode_error(osp.voltage_from_millivolts, 327680)  # 32768 centivolts
    assert e.code == "value_out_of_range"
    e = encode_error(osp.angle_from_radians, -1.0)
    assert (e.code, e.offset) == ("value_out_of_range", 5)
    e = encode_error(buwizz3.k_lp_from_cutoff, 0.0)
    assert e.code == "value_out_of_range"
    e = encode_error(buwizz3.generic_pid_preset, 0, "fast")
    assert e.code == "invalid_enum"
    e = encode_error(navbot.fragment, navbot.command.json, bytes(3841))
    assert e.code == "capacity_exceeded"


def test_advertisement_error():
    # length byte 5 at offset 3 runs past the end
    e = decode_error(buwizz3.parse_advertisement, bytes.fromhex("02 01 06 05 FF 4E"))
    assert (e.code, e.offset) == ("bad_length", 3)


def test_schema_unknown_protocol():
    with pytest.raises(KeyError):
        robowire.schema("lego")
