"""Thin layers and gaps: every integrator with a step control samples them.

The step bound near thin layers (:func:`pencore.kernels.state.layer_travel_bound`,
:attr:`pencore.integrators.problem.Problem.thin_layers`) is used by the compiled
Rosenbrock integrator and by scipy's reference methods; these tests check its physics.
"""

import pytest

import pencore

ROD = "al_ogive_var4340"  # 71 mm long: shorter than the default step travel of 0.1 m


def _plate(thickness: float) -> dict:
    return {"name": "plate", "layers": [{"medium": "aluminium", "thickness": thickness}]}


@pytest.mark.parametrize("method", ["rosenbrock", "Radau"])
def test_a_thin_plate_behind_a_wide_gap_is_felt(method):
    # 1 mm plate, 0.5 m of air, 0.1 mm plate: the rod flies through the gap in steps of
    # up to 0.1 m, longer than itself, so without the bound it stepped over the second
    # plate (residual speed that of the first plate alone, measured). With it, the
    # stack's residual speed is the first plate's applied to the second: three runs,
    # each controlled to rtol * v0 = 8e-3 m/s per step, against a drop of 0.38 m/s
    v0, rtol = 800.0, 1e-5
    stack = {
        "name": "stack",
        "layers": [
            {"medium": "aluminium", "thickness": 1e-3},
            {"gap": 0.5},
            {"medium": "aluminium", "thickness": 1e-4},
        ],
    }
    v1 = pencore.simulate(ROD, _plate(1e-3), v0, method=method).attrs["residual_velocity"]
    v2 = pencore.simulate(ROD, _plate(1e-4), v1, method=method).attrs["residual_velocity"]
    ds = pencore.simulate(ROD, stack, v0, method=method)
    assert ds.attrs["outcome"] == "perforated"
    assert v1 - v2 > 0.3  # m/s: what the second plate takes
    assert ds.attrs["residual_velocity"] == pytest.approx(v2, abs=3 * rtol * v0)


@pytest.mark.parametrize("projectile", ["p2", ROD])
def test_a_foils_energy_loss_is_linear_in_its_thickness(projectile):
    # thin-plate limit: the work of a layer of thickness t is t times a load per unit
    # thickness (the speed hardly changes), so v0^2 - vr^2 is proportional to t down
    # to a 1-um foil, thinner than every band of the body (then resolved at the band
    # scale). At rtol 1e-8 the step control holds the speed to about rtol * v0 = 8e-6
    # m/s per step; a skipped foil would miss its whole drop (6e-4 m/s at 1 um, p2).
    v0, rtol = 800.0, 1e-8
    runs = {
        t: pencore.simulate(projectile, _plate(t), v0, 20.0, rtol=rtol) for t in (1e-6, 1e-5, 1e-4)
    }
    assert all(ds.attrs["outcome"] == "perforated" for ds in runs.values())
    vr = {t: ds.attrs["residual_velocity"] for t, ds in runs.items()}
    per_thickness = (v0**2 - vr[1e-4] ** 2) / 1e-4  # m/s^2
    for t in (1e-6, 1e-5):
        predicted = (v0**2 - per_thickness * t) ** 0.5
        assert v0 - vr[t] > 1e-4
        assert vr[t] == pytest.approx(predicted, abs=2 * rtol * v0)


@pytest.mark.parametrize(("projectile", "obliquity"), [("p2", 0.0), ("p2", 45.0), (ROD, 30.0)])
def test_foils_with_thin_gaps_act_as_one_plate_of_their_total_thickness(projectile, obliquity):
    # the DAFL stress depends on the normal velocity only, and a gap carries no load, so
    # twenty 10-um foils 10 um apart take what one 0.2 mm plate takes (the gaps shift
    # each foil by at most 0.2 mm, over which the speed hardly changes): two runs, each
    # controlled to rtol * v0 = 8e-3 m/s per step, against drops of 0.1-0.9 m/s
    v0, rtol = 800.0, 1e-5
    foils = []
    for _ in range(20):
        foils += [{"medium": "aluminium", "thickness": 1e-5}, {"gap": 1e-5}]
    stack = {"name": "foils", "layers": foils[:-1]}
    one = pencore.simulate(projectile, _plate(2e-4), v0, obliquity)
    ds = pencore.simulate(projectile, stack, v0, obliquity)
    assert ds.attrs["outcome"] == one.attrs["outcome"] == "perforated"
    assert v0 - one.attrs["residual_velocity"] > 0.1
    assert ds.attrs["residual_velocity"] == pytest.approx(
        one.attrs["residual_velocity"], abs=2 * rtol * v0
    )
