#!/usr/bin/env python3
"""Fails when CHANGELOG.md and the version disagree (CONTRIBUTING.md,
"Versions and releases"):

- every section heading is `## X.Y.Z (unreleased)` or `## X.Y.Z (YYYY-MM-DD)`,
  newest first, each version once, only the first one unreleased;
- the first section's version is the one in core/config.hpp (ROBOWIRE_VERSION_*),
  which CMakeLists.txt and meson.build use;
- every tag vX.Y.Z of the repository (when it is a git checkout) has a dated
  section;
- a section's entries are grouped under `### Added`, `### Changed`,
  `### Fixed` (those present, in that order), none outside a group, and no
  entry gives a before-to-after figure (`12.3 -> 11.0`; figures are in
  docs/benchmarks.md and docs/footprint.md).
"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def version_key(v):
    return tuple(int(x) for x in v.split("."))


with open(os.path.join(ROOT, "CHANGELOG.md"), encoding="utf-8") as f:
    lines = [line.rstrip("\n") for line in f]
headings = [line for line in lines if line.startswith("## ")]
with open(os.path.join(ROOT, "include", "robowire", "core", "config.hpp"), encoding="utf-8") as f:
    config = f.read()
parts = [re.search(rf"^#define ROBOWIRE_VERSION_{p} (\d+)$", config, re.M) for p in ("MAJOR", "MINOR", "PATCH")]
project_version = ".".join(m.group(1) for m in parts) if all(parts) else None

failures = []
sections = []
for i, h in enumerate(headings):
    m = re.fullmatch(r"## (\d+\.\d+\.\d+) \((unreleased|\d{4}-\d{2}-\d{2})\)", h)
    if not m:
        failures.append(f"CHANGELOG.md: heading '{h}' is not '## X.Y.Z (unreleased)' or '## X.Y.Z (YYYY-MM-DD)'")
        continue
    if m.group(2) == "unreleased" and i != 0:
        failures.append(f"CHANGELOG.md: '{h}' is unreleased but not the first section")
    sections.append((m.group(1), m.group(2)))
versions = [v for v, _ in sections]
if len(set(versions)) != len(versions):
    failures.append("CHANGELOG.md: a version has two sections")
if versions != sorted(versions, key=version_key, reverse=True):
    failures.append("CHANGELOG.md: sections are not newest first: " + ", ".join(versions))
if not sections:
    failures.append("CHANGELOG.md: no section")
elif sections[0][0] != project_version:
    failures.append(f"CHANGELOG.md: the first section is {sections[0][0]}, config.hpp says {project_version}")

tags = subprocess.run(["git", "-C", ROOT, "tag", "--list", "v*"], capture_output=True, text=True)
dated = {v for v, d in sections if d != "unreleased"}
for tag in tags.stdout.split() if tags.returncode == 0 else []:
    if re.fullmatch(r"v\d+\.\d+\.\d+", tag) and tag[1:] not in dated:
        failures.append(f"tag {tag} has no dated section in CHANGELOG.md")

GROUPS = ["Added", "Changed", "Fixed"]
FIGURE = re.compile(r"\d[\d.,]*\s*(%|x|[A-Za-z]+)?\s*(->|→)\s*\d")
section, groups, group, entry = None, [], None, ""


def check_entry(text, where):
    if FIGURE.search(text):
        failures.append(f"CHANGELOG.md: {where}: an entry gives a before-to-after figure "
                        f"(put figures in docs/benchmarks.md): {text[:70]}...")


for n, line in enumerate(lines, 1):
    if line.startswith("## ") or line.startswith("### ") or line.startswith("- "):
        if entry:
            check_entry(entry, f"{section} {group}")
        entry = ""
    if line.startswith("## "):
        section, groups, group = line[3:], [], None
    elif line.startswith("### "):
        group = line[4:].strip()
        if section is None:
            failures.append(f"CHANGELOG.md:{n}: '{line}' before any version section")
        elif group not in GROUPS:
            failures.append(f"CHANGELOG.md:{n}: '{line}': groups are ### " + ", ### ".join(GROUPS))
        elif group in groups or any(GROUPS.index(g) > GROUPS.index(group) for g in groups):
            failures.append(f"CHANGELOG.md:{n}: '{line}' twice or out of order (Added, Changed, Fixed)")
        else:
            groups.append(group)
    elif line.startswith("- "):
        if section is not None and group is None:
            failures.append(f"CHANGELOG.md:{n}: an entry of {section} outside ### Added / Changed / Fixed")
        entry = line
    elif entry and line.strip():
        entry += " " + line.strip()
if entry:
    check_entry(entry, f"{section} {group}")

for line in failures:
    print(line)
if failures:
    sys.exit(1)
print(f"CHANGELOG.md: {len(sections)} sections, the first is {sections[0][0]} ({sections[0][1]}) as in config.hpp")
