#!/usr/bin/env python3
"""Every function robowire defines under one name in files of different size
settings has the same code in all of them.

    symbols.py CXX INCLUDE_DIR

Compiles tests/mixed_modes/size.cpp (the codecs of codecs.hpp) at -O0, where
every function stays out of line, once per setting of ROBOWIRE_OPTIMIZE_SIZE
and ROBOWIRE_ARRAY_LOOPS, and disassembles each object (objdump -dr). A
function defined in two of them must have the same instructions and
relocations: code that depends on the settings is in their inline namespace
(size0_loops0 ... size1_loops2, core/config.hpp), so its names differ. Exits 1
naming each function that breaks this (two bodies under one name: the linker
keeps either). The six objects are built at once; llvm-objdump disassembles
them where it is installed (about 15 times faster than GNU objdump on these
objects of some 4,600 sections each), GNU objdump otherwise.

Then links scanner_caller.cpp built at -Os with scanner_user.cpp built at
-O2: osp::scanner is a type per setting, so the function taking one must
not be found (an undefined reference naming size1_loops1::scanner)."""
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SETTINGS = [(s, l) for s in (0, 1) for l in (0, 1, 2)]
OBJDUMP = shutil.which("llvm-objdump") or shutil.which("llvm-objdump-14") or "objdump"
OWN = re.compile(r"^_Z[ZN]*K?9size_file")  # the test's own functions (they call the codecs)


def functions(cxx, include, size, loops, out):
    obj = os.path.join(out, f"size{size}_loops{loops}.o")
    subprocess.run([cxx, "-std=c++20", "-O0", "-ffunction-sections", "-I", include,
                    f"-DROBOWIRE_OPTIMIZE_SIZE={size}", f"-DROBOWIRE_ARRAY_LOOPS={loops}",
                    "-c", os.path.join(HERE, "size.cpp"), "-o", obj], check=True)
    dump = subprocess.run([OBJDUMP, "-dr", "--no-show-raw-insn", obj], check=True,
                          capture_output=True, text=True).stdout
    bodies, name = {}, None
    for line in dump.splitlines():
        m = re.match(r"^[0-9a-f]+ <(.+)>:$", line)
        if m:
            name = m.group(1)
            bodies[name] = []
        elif name and line.strip() and not line.startswith("Disassembly"):
            line = re.sub(r" ?<[^>]*>", "", line)  # objdump's guess of a symbol near an address
            line = re.sub(r"\s\.[\w.$]*([+-]0x[0-9a-f]+)?$", " LOCAL", line)  # section / local label: offsets depend on the file
            bodies[name].append(re.sub(r"\s+", " ", line.strip()))
    return {n: b for n, b in bodies.items() if not OWN.match(n) and n != "main"}


def main():
    cxx, include = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as out:
        with concurrent.futures.ThreadPoolExecutor(os.cpu_count() or 2) as pool:
            jobs = {st: pool.submit(functions, cxx, include, *st, out) for st in SETTINGS}
            objs = {st: job.result() for st, job in jobs.items()}
    names = lambda st: f"size{st[0]}_loops{st[1]}"
    first = SETTINGS[0]
    clashes, shared = set(), 0
    for other in SETTINGS[1:]:
        common = objs[first].keys() & objs[other].keys()
        shared = max(shared, len(common))
        for f in sorted(common):
            if objs[first][f] != objs[other][f]:
                clashes.add((f, names(other)))
    if clashes:
        demangled = subprocess.run(["c++filt"], input="\n".join(f for f, _ in sorted(clashes)),
                                   capture_output=True, text=True).stdout.splitlines()
        for (f, other), d in zip(sorted(clashes), demangled):
            print(f"{d}: differs between {names(first)} and {other}")
        print(f"{len({f for f, _ in clashes})} functions have a body per setting under one name")
        return 1
    with tempfile.TemporaryDirectory() as out:
        parts = []
        for src, opt in (("scanner_caller.cpp", "-Os"), ("scanner_user.cpp", "-O2")):
            parts.append(os.path.join(out, src + ".o"))
            subprocess.run([cxx, "-std=c++20", opt, "-I", include, "-c", os.path.join(HERE, src), "-o", parts[-1]],
                           check=True)
        link = subprocess.run([cxx, *parts, "-o", os.path.join(out, "scanner")], capture_output=True, text=True)
    expected = "on_uart(robowire::osp::size1_loops1::scanner&)"
    if link.returncode == 0 or expected not in link.stderr:
        print(f"an osp::scanner passed from an -Os file to an -O2 file: link {'succeeded' if link.returncode == 0 else 'failed'}"
              f", expected an undefined reference to {expected}\n{link.stderr}")
        return 1
    total = {names(st): len(objs[st]) for st in SETTINGS}
    print(f"functions per object: {total}; at most {shared} shared between two settings, all identical;"
          f" an osp::scanner across settings does not link")
    return 0


if __name__ == "__main__":
    sys.exit(main())
