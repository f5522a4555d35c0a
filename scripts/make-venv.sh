#!/usr/bin/env bash
# Makes .venv/: Debian's python3 with system site packages (torch, numpy,
# pandas, matplotlib, cloudpickle come from Debian) plus the pinned PyPI
# packages. numpy is pinned to Debian's version so pip never replaces it.
#
# stable-baselines3 is installed without its dependencies: Debian's torch
# 1.13.1 reports itself as "1.13.0a0", which pip does not accept for SB3's
# "torch>=1.13", so pip would otherwise download a multi-gigabyte CUDA torch
# from PyPI. Its other dependencies are Debian packages (install-deps.sh).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
venv="$root/.venv"
stamp="$venv/.accsim-stamp"
gym="gymnasium==1.0.0"
sb3="stable-baselines3==2.4.1"
want="$gym $sb3 torch-from-debian"

if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ] && [ -x "$venv/bin/python" ]; then
  exit 0
fi
echo "make-venv: creating $venv"
rm -rf "$venv"
/usr/bin/python3 -m venv --system-site-packages "$venv"
numpy_version="$(/usr/bin/python3 -c 'import numpy; print(numpy.__version__)')"
constraints="$(mktemp)"
trap 'rm -f "$constraints"' EXIT
echo "numpy==$numpy_version" > "$constraints"
pip=("$venv/bin/python" -m pip install -q --disable-pip-version-check)
"${pip[@]}" -c "$constraints" "$gym"
"${pip[@]}" --no-deps "$sb3"
torch_file="$("$venv/bin/python" -c 'import torch; print(torch.__file__)')"
case "$torch_file" in
  /usr/lib/python3/*) ;;
  *) echo "make-venv: expected Debian's torch, found $torch_file" >&2; exit 1 ;;
esac
"$venv/bin/python" -c 'import stable_baselines3, gymnasium' >/dev/null
echo "$want" > "$stamp"
