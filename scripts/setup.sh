#!/usr/bin/env bash
# Installs what is missing (Debian packages), then configures and builds.
# Usage: scripts/setup.sh [PRESET]   (PRESET: release (default), dev, ci, asan)
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"

packages=(
    build-essential cmake ninja-build pkg-config
    libglfw3-dev libglm-dev libepoxy-dev libegl-dev libgl1-mesa-dri libegl-mesa0
    libtinygltf-dev libstb-dev nlohmann-json3-dev libopenimageio-dev libopenexr-dev
    libembree-dev libtbb-dev libeigen3-dev libmd4c-dev fonts-dejavu-core
    libgtest-dev libboost-math-dev
    xvfb xauth python3-mpmath chromium tidy
    clang libclang-rt-14-dev
)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "setup: installing ${missing[*]}"
    sudo_cmd=()
    if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
    "${sudo_cmd[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
