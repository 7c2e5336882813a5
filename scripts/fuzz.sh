#!/usr/bin/env bash
# Fuzzes the scenario reader: scripts/fuzz.sh [SECONDS] [libFuzzer options...] (default 600 s).
# Builds tests/fuzz/scenario_fuzz.cpp with clang, libFuzzer, AddressSanitizer and
# UndefinedBehaviorSanitizer into build-fuzz/, then feeds it mutated scenario files, starting
# from examples/*.toml. Inputs that crash, hang or leak land in build-fuzz/crashes/; replay one
# with TALUS_FUZZ_VERBOSE=1 build-fuzz/tests/fuzz/talus_scenario_fuzz FILE. Not part of CI: a
# session has no natural end. Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true
./scripts/install-deps.sh clang libclang-rt-dev libomp-dev

build=build-fuzz
# -O1 -g: fast enough to fuzz, with exact stack traces; asserts stay on.
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" \
  -DTALUS_FUZZ=ON -DTALUS_BUILD_TESTS=OFF -DTALUS_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target talus_scenario_fuzz

# The seeds are copied afresh (the examples may have changed); the corpus grows from run to run.
rm -rf "$build/seeds"
mkdir -p "$build/seeds" "$build/corpus" "$build/crashes"
cp examples/*.toml "$build/seeds/"

# max_len: the largest example is 3 kB. timeout: the slowest clean inputs, a dam break whose
# crosses fit the region in no orientation (a million are drawn before the InputError), take
# 30 s under the sanitizers, and 47 s were seen on a busy machine; inputs slower than 30 s are
# kept as slow-unit-* (a notice, not a failure). rss_limit_mb: the reader refuses more than 50 particles here
# (scenario_fuzz.cpp), so 2 GB is a leak or an absurd allocation, not a big scenario.
exec "$build/tests/fuzz/talus_scenario_fuzz" "$build/corpus" "$build/seeds" \
  -dict=tests/fuzz/scenario.dict -max_len=8192 -timeout=120 -report_slow_units=30 -rss_limit_mb=2048 \
  -max_total_time="$seconds" -artifact_prefix="$build/crashes/" -print_final_stats=1 "$@"
