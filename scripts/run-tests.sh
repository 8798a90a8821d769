#!/usr/bin/env bash
# The README's test command, and what CI runs (.ci/run). Each test runs in the builds that can
# run it: the unit tests under the sanitizers (the multi-threaded one also under
# ThreadSanitizer); the apps' scripted checks, the plugin's round trip and map-by-path checks and
# the docs checks in both builds (the Release binaries are what users run; the sanitizers check
# their memory); the rest in one:
#   1. scripts/setup.sh --no-unit-tests: installs the missing Debian packages and builds ./build
#      (Release: the libraries, apps, plugin, Python module and benchmarks; of the tests, those
#      that need this build: see 2)
#   2. CTest on ./build: the apps' and the plugin's scripted checks (MRPT's own rawlog-edit and
#      RawLogViewer load the plugin: they cannot load a sanitized one), the Python module (python3
#      cannot load a sanitized extension), the installed package and the figure tests
#      (closed-loop navigation, the real drive's tracking and registration)
#   3. the unit tests and the apps' scripted checks under AddressSanitizer +
#      UndefinedBehaviorSanitizer (./build-asan, -Og; MRPT itself is not instrumented), then the
#      Release build's labels compared byte for byte with the sanitizer build's (one scan of
#      every scene the unit tests use, and the real scans: the unit tests do not run on the -O3
#      library, this shows that their thresholds carry over), and the multi-threaded test under
#      ThreadSanitizer (./build-tsan)
#   4. libFuzzer targets, 10 s each (TRAVEL_FUZZ_SECONDS), built with clang (scripts/run-fuzzers.sh)
#   5. clang-format check of every C++ file, when clang-format is installed
# `scripts/setup.sh` alone builds the unit tests into ./build too (TRAVEL_BUILD_UNIT_TESTS).
# Tests that need the real scans (SemanticKITTI etc., TRAVEL_DATA_DIR) skip with a message when absent.
set -euo pipefail

ROOT_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT_DIR"
TIMES_FILE=$(mktemp)
trap 'rm -f "$TIMES_FILE"' EXIT
# Each line says the wall time so far and the CPU time (user + sys) its child processes have used,
# so that a slow phase shows in CI's log.
log() {
  local cpu
  times >"$TIMES_FILE" # the builtin in this shell: a $(times) subshell reports its own children
  cpu=$(awk 'NR == 2 { for (i = 1; i <= 2; ++i) { split($i, t, /[ms]/); s += t[1] * 60 + t[2] } printf "%.0f", s }' "$TIMES_FILE")
  printf '[run-tests %4d s, cpu %5d s] %s\n' "$SECONDS" "$cpu" "$*"
}

log "setup: packages, then the Release build (build/, without the unit tests)"
"$ROOT_DIR/scripts/setup.sh" --no-unit-tests

log "Release suite (build/): apps, plugin in MRPT's apps, Python, install, figures"
ctest --test-dir build -j2 --output-on-failure

log "sanitizer build (build-asan/: address,undefined)"
# -Og -g1: -O1's optimisations that keep debugging sane, at 40-70 % of -O1's compile time under
# ASan (Config.cpp 11.4 -> 7.0 s, SyntheticLidar.cpp 11.0 -> 5.3 s, a test source 49 -> 19 s;
# the compile is two thirds of this step), file:line in every sanitizer report.
# -Wno-maybe-uninitialized: with ASan, GCC 12 warns inside libstdc++'s <regex> (std::function in
# its automaton); the plain build keeps the warning.
asan=(cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTRAVEL_SANITIZE=address,undefined
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-Og -g1 -DNDEBUG -Wno-maybe-uninitialized" -DTRAVEL_TEST_COMPILE_OPTIONS= -DTRAVEL_BUILD_MRPT=ON
      -DTRAVEL_BUILD_TESTS=ON -DTRAVEL_BUILD_UNIT_TESTS=ON -DTRAVEL_BUILD_FIGURE_TESTS=OFF
      -DTRAVEL_BUILD_BENCHMARKS=OFF -DTRAVEL_BUILD_PYTHON=OFF)
