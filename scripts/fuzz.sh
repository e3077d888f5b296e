#!/usr/bin/env bash
# Fuzzes the glTF loader for SECONDS (default 3600): configures and builds the 'fuzz' preset (clang,
# libFuzzer, ASan + UBSan), then runs gltf_fuzz from the seeds and the regressions with the dictionary.
# The fuzzer keeps going after a finding (fork mode); each crash, hang or out-of-memory input lands in
# build/fuzz/crashes/. New interesting inputs collect in build/fuzz/corpus/ and carry over to the next
# run. Prints one summary line at the end; exits 1 when something was found or the fuzzer failed.
# Usage: scripts/fuzz.sh [SECONDS]      (FUZZ_JOBS=N runs N fuzzing processes, default 1)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-3600}"
jobs="${FUZZ_JOBS:-1}"

runtime=(/usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a)
if ! command -v clang++ >/dev/null || [ ! -e "${runtime[0]}" ]; then
    echo "fuzz: needs clang and libFuzzer: sudo apt-get install clang libclang-rt-dev" >&2
    exit 1
fi
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz

out=build/fuzz
mkdir -p "$out/corpus" "$out/crashes"
before=$(find "$out/crashes" -type f | wc -l)
log="$out/fuzz.log"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
set +e
"$out/tests/fuzz/gltf_fuzz" "$out/corpus" tests/fuzz/corpus tests/fuzz/regressions \
    -dict=tests/fuzz/gltf.dict -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -fork="$jobs" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -artifact_prefix="$out/crashes/" -print_final_stats=1 >"$log" 2>&1
status=$?
set -e

# Fork mode reports "#N: cov: C ft: F corp: K exec/s E oom/timeout/crash: O/T/X time: Ss ...".
last=$(grep -E '^#[0-9]+: cov:' "$log" | tail -n 1 || true)
execs=$(sed -E 's/^#([0-9]+):.*/\1/' <<<"$last")
took=$(sed -nE 's/.* time: ([0-9]+)s.*/\1/p' <<<"$last")
took=${took:-0}
rate=$(( took > 0 ? ${execs:-0} / took : 0 ))  # averaged: the line's own exec/s is its last job's
cov=$(sed -nE 's/.* cov: ([0-9]+).*/\1/p' <<<"$last")
found=$(( $(find "$out/crashes" -type f | wc -l) - before ))
corpus=$(find "$out/corpus" -type f | wc -l)
echo "fuzz: ${seconds} s, ${execs:-0} runs (${rate} exec/s), coverage ${cov:-?}, corpus ${corpus} files," \
     "${found} new finding(s) in $out/crashes/ (log: $log, exit $status)"
[ "$found" -eq 0 ] && [ "$status" -eq 0 ]
