"""Tables and numbers of the documentation, generated from the files that hold them.

No number in the docs or the README is typed by hand where a file holds it: the pages
include the Markdown this module writes to ``docs/_generated/`` at every build (a Sphinx
extension, :func:`setup`), and the prose holds single numbers written into the Markdown
between comments, ``<!-- n:vcr_p2_45 -->1573.68<!-- /n -->`` (:func:`numbers`,
:func:`with_numbers`), so a page reads the same on GitHub, in a terminal and in the site.
The README's generated blocks come from the same functions. ``python
docs/_ext/pencore_docs.py --readme`` rewrites both; ``tests/docs/test_readme.py`` and
``tests/docs/test_pages.py`` fail when either is stale.

Sources: ``results/archive/paper_comparison.csv`` (the archived comparison with the paper),
``config/paper_claims.csv``, ``config/concrete_compilation.csv``, ``benchmarks/results/*.csv``,
:data:`pencore.inputs.limits.LIMITS`, the workflow's configuration schema, and a run of the
solver (the Dataset's variables).
"""

from __future__ import annotations

import argparse
import math
import re
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pandas as pd

REPO = Path(__file__).resolve().parents[2]
GENERATED = REPO / "docs" / "_generated"
COMPARISON = REPO / "results" / "archive" / "paper_comparison.csv"
BENCH = REPO / "benchmarks" / "results"

#: The README's headline rows: (quantity in the comparison table, short label[, the key of
#: :func:`pencore.paper.claims.paper_values` when the paper gives a bracket, not a value]).
HEADLINE = (
    (
        "Table 2 test 2: penetration depth (V=280 m/s, obliquity 0 deg, yaw 0 deg)",
        "depth of #2 in soil, 280 m/s, normal (Table 2)",
    ),
    ("Vcr of #2 at 45 deg obliquity (Fig. 7)", "Vcr of #2 at 45 deg (Fig. 7)", "vcr_p2_45_bracket"),
    (
        "Fig. 13: deviation phi of #4, yaw 0.1 deg, Vi = 1000 m/s, axis_tilted (configured)",
        "deviation of #4, yaw 0.1 deg, 1000 m/s (Fig. 13)",
    ),
    (
        "Fig. 16: deviation alpha of #2, 1000 m/s, omega = 20 rad/s",
        "deviation of #2 spun at 20 rad/s, 1000 m/s (Fig. 16)",
    ),
    (
        "omega_c of #2 at 1000 m/s (Figs 16-17)",
        "omega_c of #2 at 1000 m/s (Figs 16-17)",
        "omega_c_p2_1000_bracket",
    ),
)

UNIT_TEXT = {"m s-1": "m/s", "rad s-1": "rad/s", "degree": "deg", "1": "", "kg": "kg", "m": "m"}


def _fmt(value: object, digits: int = 4) -> str:
    """A number with ``digits`` significant digits, a boolean as yes/no, text as it is."""
    if isinstance(value, bool) or str(value) in ("True", "False"):
        return "yes" if str(value) == "True" else "no"
    try:
        x = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return str(value)
    if x != x:  # NaN
        return ""
    return f"{x:.{digits}g}"


def comparison() -> pd.DataFrame:
    """The archived comparison with the paper (``results/archive/paper_comparison.csv``),
    checked: every ``value`` row has a finite, nonzero paper value and a finite pencore
    value or a bound (``> 500``), so that no ``nan`` or stray text renders as a number."""
    table = pd.read_csv(COMPARISON, dtype=str, keep_default_na=False)
    for _, row in table[table["kind"] == "value"].iterrows():
        paper, ours = _finite(row["paper_value"]), _finite(row["pencore_value"])
        if paper is None or paper == 0.0:
            _bad(row, "paper_value", "a finite, nonzero number")
        if ours is None and not re.match(r"^[<>]=? ?[0-9]", row["pencore_value"]):
            _bad(row, "pencore_value", "a finite number or a bound such as '> 500'")
        if row["difference"] and _finite(row["difference"]) is None:
            _bad(row, "difference", "a finite number or empty")
    return table


def _finite(text: str) -> float | None:
    """``text`` as a finite float, else None (text, ``nan``, ``inf``)."""
    try:
        x = float(text)
    except ValueError:
        return None
    return x if math.isfinite(x) else None


def _bad(row: pd.Series, column: str, allowed: str) -> None:
    raise ValueError(
        f"{COMPARISON.name}: row {row['quantity'][:60]!r} has {column} = "
        f"{row[column][:40]!r}; a value row needs {allowed}"
    )


def _row(table: pd.DataFrame, quantity: str) -> pd.Series:
    hit = table[table["quantity"] == quantity]
    if len(hit) != 1:
        raise KeyError(f"{quantity!r} is not one row of {COMPARISON.name}")
    return hit.iloc[0]


def _relative(row: pd.Series) -> str:
    try:
        p, q = float(row["paper_value"]), float(row["pencore_value"])
    except ValueError:
        return row["difference"]
    return f"{100 * (q - p) / p:+.1f} %"


def headline_table() -> str:
    """The README's five-row table of pencore against the paper."""
    from pencore.paper.claims import paper_values

    paper_of = paper_values()
    table = comparison()
    lines = ["| quantity | paper | pencore | difference |", "|---|---|---|---|"]
    for quantity, label, *bracket in HEADLINE:
        row = _row(table, quantity)
        unit = UNIT_TEXT.get(row["units"], row["units"])
        paper = f"{_fmt(row['paper_value'])} {unit}".strip()
        if bracket:
            lo, hi = paper_of[bracket[0]]
            paper = f"{_fmt(lo)} to {_fmt(hi)} {unit}"
        ours = f"{_fmt(row['pencore_value'], 5)} {unit}".strip()
        diff = _relative(row) if re.match(r"^[+-]?\d", ours) else "differs"
        if bracket and diff != "differs":
            diff += " (from the midpoint)"
        lines.append(f"| {label} | {paper} | {ours} | {diff} |")
    return "\n".join(lines)


def comparison_counts() -> str:
    """One sentence counting the verdicts and trends of the comparison table, after its
    first words "Of the paper's" (a page line must not start with the number's comment:
    Markdown would take the line for HTML)."""
    table = comparison()
    verdicts = table[table["kind"] == "verdict"]["difference"].value_counts()
    trends = table[table["kind"] == "trend"]["pencore_value"].value_counts()
    return (
        f"{len(table[table['kind'] == 'trend'])} trends, "
        f"{trends.get('holds', 0)} hold and {trends.get('partly holds', 0)} partly hold; "
        f"of its {len(table[table['kind'] == 'verdict'])} yes/no statements, "
        f"{verdicts.get('agrees', 0)} agree and {verdicts.get('differs', 0)} differ."
    )


def comparison_table() -> str:
    """Every row of the archived comparison, as the docs' results page shows it."""
    table = comparison()
    lines = [
        "| quantity | paper | pencore | difference | units | note |",
        "|---|---|---|---|---|---|",
    ]
    for _, row in table.iterrows():
        cells = [
            row["quantity"],
            _fmt(row["paper_value"], 5),
            _fmt(row["pencore_value"], 6),
            _fmt(row["difference"], 3) if row["kind"] == "value" else row["difference"],
            UNIT_TEXT.get(row["units"], row["units"]),
            row["note"],
        ]
        lines.append("| " + " | ".join(c.replace("|", "/") for c in cells) + " |")
    return "\n".join(lines)


def limits_table(group: str = "core") -> str:
    """Valid ranges of every input (:func:`pencore.inputs.limits.limits_markdown`)."""
    from pencore.inputs.limits import limits_markdown

    return limits_markdown(group)


def plausible_table() -> str:
    """Plausible ranges and the slips they point to
    (:func:`pencore.inputs.limits.plausible_markdown`)."""
    from pencore.inputs.limits import plausible_markdown

    return plausible_markdown()


