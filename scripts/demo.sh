#!/usr/bin/env bash
# The main job with bundled defaults:
#   1. every example scenario under each scripted ego driver;
#   2. a balanced train/test suite generated from them;
#   3. SafeBench-style collision rates of the drivers on the test suite;
#   4. a collision video and image.
# Everything lands in out/demo/.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-build}"
accsim="$root/$build/bin/accsim"
out="$root/out/demo"
mkdir -p "$out"

echo "== 1. example scenarios =="
printf "%-24s %-6s %-10s %-8s %-12s %-10s\n" scenario ego outcome "t [s]" "impulse[Ns]" "rel [m/s]"
for f in "$root"/scenarios/examples/*.json; do
  name="$(basename "$f" .json)"
  for ego in hold brake rule; do
    "$accsim" simulate "$f" --ego "$ego" --json --out "$out/${name}_${ego}.json" |
      python3 "$root/scripts/demo_row.py" "$name" "$ego"
  done
done

echo
echo "== 2. crash reports -> reconstructed scenarios -> suite =="
sources="$root/scenarios/examples"
narratives="$root/../shared/data/narratives/nmvccs"
if [ -d "$narratives" ]; then
  mkdir -p "$out/reconstructed"
  ok=0; total=0
  for f in "$narratives"/*/*.txt; do
    case_id="$(basename "$(dirname "$f")")_$(basename "$f" .txt)"
    total=$((total + 1))
    if "$accsim" reconstruct "$f" -o "$out/reconstructed/$case_id.json" --json 2>/dev/null | grep -q '"success":true'; then
      ok=$((ok + 1))
    else
      rm -f "$out/reconstructed/$case_id.json"
    fi
  done
  echo "reconstructed $ok of $total NMVCCS reports (checked in Bullet) into out/demo/reconstructed/"
  sources="$out/reconstructed"
fi
"$accsim" generate-suite --train 240 --test 120 --seed 1 --sources "$sources" -o "$out/suite"

echo
echo "== 3. evaluation on the test suite =="
"$accsim" evaluate "$out/suite/test.jsonl" --ego hold,brake,rule --markdown "$out/report.md"

echo
echo "== 4. collision video =="
"$accsim" simulate "$root/scenarios/examples/unprotected_left_turn.json" --ego hold \
  --video "$out/collision.mp4" --png "$out/collision.png" >/dev/null
echo "wrote out/demo/collision.mp4 and collision.png; report in out/demo/report.md"
