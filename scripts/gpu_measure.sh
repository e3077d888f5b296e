#!/usr/bin/env bash
# Measures Airlight on a machine with an NVIDIA GPU and none of Debian's packages: the bundle from
# scripts/bundle.sh (build/bundle/airlight.tar.xz) and the GLVND loader packages in .gl/ travel with the
# working tree. The packages are downloaded on a Debian machine, without installing them, with
#   mkdir -p .gl && (cd .gl && apt-get download libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2)
# and unpacked here into / (the machine has the NVIDIA driver's own EGL vendor library). Writes everything into $OUT (default: gpu-out/) as
# one archive, gpu.tar.gz, and prints a summary last.
# Usage: scripts/gpu_measure.sh [SECONDS]   (a budget for the whole run, default 420)
# Environment: SCENES (the bench's scenes, default all six), SIZES (its sizes, default 480x270,1920x1080),
# REPORT_SCENES (default grate), REPORT_SIZE (default 320x240).
set -uo pipefail
cd "$(dirname "$0")/.."
budget="${1:-420}"
out="${OUT:-$PWD/gpu-out}"
mkdir -p "$out"
work=/tmp/airlight-gpu
rm -rf "$work" && mkdir -p "$work"
start=$(date +%s)
left() { echo $(( budget - ($(date +%s) - start) )); }
log="$work/log.txt"
say() { echo "$@" | tee -a "$log"; }

if ls .gl/*.deb >/dev/null 2>&1; then
    for f in .gl/*.deb; do dpkg -x "$f" /; done
    ldconfig
fi
for f in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /usr/share/glvnd/egl_vendor.d/10_nvidia.json; do
    if [ -f "$f" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES="$f"; break; fi
done
tar xJf build/bundle/airlight.tar.xz -C "$work" || { say "gpu_measure: no bundle at build/bundle/airlight.tar.xz"; exit 2; }
A="$work/airlight/airlight"
export AIRLIGHT_CACHE_DIR="$work/cache"
if [ -d gpu-cache ]; then cp -r gpu-cache "$AIRLIGHT_CACHE_DIR"; fi

{ nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.sm,clocks.max.sm --format=csv; nproc; } >"$work/machine.txt" 2>&1
say "== machine"; cat "$work/machine.txt" | tee -a "$log"

# 1. Per-stage times of every technique on every built-in scene, default settings, at two image sizes
#    up to 1920x1080 (SIZES; the two also give a scaling exponent). One run per scene, so that a scene
#    that runs out of time leaves the others' files.
sizes="${SIZES:-480x270,1920x1080}"
scenes="${SCENES:-colonnade grate forest terrain stained-glass tv-room}"
count=$(echo $scenes | wc -w)
for scene in $scenes; do
    say "== bench size $scene ($(left) s left)"
    timeout $(( budget * 66 / 100 / count )) "$A" bench --scenes "$scene" --axes size --sizes "$sizes" --runs 3 \
        --out "$work/bench-size-$scene" >"$work/bench-size-$scene.txt" 2>"$work/bench-size-$scene.err"
    say "exit $?"
done
# 2. Error against time (the reference on the CPU, cached on disk): speed-ups at equal error.
say "== report ($(left) s left)"
timeout $(( $(left) - 20 )) "$A" report --scenes "${REPORT_SCENES:-grate}" --size "${REPORT_SIZE:-320x240}" --quick --runs 3 \
    --out "$work/report" >"$work/report.txt" 2>"$work/report.err"
say "exit $?"
(cd "$work" && find . -path ./cache -prune -o -path ./airlight -prune -o -type f \( -name '*.csv' -o -name '*.html' \
    -o -name '*.txt' -o -name '*.err' -o -name '*.json' -o -name '*-size*.png' -o -name '*plot.png' \) -print |
    tar czf "$out/gpu.tar.gz" -T -) 2>/dev/null
say "== summary"
grep -h 'total ~\|faster\|slower\|wrote' "$work"/bench-*.txt "$work"/report.txt 2>/dev/null | tail -n 70
tail -n 2 "$work"/bench-*.err 2>/dev/null | tail -n 24
grep -v '^#\|^!!\|^[A-Z]*[ .]\|^ *$' "$work/report.err" | head -n 8
