#!/usr/bin/env bash
# Install pencore (no dependencies: the conda environment has them) from the checkout
# the workflow runs in, or from $PENCORE_SRC when the working directory is elsewhere.
set -euo pipefail
python -m pip install --no-deps --no-build-isolation -e "${PENCORE_SRC:-$PWD}"
