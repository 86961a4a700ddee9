#!/usr/bin/env bash
# POV-Ray 3.7 peer of the Cornell box: renders tools/peers/povray/cornell-box.pov at a ladder of
# radiosity quality settings on all cores, times each render (wall clock, parsing, radiosity
# pretrace and image writing included) and measures its error against
# scenes/cornell-box/reference.exr with `radcache compare`.
# Usage: tools/peers/povray/run.sh [OUTDIR] [SETTING ...]   (default build/peers/povray; all settings)
# Writes OUTDIR/SETTING.exr (linear half-float OpenEXR, R G B), OUTDIR/SETTING.log (POV-Ray's
# output and statistics), OUTDIR/SETTING.json (radcache compare), OUTDIR/povray.csv (setting,
# seconds, threads, rmse, relmse) and OUTDIR/machine.txt, and prints the table.
set -euo pipefail
cd "$(dirname "$0")/../../.."
out="${1:-build/peers/povray}"
shift || true

radcache=build/radcache
scene=tools/peers/povray/cornell-box.pov
reference=scenes/cornell-box/reference.exr
command -v povray >/dev/null ||
    { echo "povray not found: install POV-Ray 3.7 (apt-get install -y povray)" >&2; exit 2; }
[ -x "$radcache" ] || { echo "$radcache not found: build radcache first (see README)" >&2; exit 2; }
[ -f "$scene" ] || { echo "$scene missing: run tools/peers/povray/make-scene.py" >&2; exit 2; }

# The ladder. Radiosity: count (rays per new cache sample at the top level, halved per bounce),
# nearest_count (cache samples averaged), error_bound (cache spacing), pretrace_end (finest
# pretrace block, a fraction of the image); recursion_limit 10 bounces throughout (light beyond
# 10 bounces is well under 1% of the image here). Anti-aliasing: adaptive method 2 with threshold 0 (every
# pixel subdivided, R = recursion depth, jittered) so that the edges of the bright light, a large
# part of the image's mean, get their coverage.
declare -A options=(
    [low]="Declare=RadCount=100 Declare=RadNearest=5 Declare=RadErrorBound=0.5 Declare=RadPretraceEnd=0.04 +AM2 +A0.0 +R1 +J"
    [medium]="Declare=RadCount=800 Declare=RadNearest=10 Declare=RadErrorBound=0.2 Declare=RadPretraceEnd=0.01 +AM2 +A0.0 +R2 +J"
    [high]="Declare=RadCount=1600 Declare=RadNearest=20 Declare=RadErrorBound=0.1 Declare=RadPretraceEnd=0.005 +AM2 +A0.0 +R2 +J"
)
settings=("$@")
[ ${#settings[@]} -gt 0 ] || settings=(low medium high)
for setting in "${settings[@]}"; do
    [ -n "${options[$setting]:-}" ] || { echo "unknown setting $setting (low, medium, high)" >&2; exit 2; }
done

threads=$(nproc)
read -r width height < <(python3 -c 'import json, sys
text = "".join(l for l in open(sys.argv[1]) if not l.lstrip().startswith("//"))
print(*json.loads(text)["camera"]["resolution"])' scenes/cornell-box/scene.json)

mkdir -p "$out"
{
    date -u +"%Y-%m-%d %H:%M UTC"
    echo "git $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
    povray --version 2>&1 | grep -m1 "^POV-Ray" || true
    echo "nproc $threads"
    lscpu | grep -E "Model name" || true
} > "$out/machine.txt"
cat "$out/machine.txt"

csv="$out/povray.csv"
echo "setting,seconds,threads,rmse,relmse" > "$csv"
for setting in "${settings[@]}"; do
    image="$out/$setting.exr"
    read -ra extra <<< "${options[$setting]}"
    command=(povray "+I$scene" "+O$image" +FE "+W$width" "+H$height" -D "+WT$threads"
             File_Gamma=1.0 Declare=RadRecursion=10 "${extra[@]}")
    echo "rendering $setting: ${command[*]}"
    start=$(date +%s.%N)
    "${command[@]}" > "$out/$setting.log" 2>&1 ||
        { tail -n 20 "$out/$setting.log" >&2; echo "povray failed ($setting)" >&2; exit 1; }
    end=$(date +%s.%N)
    seconds=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
    "$radcache" compare "$image" "$reference" --json "$out/$setting.json"
    python3 - "$out/$setting.json" "$setting" "$seconds" "$threads" >> "$csv" <<'PY'
import json, sys
path, setting, seconds, threads = sys.argv[1:]
c = json.load(open(path))
print(f"{setting},{seconds},{threads},{c['rmse']:.6g},{c['relmse']:.6g}")
PY
done

echo
column -s, -t "$csv"
