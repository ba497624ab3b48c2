#!/usr/bin/env bash
# Fails when a test source is missing from tests/meson.build.
cd "$(dirname "$0")"
rc=0
for f in */*.cpp; do
  case "$f" in consumer/* | alloc/* | compile_fail/*) continue ;; esac  # compile_fail: compiled by compile_fail/run
  grep -q "'$f'" meson.build || { echo "tests/meson.build does not list $f"; rc=1; }
done
exit $rc
