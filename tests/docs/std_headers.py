#!/usr/bin/env python3
"""Fails when README.md's list of the standard headers robowire includes
(the backquoted <...> names in its "Supported compilers" section) differs
from the #include <...> lines of include/robowire/**/*.hpp."""
import glob
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

used = set()
for path in glob.glob(os.path.join(ROOT, "include", "robowire", "**", "*.hpp"), recursive=True):
    with open(path, encoding="utf-8") as f:
        used |= set(re.findall(r"^\s*#\s*include\s*<([A-Za-z_0-9./]+)>", f.read(), re.M))

with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as f:
    readme = f.read()
m = re.search(r"^## Supported compilers\n(.*?)(?=^## )", readme, re.M | re.S)
if not m:
    sys.exit("README.md has no '## Supported compilers' section")
listed = set(re.findall(r"`<([A-Za-z_0-9./]+)>`", m.group(1)))

rc = 0
for h in sorted(used - listed):
    print(f"README.md does not list <{h}>, which a header includes")
    rc = 1
for h in sorted(listed - used):
    print(f"README.md lists <{h}>, which no header includes")
    rc = 1
if rc == 0:
    print(f"README.md lists the {len(used)} standard headers the headers include")
sys.exit(rc)
