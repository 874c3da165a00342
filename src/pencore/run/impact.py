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

import inspect
import json
import math
import time
from collections.abc import Callable, Mapping
from typing import Any, ParamSpec

import numpy as np
import xarray as xr

from pencore.errors import InputError, SolverError, hint_keywords, interrupted_import
from pencore.inputs.geometry import Projectile
from pencore.inputs.library import get_projectile, get_target
from pencore.inputs.limits import flag, plausible
from pencore.inputs.models import Emulation, ShankModel, emulation, shank_model, to_json
from pencore.inputs.numerics import Numerics, check_keywords, keywords_checked, resolve_numerics
from pencore.inputs.regime import warn_outside
from pencore.inputs.target import Target
from pencore.integrators.driver import CHUNK_STEPS, RunResult
from pencore.integrators.problem import Problem
from pencore.integrators.rosenbrock import integrate, integrate_chunk
from pencore.kernels.cache import COMPILE_NOTICE, compiled_in_cache
from pencore.kernels.cache import compile_notice as _compile_notice
from pencore.kernels.forces import kernel_model, rhs_model
from pencore.kernels.state import body_reach
from pencore.run.band import attach_depth_band
from pencore.run.dataset import trajectory_dataset
from pencore.run.initial import (
    _check_inputs,
    _check_reaches_target,
    initial_state,
)
from pencore.run.loads import body_loads

__all__ = ["prepare", "simulate", "run_impact", "COMPILE_NOTICE", "compiled_in_cache"]


@keywords_checked
def prepare(
    projectile: Any,
    target: Any,
    numerics: Numerics | None = None,
    *,
    shank: ShankModel | Mapping[str, Any] | str | None = None,
    emulation: Emulation | Mapping[str, Any] | None = None,
    **overrides: Any,
) -> Problem:
    """Resolve a projectile and a target into a problem many trajectories can share.

    Builds what every run of one projectile in one target needs (the surface rings, the
    target's layer arrays, mass properties, the shank model and emulation), once. Pass the
    result as ``simulate(..., prepared=pr)`` in loops over speeds or angles; the searches
    (:func:`~pencore.vcr`, :func:`~pencore.ballistic_limit`...) do so.

    Parameters
    ----------
    projectile : str, Projectile or dict
        A library name (:func:`~pencore.projectile_names`), a YAML file path, a
        :class:`~pencore.Projectile`, or a mapping as in a YAML file
        (:func:`~pencore.get_projectile`).
    target : str, Target, Medium or dict
        A library name (:func:`~pencore.target_names`), a YAML file path or an object
        (:func:`~pencore.get_target`).
    numerics : Numerics, optional
        Numerical parameters (default :class:`~pencore.Numerics` ()); ``**overrides`` apply on top.
    shank : ShankModel, mapping or str, optional
        Shank contact model (:class:`~pencore.ShankModel`): ``"dafl"`` (default), ``"cavity"`` or
        ``"factor"``.
    emulation : Emulation or mapping, optional
        Paper-emulation numerics (:class:`~pencore.Emulation`): panel surface, explicit integrator.
        Default: pencore's rings and the adaptive Rosenbrock integrator.
    **overrides
        Fields of :class:`~pencore.Numerics` by name (``rtol=1e-8``, ``n_nose=64``...).

    Returns
    -------
    pencore.integrators.problem.Problem
        The resolved inputs (``.projectile``, ``.target``, ``.numerics``) and the arrays
        the compiled kernels take.

    Raises
    ------
    InputError
        An unknown name or field, a value out of its range (the message names it and the
        allowed range), a file that cannot be read, or a numerics ``method`` other than
        ``"rosenbrock"`` combined with the explicit integrator or the cavity model.

    Examples
    --------
    >>> import pencore
    >>> pr = pencore.prepare("p2", "soil")
    >>> print(pr.projectile.name, pr.target.name, f"{pr.mass:.3f} kg")
    p2 soil 23.160 kg
    >>> for v in (200.0, 300.0):
    ...     ds = pencore.simulate("p2", "soil", v, prepared=pr)
    ...     print(f"{v:.0f} m/s: {ds.penetration_depth.item():.2f} m")
    200 m/s: 2.68 m
    300 m/s: 4.50 m
    """
    check_keywords(overrides, _PREPARE_KEYWORDS, "prepare")
    num = resolve_numerics(numerics, overrides)
    sm = shank_model(shank)
    em = _emulation(emulation)
    if num.method != "rosenbrock" and (em.integrator == "explicit" or sm.kind == "cavity"):
        what = "the explicit integrator" if em.integrator == "explicit" else "the cavity model"
        raise InputError(
            f"numerics method {num.method!r} cannot be combined with {what}; "
            "use method 'rosenbrock'"
        )
    p = get_projectile(projectile)
    # a law that depends on the projectile (a crater rule, a size term) resolved for it:
    # the run's Dataset records the resolved medium and its source
    t = get_target(target).for_projectile(p.diameter, p.nose_length)
    t.check_plates(p.diameter)
    mp = p.mass_properties()
    ring_set = p.rings(num.n_nose, num.n_shank, num.n_face)
    rings = ring_set.as_array()
    bounds, coef, fric = t.kernel_arrays(p.diameter, mp.mass, p.nose_length, mp.lc, p.nose)
    inertia = np.array([mp.i_axial, mp.i_transverse, mp.i_transverse])
    pr = Problem(p, t, num, rings, bounds, coef, fric, mp.mass, inertia, mp.lc, sm, em)
    if not (sm.is_default and em.surface == "rings"):
        pr.kernel_rings, pr.model = kernel_model(
            p, ring_set, sm, em, num.n_nose, num.n_shank, num.n_face
        )
    return pr


