#!/usr/bin/env python3
"""The figures table of docs/benchmarks.md, from the gated baselines.

    bench/figures.py [--gcc FILE] [--clang FILE] [--write-docs | --check]

Prints one row per case and baseline (careful, handwritten, bytewise,
memcpy, memchr): robowire / baseline in instructions and estimated cycles
per message, for g++ (default bench/baseline.json) and clang++ (default
bench/baseline-clang++.json), the files bench/check gates. --write-docs
replaces the table between the markers in docs/benchmarks.md; --check exits
1 when the table there differs from these files (run by the unit tests), so
the page's figures are the gated ones."""
import argparse
import json
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOC = ROOT / "docs" / "benchmarks.md"
BEGIN = "<!-- figures: bench/figures.py --write-docs -->"
END = "<!-- end of figures -->"
BASELINES = ("careful", "handwritten", "bytewise", "memcpy", "memchr")


def number(x):
    return f"{x:,.0f}" if x >= 1000 else f"{x:.2f}"


def cell(cases, case, base, key):
    v = cases.get(case, {})
    if "robowire" not in v or base not in v:
        return "-", "-"
    r, b = v["robowire"][key], v[base][key]
    return f"{number(r)} / {number(b)}", f"{r / b:.2f}"


def table(gcc, clang):
    rows = ["| case | baseline | g++ instructions | ratio | g++ est. cycles | ratio "
            "| clang++ instructions | ratio | clang++ est. cycles | ratio |",
            "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for case in sorted(set(gcc["cases"]) | set(clang["cases"])):
        for base in BASELINES:
            if base not in gcc["cases"].get(case, {}) and base not in clang["cases"].get(case, {}):
                continue
            cells = []
            for data in (gcc, clang):
                for key in ("instructions", "estimated_cycles"):
                    cells += cell(data["cases"], case, base, key)
            rows.append(f"| {case} | {base} | " + " | ".join(cells) + " |")
    return "\n".join(rows) + "\n"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--gcc", default=str(ROOT / "bench" / "baseline.json"))
    p.add_argument("--clang", default=str(ROOT / "bench" / "baseline-clang++.json"))
    g = p.add_mutually_exclusive_group()
    g.add_argument("--write-docs", action="store_true", help="replace the table in docs/benchmarks.md")
    g.add_argument("--check", action="store_true", help="exit 1 if docs/benchmarks.md's table differs")
    args = p.parse_args()
    with open(args.gcc) as f:
        gcc = json.load(f)
    with open(args.clang) as f:
        clang = json.load(f)
    t = table(gcc, clang)
    if not (args.write_docs or args.check):
        sys.stdout.write(t)
        return 0
    doc = DOC.read_text()
    if BEGIN not in doc or END not in doc:
        print(f"{DOC}: no '{BEGIN}' ... '{END}' markers", file=sys.stderr)
        return 1
    head, rest = doc.split(BEGIN, 1)
    old, tail = rest.split(END, 1)
    new = f"{head}{BEGIN}\n{t}{END}{tail}"
    if args.check:
        if old.strip() != t.strip():
            print("docs/benchmarks.md: the figures table differs from the gated baselines "
                  "(bench/figures.py --write-docs)", file=sys.stderr)
            return 1
        print("docs/benchmarks.md: the figures table is the gated baselines'")
        return 0
    DOC.write_text(new)
    print(f"wrote the figures table of {DOC.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
