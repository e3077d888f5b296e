#!/usr/bin/env bash
# Second README command: set up, build (warnings are errors), fuzz the glTF loader for a minute, and
# run the whole test suite headless.
# GL tests use a headless EGL context; the window test needs a display, so without one the suite runs
# under xvfb-run (a virtual X server). Its server runs with -noreset: by default Xvfb resets whenever its
# last client leaves, and a window test connecting during that reset fails to open the display (four
# processes opening and closing the display 400 times each: 55 failures in 1,600 by default, none with
# -noreset).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh ci
export VIZ_REQUIRE_GL="${VIZ_REQUIRE_GL:-1}"
export VIZ_REQUIRE_DISPLAY="${VIZ_REQUIRE_DISPLAY:-1}"
export VIZ_REQUIRE_BROWSER="${VIZ_REQUIRE_BROWSER:-1}"
export LP_NUM_THREADS="${LP_NUM_THREADS:-2}"
export AIRLIGHT_CACHE_DIR="${AIRLIGHT_CACHE_DIR:-$PWD/build/ci/cache}"
# The CPU test binaries that need neither the window nor a GL technique, built with clang, ASan and UBSan
# (preset fuzz) and run with leak checks: the scene tests (the loader's hardening and fuzz regressions among
# them), the maths, the reference, minmax's and vsv's CPU code and the report; then the fuzz target: the
# regressions and seeds replayed, and 60 s of fuzzing. AIRLIGHT_SKIP_FUZZ=1 leaves it out (a quick local
# run). The plans and the window's plain parts link every technique and the window (airlight_app): building
# those too under ASan doubled this build (about 380 s of 810 s of compiling), which the 20-minute budget
# on 2 cores has no room for. They run under ASan in the asan preset's whole suite (README, Build presets).
cpu_test_binaries=(viz_scene_tests viz_math_tests viz_minmax_tests viz_vsv_tests viz_reference_tests viz_report_tests)
fuzz() {
    cmake --preset fuzz >/dev/null &&
        cmake --build --preset fuzz -j "$1" &&
        for t in "${cpu_test_binaries[@]}"; do
            # A reference cache of its own: frames computed by this build never stand in for the suite's.
            AIRLIGHT_CACHE_DIR="$PWD/build/fuzz/cache" ASAN_OPTIONS=detect_leaks=1 \
                UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 "build/fuzz/tests/$t" --gtest_brief=1 || return 1
        done &&
        ctest --preset fuzz
}
suite() {
    local rc=0
    if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
        xvfb-run -a -s "-screen 0 1280x720x24 -noreset" ctest --preset ci "$@" || rc=$?
    else
        ctest --preset ci "$@" || rc=$?
    fi
    [ "$rc" = 0 ] || record_failures
    return "$rc"
}
# A failed test's name and the end of its output, kept for the summary printed last: a CI log is often
# read from its end, and the fuzz preset's output would otherwise bury the suite's failures.
record_failures() {
    local dir=build/ci/Testing/Temporary
    [ -f "$dir/LastTestsFailed.log" ] || return 0
    mkdir -p build
    while IFS=: read -r _ name; do
        echo "==== FAILED: $name"
        awk -v t="$name" '$0 ~ "^[0-9]+/[0-9]+ Testing: " t "$" {on=1; n=0; next}
                          on && /^Test time = / {exit}
                          on {line[n++ % 40] = $0}
                          END {for (i = (n > 40 ? n - 40 : 0); i < n; ++i) print "  " line[i % 40]}' "$dir/LastTest.log"
    done < "$dir/LastTestsFailed.log" >> build/failures.log
}
if [ "${AIRLIGHT_SKIP_FUZZ:-0}" = 1 ]; then
    suite "$@"
elif [ $# -gt 0 ]; then
    # A chosen part of the suite (ctest arguments): the fuzz preset first, as a whole.
    fuzz "$(nproc)"
    suite "$@"
else
    # The whole suite (CI). The soak first, alone, as RUN_SERIAL keeps it in the suite: with another
    # process beside it the window's slower runs take other paths and its heap figure is not comparable.
    # Then the rest of the suite, with the fuzz preset beside it (alone, building, then fuzzing on one
    # core, it would leave the other idle), its output printed after the suite's. At the suite's own
    # priority: at nice 10 the two busy tests left it so little that it ran 3.5 minutes past the suite's
    # end with the other core idle (its 60 s of fuzzing are wall-clock seconds either way). Its build runs
    # two compilers: with one, when it still built every CPU test binary, it ran about 5.4 minutes past the
    # suite's end, the other core idle.
    mkdir -p build
    rm -f build/failures.log
    status=0
    suite -R '^Soak\.' || status=1
    fuzz 2 > build/fuzz-run.log 2>&1 &
    fuzz_pid=$!
    trap 'kill 0' INT TERM
    suite -E '^Soak\.' || status=1
    fuzz_status=0
    wait "$fuzz_pid" || fuzz_status=$?
    echo "---- preset fuzz (the CPU test binaries without the window or GL under ASan and UBSan, gltf_fuzz), beside the suite ----"
    cat build/fuzz-run.log
    if [ "$fuzz_status" != 0 ]; then
        echo "preset fuzz failed (exit $fuzz_status)"
        status=1
    fi
    if [ -s build/failures.log ]; then
        echo "---- the suite's failed tests, each with the last 40 lines of its output ----"
        cat build/failures.log
        echo "---- failed: $(grep '^==== FAILED: ' build/failures.log | cut -c14- | tr '\n' ' ')"
    fi
    exit "$status"
fi
