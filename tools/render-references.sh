#!/usr/bin/env bash
# Renders the path-traced reference of every non-analytic shipped scene into
# scenes/<name>/reference.exr (half floats: beauty, direct, indirect and the per-sample standard
# deviation of the beauty) and records how in scenes/<name>/reference.json.
# Usage: tools/render-references.sh [scene ...]   (default: all; build radcache first)
set -euo pipefail
cd "$(dirname "$0")/.."
radcache=build/radcache
[ -x "$radcache" ] || { echo "build radcache first (see README)" >&2; exit 2; }

# Samples per pixel of each reference; the seed is fixed so the files are reproducible.
declare -A spp=([cornell-box]=4096 [glossy-box]=4096 [two-rooms]=8192 [moving-sphere]=8192)
seed=20261121
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(cornell-box glossy-box two-rooms moving-sphere)

for name in "${scenes[@]}"; do
    n=${spp[$name]:?"no reference settings for scene $name"}
    dir=scenes/$name
    command=("$radcache" render "$dir/scene.json" -o "$dir/reference.exr" --spp "$n" --seed "$seed"
             --half --aovs beauty,direct,indirect,stddev --stats "$dir/reference.stats.json" --quiet)
    echo "rendering $name at $n spp"
    "${command[@]}"
    python3 - "$dir" "$n" "$seed" "${command[*]}" <<'PY'
import json, sys
directory, spp, seed, command = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
stats = json.load(open(f"{directory}/reference.stats.json"))
record = {
    "file": "reference.exr",
    "layers": "beauty (R, G, B), direct, indirect, stddev (of one beauty sample of the pixel)",
    "storage": "OpenEXR, half float, zip",
    "spp": spp,
    "seed": seed,
    "frame": stats["frames"][0]["frame"],
    "resolution": stats["resolution"],
    "command": command.replace("build/radcache", "radcache"),
    "device": stats["device"],
    "seconds": round(stats["seconds"]["total"], 1),
    "rays": stats["rays"],
    "nonfinite_samples": stats["nonfinite_samples"],
}
json.dump(record, open(f"{directory}/reference.json", "w"), indent=2)
open(f"{directory}/reference.json", "a").write("\n")
PY
    rm -f "$dir/reference.stats.json"
done
