#!/usr/bin/env bash
# The built wheel, installed in a fresh virtual environment (its dependencies from the
# package registry), used from an empty directory: the README's commands and Python
# example, the paper's claims and comparison (.ci/wheel_examples.py).
#   bash .ci/wheel.sh [DIST_DIR]    (a DIST_DIR holding the wheel; default: build one)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
dist=${1:-$work/dist}
if [[ -z ${1:-} ]]; then
    python -m build --wheel --outdir "$dist" "$repo" >"$work/build.log" 2>&1 \
        || { cat "$work/build.log"; exit 1; }
fi
wheel=$(ls "$dist"/pencore-*.whl)
start=$SECONDS
python -m venv "$work/venv"
"$work/venv/bin/python" -m pip install --quiet --disable-pip-version-check "$wheel"
echo "wheel: installed with its dependencies in $((SECONDS - start)) s"
mkdir "$work/empty"
cd "$work/empty"
# nothing of the repository on the path: the installed package, its data and its kernels
env -u PYTHONPATH PATH="$work/venv/bin:$PATH" python -c \
    "import pencore, sys; print('wheel:', pencore.__file__); sys.exit('site-packages' not in pencore.__file__)"
env -u PYTHONPATH PATH="$work/venv/bin:$PATH" python "$repo/.ci/wheel_examples.py" "$repo/README.md"
echo "wheel: installed and checked in $((SECONDS - start)) s"