def speed_table() -> str:
    """The current speed figures (``benchmarks/speed_summary.py --markdown``)."""
    out = subprocess.run(
        [sys.executable, str(REPO / "benchmarks" / "speed_summary.py"), "--markdown"],
        check=True,
        capture_output=True,
        text=True,
        cwd=REPO,
    )
    return out.stdout.strip()


def _csv_table(path: Path, columns: dict[str, str], digits: int = 5) -> str:
    frame = pd.read_csv(path)
    lines = ["| " + " | ".join(columns.values()) + " |", "|" + "---|" * len(columns)]
    for _, row in frame.iterrows():
        lines.append("| " + " | ".join(_fmt(row[c], digits) for c in columns) + " |")
    return "\n".join(lines)


def convergence_table() -> str:
    """Each numerical parameter varied alone (``benchmarks/results/convergence.csv``)."""
    return _csv_table(
        BENCH / "convergence.csv",
        {
            "parameter": "parameter",
            "value": "value",
            "depth_280": "depth #2, 280 m/s (m)",
            "depth_280_vs_exact": "vs exact 1-D (m)",
            "path_45_1000": "path #2, 45 deg, 1000 m/s (m)",
            "turn_45_1000": "turning angle (deg)",
            "dev_p4_1000": "deviation #4, yaw 0.1 deg (deg)",
            "vcr_p2_45": "Vcr #2, 45 deg (m/s)",
        },
        6,
    )


def emulation_table() -> str:
    """Convergence of the paper-emulation numerics (``emulation_convergence.csv``)."""
    return _csv_table(
        BENCH / "emulation_convergence.csv",
        {
            "sweep": "sweep",
            "setting": "setting",
            "reference": "reference",
            "err_depth": "depth error (rel.)",
            "err_path": "path error (rel.)",
            "err_dev_deg": "deviation error (deg)",
            "err_depth_280": "depth 280 m/s error (rel.)",
            "steps": "steps",
        },
        3,
    )


def attribution_table() -> str:
    """Each attribution setting's disputed numbers (``benchmarks/results/attribution.csv``)."""
    from pencore.paper.claims import paper_values

    paper = paper_values()
    lo, hi = paper["vcr_p2_45_bracket"]
    alpha = paper["fig16_alpha_deg"]
    phi = paper["fig13_phi_deg"]
    depth = comparison()
    depth_280 = _row(
        depth, "Table 2 test 2: penetration depth (V=280 m/s, obliquity 0 deg, yaw 0 deg)"
    )["paper_value"]
    header = {
        "setting": "setting",
        "alpha_5": f"phi #2 5 rad/s (paper {_fmt(alpha[5.0])} deg)",
        "alpha_20": f"phi #2 20 rad/s (paper {_fmt(alpha[20.0])} deg)",
        "back_25": "turns back at 25 rad/s (paper: yes)",
        "vcr": f"Vcr (paper {_fmt(lo)}-{_fmt(hi)} m/s)",
        "depth_280": f"depth 280 m/s (paper {depth_280} m)",
        "phi_p4_280": f"phi #4 280 m/s (paper {_fmt(phi[280.0])} deg)",
        "phi_p4_1000": f"phi #4 1000 m/s (paper {_fmt(phi[1000.0])} deg)",
        "within_3pct_all": "all within 3 %",
    }
    return _csv_table(BENCH / "attribution.csv", header, 4)


def dataset_table() -> str:
    """Every variable and coordinate of a trajectory Dataset, with units and meaning."""
    import pencore

    ds = pencore.simulate("p2", "soil", 280.0)
    lines = ["| name | dims | units | meaning |", "|---|---|---|---|"]
    for name in list(ds.coords) + list(ds.data_vars):
        var = ds[name]
        dims = ", ".join(var.dims) or "(scalar)"
        unit = var.attrs.get("units", "")
        meaning = var.attrs.get("long_name", "")
        lines.append(f"| `{name}` | {dims} | {unit} | {meaning} |")
    return "\n".join(lines)


def dataset_attrs_table() -> str:
    """The run-level attributes of a trajectory Dataset."""
    import pencore

    ds = pencore.simulate("p2", "soil", 280.0)
    lines = ["| attribute | example (p2, soil, 280 m/s) |", "|---|---|"]
    for key, value in ds.attrs.items():
        text = str(value).replace("|", "/").replace("\n", " ")
        if len(text) > 80:
            text = text[:77] + "..."
        lines.append(f"| `{key}` | {text} |")
    return "\n".join(lines)


def duration(seconds: float) -> str:
    """A duration as a reader says it: ``46 s``, ``2.6 min``, ``1.5 h``."""
    if seconds < 100:
        return f"{seconds:.2g} s" if seconds < 10 else f"{seconds:.0f} s"
    if seconds < 6000:
        return f"{seconds / 60:.2g} min"
    return f"{seconds / 3600:.2g} h"


def fresh_installs() -> pd.DataFrame:
    """The fresh editable installs of ``install.csv`` on the newest commit measured with
    both installers (``pip``, ``uv``: the two are compared back to back), one row each."""
    install = pd.read_csv(BENCH / "install.csv")
    fresh = install[install["case"] == "fresh_editable_install"]
    both = [
        c
        for c, rows in fresh.groupby("commit", sort=False)
        if {"pip", "uv"} <= set(rows["installer"])
    ]
    if not both:
        raise SystemExit(
            "benchmarks/results/install.csv has no commit measured with both pip and uv: "
            "run python benchmarks/bench_install.py HEAD:pip HEAD:uv"
        )
    return (
        fresh[fresh["commit"] == both[-1]]
        .drop_duplicates("installer", keep="last")
        .set_index("installer")
    )


def timing_sentence() -> str:
    """The README's line on how long its two commands take, from the benchmarks, with the
    load each figure was measured at: idle-host figures say so, and a figure from a busy
    host says how busy (a busy host takes longer than the README's figures)."""
    speed = pd.read_csv(BENCH / "speed.csv").set_index("figure")
    compile_ = pd.read_csv(BENCH / "compile.csv").set_index("case")
    fresh = fresh_installs()
    repro = speed.loc["reproduction_wall"]
    cores = int(repro["cores"])
    loads = [
        float(fresh.loc["uv", "load_1min"]),
        float(fresh.loc["pip", "load_1min"]),
        float(compile_.loc["warmup", "load_1min"]),
        float(repro["load_1min"]),
    ]
    # the README's test command, timed by benchmarks/bench_tests.py (its newest row)
    tests = None
    if (BENCH / "tests.csv").exists():  # the newest run that passed: a time to expect
        runs = pd.read_csv(BENCH / "tests.csv")
        runs = runs[(runs["failed"] == 0) & (runs["errors"] == 0)]
        tests = runs.iloc[-1] if len(runs) else None
    busiest = max(loads)
    tests_load = 0.0
    if tests is not None:
        tests_load = max(float(tests["load_1min"]), float(tests["load_mean"]))
        files = "`install.csv`, `compile.csv`, `speed.csv`, `tests.csv`"
        other_cpu = tests["cpu_model"] != repro["cpu_model"]
        repro_and_tests = (
            f"the reproduction about {duration(repro['value'])} and the tests about "
            f"{duration(tests['wall_s'])}" + (f" on an {tests['cpu_model']}" if other_cpu else "")
        )
    else:
        files = "`install.csv`, `compile.csv`, `speed.csv`"
        repro_and_tests = f"the reproduction about {duration(repro['value'])}"
    if max(busiest, tests_load) <= cores:
        load = (
            f"These are idle-host figures (a 1-minute load of at most "
            f"{max(busiest, tests_load):.1f} on {cores} cores); a busy host takes longer."
        )
    elif busiest <= cores:
        load = (
            f"The install and reproduction figures are an idle host's (a 1-minute load of "
            f"at most {busiest:.1f} on {cores} cores), the tests' a busy one's (a mean load "
            f"of {tests_load:.1f}): an idle host runs them faster."
        )
    else:
        load = (
            f"They were measured at 1-minute loads of up to {max(busiest, tests_load):.1f} "
            f"on {cores} cores; an idle host is faster."
        )
    return (
        f"On {cores} cores ({repro['cpu_model']}) the install takes about "
        f"{duration(fresh.loc['uv', 'wall_s'])} with uv "
        f"({duration(fresh.loc['pip', 'wall_s'])} with pip), most of it the kernel compile "
        f"(about {duration(compile_.loc['warmup', 'wall_s'])}, "
        f"{duration(compile_.loc['warmup', 'cpu_s'])} of CPU), {repro_and_tests} "
        f"(`benchmarks/results/`: {files}; downloading the dependencies comes on top). "
        f"{load}"
    )


