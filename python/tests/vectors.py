"""Golden vectors: tests/vectors/vectors.json, the file the C++, command-line,
Python and JavaScript tests all read. Frames and field values there are worked
out by hand from the protocol documents (each vector's "source" says where);
nothing in it was produced by running robowire."""
import json
import pathlib

PATH = pathlib.Path(__file__).resolve().parents[2] / "tests" / "vectors" / "vectors.json"
DATA = json.loads(PATH.read_text(encoding="utf-8"))


def _value(v):
    """An encode value as the package takes it: {"hex": "01 02"} is bytes."""
    if isinstance(v, dict):
        return bytes.fromhex(v["hex"]) if set(v) == {"hex"} else {k: _value(x) for k, x in v.items()}
    if isinstance(v, list):
        return [_value(x) for x in v]
    return v


# (protocol, direction, hex frame, message, fields that must match, encode keywords)
CASES = [(m["protocol"], m["direction"], m["hex"], m["message"], m["fields"], _value(m["encode"])) for m in DATA["messages"]]

# (protocol, hex frame, message, encode keywords): other spellings of a vector's field values
ENCODE_ALSO = [(m["protocol"], m["hex"], m["message"], _value(kw)) for m in DATA["messages"] for kw in m.get("encode_also", [])]

# decode errors: dicts with protocol, direction, hex, code, offset, field, message, error (the text)
ERRORS = DATA["errors"]
# NAVBOT messages of several frames, and frame sequences with what a reassembler says of each frame
MULTIFRAME = DATA["navbot_multiframe"]
REASSEMBLY = DATA["navbot_reassembly"]
# OSP byte streams with noise and the records a scanner finds in them
OSP_SCAN = DATA["osp_scan"]

# BuWizz3 status, 68 bytes (with the PID block), and its 54-byte form without it
_STATUS = next(m for m in DATA["messages"] if m["protocol"] == "buwizz3" and m["message"] == "status")
STATUS_68 = bytes.fromhex(_STATUS["hex"])
STATUS_54 = STATUS_68[:54]
# the whole decoded status, fields worked out by hand (see its "source")
STATUS_68_FIELDS = _STATUS["fields"]
