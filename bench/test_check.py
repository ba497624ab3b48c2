#!/usr/bin/env python3
"""Shows that bench/check fails on planted regressions and passes on the
committed baseline. Usage: bench/test_check.py INSTRUCTIONS_JSON BASELINE_JSON
(the figures of this build, from bench/run --instructions, and the baseline
they are gated against)."""
import copy
import json
import pathlib
import subprocess
import sys
import tempfile

if sys.argv[1:2] in (["-h"], ["--help"]):  # usage: the docstring
    print(__doc__)
    sys.exit(0)
check = pathlib.Path(__file__).resolve().parent / "check"
if len(sys.argv) != 3:
    sys.exit(__doc__)
current, committed = sys.argv[1], sys.argv[2]
base = json.loads(pathlib.Path(committed).read_text())
failed = []


def gate(baseline, *extra):
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(baseline, f)
    p = subprocess.run([sys.executable, str(check), "--current", current, "--baseline", f.name, *extra],
                       capture_output=True, text=True)
    pathlib.Path(f.name).unlink()
    return p.returncode, p.stdout


def expect(what, ok):
    print(f"{'ok  ' if ok else 'FAIL'} {what}")
    if not ok:
        failed.append(what)


def cheaper(baseline, factor, which=("robowire",)):
    b = copy.deepcopy(baseline)
    for variants in b["cases"].values():
        for v in which:
            if v in variants:
                variants[v]["instructions"] *= factor
    return b


robowire_cases = [c for c, v in base["cases"].items() if "robowire" in v]
rated = [c for c in robowire_cases if {"careful", "handwritten", "bytewise"} & set(base["cases"][c])]

code, out = gate(base)
expect("the committed baseline passes", code == 0)

code, out = gate(cheaper(base, 1 / 1.05))
named = [c for c in robowire_cases if f"FAIL {c}:" in out]
expect(f"a baseline 5 % cheaper fails, naming every case ({len(named)}/{len(robowire_cases)})",
       code == 1 and len(named) == len(robowire_cases))

def gate_current(changed):  # the committed baseline against a changed copy of the current figures
    global current
    saved = current
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(changed, f)
    current = f.name
    try:
        return gate(base)
    finally:
        pathlib.Path(f.name).unlink()
        current = saved


figures = json.loads(pathlib.Path(current).read_text())
for case, variant, figure, value, goal in (
        ("osp.scan_noise/4096", "robowire", "instructions",
         lambda c: c["osp.scan_noise/4096"]["memchr"]["instructions"] + 1, "instructions, more than memchr's scan"),
        ("osp.scan_noise/4096", "robowire", "estimated_cycles",
         lambda c: c["osp.scan_noise/4096"]["memchr"]["estimated_cycles"] + 1,
         "estimated cycles, more than memchr's scan"),
        ("osp.scan_ff_aa/4096", "robowire", "instructions", lambda c: 8 * 65536 + 1, "more than 8"),
        ("osp.scan_clean/64", "robowire", "instructions",
         lambda c: c["osp.scan_clean/1"]["robowire"]["instructions"] + 1, "more than one byte per call")):
    changed = copy.deepcopy(figures)
    changed["cases"][case][variant][figure] = value(changed["cases"])
    code, out = gate_current(changed)
    expect(f"a missed scanner goal fails: {case} {goal}",
           code == 1 and f"FAIL scanner goal: {case}" in out and goal in out)

code, out = gate(cheaper(base, 1 / 1.005))
expect("a baseline 0.5 % cheaper passes at the default 1 % threshold", code == 0)
code, out = gate(cheaper(base, 1 / 1.005), "--threshold", "0.25")
expect("... and fails at --threshold 0.25", code == 1)

other = cheaper(base, 1 / 1.05)
other["toolchain"] = "another compiler"
code, out = gate(other)
named = [c for c in rated if f"FAIL {c}:" in out]
expect(f"another toolchain: gated on ratios, every rated case named ({len(named)}/{len(rated)})",
       code == 1 and "toolchain differs" in out and len(named) == len(rated))

same_ratio = cheaper(base, 1 / 1.05, ("robowire", "careful", "handwritten", "bytewise"))
same_ratio["toolchain"] = "another compiler"
code, out = gate(same_ratio)
expect("another toolchain, every variant 5 % cheaper (same ratios): passes", code == 0)

libc = copy.deepcopy(base)
touched = 0
for variants in libc["cases"].values():
    for e in variants.values():
        if e.get("libc_functions"):
            e["libc_functions"] = ["__memchr_other"]
            e["instructions"] += 1000.0  # a different implementation, other counts
            e["libc_instructions"] += 1000.0
            touched += 1
code, out = gate(libc)
expect(f"other libc implementations ({touched} variants): compared without libc, passes",
       touched > 0 and code == 0 and "libc differs" in out)

renamed = copy.deepcopy(base)
for variants in renamed["cases"].values():
    for e in variants.values():
        if e.get("libc_functions"):
            e["libc_functions"] = ["0x00000000000a24c0"]  # no libc debug symbols: named by address
code, out = gate(renamed)
expect("libc functions named otherwise, same counts: compared whole, passes",
       code == 0 and "libc differs" not in out)

# A baseline made before a case got its hand-written variant (it had only the
# byte-at-a-time one): the ratios compare the variant both files have.
older = copy.deepcopy(base)
dropped = 0
for variants in older["cases"].values():
    if "handwritten" in variants and "bytewise" in variants:
        del variants["handwritten"]
        dropped += 1
code, out = gate(older)
expect(f"a baseline without a newer hand-written variant ({dropped} cases): ratios to the common one, passes",
       dropped > 0 and code == 0)

missing = copy.deepcopy(base)
missing["cases"]["core.removed_case"] = {"robowire": {"instructions": 1.0, "estimated_cycles": 1.0}}
code, out = gate(missing)
expect("a case in the baseline that was not measured fails", code == 1 and "core.removed_case" in out)
code, out = gate(missing, "--allow-removed")
expect("... and with --allow-removed is listed and passes", code == 0 and "gone core.removed_case" in out)

code, out = gate(base, "-q")
expect("-q on unchanged figures prints only the verdict", code == 0 and out.strip().count("\n") == 0)

sys.exit(1 if failed else 0)
