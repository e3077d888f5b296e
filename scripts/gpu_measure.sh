#!/usr/bin/env bash
# Measures Airlight on a machine with an NVIDIA GPU and none of Debian's packages: the bundle from
# scripts/bundle.sh (build/bundle/airlight.tar.xz) and the GLVND loader packages in .gl/ travel with the
# working tree. The packages are downloaded on a Debian machine, without installing them, with
#   mkdir -p .gl && (cd .gl && apt-get download libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2)
# and unpacked here into / (the machine has the NVIDIA driver's own EGL vendor library). Writes everything
# into $OUT (default: gpu-out/) as one archive, gpu.tar.gz, and prints a summary last.
# Usage: scripts/gpu_measure.sh [SECONDS]   (a budget for the whole run, default 540)
# Environment: STEPS (which steps, comma-separated, default all: plot,probe,bench,variants,ablate,report,quick),
# SCENES (default all six), TECHNIQUES (default all six GPU techniques), SIZES (the size
# axis, default 480x270,1920x1080), REPORT_SCENES (default colonnade), REPORT_SIZE (default 1920x1080),
# REPORT_TECHNIQUES (default every one but the reference).
# Each scene and technique is its own bench run with its own time limit, so that one slow pair leaves
# the others' figures.
set -uo pipefail
cd "$(dirname "$0")/.."
budget="${1:-540}"
out="${OUT:-$PWD/gpu-out}"
mkdir -p "$out"
work=/tmp/airlight-gpu
rm -rf "$work" && mkdir -p "$work"
start=$(date +%s)
steps=",${STEPS:-plot,probe,bench,variants,ablate,report,quick},"
want() { [[ "$steps" == *",$1,"* ]]; }
left() { echo $(( budget - ($(date +%s) - start) )); }
log="$work/log.txt"
say() { echo "$@" | tee -a "$log"; }
pack() {
    (cd "$work" && find . -path ./cache -prune -o -path ./airlight -prune -o -type f \( -name '*.csv' -o -name '*.html' \
        -o -name '*.txt' -o -name '*.err' -o -name '*.json' -o -name '*.png' \) -print |
        tar czf "$out/gpu.tar.gz" -T -) 2>/dev/null
}

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
say "== machine"; tee -a "$log" <"$work/machine.txt"
# The SM clock every 200 ms: the GPU lowers it while the CPU side (the reference, read-backs) keeps it
# idle, and every GPU time depends on it. The log's lines carry the time of day to match them up.
nvidia-smi --query-gpu=timestamp,clocks.sm,utilization.gpu --format=csv -lms 200 >"$work/clocks.csv" 2>/dev/null &
sampler=$!
say() { echo "$(date +%T) $*" | tee -a "$log"; }

# 0. Plots drawn off-screen: one tiny bench in a fresh process with the GL debug output on, and a count
#    of the pixels of each plot that are not the background.
if want plot; then
say "== plot check ($(left) s left)"
AIRLIGHT_GL_DEBUG=1 timeout 40 "$A" bench --scenes grate --techniques raymarch --axes size --sizes 160x120,320x240 --runs 1 \
    --out "$work/plotcheck" >"$work/plotcheck.txt" 2>"$work/plotcheck.err"
say "exit $?"
python3 - "$work/plotcheck" <<'PY' 2>&1 | tee -a "$log"
import sys, pathlib
from PIL import Image
for p in sorted(pathlib.Path(sys.argv[1]).glob('*.png')):
    im = Image.open(p).convert('RGB')
    px = im.getdata()
    print(p.name, im.size, 'pixels not white:', sum(1 for c in px if c != (255, 255, 255)))
PY
grep -v '^#' "$work/plotcheck.err" | sort | uniq -c | sort -rn | head -n 12 | tee -a "$log"
fi

# 0b. The renderer's throughput for each kind of work alone (airlight probe): arithmetic in a compute and in
#     a fragment shader, full-screen blending into float targets, small triangles. Twice: at the default
#     1920x1080 and with 4x the arithmetic, so that the ratio is not the fixed cost of a pass.
if want probe; then
    say "== probe ($(left) s left)"
    timeout 60 "$A" probe --out "$work/probe.csv" 2>&1 | tee "$work/probe.txt" | tee -a "$log"
    timeout 60 "$A" probe --iterations 4096 --layers 512 --out "$work/probe-4x.csv" 2>&1 | tee "$work/probe-4x.txt" | tee -a "$log"
    pack
