#!/usr/bin/env bash
# Installs what .ci/cf_check.py needs, idempotently (nothing is downloaded twice):
#  - the udunits2 C library (Debian libudunits2-0), which cfchecker loads at import;
#  - cfchecker itself (PyPI);
#  - the CF standard-name table, taken from the compliance-checker wheel (PyPI), which
#    ships it; cfchecker would otherwise download it from the web at every run.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
if ! ldconfig -p 2>/dev/null | grep -q libudunits2; then
    if [[ $(id -u) -eq 0 ]]; then
        apt-get update -qq && apt-get install -y -qq --no-install-recommends libudunits2-0
    else
        echo "install-cf-checker: need the udunits2 library (Debian: libudunits2-0)" >&2
        exit 1
    fi
fi
python -m pip install -q 'cfchecker>=4.1,<5'
table=cf/cache/cf-standard-name-table.xml
if [[ ! -s $table ]]; then
    tmp=$(mktemp -d)
    python -m pip download -q --no-deps -d "$tmp" 'compliance-checker==6.1.0'
    mkdir -p cf/cache
    python - "$tmp" "$table" <<'PY'
import sys, zipfile, pathlib
wheel = next(pathlib.Path(sys.argv[1]).glob("compliance_checker-*.whl"))
with zipfile.ZipFile(wheel) as z:
    pathlib.Path(sys.argv[2]).write_bytes(z.read("compliance_checker/data/cf-standard-name-table.xml"))
PY
    rm -rf "$tmp"
fi
