#!/bin/bash -eu
# ClusterFuzzLite build: the same as OSS-Fuzz's (harnesses, seed corpora, dictionaries in $OUT).
"$SRC/robowire/fuzz/oss-fuzz/build.sh"
