"""A seeded random loop over the whole compiled API: every function and class
of buwizz3, navbot and osp (and robowire.schema) is called with arguments of
many types, and the only exceptions allowed are the documented ones
(docs/python.md): DecodeError, EncodeError, TypeError, KeyError, ValueError,
exactly those types (not a subclass such as UnicodeDecodeError), each with a
text."""
import math
import random

import pytest

import robowire
from robowire import DecodeError, EncodeError, _robowire, buwizz3, navbot, osp

ALLOWED = (DecodeError, EncodeError, TypeError, KeyError, ValueError)
MODULES = {"buwizz3": buwizz3, "navbot": navbot, "osp": osp}
SCHEMA = robowire.schema()
MESSAGES = sorted({m["name"] for p in SCHEMA["protocols"] for d in p["messages"].values() for m in d}
                  if isinstance(SCHEMA["protocols"][0].get("messages"), dict) else set())


def _names(node, out):
    """Every "name" in the schema (messages, fields, enum values): keys and values worth trying."""
    if isinstance(node, dict):
        for k, v in node.items():
            if k == "name" and isinstance(v, str):
                out.add(v)
            _names(v, out)
    elif isinstance(node, list):
        for v in node:
            _names(v, out)
    elif isinstance(node, str) and node.isidentifier():
        out.add(node)
    return out


NAMES = sorted(_names(SCHEMA, set()) | {"command", "notification", "direction", "scale", "document", "published_firmware"})
INTS = [0, 1, -1, 2, 7, 20, 100, 127, -128, 255, 256, 10000, 10001, 65535, 65536, 70000, 2**31 - 1, 2**31, -2**31 - 1,
        2**63, -2**63 - 1, 2**64, 10**30, -10**30]
FLOATS = [0.0, -0.0, 0.5, -1.5, 1e-300, 1e30, -1e308, math.inf, -math.inf, math.nan, 3.4e38, 1e39]
STRS = ["", "x", "\udcff", "a\udcffb", "\x00", "é", "30 00", "FF AA 02 12 D2 04 00 00 55 77", "zz", "x" * 300, "{\"a\":1}"]


def value(rng, depth=0):
    """One random argument."""
    kind = rng.randrange(13 if depth < 2 else 10)
    if kind == 0:
        return rng.choice(INTS) + rng.choice([0, 0, 1, -1])
    if kind == 1:
        return rng.choice(FLOATS)
    if kind == 2:
        return rng.choice(STRS)
    if kind == 3:
        return rng.choice(NAMES)
    if kind in (4, 5):  # bytes of every length, often starting like a frame
        n = rng.choice([0, 1, 2, 3, 9, 10, 11, 19, 20, 21, 54, 68, 129, 130, rng.randrange(300)])
        b = bytearray(rng.randrange(256) for _ in range(n))
        if n >= 2 and rng.random() < 0.5:
            b[0:2] = rng.choice([b"\xff\xaa", b"\x54\xaa", b"\x30\x00", b"\x01\x00", b"\x32\x0a"])
        return rng.choice([bytes, bytearray, memoryview])(bytes(b))
    if kind == 6:
        return None
    if kind == 7:
        return rng.choice([True, False])
    if kind == 8:
        return object()
    if kind == 9:
        return rng.choice([b"", "", 0])
    if kind == 10:
        return [value(rng, depth + 1) for _ in range(rng.randrange(8))]
    if kind == 11:
        return tuple(value(rng, depth + 1) for _ in range(rng.randrange(8)))
    return fields(rng, depth + 1)


def key(rng):
    return rng.choice([rng.choice(NAMES), rng.choice(NAMES), "\udcff", "a\udcff", "", 1, None, b"x", (1,)])


def fields(rng, depth):
    """A dict: fields (some with bad keys), or a message dict as decode returns it."""
    d = {}
    for _ in range(rng.randrange(5)):
        try:
            d[key(rng)] = value(rng, depth)
        except TypeError:  # unhashable key
            pass
    if rng.random() < 0.3:
        d = {"message": rng.choice([rng.choice(NAMES), 1, "\udcff"]), "fields": d,
             "protocol": rng.choice(list(MODULES) + ["\udcff", 3])}
    return d


def call(fn, rng, where):
    args = [value(rng) for _ in range(rng.choice([0, 1, 1, 2, 2, 3]))]
    kwargs = {}
    for _ in range(rng.choice([0, 0, 1, 2, 4])):
        k = key(rng)
        if isinstance(k, str):
            kwargs[k] = value(rng)
    try:
        fn(*args, **kwargs)
    except ALLOWED as e:
        assert type(e) in ALLOWED, f"{where}{args!r} {kwargs!r}: {type(e).__name__}: {e}"
        assert str(e), f"{where}{args!r} {kwargs!r}: {type(e).__name__} without a text"
    except Exception as e:  # noqa: BLE001 (the point of the test)
        pytest.fail(f"{where}(*{args!r}, **{kwargs!r}) raised {type(e).__name__}: {e}")


