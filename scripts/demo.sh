#!/usr/bin/env bash
# The main job with bundled defaults: every example scenario under each
# scripted ego driver, with the outcome of each run.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-build}"
accsim="$root/$build/bin/accsim"
out="$root/out/demo"
mkdir -p "$out"
printf "%-24s %-6s %-10s %-8s %-12s %-10s\n" scenario ego outcome "t [s]" "impulse[Ns]" "rel [m/s]"
for f in "$root"/scenarios/examples/*.json; do
  name="$(basename "$f" .json)"
  for ego in hold brake rule; do
    "$accsim" simulate "$f" --ego "$ego" --json --out "$out/${name}_${ego}.json" |
      python3 "$root/scripts/demo_row.py" "$name" "$ego"
  done
done
echo "trajectories saved in out/demo/"
