#!/usr/bin/env bash
# The README's test command: installs what is needed, builds in Release with warnings as
# errors and runs every test suite (the Python module's among them), installs the Python
# package with pip and tests that copy, then runs the unit tests again under AddressSanitizer and
# UndefinedBehaviorSanitizer, then fuzzes each input parser and the whole operation for a
# bounded time.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
jobs=$(nproc)
# Each section says when it starts (seconds since the script began), so that a slow CI run
# shows where its time went.
section() { echo "== $1 (at ${SECONDS}s)"; }

section "Release build and tests"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DMK_WERROR=ON >/dev/null
cmake --build build -j "$jobs"
ctest --test-dir build -j "$jobs" --output-on-failure

section "Python package: pip install offline, tests against the installed copy"
# ctest ran the Python tests on the build tree (pythonTests); here the package goes through
# pip as a user installs it (python/setup.py, reusing the Release build) into a scratch
# folder, and the docs, input and hostile-input tests run against that copy (seconds).
site="$(mktemp -d)"
MKBOOL_CMAKE_BUILD_DIR=build /usr/bin/python3 -m pip install --quiet --root-user-action=ignore --no-build-isolation --no-deps \
  --no-index --target "$site" ./python
PYTHONPATH="$site" MKBOOL_EXPECTED_PACKAGE="$site/mkbool" \
  /usr/bin/python3 -m pytest -q -p no:cacheprovider python/tests/test_docs.py python/tests/test_inputs.py \
  python/tests/test_hostile.py
rm -rf "$site"

section "AddressSanitizer + UndefinedBehaviorSanitizer"
# The benchmarks and the headers' layer check (compile-only) were built in Release above.
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Sanitize "-DCMAKE_CXX_FLAGS_SANITIZE=-Og -DNDEBUG" -DMK_SANITIZE=ON -DMK_WERROR=ON "-DMK_SKIP_PARTS=bench" -DMK_CHECK_LAYERS=OFF >/dev/null
cmake --build build-asan -j "$jobs"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-asan -j "$jobs" --output-on-failure -LE slow

if [ -x fuzz/run.sh ] || [ -f fuzz/run.sh ]; then
  section "Fuzzing the parsers and the whole operation"
  bash fuzz/run.sh 20
fi
section "all tests passed"
