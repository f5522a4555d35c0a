#!/usr/bin/env bash
# Makes .venv/: Debian's python3 with system site packages (torch, numpy,
# pandas, matplotlib come from Debian) plus the pinned PyPI packages.
# numpy is pinned to Debian's version so pip never replaces it.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
venv="$root/.venv"
stamp="$venv/.accsim-stamp"
want="gymnasium==1.0.0 stable-baselines3==2.4.1"

if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ] && [ -x "$venv/bin/python" ]; then
  exit 0
fi
echo "make-venv: creating $venv"
/usr/bin/python3 -m venv --system-site-packages "$venv"
numpy_version="$(/usr/bin/python3 -c 'import numpy; print(numpy.__version__)')"
constraints="$(mktemp)"
trap 'rm -f "$constraints"' EXIT
echo "numpy==$numpy_version" > "$constraints"
"$venv/bin/python" -m pip install -q --disable-pip-version-check -c "$constraints" $want
echo "$want" > "$stamp"
