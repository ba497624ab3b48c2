#!/usr/bin/env bash
# Fails when a protocol header (include/robowire/<protocol>/*.hpp, the
# umbrellas) names robowire::detail or includes core/detail/: protocols use
# the public API (robowire, robowire::codec; docs/extending.md). Comments are
# not searched. reflect.hpp is part of the core (it names the tables' own
# lookups); ext/fuzz.hpp, an optional extra, is held to the protocols' rule.
cd "$(dirname "$0")/../include/robowire" || exit 1
headers=$(ls -- */*.hpp *.hpp | grep -v -e '^core/' -e '^reflect\.hpp$')
[ -n "$headers" ] || { echo "no protocol headers found"; exit 1; }
found=$(for h in $headers; do
  sed 's://.*$::' "$h" | grep -n -w 'detail' | sed "s|^|include/robowire/$h:|"
done)
if [ -n "$found" ]; then
  echo "protocol headers use robowire::detail (use robowire::codec, docs/extending.md):"
  echo "$found"
  exit 1
fi
echo "$(echo "$headers" | wc -l) protocol headers, none uses robowire::detail"