_emulation = emulation
_PREPARE_KEYWORDS = tuple(inspect.signature(prepare).parameters)


@keywords_checked
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
    prepared: Problem | None = None,
    shank: ShankModel | Mapping[str, Any] | str | None = None,
    emulation: Emulation | Mapping[str, Any] | None = None,
    spin_about: str = "cm",
    loads: bool = True,
    **overrides: Any,
) -> xr.Dataset:
    """Simulate one impact: the trajectory of a rigid projectile in a target.

    The projectile's nose tip starts at the surface (or at ``start``) with the impact
    velocity; the run ends when the projectile stops, turns back out of the target, leaves
    it (a ricochet, ``exited``) or perforates its last layer. Conventions (the module's
    text above): the target is ``y <= 0``, the projectile moves towards ``+x`` and ``-y``.

    Parameters
    ----------
    projectile : str, Projectile or dict
        A library name (``"p1"``..``"p4"`` of the paper, the validation projectiles:
        :func:`~pencore.projectile_names`), a YAML file path, or an object
        (:func:`~pencore.get_projectile`).
    target : str, Target, Medium or dict
        A library name (``"soil"``, ``"concrete"``, ``"aluminium"``...:
        :func:`~pencore.target_names`), a YAML file path, or an object
        (:func:`~pencore.get_target`).
    velocity : float
        Impact speed (m/s), > 0.
    obliquity : float, default 0
        Angle of the projectile axis from the target normal ``-y``, towards ``+x`` (deg).
    yaw : float, default 0
        Velocity angle minus axis angle (deg): the velocity makes ``obliquity + yaw``
        with the normal.
    omega : float, default 0
        Initial angular velocity about ``+z`` (rad/s); positive turns the nose towards
        ``+x``.
    start : (3,) float, optional
        Initial nose-tip position (m), in order, with ``y >= 0`` (at or above the
        surface). Default: ``x = z = 0``, the body lowered until its
        lowest surface point touches ``y = 0``.
    azimuth : float, default 0
        Rotation of the whole impact about the target normal ``+y`` (deg).
    stop_at_reversal : bool, default False
        End the run at the first reversal (outcome ``reversed``), as the Vcr search does.
    numerics : Numerics, optional
        Numerical parameters; keyword ``**overrides`` (``rtol=...``, ``eps=...``) apply
        on top.
    prepared : pencore.integrators.problem.Problem, optional
        Output of :func:`~pencore.prepare` for this projectile and target, to skip re-resolving in
        loops (it carries the numerics, shank model and emulation: do not pass those too).
    shank : ShankModel, mapping or str, optional
        Shank contact model (:class:`~pencore.ShankModel`): ``"dafl"`` (default), ``"cavity"``,
        ``"factor"``.
    emulation : Emulation or mapping, optional
        Paper-emulation numerics (:class:`~pencore.Emulation`): panels, explicit integrator.
    spin_about : {"cm", "tip"}, default "cm"
        The point ``omega`` turns the body about at t = 0.
    loads : bool, default True
        Add the loads on the body at each saved state (``axial_force``, ``lateral_force``
        in N, ``deceleration`` in m/s^2 and ``deceleration_g`` in g, their peaks in the
        attributes; :mod:`pencore.run.loads`). They are the solver's own contact force,
        evaluated once per saved state after the run (about a fifth of a run's time);
        ``False`` skips them, for loops that read only the path.
    **overrides
        Fields of :class:`~pencore.Numerics` by name.

    Returns
    -------
    xarray.Dataset
        Time histories on dimension ``time`` (s), scalar results (``penetration_depth``,
        m...) and attributes (``outcome``, ``reversed``, the inputs); every variable has
        ``units`` and ``long_name``. The user guide's Dataset page lists them.

    Raises
    ------
    InputError
        An unknown name, a value out of its range or of the wrong type (the one-line
        message names the value and what is allowed), a start position from which the
        body cannot reach the target, or ``prepared`` given with ``numerics``, ``shank``
        or ``emulation``.
    SolverError
        The integration could not finish (step size underflow, step budget or wall-time
        limit); the message names the cause and the state reached.

    Examples
    --------
    Projectile #2 of the paper into soil at 280 m/s, normal impact:

    >>> import pencore
    >>> ds = pencore.simulate("p2", "soil", 280.0)
    >>> ds.attrs["outcome"]
    'stopped'
    >>> print(f"{ds.penetration_depth.item():.2f} {ds.penetration_depth.units}")
    4.15 m

    At 45 deg obliquity the path curves (the paper's Fig. 7):

    >>> ds = pencore.simulate("p2", "soil", 1000.0, obliquity=45.0)
    >>> print(ds.attrs["outcome"], f"{pencore.final_deviation(ds):.0f} deg")
    stopped 46 deg

    The loads: the peak axial deceleration, in g:

    >>> print(f"{ds.attrs['peak_deceleration_g']:.0f} g")
    13754 g
    """
    pr, run, wall, (velocity, obliquity, yaw, omega, azimuth, start) = _impact(locals(), loads)
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
            stop_at_reversal=bool(stop_at_reversal),
        ),
        loads=body_loads(pr, run) if loads else None,
    )
    ds = attach_depth_band(ds, pr.projectile, pr.target, velocity, bool(obliquity or yaw))
    return _record_model(ds, pr, spin_about)


