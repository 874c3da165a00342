"""benchmarks/pointpanel.py: the independent point-panel reference solver.

First the reference alone against what it must satisfy (its independence from pencore's
solver, Table 3, a closed surface, the closed-form normal-impact force and depth, mirror
symmetry); then the reference against pencore (``pencore.simulate``) on the disputed
cases, each within a tolerance set by the reference's own measured discretisation error
(``benchmarks/results/pointpanel.csv``: step halved, panels doubled) plus pencore's
(its change from ``rtol`` 1e-5 to 1e-7, below 0.001 deg and 1 m/s on these cases).
"""

from __future__ import annotations

import csv
import math
import os
import subprocess
import sys

import numpy as np
import pytest

from pencore.inputs.library import TABLE3

#: Resolution of the disputed-case tests (see TOL_* for what it costs in accuracy).
RES_KW = dict(n_nose=24, n_shank=24, n_face=4, n_phi=32, dt=2.5e-6)


@pytest.fixture(scope="module")
def pp(load_benchmark):
    return load_benchmark("pointpanel")


def test_reference_imports_none_of_pencores_solver():
    """The reference must not lean on the code it checks: loading it pulls in none of
    pencore's kernels, integrators, run, search or analysis modules."""
    code = (
        "import importlib.util, sys\n"
        "spec = importlib.util.spec_from_file_location('pp', sys.argv[1])\n"
        "mod = importlib.util.module_from_spec(spec); spec.loader.exec_module(mod)\n"
        "m = mod.Model('p2', mod.Resolution(8, 8, 2, 8, 1e-5))\n"
        "m.rhs(m.initial_state(500.0, 0.0, 0.0, 0.0, None))\n"
        "bad = ('pencore.kernels', 'pencore.integrators', 'pencore.run', 'pencore.search',\n"
        "       'pencore.analysis')\n"
        "print(sorted(m for m in sys.modules if m.startswith(bad)))\n"
    )
    path = os.path.join(os.path.dirname(__file__), "..", "..", "benchmarks", "pointpanel.py")
    out = subprocess.run(
        [sys.executable, "-c", code, path], capture_output=True, text=True, check=True
    )
    assert out.stdout.strip() == "[]"


@pytest.mark.parametrize("key", sorted(TABLE3))
def test_mass_and_lc_match_table3(pp, key):
    """The reference's own quadrature of the Table-3 bodies gives the table's mass and
    Lc/L to 1.25 x its rounding (0.05 kg, 0.0005): no solid ogive + cylinder does better,
    the four masses being slightly inconsistent (tests/inputs/test_geometry.py)."""
    m, lc, ia, it = pp.table3_body(key).mass_properties()
    body = pp.table3_body(key)
    assert abs(m - TABLE3[key][1]) <= 1.25 * 0.05
    assert abs(lc / body.length - TABLE3[key][2]) <= 1.25 * 0.0005
    # a thin rod's transverse inertia is bounded by that of its end masses
    assert 0.0 < ia < it < m * body.length**2 / 4.0


def test_panels_close_the_surface(pp):
    """The panels' area vectors of a closed surface sum to zero; the axial ones to the
    nose's projected area against the rear disc's (pi a^2 each)."""
    model = pp.Model("p2", pp.Resolution(**RES_KW))
    pn = model.panels
    a = model.body.a
    ax = pn.area * pn.n1
    assert abs(ax.sum()) <= 1e-12 * math.pi * a * a
    assert ax[ax > 0].sum() == pytest.approx(math.pi * a * a, rel=1e-12)
    assert abs((pn.area * pn.n2).sum()) <= 1e-15


