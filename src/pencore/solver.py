"""``simulate``: one penetration trajectory as an :class:`xarray.Dataset`.

Geometry of the impact (angles in degrees at this interface, radians inside):

* the target is ``y <= 0``, the projectile moves towards ``+x`` and ``-y``;
* ``obliquity`` (phi1) is the angle between the projectile axis and the target normal
  (``-y``), measured towards ``+x``;
* ``yaw`` (phi2) is the velocity angle minus the axis angle (paper Fig. 10), so the
  velocity makes ``alpha = phi1 + phi2`` with the normal;
* ``omega`` is the initial angular velocity about ``+z`` (rad/s), about the centre of
  mass (``spin_about="cm"``, default) or about the nose tip (``"tip"``: the tip keeps
  the impact velocity and the centre of mass moves with it); positive turns the nose
  towards ``+x``;
* ``start`` is the initial nose-tip position (m); by default the tip is at ``x = z = 0``
  and the body is lowered until its lowest surface point just touches ``y = 0``;
* ``azimuth`` turns the whole impact (position, velocity, attitude, spin) about the
  target normal ``+y`` (deg); 0 keeps the motion in the x-y plane. The target is
  invariant under this rotation, so the trajectory just turns with it.
"""

from __future__ import annotations

import difflib
import json
import math
import time
from collections.abc import Mapping
from dataclasses import dataclass, fields, replace
from typing import Any

import numpy as np
import xarray as xr

from .forces import default_model as _default_model
from .forces import kernel_model
from .geometry import Projectile
from .initial import (  # noqa: F401 - re-exported
    SPIN_CENTRES,
    _axis_quaternion,
    _check_inputs,
    _check_reaches_target,
    initial_state,
)
from .integrate import CHUNK_STEPS, RunResult, body_reach, integrate
from .library import get_projectile, get_target
from .models import Emulation, ShankModel, emulation, shank_model, to_json
from .target import Target
from .trajectory import trajectory_dataset
from .validate import InputError, check_keys, integer, number

__all__ = ["Numerics", "simulate", "initial_state", "SolverError", "DEFAULT_NUMERICS"]


class SolverError(RuntimeError):
    """The integration could not finish; the message names the cause and the state."""


#: Integration methods: the compiled Rosenbrock pair (default) and scipy's implicit
#: ``solve_ivp`` methods on the same right-hand side (reference; much slower).
METHODS = ("rosenbrock", "Radau", "BDF")

#: Jacobians of the Rosenbrock integrator: closed form where the model allows it
#: (:func:`pencore.jacobian.analytic_jacobian_applies`), or finite differences.
JACOBIANS = ("analytic", "finite_difference")

_INT_FIELDS = ("n_nose", "n_shank", "n_face", "max_steps", "n_gauss", "jacobian_age")