fi

# 1. Per-stage times of every technique on every built-in scene, default settings, at two image sizes.
sizes="${SIZES:-480x270,1920x1080}"
scenes="${SCENES:-colonnade grate forest terrain stained-glass tv-room}"
techniques="${TECHNIQUES:-raymarch slices polyvol minmax vsv ivsv}"
want bench || scenes=""
for scene in $scenes; do
    for t in $techniques; do
        [ "$(left)" -gt 200 ] || { say "skip $scene $t: too little time left"; continue; }
        cap=30; case "$t" in minmax|polyvol) cap=50 ;; esac
        timeout $cap "$A" bench --scenes "$scene" --techniques "$t" --axes size --sizes "$sizes" --runs 3 \
            --out "$work/bench-$scene-$t" >"$work/bench-$scene-$t.txt" 2>"$work/bench-$scene-$t.err"
        say "bench $scene $t exit $? ($(left) s left)"
    done
    pack
done
# 1b. The fast paths whose choice waits for a GPU, each pair side by side: minmax's prefix sums (sequential
# rows against log2 passes, integrand=svd) and ivsv's interleaved gather (deinterleaved or screen order).
variants=""
want variants && variants="minmax:stained-glass:prefix_sums=sequential minmax:stained-glass:prefix_sums=log2
    ivsv:tv-room:deinterleave=on ivsv:tv-room:deinterleave=off"
for variant in $variants; do
    variant="${variant//:/ }"
    set -- $variant
    [ "$(left)" -gt 200 ] || { say "skip $variant: too little time left"; continue; }
    extra="--set integrand=svd"; [ "$1" = ivsv ] && extra="--set gather=interleaved --set vpls=256"
    timeout 40 "$A" bench --scenes "$2" --techniques "$1" --axes size --sizes "$sizes" --runs 3 $extra --set "$3" \
        --out "$work/variant-$1-$3" >"$work/variant-$1-$3.txt" 2>"$work/variant-$1-$3.err"
    say "variant $1 $2 $3 exit $? ($(left) s left)"
done
pack
# 1c. Where slices' planes and polyvol's volume spend their time on this GPU: each alone with one knob
#     changed against its default (the depth test, blending format, the slab's nodes, the plane count; the segment integral,
#     the mesh), on colonnade at the sizes above.
ablations=""
want ablate && ablations="slices:default slices:depth_test=0 slices:accum=rgba16f slices:integration=midpoint slices:planes=32
    polyvol:default polyvol:airlight=lut polyvol:tessellation=static raymarch:default"
for a in $ablations; do
    t="${a%%:*}"; knob="${a#*:}"
    [ "$(left)" -gt 200 ] || { say "skip ablation $a: too little time left"; continue; }
    extra=""; [ "$knob" != default ] && extra="--set $knob"
    timeout 50 "$A" bench --scenes colonnade --techniques "$t" --axes size --sizes "$sizes" --runs 3 $extra \
        --out "$work/ablate-$t-$knob" >"$work/ablate-$t-$knob.txt" 2>"$work/ablate-$t-$knob.err"
    say "ablation $t $knob exit $? ($(left) s left)"
done
pack
# 2. Error against time at the report's size (the reference on the CPU's threads, cached on disk).
if want report; then
say "== report ($(left) s left)"
report_techniques=(); [ -n "${REPORT_TECHNIQUES:-}" ] && report_techniques=(--techniques "$REPORT_TECHNIQUES")
timeout $(( $(left) - 70 )) "$A" report --scenes "${REPORT_SCENES:-colonnade}" --size "${REPORT_SIZE:-1920x1080}" --quick --runs 3 \
    "${report_techniques[@]}" \
    --out "$work/report" >"$work/report.txt" 2>"$work/report.err"
say "exit $?"
pack
fi
# 3. The bench's own quick run (grate and tv-room, small sizes).
if want quick; then
say "== bench --quick ($(left) s left)"
timeout $(( $(left) - 15 )) "$A" bench --quick --out "$work/bench-quick" >"$work/bench-quick.txt" 2>"$work/bench-quick.err"
say "exit $?"
pack
fi
kill "$sampler" 2>/dev/null
pack
say "== summary"
grep -h 'fragment_alu / compute_alu' "$work"/probe*.txt 2>/dev/null
grep -h 'faster\|slower' "$work"/report.txt 2>/dev/null | head -n 20
tail -n 3 "$work"/report.err "$work"/bench-quick.err 2>/dev/null
