#!/bin/bash -eu
# OSS-Fuzz build script. Honours the OSS-Fuzz contract: $CXX, $CXXFLAGS,
# $LIB_FUZZING_ENGINE, $OUT. Writes each harness to $OUT/<name>, its seed
# corpus to $OUT/<name>_seed_corpus.zip and its dictionary to $OUT/<name>.dict.
# Local test:
#   CXX=clang++ CXXFLAGS="-fsanitize=address,fuzzer-no-link -O1 -g" \
#   LIB_FUZZING_ENGINE=-fsanitize=fuzzer OUT=/tmp/out fuzz/oss-fuzz/build.sh
root="$(cd "$(dirname "$0")/../.." && pwd)"
mkdir -p "$OUT"
# fuzz/harnesses.txt: "<name> <dictionary>" per line
while read -r h dict _ <&3; do
  case $h in '' | '#'*) continue ;; esac
  # shellcheck disable=SC2086  # CXXFLAGS and LIB_FUZZING_ENGINE are word lists
  $CXX $CXXFLAGS -std=c++20 -I"$root/include" "$root/fuzz/$h.cpp" -o "$OUT/$h" $LIB_FUZZING_ENGINE
  cp "$root/fuzz/dict/$dict.dict" "$OUT/$h.dict"
  rm -f "$OUT/${h}_seed_corpus.zip"
  python3 - "$OUT/${h}_seed_corpus.zip" "$root/fuzz/corpus/$h" <<'PY'
import os, sys, zipfile
with zipfile.ZipFile(sys.argv[1], "w") as z:
    for name in sorted(os.listdir(sys.argv[2])):
        z.write(os.path.join(sys.argv[2], name), name)
PY
done 3< "$root/fuzz/harnesses.txt"
