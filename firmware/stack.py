#!/usr/bin/env python3
"""Worst-case stack of entry points, from GCC's -fcallgraph-info=su output.

stack.py ELF CI_FILE ENTRY...  prints, per entry, the deepest path through the
call graph (the sum of the frames along it) and the largest over all entries.
Frames come from the compiler (static sizes); a callee outside the program's
own code (libc: memcpy, memset, ...) is measured from its prologue in the
linked ELF (pushed registers plus `sub sp`; RISC-V: `addi sp,sp,-N`; the
objdump is $ROBOWIRE_OBJDUMP, default arm-none-eabi-objdump). An indirect call counts as the deepest
path from any function of the program with no direct caller (the targets of
function pointers, such as std::visit's visitors). A dynamic or
unbounded frame, or recursion, is reported in a `note` line.
"""
import os
import re
import subprocess
import sys


def parse_ci(path):
    nodes, edges, notes = {}, {}, set()
    for line in open(path, encoding="utf-8", errors="replace"):
        m = re.match(r'node: \{ title: "([^"]+)" label: "(.*)"', line)
        if m:
            title, label = m.groups()
            f = re.search(r"\\n(\d+) bytes \(([^)]*)\)", label)
            if f:
                nodes[title] = int(f.group(1))
                if f.group(2) != "static":
                    notes.add(f"{short(title)}: {f.group(2)} frame")
            else:
                nodes.setdefault(title, None)  # external
            continue
        m = re.match(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"', line)
        if m:
            edges.setdefault(m.group(1), set()).add(m.group(2))
    return nodes, edges, notes


def short(title):
    return title.rsplit(":", 1)[-1]


def external_frames(elf):
    """Stack of each function in the ELF from its prologue (push + sub sp)."""
    objdump = os.environ.get("ROBOWIRE_OBJDUMP", "arm-none-eabi-objdump")
    out = subprocess.run([objdump, "-d", "--no-show-raw-insn", elf], capture_output=True,
                         text=True, check=True).stdout
    frames, cur, seen = {}, None, 0
    for line in out.splitlines():
        m = re.match(r"[0-9a-f]+ <([^>]+)>:", line)
        if m:
            cur, seen = m.group(1), 0
            frames[cur] = 0
            continue
        if cur is None or not line.strip():
            continue
        seen += 1
        if seen > 6:
            continue
        m = re.search(r"\b(push|stmdb\s+sp!,)\s*\{([^}]*)\}", line)
        if m:
            regs = 0
            for part in m.group(2).split(","):
                part = part.strip()
                r = re.match(r"r(\d+)-r(\d+)", part)
                regs += int(r.group(2)) - int(r.group(1)) + 1 if r else 1
            frames[cur] += 4 * regs
            continue
        m = re.search(r"\bsub(?:\.w|s)?\s+sp,\s*(?:sp,\s*)?#(\d+)", line)
        if m:
            frames[cur] += int(m.group(1))
            continue
        m = re.search(r"\b(?:c\.)?addi(?:16sp)?\s+sp,\s*(?:sp,\s*)?-(\d+)", line)  # RISC-V
        if m:
            frames[cur] += int(m.group(1))
    return frames


def main():
    if sys.argv[1:2] in (["-h"], ["--help"]) or len(sys.argv) < 3:
        print(__doc__)
        sys.exit(0 if len(sys.argv) == 2 else 2)
    elf, ci, entries = sys.argv[1], sys.argv[2], sys.argv[3:]
    nodes, edges, notes = parse_ci(ci)
    ext = external_frames(elf)
    by_name = {short(t): t for t in nodes}
    called = {c for cs in edges.values() for c in cs}

    memo = {}

    def worst(t, path):
        if t in path:
            notes.add(f"recursion through {short(t)}")
            return 0, []
        if t in memo:
            return memo[t]
        own = nodes.get(t)
        if t == "__indirect_call":
            # the targets are functions called only through pointers (no direct caller; e.g. the
            # visitors of std::visit), other than the entries and main: take the deepest
            notes.add("indirect call (counted as the deepest path from a function with no direct caller)")
            memo[t] = max((worst(c, path | {t}) for c in nodes
                           if nodes[c] is not None and c not in called and short(c) not in entries
                           and short(c) != "main"), default=(0, []))
            return memo[t]
        if own is None:
            own = ext.get(short(t), 0)
        best, best_path = 0, []
        for c in edges.get(t, ()):
            s, p = worst(c, path | {t})
            if s > best:
                best, best_path = s, p
        memo[t] = (own + best, [f"{short(t)}({own})"] + best_path)
        return memo[t]

    overall = 0
    for e in entries:
        t = by_name.get(e)
        if t is None:
            sys.exit(f"stack.py: entry {e} not in {ci}")
        s, p = worst(t, frozenset())
        overall = max(overall, s)
        print(f"{e}\t{s}\t{' > '.join(p)}")
    for n in sorted(notes):
        print(f"note\t{n}")
    print(f"worst\t{overall}")


if __name__ == "__main__":
    main()
