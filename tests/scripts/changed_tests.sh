#!/usr/bin/env bash
# scripts/changed-tests picks the unit test programs of the changed areas:
# a protocol's header or test -> its program, core and shared files -> all,
# docs and tools -> none. Exit 1 naming each case that picks otherwise.
set -uo pipefail
cd "$(dirname "$0")/../.."
all=$(tests/unit_sources.sh | sed 's|/.*||' | sort -u | sed 's/^/robowire_tests_/' | tr '\n' ' ')
bad=0
expect() {  # expect "PROGRAMS" PATH...
  local want=$1 got; shift
  got=$(scripts/changed-tests --files "$@" | tr '\n' ' ')
  if [ "$got" != "$want" ]; then echo "changed-tests --files $*: got '$got', want '$want'"; bad=1; fi
}
expect "robowire_tests_osp " include/robowire/osp/messages.hpp
expect "robowire_tests_osp " include/robowire/osp.hpp
expect "robowire_tests_navbot robowire_tests_osp " tests/navbot/maneuver.cpp include/robowire/osp/scanner.hpp
expect "robowire_tests_buwizz3 " tests/buwizz3/status.cpp docs/buwizz3.md
expect "robowire_tests_fuzz " include/robowire/ext/fuzz.hpp
expect "" docs/cli.md tools/main.cpp scripts/test
expect "$all" include/robowire/core/bits.hpp
expect "$all" include/robowire/robowire.hpp
expect "$all" tests/check.hpp
expect "$all" tests/CMakeLists.txt
expect "$all" include/robowire/no_test_folder.hpp
[ "$bad" -eq 0 ] && echo "changed-tests: 11 cases pick the expected programs"
exit "$bad"