def callables(module):
    """The module's functions and classes that come from the extension (the codecs, no file I/O)."""
    ext = getattr(_robowire, module.__name__.rsplit(".", 1)[1])
    out = []
    for name in sorted(dir(ext)):
        obj = getattr(module, name)
        if not name.startswith("_") and callable(obj) and not hasattr(obj, "__members__"):
            out.append((name, obj))
    return out


@pytest.mark.parametrize("protocol", sorted(MODULES))
def test_random_calls_raise_only_documented_types(protocol):
    rng = random.Random(f"robowire-{protocol}")
    fns = callables(MODULES[protocol]) + [("schema", MODULES[protocol].schema)]
    assert len(fns) >= 6
    for _ in range(4000):
        name, fn = rng.choice(fns)
        if isinstance(fn, type):  # a class: make one, then call its methods at random
            call(fn, rng, f"{protocol}.{name}")
            obj = fn()
            methods = [(m, getattr(obj, m)) for m in dir(obj) if not m.startswith("_") and callable(getattr(obj, m))]
            for _ in range(rng.randrange(1, 8)):
                m, meth = rng.choice(methods)
                call(meth, rng, f"{protocol}.{name}().{m}")
        else:
            call(fn, rng, f"{protocol}.{name}")


def test_random_encodes_of_every_message():
    """Deeper: every message by name, with its own field names and random values."""
    rng = random.Random("robowire-encode")
    for p in SCHEMA["protocols"]:
        enc = MODULES[p["name"]].encode
        msgs = [m for d in p["messages"].values() for m in d] if isinstance(p["messages"], dict) else p["messages"]
        for m in msgs:
            names = sorted(_names(m, set()))
            for _ in range(60):
                kwargs = {rng.choice(names): value(rng) for _ in range(rng.randrange(1, 4))}
                try:
                    enc(m["name"], **kwargs)
                except ALLOWED as e:
                    assert type(e) in ALLOWED and str(e), (m["name"], kwargs, e)
                except Exception as e:  # noqa: BLE001
                    pytest.fail(f"{p['name']}.encode({m['name']!r}, **{kwargs!r}) raised {type(e).__name__}: {e}")


@pytest.mark.parametrize("fn,args", [
    (osp.encode, ("\udcff",)),
    (buwizz3.decode, (b"22",), ),
    (buwizz3.lpf_hz, (10**30,)),
    (osp.soc_from_basis_points, (70000,)),
    (osp.soc_from_basis_points, (10001,)),
    (osp.soc_from_basis_points, (-1,)),
    (buwizz3.battery_volts, (256,)),
    (navbot.encode, ("maneuver",)),
])
def test_known_escapes(fn, args):
    """The escapes a random loop found once: each is now a documented type naming the argument."""
    kwargs = {"direction": "\udcff"} if fn is buwizz3.decode else {}
    if fn is navbot.encode:
        kwargs = {"\udcff": 1}
    with pytest.raises(ALLOWED) as e:
        fn(*args, **kwargs)
    assert type(e.value) in ALLOWED


def test_out_of_range_helper_arguments_are_one_type():
    """10001 and 70000 basis points are the same mistake: both EncodeError value_out_of_range."""
    for bp in (10001, 70000, 2**64, -1):
        with pytest.raises(EncodeError) as e:
            osp.soc_from_basis_points(bp)
        assert e.value.code == "value_out_of_range" and "basis_points" in str(e.value)
    for raw in (-1, 256, 10**30):
        with pytest.raises(ValueError) as e:
            buwizz3.battery_volts(raw)
        assert type(e.value) is ValueError and "raw" in str(e.value) and "0..255" in str(e.value)


def test_unknown_keyword_that_is_not_utf8_is_a_key_error():
    with pytest.raises(KeyError) as e:
        navbot.encode("maneuver", **{"\udcff": 1})
    assert "unknown field maneuver." in str(e.value)


def test_reassembler_json_of_invalid_utf8():
    """A message push() accepted whose bytes are not UTF-8: json() gives its text with the bytes
    kept as surrogates (as 'text' does), not a UnicodeDecodeError."""
    r = navbot.Reassembler()
    frame = bytes([0x55, 0xAA, 0x02, 0x00, 0x00]) + b"{\"a\":\"\xff\"}".ljust(15, b"\x00")
    outcome, message = r.push(frame)
    assert outcome == "complete" and message["text"] == "{\"a\":\"\udcff\"}"
    assert r.json() == "{\"a\":\"\udcff\"}"


@pytest.mark.parametrize("fn,args", [
    (buwizz3.decode, (b"22",)), (osp.decode, ()), (osp.encode, ()), (osp.encode, ("voltage", 1)), (osp.millivolts, (1,)),
    (navbot.Reassembler, ()), (navbot.Reassembler().push, (bytes(20),)), (buwizz3.lpf_hz, ("hz_50",)),
])
def test_keyword_that_is_not_utf8_on_a_call_that_does_not_match(fn, args):
    """pybind11 formats its TypeError from the keywords and aborted the interpreter on this one."""
    with pytest.raises(TypeError) as e:
        fn(*args, **{"a\udcff": 1})
    assert type(e.value) is TypeError and str(e.value)
