#!/usr/bin/env python3
"""Deterministic benchmark figures: instructions and estimated cycles per
message, counted by callgrind over the measured loop of every benchmark.

    bench/instructions.py BUILD_DIR [--out FILE] [--keep DIR] [--filter REGEX]

Runs BUILD_DIR/bench/robowire_bench twice under callgrind (2 and 4 rounds of
each benchmark's input rotation, in parallel), takes the difference of the
two counts per benchmark (so that what does not repeat per iteration, such as
the first pass through cold caches, drops out), divides by the messages
processed, and writes {"toolchain", "libc", "cases"} as JSON. Estimated
cycles = L1 hits + 5 x last-level hits + 35 x memory accesses, from
callgrind's cache simulation with fixed cache sizes (the weights
iai-callgrind uses). Two runs of the same build give identical files."""
import argparse
import concurrent.futures
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

ROUNDS = (2, 4)
# Fixed cache geometry: the simulation must not depend on the host's caches.
CACHES = ["--I1=32768,8,64", "--D1=32768,8,64", "--LL=8388608,16,64"]
# glibc picks memchr/memcpy by CPU features: keep the baseline x86-64 (SSE2)
# versions on every machine, so that their counts do not depend on the CPU.
TUNABLES = "glibc.cpu.hwcaps=-AVX2,-AVX512F,-AVX512VL,-AVX512BW,-ERMS,-FSRM,-AVX_Fast_Unaligned_Load"
EVENTS = ["Ir", "Dr", "Dw", "I1mr", "D1mr", "D1mw", "ILmr", "DLmr", "DLmw"]


def parse_dump(path):
    """Self cost per (object, function) of one callgrind dump."""
    names = {"ob": {}, "fn": {}}
    events = None
    cost = {}
    ob = fn = None
    after_calls = False
    with open(path) as f:
        for line in f:
            if line.startswith("events:"):
                events = line.split()[1:]
                continue
            m = re.match(r"(c?ob|c?fn|fl|fi|fe|cfi|cfl)=(?:\((\d+)\))?\s*(.*)", line)
            if m:
                kind, ident, name = m.group(1), m.group(2), m.group(3).strip()
                table = names.get(kind.lstrip("c"))
                if table is not None and ident is not None:
                    if name:
                        table[ident] = name
                    name = table.get(ident, name)
                if kind == "ob":
                    ob = name
                elif kind == "fn":
                    fn = name
                continue
            if line.startswith("calls="):
                after_calls = True
                continue
            if line[:1].isdigit() or line[:1] in "+-*":
                if after_calls:  # inclusive cost of a call: counted in the callee
                    after_calls = False
                    continue
                values = [int(v) for v in line.split()[1:]]
                row = cost.setdefault((ob, fn), [0] * len(events))
                for i, v in enumerate(values):
                    row[i] += v
    return {key: dict(zip(events, row)) for key, row in cost.items()}


def run(binary, rounds, keep, filter_regex=None):
    env = {"PATH": "/usr/bin:/bin", "ROBOWIRE_BENCH_ROUNDS": str(rounds), "GLIBC_TUNABLES": TUNABLES,
           "LD_BIND_NOW": "1"}
    # The same argv, environment, program path and working directory on every
    # machine (valgrind puts the last two on the client's stack): their sizes
    # move the stack, and with it the alignment that memcpy's path and the
    # cache simulation see. mkdtemp names are of a fixed length.
    out = pathlib.Path(tempfile.mkdtemp(prefix="robowire-cg-", dir="/tmp"))
    (out / "bench").symlink_to(pathlib.Path(binary).resolve())
    cmd = ["valgrind", "--tool=callgrind", "--collect-atstart=no", "--cache-sim=yes", *CACHES,
           "--toggle-collect=benchmark::State::StartKeepRunning()",
           "--toggle-collect=benchmark::State::FinishKeepRunning()",
           "--callgrind-out-file=cg", str(out / "bench"), "--benchmark_out=results.json",
           "--benchmark_out_format=json"]
    if filter_regex:
        cmd.append(f"--benchmark_filter={filter_regex}")
    try:
        proc = subprocess.run(cmd, env=env, cwd=out, capture_output=True, text=True)
        if proc.returncode != 0:
            sys.exit(f"callgrind run failed ({' '.join(cmd)}):\n{proc.stderr[-3000:]}")
        return collect(out)
    finally:
        (out / "bench").unlink()
        if keep:
            shutil.copytree(out, pathlib.Path(keep) / f"rounds{rounds}", dirs_exist_ok=True)
        shutil.rmtree(out)


