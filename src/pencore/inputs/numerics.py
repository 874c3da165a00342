"""Numerical parameters of a run, and the one way to build them from user input.

:class:`Numerics` holds the integrator's settings (defaults chosen by the convergence
study ``benchmarks/convergence.py``); :func:`resolve_numerics` turns what a user gives
(``None``, a :class:`Numerics`, a mapping of options, keyword overrides) into one, with
every value checked against :data:`pencore.inputs.limits.LIMITS`.
"""

from __future__ import annotations

import difflib
import functools
import inspect
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, fields, replace
from typing import Any

from pencore.errors import ArgumentError, InputError, hint_keywords
from pencore.inputs.gate import brief
from pencore.inputs.limits import check_keys, integer, number

__all__ = [
    "Numerics",
    "DEFAULT_NUMERICS",
    "DEFAULT_MAX_WALL",
    "METHODS",
    "JACOBIANS",
    "NUMERIC_FIELDS",
    "resolve_numerics",
    "check_keywords",
    "keywords_checked",
]

#: Integration methods: the compiled Rosenbrock pair (default) and scipy's implicit
#: ``solve_ivp`` methods on the same right-hand side (reference; much slower).
METHODS = ("rosenbrock", "Radau", "BDF")

#: Jacobians of the Rosenbrock integrator: closed form where the model allows it
#: (:func:`pencore.kernels.jacobian.analytic_jacobian_applies`), or finite differences.
JACOBIANS = ("analytic", "finite_difference")

#: Default wall-time budget of one run (s); see ``Numerics.max_wall``.
DEFAULT_MAX_WALL = 600.0

_INT_FIELDS = ("n_nose", "n_shank", "n_face", "max_steps", "n_gauss", "jacobian_age")