_P = ParamSpec("_P")


def _arguments_of(
    public: Callable[_P, Any],
) -> Callable[[Callable[..., RunResult]], Callable[_P, RunResult]]:
    """Give the decorated function the parameters of ``public`` (for ``help``, the API
    docs and type checkers), so that one signature is written once."""

    def give(f: Callable[..., RunResult]) -> Callable[_P, RunResult]:
        sig = inspect.signature(public)
        f.__signature__ = sig.replace(return_annotation="RunResult")  # type: ignore[attr-defined]
        return f  # type: ignore[return-value]

    return give


@keywords_checked
@_arguments_of(simulate)
def run_impact(*args: Any, **kwargs: Any) -> RunResult:
    """:func:`simulate` without building the Dataset: the raw run (SI units).

    Same arguments, checks and errors as :func:`simulate`, and the same run to the last
    bit; for searches that need only a verdict (``.reversed``, ``.outcome``), where the
    Dataset would cost ~15 % of a trajectory. ``.ys`` is the state history (see
    :mod:`pencore.kernels.dynamics`), ``.ts`` its times (s).
    """
    arguments = _SIMULATE.bind(*args, **kwargs)
    arguments.apply_defaults()
    return _impact(arguments.arguments)[1]


def _impact(a: Mapping[str, Any], loads: bool = False) -> tuple[Problem, RunResult, float, tuple]:
    """Check the inputs, prepare, integrate; ``(prepared, run, wall s, checked inputs)``.

    ``a`` maps each parameter of :func:`simulate` to its value (``overrides``: the dict
    of numerics overrides), every one present; ``loads``: the run keeps what the loads
    are read from."""
    check_keywords(a["overrides"], _SIMULATE.parameters, "simulate")
    stop_at_reversal, prepared = a["stop_at_reversal"], a["prepared"]
    shank, emulation, spin_about = a["shank"], a["emulation"], a["spin_about"]
    velocity, obliquity, yaw, omega, azimuth, start = _check_inputs(
        a["velocity"], a["obliquity"], a["yaw"], a["omega"], a["azimuth"], a["start"]
    )
    flag(a["loads"], "loads")
    stop_at_reversal = flag(stop_at_reversal, "stop_at_reversal")
    if prepared is not None and not isinstance(prepared, Problem):
        raise InputError(f"prepared must come from pencore.run.impact.prepare, got {prepared!r}")
    if prepared is not None and (shank is not None or emulation is not None):
        raise InputError("pass shank= and emulation= to pencore.prepare, not with prepared=")
    if prepared is not None:
        _check_prepared(prepared, a)
    pr = prepared or prepare(
        a["projectile"], a["target"], a["numerics"], shank=shank, emulation=emulation,
        **a["overrides"],
    )  # fmt: skip
    if not pr.regime_warned:  # once per prepared problem: a search warns at most once
        pr.regime_warned = warn_outside(pr.projectile, pr.target, velocity)
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
    # the nose tip reaches further than the outermost ring (up to ~1.5 mm on an ogive)
    if start is not None:
        _check_reaches_target(y0, max(body_reach(pr.rings), pr.lc), num)
        for c, n in zip(start, "xyz", strict=True):  # a start in cm or mm
            plausible(c, "start", f"start {n}")
    t0 = time.perf_counter()
    run = _run(pr, y0, velocity, stop_at_reversal, loads)
    wall = time.perf_counter() - t0
    _raise_on_failure(run, pr)
    return pr, run, wall, (velocity, obliquity, yaw, omega, azimuth, start)


