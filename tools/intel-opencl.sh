#!/usr/bin/env bash
# Intel's OpenCL CPU runtime, a second conformant OpenCL implementation beside PoCL
# (docs/devices.md, "Intel's CPU runtime"). pip installs it (intel-opencl-rt, with
# intel-cmplr-lib-rt for its maths libraries and tbb), but not where the ICD loader looks: its own
# .icd file names a placeholder path, and its folder, the Python prefix's lib, also holds a
# libOpenCL.so of its own and libraries that would shadow Debian's for every program.
#
#   tools/intel-opencl.sh install     pip-install the runtime where it is missing (fails if pip
#                                     cannot)
#   tools/intel-opencl.sh env         print the two exports that list it beside the system's
#                                     platforms: eval "$(tools/intel-opencl.sh env)"
#   tools/intel-opencl.sh run CMD...  run CMD with them
#
# The exports: OCL_ICD_VENDORS names a folder of links to /etc/OpenCL/vendors' files and one
# .icd file naming the installed libintelocl.so, listed last ("zz-"), so the system's platforms
# keep their indices; LD_LIBRARY_PATH gains a folder of links to the runtime's own libraries,
# without its libOpenCL.so* (Debian's ICD loader stays the one loaded). The folders are made under
# $RADCACHE_INTEL_OPENCL_DIR (default ~/.cache/radcache/intel-opencl). The platform is named
# "Intel(R) OpenCL": RADCACHE_TEST_DEVICE='Intel(R) OpenCL' runs the tests there.
set -euo pipefail

packages=(intel-opencl-rt intel-cmplr-lib-rt)
work="${RADCACHE_INTEL_OPENCL_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/radcache/intel-opencl}"

# The installed files of the runtime's packages (and of tbb, which it needs), absolute paths.
installed_libraries() {
    local package location
    for package in "${packages[@]}" tbb; do
        location="$(python3 -m pip show "$package" 2>/dev/null | sed -n 's/^Location: //p')"
        [ -n "$location" ] || continue
        python3 -m pip show -f "$package" | sed -n 's/^  //p' | grep -E '\.so(\.|$)' |
            while read -r file; do realpath -m "$location/$file"; done
    done
}

find_runtime() {
    installed_libraries | grep -E '/libintelocl\.so$' | head -1
}

install_runtime() {
    if [ -n "$(find_runtime)" ]; then
        echo "intel-opencl: Intel's OpenCL runtime present ($(find_runtime))"
        return
    fi
    echo "intel-opencl: installing ${packages[*]} through pip"
    python3 -m pip install --quiet --disable-pip-version-check "${packages[@]}" 2>/dev/null ||
        python3 -m pip install --quiet --disable-pip-version-check --user \
            --break-system-packages "${packages[@]}"
    [ -n "$(find_runtime)" ] || {
        echo "intel-opencl: pip installed ${packages[*]} but no libintelocl.so is listed" >&2
        exit 1
    }
}

# A link in folder $2 to file $1, made only where it is missing or points elsewhere.
link_once() {
    [ -e "$1" ] || return 0
    [ "$(readlink "$2/$(basename "$1")")" = "$1" ] || ln -sfn "$1" "$2/"
}

# Makes the two folders, or brings them up to date in place (never removed: another process
# may be reading them); prints the exports.
make_env() {
    local runtime file
    runtime="$(find_runtime)"
    if [ -z "$runtime" ]; then
        echo "intel-opencl: Intel's OpenCL runtime is not installed (tools/intel-opencl.sh install)" >&2
        exit 1
    fi
    mkdir -p "$work/vendors" "$work/lib"
    for file in /etc/OpenCL/vendors/*.icd; do
        link_once "$file" "$work/vendors"
    done
    if [ "$(cat "$work/vendors/zz-intel-cpu.icd" 2>/dev/null)" != "$runtime" ]; then
        echo "$runtime" >"$work/vendors/.zz-intel-cpu.icd.$$"
        mv -f "$work/vendors/.zz-intel-cpu.icd.$$" "$work/vendors/zz-intel-cpu.icd"
    fi
    installed_libraries | grep -vE '/libOpenCL\.so' | while read -r file; do
        link_once "$file" "$work/lib"
    done
    echo "export OCL_ICD_VENDORS='$work/vendors'"
    echo "export LD_LIBRARY_PATH='$work/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}'"
}

case "${1:-}" in
install) install_runtime ;;
env) make_env ;;
run)
    shift
    [ $# -gt 0 ] || { echo "intel-opencl: run needs a command" >&2; exit 2; }
    eval "$(make_env)"
    exec "$@"
    ;;
*)
    echo "usage: tools/intel-opencl.sh install | env | run COMMAND..." >&2
    exit 2
    ;;
esac
