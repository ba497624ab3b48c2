#!/usr/bin/env python3
"""Configuration in one place.

    config_macros.py [CXX...]

Fails when
  - a header other than core/config.hpp defines a ROBOWIRE_ macro, or uses
    one that config.hpp does not name;
  - a macro a user may set (a row of the table in docs/architecture.md's
    "Configuration" section) is not read in config.hpp under #ifndef (or
    defined(...) for one without a default), or config.hpp has an #ifndef
    default the table does not list;
  - with each compiler given: ROBOWIRE_ALWAYS_INLINE forces inlining at -O0
    (it must be plain inline there) or does not at -O2, or a user's
    definition is not kept."""
import glob
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
INCLUDE = os.path.join(ROOT, "include")
CONFIG = os.path.join(INCLUDE, "robowire", "core", "config.hpp")
errors = []

with open(CONFIG, encoding="utf-8") as f:
    config = f.read()
named = set(re.findall(r"\bROBOWIRE_[A-Z0-9_]+", config))
for path in glob.glob(os.path.join(INCLUDE, "robowire", "**", "*.hpp"), recursive=True):
    if path == CONFIG:
        continue
    rel = os.path.relpath(path, INCLUDE)
    with open(path, encoding="utf-8") as f:
        text = f.read()
    for m in re.findall(r"^\s*#\s*define\s+(ROBOWIRE_\w+)", text, re.M):
        errors.append(f"{rel} defines {m}: configuration macros belong in core/config.hpp")
    for m in sorted(set(re.findall(r"\bROBOWIRE_[A-Z0-9_]+", text)) - named):
        errors.append(f"{rel} uses {m}, which core/config.hpp does not name")

with open(os.path.join(ROOT, "docs", "architecture.md"), encoding="utf-8") as f:
    doc = f.read()
section = re.search(r"^## Configuration\n(.*?)(?=^##)", doc, re.M | re.S)
documented = set(re.findall(r"^\| `(ROBOWIRE_\w+)` \|", section.group(1), re.M)) if section else set()
if not documented:
    errors.append("docs/architecture.md: no table of macros in a '## Configuration' section")
guarded = set(re.findall(r"^#ifndef (ROBOWIRE_\w+)", config, re.M))
for m in sorted(documented):
    if m not in guarded and not re.search(rf"defined\({m}\)", config):
        errors.append(f"{m}: in the docs' table, but config.hpp neither defaults it under #ifndef nor tests defined()")
for m in sorted(guarded - documented):
    errors.append(f"{m}: settable in config.hpp (#ifndef), missing from docs/architecture.md's table")


def always_inline(cxx, *flags):
    out = subprocess.run([cxx, "-std=c++20", "-E", "-dM", *flags, "-x", "c++", CONFIG],
                         capture_output=True, text=True, check=True).stdout
    m = re.search(r"^#define ROBOWIRE_ALWAYS_INLINE (.*)$", out, re.M)
    return m.group(1).strip() if m else None


for cxx in sys.argv[1:]:
    if always_inline(cxx, "-O0") != "inline":
        errors.append(f"{cxx} -O0: ROBOWIRE_ALWAYS_INLINE is {always_inline(cxx, '-O0')!r}, not inline")
    if "always_inline" not in (always_inline(cxx, "-O2") or ""):
        errors.append(f"{cxx} -O2: ROBOWIRE_ALWAYS_INLINE does not force inlining")
    if always_inline(cxx, "-O2", "-DROBOWIRE_ALWAYS_INLINE=inline") != "inline":
        errors.append(f"{cxx}: -DROBOWIRE_ALWAYS_INLINE=inline is not kept")

for e in errors:
    print(e, file=sys.stderr)
if errors:
    sys.exit(1)
print(f"{len(named)} macros named in config.hpp; settable and documented: {', '.join(sorted(documented))}")
