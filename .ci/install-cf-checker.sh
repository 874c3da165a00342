#!/usr/bin/env bash
# Installs what .ci/cf_check.py needs, idempotently (nothing is downloaded twice):
#  - the udunits2 C library (Debian libudunits2-0), which both checkers load at import;
#  - the two CF checkers (PyPI): cfchecker, the CF community's reference checker, and the
#    IOOS compliance-checker, whose cf:1.10 suite adds checks cfchecker does not make
#    (for example that a dimension named like a CF axis is one). They are CI tools, not
#    something pencore or its users need, hence installed here and not in an extra;
#  - the CF standard-name table, copied from the compliance-checker package, which ships
#    it; cfchecker would otherwise download it from the web at every run.
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
python -m pip install -q 'cfchecker>=4.1,<5' 'compliance-checker==6.1.0'
table=cf/cache/cf-standard-name-table.xml
if [[ ! -s $table ]]; then
    mkdir -p cf/cache
    python - "$table" <<'PY'
import pathlib, sys
import compliance_checker
src = pathlib.Path(compliance_checker.__file__).parent / "data" / "cf-standard-name-table.xml"
pathlib.Path(sys.argv[1]).write_bytes(src.read_bytes())
PY
fi