@dataclass(frozen=True)
class Numerics:
    """Numerical parameters (defaults chosen by ``benchmarks/convergence.py``).

    Every field is checked against :data:`pencore.inputs.limits.LIMITS` on construction;
    booleans are not numbers and integer fields must be whole numbers.

    Attributes
    ----------
    n_nose, n_shank, n_face : int
        Surface bands on the nose, on each 5 calibres of shank, and on each flat face.
    eps : float
        Half-width of the smoothed contact step in normal velocity (m/s). 0 is the
        discontinuous law, which usually fails as chatter (``step_underflow``).
    rtol : float
        Relative tolerance of the adaptive step control.
    max_travel : float
        Largest distance (m) the centre of mass may move in one step.
    v_stop : float
        Speed (m/s) below which the projectile is taken as stopped. An impact at or below
        it is at rest from the start (outcome ``stopped``, depth 0), as a search or an
        ensemble may meet it; the ``pencore simulate`` command refuses it.
    t_max : float
        Time limit (s) of the simulated motion.
    max_steps : int
        Step budget: accepted steps before the run fails with ``step_limit``.
    max_wall : float
        Wall-time budget (s) of one run; the run fails with ``wall_limit`` when it is
        used up (looked at on a time basis, not between chunks of steps). Default
        :data:`~pencore.inputs.numerics.DEFAULT_MAX_WALL` = 600 s, so that no accepted input runs
        for hours
        unannounced: the limits allow numerics (``n_nose = n_shank = 10 000``,
        ``n_gauss = 64``, long friction tables) whose steps cost a second each, times
        ``max_steps`` = 400 000. 600 s is over 300 times the slowest single run
        measured here (scipy's BDF on the reference case, 1.8 s; the default
        integrator takes 0.07 s), so it does not end a sane run even on a slow,
        loaded machine; ``inf`` turns the budget
        off (results then never depend on the machine's speed).
    h_min : float
        Smallest time step (s): a step the error control would make shorter fails the
        run as stiff or chattering (``step_underflow``).
    n_gauss : int
        Gauss points per 45-degree arc piece in the friction integral.
    jacobian_age : int
        Accepted steps the Rosenbrock integrator holds one Jacobian for (1: a fresh one
        every step); rebuilt after a rejected step and when the body enters or leaves
        the target. The second-order step is a W-method, so holding it keeps the order
        (:mod:`pencore.integrators.rosenbrock`); the default is chosen by
        ``benchmarks/bench_jacobian.py``.
    jacobian : str
        ``"analytic"`` (default): the velocity derivatives of the DAFL loads (rings,
        panels, cavity points) in closed form (:mod:`pencore.kernels.jacobian`) wherever they
        cover the model (frictionless targets, ``eps > 0``), finite differences
        elsewhere;
        ``"finite_difference"``: finite differences everywhere (six extra right-hand-side
        calls per Jacobian).
    gravity : float
        Gravitational acceleration (m/s^2) along ``-y``; 0 by default (as in the paper).
    method : str
        ``"rosenbrock"`` (compiled, default) or scipy's ``"Radau"`` / ``"BDF"`` through
        :func:`scipy.integrate.solve_ivp` on the same right-hand side
        (:mod:`pencore.integrators.scipy_ivp`).

    Raises
    ------
    InputError
        A field out of its range or of the wrong type (the one-line message names it and
        the range), an unknown ``method`` or ``jacobian``, or a ``v_stop`` below the
        creep speed of the smoothed contact step.

    Examples
    --------
    The defaults with a tighter tolerance; ``simulate(..., rtol=1e-8)`` does the same:

    >>> import pencore
    >>> num = pencore.Numerics(rtol=1e-8)
    >>> print(num.rtol, num.n_nose, num.method)
    1e-08 48 rosenbrock
    >>> pencore.Numerics(rtol=-1.0)
    Traceback (most recent call last):
    ...
    pencore.errors.InputError: numerics: rtol must be in [1e-12, 0.1], got -1.0
    """

    n_nose: int = 48
    n_shank: int = 24
    n_face: int = 4
    eps: float = 1e-3
    rtol: float = 1e-5
    max_travel: float = 0.1
    v_stop: float = 1.0
    t_max: float = 1.0
    max_steps: int = 400_000
    max_wall: float = DEFAULT_MAX_WALL
    h_min: float = 1e-12
    n_gauss: int = 4
    jacobian_age: int = 6
    jacobian: str = "analytic"
    gravity: float = 0.0
    method: str = "rosenbrock"

    def __post_init__(self) -> None:
        for name in NUMERIC_FIELDS:
            value = getattr(self, name)
            if name in _INT_FIELDS:
                checked: float = integer(value, name, "numerics")
            else:
                checked = number(value, name, "numerics")
            object.__setattr__(self, name, checked)
        if self.eps > 0.0 and not self.v_stop >= CREEP_FACTOR * self.eps:
            raise InputError(
                f"numerics v_stop = {self.v_stop:g} m/s is below {CREEP_FACTOR:g} eps = "
                f"{CREEP_FACTOR * self.eps:g} m/s: the contact step smoothed over +-eps "
                "leaves a body at rest half its static resistance, which pushes it back at a "
                "creep of a few eps, so the run would follow the smoothing, not the DAFL "
                "(raise v_stop or lower eps)"
            )
        if self.method not in METHODS:
            hint = difflib.get_close_matches(str(self.method), METHODS, n=1)
            tip = f"; did you mean {brief(hint[0])}?" if hint else ""
            raise InputError(
                f"numerics method must be one of {', '.join(METHODS)}, "
                f"got {brief(self.method)}{tip}"
            )
        if self.jacobian not in JACOBIANS:
            hint = difflib.get_close_matches(str(self.jacobian), JACOBIANS, n=1)
            tip = f"; did you mean {brief(hint[0])}?" if hint else ""
            raise InputError(
                f"numerics jacobian must be one of {', '.join(JACOBIANS)}, "
                f"got {brief(self.jacobian)}{tip}"
            )


#: ``v_stop`` must be at least this many times ``eps`` (when ``eps > 0``): below a few
#: ``eps`` a body at rest creeps under the smoothed contact step (#2 stopped in a 5 mm
#: aluminium plate drifted back out at 6.6 eps), a speed of the smoothing, not of the DAFL.
CREEP_FACTOR = 10.0

