#!/usr/bin/env bash
# Fails when README.md's usage example differs from examples/readme_usage.cpp (which the build compiles).
cd "$(dirname "$0")/.."
body=$(sed -n '/^#include <robowire\/osp.hpp>/,$p' examples/readme_usage.cpp)
readme=$(sed -n '/^```cpp$/,/^```$/p' README.md | sed -n '/^#include <robowire\/osp.hpp>/,/^}$/p' | head -n "$(printf '%s\n' "$body" | wc -l)")
if [ "$body" != "$readme" ]; then
  echo "README.md usage example differs from examples/readme_usage.cpp"
  diff <(printf '%s\n' "$body") <(printf '%s\n' "$readme")
  exit 1
fi
