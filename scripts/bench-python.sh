#!/usr/bin/env bash
# Python-side throughput: accsim's single env and C++ VectorEnv against
# highway-env, measured side by side in one run. highway-env lives only in
# .venv-bench (never in the project's .venv).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
venv="$root/.venv-bench"
want="gymnasium==1.0.0 highway-env==1.10.1"
if [ ! -f "$venv/.accsim-stamp" ] || [ "$(cat "$venv/.accsim-stamp")" != "$want" ]; then
  echo "bench-python: creating $venv"
  /usr/bin/python3 -m venv --system-site-packages "$venv"
  constraints="$(mktemp)"
  trap 'rm -f "$constraints"' EXIT
  echo "numpy==$(/usr/bin/python3 -c 'import numpy; print(numpy.__version__)')" > "$constraints"
  "$venv/bin/python" -m pip install -q --disable-pip-version-check -c "$constraints" $want
  echo "$want" > "$venv/.accsim-stamp"
fi
"$venv/bin/python" "$root/bench/python_bench.py" "$@"
