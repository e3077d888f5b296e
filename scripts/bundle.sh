#!/usr/bin/env bash
# Makes a self-contained folder that runs airlight on another Linux x86-64 machine without Debian's
# packages: the stripped airlight-portable binary (airlight with PNG and EXR through stb_image and OpenEXR
# instead of OpenImageIO, whose Debian closure is some 330 MiB; it writes no animated GIF), every shared library it loads except the C library family and the
# GL driver/loader (those come from the machine it runs on), the run-time data (shaders, lessons,
# assets, the UI font) and a launcher, plus a .tar.xz of the folder beside it.
# Usage: scripts/bundle.sh [--build-dir DIR] [--out DIR] [--no-tar]
#   --build-dir DIR  a configured and built tree holding app/airlight-portable (default: configure and
#                    build the release preset's airlight-portable target, build/release)
#   --out DIR        the folder to make (default build/bundle/airlight); the archive is DIR.tar.xz
#   --no-tar         leave out the archive
# The folder is made in a temporary folder beside DIR and moved into place at the end: on any error
# DIR and DIR.tar.xz are left as they were.
set -Eeuo pipefail
trap 'echo "bundle: error: line $LINENO: $BASH_COMMAND failed" >&2' ERR
root="$(cd "$(dirname "$0")/.." && pwd)"

die() { echo "bundle: error: $*" >&2; exit 1; }

build_dir=""
out="$root/build/bundle/airlight"
make_tar=1
while [ $# -gt 0 ]; do
    case "$1" in
        --build-dir) [ $# -ge 2 ] || die "--build-dir needs a folder"; build_dir="$2"; shift 2 ;;
        --out) [ $# -ge 2 ] || die "--out needs a folder"; out="$2"; shift 2 ;;
        --no-tar) make_tar=0; shift ;;
        -h|--help) sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) die "unknown argument '$1' (usage: scripts/bundle.sh [--build-dir DIR] [--out DIR] [--no-tar])" ;;
    esac
done

for tool in ldd strip tar xz du; do
    command -v "$tool" >/dev/null || die "'$tool' is not installed"
done

if [ -z "$build_dir" ]; then
    (cd "$root" && cmake --preset release >/dev/null && cmake --build --preset release --target airlight-portable >/dev/null) ||
        die "building the release preset's airlight-portable target failed"
    build_dir="$root/build/release"
fi
exe="$build_dir/app/airlight-portable"
[ -f "$exe" ] && [ -x "$exe" ] || die "no airlight-portable binary at $exe (build the airlight-portable target first)"

# The files the binary reads at run time (see the launcher below for how it finds them).
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf  # viz/ui/font.h: FontAtlas::kDefaultFontPath
[ -f "$font" ] || die "font $font is missing (install fonts-dejavu-core)"
for d in shaders lessons assets; do
    [ -d "$root/$d" ] || die "$root/$d is missing"
done

# Libraries left to the machine the bundle runs on: the C library family and the GL loader/driver
# family (libepoxy opens libEGL.so.1 / libGL.so.1 there with dlopen).
system_lib_re='^(libc|libm|libmvec|libdl|libpthread|librt|libresolv|libutil|libanl|libnss_[a-z0-9]+|ld-linux-x86-64)\.so'
gl_lib_re='^lib(GL|EGL|GLX|GLdispatch|OpenGL|GLES[A-Za-z0-9_]*|GLX_[A-Za-z0-9]+|EGL_[A-Za-z0-9]+)\.so'

out="$(realpath -m "$out")"
name="$(basename "$out")"
parent="$(dirname "$out")"
mkdir -p "$parent" || die "cannot make $parent"
tmp="$(mktemp -d "$parent/.$name.bundle.XXXXXX")" || die "cannot make a temporary folder in $parent"
trap 'rm -rf "$tmp"' EXIT
stage="$tmp/$name"
mkdir -p "$stage/bin" "$stage/lib" "$stage/fonts"

