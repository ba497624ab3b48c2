"""Every message of robowire.schema() encoded from values made from its own
table (the ends and the middle of each range, every enum value, full and
empty text), decoded again, and re-encoded: the values and the bytes must
come back. Optional blocks: every allowed combination."""
import pytest

import robowire
from robowire import buwizz3, navbot, osp

MODULES = {"buwizz3": buwizz3, "navbot": navbot, "osp": osp}
FLOATS = [0.5, -2.5, 2.0 ** 100, -0.0, 3.25]  # exact in binary32


def element(field, k):
    kind = field["value"]
    if kind == "int":
        lo, hi = field["valid"]["min"], field["valid"]["max"]
        return [lo, hi, (lo + hi) // 2][k % 3]
    if kind == "bool":
        return k % 2 == 1
    if kind == "float":
        return FLOATS[k % len(FLOATS)]
    if kind == "enum":
        return field["enum"][k % len(field["enum"])]["name"]
    if kind == "text":
        return ["", "x" * field["capacity"], "abc"][k % 3]
    if kind == "bytes":
        return [b"", bytes(range(field["capacity"])), b"\x01"][k % 3]
    if kind == "record":
        return values(field["record"]["fields"], k)
    raise AssertionError(kind)


def value(field, k):
    if field["array"]:
        return [element(field, k + i) for i in range(field["count"])]
    return element(field, k)


def values(fields, k, present=None):
    out = {}
    optional = 0
    for f in fields:
        if f["optional"]:
            optional += 1
            if present is not None and optional > present:
                continue
        out[f["name"]] = value(f, k)
    return out


def raw(decoded, given):
    """decode's values for the keys given (bytes: decode gives hex text)."""
    out = {}
    for name, v in given.items():
        d = decoded[name]
        if isinstance(v, bytes):
            d = bytes.fromhex(d)
        elif isinstance(v, dict):
            d = raw(d, v)
        elif isinstance(v, list) and v and isinstance(v[0], dict):
            d = [raw(a, b) for a, b in zip(d, v)]
        out[name] = d
    return out


CASES = []
for proto in robowire.schema()["protocols"]:
    for message in proto["messages"]:
        optional = sum(f["optional"] for f in message["fields"])
        for present in range(optional + 1):
            for k in range(3):
                CASES.append((proto["name"], message, present, k))


@pytest.mark.parametrize("proto,message,present,k", CASES,
                         ids=[f"{c[0]}-{c[1]['name']}-{c[2]}-{c[3]}" for c in CASES])
def test_round_trip(proto, message, present, k):
    m = MODULES[proto]
    given = values(message["fields"], k, present)
    frame = m.encode(message["name"], **given)
    # the frame has one of the lengths the table lists
    assert any(lo <= len(frame) <= hi for lo, hi in message["lengths"])
    for fixed in message["fixed"]:
        assert frame[fixed["offset"]] == fixed["value"]
    d = m.decode(frame, direction=message["direction"]) if proto == "buwizz3" else m.decode(frame)
    assert d["message"] == message["name"]
    assert raw(d["fields"], given) == given
    # optional blocks not given are None
    for f in message["fields"]:
        if f["name"] not in given:
            assert d["fields"][f["name"]] is None
    assert m.encode(d) == frame


def test_every_message_is_covered():
    names = {(c[0], c[1]["name"]) for c in CASES}
    assert len(names) == sum(len(p["messages"]) for p in robowire.schema()["protocols"])
    assert ("buwizz3", "status") in names and ("osp", "set_angle") in names and ("navbot", "maneuver") in names