def numbers() -> dict[str, str]:
    """Single numbers for the prose (MyST substitutions), each read from its file."""
    table = comparison()
    out: dict[str, str] = {}

    def value(quantity: str, digits: int = 5) -> str:
        return _fmt(_row(table, quantity)["pencore_value"], digits)

    out["vcr_p2_45"] = value("Vcr of #2 at 45 deg obliquity (Fig. 7)", 6)
    out["vcr_p2_45_paper"] = _fmt(
        _row(table, "Vcr of #2 at 45 deg obliquity (Fig. 7)")["paper_value"], 5
    )
    out["depth_t2"] = value(
        "Table 2 test 2: penetration depth (V=280 m/s, obliquity 0 deg, yaw 0 deg)", 4
    )
    out["depth_t2_paper"] = _fmt(
        _row(table, "Table 2 test 2: penetration depth (V=280 m/s, obliquity 0 deg, yaw 0 deg)")[
            "paper_value"
        ]
    )
    out["table2_offset"] = _relative(
        _row(table, "Table 2 test 2: penetration depth (V=280 m/s, obliquity 0 deg, yaw 0 deg)")
    )
    out["alpha_20"] = value("Fig. 16: deviation alpha of #2, 1000 m/s, omega = 20 rad/s", 3)
    out["alpha_20_paper"] = _fmt(
        _row(table, "Fig. 16: deviation alpha of #2, 1000 m/s, omega = 20 rad/s")["paper_value"]
    )
    speed = pd.read_csv(BENCH / "speed.csv").set_index("figure")["value"]
    out["trajectory_ms"] = _fmt(speed["trajectory"], 3)
    out["reproduction_wall_s"] = _fmt(speed["reproduction_wall"], 2)
    compile_ = pd.read_csv(BENCH / "compile.csv").set_index("case")["cpu_s"]
    out["warmup_s"] = _fmt(compile_["warmup"], 2)
    out["reproduction_wall"] = duration(speed["reproduction_wall"])
    out["warmup_cpu"] = duration(compile_["warmup"])
    fresh = fresh_installs()["wall_s"]
    out["install_uv"], out["install_pip"] = duration(fresh["uv"]), duration(fresh["pip"])
    out["comparison_counts"] = comparison_counts()
    out.update(concrete_numbers())
    out.update(compilation_numbers())
    out.update(record_numbers())
    from pencore.inputs import gate
    from pencore.inputs.numerics import DEFAULT_MAX_WALL

    out["yaml_mib"] = _fmt(gate.MAX_YAML_BYTES / 2**20)
    out["yaml_depth"] = str(gate.MAX_YAML_DEPTH)
    out["yaml_nodes"] = f"{gate.MAX_YAML_NODES:,}".replace(",", " ")
    out["max_quote"] = str(gate.MAX_QUOTE)
    out["max_wall_s"] = _fmt(DEFAULT_MAX_WALL)
    from pencore.studies.common import MAX_AXIS_POINTS, MAX_SEARCHES

    out["max_searches"] = str(MAX_SEARCHES)
    out["max_axis_points"] = str(MAX_AXIS_POINTS)
    from pencore.integrators.scipy_ivp import CALLS_PER_STEP

    out["scipy_calls_per_step"] = str(CALLS_PER_STEP)
    import pencore
    from pencore.inputs.numerics import Numerics

    out["max_travel_m"] = _fmt(Numerics().max_travel)
    from pencore.inputs.numerics import CREEP_FACTOR

    out["creep_factor"] = _fmt(CREEP_FACTOR)
    out["band_p2_mm"] = _fmt(1e3 * pencore.prepare("p2", "soil").band_length, 2)
    from pencore import analysis

    out["deviation_speed_percent"] = _fmt(100 * analysis.DEFAULT_SPEED_FRACTION)
    out["turning_bracket_percent"] = _fmt(100 * analysis.DEFAULT_BRACKET_FRACTION)
    import json

    import yaml

    repro = json.loads((BENCH / "reproduction.json").read_text())
    cases = yaml.safe_load((REPO / "config" / "config.yaml").read_text())["ensemble"]["cases"]
    n = sum(int(c["n_samples"]) for c in cases)
    out["ensemble_n"] = str(n)
    out["ensemble_wall_s"] = _fmt(repro["group_wall_sum_s"]["ensemble"], 3)
    out["ensemble_ms_per_sample"] = _fmt(1e3 * repro["group_wall_sum_s"]["ensemble"] / n, 2)
    out.update(search_cost_numbers())
    return out


def search_cost_numbers() -> dict[str, str]:
    """Where the reproduction's threshold searches spend their time
    (``benchmarks/results/search_cost.json``, ``benchmarks/search_cost.py``)."""
    import json

    cost = json.loads((BENCH / "search_cost.json").read_text())
    every = cost["by_group"]["all"]
    return {
        "search_commit": cost["commit"],
        "search_count": str(cost["n_searches"]),
        "search_total_s": _fmt(every["total_s"], 3),
        "search_scan_s": _fmt(every["ends_scan_s"], 3),
        "search_wide_s": _fmt(every["wide_s"], 3),
        "search_narrow_s": _fmt(every["narrow_s"], 3),
        "search_narrow_tol": str(cost["narrow_tolerances"]),
        "search_job_sum_s": _fmt(cost["job_wall_sum_s"], 3),
        "search_floor_sum_s": _fmt(cost["without_scan_and_wide_s"], 3),
        "search_floor_wall_s": _fmt(cost["wall_floor_s"], 3),
        "search_near_surface_s": _fmt(cost["by_group"]["near_surface"]["total_s"], 3),
        "search_near_surface_narrow_s": _fmt(cost["by_group"]["near_surface"]["narrow_s"], 3),
        "search_narrow_mean_ms": _fmt(1e3 * every["narrow_s"] / every["narrow_n"], 2),
        "search_other_mean_ms": _fmt(
            1e3
            * (every["ends_scan_s"] + every["wide_s"])
            / (every["ends_scan_n"] + every["wide_n"]),
            2,
        ),
    }


ARCHIVE = REPO / "results" / "archive"


def open_archive(path: Path, study: str) -> Any:
    """The archived dataset at ``path``, opened, when it holds ``study`` (its ``study``
    attribute); another study's dataset (a valid netCDF in the wrong place) stops the
    build with one line naming the file and both studies, not a ``KeyError`` on a
    variable it lacks."""
    import xarray as xr

    ds = xr.open_dataset(path)
    found = ds.attrs.get("study")
    if found != study:
        ds.close()
        raise ValueError(
            f"{path.relative_to(REPO)} holds the study {found!r}, not {study!r}; "
            "remake it with `python -m snakemake --cores 2 archive`"
        )
    return ds


