"""osp.Scanner, navbot.Reassembler and navbot.fragment, fed byte by byte and in chunks."""
import pytest

from robowire import DecodeError, EncodeError, navbot, osp
from vectors import MULTIFRAME, OSP_SCAN, REASSEMBLY

VOLTAGE = bytes.fromhex("FF AA 02 12 D2 04 00 00 55 77")   # 12.34 V
STATUS = bytes.fromhex("FF AA 02 14 03 05 00 00 55 77")    # charging, low_voltage | overheat
UNKNOWN = bytes.fromhex("FF AA 03 01 0A 0B 0C 0D 55 77")   # DEV 03 CMD 01: no such message
# noise byte, a frame, an unknown frame, a false start (FF 00), a frame
STREAM = b"\x00" + VOLTAGE + UNKNOWN + b"\xff\x00" + STATUS

EXPECTED = [
    {"type": "message", "protocol": "osp", "message": "voltage",
     "fields": {"centivolts": 1234, "centivolts_physical": {"value": 12.34, "unit": "V"}}},
    {"type": "error", "protocol": "osp", "error": "unknown key 0x03 0x01 at byte 2",
     "bytes": "FF AA 03 01 0A 0B 0C 0D 55 77", "code": "unknown_message", "offset": 2, "field": None},
    {"type": "message", "protocol": "osp", "message": "status",
     "fields": {"state": "charging", "flags": 5,
                "flags_bits": {"low_voltage": True, "high_voltage": False, "overheat": True, "short_circuit": False}}},
]


@pytest.mark.parametrize("chunk", [1, 2, 3, 7, 10, 11, 64, len(STREAM)])
def test_scanner_chunks(chunk):
    s = osp.Scanner()
    got = []
    for i in range(0, len(STREAM), chunk):
        got += s.feed(STREAM[i:i + chunk])
    assert got == EXPECTED
    # 3 frames with markers; skipped: the noise byte, FF and 00 of the false start
    assert (s.frames, s.skipped_bytes, s.false_starts, s.pending) == (3, 3, 1, 0)
    assert s.counters() == {"type": "counters", "frames": 3, "skipped_bytes": 3, "false_starts": 1}


def test_scanner_partial_and_reset():
    s = osp.Scanner()
    assert s.feed(VOLTAGE[:6]) == [] and s.pending == 6
    assert s.feed(bytearray(VOLTAGE[6:])) == EXPECTED[:1] and s.pending == 0
    s.reset()
    assert (s.frames, s.skipped_bytes, s.false_starts, s.pending) == (0, 0, 0, 0)


def test_scanner_frame_inside_false_start():
    # FF AA 02 ... whose EN1 is wrong, with a real frame starting inside it: the frame is not lost
    s = osp.Scanner()
    stream = b"\xff\xaa\x02" + VOLTAGE
    assert [m["message"] for m in s.feed(stream)] == ["voltage"]
    assert s.false_starts >= 1


JSON_TEXT = '{"type":"get_device_info","id":12345}'  # 37 bytes: 3 frames


def test_fragment_by_hand():
    frames = navbot.fragment(navbot.command.json, JSON_TEXT)
    t = JSON_TEXT.encode()
    assert frames == [
        bytes([0x55, 0xAA, 0x02, 2, 0]) + t[0:15],
        bytes([0x55, 0xAA, 0x02, 1, 0]) + t[15:30],
        bytes([0x55, 0xAA, 0x02, 0, 0]) + t[30:] + bytes(8),
    ]
    assert navbot.fragment(1, b"") == [bytes([0x55, 0xAA, 0x01, 0, 0]) + bytes(15)]
    assert len(navbot.fragment(1, bytes(3840))) == 256
    with pytest.raises(ValueError):
        navbot.fragment(256, b"")


def test_reassembler_complete_and_duplicate():
    r = navbot.Reassembler()
    frames = navbot.fragment(navbot.command.json, JSON_TEXT)
    assert r.push(frames[0]) == ("need_more", None) and r.in_progress
    assert r.push(frames[1]) == ("need_more", None)
    outcome, message = r.push(frames[2])
    assert outcome == "complete" and not r.in_progress
    assert message == {"command": 2, "payload": JSON_TEXT.encode() + bytes(8), "text": JSON_TEXT}
    assert r.json() == JSON_TEXT
    assert r.push(frames[2]) == ("duplicate", None)


