#!/usr/bin/env bash
# Second README command: set up, build (warnings are errors), fuzz the glTF loader for a minute, and
# run the whole test suite headless.
# GL tests use a headless EGL context; the window test needs a display, so without one the suite runs
# under xvfb-run (a virtual X server).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh ci
export VIZ_REQUIRE_GL="${VIZ_REQUIRE_GL:-1}"
export VIZ_REQUIRE_DISPLAY="${VIZ_REQUIRE_DISPLAY:-1}"
export VIZ_REQUIRE_BROWSER="${VIZ_REQUIRE_BROWSER:-1}"
export LP_NUM_THREADS="${LP_NUM_THREADS:-2}"
export AIRLIGHT_CACHE_DIR="${AIRLIGHT_CACHE_DIR:-$PWD/build/ci/cache}"
# The scene code built with clang, ASan and UBSan (preset fuzz): the scene tests (the loader's hardening
# and fuzz regressions among them) with leak checks, then the fuzz target: the regressions and seeds
# replayed, and 60 s of fuzzing. AIRLIGHT_SKIP_FUZZ=1 leaves it out (a quick local run).
if [ "${AIRLIGHT_SKIP_FUZZ:-0}" != 1 ]; then
    cmake --preset fuzz >/dev/null
    cmake --build --preset fuzz -j "$(nproc)"
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 build/fuzz/tests/viz_scene_tests --gtest_brief=1
    ctest --preset fuzz
fi
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
    exec xvfb-run -a -s "-screen 0 1280x720x24" ctest --preset ci "$@"
fi
exec ctest --preset ci "$@"
