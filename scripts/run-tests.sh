#!/usr/bin/env bash
# Runs every test: ctest (GoogleTest suites, CLI end to end), then pytest.
# The last lines printed are the two runners' summaries.
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-build}"
cd "$root"
status=0
(cd "$build" && ctest --output-on-failure -j "$(nproc)" > ctest.log 2>&1) || status=$?
grep -E "^(The following tests FAILED|[[:space:]]+[0-9]+ - )" -A0 "$build/ctest.log" || true
py_status=0
if [ -d python/tests ]; then
  .venv/bin/python -m pytest -q python/tests > "$build/pytest.log" 2>&1 || py_status=$?
  if [ "$py_status" -ne 0 ]; then tail -n 60 "$build/pytest.log"; fi
fi
echo
echo "== ctest =="
tail -n 4 "$build/ctest.log" | grep -E "tests passed|Total Test time" || tail -n 20 "$build/ctest.log"
if [ -d python/tests ]; then
  echo "== pytest =="
  tail -n 1 "$build/pytest.log"
fi
[ "$status" -eq 0 ] && [ "$py_status" -eq 0 ]
