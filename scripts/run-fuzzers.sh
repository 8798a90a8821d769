#!/usr/bin/env bash
# Coverage-guided fuzzing of libtravel (libFuzzer + ASan + UBSan), see tests/fuzz/.
#
#   scripts/run-fuzzers.sh [SECONDS_PER_TARGET]      (default 60; CI smoke run)
#
# Builds tests/fuzz (standalone CMake project) with clang into ./build-fuzz (-O1 -g), then runs
# every target for SECONDS_PER_TARGET on a COPY of its seed corpus (tests/fuzz/corpus/<target>,
# which is never modified). Exits non-zero if any target crashes, leaks, hits a sanitizer report
# or a FUZZ_CHECK. Crash reproducers are kept in build-fuzz/findings/<target>/.
#
# Longer runs (nightly / before a release), e.g. one hour per target:
#   scripts/run-fuzzers.sh 3600
# Environment: FUZZ_TARGETS="fuzz_params fuzz_segmentation" (subset), FUZZ_JOBS=N (parallel
# libFuzzer workers per target, default 1), FUZZ_PARALLEL=N (targets fuzzed at the same time,
# default: the number of cores; each target still gets its full SECONDS_PER_TARGET of one core),
# FUZZ_RAWLOG=0 (skip fuzz_rawlog),
# TRAVEL_FUZZ_MRPT=OFF (do not even build fuzz_rawlog),
# CXX (default clang++). Reproduce a finding: build-fuzz/<target> build-fuzz/findings/<target>/crash-*
set -euo pipefail

SECONDS_PER_TARGET="${1:-60}"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${ROOT}/build-fuzz"
CXX="${CXX:-clang++}"
MRPT="${TRAVEL_FUZZ_MRPT:-ON}"
JOBS="${FUZZ_JOBS:-1}"
PARALLEL="${FUZZ_PARALLEL:-$(nproc)}"

generator=()
command -v ninja >/dev/null 2>&1 && generator=(-G Ninja)
if [[ ! -f "${BUILD}/CMakeCache.txt" ]]; then
    cmake -S "${ROOT}/tests/fuzz" -B "${BUILD}" "${generator[@]}" -DCMAKE_CXX_COMPILER="${CXX}" \
        -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTRAVEL_FUZZ_MRPT="${MRPT}"
fi
# Serialise concurrent invocations' builds (two ninjas in one build tree clash).
mkdir -p "${BUILD}"
if command -v flock >/dev/null 2>&1; then
    flock "${BUILD}/.build.lock" cmake --build "${BUILD}" -j "$(nproc)"
else
    cmake --build "${BUILD}" -j "$(nproc)"
fi

targets=(fuzz_kitti_bin fuzz_scan_reader fuzz_label_file fuzz_params fuzz_segmentation)
# fuzz_rawlog: MRPT 2.5's deserializers allocate whatever size a corrupt stream announces
# (CPointsMapXYZI::resize via aligned_alloc, CSensoryFrame's deque). travel-rawlog caps its
# address space (--max-memory) and replaces mrpt::aligned_malloc so that failure throws; the
# harness gets the same behaviour from its operator new cap plus, below, ASan's
# max_allocation_size_mb with allocator_may_return_null (malloc returns null, which
# apps/MemoryLimit.cpp's mrpt::aligned_malloc turns into std::bad_alloc).
[[ "${MRPT}" == "ON" && "${FUZZ_RAWLOG:-1}" == "1" ]] && targets+=(fuzz_rawlog)
[[ -n "${FUZZ_TARGETS:-}" ]] && read -r -a targets <<<"${FUZZ_TARGETS}"

export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1:symbolize=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

# One target: fuzz it, then write its summary line to ${BUILD}/fuzz-work/<target>/result (the
# first word says whether it failed), so that targets can run side by side.
fuzz_target() {
    local t="$1"
    local work="${BUILD}/fuzz-work/${t}"
    local findings="${BUILD}/findings/${t}"
    local log="${work}/fuzz.log"
    local seeds runs cov corpus status=0 extra=() target_asan result
    seeds=$(find "${work}/corpus" -type f | wc -l)
    [[ "${JOBS}" -gt 1 ]] && extra=(-fork="${JOBS}" -ignore_crashes=0)
    target_asan="${ASAN_OPTIONS}"
    [[ "${t}" == "fuzz_rawlog" ]] && target_asan="${ASAN_OPTIONS}:allocator_may_return_null=1:max_allocation_size_mb=256"
    (cd "${work}" && ASAN_OPTIONS="${target_asan}" "${BUILD}/${t}" "${work}/corpus" -max_total_time="${SECONDS_PER_TARGET}" \
        -rss_limit_mb=2048 -timeout=60 -max_len=65536 -print_final_stats=1 \
        -artifact_prefix="${findings}/" "${extra[@]}") >"${log}" 2>&1 || status=$?
    runs=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "${log}" | grep -oE '[0-9]+$' | tail -1)
    [[ -z "${runs}" ]] && runs=$(grep -oE '^#[0-9]+' "${log}" | tail -1 | tr -d '#')
    cov=$(grep -oE 'cov: [0-9]+ ft: [0-9]+' "${log}" | tail -1)
    corpus=$(find "${work}/corpus" -type f | wc -l)
    if [[ ${status} -ne 0 ]] || grep -qE 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:|FUZZ_CHECK failed' "${log}"; then
        result="FOUND SOMETHING (exit ${status}); see ${log} and ${findings}/"
        grep -E 'ERROR:|runtime error:|FUZZ_CHECK|SUMMARY|Test unit written' "${log}" | head -8 || true
        echo "FAILED ${t}: runs ${runs:-?}, ${cov:-cov ?}, corpus ${seeds} -> ${corpus} files: ${result}" >"${work}/result"
    else
        echo "ok ${t}: runs ${runs:-?}, ${cov:-cov ?}, corpus ${seeds} -> ${corpus} files: nothing found" >"${work}/result"
    fi
}

running=0
for t in "${targets[@]}"; do
    work="${BUILD}/fuzz-work/${t}"
    rm -rf "${work}"
    mkdir -p "${work}/corpus" "${BUILD}/findings/${t}"
    cp -r "${ROOT}/tests/fuzz/corpus/${t}/." "${work}/corpus/" 2>/dev/null || true
    echo "=== ${t}: ${SECONDS_PER_TARGET} s, $(find "${work}/corpus" -type f | wc -l) seeds"
    if [[ ${running} -ge ${PARALLEL} ]]; then
        wait -n || true
        running=$((running - 1))
    fi
    fuzz_target "${t}" &
    running=$((running + 1))
done
wait || true

failed=()
summary=()
for t in "${targets[@]}"; do
    result_file="${BUILD}/fuzz-work/${t}/result"
    if [[ ! -f "${result_file}" ]]; then
        summary+=("${t}: no result (the run did not finish)")
        failed+=("${t}")
        continue
    fi
    read -r status line <"${result_file}"
    summary+=("${line}")
    [[ "${status}" == "FAILED" ]] && failed+=("${t}")
done

echo
echo "=== fuzzing summary (${SECONDS_PER_TARGET} s per target)"
printf '%s\n' "${summary[@]}"
if [[ ${#failed[@]} -gt 0 ]]; then
    echo "FAILED: ${failed[*]}"
    exit 1
fi
echo "all fuzz targets clean"
