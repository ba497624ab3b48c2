#!/usr/bin/env python3
"""The version is written once, in include/robowire/core/config.hpp
(ROBOWIRE_VERSION_MAJOR, _MINOR, _PATCH); CMake reads it there. Every other
file that carries it must say the same: meson.build, library.json (PlatformIO),
library.properties (Arduino), idf_component.yml (ESP-IDF), the Python and JavaScript packages.
Exits 1 naming each file that differs."""
import os
import re
import sys

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def read(path):
    with open(os.path.join(root, path), encoding="utf-8") as f:
        return f.read()


config = read("include/robowire/core/config.hpp")
parts = [re.search(rf"^#define ROBOWIRE_VERSION_{p} (\d+)$", config, re.M) for p in ("MAJOR", "MINOR", "PATCH")]
if not all(parts):
    sys.exit("config.hpp: no #define ROBOWIRE_VERSION_MAJOR / _MINOR / _PATCH <number>")
version = ".".join(m.group(1) for m in parts)

carriers = {
    "meson.build": r"^\s*version:\s*'([^']*)'",
    "library.json": r'^\s*"version":\s*"([^"]*)"',
    "library.properties": r"^version=(\S*)$",
    "idf_component.yml": r'^version:\s*"([^"]*)"',
    "python/pyproject.toml": r'^version\s*=\s*"([^"]*)"',
    "python/robowire/__init__.py": r'^__version__\s*=\s*"([^"]*)"',
    "js/package.json": r'^  "version":\s*"([^"]*)"',
    "js/package-lock.json": r'^  "version":\s*"([^"]*)"',
}
errors = []
for path, pattern in carriers.items():
    m = re.search(pattern, read(path), re.M)
    if not m:
        errors.append(f"{path}: no version found")
    elif m.group(1) != version:
        errors.append(f"{path}: version {m.group(1)}, config.hpp says {version}")
# CMake reads config.hpp instead of writing the number.
if not re.search(r"project\(robowire VERSION \$\{ROBOWIRE_VERSION\}", read("CMakeLists.txt")):
    errors.append("CMakeLists.txt: project() does not take the version read from config.hpp")
for e in errors:
    print(e, file=sys.stderr)
if errors:
    sys.exit(1)
print(f"robowire {version}: config.hpp, CMakeLists.txt and {len(carriers)} package files agree")
