#!/usr/bin/env bash
# Fails when fuzz/harnesses.txt and the harness sources disagree: every
# fuzz/*.cpp that defines LLVMFuzzerTestOneInput is listed, every listed name has its
# source, corpus folder and dictionary; those marked `mutator` name their
# variant with FUZZ_STRUCTURE_AWARE, and only those.
case "${1:-}" in -h | --help) sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;; esac  # usage: the comment above
cd "$(dirname "$0")"
rc=0
listed=$(grep -v '^[[:space:]]*\(#\|$\)' harnesses.txt)
names=$(awk '{print $1}' <<<"$listed")
for f in *.cpp; do
  grep -q "LLVMFuzzerTestOneInput(.*) *{" "$f" || continue  # a harness defines it
  grep -qx "${f%.cpp}" <<<"$names" || { echo "fuzz/harnesses.txt does not list ${f%.cpp}"; rc=1; }
done
while read -r name dict mutator extra; do
  [ -n "$dict" ] && [ -z "$extra" ] && [ "${mutator:-mutator}" = mutator ] ||
    { echo "fuzz/harnesses.txt: '$name $dict $mutator $extra': want <name> <dictionary> [mutator]"; rc=1; continue; }
  if [ -n "$mutator" ]; then
    grep -q '^FUZZ_STRUCTURE_AWARE(' "$name.cpp" || { echo "fuzz/$name.cpp: marked mutator, but no FUZZ_STRUCTURE_AWARE(variant)"; rc=1; }
  elif grep -q '^FUZZ_STRUCTURE_AWARE(' "$name.cpp" 2>/dev/null; then
    echo "fuzz/harnesses.txt: $name has FUZZ_STRUCTURE_AWARE but is not marked mutator"; rc=1
  fi
  [ -f "$name.cpp" ] || { echo "fuzz/harnesses.txt lists $name but fuzz/$name.cpp does not exist"; rc=1; }
  [ -d "corpus/$name" ] || { echo "fuzz/corpus/$name/ does not exist"; rc=1; }
  [ -f "dict/$dict.dict" ] || { echo "$name: fuzz/dict/$dict.dict does not exist"; rc=1; }
done <<<"$listed"
[ "$(sort <<<"$names" | uniq -d)" = "" ] || { echo "fuzz/harnesses.txt lists a name twice"; rc=1; }
exit $rc
