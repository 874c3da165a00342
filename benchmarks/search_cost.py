"""Where a reproduction's threshold searches spend their time, read from its logs.

Every search (:func:`pencore.search.threshold.find_threshold`) logs its range, each
evaluation with the bracket it bisects, and its outcome, with millisecond timestamps, to
the rule's log. An evaluation's time is the gap since the previous line of its search
(the first evaluation of a job also carries the kernels' first load). Each evaluation is
put in one of three classes:

* ``ends_scan``: made while the bracket is still the whole search range (the two ends and
  the coarse scan);
* ``wide``: bisection of a bracket wider than ``NARROW`` times the tolerance;
* ``narrow``: bisection of a bracket at most ``NARROW`` tolerances wide, i.e. the
  evaluations a search would still make if it were handed a bracket that tight around its
  answer (from a neighbour's answer, a model of the threshold, or anything else) and
  skipped the scan.

The sum of ``narrow`` is therefore a floor for every cheaper-bracket scheme that keeps the
tolerance: it is what bisection to the same tolerance costs once the bracket is tight.
Together with the jobs' wall times of the same run it bounds the reproduction's wall on
``cores`` cores: ``(job sum - ends_scan - wide) / cores``.

Input: a directory in which ``snakemake --forceall`` has run (``results/logs`` and
``results/benchmarks``), e.g. the clone kept by
``python benchmarks/bench_reproduction.py --keep DIR``.
Writes benchmarks/results/search_cost.csv (one row per search) and search_cost.json (the
commit, the totals per study group, the jobs' wall sum and the bound), and prints them.
Run: python benchmarks/search_cost.py DIR [--cores 2]
"""

from __future__ import annotations

import argparse
import json
import re
import subprocess
import sys
from datetime import datetime
from pathlib import Path

import pandas as pd

HERE = Path(__file__).parent
sys.path.insert(0, str(HERE))
from bench_reproduction import job_table  # noqa: E402

#: A bracket at most this many tolerances wide counts as "tight" (class ``narrow``).
NARROW = 32

_STAMP = r"^(?P<t>\d{4}-\d\d-\d\d \d\d:\d\d:\d\d,\d{3}) INFO pencore\.search: (?P<name>[^:]+): "
_START = re.compile(_STAMP + r"search in \[(?P<lo>[^,]+), (?P<hi>[^\]]+)\], tol (?P<tol>\S+)$")
_EVAL = re.compile(
    _STAMP + r"evaluation (?P<k>\d+) at (?P<v>\S+) -> (?P<verdict>True|False) "
    r"\(bracket \[(?P<blo>[^,]+), (?P<bhi>[^\]]+)\]\)$"
)
_END = re.compile(_STAMP + r"(?P<status>\w+) after (?P<n>\d+) evaluations")
_VALUE = re.compile(r"value (?P<value>\S+) in")


def _time(stamp: str) -> datetime:
    return datetime.strptime(stamp, "%Y-%m-%d %H:%M:%S,%f")


def searches(log: Path) -> list[dict]:
    """One dict per search of ``log``: its range, tolerance, outcome and the seconds of its
    evaluations by class (module docstring). A search the log does not finish (its job
    stopped, or a run of it raised) is reported with status ``unfinished``."""
    out: list[dict] = []
    cur: dict | None = None
    last = None
    for line in log.read_text().splitlines():
        if m := _START.match(line):
            if cur is not None:
                out.append(cur)
            lo, hi = float(m["lo"]), float(m["hi"])
            cur = {"name": m["name"], "lo": lo, "hi": hi, "tol": float(m["tol"]),
                   "n_evals": 0, "status": "unfinished", "value": float("nan"),
                   "ends_scan_s": 0.0, "wide_s": 0.0, "narrow_s": 0.0,
                   "ends_scan_n": 0, "wide_n": 0, "narrow_n": 0}  # fmt: skip
            last = _time(m["t"])
        elif cur is not None and (m := _EVAL.match(line)) and m["name"] == cur["name"]:
            t = _time(m["t"])
            dt = (t - last).total_seconds()
            last = t
            blo, bhi = float(m["blo"]), float(m["bhi"])
            if (blo, bhi) == (cur["lo"], cur["hi"]):
                cls = "ends_scan"
            elif bhi - blo <= NARROW * cur["tol"]:
                cls = "narrow"
            else:
                cls = "wide"
            cur[f"{cls}_s"] += dt
            cur[f"{cls}_n"] += 1
            cur["n_evals"] += 1
        elif cur is not None and (m := _END.match(line)) and m["name"] == cur["name"]:
            cur["status"] = m["status"]
            if v := _VALUE.search(line):
                cur["value"] = float(v["value"])
            out.append(cur)
            cur = None
    if cur is not None:
        out.append(cur)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run", type=Path, help="directory the reproduction ran in")
    ap.add_argument("--cores", type=int, default=2)
    ap.add_argument("--csv", default=str(HERE / "results" / "search_cost.csv"))
    ap.add_argument("--json", default=str(HERE / "results" / "search_cost.json"))
    args = ap.parse_args()
    logs = args.run / "results" / "logs"
    rows = []
    for log in sorted(logs.rglob("*.log")):
        if log.relative_to(logs).parts[0] == "archive":
            continue
        for i, s in enumerate(searches(log)):
            rows.append({"log": log.relative_to(logs).as_posix(), "search": i, **s})
    if not rows:
        raise SystemExit(f"search_cost: no search in any log under {logs}")
    df = pd.DataFrame(rows)
    df["total_s"] = df[["ends_scan_s", "wide_s", "narrow_s"]].sum(axis=1)
    df.round(4).to_csv(args.csv, index=False)
    df["group"] = df["log"].str.split("/").str[0]
    cols = ["total_s", "ends_scan_s", "wide_s", "narrow_s", "ends_scan_n", "wide_n", "narrow_n"]
    by = df.groupby("group")[cols].sum()
    by.loc["all"] = by.sum()
    print(f"searches: {len(df)}, evaluations: {int(df['n_evals'].sum())}")
    print(by.round(1).to_string())
    jobs = job_table(args.run / "results" / "benchmarks")
    job_sum = float(jobs["wall_s"].sum())
    cut = float(by.loc["all", "ends_scan_s"] + by.loc["all", "wide_s"])
    commit = subprocess.run(
        ["git", "rev-parse", "--short", "HEAD"], cwd=args.run, capture_output=True, text=True,
        check=True,
    ).stdout.strip()  # fmt: skip
    out = {
        "commit": commit,
        "narrow_tolerances": NARROW,
        "n_searches": len(df),
        "n_evaluations": int(df["n_evals"].sum()),
        "by_group": {g: {c: round(float(v), 2) for c, v in r.items()} for g, r in by.iterrows()},
        "n_jobs": len(jobs),
        "job_wall_sum_s": round(job_sum, 2),
        "without_scan_and_wide_s": round(job_sum - cut, 2),
        "cores": args.cores,
        "wall_floor_s": round((job_sum - cut) / args.cores, 2),
    }
    Path(args.json).write_text(json.dumps(out, indent=1) + "\n")
    print(
        f"jobs: {len(jobs)}, wall sum {job_sum:.1f} s; without every scan and wide bisection "
        f"{job_sum - cut:.1f} s, i.e. at least {out['wall_floor_s']:.1f} s of wall "
        f"on {args.cores} cores"
    )


if __name__ == "__main__":
    main()