def test_embedded_nose_force_is_the_closed_form(pp):
    """A nose fully below the surface in axial motion carries
    F = pi a^2 (a0 + N* a2 V^2), N* = (8 psi - 1) / (24 psi^2) for CRH psi (the shank's
    zero normal velocity loads it all round, which cancels; the rear face moves away).
    The point panels converge to it at second order: the error falls four-fold each time
    the rings and sectors double (0.15 %, 0.037 %, 0.0093 % at 1500 m/s)."""
    a0, _, a2 = pp.SOIL
    nstar = pp.closed_form_nstar(3.0)
    errs = []
    for k in (1, 2, 4):
        model = pp.Model("p2", pp.Resolution(24 * k, 24, 4, 32 * k, 1e-5))
        a = model.body.a
        row = []
        for v in (100.0, 500.0, 1500.0):
            st = model.initial_state(v, 0.0, 0.0, 0.0, None)
            st[1] -= 5.0  # deep
            d = model.rhs(st)
            assert d[4] == 0.0 and d[6] == 0.0  # no side force, no moment
            row.append(d[5] * model.mass / (math.pi * a * a * (a0 + nstar * a2 * v * v)) - 1.0)
        errs.append(np.abs(row))
    assert np.all(errs[0] < 2e-3) and np.all(errs[2] < 1.5e-4)
    ratios = errs[0] / errs[1], errs[1] / errs[2]
    assert np.all((np.array(ratios) > 3.5) & (np.array(ratios) < 4.5))


@pytest.mark.slow
def test_normal_impact_depth_is_the_closed_form(pp):
    """Normal impact of #2 at 500 m/s: the depth travelled after nose embedment is the
    closed form (m / (2 pi a^2 N* a2)) ln(1 + N* a2 V1^2 / a0) from the speed V1 at
    embedment, to 0.1 % (measured 0.045 % at 40 nose rings, 0.012 % at 80: the panels'
    N*); the path stays exactly on the axis (mirror-symmetric panels)."""
    model = pp.Model("p2", pp.Resolution(40, 40, 6, 48, 1e-5))
    tr = model.run(500.0)
    assert tr.outcome == "stopped" and not tr.reversed
    tip = tr.tip()
    ln = model.body.nose_length
    i = int(np.flatnonzero(tip[:, 1] <= -ln)[0])
    v1 = float(np.interp(-ln, tip[i - 1 : i + 1, 1][::-1], tr.speed[i - 1 : i + 1][::-1]))
    depth = -tip[-1, 1] - ln
    assert depth == pytest.approx(pp.closed_form_depth(model.mass, model.body.a, 3.0, v1), rel=1e-3)
    assert np.all(tr.y[:, 0] == 0.0) and np.all(tr.y[:, 4] == 0.0) and np.all(tr.y[:, 6] == 0.0)


@pytest.mark.slow
def test_mirror_impact_gives_the_mirror_path(pp):
    """Obliquity, yaw, spin and start mirrored in x give the path mirrored in x, to the
    last bit (the panel set and the sums are built mirror-symmetric)."""
    model = pp.Model("p2", pp.Resolution(12, 12, 2, 16, 2e-5))
    a = model.run(300.0, 20.0, 2.0, 3.0, start=(-0.5, 0.3))
    b = model.run(300.0, -20.0, -2.0, -3.0, start=(0.5, 0.3))
    assert a.outcome == b.outcome and a.y.shape == b.y.shape
    flip = np.array([-1.0, 1.0, -1.0, 1.0, -1.0, 1.0, -1.0])
    np.testing.assert_array_equal(b.y, a.y * flip)
    assert abs(a.y[-1, 0] - a.y[0, 0]) > 0.1  # the path did curve sideways


# ------------------------------------------------------------------ the disputed cases

#: Tolerance of each comparison with pencore at the reference's base resolution
#: (pointpanel.BASE): 2 |change when the step is halved| + 2 |change when the panels are
#: doubled| + |pencore's change from rtol 1e-5 to 1e-7| (+ both bracket widths for Vcr),
#: as measured in benchmarks/results/pointpanel.csv, rounded up. A first-order error is
#: twice its change under halving; the changes are large for the small deviations because
#: the pure Heaviside switches the shank's zero-normal-velocity panels on and off within
#: a step, and a whole row of panels crosses the free surface at once.
TOL = {
    "alpha_5": 0.23,  # deg
    "alpha_20": 0.15,  # deg
    "alpha_25": 0.27,  # deg
    "phi_280": 0.022,  # deg
    "phi_1000": 0.12,  # deg
    "vcr": 10.0,  # m/s
}


