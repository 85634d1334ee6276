#!/usr/bin/env bash
# The clang-tidy job (docs/reliability.md): the committed .clang-tidy on every
# source of runtime/, compiler/ and cli/, each with its own compile command.
# Fails on any warning.
#
# The release tree compiles those sources in unity batches
# (cmake/RiftUnity.cmake), so its compile commands name the batches, not the
# sources, and a command clang-tidy guessed for a source would be another
# target's. The job therefore configures a tree of its own without batches
# (build/tidy, or $RIFT_TIDY_BUILD) and generates there only the parser and
# lexer riftc's sources include: nothing is compiled in it. Checked alone, a
# source that misses an #include fails here, as it would in a build without
# batches.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -ne 0 ]; then
  # It once read the compile commands of the folder given (build/release):
  # configuring that folder without batches would change the user's build.
  echo "clang-tidy.sh takes no argument: it configures build/tidy" \
    "(set RIFT_TIDY_BUILD for another folder)" >&2
  exit 2
fi
build=${RIFT_TIDY_BUILD:-build/tidy}
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRIFT_WERROR=ON \
  -DRIFT_UNITY_BUILD=OFF -DRIFT_UNITY_TESTS=OFF > /dev/null
cmake --build "$build" --target compiler/generated/parse/parser.cpp \
  compiler/generated/parse/lexer.cpp > /dev/null
# The newest installed clang-tidy: 22 (scripts/setup.sh installs it where
# Debian has it) runs the same checks about 2.8 times faster than 14 on this
# tree, because it no longer matches inside system headers.
tidy=$(command -v clang-tidy-22 || command -v clang-tidy-19 || command -v clang-tidy-14 ||
  command -v clang-tidy)
# Each file alone (xargs -P for the two cores), quiet unless it warns.
find runtime compiler cli -name '*.cpp' -print0 | sort -z |
  xargs -0 -n 1 -P "$jobs" "$tidy" -p "$build" --quiet --warnings-as-errors='*' 2>/dev/null
echo "clang-tidy: no warning"
