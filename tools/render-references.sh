#!/usr/bin/env bash
# Renders the path-traced references of the shipped scenes with the settings of the shipped ones
# (65 536 samples per pixel, seed 20261123; moving-sphere every frame 0-23 at 16 384 samples;
# kettle, the glossy kettle of the SDRC paper, 256 x 256 at 4096 samples, rendered on a CPU;
# relief, the detail scene of irradiance decomposition, 256 x 256 at 4096 samples, on a CPU;
# moving-light, the moving light of the temporal radiance caching report, every frame 0-15 at
# 128 x 96 and 4096 samples, rendered on a CPU; walkthrough, the camera walking through the two
# rooms, every 4th frame 0, 4, ..., 44 at 256 x 256 and 256 samples, rendered on a CPU;
# half floats: beauty, direct, indirect and the per-sample standard deviation of the beauty) and
# writes beside each EXR the record of how it was made (tools/references.py). Layout:
# scenes/NAME/reference.exr + reference.json for a still scene, scenes/NAME/reference/frameFFFF.exr
# + frameFFFF.json for every frame of an animated one, or every Nth from its first (scenes/README.md).
#
# Usage: tools/render-references.sh [--device SPEC] [--out DIR] [--spp N] [scene ...]
#   scene ...      cornell-box glossy-box two-rooms moving-sphere kettle relief moving-light
#                  walkthrough (default: all)
#   --device SPEC  the OpenCL device (radcache render --device: P:D or part of its name;
#                  default: radcache's, the first GPU, else the first CPU device)
#   --out DIR      write DIR/NAME/... instead of scenes/NAME/... (the same layout)
#   --spp N        N samples per pixel (every frame) instead of the shipped settings, for a smoke
#                  run; needs --out, so that it never replaces the shipped references
# The radcache executable is $RADCACHE, else build/radcache. Each scene renders into a temporary
# folder and replaces its old reference only once its render and records are complete.
# One scene takes about a minute on an NVIDIA H100 (scenes/*/reference.json: seconds), hours on
# a CPU (the kettle's 4096 samples: about 25 minutes on 2 CPU cores with PoCL; the moving
# light's 16 frames about as long).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
radcache=${RADCACHE:-$root/build/radcache}
fail() { echo "render-references: $*" >&2; exit 2; }

# The shipped references' settings: samples per pixel, resolution, and the frames of the
# animated scene (every one).
seed=20261123
declare -A spp=([cornell-box]=65536 [glossy-box]=65536 [two-rooms]=65536 [moving-sphere]=16384
                [kettle]=4096 [relief]=4096 [moving-light]=4096 [walkthrough]=256)
declare -A size=([cornell-box]=512x512 [glossy-box]=512x512 [two-rooms]=512x384
                 [moving-sphere]=256x256 [kettle]=256x256 [relief]=256x256
                 [moving-light]=128x96 [walkthrough]=256x256)
declare -A frames=([moving-sphere]=0:23 [moving-light]=0:15 [walkthrough]=0:44)
# Animated scenes whose references are every Nth frame of the range above, each its own run.
declare -A step=([walkthrough]=4)
all=(cornell-box glossy-box two-rooms moving-sphere kettle relief moving-light walkthrough)

out=$root/scenes
spp_override=""
device=()
scenes=()
while [ $# -gt 0 ]; do
    case "$1" in
        --device) [ $# -ge 2 ] || fail "--device needs a value"; device=(--device "$2"); shift 2 ;;
        --out) [ $# -ge 2 ] || fail "--out needs a folder"; out=$2; shift 2 ;;
        --spp)
            [ $# -ge 2 ] || fail "--spp needs a value"
            [[ "$2" =~ ^[1-9][0-9]*$ ]] || fail "--spp: expected a positive integer, got '$2'"
            spp_override=$2; shift 2 ;;
        -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
        -*) fail "unknown option $1 (see --help)" ;;
        *) [ -n "${spp[$1]:-}" ] || fail "no reference settings for scene '$1' (known: ${all[*]})"
           scenes+=("$1"); shift ;;
    esac
done
[ ${#scenes[@]} -gt 0 ] || scenes=("${all[@]}")
if [ -n "$spp_override" ] && [ "$out" = "$root/scenes" ]; then
    fail "--spp $spp_override: give --out DIR too; the shipped references keep their settings"
fi
[ -x "$radcache" ] || fail "no radcache executable at $radcache (build it, or set RADCACHE)"
radcache=$(cd "$(dirname "$radcache")" && pwd)/$(basename "$radcache")
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$root"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Renders frames $3 of scene $1 at $2 spp (a still scene: $3 empty) into $work and writes its
# records into $4 (tools/references.py record).
render_one() {
    local name=$1 n=$2 range=$3 staged=$4
    local outputs stats
    # The command as the records state it: paths of the outputs relative to the render folder.
    if [ -n "$range" ]; then
        outputs=(--frames "$range" -o "$name/frame####.exr")
        stats=$name/stats.json
    else
        outputs=(-o "$name.exr")
        stats=$name.stats.json
    fi
    # Independent samples: the stddev layer then states the pixel mean's noise exactly (compare's
    # error net of the reference's noise subtracts it; docs/pixel-filters.md, "Pixel samplers").
    local command=(render "scenes/$name/scene.json" "${outputs[@]}" --spp "$n" --seed "$seed"
                   --sampler independent --width "${size[$name]%x*}" --height "${size[$name]#*x}"
                   --half --aovs beauty,direct,indirect,stddev --stats "$stats" "${device[@]}")
    # The command line as text: arguments with spaces (a device's name) in single quotes.
    local text=radcache argument
    for argument in "${command[@]}"; do
        if [[ "$argument" =~ [[:space:]] ]]; then text+=" '$argument'"; else text+=" $argument"; fi
    done
    echo "rendering $name at $n spp: $text"
    # Step 1: render into the temporary folder (the same command, its outputs under $work).
    local run=()
    for argument in "${command[@]}"; do
        case "$argument" in
            "$name.exr" | "$name/frame####.exr" | "$stats") run+=("$work/$argument") ;;
            *) run+=("$argument") ;;
        esac
    done
    "$radcache" "${run[@]}"
    # Step 2: the records.
    python3 tools/references.py record "$work/$stats" --scene "scenes/$name" --dest "$staged" \
        --command "$text"
}

for name in "${scenes[@]}"; do
    n=${spp_override:-${spp[$name]}}
    tmp=$work/$name
    mkdir -p "$tmp"
    staged=$tmp/staged
    range=${frames[$name]:-}
    if [ -n "${step[$name]:-}" ]; then
        # Every step-th frame, one run each.
        for ((f = ${range%:*}; f <= ${range#*:}; f += ${step[$name]})); do
            render_one "$name" "$n" "$f:$f" "$staged"
        done
    else
        render_one "$name" "$n" "$range" "$staged"
    fi
    # The EXRs under their shipped names.
    if [ -n "$range" ]; then
        mv "$tmp"/frame*.exr "$staged/reference/"
        rm -rf "$out/$name/reference"
        mkdir -p "$out/$name"
        mv "$staged/reference" "$out/$name/reference"
    else
        mv "$work/$name.exr" "$staged/reference.exr"
        mkdir -p "$out/$name"
        mv "$staged/reference.exr" "$staged/reference.json" "$out/$name/"
    fi
    echo "written $out/$name"
done
