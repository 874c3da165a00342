"""``python -m pencore.warmup`` says where it is: each kernel variant is announced
(``kernel i of n``) before it runs, so a cold compile is never a silent minute."""

from __future__ import annotations

from pencore import warmup
from pencore.run import impact


def test_each_variant_is_announced_before_it_runs(monkeypatch, capsys):
    seen = []

    def simulate(projectile, target, velocity, obliquity=0.0, **kw):
        # what the user has read when this variant starts compiling
        seen.append(capsys.readouterr().out)

    monkeypatch.setattr(impact, "simulate", simulate)
    monkeypatch.setattr(impact, "run_impact", simulate)  # the search run's variant
    assert warmup.main([]) == 0
    n = len(warmup.VARIANTS)
    assert len(seen) == n
    for i, (label, _) in enumerate(warmup.VARIANTS, 1):
        assert f"kernel {i} of {n} ({label}) ..." in seen[i - 1].splitlines()[-1]
    out = capsys.readouterr().out
    assert f"kernel {n} of {n} ready in" in out
    assert "kernels compiled and cached in" in out


# --- the cold compile split into parts compiled side by side ------------------------------


def _integrator_types() -> dict[str, object]:
    """Argument types of the integrator's compiled chunk by parameter name, as a run
    passes them (the run loads it from the cache, or compiles it)."""
    import inspect

    import pencore
    from pencore.integrators.rosenbrock import integrate_chunk

    pencore.simulate("p2", "soil", 300.0, obliquity=30.0)
    names = list(inspect.signature(integrate_chunk.py_func).parameters)
    return dict(zip(names, integrate_chunk.signatures[0], strict=False))


def test_each_part_is_called_with_the_types_the_integrator_passes():
    # a part compiled with other types would be a second specialisation: the integrator's
    # compile would not find it in the cache and would compile it again, serially
    import numba

    types = _integrator_types()
    rhs_names = ("y", "mass", "inertia", "gravity", "rings", "bounds", "coef", "fric", "eps",
                 "n_gauss", "model")  # fmt: skip
    function, args = warmup.part_call("rhs")
    assert function.py_func.__name__ == "rhs_model"
    assert [numba.typeof(a) for a in args] == [types[n] for n in rhs_names]
    function, args = warmup.part_call("jacobian")
    assert function.py_func.__name__ == "velocity_jacobian"
    jac_names = ("y", "f0", "mass", "inertia", "gravity", "rings", "bounds", "coef", "fric",
                 "eps", "model")  # fmt: skip
    assert numba.typeof(args[0]) == numba.typeof(__import__("numpy").zeros((14, 14)))
    assert [numba.typeof(a) for a in args[1:]] == [types[n] for n in jac_names]


def test_no_parts_on_one_core_or_a_warm_cache(monkeypatch):
    from pencore.kernels import cache

    monkeypatch.setattr(warmup, "_cores", lambda: 1)
    assert warmup.compile_parts_side_by_side(verbose=False) == []
    monkeypatch.setattr(warmup, "_cores", lambda: 2)
    monkeypatch.setattr(cache, "compiled_in_cache", lambda dispatcher: True)
    assert warmup.compile_parts_side_by_side(verbose=False) == []


def test_a_failed_part_is_said_and_does_not_stop_the_warmup(capsys):
    warmup._finish(warmup._start_parts(["no_such_part"]))
    err = capsys.readouterr().err
    assert "part 'no_such_part' exited 2; the variants compile it instead" in err


def test_an_unknown_part_is_a_usage_error(capsys):
    assert warmup.main(["--part", "no_such_part"]) == 2
    assert "usage: python -m pencore.warmup" in capsys.readouterr().err
