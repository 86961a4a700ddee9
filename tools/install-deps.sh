#!/usr/bin/env bash
# Installs the Debian packages radcache needs, skipping those already present.
# Idempotent: runs `apt-get update` at most once, and only when something is missing.
set -euo pipefail

packages=(
    build-essential cmake pkg-config
    ocl-icd-opencl-dev opencl-headers pocl-opencl-icd clinfo
    libembree-dev libopenimageio-dev openimageio-tools libglm-dev nlohmann-json3-dev
    libtinyobjloader-dev libgtest-dev googletest
)

missing=()
for package in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all packages present"
    exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
    sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
