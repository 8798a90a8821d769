#!/usr/bin/env bash
# Installs what TRAVEL needs on Debian bookworm (only the missing packages; clang for the fuzz
# targets), then builds the project into ./build (Release, Ninja). Safe to run again: it installs
# nothing when everything is present and the build is incremental.
#
#   scripts/setup.sh                 install missing packages, then build everything
#   scripts/setup.sh --target T ...  install missing packages, then build only target(s) T
#   scripts/setup.sh --no-build      install missing packages only
#   scripts/setup.sh --demo ...      only the packages and targets of the apps and the plugin
#                                    (no tests, benchmarks, fuzzers or Python module)
#   scripts/setup.sh --no-unit-tests  everything but the unit tests (scripts/run-tests.sh runs
#                                    those in its sanitizer build; TRAVEL_BUILD_UNIT_TESTS)
set -euo pipefail

ROOT_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="$ROOT_DIR/build"
PACKAGES=(
  libyaml-cpp-dev
  cmake ninja-build g++ pkg-config
  libeigen3-dev libmrpt-maps-dev libmrpt-nav-dev libmrpt-gui-dev libmrpt-tclap-dev
  libmrpt-hwdrivers-dev
  liboctomap-dev mrpt-common libnanoflann-dev
  lld  # the linker (TRAVEL_USE_LLD): a quarter of GNU ld's time per link
)
# Only for the test suite, the benchmarks, the fuzzers and the Python module (not with --demo).
TEST_PACKAGES=(
  libgtest-dev googletest libbenchmark-dev libmrpt-slam-dev
  clang libclang-rt-14-dev
  python3-dev python3-pybind11 python3-numpy python3-pytest python3-open3d
  mrpt-apps xvfb xauth  # rawlog-edit -p and RawLogViewer -l loading the plugin (tests/plugin)
)

log() { printf '[setup] %s\n' "$*"; }
die() { printf '[setup] error: %s\n' "$*" >&2; exit 1; }

build=1
demo=0
unit_tests=ON
targets=()
while (($# > 0)); do
  case "$1" in
    --no-build) build=0 ;;
    --demo) demo=1 ;;
    --no-unit-tests) unit_tests=OFF ;;
    --target)
      (($# > 1)) || die "--target needs a target name (e.g. travel-rawlog)"
      targets+=(--target "$2"); shift ;;
    -h|--help) sed -n '2,12p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown option '$1' (options: --no-build, --demo, --no-unit-tests, --target NAME)" ;;
  esac
  shift
done

# ---- Packages ------------------------------------------------------------------------------
command -v dpkg-query >/dev/null 2>&1 || die "dpkg-query not found: this script supports Debian bookworm (apt) only"
((demo)) || PACKAGES+=("${TEST_PACKAGES[@]}")
missing=()
for pkg in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$pkg")
  fi
done

if ((${#missing[@]} == 0)); then
  log "all ${#PACKAGES[@]} required packages are installed"
else
  if [[ "$(id -u)" -eq 0 ]]; then
    as_root=()
  elif command -v sudo >/dev/null 2>&1; then
    as_root=(sudo)
  else
    die "missing packages (${missing[*]}) and not root, and sudo is not available"
  fi
  log "missing packages: ${missing[*]}"
  log "running: apt-get update"
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
  log "running: apt-get install -y --no-install-recommends ${missing[*]}"
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${missing[@]}"
fi

# ---- Build ---------------------------------------------------------------------------------
if ((build == 0)); then
  log "--no-build: skipping the build"
  exit 0
fi

configure=(cmake -S "$ROOT_DIR" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release)
# Stated every time: a build folder configured by --demo is switched back by a full setup.
if ((demo)); then
  configure+=(-DTRAVEL_BUILD_TESTS=OFF -DTRAVEL_BUILD_BENCHMARKS=OFF -DTRAVEL_BUILD_PYTHON=OFF)
else
  # Test sources at -O1 (TRAVEL_TEST_COMPILE_OPTIONS): the libraries, apps and benchmarks they
  # exercise stay Release (-O3); -O3 on the tests' own code only costs build time.
  configure+=(-DTRAVEL_BUILD_TESTS=ON -DTRAVEL_BUILD_UNIT_TESTS=$unit_tests
              -DTRAVEL_BUILD_FIGURE_TESTS=ON -DTRAVEL_BUILD_BENCHMARKS=ON -DTRAVEL_BUILD_PYTHON=ON
              -DTRAVEL_TEST_COMPILE_OPTIONS=-O1)
fi
# The generator of an existing build directory cannot change; choose Ninja only for a new one.
[[ -f "$BUILD_DIR/CMakeCache.txt" ]] || configure+=(-G Ninja)
log "configuring: ${configure[*]}"
"${configure[@]}"
log "building: cmake --build $BUILD_DIR -j2 ${targets[*]}"
cmake --build "$BUILD_DIR" -j2 "${targets[@]}"
log "done: built in $BUILD_DIR (tools in $BUILD_DIR/apps)"