def attribution_mass_text() -> str:
    """The mass-distribution settings of the archived attribution study
    (``results/archive/attribution/attribution.nc``): a table, the inverse step with its
    out-of-fit verdicts, and the spread of the buildable bodies."""
    from pencore.paper.claims import disputed_values

    paper = disputed_values()
    with open_archive(ARCHIVE / "attribution" / "attribution.nc", "attribution") as ds:
        groups = [str(g) for g in ds["group"].values]
        names = [str(n) for n in ds["setting"].values]
        rows = [
            i for i, g in enumerate(groups) if g == "mass distribution" or names[i] == "default"
        ]
        head = (
            "| setting | body of #2 | Lc/L | I_t (kg m^2) | buildable #2 / #4 "
            "| alpha 5 rad/s (deg) "
            "| alpha 20 | alpha 25 | turns back at 25 | Vcr (m/s) | depth 280 (m) "
            "| phi #4 280 / 1000 (deg) | Fig. 12 falls |"
        )
        lines = [head, "|" + "---|" * 13]
        paper_row = (
            f"| paper | | 0.525 | | | {_fmt(paper['alpha'][5.0])} | {_fmt(paper['alpha'][20.0])} "
            f"| | yes | {_fmt(paper['vcr_bracket'][0])}-{_fmt(paper['vcr_bracket'][1])} "
            f"| {_fmt(paper['depth_280'])} | {_fmt(paper['phi_p4'][280.0])} / "
            f"{_fmt(paper['phi_p4'][1000.0])} | yes |"
        )
        lines.append(paper_row)
        for i in rows:
            d = ds.isel(setting=i)
            a = d["alpha"].values
            lines.append(
                f"| {d['label'].item()} | {d['body_description'].item()} "
                f"| {_fmt(float(d['body_lc_over_l']), 4)} "
                f"| {_fmt(float(d['body_i_transverse']), 3)} "
                f"| {'yes' if int(d['body_buildable']) else 'no'} / "
                f"{'yes' if int(d['body_p4_buildable']) else 'no'} "
                f"| {_fmt(a[0], 3)} | {_fmt(a[1], 3)} | {_fmt(a[2], 3)} "
                f"| {'yes' if bool(d['turned_back'].values[2]) else 'no'} "
                f"| {_fmt(float(d['value_vcr']), 4)} | {_fmt(float(d['value_depth_280']), 3)} "
                f"| {_fmt(float(d['value_phi_p4_280']), 3)} / "
                f"{_fmt(float(d['value_phi_p4_1000']), 3)} "
                f"| {'yes' if float(d['value_fig12_falls']) else 'no'} |"
            )
        built = [i for i in rows if names[i] != "default" and int(ds["body_buildable"].values[i])]
        a20 = ds["alpha"].sel(omega=20.0).values
        back = ds["turned_back"].sel(omega=25.0).values
        spread = (
            f"\n\nThe {len(built)} buildable bodies give alpha at 20 rad/s from "
            f"{_fmt(min(a20[built]), 3)} to {_fmt(max(a20[built]), 3)} deg (paper "
            f"{_fmt(paper['alpha'][20.0])}); "
            + (
                "none turns back at 25 rad/s."
                if not back[built].any()
                else "some turn back at 25 rad/s: "
                + ", ".join(names[i] for i in built if back[i])
                + "."
            )
        )
        fit = [i for i in range(len(names)) if str(ds["fitted_to"].values[i])]
        text = ""
        if fit:
            d = ds.isel(setting=fit[0])
            oc = d["omega_c_p2"].values
            vel = d["omega_c_velocity"].values
            falls_v = bool(all(oc[k + 1] < oc[k] for k in range(len(oc) - 1)))
            oc3 = float(d["omega_c_p3_1000"])
            oc2 = float(oc[list(vel).index(1000.0)])

            def rel(key: str) -> str:
                return f"{float(d[f'rel_{key}']):+.0%}"

            text = (
                f"\n\n**The inverse step** (`{names[fit[0]]}`, fitted to "
                f"{str(d['fitted_to'].item()).replace(';', ' and ')}): Lc/L of #2 "
                f"{_fmt(float(d['fitted_lc_over_l']), 4)} (Table 3: 0.525) and a transverse "
                f"inertia {_fmt(float(d['fitted_i_transverse_factor']), 3)} times the solid "
                f"body's ({_fmt(float(d['body_i_transverse']), 3)} kg m^2) give alpha "
                f"{_fmt(float(d['alpha'].sel(omega=20.0)), 3)} deg at 20 rad/s and "
                f"{'a turn-back' if bool(d['turned_back'].sel(omega=25.0)) else 'no turn-back'} "
                f"at 25 rad/s. It is {'' if int(d['body_buildable']) else 'not '}"
                "a body that could be built"
                f" ({d['body_description'].item()}). On the numbers it was not fitted to: "
                f"alpha at 5 rad/s {_fmt(float(d['value_alpha_5']), 3)} deg ({rel('alpha_5')}), "
                f"Vcr {_fmt(float(d['value_vcr']), 4)} m/s ({rel('vcr')}), the Table 2 depth "
                f"{_fmt(float(d['value_depth_280']), 3)} m ({rel('depth_280')}), phi of #4 "
                f"{_fmt(float(d['value_phi_p4_280']), 3)} / "
                f"{_fmt(float(d['value_phi_p4_1000']), 3)} deg "
                f"({rel('phi_p4_280')} / {rel('phi_p4_1000')}), Vcr at 30 deg "
                f"{'falls' if float(d['value_fig12_falls']) else 'does not fall'} with yaw "
                f"(Fig. 12); omega_c {', '.join(_fmt(x, 3) for x in oc)} rad/s at "
                f"{', '.join(_fmt(v) for v in vel)} m/s "
                f"({'falls' if falls_v else 'does not fall'} with the speed, Figs 17-18) and "
                f"{_fmt(oc3, 3)} rad/s for #3 with the same recipe against {_fmt(oc2, 3)} for "
                f"#2 ({'falls' if oc3 < oc2 else 'does not fall'} with Lc/L, Fig. 18)."
            )
        return "\n".join(lines) + spread + text


def ballistic_limit_table() -> str:
    """Archived ballistic limits against plate thickness and obliquity (m/s)."""

    with open_archive(
        ARCHIVE / "perforation" / "ballistic_limit.nc", "perforation/ballistic_limit"
    ) as ds:
        obl = [f"{o:g} deg" for o in ds.obliquity.values]
        lines = [
            "| thickness (m) | " + " | ".join(obl) + " |",
            "|---|" + "---|" * len(obl),
        ]
        for i, t in enumerate(ds.thickness.values):
            cells = [_fmt(v, 4) for v in ds.v_bl.values[i]]
            lines.append(f"| {t:g} | " + " | ".join(cells) + " |")
        caption = (
            f"\n\nProjectile {ds.attrs['projectile']} into slabs of the "
            f"{ds.attrs['medium']} law, crater {ds.attrs['crater_depth_calibers']:g} and free "
            f"surface {ds.attrs['free_surface_depth_calibers']:g} calibers; ballistic limit "
            "in m/s (midpoint of the bracket; `results/archive/perforation/ballistic_limit.nc`)."
        )
    return "\n".join(lines) + caption


def residual_velocity_text() -> str:
    """The archived residual-velocity study's Recht-Ipson fit, in one paragraph."""

    with open_archive(
        ARCHIVE / "perforation" / "residual_velocity.nc", "perforation/residual_velocity"
    ) as ds:
        a = ds.attrs
        v = ds.velocity.values
        return (
            f"Residual velocity of {a['projectile']} through a {a['thickness_m']:g} m slab "
            f"of {a['medium']}, obliquity {a['obliquity_deg']:g} deg, impact speeds "
            f"{v.min():g}-{v.max():g} m/s (`results/archive/perforation/"
            f"residual_velocity.nc`): with the searched ballistic limit "
            f"{_fmt(a['v_bl_m_s'], 4)} m/s, the Recht-Ipson fit gives "
            f"a = {_fmt(a['recht_ipson_a'], 3)}, p = {_fmt(a['recht_ipson_p'], 3)} (RMS "
            f"{_fmt(a['recht_ipson_rms_m_s'], 2)} m/s); the rigid-body values a = 1, p = 2 "
            f"miss by {_fmt(a['recht_ipson_rigid_rms_m_s'], 2)} m/s RMS."
        )


