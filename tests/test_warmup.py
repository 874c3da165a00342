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
    assert warmup.main([]) == 0
    n = len(warmup.VARIANTS)
    assert len(seen) == n
    for i, (label, _) in enumerate(warmup.VARIANTS, 1):
        assert f"kernel {i} of {n} ({label}) ..." in seen[i - 1].splitlines()[-1]
    out = capsys.readouterr().out
    assert f"kernel {n} of {n} ready in" in out
    assert "kernels compiled and cached in" in out
