#!/usr/bin/env python3
"""Compiles every ```cpp block of README.md and docs/*.md with each compiler given
(default: g++ and clang++) under the project's strict warning set, and fails on a line longer than
.clang-format's column limit.

A block with its own main() (or a fuzz harness's LLVMFuzzerTestOneInput) is
compiled as it is. Any other block is a
fragment: it goes into a function body after a prelude that includes robowire
and declares the application's own functions and buffers the fragments use
(send, write, adv_bytes, ...). Fragments show values a program would go on to
use, so unused variables are not errors there; every other warning is.

With --single-header FILE (the output of scripts/amalgamate.py), every
`#include <robowire/...>` of the blocks and the prelude becomes an include of
FILE, and include/ is left off the include path: each block then compiles
against the single header alone. Blocks that include an optional extra
(<robowire/ext/...>), which the single header leaves out, are skipped there.

Usage: snippets.py [--list] [--single-header FILE] [compiler...]   (run from anywhere)
"""
import os
import re
import concurrent.futures
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
STRICT = ["-std=c++20", "-Wall", "-Wextra", "-Wpedantic", "-Wconversion", "-Wsign-conversion",
          "-Wshadow", "-Werror"]
COLUMN_LIMIT = int(re.search(r"^ColumnLimit:\s*(\d+)", open(os.path.join(ROOT, ".clang-format")).read(), re.M)[1])
FRAGMENT_ONLY = ["-Wno-unused-variable", "-Wno-unused-but-set-variable"]

PRELUDE = r"""
#include <robowire/robowire.hpp>
#include <robowire/core/fields.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string_view>
#include <variant>
#include <unistd.h>  // read, write on a file descriptor

using std::printf;
// What the fragments assume the application provides.
template <std::size_t N> void send(const robowire::bytes<N>& frame);          // BLE write
template <std::size_t N> void write(const robowire::bytes<N>& frame);         // BLE write
void handle_json(std::string_view text);
extern std::span<const std::uint8_t> adv_bytes, scan_response_bytes, notification_bytes, rx_bytes;
extern int fd;                                                                // a serial port
std::uint16_t read_soc();
std::int16_t read_centivolts();
std::int32_t read_millivolts();
std::uint16_t read_soc_basis_points();
void uart_write(const std::uint8_t* data, std::size_t size);
"""


def blocks(path):
    """(line number, code) of each ```cpp block of a Markdown file."""
    out, code, start = [], None, 0
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            if code is None and line.strip() == "```cpp":
                code, start = [], n + 1
            elif code is not None and line.strip() == "```":
                out.append((start, "".join(code)))
                code = None
            elif code is not None:
                code.append(line)
    return out


def sources():
    files = [os.path.join(ROOT, "README.md")]
    docs = os.path.join(ROOT, "docs")
    files += sorted(os.path.join(docs, f) for f in os.listdir(docs) if f.endswith(".md"))
    for path in files:
        for line, code in blocks(path):
            yield os.path.relpath(path, ROOT), line, code


def translation_unit(rel, line, code):
    if re.search(r"\bint\s+main\s*\(|\bLLVMFuzzerTestOneInput\s*\(", code):  # a program, or a fuzz harness
        return f'#line {line} "{rel}"\n{code}', False
    if re.search(r"^\s*constexpr auto table_of\(", code, re.M):
        # Declarations (a message and its table), as they would sit in a protocol's namespace.
        return f'{PRELUDE}\nnamespace robowire::osp::snippet {{\n#line {line} "{rel}"\n{code}}}\n', False
    return f'{PRELUDE}\nvoid snippet() {{\n#line {line} "{rel}"\n{code}}}\n', True


def main(argv):
    argv = list(argv)
    single = None
    if "--single-header" in argv:
        i = argv.index("--single-header")
        single = os.path.abspath(argv[i + 1])
        del argv[i:i + 2]
        if not os.path.isfile(single):
            print(f"{single}: no such file (write it with scripts/amalgamate.py)")
            return 1
    listing = "--list" in argv
    compilers = [a for a in argv if a != "--list"] or ["g++", "clang++"]
    snippets = list(sources())
    if listing:
        for rel, line, _ in snippets:
            print(f"{rel}:{line}")
        return 0
    if not snippets:
        print("no ```cpp blocks found")
        return 1
    failures = 0
    # the column limit of .clang-format (scripts/format): a block must read as code formatted in the tree
    for rel, line, code in snippets:
        for n, text in enumerate(code.splitlines()):
            if len(text) > COLUMN_LIMIT:
                failures += 1
                print(f"FAILED {rel}:{line + n}: {len(text)} columns, more than .clang-format's {COLUMN_LIMIT}")
    with tempfile.TemporaryDirectory() as tmp:
        jobs = []
        skipped = 0
        for i, (rel, line, code) in enumerate(snippets):
            tu, fragment = translation_unit(rel, line, code)
            if single and re.search(r"^\s*#\s*include\s*<robowire/ext/", tu, flags=re.M):
                skipped += 1
                continue
            if single:
                tu = re.sub(r"^\s*#\s*include\s*<robowire/[^>]+>", f'#include "{single}"', tu, flags=re.M)
            src = os.path.join(tmp, f"snippet{i}.cpp")
            with open(src, "w", encoding="utf-8") as f:
                f.write(tu)
            for cxx in compilers:
                include = [] if single else ["-I", os.path.join(ROOT, "include")]
                cmd = [cxx, *STRICT, *(FRAGMENT_ONLY if fragment else []), *include, "-fsyntax-only", src]
                jobs.append((cxx, rel, line, cmd))
        with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
            results = list(pool.map(lambda j: subprocess.run(j[3], capture_output=True, text=True), jobs))
        for (cxx, rel, line, _), r in zip(jobs, results):
            status = "ok" if r.returncode == 0 else "FAILED"
            print(f"{status:6} {cxx:8} {rel}:{line}")
            if r.returncode != 0:
                failures += 1
                print(r.stderr[:4000])
    against = f", against {single} ({skipped} using an extra skipped)" if single else ""
    print(f"{len(snippets)} snippets, {len(compilers)} compilers{against}, {failures} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
