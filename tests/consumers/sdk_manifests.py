#!/usr/bin/env python3
"""Checks idf_component.yml (ESP-IDF component manifest) and zephyr/module.yml
(Zephyr module) as far as the SDKs are absent: both parse as YAML, have the
fields their formats ask for, and name files that exist; the Kconfig symbol is
the one the module's CMakeLists.txt tests. Prints the cmake folder of the
Zephyr module (for tests/consumers/run) on success."""
import os
import re
import sys

import yaml

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
errors = []

idf = yaml.safe_load(open(os.path.join(root, "idf_component.yml")))
config = open(os.path.join(root, "include", "robowire", "core", "config.hpp")).read()
version = ".".join(re.search(rf"^#define ROBOWIRE_VERSION_{p} (\d+)$", config, re.M).group(1) for p in ("MAJOR", "MINOR", "PATCH"))
if idf.get("version") != version:
    errors.append(f"idf_component.yml: version {idf.get('version')!r}, core/config.hpp says {version}")
if idf.get("license") != "BSL-1.0" or "Boost Software License" not in open(os.path.join(root, "LICENSE")).read():
    errors.append("idf_component.yml: license is not BSL-1.0 (LICENSE is the Boost Software License)")
if not idf.get("description"):
    errors.append("idf_component.yml: no description")
if not str(idf.get("dependencies", {}).get("idf", {}).get("version", "")).startswith(">=5"):
    errors.append("idf_component.yml: dependencies.idf.version should ask for ESP-IDF 5 or later (C++20)")
cmake = open(os.path.join(root, "CMakeLists.txt")).read()
if not re.search(r"if\(ESP_PLATFORM\)\s*\n\s*idf_component_register\(INCLUDE_DIRS include\)\s*\n\s*return\(\)", cmake):
    errors.append("CMakeLists.txt: no ESP_PLATFORM branch with idf_component_register(INCLUDE_DIRS include)")

mod = yaml.safe_load(open(os.path.join(root, "zephyr", "module.yml")))
build = mod.get("build", {})
cmake_dir = build.get("cmake", "")
if mod.get("name") != "robowire":
    errors.append("zephyr/module.yml: name is not robowire")
if not os.path.isfile(os.path.join(root, cmake_dir, "CMakeLists.txt")):
    errors.append(f"zephyr/module.yml: build.cmake {cmake_dir!r} has no CMakeLists.txt")
kconfig = build.get("kconfig", "")
if not os.path.isfile(os.path.join(root, kconfig)):
    errors.append(f"zephyr/module.yml: build.kconfig {kconfig!r} does not exist")
else:
    symbols = re.findall(r"^config (\w+)$", open(os.path.join(root, kconfig)).read(), re.M)
    used = re.findall(r"CONFIG_(\w+)", open(os.path.join(root, cmake_dir, "CMakeLists.txt")).read())
    if symbols != ["ROBOWIRE"] or used != ["ROBOWIRE"]:
        errors.append(f"zephyr: Kconfig defines {symbols}, CMakeLists.txt tests {used}")

for e in errors:
    print(e, file=sys.stderr)
if errors:
    sys.exit(1)
print(cmake_dir)
