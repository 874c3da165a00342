#!/usr/bin/env python
"""Compare the netCDF results of two workflow runs (e.g. Slurm vs local).

    python .ci/compare_results.py RESULTS_A RESULTS_B

Same set of *.nc files; every variable and coordinate equal (numerical ones exactly,
NaNs equal); global and per-variable attributes equal except provenance that
legitimately differs between runs (created_utc, history, git_dirty).
Exit 0 if identical, 1 with one line per difference otherwise.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import xarray as xr

IGNORED_ATTRS = {"created_utc", "history", "git_dirty"}


def _attrs(a: dict) -> dict:
    return {k: v for k, v in a.items() if k not in IGNORED_ATTRS}


def _attrs_equal(a: dict, b: dict) -> bool:
    a, b = _attrs(a), _attrs(b)
    if a.keys() != b.keys():
        return False
    for k in a:
        va, vb = np.asarray(a[k]), np.asarray(b[k])
        if va.shape != vb.shape or not np.array_equal(va, vb):
            return False
    return True


def _values_equal(a: xr.DataArray, b: xr.DataArray) -> bool:
    if a.dims != b.dims or a.shape != b.shape:
        return False
    va, vb = a.values, b.values
    if np.issubdtype(va.dtype, np.number) and np.issubdtype(vb.dtype, np.number):
        return bool(np.array_equal(va, vb, equal_nan=True))
    return bool(np.array_equal(va, vb))


def compare_file(fa: Path, fb: Path) -> list[str]:
    diffs = []
    with xr.open_dataset(fa, decode_times=False) as a, xr.open_dataset(fb, decode_times=False) as b:
        if not _attrs_equal(a.attrs, b.attrs):
            keys = sorted(set(_attrs(a.attrs)) ^ set(_attrs(b.attrs))) or sorted(
                k
                for k in _attrs(a.attrs)
                if not np.array_equal(np.asarray(a.attrs[k]), np.asarray(b.attrs.get(k)))
            )
            diffs.append(f"global attributes differ: {keys}")
        names_a, names_b = set(a.variables), set(b.variables)
        if names_a != names_b:
            diffs.append(
                f"variables differ: only A {sorted(names_a - names_b)}, "
                f"only B {sorted(names_b - names_a)}"
            )
        for name in sorted(names_a & names_b):
            if not _values_equal(a[name], b[name]):
                diffs.append(f"values of {name!r} differ")
            if not _attrs_equal(a[name].attrs, b[name].attrs):
                diffs.append(f"attributes of {name!r} differ")
    return diffs


def main(argv: list[str]) -> int:
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    ra, rb = Path(argv[1]), Path(argv[2])
    fa = {p.relative_to(ra) for p in ra.rglob("*.nc")}
    fb = {p.relative_to(rb) for p in rb.rglob("*.nc")}
    problems = []
    for p in sorted(fa - fb):
        problems.append(f"{p}: only in {ra}")
    for p in sorted(fb - fa):
        problems.append(f"{p}: only in {rb}")
    for p in sorted(fa & fb):
        problems += [f"{p}: {d}" for d in compare_file(ra / p, rb / p)]
    if not fa and not fb:
        problems.append(f"no *.nc files under {ra} or {rb}")
    for line in problems:
        print(f"compare_results: {line}")
    if problems:
        return 1
    print(f"compare_results: {len(fa)} netCDF files identical (ignoring {sorted(IGNORED_ATTRS)})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