_SIMULATE = inspect.signature(simulate)


def _same(spec: Any, resolved: Any, resolve: Callable[[Any], Any]) -> bool:
    """Whether the projectile or target ``spec`` of a call names ``resolved`` (the one a
    prepared problem holds): the object itself, an equal one, its name, or a name, file
    or mapping that resolves to an equal one."""
    if spec is resolved or (isinstance(spec, str) and spec == resolved.name):
        return True
    try:
        return bool(resolve(spec) == resolved)
    except InputError:
        return False


def _check_prepared(pr: Problem, a: Mapping[str, Any]) -> None:
    """Refuse a prepared problem that is not the one the call names: its projectile,
    target and (when the call gives them) numerics must be the call's, or the run would
    silently be another's."""
    for kind, resolve, held in (
        ("projectile", get_projectile, pr.projectile),
        ("target", get_target, pr.target),
    ):
        if not _same(a[kind], held, resolve):
            given = a[kind] if isinstance(a[kind], str) else getattr(a[kind], "name", a[kind])
            raise InputError(
                f"prepared= holds {kind} {held.name!r}, but the call names {kind} "
                f"{str(given)[:60]!r}; prepare the problem for this {kind} "
                f"(pencore.prepare(projectile, target, ...)) or pass the one it holds"
            )
    if a["numerics"] is not None or a["overrides"]:
        if resolve_numerics(a["numerics"], a["overrides"]) != pr.numerics:
            raise InputError(
                "prepared= carries its own numerics, and the call gives different ones "
                "(numerics= or keyword overrides); pass them to pencore.prepare instead"
            )


