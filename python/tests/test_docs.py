"""The Python examples of docs/python.md run and show what the package gives:
code blocks are executed; an expression followed by `# <Python literal>`
(continued on further comment lines) must equal that literal; a `>>> ` line
followed by `robowire.DecodeError: text` must raise it with that text."""
import ast
import re
from pathlib import Path

import pytest

import robowire
from robowire import buwizz3, navbot, osp  # noqa: F401 (used by the examples)

DOC = Path(__file__).resolve().parents[2] / "docs" / "python.md"


class FakePort:
    """What the scanner example reads from: one voltage frame."""
    in_waiting = 10

    def read(self, n):
        return bytes.fromhex("FF AA 02 12 D2 04 00 00 55 77")


def blocks():
    text = DOC.read_text()
    return re.findall(r"```python\n(.*?)```", text, re.S)


def namespace():
    return {"robowire": robowire, "buwizz3": buwizz3, "navbot": navbot, "osp": osp, "print": lambda *a, **k: None,
            "frame": bytes.fromhex("FF AA 02 14 03 05 00 00 55 77"), "port": FakePort()}


def test_doc_has_examples():
    assert len(blocks()) >= 4


@pytest.mark.parametrize("block", [b for b in blocks() if not b.startswith(">>>")], ids=lambda b: b.splitlines()[0][:40])
def test_code_blocks(block):
    ns = namespace()
    lines = block.splitlines()
    checked = 0
    i = 0
    while i < len(lines):
        line = lines[i]
        code, _, comment = line.partition("  # ")
        literal = comment
        while i + 1 < len(lines) and lines[i + 1].startswith("# "):  # the value, on comment lines below
            literal += lines[i + 1][1:]
            i += 1
        i += 1
        if not code.strip() or code.startswith(("#", "from ", "import ", "for ", " ", "scanner =")):
            continue
        try:
            want = ast.literal_eval(literal.strip()) if literal else None
        except (ValueError, SyntaxError):
            want = None
        got = eval(code, ns)
        if want is not None:
            assert got == want, code
            checked += 1
    exec(block, namespace())  # the block as a whole
    if "# b'" in block or "# {" in block:
        assert checked > 0


@pytest.mark.parametrize("block", [b for b in blocks() if b.startswith(">>>")], ids=lambda b: b.splitlines()[0][:40])
def test_errors_shown(block):
    lines = block.splitlines()
    errors = 0
    for i, line in enumerate(lines[:-1]):
        m = re.match(r"robowire\.(DecodeError|EncodeError): (.*)", lines[i + 1])
        if not line.startswith(">>> ") or not m:
            continue
        expr = line[4:].partition("  # ")[0]
        with pytest.raises(getattr(robowire, m.group(1))) as e:
            eval(expr, namespace())
        assert str(e.value) == m.group(2)
        errors += 1
    if "Error:" in block:
        assert errors > 0
