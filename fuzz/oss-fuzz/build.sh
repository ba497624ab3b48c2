#!/bin/bash -eu
# OSS-Fuzz build script, also used by ClusterFuzzLite (.clusterfuzzlite/build.sh).
# Honours the OSS-Fuzz contract: $CXX, $CXXFLAGS, $LIB_FUZZING_ENGINE, $OUT
# (and $FUZZING_ENGINE when set). Writes each harness to $OUT/<name>, its seed
# corpus to $OUT/<name>_seed_corpus.zip and its dictionary to $OUT/<name>.dict.
# With libFuzzer, the harnesses marked `mutator` in fuzz/harnesses.txt are
# also built as <name>_structure_aware (robowire::fuzz::mutate as the mutator).
# Run from fuzz/oss-fuzz/ in the source tree, or, copied elsewhere (OSS-Fuzz's
# $SRC/build.sh), from the source tree as the working directory.
# Local test:
#   CXX=clang++ CXXFLAGS="-fsanitize=address,fuzzer-no-link -O1 -g" \
#   LIB_FUZZING_ENGINE=-fsanitize=fuzzer OUT=/tmp/out fuzz/oss-fuzz/build.sh
case "${1:-}" in -h | --help) sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;; esac  # usage: the comment above
root="$(cd "$(dirname "$0")/../.." && pwd)"
[ -f "$root/fuzz/harnesses.txt" ] || root="$PWD"
mkdir -p "$OUT"
# One harness: the binary, its dictionary and its seed corpus.
build_one() {
  local h=$1 dict=$2 t=$3 defines=()
  [ "$t" != "$h" ] && defines=(-DROBOWIRE_FUZZ_STRUCTURE_AWARE)
  # shellcheck disable=SC2086  # CXXFLAGS and LIB_FUZZING_ENGINE are word lists
  $CXX $CXXFLAGS -std=c++20 "${defines[@]}" -I"$root/include" "$root/fuzz/$h.cpp" -o "$OUT/$t" $LIB_FUZZING_ENGINE
  cp "$root/fuzz/dict/$dict.dict" "$OUT/$t.dict"
  rm -f "$OUT/${t}_seed_corpus.zip"
  python3 - "$OUT/${t}_seed_corpus.zip" "$root/fuzz/corpus/$h" <<'PY'
import os, sys, zipfile
with zipfile.ZipFile(sys.argv[1], "w") as z:
    for name in sorted(os.listdir(sys.argv[2])):
        z.write(os.path.join(sys.argv[2], name), name)
PY
}
# The harnesses build in parallel, one per core ($ROBOWIRE_BUILD_JOBS to set).
jobs_max=${ROBOWIRE_BUILD_JOBS:-$(nproc 2>/dev/null || echo 2)}
pids=()
# fuzz/harnesses.txt: "<name> <dictionary> [mutator]" per line
while read -r h dict mutator _ <&3; do
  case $h in '' | '#'*) continue ;; esac
  targets=("$h")
  [ -n "$mutator" ] && [ "${FUZZING_ENGINE:-libfuzzer}" = libfuzzer ] && targets+=("${h}_structure_aware")
  for t in "${targets[@]}"; do
    while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do wait -n || true; done
    build_one "$h" "$dict" "$t" &
    pids+=($!)
  done
done 3< "$root/fuzz/harnesses.txt"
failed=0
for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
exit "$failed"
