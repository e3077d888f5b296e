#!/usr/bin/env bash
# The bundle for another machine (scripts/bundle.sh): made from BUILD_DIR's airlight-portable, then run in a chroot
# that holds only the bundle, the C library family, /bin/sh (the launcher's shell), the GL driver (GLVND's
# libEGL/libGLdispatch/libGLX/libGL/libOpenGL, Mesa's EGL vendor library and software dri driver and the
# libraries those load), /dev/null, /dev/zero, /dev/urandom and /tmp.
# Checks: the folder is under 64 MiB; a GPU technique (raymarch, surfaceless EGL on llvmpipe) and the CPU
# reference render a non-empty PNG in the chroot, and a lesson exports by name (the bundle's lessons/ and
# font); every library the binary needs resolves to the bundle's
# lib/ unless it is C library or GL loader family, and every object loaded at run time is the bundle's,
# the C library's or the GL driver's.
# Usage: tests/bundle/bundle_test.sh BUILD_DIR
# chroot needs root: as another user the test fails, unless AIRLIGHT_ALLOW_NO_ROOT=1, when it makes and
# measures the bundle and then exits 77 (ctest: skipped).
set -Eeuo pipefail
trap 'echo "bundle_test: FAIL: line $LINENO: $BASH_COMMAND failed" >&2' ERR
src="$(cd "$(dirname "$0")/../.." && pwd)"
[ $# -eq 1 ] || { echo "usage: tests/bundle/bundle_test.sh BUILD_DIR" >&2; exit 2; }
build_dir="$(realpath "$1")"
start=$SECONDS

fail() { echo "bundle_test: FAIL: $*" >&2; exit 1; }

is_root=1
if [ "$(id -u)" -ne 0 ]; then
    is_root=0
    [ "${AIRLIGHT_ALLOW_NO_ROOT:-0}" = 1 ] ||
        fail "needs root for chroot (CI runs as root); set AIRLIGHT_ALLOW_NO_ROOT=1 to test only the bundle's making and size"
fi

tmp="$(mktemp -d "${TMPDIR:-/tmp}/airlight_bundle_test.XXXXXX")"
mounts=()
cleanup() {
    local m ok=1
    for m in "${mounts[@]}"; do
        umount "$m" 2>/dev/null || umount -l "$m" 2>/dev/null || { echo "bundle_test: cannot unmount $m" >&2; ok=0; }
    done
    if [ "$ok" = 1 ]; then rm -rf "$tmp"; else echo "bundle_test: left $tmp in place (a mount is still there)" >&2; fi
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# The bundle (without its .tar.xz, which takes minutes to compress), and its size: over 64 MiB fails the
# test at the end, after the chroot runs, so that one run reports both.
"$src/scripts/bundle.sh" --build-dir "$build_dir" --out "$tmp/out/airlight" --no-tar || fail "scripts/bundle.sh failed"
bundle="$tmp/out/airlight"
bytes="$(du -sb "$bundle" | cut -f1)"
limit=$((64 * 1024 * 1024))
mib() { awk -v b="$1" 'BEGIN {printf "%.1f MiB", b / 1048576}'; }
size_fail() {
    [ "$bytes" -lt "$limit" ] && return 0
    echo "bundle_test: FAIL: the bundle is $(mib "$bytes") ($bytes bytes), not under 64 MiB; its largest libraries:" >&2
    (cd "$bundle/lib" && ls -S | sed -n 1,10p | while read -r f; do echo "  $(mib "$(stat -c %s "$f")")  $f"; done) >&2
    exit 1
}

if [ "$is_root" = 0 ]; then
    size_fail
    echo "bundle_test: not root (AIRLIGHT_ALLOW_NO_ROOT=1): bundle made and measured ($(mib "$bytes")); the chroot run is skipped"
    exit 77
fi

# The chroot. Paths are kept as the host has them (/lib -> usr/lib and the like are copied as links).
r="$tmp/root"
mkdir -p "$r/bundle" "$r/tmp" "$r/dev"
chmod 1777 "$r/tmp"
for d in bin sbin lib lib32 lib64 libx32; do
    if [ -L "/$d" ]; then
        target="$(readlink "/$d")"
        case "$target" in /*) mkdir -p "$r$target" ;; *) mkdir -p "$r/$target" ;; esac
        ln -s "$target" "$r/$d"
    fi
done
cp -a "$bundle/." "$r/bundle/"

declare -A allowed=()  # chroot path -> 1: the files outside the bundle that may be loaded
# put PATH: the file, by its real path, and PATH as a link to it when they differ (same folder: relative).
put() {
    local path="$1" real
    real="$(readlink -f "$path")"
    [ -f "$real" ] || fail "$path is missing on this system"
    if [ ! -e "$r$real" ]; then
        mkdir -p "$r$(dirname "$real")"
        cp "$real" "$r$real"
    fi
    if [ "$path" != "$real" ] && [ ! -e "$r$path" ] && [ ! -L "$r$path" ]; then
        mkdir -p "$r$(dirname "$path")"
        if [ "$(readlink -f "$(dirname "$path")")" = "$(dirname "$real")" ]; then
            ln -s "$(basename "$real")" "$r$path"
        else
            ln -s "$real" "$r$path"
        fi
    fi
    allowed["$path"]=1
    allowed["$real"]=1
}
# put_closure FILE...: the files and every library ldd resolves for them.
put_closure() {
    local f lib
    for f in "$@"; do
        put "$f"
        while read -r lib; do put "$lib"; done < <(env -u LD_LIBRARY_PATH ldd "$f" | awk '$2 == "=>" && $3 ~ /^\// {print $3} $1 ~ /^\// {print $1}')
    done
}

multiarch=/usr/lib/x86_64-linux-gnu
system_lib_re='^(libc|libm|libmvec|libdl|libpthread|librt|libresolv|libutil|libanl|libnss_[a-z0-9]+|ld-linux-x86-64)\.so'
gl_lib_re='^lib(GL|EGL|GLX|GLdispatch|OpenGL|GLES[A-Za-z0-9_]*|GLX_[A-Za-z0-9]+|EGL_[A-Za-z0-9]+)\.so'

# The C library family, as the binary uses it here, and the launcher's shell.
while read -r soname path; do
    if [[ "$(basename "$soname")" =~ $system_lib_re ]]; then put "$path"; fi
done < <(env -u LD_LIBRARY_PATH ldd "$build_dir/app/airlight" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3} $1 ~ /^\// {print $1, $1}')
put_closure /bin/sh

# The GL driver: GLVND, Mesa's EGL vendor library (named by its JSON file) and the software dri driver.
[ -d /usr/share/glvnd/egl_vendor.d ] || fail "/usr/share/glvnd/egl_vendor.d is missing (libegl-mesa0)"
mkdir -p "$r/usr/share/glvnd"
cp -r /usr/share/glvnd/egl_vendor.d "$r/usr/share/glvnd/"
driver=()
for lib in libEGL.so.1 libGLdispatch.so.0 libGLX.so.0 libGL.so.1 libOpenGL.so.0; do
    [ -e "$multiarch/$lib" ] || fail "$multiarch/$lib is missing (GLVND)"
    driver+=("$multiarch/$lib")
done
for json in /usr/share/glvnd/egl_vendor.d/*.json; do
    vendor="$(sed -n 's/.*"library_path" *: *"\([^"]*\)".*/\1/p' "$json")"
    [ -n "$vendor" ] || continue
    case "$vendor" in /*) ;; *) vendor="$multiarch/$vendor" ;; esac
    [ -e "$vendor" ] && driver+=("$vendor")
done
[ -e "$multiarch/dri/swrast_dri.so" ] || fail "$multiarch/dri/swrast_dri.so is missing (libgl1-mesa-dri)"
driver+=("$multiarch/dri/swrast_dri.so")
put_closure "${driver[@]}"

# /dev: device nodes, or bind mounts where mknod is not allowed.
for dev in null:1:3 zero:1:5 urandom:1:9; do
    IFS=: read -r node major minor <<<"$dev"
    if ! mknod -m 0666 "$r/dev/$node" c "$major" "$minor" 2>/dev/null; then
        : >"$r/dev/$node"
        mount --bind "/dev/$node" "$r/dev/$node" || fail "cannot make or bind /dev/$node in the chroot"
        mounts+=("$r/dev/$node")
    fi
done

# is_allowed PATH: PATH (as the chroot sees it) is one of the files put there outside the bundle.
is_allowed() {
    local real
    real="$(readlink -f "$r$1")"
    [ -n "${allowed[$1]:-}" ] || [ -n "${allowed[${real#"$r"}]:-}" ]
}
outside_bundle() {  # the files the chroot holds outside /bundle (for messages)
    (cd "$r" && find . -path ./bundle -prune -o \( -type f -o -type l \) -print | sed 's/^\.//' | sort | tr '\n' ' ')
}

# Every library the binary needs comes from the bundle, but for the C library and GL loader families.
listing="$(chroot "$r" /lib64/ld-linux-x86-64.so.2 --library-path /bundle/lib --list /bundle/bin/airlight 2>&1)" ||
    fail "the loader cannot list the bundled binary's libraries in the chroot: $listing"
if grep -q "not found" <<<"$listing"; then fail "in the chroot the binary misses: $(grep "not found" <<<"$listing" | tr -s ' \t\n' ' ')"; fi
while read -r soname path; do
    name="$(basename "$soname")"
    if [[ "$name" =~ $system_lib_re ]] || [[ "$name" =~ $gl_lib_re ]]; then
        is_allowed "$path" || fail "$name resolves to $path in the chroot"
    else
        [[ "$path" == /bundle/lib/* ]] || fail "$name resolves to $path, not to the bundle's lib/"
    fi
done < <(awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}' <<<"$listing")

# run NAME ARGS...: the launcher in the chroot with a bare environment; LD_DEBUG=libs names each loaded
# object ("calling init: PATH"), each of which must be the bundle's, the C library's or the driver's.
run() {
    local label="$1" log="$tmp/$1.log" f path
    shift
    rm -f "$r"/tmp/ld.*
    if ! env -i PATH=/bundle HOME=/tmp AIRLIGHT_CACHE_DIR=/tmp/cache LP_NUM_THREADS=2 \
            "$(command -v chroot)" "$r" /bin/sh -c 'LD_DEBUG=libs LD_DEBUG_OUTPUT=/tmp/ld exec /bundle/airlight "$@"' sh "$@" \
            >"$log" 2>&1; then
        cat "$log" >&2
        tail -n 40 "$r"/tmp/ld.* 2>/dev/null | grep -v "^ *$" | tail -n 40 >&2 || true
        fail "$label: 'airlight $*' failed in the chroot (outside the bundle it holds: $(outside_bundle))"
    fi
    local loaded=0
    for f in "$r"/tmp/ld.*; do
        while read -r path; do
            loaded=$((loaded + 1))
            [[ "$path" == /bundle/* ]] || is_allowed "$path" ||
                fail "$label: loaded $path, which is neither the bundle's nor the C library's or GL driver's"
        done < <(sed -n 's/^[[:space:]]*[0-9]*:[[:space:]]*calling init: //p' "$f")
    done
    [ "$loaded" -gt 0 ] || fail "$label: LD_DEBUG named no loaded object"
    echo "bundle_test: $label: ok ($loaded objects with initialisers loaded)"
}

run raymarch render --scene grate --technique raymarch --size 32x24 --out /tmp/raymarch.png
[ -s "$r/tmp/raymarch.png" ] || fail "raymarch: /tmp/raymarch.png is missing or empty"
grep -q "swrast_dri.so" "$r"/tmp/ld.* || fail "raymarch: the GL driver (swrast_dri.so) was not loaded"
run reference render --scene grate --technique reference --size 32x24 --out /tmp/reference.png
[ -s "$r/tmp/reference.png" ] || fail "reference: /tmp/reference.png is missing or empty"
# A lesson by name: the bundle's lessons/ and font (the figures' captions), GL and CPU techniques.
run lesson lesson 01-airlight-integral --export /tmp/lesson --size 32x24
[ -s "$r/tmp/lesson/index.html" ] || fail "lesson: /tmp/lesson/index.html is missing or empty"

echo "bundle_test: chroot runs passed ($((SECONDS - start)) s so far)"
size_fail
echo "bundle_test: passed: bundle $(mib "$bytes"), $((SECONDS - start)) s"
