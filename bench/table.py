#!/usr/bin/env python3
"""Prints benchmark ratios from one Google Benchmark JSON file.

Benchmarks are named "<case>:<variant>[/arg]". For each case, robowire's time
is divided by each baseline's time measured in the same run (median when
repetitions were run): ratio < 1 means robowire is faster. Benchmarks that
process a batch of messages per iteration report the time per message."""
import json, sys
from collections import defaultdict

if sys.argv[1:2] in (["-h"], ["--help"]):  # usage: the docstring
    print(__doc__)
    sys.exit(0)
data = json.load(open(sys.argv[1]))
rows = defaultdict(dict)
for b in data["benchmarks"]:
    if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
        continue
    name = b.get("run_name", b["name"])
    if ":" not in name:
        continue
    case, rest = name.split(":", 1)
    variant, _, arg = rest.partition("/")
    key = case + (f"/{arg}" if arg else "")
    t, unit = b["real_time"], b["time_unit"]
    if b.get("items_per_second"):  # a batch per iteration: time per message
        t, unit = 1e9 / b["items_per_second"], "ns"
    rows[key][variant] = t, unit, b.get("bytes_per_second")

print(f"{'case':44} {'robowire':>12} {'baseline':>24} {'ratio':>7}")
for key in sorted(rows):
    v = rows[key]
    if "robowire" not in v:
        continue
    t, unit, bps = v["robowire"]
    for base in ("careful", "handwritten", "bytewise", "memcpy", "memchr"):
        if base in v:
            bt, bunit, _ = v[base]
            print(f"{key:44} {t:9.2f} {unit:2} {base:>12} {bt:8.2f} {bunit:2} {t / bt:7.2f}")
