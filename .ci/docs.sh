#!/usr/bin/env bash
# The documentation, built strictly and opened in a real browser:
#  1. Sphinx builds docs/ with warnings as errors and nitpicky (-n -W: broken internal
#     links, cross-references that do not resolve, undefined substitutions, docstrings that
#     do not render) and runs every example of the gallery (an example that raises fails
#     the build); it needs no network (intersphinx inventories in docs/_inventories/,
#     MathJax from the docs extra, served by the site);
#  2. Snakemake writes the HTML report of the small configuration .test/config.yaml, run
#     by the test suite (kept by .ci/run in PENCORE_E2E_DIR) or else here in a scratch clone;
#  3. headless chromium opens every page of the site and the report, and fails on an image
#     that did not load, a script error, a docs page's request to another host, or math
#     left as raw TeX (.ci/browser_check.py); screenshots of the front page and the report
#     are kept in ci-artifacts/.
# Needs the docs extra (python -m pip install -e '.[docs]') and Debian's chromium and
# chromium-driver, which this script installs with apt-get when they are missing.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
REPO=$(pwd)

if [[ ! -x /usr/bin/chromium || ! -x /usr/bin/chromedriver ]]; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium chromium-driver > /dev/null
fi

rm -rf docs/_build docs/auto_examples docs/api/generated
python -m sphinx -n -W --keep-going -q -b html docs docs/_build/html
echo "docs: built docs/_build/html"

WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
# the test suite's end-to-end run of .test/config.yaml when .ci/run kept it
# (PENCORE_E2E_DIR, tests/workflow/conftest.py), else a run in a scratch clone
E2E=${PENCORE_E2E_DIR:-}
if [[ -n "$E2E" && -f "$E2E/done.json" ]] \
    && python -c "import json, sys; sys.exit(not json.load(open(sys.argv[1]))['ok'])" \
        "$E2E/done.json"; then
    run_dir="$E2E/wd"
    echo "docs: the workflow report from the test suite's run in $run_dir"
else
    run_dir="$WORK/repo"
    git clone -q "$REPO" "$run_dir"
    (cd "$run_dir" && python -m snakemake --cores 2 --configfile .test/config.yaml --quiet) \
        > "$WORK/run.log" 2>&1 || { tail -40 "$WORK/run.log"; exit 1; }
fi
(cd "$run_dir" && python -m snakemake --configfile .test/config.yaml --report "$WORK/report.html") \
    > "$WORK/report.log" 2>&1 || { tail -40 "$WORK/report.log"; exit 1; }
python .ci/browser_check.py --site docs/_build/html --report "$WORK/report.html" \
    --screenshots ci-artifacts
