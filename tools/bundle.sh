#!/usr/bin/env bash
# A portable radcache bundle: radcache-<version>-linux-x86_64.tar.xz holding the
# executable (kernels are embedded in it), every shared library it loads except the C library's
# own (glibc: the machine's) and the GPU driver (loaded by the OpenCL ICD loader, which is
# bundled), the scenes without their references, and a launcher. Unpacked anywhere, `./radcache`
# runs on a Linux x86-64 machine with glibc >= the build machine's (2.36 for Debian 12) and none
# of the Debian packages; on a GPU machine whose driver did not register itself with
# /etc/OpenCL/vendors, the launcher points the loader at libnvidia-opencl.so.1 when it is there.
#
#   usage: tools/bundle.sh [--dir-only] [BUILD_DIR=build] [OUT_DIR=dist]
#   --dir-only: leave the bundle as a directory under OUT_DIR (no archive)
set -euo pipefail
dir_only=0
if [ "${1:-}" = "--dir-only" ]; then dir_only=1; shift; fi
build=${1:-build}; out=${2:-dist}
root=$(cd "$(dirname "$0")/.." && pwd)
[ -x "$build/radcache" ] || { echo "bundle: no $build/radcache; build first (README)" >&2; exit 2; }
version=$(sed -n 's/^project(radcache VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
[ -n "$version" ] || { echo "bundle: no version in CMakeLists.txt's project()" >&2; exit 1; }
name="radcache-$version-linux-x86_64"
mkdir -p "$out"
stage="$out/$name"
rm -rf "$stage"
mkdir -p "$stage/bin" "$stage/lib"
cp "$build/radcache" "$stage/bin/"
# The C library's own libraries stay the machine's (they must match its dynamic loader).
system='^(linux-vdso\.so|ld-linux-x86-64\.so|libc\.so|libm\.so|libpthread\.so|libdl\.so|librt\.so|libresolv\.so|libutil\.so|libanl\.so)'
ldd "$build/radcache" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}' | while read -r soname path; do
    if ! [[ "$soname" =~ $system ]]; then
        cp -L "$path" "$stage/lib/$soname"
    fi
done
# Scenes without their path-traced references (the repository's tests need those, a user not).
tar -C "$root" --exclude='reference*.exr' --exclude='reference' -cf - scenes | tar -C "$stage" -xf -
cat > "$stage/radcache" <<'LAUNCHER'
#!/bin/sh
# radcache from this bundle: its libraries first; the OpenCL platforms are the machine's.
here=$(cd "$(dirname "$0")" && pwd)
export LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# A GPU driver that did not register with the ICD loader: name it directly.
if [ -z "${OCL_ICD_VENDORS:-}${OCL_ICD_FILENAMES:-}" ] && ! ls /etc/OpenCL/vendors/*.icd >/dev/null 2>&1; then
    for lib in /usr/lib/x86_64-linux-gnu/libnvidia-opencl.so.1 /usr/lib64/libnvidia-opencl.so.1 /usr/lib/libnvidia-opencl.so.1; do
        if [ -e "$lib" ]; then export OCL_ICD_FILENAMES="$lib"; break; fi
    done
fi
exec "$here/bin/radcache" "$@"
LAUNCHER
chmod +x "$stage/radcache"
if [ "$dir_only" = 1 ]; then
    echo "bundle: $stage ($(du -sh "$stage" | cut -f1))"
    exit 0
fi
tar -C "$out" --sort=name --owner=0 --group=0 --numeric-owner -cf - "$name" | xz -T0 -6 > "$out/$name.tar.xz.tmp"
mv "$out/$name.tar.xz.tmp" "$out/$name.tar.xz"
rm -rf "$stage"
echo "bundle: $out/$name.tar.xz ($(du -h "$out/$name.tar.xz" | cut -f1))"
