#!/usr/bin/env python3
"""Fails when a header under include/robowire/ is left out of an umbrella or
of the single header, so that a new header cannot be forgotten:

- core.hpp, buwizz3.hpp, navbot.hpp and osp.hpp each reach every header of
  their folder, directly or through another header (a new message header
  included by the protocol's decode.hpp needs no second edit; core/detail/
  is reached through the core headers);
- robowire.hpp includes every other header of include/robowire/ (the four
  umbrellas, protocols.hpp and reflect.hpp), directly or, for a protocol's
  umbrella, through protocols.hpp (a new protocol's one registry edit), and
  through them reaches every header there;
- scripts/amalgamate.py writes a section for every header;
- the optional extras (include/robowire/ext/, and fuzz.hpp, ext/fuzz.hpp's
  former path) are in none of them: robowire.hpp and the single header do
  not reach them.

Usage: umbrellas.py   (run from anywhere)"""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
INCLUDE = os.path.join(ROOT, "include")
LOCAL = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def rel(path):
    return os.path.relpath(path, INCLUDE)


def includes(path):
    """The robowire headers a header includes directly, as paths under INCLUDE."""
    with open(path, encoding="utf-8") as f:
        return {rel(os.path.normpath(os.path.join(os.path.dirname(path), m))) for m in LOCAL.findall(f.read())}


top = os.path.join(INCLUDE, "robowire")
headers = sorted(rel(os.path.join(d, f)) for d, _, files in os.walk(top) for f in files if f.endswith(".hpp"))
extras = [h for h in headers if h.startswith("robowire/ext/") or h == "robowire/fuzz.hpp"]
headers = [h for h in headers if h not in extras]
failures = []

def reach(start):
    """Every robowire header an #include of start brings, start included."""
    seen, todo = set(), [start]
    while todo:
        h = todo.pop()
        if h not in seen:
            seen.add(h)
            todo += includes(os.path.join(INCLUDE, h))
    return seen


for umbrella in ("core", "buwizz3", "navbot", "osp"):
    reached = reach(f"robowire/{umbrella}.hpp")
    for h in headers:
        if h.startswith(f"robowire/{umbrella}/") and h not in reached:
            failures.append(f"robowire/{umbrella}.hpp does not include {h} (nor a header that includes it)")

direct = includes(os.path.join(top, "robowire.hpp"))
if "robowire/protocols.hpp" in direct:
    direct |= includes(os.path.join(top, "protocols.hpp"))
for h in headers:
    if os.path.dirname(h) == "robowire" and h != "robowire/robowire.hpp" and h not in direct:
        failures.append(f"robowire/robowire.hpp does not include {h}")


def check_holds(held, what):
    """Every header in `held`, no extra."""
    failures.extend(f"{what} leaves out {h}" for h in headers if h not in held)
    failures.extend(f"{what} holds the optional extra {h}" for h in extras if h in held)


check_holds(reach("robowire/robowire.hpp"), "robowire/robowire.hpp (what it reaches)")

with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "robowire.hpp")
    r = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "amalgamate.py"), out],
                       capture_output=True, text=True)
    if r.returncode != 0:
        failures.append("scripts/amalgamate.py failed: " + (r.stderr or r.stdout).strip())
    else:
        with open(out, encoding="utf-8") as f:
            sections = set(re.findall(r"^// ---- (robowire/\S+\.hpp)$", f.read(), re.M))
        check_holds(sections, "the single header (scripts/amalgamate.py)")

for line in failures:
    print(line)
if failures:
    sys.exit(1)
print(f"{len(headers)} headers under include/robowire/: every one in its umbrella, robowire.hpp and the single header;"
      f" {len(extras)} optional extras in none")