# The binary's library closure as the loader resolves it here.
ldd_out="$(env -u LD_LIBRARY_PATH -u LD_PRELOAD ldd "$exe" 2>&1)" || die "ldd $exe failed: $(echo "$ldd_out" | head -1)"
missing="$(echo "$ldd_out" | awk '/=> not found/ {print $1}' | tr '\n' ' ')"
[ -z "$missing" ] || die "ldd: libraries not found: ${missing% }"
count=0
while read -r soname path; do
    case "$soname" in */*) soname="$(basename "$soname")" ;; esac
    if [[ "$soname" =~ $system_lib_re ]] || [[ "$soname" =~ $gl_lib_re ]]; then continue; fi
    [ -f "$path" ] || die "ldd names $path for $soname but it is not a file"
    strip --strip-unneeded -o "$stage/lib/$soname" "$path" 2>/dev/null || die "strip $path failed"
    chmod 0644 "$stage/lib/$soname"
    count=$((count + 1))
done < <(echo "$ldd_out" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}')
strip --strip-all -o "$stage/bin/airlight" "$exe" 2>/dev/null || die "strip $exe failed"
chmod 0755 "$stage/bin/airlight"

# Every library the bundled binary needs is either in lib/ or left to the system (by the lists above).
check="$(env -u LD_PRELOAD LD_LIBRARY_PATH="$stage/lib" ldd "$stage/bin/airlight" 2>&1)" || die "ldd of the bundled binary failed"
echo "$check" | grep -q "not found" && die "the bundled binary misses: $(echo "$check" | awk '/not found/ {print $1}' | tr '\n' ' ')"
while read -r soname path; do
    if [[ "$soname" =~ $system_lib_re ]] || [[ "$soname" =~ $gl_lib_re ]]; then continue; fi
    [ "$path" = "$stage/lib/$soname" ] || die "the bundled binary takes $soname from $path, not from lib/"
done < <(echo "$check" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}')

cp -RL "$root/shaders" "$root/lessons" "$root/assets" "$stage/" || die "copying the data folders failed"
cp "$font" "$stage/fonts/" || die "copying $font failed"
if [ -f /usr/share/doc/fonts-dejavu-core/copyright ]; then
    cp /usr/share/doc/fonts-dejavu-core/copyright "$stage/fonts/DejaVu-copyright.txt"
fi

cat >"$stage/airlight" <<'EOF'
#!/bin/sh
# airlight bundle launcher: the bundled libraries first, the bundled data folders unless the caller
# set them, then the real binary with the same arguments.
here=$0
if command -v readlink >/dev/null 2>&1; then here=$(readlink -f -- "$0"); fi
case $here in */*) here=${here%/*} ;; *) here=. ;; esac
here=$(cd -- "$here" && pwd) || exit 1
LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
: "${AIRLIGHT_SHADER_DIR:=$here/shaders}"
: "${AIRLIGHT_LESSON_DIR:=$here/lessons}"
: "${AIRLIGHT_FONT:=$here/fonts/DejaVuSans.ttf}"
export LD_LIBRARY_PATH AIRLIGHT_SHADER_DIR AIRLIGHT_LESSON_DIR AIRLIGHT_FONT
exec "$here/bin/airlight" "$@"
EOF
chmod 0755 "$stage/airlight"

bytes="$(du -sb "$stage" | cut -f1)"
limit=$((64 * 1024 * 1024))
mib() { awk -v b="$1" 'BEGIN {printf "%.1f MiB", b / 1048576}'; }

if [ "$make_tar" = 1 ]; then
    tar -C "$tmp" -cf - "$name" | xz -T0 -6 >"$tmp/$name.tar.xz" || die "making $name.tar.xz failed"
    tar_bytes="$(stat -c %s "$tmp/$name.tar.xz")"
fi

# Into place: the old folder and archive are replaced only now.
rm -rf "$out" || die "cannot remove the old $out"
mv "$stage" "$out" || die "cannot move the bundle to $out"
if [ "$make_tar" = 1 ]; then
    mv "$tmp/$name.tar.xz" "$out.tar.xz" || die "cannot move the archive to $out.tar.xz"
fi

echo "bundle: $out: $(mib "$bytes") ($bytes bytes; binary $(mib "$(stat -c %s "$out/bin/airlight")"), $count libraries $(mib "$(du -sb "$out/lib" | cut -f1)"))"
if [ "$make_tar" = 1 ]; then echo "bundle: $out.tar.xz: $(mib "$tar_bytes") ($tar_bytes bytes)"; fi
if [ "$bytes" -ge "$limit" ]; then
    echo "bundle: warning: the folder is over 64 MiB; its largest libraries:" >&2
    (cd "$out/lib" && ls -S | sed -n 1,10p | while read -r f; do echo "  $(mib "$(stat -c %s "$f")")  $f"; done) >&2
fi
exit 0
