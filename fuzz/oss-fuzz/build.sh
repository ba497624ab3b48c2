#!/bin/bash -eu
# OSS-Fuzz build script. Honours the OSS-Fuzz contract: $CXX, $CXXFLAGS,
# $LIB_FUZZING_ENGINE, $OUT. Writes each harness to $OUT/<name>, its seed
# corpus to $OUT/<name>_seed_corpus.zip and its dictionary to $OUT/<name>.dict.
# Local test:
#   CXX=clang++ CXXFLAGS="-fsanitize=address,fuzzer-no-link -O1 -g" \
#   LIB_FUZZING_ENGINE=-fsanitize=fuzzer OUT=/tmp/out fuzz/oss-fuzz/build.sh
root="$(cd "$(dirname "$0")/../.." && pwd)"
mkdir -p "$OUT"
harnesses="buwizz3_command buwizz3_notification buwizz3_advertisement navbot_frame navbot_reassembler
           osp_decode osp_scanner roundtrip_buwizz3 roundtrip_navbot roundtrip_osp"
for h in $harnesses; do
  case $h in *buwizz3*) dict=buwizz3 ;; *navbot*) dict=navbot ;; *) dict=osp ;; esac
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
done
