#!/usr/bin/env bash
# Prints the unit test sources, one per line (a program per folder:
# robowire_tests_<folder>, in CMake and meson), relative to tests/: every
# tests/<folder>/*.cpp (main.cpp aside), except the folders below, which hold
# programs or scripts of their own. Read by tests/CMakeLists.txt and
# tests/meson.build, so a new test file or a new protocol's test folder needs
# no list edited.
#   unit_sources.sh            every source
#   unit_sources.sh FOLDER     the sources of one folder
#   unit_sources.sh --folders  the folders, one per line
cd "$(dirname "$0")" || exit 1
not_unit=" alloc cli compile_fail consumer consumers docs handler instantiation mixed_modes vectors wasm wireshark "
for f in */*.cpp; do
  [ -e "$f" ] || continue
  case "$not_unit" in *" ${f%%/*} "*) continue ;; esac
  echo "$f"
done | case "${1:-}" in
  "") cat ;;
  --folders) sed 's|/.*||' | uniq ;;
  *) grep "^$1/" ;;
esac
