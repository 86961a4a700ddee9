#!/usr/bin/env bash
# Runs the libFuzzer targets of tests/fuzz/ (docs/reliability.md):
#
#   tools/fuzz.sh TARGET SECONDS [libFuzzer options...]
#   tools/fuzz.sh TARGET|all --build-only
#
# TARGET is scene, obj, gltf, pbrt, cache_file, grid_file, kernel_cache, or all (each for SECONDS). The fuzz
# build (clang, -DRADCACHE_FUZZ=ON: coverage, ASan, UBSan) is made in build-fuzz/ first
# ($RADCACHE_FUZZ_BUILD_DIR overrides), apart from the main build. Seeds: tests/fuzz/seeds/TARGET,
# the shipped scenes (scene, obj) and every saved regression input; the corpus grows in
# build-fuzz/corpus/TARGET. A crash, a sanitizer report, an input slower than 10 s or one that
# takes more than 2 GiB stops the run with a non-zero status and leaves the input in
# build-fuzz/artifacts/TARGET/: fix the bug and copy the input to tests/fuzz/regressions/TARGET/.
# --build-only makes the fuzz build of the targets and runs nothing (CI makes it beside other work).
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
build="${RADCACHE_FUZZ_BUILD_DIR:-$root/build-fuzz}"
all_targets=(scene obj gltf pbrt cache_file grid_file kernel_cache)

if [ $# -lt 2 ]; then
    echo "usage: tools/fuzz.sh TARGET|all SECONDS [libFuzzer options...]" >&2
    echo "       tools/fuzz.sh TARGET|all --build-only" >&2
    echo "targets: ${all_targets[*]}" >&2
    exit 2
fi
target="$1"
seconds="$2"
shift 2
if [ "$target" = all ]; then
    targets=("${all_targets[@]}")
elif [[ " ${all_targets[*]} " == *" $target "* ]]; then
    targets=("$target")
else
    echo "tools/fuzz.sh: unknown target '$target' (${all_targets[*]}, all)" >&2
    exit 2
fi

if [ "$seconds" != --build-only ] && ! [[ "$seconds" =~ ^[0-9]+$ ]]; then
    echo "tools/fuzz.sh: SECONDS must be a whole number or --build-only, not '$seconds'" >&2
    exit 2
fi

if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DRADCACHE_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ >/dev/null
fi
cmake --build "$build" -j"$(nproc)" --target "${targets[@]/#/fuzz_}" >/dev/null
if [ "$seconds" = --build-only ]; then
    exit 0
fi

# The seeds tools/fuzz.sh adds from the shipped scenes: each scene file with its small meshes
# (as "#@file" sections), and every mesh.
shipped_seeds() {
    local dir="$1" kind="$2"
    mkdir -p "$dir"
    for scene in "$root"/scenes/*/scene.json; do
        local folder name
        folder="$(dirname "$scene")"
        name="$(basename "$folder")"
        if [ "$kind" = scene ]; then
            {
                cat "$scene"
                find "$folder" -name '*.obj' -size -64k | sort | while read -r mesh; do
                    printf '\n#@file %s\n' "${mesh#"$folder"/}"
                    cat "$mesh"
                done
            } >"$dir/$name.json"
        else
            find "$folder" -name '*.obj' | sort | while read -r mesh; do
                cp "$mesh" "$dir/${name}_$(basename "$mesh")"
            done
        fi
    done
}

# Known third-party leaks (tests/fuzz/lsan.supp) do not stop a run; any other leak does.
export LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"

status=0
for t in "${targets[@]}"; do
    corpus="$build/corpus/$t"
    seeds="$build/seeds/$t"
    artifacts="$build/artifacts/$t"
    rm -rf "$seeds"
    mkdir -p "$corpus" "$seeds" "$artifacts"
    cp "$root"/tests/fuzz/seeds/"$t"/* "$seeds"/
    if [ -d "$root/tests/fuzz/regressions/$t" ]; then
        cp "$root"/tests/fuzz/regressions/"$t"/* "$seeds"/ 2>/dev/null || true
    fi
    options=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048
             -close_fd_mask=3 -print_final_stats=1 -artifact_prefix="$artifacts/")
    case "$t" in
        scene | obj)
            [ "$t" = scene ] && shipped_seeds "$seeds" scene || shipped_seeds "$seeds" obj
            options+=(-max_len=16384 -dict="$root/tests/fuzz/scene.dict") ;;
        kernel_cache) options+=(-max_len=4096) ;;
        *) options+=(-max_len=65536) ;;
    esac
    log="$build/fuzz-$t.log"
    echo "fuzz $t: ${seconds} s ..."
    if ! "$build/fuzz_$t" "${options[@]}" "$@" "$corpus" "$seeds" >"$log" 2>&1; then
        status=1
        echo "fuzz $t: FAILED (see $log; the input is in $artifacts/)" >&2
        grep -E "ERROR|SUMMARY|Test unit written" "$log" >&2 || tail -20 "$log" >&2
    fi
    executed="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)"
    took="$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -1)"
    echo "fuzz $t: ${executed:-?} inputs executed in ${took:-$seconds} s," \
        "corpus $(find "$corpus" -type f | wc -l) files"
done
exit $status
