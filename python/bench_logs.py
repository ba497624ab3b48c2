#!/usr/bin/env python3
"""robowire.read_log and robowire.to_csv on logs of N lines: CPU time and peak memory.

    python python/bench_logs.py [--lines 10000,100000,1000000] [--cli PATH] [--check [--timings]]

Writes the sample session (examples/logs/session.py --lines N: an nRF Connect
for Android log of N 68-byte BuWizz3 status notifications at 20 Hz), then
measures, each in a fresh Python process (so that the peak RSS is its own):
  - read_log: every record read as a dict (list(...) is not kept: a loop),
  - to_csv(path): the status table written to /dev/null (the C++ CSV writer),
  - to_csv(read_log(path)): the same table from the records, in Python,
  - with --cli, `robowire decode buwizz3 --file LOG --json` for comparison;
CPU time (user + system, from getrusage) and microseconds per line; the peak
RSS (ru_maxrss) and what `import robowire` alone takes.
--check exits 1 unless, at the largest N, read_log's peak RSS is within 2 MB
of the smallest N's (memory does not grow with the log) and every peak RSS is
at most PEAK_MB (what docs/python.md states) + 1 MB; with --timings also
unless each case takes at most its US_A_LINE (the microseconds of CPU a line
docs/python.md states at 10 k, 100 k and 1 M lines) + 30 % at each of those
N measured (a timing: for a manual run on the machine the figures come from,
not for CI); with --max-us
also unless read_log takes at most that many microseconds of CPU per line.
"""
import argparse
import os
import resource
import subprocess
import sys
import tempfile
from pathlib import Path

# As docs/python.md states them: CPU microseconds a line at 1 M lines, and the largest peak RSS in MB.
US_A_LINE = {10_000: {"read_log": 13.0, "to_csv": 2.0, "to_csv(read_log)": 40.0},
             100_000: {"read_log": 13.1, "to_csv": 1.4, "to_csv(read_log)": 38.5},
             1_000_000: {"read_log": 12.5, "to_csv": 1.2, "to_csv(read_log)": 42.0}}
PEAK_MB = 14.4
HERE = Path(__file__).resolve().parent
SESSION = HERE.parent / "examples" / "logs" / "session.py"

CHILD = r"""
import os, resource, sys
import robowire
rss_import = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
t0 = resource.getrusage(resource.RUSAGE_SELF)
what, path = sys.argv[1], sys.argv[2]
if what == "read_log":
    n = 0
    for r in robowire.read_log(path):
        n += 1
elif what == "to_csv":
    with open(os.devnull, "w") as out:
        n = robowire.to_csv(path, out, message="status")
else:
    with open(os.devnull, "w") as out:
        n = robowire.to_csv(robowire.read_log(path), out, message="status")
t1 = resource.getrusage(resource.RUSAGE_SELF)
cpu = (t1.ru_utime - t0.ru_utime) + (t1.ru_stime - t0.ru_stime)
print(n, cpu, rss_import, t1.ru_maxrss)
"""


def run_child(what, path):
    out = subprocess.run([sys.executable, "-c", CHILD, what, str(path)], capture_output=True, text=True, check=True)
    n, cpu, rss_import, rss = out.stdout.split()
    return int(n), float(cpu), int(rss_import), int(rss)


def run_cli(cli, path):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([cli, "decode", "buwizz3", "--file", str(path), "--json"], stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main():
    a = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    a.add_argument("--lines", default="10000,100000,1000000")
    a.add_argument("--cli", help="the command-line tool, for comparison")
    a.add_argument("--check", action="store_true")
    a.add_argument("--max-us", type=float, default=None)
    a.add_argument("--timings", action="store_true", help="--check: also each case's time against US_A_LINE")
    args = a.parse_args()
    sizes = [int(x) for x in args.lines.split(",")]
    results = {}
    with tempfile.TemporaryDirectory() as d:
        print(f"{'lines':>8} {'case':<24} {'records':>8} {'CPU s':>7} {'us/line':>8} {'peak RSS MB':>12} {'after import MB':>16}")
        for n in sizes:
            path = Path(d) / f"{n}.txt"
            subprocess.run([sys.executable, str(SESSION), "--lines", str(n), "-o", str(path)], check=True)
            for what in ("read_log", "to_csv", "to_csv(read_log)"):
                records, cpu, rss_import, rss = run_child(what, path)
                results[(n, what)] = (cpu, rss)
                print(f"{n:>8} {what:<24} {records:>8} {cpu:>7.2f} {cpu / n * 1e6:>8.1f} {rss / 1024:>12.1f} "
                      f"{rss_import / 1024:>16.1f}")
            if args.cli:
                cpu = run_cli(args.cli, path)
                print(f"{n:>8} {'robowire decode --json':<24} {'':>8} {cpu:>7.2f} {cpu / n * 1e6:>8.1f}")
            os.remove(path)
    if args.check:
        big, small = max(sizes), min(sizes)
        cpu, rss = results[(big, "read_log")]
        ok = (args.max_us is None or cpu / big * 1e6 <= args.max_us) and rss - results[(small, "read_log")][1] <= 2048
        limit = "" if args.max_us is None else f" (at most {args.max_us})"
        print(f"check: read_log {cpu / big * 1e6:.1f} us a line{limit}, peak RSS "
              f"{(rss - results[(small, 'read_log')][1]) / 1024:+.1f} MB from {small} to {big} lines (at most +2)")
        peak = max(r for _, r in results.values()) / 1024
        print(f"check: largest peak RSS {peak:.1f} MB (at most {PEAK_MB} + 1)")
        ok = ok and peak <= PEAK_MB + 1
        if args.timings:
            for n in sizes:
                for what, us in US_A_LINE.get(n, {}).items():
                    got = results[(n, what)][0] / n * 1e6
                    print(f"check: {n} lines, {what} {got:.1f} us a line (stated {us}, at most +30 %)")
                    ok = ok and got <= 1.3 * us
        print("check: " + ("ok" if ok else "FAILED"))
        return 0 if ok else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
