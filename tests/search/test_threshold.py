"""pencore.search.threshold: the search reports its progress on the pencore.search logger."""

import logging


def test_find_threshold_logs_progress(caplog):
    """Long searches report bracket, evaluations and verdicts on the pencore.search logger."""
    from pencore.search.threshold import find_threshold

    with caplog.at_level(logging.INFO, logger="pencore.search"):
        r = find_threshold(lambda v: v > 3.3, 0.0, 10.0, 0.5, scan=3, name="Vtest")
    assert r.status == "ok"
    msgs = [rec.getMessage() for rec in caplog.records if rec.name == "pencore.search"]
    assert msgs[0] == "Vtest: search in [0, 10], tol 0.5"
    assert any(m.startswith("Vtest: evaluation 1 at 0 -> False") for m in msgs)
    assert len([m for m in msgs if ": evaluation " in m]) == r.n_evals
    assert msgs[-1].startswith(f"Vtest: ok after {r.n_evals} evaluations")