def _validation_summary():  # noqa: ANN202 (pandas.DataFrame)
    """The validation summary of the archive (:func:`pencore.studies.validation.measurements.
    summary_table` over the archived measurements and obliquity ratios)."""
    from pencore.studies.validation.measurements import summary_table

    with (
        open_archive(ARCHIVE / "validation" / "measurements.nc", "validation/measurements") as m,
        open_archive(ARCHIVE / "near_surface" / "obliquity_ratio.nc", "near_surface/ratio") as r,
    ):
        return summary_table(m.load(), r.load())


def _pct(x: float) -> str:
    return f"{100 * x:+.1f} %" if x == x else "-"  # NaN: no shot


def measurements_table() -> str:
    """The validation summary: every measurement, per data set, law and model."""
    lines = [
        "| data set | law | model | n | left out | mean abs(e) | bias | worst |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for _, r in _validation_summary().iterrows():
        lines.append(
            f"| {r['data_set']} | {r['law']} | {r['model']} | {r['n']} | {r['n_left_out']} | "
            f"{_pct(r['mean_abs_rel_error']).lstrip('+')} | {_pct(r['bias'])} | "
            f"{_pct(r['worst'])} |"
        )
    return "\n".join(lines)


def _concrete_summary():  # noqa: ANN202 (pandas.DataFrame)
    """The validation summary's rows of the body shot sets (the concrete family): the data
    sets named after a set of their file, not after the file's entry (the shot's prefix)."""
    t = _validation_summary()
    with open_archive(ARCHIVE / "validation" / "measurements.nc", "validation/measurements") as m:
        entry = [str(s).split(":", 1)[0] for s in m["shot"].values]
        body = {str(d) for d, e in zip(m["dataset"].values, entry, strict=True) if str(d) != e}
    return t[t["data_set"].isin(body)]


def concrete_table() -> str:
    """pencore and Forrestal's closed form on every concrete set, per law: bias and mean
    abs(e) of the rigid-as-compiled shots (the full rows are in the validation summary)."""
    t = _concrete_summary()
    models = {
        "pencore": "pencore (3-D",
        "Forrestal": "Forrestal's closed form",
    }
    lines = [
        "| set | n | S(fc): pencore bias, mean abs(e) | S(fc): Forrestal's form | "
        "S = 21: pencore | S = 21: Forrestal's form |",
        "|---|---|---|---|---|---|",
    ]
    for ds in dict.fromkeys(t["data_set"]):
        cells = []
        n = "-"
        for law in ("s_of_fc", "paper_s21"):
            for prefix in models.values():
                r = t[(t["data_set"] == ds) & (t["law"] == law) & t["model"].str.startswith(prefix)]
                if r.empty:
                    cells.append("-")
                    continue
                r = r.iloc[0]
                n = str(r["n"])
                mean = _pct(r["mean_abs_rel_error"]).lstrip("+")
                cells.append(f"{_pct(r['bias'])}, {mean}")
        lines.append(f"| {ds} | {n} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def concrete_numbers() -> dict[str, str]:
    """Single numbers of the grout shots (Fig. 5's concrete points) for the prose: the
    paper's law (S = 21), pencore in 3-D, per nose, and at the fastest CRH 3 shot."""
    out: dict[str, str] = {}
    with open_archive(ARCHIVE / "validation" / "measurements.nc", "validation/measurements") as m:
        m = m.load()
    for tag, crh in (("3", "crh3"), ("4p25", "crh4.25")):
        sel = (m["dataset"] == f"forrestal1996_d12.9_{crh}_fc13.5") & (m["target"] == "paper_s21")
        e = m["rel_error"].values[sel.values]
        out[f"grout_crh{tag}_bias"] = _pct(float(e.mean()))
        out[f"grout_crh{tag}_range"] = f"{_pct(float(e.min()))} to {_pct(float(e.max()))}"
        if tag == "3":
            v = m["velocity"].values[sel.values]
            out["grout_crh3_fastest_v"] = _fmt(float(v.max()), 4)
            out["grout_crh3_fastest_e"] = _pct(float(e[v.argmax()]))
    for law, key, fmt in (
        ("aluminium", "al_ogive_table1_bias", "{:+.0f} %"),
        ("aluminium_3term", "al_ogive_3term_bias", "{:+.1f} %"),
        ("aluminium_cavity", "al_ogive_cavity_bias", "{:+.1f} %"),
    ):
        sel = m["dataset"] == "piekutowski_1999_ogive"
        sel = sel & (m["target"] == law) & (m["rigid"] == 1)
        out[key] = fmt.format(100 * float(m["rel_error"].values[sel.values].mean()))
    return out


def compilation_reasons_table() -> str:
    """The concrete compilation's reasons (:mod:`pencore.measured.compilation`): per code,
    the rows that carry it and those set aside for it alone, with its meaning."""
    from pencore.measured import compilation as comp

    df = comp.read_compilation()
    counts = comp.reason_counts(df)
    clean = int((df["status"] == "clean").sum())
    lines = [
        "| reason | rows | rows for it alone | meaning |",
        "|---|---|---|---|",
        f"| (clean) | {clean} | | every number present, no reason below |",
    ]
    for code, r in counts.iterrows():
        lines.append(f"| `{code}` | {r['rows']} | {r['only']} | {r['text']} |")
    lines.append(f"| all rows | {len(df)} | | |")
    return "\n".join(lines)


def compilation_sources_table() -> str:
    """The concrete compilation per compiler's key: the reference it cites, the rows and the
    clean rows, the compilation's numbers."""
    from pencore.measured import compilation as comp

    df = comp.read_compilation()
    cited = dict(zip(df["reference_number"], df["reference"], strict=True))
    lines = ["| key | references cited | rows | clean | Numbers |", "|---|---|---|---|---|"]
    for key, r in comp.source_counts(df).iterrows():
        # each reference by its authors and year (the text before its title)
        refs = "; ".join(
            f"[{n}] {cited[int(n)].split('. ')[0]}" for n in r["references"].split(", ")
        )
        lines.append(
            f"| {key} | {refs} | {r['rows']} | {r['clean']} | {r['first_row']}-{r['last_row']} |"
        )
    return "\n".join(lines)


def compilation_duplicates_table() -> str:
    """The concrete compilation's duplicates: per compiler's key of the row set aside and
    of the row kept, the number of shots the two quote alike."""
    from pencore.measured import compilation as comp

    df = comp.read_compilation()
    key = dict(zip(df["row"], df["reference_key"], strict=True))
    dup = df[df["same_shot_as"].notna()]
    pairs = pd.Series(
        [(key[int(k)], r) for k, r in zip(dup["same_shot_as"], dup["reference_key"], strict=True)]
    ).value_counts(sort=False)
    lines = ["| kept (key) | set aside as its duplicate (key) | shots |", "|---|---|---|"]
    for (kept, other), n in sorted(pairs.items(), key=lambda kv: (-kv[1], kv[0])):
        lines.append(f"| {kept} | {other} | {n} |")
    return "\n".join(lines)


def compilation_numbers() -> dict[str, str]:
    """Counts of the concrete compilation for the prose."""
    from pencore.measured import compilation as comp

    df = comp.read_compilation()
    raw = sum(len(comp.parse_raw_cells(t)) for t in df["raw_cells"])
    series = comp.read_series()
    return {
        "compilation_rows": str(len(df)),
        "compilation_references": str(df["reference_number"].nunique()),
        "compilation_keys": str(df["reference_key"].nunique()),
        "compilation_clean": str(int((df["status"] == "clean").sum())),
        "compilation_text_cells": str(raw),
        "compilation_series": str(series["series"].nunique()),
        "compilation_series_rows": str(len(series)),
        "compilation_errata": str(len(comp.read_errata())),
    }


def _record():  # noqa: ANN202 (xarray.Dataset, xarray.Dataset)
    """The archived concrete record and its statistics."""
    with open_archive(
        ARCHIVE / "validation" / "concrete_record.nc", "validation/concrete_record"
    ) as d:
        ds = d.load()
    with open_archive(
        ARCHIVE / "validation" / "concrete_record_stats.nc", "validation/concrete_record_stats"
    ) as s:
        stats = s.load()
    return ds, stats


def _law_label(law: str) -> str:
    from pencore.inputs.record import DEFAULT_RECORD_LAW, RECORD_LAWS

    if law not in RECORD_LAWS:
        return law
    o = RECORD_LAWS[law]
    text = f"S {o['s_model']}, crater {o['crater']}, size term {o['size_term']}"
    return f"`{law}` ({text})" + (" **default**" if law == DEFAULT_RECORD_LAW else "")


def record_laws_table() -> str:
    """Every scored model on the held-out rows: count, median error, median and mean abs(e),
    the share within 25 %, and the depth band's calibration."""
    ds, st = _record()
    lines = [
        "| law or closed form | held-out shots | median e | median abs(e) | mean abs(e) | "
        "within 25 % | all clean: median e | band's level | band held |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for m in st["model"].values.astype(str):
        h = st.sel(model=m, rows="held_out")
        a = st.sel(model=m, rows="all_clean")
        if str(st["kind"].sel(model=m).values) == "solver":
            lvl = f"{float(st['nominal_level'].sel(model=m)):.2f}"
            held = f"{100 * float(st['held_out_coverage'].sel(model=m)):.0f} %"
        else:
            lvl = held = "-"
        lines.append(
            f"| {_law_label(m)} | {int(h['overall_n'])} | {_pct(float(h['overall_median_error']))} "
            f"| {_pct(float(h['overall_median_abs_error'])).lstrip('+')} "
            f"| {_pct(float(h['overall_mean_abs_error'])).lstrip('+')} "
            f"| {100 * float(h['overall_within']):.0f} % "
            f"| {_pct(float(a['overall_median_error']))} | {lvl} | {held} |"
        )
    return "\n".join(lines)


def _record_bins(quantity: str, stat: str = "median_error") -> str:
    _, st = _record()
    bins = [str(b) for b in st[f"{quantity}_bin"].values]
    n = st[f"{quantity}_n"].isel(model=0).values
    lines = [
        "| law or closed form | "
        + " | ".join(f"{b} ({int(k)})" for b, k in zip(bins, n, strict=True))
        + " |",
        "|---|" + "---|" * len(bins),
    ]
    for m in st["model"].values.astype(str):
        v = st[f"{quantity}_{stat}"].sel(model=m).values
        cells = ["-" if not math.isfinite(x) else _pct(float(x)) for x in v]
        lines.append(f"| `{m}` | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def record_diameter_table() -> str:
    """Median error per diameter bin over the held-out rows (count in the header)."""
    return _record_bins("diameter")


def record_speed_table() -> str:
    """Median error per striking-speed bin over the held-out rows."""
    return _record_bins("speed")


def record_regime_table() -> str:
    """The rigid-regime criterion on the record: rows kept and flagged, clean and eroding,
    with the default law's median error."""
    from pencore.inputs.record import DEFAULT_RECORD_LAW

    _, st = _record()
    lines = ["| rows | shots | median e (default law) | within 25 % |", "|---|---|---|---|"]
    for g in st["regime"].values.astype(str):
        r = st.sel(model=DEFAULT_RECORD_LAW, regime=g)
        n = int(r["regime_n"])
        if n == 0:
            lines.append(f"| {g} | 0 | - | - |")
            continue
        lines.append(
            f"| {g} | {n} | {_pct(float(r['regime_median_error']))} "
            f"| {100 * float(r['regime_within']):.0f} % |"
        )
    return "\n".join(lines)


def record_numbers() -> dict[str, str]:
    """Single numbers of the concrete record for the prose and the README."""
    from pencore.inputs.record import DEFAULT_RECORD_LAW

    ds, st = _record()
    h = st.sel(rows="held_out")
    d = h.sel(model=DEFAULT_RECORD_LAW)
    f = h.sel(model="forrestal")
    big = st.sel(diameter_bin=str(st["diameter_bin"].values[-1]))
    band = st.sel(model=DEFAULT_RECORD_LAW)
    return {
        "record_scored": str(ds.sizes["shot"]),
        "record_clean": str(int((ds["group"] == "clean").sum())),
        "record_eroding": str(int((ds["group"] == "eroding").sum())),
        "record_held_out": str(int(d["overall_n"])),
        "record_sources_held_out": str(
            len(set(ds["source"].values[ds["held_out"].values.astype(bool)]))
        ),
        "record_best": DEFAULT_RECORD_LAW,
        "record_best_within": f"{100 * float(d['overall_within']):.0f} %",
        "record_best_median_abs": f"{100 * float(d['overall_median_abs_error']):.1f} %",
        "record_forrestal_within": f"{100 * float(f['overall_within']):.0f} %",
        "record_forrestal_median_abs": f"{100 * float(f['overall_median_abs_error']):.1f} %",
        "record_big_forrestal": _pct(float(big["diameter_median_error"].sel(model="forrestal"))),
        "record_big_best": _pct(float(big["diameter_median_error"].sel(model=DEFAULT_RECORD_LAW))),
        "record_big_n": str(int(big["diameter_n"].sel(model="forrestal"))),
        "record_band_held": f"{100 * float(band['held_out_coverage']):.0f} %",
        "record_band_level": f"{float(band['nominal_level']):.2f}",
        "record_band_uncalibrated": f"{100 * float(band['coverage_at_stated']):.0f} %",
        "record_loses": str(st.attrs["best_law_loses"]) or "no bin",
    }


def record_headline() -> str:
    """The README's rows of the concrete record: each concrete law on the held-out sources."""
    _, st = _record()
    lines = [
        "| concrete law (`law: concrete` options) | held-out shots | median error | "
        "within 25 % | 80 % band held |",
        "|---|---|---|---|---|",
    ]
    for m in st["model"].values.astype(str):
        if str(st["kind"].sel(model=m).values) != "solver":
            continue
        h = st.sel(model=m, rows="held_out")
        lines.append(
            f"| {_law_label(m)} | {int(h['overall_n'])} | {_pct(float(h['overall_median_error']))} "
            f"| {100 * float(h['overall_within']):.0f} % "
            f"| {100 * float(st['held_out_coverage'].sel(model=m)):.0f} % |"
        )
    return "\n".join(lines)


def validation_headline() -> str:
    """The README's table of pencore against measured depths: pencore's 3-D run, one row
    per data file (config entry) and law with a rigid shot, its rigid shots pooled (a body
    shot table's sets in one row; the docs' measurements page has every set and the data
    files with no rigid shot)."""
    from pencore.analysis.errors import summary_statistics

    with open_archive(ARCHIVE / "validation" / "measurements.nc", "validation/measurements") as m:
        m = m.load()
    entry = [str(s).split(":", 1)[0] for s in m["shot"].values]
    law = [str(t) for t in m["target"].values]
    rigid = m["rigid"].values.astype(bool)
    rel = m["rel_error"].values
    lines = [
        "| measured shots | law | shots compared | bias | mean abs(e) |",
        "|---|---|---|---|---|",
    ]
    for e, t in dict.fromkeys(zip(entry, law, strict=True)):
        sel = [a == e and b == t for a, b in zip(entry, law, strict=True)]
        st = summary_statistics(rel[sel & rigid])
        if not st["n"]:
            continue  # every rod deformed: nothing to compare (the docs list the file)
        n_out = int((sel & ~rigid).sum())
        mean = _pct(st["mean_abs_rel_error"]).lstrip("+")
        lines.append(f"| {e} | {t} | {st['n']} (+{n_out} deformed) | {_pct(st['bias'])} | {mean} |")
    return "\n".join(lines)


def _stats_table(ds, rows_dim: str, group_dim: str) -> str:  # noqa: ANN001 (xarray.Dataset)
    lines = [
        f"| {rows_dim} | {group_dim} | n | mean error | 95 % interval | RMS | largest |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in ds[rows_dim].values:
        for g in ds[group_dim].values:
            st = ds.sel({rows_dim: r, group_dim: g})
            n = float(st["stat_n"]) if "stat_n" in st else float("nan")
            if not n > 0:
                continue

            def pct(name: str, st=st) -> str:  # noqa: ANN001
                return f"{100 * float(st[name]):+.1f} %"

            lines.append(
                f"| {r} | {g} | {n:.0f} | {pct('stat_mean_rel_error')} | "
                f"{pct('stat_ci95_lo')} to {pct('stat_ci95_hi')} | "
                f"{pct('stat_rms_rel_error')[1:]} | {pct('stat_max_abs_rel_error')[1:]} |"
            )
    return "\n".join(lines)


def measurement_options_table() -> str:
    """Error statistics of every measured shot under each near-surface option set."""

    with open_archive(
        ARCHIVE / "validation" / "measurements_options.nc", "validation/measurements_options"
    ) as ds:
        return _stats_table(ds.load(), "option", "group")


def obliquity_ratio_table() -> str:
    """Measured obliquity ratios V_bl(theta)/V_bl(0) against each model's."""

    with open_archive(ARCHIVE / "near_surface" / "obliquity_ratio.nc", "near_surface/ratio") as ds:
        return _stats_table(ds.load(), "model", "material_class")


def map_mesh_check(ds: Any) -> Any:
    """The archived ring-mesh check of the archived map ``ds`` (rule ``near_surface_mesh``,
    ``pencore.studies.perforation.mesh_check``): its default-mesh limits must be the
    archive's map, or the check is of another map and the build stops saying so."""
    import numpy as np

    path = ARCHIVE / "near_surface" / "mesh_check.nc"
    with open_archive(path, "near_surface/mesh_check") as check:
        check = check.load()
    a, b = ds.v_bl.values, check.v_bl.transpose(*ds.v_bl.dims).values
    same = (np.isnan(a) & np.isnan(b)) | (np.abs(a - b) <= 1e-9 * np.maximum(1.0, np.abs(a)))
    if not same.all() or list(check.option.values) != list(ds.option.values):
        raise ValueError(
            f"{path.relative_to(REPO)} is the check of another map than the archived "
            "ballistic_map.nc: refresh the archive (snakemake archive)"
        )
    return check


def ballistic_map_table() -> str:
    """The archived ballistic-limit map: V_bl (m/s) and its ratio to normal incidence,
    one table per near-surface option, with the line-of-sight rule; cells that twice the
    rings move by more than the search tolerance, or where a search failed, are marked
    with their reason (:func:`map_mesh_check`)."""
    import numpy as np

    with open_archive(ARCHIVE / "near_surface" / "ballistic_map.nc", "near_surface/map") as ds:
        ds = ds.load()
    check = map_mesh_check(ds)
    tol = float(check.attrs["search_tol_m_s"])
    factor = float(check.attrs["mesh_factor"])
    obl = ds.obliquity.values
    head = "| t/d | " + " | ".join(f"{o:g} deg" for o in obl) + " |"
    out = []
    n_bad = 0
    for option in ds.option.values:
        m = ds.sel(option=option)
        c = check.sel(option=option)
        out += [
            f"**{option}** (V_bl in m/s, [ratio to 0 deg])",
            "",
            head,
            "|---|" + "---|" * len(obl),
        ]
        notes = []
        for i, t in enumerate(ds.t_over_d.values):
            cells = []
            for j, o in enumerate(obl):
                v, r = float(m.v_bl.values[i, j]), float(m.ratio.values[i, j])
                cell = "failed" if np.isnan(v) else f"{v:.0f} [{r:.2f}]"
                reason = str(c.reason.sel(t_over_d=t, obliquity=o).values)
                if reason:
                    n_bad += 1
                    cell += " \\*"
                    notes.append(f"t/d {t:g} at {o:g} deg: {reason}")
                cells.append(cell)
            out.append(f"| {t:g} | " + " | ".join(cells) + " |")
        out.append("")
        if notes:
            out += ["\\* Not converged in the ring mesh: " + "; ".join(notes) + ".", ""]
    sec = " ".join(f"{1 / np.cos(np.radians(o)):.3f}" for o in obl)
    out.append(f"Line-of-sight rule, sec(obliquity): {sec}.")
    out.append("")
    out.append(
        f"Ring-mesh check (rule `near_surface_mesh`, archived as "
        f"`results/archive/near_surface/mesh_check.nc`): every search again on {factor:g}x "
        f"the rings ({int(check.attrs['n_nose_fine'])} nose rings against "
        f"{int(check.attrs['n_nose'])}); {int(check.attrs['n_converged'])} of the "
        f"{int(check.attrs['n_cells'])} cells agree within the search tolerance ({tol:g} m/s)"
        + (
            f", and the {n_bad} marked \\* do not (their reasons above): keep their numbers "
            "out of any conclusion."
            if n_bad
            else "."
        )
    )
    return "\n".join(out)


def layers_table() -> str:
    """The package's layers, top first, as ``pyproject.toml``'s import contract lists them."""
    import tomllib

    config = tomllib.loads((REPO / "pyproject.toml").read_text())["tool"]["importlinter"]
    contract = next(
        c for c in config["contracts"] if c["type"] == "layers" and "containers" not in c
    )
    lines = ["| layer (top first) | modules |", "|---|---|"]
    for i, layer in enumerate(contract["layers"], 1):
        names = ", ".join(f"`{m.strip()}`" for m in layer.split("|"))
        lines.append(f"| {i} | {names} |")
    return "\n".join(lines)


def config_reference_page() -> str:
    """Every workflow configuration key (:mod:`pencore.workflowconfig.config_reference`), its
    title dropped to sit under the page's own."""
    from pencore.workflowconfig.config_reference import config_reference

    return config_reference(REPO).split("\n", 1)[1].strip()


#: The reproduced figures the results pages show, drawn from the archive (no run):
#: (figure kind of :data:`pencore.plotting.PLOTS`, archived file, its study, the paper's
#: figure, the text that finds its rows in the comparison table).
FIGURES = (
    ("table2", "validation/table2.nc", "validation/table2", "Table 2", "Table 2 test"),
    ("fig5", "validation/fig5.nc", "validation/fig5", "Fig. 5", "Fig. 5"),
    ("fig7", "fig7/trajectories.nc", "section4/fig7", "Fig. 7", "Fig. 7"),
    ("fig8", "fig8/vcr.nc", "section4/fig8", "Fig. 8", "Fig. 8"),
    ("fig9", "fig9/turning_angle.nc", "section4/fig9", "Fig. 9", "Fig. 9"),
    ("fig11", "fig11/trajectories.nc", "section4/fig11", "Fig. 11", "Fig. 11"),
    ("fig12", "fig12/vcr_yaw.nc", "section4/fig12", "Fig. 12", "Fig. 12"),
    ("fig13", "fig13/trajectories.nc", "section4/fig13", "Fig. 13", "Fig. 13"),
    ("fig15", "fig15/vci.nc", "section4/fig15", "Fig. 15", "Fig. 15"),
    ("fig16", "fig16/trajectories.nc", "section4/fig16", "Fig. 16", "Fig. 16"),
    ("start_height", "fig16/start_height.nc", "section4/start_height", "Figs 16-17 (start "
     "height)", "Start-height"),
    ("fig18", "fig18/omega_c.nc", "section4/fig18", "Fig. 18", "omega_c of"),
)  # fmt: skip


def figures_page(target: Path = GENERATED) -> str:
    """The reproduced figures, drawn from ``results/archive`` into
    ``docs/_generated/figures/`` (PNG), each with the paper's numbers for it beside
    pencore's (the archived comparison's rows that name it)."""
    from pencore.plotting import PLOTS
    from pencore.plotting.style import save_figure

    table = comparison()
    out = target / "figures"
    out.mkdir(parents=True, exist_ok=True)
    lines = []
    for kind, path, study, label, key in FIGURES:
        with open_archive(ARCHIVE / path, study) as ds:
            fig = PLOTS[kind](ds)
        png = out / f"{kind}.png"
        save_figure(fig, png, dpi=90)
        lines += [
            f"## {label}",
            "",
            f"![pencore's {label}, drawn from results/archive/{path}](../_generated/figures/"
            f"{kind}.png)",
            "",
            f"*Drawn from `results/archive/{path}` (study `{study}`).*",
            "",
        ]
        rows = table[table["quantity"].str.contains(key, regex=False)]
        if len(rows):
            lines += ["| quantity | paper | pencore | units |", "|---|---|---|---|"]
            for _, row in rows.iterrows():
                cells = [
                    row["quantity"],
                    _fmt(row["paper_value"], 5),
                    _fmt(row["pencore_value"], 6),
                    UNIT_TEXT.get(row["units"], row["units"]),
                ]
                lines.append("| " + " | ".join(c.replace("|", "/") for c in cells) + " |")
            lines.append("")
    return "\n".join(lines).rstrip()


#: every generated page: file name in docs/_generated -> the function that writes it
def _cff_names(authors: list[dict[str, str]]) -> list[str]:
    return [
        a.get("name") or f"{a.get('family-names', '')}, {a.get('given-names', '')}".strip(", ")
        for a in authors
    ]


def cite_page(cff: Path = REPO / "CITATION.cff") -> str:
    """The "How to cite" page from ``CITATION.cff``: its message, the software's and each
    reference's citation, and BibTeX entries for both."""
    import yaml

    c = yaml.safe_load(cff.read_text())
    url = c.get("repository-code") or c.get("url")
    authors = " and ".join(_cff_names(c["authors"]))
    lines = [
        " ".join(c["message"].split()),
        "",
        f"- **The software**: {authors}, *{c['title']}*, version {c['version']}"
        + (f", {url}" if url else "")
        + f" (licence {c['license']}).",
    ]
    bib = [
        "@software{pencore,",
        f"  author = {{{{{authors}}}}},",
        f"  title = {{{c['title'].replace('&', chr(92) + '&')}}},",
        f"  version = {{{c['version']}}},",
        *([f"  url = {{{url}}},"] if url else []),
        "}",
    ]
    for r in c.get("references", []):
        names = _cff_names(r["authors"])
        lines.append(
            f"- **The paper**: {', '.join(names)}, *{r['title']}*, {r['journal']} "
            f"{r['volume']} ({r['year']}) {r['start']}-{r['end']}."
        )
        key = f"{r['authors'][0]['family-names'].lower().replace('-', '')}{r['year']}"
        bib += [
            f"@article{{{key},",
            f"  author = {{{' and '.join(names)}}},",
            f"  title = {{{r['title']}}},",
            f"  journal = {{{r['journal']}}},",
            f"  volume = {{{r['volume']}}},",
            f"  pages = {{{r['start']}--{r['end']}}},",
            f"  year = {{{r['year']}}},",
            "}",
        ]
    lines += ["", "BibTeX:", "", "```bibtex", *bib, "```"]
    return "\n".join(lines)


PAGES: dict[str, Callable[[], str]] = {
    "cite.md": cite_page,
    "headline.md": headline_table,
    "comparison.md": comparison_table,
    "limits.md": limits_table,
    "limits_models.md": lambda: limits_table("models"),
    "plausible.md": plausible_table,
    "speed.md": speed_table,
    "convergence.md": convergence_table,
    "emulation.md": emulation_table,
    "attribution.md": attribution_table,
    "attribution_mass.md": attribution_mass_text,
    "dataset.md": dataset_table,
    "dataset_attrs.md": dataset_attrs_table,
    "ballistic_limit.md": ballistic_limit_table,
    "residual_velocity.md": residual_velocity_text,
    "measurements.md": measurements_table,
    "concrete.md": concrete_table,
    "compilation_reasons.md": compilation_reasons_table,
    "compilation_sources.md": compilation_sources_table,
    "compilation_duplicates.md": compilation_duplicates_table,
    "record_laws.md": record_laws_table,
    "record_diameter.md": record_diameter_table,
    "record_speed.md": record_speed_table,
    "record_regime.md": record_regime_table,
    "layers.md": layers_table,
    "measurement_options.md": measurement_options_table,
    "obliquity_ratio.md": obliquity_ratio_table,
    "ballistic_map.md": ballistic_map_table,
    "config_reference.md": config_reference_page,
    "figures.md": figures_page,
}

#: the README's generated blocks: marker name -> the function that writes it
README_BLOCKS: dict[str, Callable[[], str]] = {
    "headline": headline_table,
    "validation": validation_headline,
    "record": record_headline,
    "timing": timing_sentence,
}

_BLOCK = re.compile(
    r"(<!-- generated: (?P<name>[\w-]+) .*?-->\n)(?P<body>.*?)(\n<!-- end generated -->)",
    re.S,
)


def readme_with_blocks(text: str) -> str:
    """``text`` with every ``<!-- generated: name -->`` block regenerated."""

    def fill(m: re.Match[str]) -> str:
        return m.group(1) + README_BLOCKS[m.group("name")]() + m.group(4)

    return _BLOCK.sub(fill, text)


#: a number in a Markdown page: ``<!-- n:name -->value<!-- /n -->``, the value written by
#: :func:`pages_with_numbers` from :func:`numbers` (so the page reads the same on GitHub,
#: in a terminal and in the site, where the comments do not show)
_NUMBER = re.compile(r"<!-- n:(?P<name>\w+) -->(?P<value>.*?)<!-- /n -->", re.S)


def number_pages() -> list[Path]:
    """The Markdown pages of the docs that may hold numbers (not the build's output)."""
    skip = {"_build", "_generated", "auto_examples"}
    return sorted(p for p in (REPO / "docs").rglob("*.md") if not skip & set(p.parts))


def with_numbers(text: str, values: dict[str, str]) -> str:
    """``text`` with every ``<!-- n:name -->...<!-- /n -->`` holding ``values[name]``
    (a name :func:`numbers` does not give stops with a KeyError naming it)."""

    def fill(m: re.Match[str]) -> str:
        name = m.group("name")
        if name not in values:
            raise KeyError(f"<!-- n:{name} --> names no number of pencore_docs.numbers()")
        return f"<!-- n:{name} -->{values[name]}<!-- /n -->"

    return _NUMBER.sub(fill, text)


def write_numbers() -> list[Path]:
    """Rewrite the numbers of every docs page (:func:`number_pages`); the pages changed."""
    values = numbers()
    changed = []
    for page in number_pages():
        text = page.read_text()
        new = with_numbers(text, values)
        if new != text:
            page.write_text(new)
            changed.append(page)
    return changed


def write_pages(target: Path = GENERATED) -> None:
    """Write every generated page into ``target`` (only files whose text changed)."""
    target.mkdir(parents=True, exist_ok=True)
    for name, make in PAGES.items():
        text = make() + "\n"
        path = target / name
        if not path.exists() or path.read_text() != text:
            path.write_text(text)


def _on_config_inited(app, config) -> None:  # noqa: ANN001 (Sphinx, Config)
    write_pages()


def setup(app) -> dict[str, object]:  # noqa: ANN001
    """Sphinx entry point: generate the pages and numbers before the sources are read."""
    app.connect("config-inited", _on_config_inited)
    return {"parallel_read_safe": True, "parallel_write_safe": True}


def main(argv: list[str] | None = None) -> int:
    """``--readme``: rewrite the README's generated blocks and the numbers in the docs'
    Markdown pages; ``--pages``: write the pages."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--readme", action="store_true", help="rewrite README.md's blocks and the docs' numbers"
    )
    parser.add_argument("--pages", action="store_true", help="write docs/_generated/")
    args = parser.parse_args(argv)
    if args.readme:
        readme = REPO / "README.md"
        readme.write_text(readme_with_blocks(readme.read_text()))
        for page in write_numbers():
            print(f"pencore_docs: rewrote the numbers of {page.relative_to(REPO)}")
    if args.pages:
        write_pages()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