def test_reassembler_single_restart_and_errors():
    r = navbot.Reassembler()
    frames = navbot.fragment(navbot.command.json, JSON_TEXT)
    maneuver = navbot.encode("maneuver", switch_a="start")
    assert r.push(frames[0])[0] == "need_more"
    outcome, message = r.push(maneuver)  # a one-frame message of another command meanwhile
    assert outcome == "single" and message["command"] == 0x10 and message["payload"] == maneuver[5:]
    assert r.push(frames[0]) == ("duplicate", None)  # an exact repeat of the last frame
    assert r.push(frames[1]) == ("need_more", None)
    assert r.push(frames[0]) == ("restarted", None)  # remaining went up: the sender started over
    # frames lost: remaining 2 then 0
    with pytest.raises(DecodeError) as e:
        r.push(frames[2])
    assert (e.value.code, e.value.offset) == ("bad_sequence", 3)
    # another multi-frame command mid-message
    r.clear()
    wifi = navbot.fragment(navbot.command.wifi, bytes(20))
    r.push(frames[0])
    with pytest.raises(DecodeError) as e:
        r.push(wifi[0])
    assert (e.value.code, e.value.offset) == ("command_changed", 2)
    # the rest of the broken JSON message is discarded
    assert r.push(frames[1]) == ("discarded", None)
    # not a frame
    with pytest.raises(DecodeError) as e:
        r.push(b"\x55\xaa\x02")
    assert e.value.code == "too_short"
    # json() of a message that is not one JSON object
    r.clear()
    tail = navbot.fragment(navbot.command.json, JSON_TEXT)[2]
    assert r.push(tail)[0] == "complete"
    with pytest.raises(DecodeError) as e:
        r.json()
    assert e.value.code == "bad_json"


def test_reassembler_byte_by_byte_is_frame_by_frame():
    # frames come whole over BLE; a frame pushed in pieces is not a frame
    r = navbot.Reassembler()
    frame = navbot.fragment(navbot.command.json, '{"a":1}')[0]
    for n in range(1, 20):
        with pytest.raises(DecodeError):
            r.push(frame[:n])
    assert r.push(frame) == ("complete", {"command": 2, "payload": b'{"a":1}' + bytes(8), "text": '{"a":1}'})


@pytest.mark.parametrize("v", OSP_SCAN, ids=[v["hex"][:20] for v in OSP_SCAN])
def test_scanner_vectors(v):
    """tests/vectors/vectors.json: OSP frames found in noise, whole and byte by byte."""
    for chunk in (1, len(bytes.fromhex(v["hex"]))):
        s = osp.Scanner()
        data = bytes.fromhex(v["hex"])
        got = []
        for i in range(0, len(data), chunk):
            got += s.feed(data[i:i + chunk])
        assert len(got) == len(v["records"])
        for g, want in zip(got, v["records"]):
            if "message" in want:
                assert g["type"] == "message" and g["message"] == want["message"]
                assert {k: g["fields"][k] for k in want["fields"]} == want["fields"]
            else:
                assert g["type"] == "error" and (g["error"], g["code"], g["offset"], g["bytes"]) == (
                    want["error"], want["code"], want["offset"], want["bytes"])
        assert s.frames == len(v["records"])


@pytest.mark.parametrize("v", MULTIFRAME, ids=[v["text"][:20] for v in MULTIFRAME])
def test_multiframe_vectors(v):
    """tests/vectors/vectors.json: NAVBOT messages of several frames, fragmented and reassembled."""
    frames = [bytes.fromhex(f) for f in v["frames"]]
    assert navbot.fragment(v["command"], v["text"]) == frames
    r = navbot.Reassembler()
    outcomes = [r.push(f) for f in frames]
    assert [o for o, _ in outcomes] == v["outcomes"]
    assert outcomes[-1][1]["command"] == v["command"] and outcomes[-1][1]["text"] == v["text"]
    assert r.json() == v["text"]


@pytest.mark.parametrize("v", REASSEMBLY, ids=[v["source"][:40] for v in REASSEMBLY])
def test_reassembly_vectors(v):
    """tests/vectors/vectors.json: frame sequences (repeats, restarts, frames lost), the outcome of each frame."""
    r = navbot.Reassembler()
    for f, want in zip(v["frames"], v["outcomes"], strict=True):
        if want == "error":
            with pytest.raises(DecodeError) as e:
                r.push(bytes.fromhex(f))
            assert (e.value.code, e.value.offset) == (v["error"]["code"], v["error"]["offset"])
            continue
        outcome, message = r.push(bytes.fromhex(f))
        assert outcome == want
        if outcome == "complete":
            assert message["text"] == v["text"]
