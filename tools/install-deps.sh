#!/usr/bin/env bash
# Installs the Debian packages radcache needs, skipping those already present, and the Python
# packages of its measurement tools (tools/requirements.txt). clang and its runtime libraries
# (libFuzzer, the sanitizers) build the fuzz targets (tools/fuzz.sh), which CI runs.
# mesa-opencl-icd is a second OpenCL implementation (rusticl; its CPU device appears with
# RUSTICL_ENABLE=llvmpipe: docs/devices.md); Intel's OpenCL CPU runtime, through pip, a third
# (tools/intel-opencl.sh).
# slurmctld, slurmd, slurm-client and munge run the one-node cluster of the farm tests
# (tools/farm/local-slurm.sh, docs/farm.md). linux-perf samples the kernels PoCL compiles
# (tools/bench/kernel_profile.py, docs/lab/path-tracer-profile.md).
# Idempotent: runs `apt-get update` at most once, and only when something is missing.
set -euo pipefail

packages=(
    build-essential cmake pkg-config
    ocl-icd-opencl-dev opencl-headers pocl-opencl-icd clinfo mesa-opencl-icd
    libembree-dev libopenimageio-dev openimageio-tools libglm-dev nlohmann-json3-dev
    libtinyobjloader-dev libtinygltf-dev zlib1g-dev libcli11-dev libgtest-dev googletest libosd-dev
    clang libclang-rt-dev
    slurmctld slurmd slurm-client munge
    linux-perf
)

missing=()
for package in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done

sudo=""
if [ "$(id -u)" -ne 0 ]; then
    sudo="sudo"
fi
if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all Debian packages present"
else
    echo "install-deps: installing ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -qq
    $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The Python packages of the measurement tools (tools/sweep.py, tools/results.py) and their
# test, for the python3 on the PATH: installed through pip only when one is missing.
requirements="$(dirname "$0")/requirements.txt"
if python3 -c "import numpy, matplotlib, flip_evaluator" 2>/dev/null; then
    echo "install-deps: all Python packages present"
else
    if ! python3 -m pip --version >/dev/null 2>&1; then
        export DEBIAN_FRONTEND=noninteractive
        $sudo apt-get update -qq
        $sudo apt-get install -y -qq --no-install-recommends python3-pip
    fi
    echo "install-deps: installing the Python packages of $requirements"
    # A Debian-managed python3 refuses plain installs (PEP 668): then install for the user.
    python3 -m pip install --quiet --disable-pip-version-check -r "$requirements" 2>/dev/null ||
        python3 -m pip install --quiet --disable-pip-version-check --user \
            --break-system-packages -r "$requirements"
fi

# The optional peers' Python packages (tools/requirements-peers.txt: Mitsuba 3, OIDN, OpenEXR for
# tools/sweep.py --mitsuba --denoise). Never fails the install: without them the sweeps skip
# those curves with one warning.
peers="$(dirname "$0")/requirements-peers.txt"
if python3 -c "import mitsuba, pyoidn, OpenEXR, pyopencl" 2>/dev/null; then
    echo "install-deps: the optional peers' Python packages present"
elif python3 -m pip install --quiet --disable-pip-version-check -r "$peers" 2>/dev/null ||
        python3 -m pip install --quiet --disable-pip-version-check --user \
            --break-system-packages -r "$peers"; then
    echo "install-deps: installed the optional peers' Python packages ($peers)"
else
    echo "install-deps: warning: pip could not install $peers: tools/sweep.py will skip the" \
         "Mitsuba and +oidn curves"
fi

# Intel's OpenCL CPU runtime, the tests' third implementation (tools/intel-opencl.sh lists it
# beside the system's platforms; docs/devices.md, "Intel's CPU runtime"). Never fails the
# install: without it `tools/intel-opencl.sh run` says so, and CI, which needs it, stops there.
if ! "$(dirname "$0")/intel-opencl.sh" install; then
    echo "install-deps: warning: pip could not install Intel's OpenCL runtime" \
         "(intel-opencl-rt, intel-cmplr-lib-rt)"
fi
