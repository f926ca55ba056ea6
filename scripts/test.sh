#!/usr/bin/env bash
# The README's test command: installs what is needed, builds in Release with warnings as
# errors and runs every test suite, then runs the unit tests again under AddressSanitizer and
# UndefinedBehaviorSanitizer, then fuzzes each input parser and the whole operation for a
# bounded time.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
jobs=$(nproc)

echo "== Release build and tests"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DMK_WERROR=ON >/dev/null
cmake --build build -j "$jobs"
ctest --test-dir build -j "$jobs" --output-on-failure

echo "== AddressSanitizer + UndefinedBehaviorSanitizer"
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Sanitize "-DCMAKE_CXX_FLAGS_SANITIZE=-O1 -DNDEBUG" -DMK_SANITIZE=ON -DMK_WERROR=ON "-DMK_SKIP_PARTS=bench" >/dev/null
cmake --build build-asan -j "$jobs"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-asan -j "$jobs" --output-on-failure -LE slow

if [ -x fuzz/run.sh ] || [ -f fuzz/run.sh ]; then
  echo "== Fuzzing the parsers and the whole operation"
  bash fuzz/run.sh 25
fi
echo "== all tests passed"
