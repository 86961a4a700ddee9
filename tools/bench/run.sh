#!/usr/bin/env bash
# Runs radcache's benchmarks side by side on one device and keeps the results with the machine
# they ran on. Usage: tools/bench/run.sh [OUTDIR] [radcache options, e.g. --device 0:0]
# Writes OUTDIR/machine.txt, OUTDIR/compile.json, OUTDIR/rays.json, OUTDIR/pt.json and prints
# the tables.
set -euo pipefail
cd "$(dirname "$0")/../.."
out="${1:-build/bench}"
shift || true
mkdir -p "$out"
radcache=build/radcache
[ -x "$radcache" ] || { echo "build radcache first (see README)" >&2; exit 2; }
{
    date -u +"%Y-%m-%d %H:%M UTC"
    echo "git $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
    lscpu | grep -E "Model name|^CPU\(s\)|Thread|L2|L3" || true
    "$radcache" devices
} > "$out/machine.txt"
cat "$out/machine.txt"
"$radcache" bench compile --json "$out/compile.json" "$@"
"$radcache" bench rays --json "$out/rays.json" "$@"
"$radcache" bench pt --json "$out/pt.json" "$@"