def test_results_file_records_agreement_within_the_test_tolerances(pp):
    """benchmarks/results/pointpanel.csv (what the docs quote) was made at the base
    resolutions the tests run, its tolerances are within those asserted here and every
    case agrees within them."""
    with pp.OUT.open(newline="") as fh:
        rows = {r["quantity"]: r for r in csv.DictReader(fh)}
    assert set(rows) == set(pp.QUANTITIES)
    for q, r in rows.items():
        case = pp.QUANTITIES[q][0]
        assert f"base {pp.BASE[case].label()}" in r["note"], q
        assert abs(float(r["difference"])) <= float(r["tolerance"]), q
        assert r["agrees"] == "yes", q
        if q in TOL:
            assert float(r["tolerance"]) <= TOL[q], q


def test_docs_quote_the_results_file(pp):
    """The agreement the docs and pencore.studies.attribution.disputed quote is the results
    file's."""
    with pp.OUT.open(newline="") as fh:
        rows = {r["quantity"]: r for r in csv.DictReader(fh)}

    def g(q, col):
        return f"{abs(float(rows[q][col])):.2g}"

    repo = pp.ROOT
    page = " ".join((repo / "docs" / "results" / "attribution.md").read_text().split())
    for text in (
        f"Vcr at 45 deg within {g('vcr', 'difference')} m/s "
        f"(tolerance {g('vcr', 'tolerance')} m/s)",
        f"phi of #2 at 20 rad/s within {g('alpha_20', 'difference')} deg "
        f"(tolerance {g('alpha_20', 'tolerance')} deg)",
        f"tolerance ({g('alpha_5', 'tolerance')}, {g('phi_280', 'tolerance')} and "
        f"{g('phi_1000', 'tolerance')} deg)",
    ):
        assert text in page
    doc = " ".join(
        (repo / "src" / "pencore" / "studies" / "attribution" / "disputed.py").read_text().split()
    )
    assert f"Vcr at 45 deg within {g('vcr', 'difference')} m/s" in doc
    assert f"alpha at 20 rad/s within {g('alpha_20', 'difference')} deg" in doc


@pytest.fixture(scope="module")
def spin_runs(pp):
    return {w: pp.spin_run(pp.BASE["spin"], w) for w in pp.SPIN_CASE["omegas"]}


@pytest.mark.slow
@pytest.mark.parametrize("omega", [5.0, 20.0, 25.0])
def test_spin_deviation_agrees_with_pencore(pp, spin_runs, omega):
    """#2 at 1000 m/s, normal, spun about the centre of mass: the reference's alpha is
    pencore's within TOL, and neither turns back (the paper: alpha 0.14 and 2.86 deg at
    5 and 20 rad/s, turning back at 25). At 20 rad/s the paper's 2.86 deg lies far
    outside the reference's tolerance."""
    import pencore

    ds = pencore.simulate("p2", "soil", 1000.0, omega=omega)
    ref = spin_runs[omega]
    assert abs(ref.final_deviation() - pp.pencore_deviation(ds)) <= TOL[f"alpha_{omega:g}"]
    assert not ref.reversed and not int(ds.attrs["reversed"])
    if omega == 20.0:
        assert abs(ref.final_deviation() - 2.86) > 5 * TOL["alpha_20"]


@pytest.mark.slow
@pytest.mark.parametrize("velocity", [280.0, 1000.0])
def test_yaw_deviation_agrees_with_pencore(pp, velocity):
    """#4, normal impact, velocity normal and axis tilted by 0.1 deg (the configured
    axis_tilted reading): the reference's phi is pencore's within TOL."""
    import pencore

    ds = pencore.simulate("p4", "soil", velocity, 0.1, -0.1)
    ref = pp.yaw_run(pp.BASE["yaw"], velocity).final_deviation()
    assert abs(ref - pp.pencore_deviation(ds)) <= TOL[f"phi_{velocity:g}"]


@pytest.mark.slow
def test_vcr_brackets_pencores(pp):
    """#2 in soil at 45 deg from the tip at (-1, 1) m: the reference does not turn back
    TOL below pencore's Vcr bracket and does turn back TOL above it (the paper's Vcr,
    1641-1650 m/s, is far above both)."""
    lo, hi = pp.pencore_vcr()
    assert hi - lo <= 1.0
    model = pp.Model("p2", pp.BASE["vcr"])
    assert not pp.vcr_turns_back(pp.BASE["vcr"], lo - TOL["vcr"], model)
    assert pp.vcr_turns_back(pp.BASE["vcr"], hi + TOL["vcr"], model)
    assert hi + TOL["vcr"] < 1641.0