#: The numeric fields of :class:`Numerics`, each checked against
#: :data:`pencore.inputs.limits.LIMITS` under its own name (all but ``method`` and
#: ``jacobian``, which are names).
NUMERIC_FIELDS: tuple[str, ...] = tuple(
    f.name for f in fields(Numerics) if f.name not in ("method", "jacobian")
)

DEFAULT_NUMERICS = Numerics()


def resolve_numerics(
    numerics: Numerics | Mapping[str, Any] | None = None,
    overrides: Mapping[str, Any] | None = None,
) -> Numerics:
    """A :class:`Numerics` from what a user gives: ``None`` (the defaults), a
    :class:`Numerics`, or a mapping of options, with ``overrides`` (a mapping of options)
    on top.

    In a mapping, entries that are ``None`` mean "keep the default" (the workflow's
    config schema fills unset numerics keys with ``null``). Unknown keys raise
    :class:`~pencore.errors.InputError` with a "did you mean" hint; values are checked
    against :data:`pencore.inputs.limits.LIMITS`.
    """
    if numerics is None:
        base = DEFAULT_NUMERICS
    elif isinstance(numerics, Numerics):
        base = numerics
    elif isinstance(numerics, Mapping):
        base = _apply(DEFAULT_NUMERICS, numerics)
    else:
        raise InputError(
            f"numerics must be a pencore.Numerics or a mapping of options, got {brief(numerics)}"
        )
    return _apply(base, overrides) if overrides else base


def check_keywords(overrides: Mapping[str, Any], own: Iterable[str], function: str) -> None:
    """Refuse a keyword of ``function`` that is neither one of its own parameters
    (``own``) nor a :class:`Numerics` field, naming the closest of both: a typo of the
    function's own keyword (``obliquty=30``) is not an unknown numerics key.

    Raises
    ------
    InputError
        ``unknown keyword 'obliquty' (did you mean 'obliquity'?)``, one line.
    """
    numerics = [f.name for f in fields(Numerics)]
    known = [k for k in own if k not in ("overrides", "kwargs")] + numerics
    for key in overrides:
        if key in numerics:
            continue
        lower = {k.lower(): k for k in known}
        hint = difflib.get_close_matches(str(key).lower(), list(lower), n=1, cutoff=0.6)
        tip = f" (did you mean {lower[hint[0]]!r}?)" if hint else ""
        raise ArgumentError(
            f"{function}: unknown keyword {brief(key)}{tip}; its keywords are its own "
            f"parameters and the numerics fields ({', '.join(numerics)})"
        )


def keywords_checked(function: Callable[..., Any]) -> Callable[..., Any]:
    """``function`` with its call checked before it runs: a keyword that is none of its
    own parameters nor a :class:`Numerics` field, or an argument missing or given twice,
    is one :class:`~pencore.errors.InputError` line (a typo of its own keyword, which
    ``**kwargs`` would swallow, is named with the closest one instead of surfacing as a
    "missing argument"). For the public functions that take ``**kwargs``; costs one
    signature binding per call.

    Examples
    --------
    >>> from pencore.inputs.numerics import keywords_checked
    >>> @keywords_checked
    ... def search(projectile, obliquity, **kwargs):
    ...     return obliquity
    >>> search("p2", obliquty=30.0)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pencore.errors.ArgumentError: search: unknown keyword 'obliquty' (did you mean ...
    """
    signature = inspect.signature(function)
    own = [
        name
        for name, parameter in signature.parameters.items()
        if parameter.kind not in (parameter.VAR_KEYWORD, parameter.VAR_POSITIONAL)
    ]

    @functools.wraps(function)
    def checked(*args: Any, **kwargs: Any) -> Any:
        try:
            signature.bind(*args, **kwargs)
        except TypeError as exc:
            swallowed = {k: v for k, v in kwargs.items() if k not in own}
            check_keywords(swallowed, own, function.__name__)  # a typo: named, with a hint
            raise ArgumentError(f"{function.__name__}: {exc}") from None
        return function(*args, **kwargs)

    return checked


def _apply(base: Numerics, mapping: Mapping[str, Any]) -> Numerics:
    check_keys(mapping, [f.name for f in fields(Numerics)], "numerics")
    given = {k: v for k, v in mapping.items() if v is not None}
    return replace(base, **given) if given else base


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