def collect(out):
    runs = json.load(open(out / "results.json"))["benchmarks"]
    dumps = sorted(out.glob("cg.*"), key=lambda p: int(p.suffix[1:]))
    if len(dumps) != len(runs):
        sys.exit(f"{len(dumps)} callgrind dumps for {len(runs)} benchmark runs: every benchmark's loop must be "
                 "`for (auto _ : bench::measure(state))`")
    result = {}
    for b, dump in zip(runs, dumps):
        name = re.sub(r"/iterations:\d+$", "", b["name"])
        result[name] = (b["iterations"], b.get("batch", 1.0), parse_dump(dump))
    return result


def totals(costs, select=lambda ob, fn: True):
    t = dict.fromkeys(EVENTS, 0)
    for (ob, fn), c in costs.items():
        if select(ob, fn):
            for e in EVENTS:
                t[e] += c.get(e, 0)
    return t


def cycles(t):
    l1_miss = t["I1mr"] + t["D1mr"] + t["D1mw"]
    ll_miss = t["ILmr"] + t["DLmr"] + t["DLmw"]
    l1_hits = t["Ir"] + t["Dr"] + t["Dw"] - l1_miss
    return l1_hits + 5 * (l1_miss - ll_miss) + 35 * ll_miss


def is_libc(ob, fn):
    return ob is not None and "/libc.so" in ob


def toolchain(build):
    text = (pathlib.Path(build) / "bench" / "toolchain.txt").read_text().strip()
    return " ".join(text.split())


def libc_version():
    out = subprocess.run(["ldd", "--version"], capture_output=True, text=True).stdout.splitlines()
    return out[0] if out else "unknown"


def measure(build, keep=None, filter_regex=None):
    binary = pathlib.Path(build) / "bench" / "robowire_bench"
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        first, second = pool.map(lambda r: run(binary, r, keep, filter_regex), ROUNDS)
    cases = {}
    libc_functions = set()
    for name, (iters2, batch, costs2) in second.items():
        iters1, _, costs1 = first[name]
        messages = (iters2 - iters1) * batch
        case, _, rest = name.partition(":")
        variant, _, arg = rest.partition("/")
        key = case + (f"/{arg}" if arg else "")
        t1, t2 = totals(costs1), totals(costs2)
        l1, l2 = totals(costs1, is_libc), totals(costs2, is_libc)
        entry = {
            "instructions": round((t2["Ir"] - t1["Ir"]) / messages, 2),
            "estimated_cycles": round((cycles(t2) - cycles(t1)) / messages, 2),
        }
        called = sorted({fn for (ob, fn), c in costs2.items() if is_libc(ob, fn) and c.get("Ir")})
        if called:
            entry["libc_instructions"] = round((l2["Ir"] - l1["Ir"]) / messages, 2)
            entry["libc_functions"] = called
            libc_functions.update(called)
        cases.setdefault(key, {})[variant] = entry
    return {
        "toolchain": toolchain(build),
        "libc": f"{libc_version()}; GLIBC_TUNABLES={TUNABLES}; called: {', '.join(sorted(libc_functions))}",
        "cases": {k: dict(sorted(cases[k].items())) for k in sorted(cases)},
    }


BASELINES = ("careful", "handwritten", "bytewise", "memcpy", "memchr")


def print_table(data, out=sys.stdout):
    print(f"{'case':40} {'robowire':>10} {'baseline':>12} {'instr':>10} {'ratio':>6} "
          f"{'cycles':>10} {'baseline':>10} {'ratio':>6}", file=out)
    for key, v in data["cases"].items():
        if "robowire" not in v:
            continue
        r = v["robowire"]
        for base in BASELINES:
            if base in v:
                b = v[base]
                print(f"{key:40} {r['instructions']:10.2f} {base:>12} {b['instructions']:10.2f} "
                      f"{r['instructions'] / b['instructions']:6.2f} {r['estimated_cycles']:10.2f} "
                      f"{b['estimated_cycles']:10.2f} {r['estimated_cycles'] / b['estimated_cycles']:6.2f}",
                      file=out)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("build", help="the benchmark build directory (bench/run's build/bench)")
    p.add_argument("--out", help="JSON file to write (default BUILD/instructions.json)")
    p.add_argument("--keep", help="keep the callgrind dumps in this directory")
    p.add_argument("--filter", help="only the benchmarks whose name matches this regular expression "
                   "(Google Benchmark's --benchmark_filter; include the baselines: 'decode_command_mixed')")
    args = p.parse_args()
    if args.filter and not args.out:
        p.error("--filter writes part of the cases: give --out FILE (BUILD/instructions.json is what bench/check reads)")
    data = measure(args.build, args.keep, args.filter)
    out = args.out or os.path.join(args.build, "instructions.json")
    with open(out, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    print("per message; ratio = robowire / baseline (below 1: robowire does less)")
    print_table(data)
    print(f"JSON: {out}")


if __name__ == "__main__":
    main()