@dataclass(frozen=True)
class Numerics:
    """Numerical parameters (defaults chosen by ``benchmarks/convergence.py``).

    Every field is checked against :data:`pencore.validate.LIMITS` on construction;
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
        Speed (m/s) below which the projectile is taken as stopped.
    t_max : float
        Time limit (s) of the simulated motion.
    max_steps : int
        Step budget: accepted steps before the run fails with ``step_limit``.
    max_wall : float
        Wall-time budget (s) of one run, ``inf`` (default) for none: results then do
        not depend on the machine's speed.
    h_min : float
        Smallest time step (s): a step the error control would make shorter fails the
        run as stiff or chattering (``step_underflow``).
    n_gauss : int
        Gauss points per 45-degree arc piece in the friction integral.
    jacobian_age : int
        Accepted steps the Rosenbrock integrator holds one Jacobian for (1: a fresh one
        every step); rebuilt after a rejected step and when the body enters or leaves
        the target. The second-order step is a W-method, so holding it keeps the order
        (:mod:`pencore.integrate`); the default is chosen by
        ``benchmarks/bench_jacobian.py``.
    jacobian : str
        ``"analytic"`` (default): the velocity derivatives of the DAFL loads (rings,
        panels, cavity points) in closed form (:mod:`pencore.jacobian`) wherever they
        cover the model (frictionless targets, ``eps > 0``), finite differences
        elsewhere;
        ``"finite_difference"``: finite differences everywhere (six extra right-hand-side
        calls per Jacobian).
    gravity : float
        Gravitational acceleration (m/s^2) along ``-y``; 0 by default (as in the paper).
    method : str
        ``"rosenbrock"`` (compiled, default) or scipy's ``"Radau"`` / ``"BDF"`` through
        :func:`scipy.integrate.solve_ivp` on the same right-hand side
        (:mod:`pencore.reference`).
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
    max_wall: float = math.inf
    h_min: float = 1e-12
    n_gauss: int = 4
    jacobian_age: int = 6
    jacobian: str = "analytic"
    gravity: float = 0.0
    method: str = "rosenbrock"

    def __post_init__(self) -> None:
        for f in fields(self):
            if f.name in ("method", "jacobian"):
                continue
            value = getattr(self, f.name)
            if f.name in _INT_FIELDS:
                checked: float = integer(value, f.name, "numerics")
            else:
                checked = number(value, f.name, "numerics")
            object.__setattr__(self, f.name, checked)
        if self.method not in METHODS:
            hint = difflib.get_close_matches(str(self.method), METHODS, n=1)
            tip = f"; did you mean {hint[0]!r}?" if hint else ""
            raise InputError(
                f"numerics method must be one of {', '.join(METHODS)}, got {self.method!r}{tip}"
            )
        if self.jacobian not in JACOBIANS:
            hint = difflib.get_close_matches(str(self.jacobian), JACOBIANS, n=1)
            tip = f"; did you mean {hint[0]!r}?" if hint else ""
            raise InputError(
                f"numerics jacobian must be one of {', '.join(JACOBIANS)}, "
                f"got {self.jacobian!r}{tip}"
            )

    @classmethod
    def from_mapping(cls, mapping: Mapping[str, Any], base: Numerics | None = None) -> Numerics:
        """``base`` (default: the defaults) with the entries of ``mapping`` on top;
        unknown keys raise :class:`InputError` with a "did you mean" hint."""
        if not isinstance(mapping, Mapping):
            raise InputError(f"numerics must be a mapping of options, got {mapping!r}")
        check_keys(mapping, [f.name for f in fields(cls)], "numerics")
        return replace(base or cls(), **mapping)


DEFAULT_NUMERICS = Numerics()


@dataclass
class _Prepared:
    projectile: Projectile
    target: Target
    numerics: Numerics
    rings: np.ndarray
    bounds: np.ndarray
    coef: np.ndarray
    fric: np.ndarray
    mass: float
    inertia: np.ndarray
    lc: float
    shank: ShankModel = ShankModel()
    emulation: Emulation = Emulation()
    kernel_rings: np.ndarray | None = None  # rings for the ring kernel under the model
    model: tuple[np.ndarray, ...] | None = None  # pencore.forces kernel tuple


def _resolve_numerics(numerics: Any, overrides: Mapping[str, Any]) -> Numerics:
    if numerics is None:
        base = DEFAULT_NUMERICS
    elif isinstance(numerics, Numerics):
        base = numerics
    elif isinstance(numerics, Mapping):
        base = Numerics.from_mapping(numerics)
    else:
        raise InputError(
            f"numerics must be a pencore.Numerics or a mapping of options, got {numerics!r}"
        )
    return Numerics.from_mapping(overrides, base) if overrides else base


def prepare(
    projectile: Any,
    target: Any,
    numerics: Numerics | None = None,
    *,
    shank: ShankModel | Mapping[str, Any] | str | None = None,
    emulation: Emulation | Mapping[str, Any] | None = None,
    **overrides: Any,
) -> _Prepared:
    """Resolve names and build the kernel arrays (reusable across many trajectories).

    ``shank`` and ``emulation`` select the shank contact model and the paper-emulation
    numerics (:mod:`pencore.models`; default: the DAFL on pencore's rings, adaptive).
    """
    num = _resolve_numerics(numerics, overrides)
    sm = shank_model(shank)
    em = _emulation(emulation)
    if num.method != "rosenbrock" and (em.integrator == "explicit" or sm.kind == "cavity"):
        what = "the explicit integrator" if em.integrator == "explicit" else "the cavity model"
        raise InputError(
            f"numerics method {num.method!r} cannot be combined with {what}; "
            "use method 'rosenbrock'"
        )
    p = get_projectile(projectile)
    t = get_target(target)
    mp = p.mass_properties()
    ring_set = p.rings(num.n_nose, num.n_shank, num.n_face)
    rings = ring_set.as_array()
    bounds, coef, fric = t.kernel_arrays(p.diameter)
    inertia = np.array([mp.i_axial, mp.i_transverse, mp.i_transverse])
    pr = _Prepared(p, t, num, rings, bounds, coef, fric, mp.mass, inertia, mp.lc, sm, em)
    if not (sm.is_default and em.surface == "rings"):
        pr.kernel_rings, pr.model = kernel_model(
            p, ring_set, sm, em, num.n_nose, num.n_shank, num.n_face
        )
    return pr


_emulation = emulation


def simulate(
    projectile: str | Projectile,
    target: str | Target,
    velocity: float,
    obliquity: float = 0.0,
    yaw: float = 0.0,
    omega: float = 0.0,
    *,
    start: tuple[float, float, float] | None = None,
    azimuth: float = 0.0,
    stop_at_reversal: bool = False,
    numerics: Numerics | None = None,
    prepared: _Prepared | None = None,
    shank: ShankModel | Mapping[str, Any] | str | None = None,
    emulation: Emulation | Mapping[str, Any] | None = None,
    spin_about: str = "cm",
    **overrides: Any,
) -> xr.Dataset:
    """Simulate one impact.

    Parameters
    ----------
    projectile : str or Projectile
        Name (``p1``..``p4``, validation projectiles), YAML path, or object.
    target : str or Target
        Name (``soil``, ``concrete``, ``aluminium``), YAML path, or object.
    velocity : float
        Impact speed (m/s), > 0.
    obliquity : float
        Axis angle from the target normal (deg).
    yaw : float
        Velocity angle minus axis angle (deg).
    omega : float
        Initial angular velocity about the centre of mass, about +z (rad/s).
    start : (3,) float, optional
        Initial nose-tip position (m). Default: just touching the surface at x = 0.
    azimuth : float
        Rotation of the whole impact about the target normal (deg).
    stop_at_reversal : bool
        End the run at the first reversal (outcome ``reversed``).
    numerics : Numerics, optional
        Numerical parameters; keyword overrides (``eps=...``, ``rtol=...``) apply on top.
    prepared : optional
        Output of :func:`prepare`, to skip re-resolving in loops (it carries the shank
        model and emulation: do not pass those as well).
    shank : ShankModel, mapping or str, optional
        Shank contact model (:mod:`pencore.models`): ``"dafl"`` (default), ``"cavity"``,
        ``"factor"``.
    emulation : Emulation or mapping, optional
        Paper-emulation numerics (:mod:`pencore.models`): panels, explicit integrator.
    spin_about : {"cm", "tip"}
        The point ``omega`` turns the body about at t = 0.

    Returns
    -------
    xarray.Dataset
        Time histories on dimension ``time`` (s) and scalar results; see the README.
    """
    pr, run, wall, (velocity, obliquity, yaw, omega, azimuth, start) = _impact(
        projectile, target, velocity, obliquity, yaw, omega, start, azimuth,
        stop_at_reversal, numerics, prepared, shank, emulation, spin_about, overrides,
    )  # fmt: skip
    ds = trajectory_dataset(
        pr.projectile,
        pr.target,
        pr.numerics,
        run,
        wall,
        dict(
            velocity=velocity,
            obliquity=obliquity,
            yaw=yaw,
            omega=omega,
            azimuth=azimuth,
            start=None if start is None else list(start),
            stop_at_reversal=stop_at_reversal,
        ),
    )
    return _record_model(ds, pr, spin_about)


def run_impact(
    projectile: str | Projectile,
    target: str | Target,
    velocity: float,
    obliquity: float = 0.0,
    yaw: float = 0.0,
    omega: float = 0.0,
    *,
    start: tuple[float, float, float] | None = None,
    azimuth: float = 0.0,
    stop_at_reversal: bool = False,
    numerics: Numerics | None = None,
    prepared: _Prepared | None = None,
    shank: ShankModel | Mapping[str, Any] | str | None = None,
    emulation: Emulation | Mapping[str, Any] | None = None,
    spin_about: str = "cm",
    **overrides: Any,
) -> RunResult:
    """:func:`simulate` without building the Dataset: the raw run (SI units).

    Same arguments, checks and errors as :func:`simulate`, and the same run to the last
    bit; for searches that need only a verdict (``.reversed``, ``.outcome``), where the
    Dataset would cost ~15 % of a trajectory. ``.ys`` is the state history (see
    :mod:`pencore.dynamics`), ``.ts`` its times (s).
    """
    return _impact(
        projectile, target, velocity, obliquity, yaw, omega, start, azimuth,
        stop_at_reversal, numerics, prepared, shank, emulation, spin_about, overrides,
    )[1]  # fmt: skip


def _impact(
    projectile: Any,
    target: Any,
    velocity: Any,
    obliquity: Any,
    yaw: Any,
    omega: Any,
    start: Any,
    azimuth: Any,
    stop_at_reversal: Any,
    numerics: Any,
    prepared: Any,
    shank: Any,
    emulation: Any,
    spin_about: str,
    overrides: Mapping[str, Any],
) -> tuple[_Prepared, RunResult, float, tuple]:
    """Check the inputs, prepare, integrate; ``(prepared, run, wall s, checked inputs)``."""
    velocity, obliquity, yaw, omega, azimuth, start = _check_inputs(
        velocity, obliquity, yaw, omega, azimuth, start
    )
    if not isinstance(stop_at_reversal, bool):
        raise InputError(f"stop_at_reversal must be True or False, got {stop_at_reversal!r}")
    if prepared is not None and not isinstance(prepared, _Prepared):
        raise InputError(f"prepared must come from pencore.solver.prepare, got {prepared!r}")
    if prepared is not None and (shank is not None or emulation is not None):
        raise InputError("pass shank= and emulation= to pencore.prepare, not with prepared=")
    pr = prepared or prepare(
        projectile, target, numerics, shank=shank, emulation=emulation, **overrides
    )
    num = pr.numerics
    y0 = initial_state(
        pr.projectile,
        pr.rings,
        velocity,
        math.radians(obliquity),
        math.radians(yaw),
        omega,
        start,
        math.radians(azimuth),
        spin_about,
    )
    _check_reaches_target(y0, body_reach(pr.rings), num)
    t0 = time.perf_counter()
    run = _run(pr, y0, velocity, stop_at_reversal)
    wall = time.perf_counter() - t0
    _raise_on_failure(run, num)
    return pr, run, wall, (velocity, obliquity, yaw, omega, azimuth, start)


def _record_model(ds: xr.Dataset, pr: _Prepared, spin_about: str) -> xr.Dataset:
    """Add the shank model, emulation and spin centre to the attributes and inputs_json,
    when they are not the defaults (default datasets stay exactly as they were)."""
    extra: dict[str, Any] = {}
    if not pr.shank.is_default:
        extra["shank"] = json.loads(to_json(pr.shank))
    if not pr.emulation.is_default or pr.emulation.surface != "rings":
        extra["emulation"] = json.loads(to_json(pr.emulation))
    if spin_about != "cm":
        extra["spin_about"] = spin_about
    if extra:
        inputs = json.loads(ds.attrs["inputs_json"])
        inputs.update(extra)
        ds.attrs["inputs_json"] = json.dumps(inputs, default=str)
        ds.attrs["shank_model"] = pr.shank.describe()
        ds.attrs["emulation"] = pr.emulation.describe()
    return ds


def _run(pr: _Prepared, y0: np.ndarray, velocity: float, stop_at_reversal: bool) -> RunResult:
    """Integrate with the selected method (the arrays of ``pr``, SI units)."""
    num = pr.numerics
    length = pr.projectile.length
    atol = (
        num.rtol
        * np.array([length] * 3 + [1.0] * 4 + [velocity] * 3 + [velocity / length] * 3)
        * 1e-2
    )
    kw = dict(
        t_max=num.t_max,
        rtol=num.rtol,
        atol=atol,
        # a step must not jump over a thin plate or gap: at most half the thinnest layer
        # (no change for the paper's half-spaces, or layers thicker than 2 max_travel)
        max_travel=min(num.max_travel, 0.5 * pr.target.thinnest),
        v_stop=num.v_stop,
        stop_at_reversal=stop_at_reversal,
        max_steps=num.max_steps,
        max_wall=num.max_wall,
        mass=pr.mass,
        inertia=pr.inertia,
        gravity=np.array([0.0, -num.gravity, 0.0]),
        rings=pr.rings,
        bounds=pr.bounds,
        coef=pr.coef,
        fric=pr.fric,
        eps=num.eps,
        n_gauss=num.n_gauss if not pr.target.frictionless else 0,
    )
    if pr.model is not None:
        kw.update(rings=pr.kernel_rings, model=pr.model)
    if pr.emulation.integrator == "explicit":
        from .explicit import integrate_explicit

        for key in ("rtol", "atol", "max_travel", "eps"):
            del kw[key]
        kw.setdefault("model", _default_model())
        return integrate_explicit(y0, dt=pr.emulation.dt, **kw)
    if num.method == "rosenbrock":
        # a chunk of steps that moves less than this has stalled (see integrate());
        # 1 % of the body length, unless the user asked for steps that short
        stall = min(1e-2 * length, 0.1 * CHUNK_STEPS * num.max_travel)
        return integrate(
            y0,
            h_init=1e-7,
            h_min=num.h_min,
            stall_distance=stall,
            reach=body_reach(pr.rings),
            jacobian_age=num.jacobian_age,
            jacobian=num.jacobian,
            **kw,
        )
    from .reference import integrate_scipy

    return integrate_scipy(y0, method=num.method, **kw)


def _raise_on_failure(run: RunResult, num: Numerics) -> None:
    """A :class:`SolverError` naming the cause and the last state, for failed runs."""
    causes = {
        "step_limit": f"step budget of {num.max_steps} steps used up (raise numerics "
        "max_steps, or loosen rtol)",
        "wall_limit": f"wall-time budget of {num.max_wall:g} s used up (raise numerics max_wall)",
        "step_underflow": f"the step needed for rtol {num.rtol:g} fell below h_min = "
        f"{num.h_min:g} s: the contact law is too stiff or chatters"
        + (" (eps = 0 is the discontinuous law: use eps > 0)" if num.eps == 0.0 else ""),
        "non_finite": "the state became infinite or NaN (a runaway)",
        "chatter": f"the steps stalled: {CHUNK_STEPS} accepted steps moved the body less "
        "than 1 % of its length and changed its speed by less than 1 % (the contact law "
        "chatters)"
        + (" (eps = 0 is the discontinuous law: use eps > 0)" if num.eps == 0.0 else ""),
    }
    if run.outcome not in causes:
        return
    y = run.ys[-1]
    raise SolverError(
        f"{causes[run.outcome]}; at t = {run.ts[-1]:.4g} s after {run.ts.size - 1} steps "
        f"the centre of mass was at ({y[0]:.4g}, {y[1]:.4g}, {y[2]:.4g}) m moving at "
        f"{math.sqrt(y[7] ** 2 + y[8] ** 2 + y[9] ** 2):.4g} m/s"
    )