def _record_model(ds: xr.Dataset, pr: Problem, spin_about: str) -> xr.Dataset:
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


def _run(
    pr: Problem, y0: np.ndarray, velocity: float, stop_at_reversal: bool, loads: bool = False
) -> RunResult:
    """Integrate with the selected integrator: the explicit scheme of the paper
    emulation, the compiled Rosenbrock pair (keeping its derivatives when the loads are
    wanted), or scipy's reference (SI units)."""
    options: dict[str, bool] = {}
    if pr.emulation.integrator == "explicit":
        from pencore.integrators.explicit import explicit_chunk as compiled
        from pencore.integrators.explicit import integrate_explicit as integrator
    elif pr.numerics.method == "rosenbrock":
        integrator, compiled = integrate, integrate_chunk
        options["keep_derivatives"] = loads
    else:
        try:
            from pencore.integrators.scipy_ivp import integrate_scipy as integrator
        except ImportError as exc:
            if interrupted_import(exc):  # Ctrl-C while scipy loads: the caller's Ctrl-C
                raise KeyboardInterrupt from exc
            raise
        compiled = rhs_model
    _compile_notice(compiled)
    return integrator(pr, y0, velocity, stop_at_reversal=stop_at_reversal, **options)


def _small_step_cause(num: Numerics) -> str:
    """Why a run takes steps too small to finish, in words: a tolerance near round-off,
    the discontinuous law, or else chatter."""
    if num.rtol < 1e-9:
        return f"rtol = {num.rtol:g} is near round-off (loosen rtol)"
    if num.eps == 0.0:
        return "the contact law chatters (eps = 0 is the discontinuous law: use eps > 0)"
    return "the contact law is too stiff or chatters"


def _raise_on_failure(run: RunResult, pr: Problem) -> None:
    """A :class:`SolverError` naming the cause and the last state (the last accepted
    step), for failed runs."""
    num = pr.numerics
    small = _small_step_cause(num)
    budget = f"step budget of {num.max_steps} steps"
    if num.method != "rosenbrock" and pr.emulation.integrator != "explicit":
        from pencore.integrators.scipy_ivp import CALLS_PER_STEP

        # scipy's methods count right-hand-side calls, so the steps can outnumber it
        budget += f" ({CALLS_PER_STEP * num.max_steps} right-hand-side calls of {num.method})"
    causes = {
        "step_limit": f"{budget} used up (raise numerics max_steps, or loosen rtol)",
        "wall_limit": f"wall-time budget of {num.max_wall:g} s used up (raise numerics max_wall)",
        "step_underflow": f"the step needed for rtol {num.rtol:g} fell below h_min = "
        f"{num.h_min:g} s: {small}",
        "non_finite": "the state became infinite or NaN (a runaway)",
        "chatter": f"the steps stalled: {CHUNK_STEPS} accepted steps moved the body less "
        f"than 1 % of its length and changed its speed by less than 1 %: {small}",
    }
    if run.outcome not in causes:
        return
    y = run.ys[-1]
    raise SolverError(
        f"{causes[run.outcome]}; at t = {run.ts[-1]:.4g} s after {run.ts.size - 1} steps "
        f"the centre of mass was at ({y[0]:.4g}, {y[1]:.4g}, {y[2]:.4g}) m moving at "
        f"{math.sqrt(y[7] ** 2 + y[8] ** 2 + y[9] ** 2):.4g} m/s"
    )


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