[[ -f build-asan/CMakeCache.txt ]] || asan+=(-G Ninja)
"${asan[@]}" >/dev/null
cmake --build build-asan -j2
# The closed-loop navigation runs (tens of simulated seconds of MRPT's navigator each) take
# minutes under ASan; they run in the plain suite above, their TRAVEL code paths are covered
# under ASan by the obstacle-source and map tests. IndependentRegistration (travel-kitti --track
# and MRPT's ICP over the 22-frame drive) is a figure, not a code path: plain suite only.
# Neither is even built here (TRAVEL_BUILD_FIGURE_TESTS=OFF saves minutes of ASan compilation);
# the filter stays for a build-asan/ configured by hand with them. test_tracking_sequences is
# built in both: its TrackingSynthetic runs here, its TrackingReal in the Release suite (a
# build without the unit tests registers only that one: tests/CMakeLists.txt).
# The apps' common-flag checks (the one flag dialect: parsing and messages, all code paths the
# apps' own CLI tests run under ASan too) and the installed package's consumer build (CMake, no
# TRAVEL code runs) are plain suite only as well: ~2 minutes of CI's 30. So are the apps' -j
# checks (outputs identical to -j 1: a property of the threading, which the ThreadSanitizer step
# below checks, and of the ordering, which the plain suite checks), the quiet / progress /
# interrupt check (the output's wording and SIGINT's flag; under ASan 68 s of apps replayed
# again) and TrackingReal (a figure on the real drive, its code paths under ASan in
# TrackingSynthetic): ~70 s of the sanitizer suite's wall time. travel-nav-sim's CLI check runs
# closed-loop navigation too (21 s under ASan).
ASAN_SKIP='^(NavClosedLoop\.|apps\.travel_nav_sim_cli$|Seeds/TravelOnRampKerb\.|Seeds/MapOnRampKerb\.|IndependentRegistration\.|TrackingReal\.|apps\.travel_[a-z_]+_common_flags$|apps\.(jobs_cli|travel_map_jobs|travel_rawlog_jobs|quiet_progress_interrupt_cli)$|install\.consumer$)'
log "unit tests and apps under sanitizers (build-asan/)"
# allocator_may_return_null: a corrupt rawlog's absurd sizes reach MRPT's allocator; the apps
# turn the failure into a clean error (apps/MemoryLimit.hpp) instead of ASan aborting.
asan_env=(env LSAN_OPTIONS=suppressions="$ROOT_DIR/tests/lsan.supp"
          ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:allocator_may_return_null=1
          UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1)
"${asan_env[@]}" ctest --test-dir build-asan -j2 --output-on-failure -E "$ASAN_SKIP"

log "Release labels = sanitizer build's labels (synthetic scenes; real scans when TRAVEL_DATA_DIR holds them)"
"${asan_env[@]}" cmake -DRELEASE_KITTI=build/apps/travel-kitti -DCHECKED_KITTI=build-asan/apps/travel-kitti \
  -DMAKE_SCANS=build/tests/make_synthetic_scans -DWORK_DIR="$ROOT_DIR/build/same_labels_across_builds" \
  -DDATA_DIR="$(sed -n 's/^TRAVEL_DATA_DIR:PATH=//p' build/CMakeCache.txt)" \
  -P tests/cli/test_same_labels_across_builds.cmake

log "thread sanitizer build (build-tsan/): one Pipeline per thread, identical results"
tsan=(cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTRAVEL_SANITIZE=thread
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-Og -g1 -DNDEBUG"
      -DTRAVEL_BUILD_TESTS=ON -DTRAVEL_BUILD_UNIT_TESTS=ON -DTRAVEL_BUILD_MRPT=OFF -DTRAVEL_BUILD_BENCHMARKS=OFF -DTRAVEL_BUILD_PYTHON=OFF)
[[ -f build-tsan/CMakeCache.txt ]] || tsan+=(-G Ninja)
"${tsan[@]}" >/dev/null
cmake --build build-tsan -j2 --target test_robustness
TSAN_OPTIONS=halt_on_error=1 build-tsan/tests/test_robustness --gtest_filter='*Thread*'

# Bounded fuzzing of every reader and the segmentation entry point (scripts/run-fuzzers.sh;
# longer runs: scripts/run-fuzzers.sh 3600).
log "fuzzing: ${TRAVEL_FUZZ_SECONDS:-10} s per target"
bash "$ROOT_DIR/scripts/run-fuzzers.sh" "${TRAVEL_FUZZ_SECONDS:-10}"

if command -v clang-format >/dev/null 2>&1; then
  log "clang-format check"
  git ls-files '*.cpp' '*.hpp' | xargs clang-format --dry-run --Werror
else
  log "clang-format not installed: format check skipped"
fi
log "all tests passed"
