"""Resistance laws computed from material properties: the polynomial
:class:`~pencore.inputs.target.Medium` ``sigma_n = a0 + a1 Vn + a2 Vn^2`` (Pa) of a concrete,
a metal or a soil, each a named law with its source and its valid range.

=========  ==================================================  ================================
law        normal stress on the nose                           inputs
=========  ==================================================  ================================
concrete   ``S fc + rho Vn^2``, ``S = 82.6 fc^-0.544``         fc (Pa), density; S if measured
metal      ``A Y + B rho Vn^2``, spherical cavity expansion    E, nu, Y, hardening n, density
soil       ``A tau0 + B rho Vn^2`` (Forrestal & Luk)           A, tau0, B, density
=========  ==================================================  ================================

Concrete and grout (:func:`concrete_law`)
    Forrestal's form, paper Table 1's concrete law: ``sigma_n = S fc + rho Vn^2``.
    ``S`` is Forrestal's empirical strength factor; without a measured one it is taken
    from the compressive strength, ``S = 82.6 fc^-0.544`` (fc in MPa; Frew, Hanchak, Green
    & Forrestal, "Penetration of concrete targets with ogive-nose steel rods", IJIE 21
    (1998) 489-497, as quoted by Li & Chen, IJIE 28 (2003) 93-116). At fc = 13.5 MPa this
    gives S = 20.05, not the S = 21 of paper Table 1 (which cites Forrestal et al. 1994):
    21 is the value fitted by Forrestal and co-authors to their own grout shots; the fitting
    paper was not readable here, so ``S`` can be given. The crater option of the medium
    (``crater_depth``, Forrestal's ``F = c z`` over 2 calibers) is passed through.

    Named options (none changes the default): ``s_model="li_chen"``, ``S = 72 fc^-0.5``
    (Li & Chen, IJIE 28 (2003) 93-116, Eq. 21; secondary, :data:`S_LI_CHEN_SOURCE`);
    ``crater="forrestal"`` (2 calibers) or ``"li_chen"`` (``0.707 + H/d`` calibers, their
    Eq. 25, H the nose length, set with the projectile); ``size_term="fit"``, ``S(fc) f(d)``
    of the form of Bazant's size-effect law with a declared fitted constant
    (:data:`~pencore.inputs.laws.SIZE_TERM_FILE`, :mod:`pencore.studies.validation.size_term`), set
    with the
    projectile's diameter (:meth:`~pencore.inputs.target.Medium.for_projectile`).
Metals (:func:`metal_law`, :func:`cavity_expansion`)
    The spherical cavity-expansion solution for an elastic-plastic solid with power-law
    strain hardening, ``sigma = E eps`` below ``Y`` and ``sigma = Y (E eps / Y)^n`` above:
    the radial stress at a cavity opening at constant speed V is ``Y A + B rho V^2``.

    * quasi-static ``A`` by the integral of Forrestal, Okajima & Luk (J. Appl. Mech. 55,
      1988, 755-760) with Hill's compressible elastic zone::

          A = 2/3 [1 + K^n I_n],   K = E / (3 (1 - nu) Y),
          I_n = integral_0^(1 - 1/K) (-ln x)^n / (1 - x) dx
              = integral_0^(ln K) (-ln(1 - e^-u))^n du

      At ``n = 0`` it is Hill's limit pressure, ``A = 2/3 (1 + ln K)`` (Hill, *The
      Mathematical Theory of Plasticity*, 1950, ch. V); at ``nu = 1/2`` it is the printed
      incompressible formula, ``K = 2E/(3Y)``; at ``n = 1``,
      ``I_1 = pi^2/6 - Li2(1/K)`` in closed form.
    * inertial ``B`` (:func:`compressible_inertia`), by default from the dynamic
      solution for a compressible elastic-perfectly plastic solid (the formulation of
      Forrestal & Luk, J. Appl. Mech. 55, 1988, 275-279, as derived here): a cavity opening
      from zero radius at constant speed ``V``; all fields depend on ``xi = r / (c t)``,
      ``c = sqrt(E / rho)``; behind the elastic-plastic boundary ``xi = gamma`` the Tresca
      condition ``sigma_r - sigma_theta = Y`` holds with the pressure ``K eta``
      (``K = E / (3 (1 - 2 nu))``, ``eta = 1 - rho0 / rho``), and momentum and mass
      balance are two ordinary differential equations in ``xi``, integrated from the
      elastic solution at ``gamma`` (``u = k c t (a^3/xi^2 - 3a + 2 xi)``, ``a`` the
      dilatational over ``c``) inwards to the cavity wall, where the particle speed equals
      the wall's. ``B`` is the least-squares slope of ``sigma_r / Y - A_0`` against
      ``rho V^2 / Y`` over ``0 < V <= max_speed``. The solution tends to Hill's
      quasi-static pressure as ``V -> 0`` (to order ``Y/E ln(E/Y)``) and to the
      incompressible ``B = 3/2`` as ``nu -> 1/2``; for an incompressible solid the velocity
      field is ``a^2 da/dt / r^2`` whatever the constitutive law, and the momentum balance
      adds exactly ``rho (a d2a/dt2 + 3/2 (da/dt)^2)`` to the static stress (the
      ``inertia="incompressible"`` choice). Strain hardening enters ``A`` only (Luk,
      Forrestal & Amos, J. Appl. Mech. 58, 1991, 1-6, solve the hardening dynamic problem;
      not done here).
    * no strain-rate term: Piekutowski et al. (1999) use ``Y (A + B V/c + C V^2/c^2)``
      with the constants of Warren & Forrestal (1998), whose linear term comes from the
      strain-rate sensitivity of the target; this law has no rate sensitivity and no
      linear term (the user guide's page "Your own projectile and target" states what
      that costs on the aluminium rods).
Soils (:func:`soil_law`)
    The Forrestal-Luk form of paper Table 1's soil, ``sigma_n = A tau0 + B rho Vn^2``,
    with its parameters as inputs (no readable source computes A and B from soil
    properties here).

Every law returns a :class:`~pencore.inputs.target.Medium` whose ``source`` names the law,
the inputs and the constants; a value outside its range (:data:`~pencore.inputs.limits.LIMITS`)
is refused with one line, with a hint when it looks like a unit slip (MPa or GPa given as
Pa); a value inside it but outside the range a law was built on gives a
:class:`~pencore.errors.PlausibilityWarning`.
"""

from __future__ import annotations

import functools
import math
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np

from pencore.errors import (
    InputError,
    PlausibilityWarning,
    TargetError,
    hint_keywords,
    keyword_hints,
)
from pencore.inputs.gate import brief
from pencore.inputs.limits import (
    LIMITS,
    _caller_level,
    as_float,
    check_keys,
    flag,
    integer,
    number,
    plausible,
)
from pencore.inputs.record import DEFAULT_RECORD_LAW, RECORD_LAWS
from pencore.inputs.target import Medium, SizeTerm

__all__ = [
    "LAWS",
    "CavityExpansion",
    "cavity_expansion",
    "CompressibleInertia",
    "compressible_inertia",
    "forrestal_s",
    "li_chen_s",
    "size_term_constants",
    "concrete_law",
    "metal_law",
    "soil_law",
    "concrete",
    "metal",
    "soil",
    "medium_from_law",
    "SIZE_TERM_FILE",
]

#: Source of ``S = 82.6 fc^-0.544``.
S_FC_SOURCE = (
    "Frew, Hanchak, Green & Forrestal, IJIE 21 (1998) 489-497, as quoted by Li & Chen, "
    "IJIE 28 (2003) 93-116"
)
#: Source of ``S = 72 fc^-0.5`` (secondary: the paper itself was not read here).
S_LI_CHEN_SOURCE = (
    "Li & Chen, IJIE 28 (2003) 93-116, Eq. 21, as quoted (secondary) by "
    "github.com/endofwave/engineering-tools, content/series-a/a4-penetration-depth"
)
#: The named ``S(fc)`` forms of :func:`concrete_law`'s ``s_model``.
S_MODELS = ("forrestal", "li_chen")
#: The named crater options of :func:`concrete_law`'s ``crater``.
CRATERS = ("none", "forrestal", "li_chen")
#: Forrestal's crater region (calibers; Forrestal et al., IJIE 15 (1994) 395-405).
FORRESTAL_CRATER = 2.0
#: The named size terms of :func:`concrete_law`'s ``size_term``.
SIZE_TERMS = ("none", "fit")
#: The constants of the declared size-term fit, with their provenance.
SIZE_TERM_FILE = Path(__file__).parent / "data" / "concrete_size_term.yaml"


@functools.lru_cache(maxsize=1)
def size_term_constants() -> dict[str, Any]:
    """The size term's constants file (:data:`~pencore.inputs.laws.SIZE_TERM_FILE`): ``d_ref_m``,
    ``exponent``, the rows and files it was fitted to, and per ``"s_model/crater"`` the
    fitted ``d0_m`` (see :mod:`pencore.studies.validation.size_term`)."""
    import yaml

    return yaml.safe_load(SIZE_TERM_FILE.read_text())


#: The compressive strengths (Pa) of the Sandia/WES shots of Forrestal's family (12.9 to
#: 76.2 mm steel rods into grout and concrete), the range the concrete form was built on:
#: 13.5 to 108 MPa (the secondary compilation DavidZyh-0319/Concrete-Penetration-Failure-
#: Response-Dataset, Data.xlsx); outside it S(fc) is extrapolated.
FC_SHOTS = (13.5e6, 108e6)
#: Densities (kg/m^3) of grouts and concretes (plausibility only).
CONCRETE_DENSITY = (1500.0, 3000.0)
#: The least ``rho V^2 / Y`` at the top of the compressible fit of ``B``
#: (:func:`compressible_inertia`): below it the inertial stress the fit measures is lost in
#: the cavity solution's numerical error, and ``B`` is wrong by any amount (6061-T6:
#: ``B = 1.27`` at 3 m/s, ``rho V^2 / Y = 9e-5``, 2.6 at 0.3 m/s, 13.3 at 0.1 m/s; 1.15 at
#: 1000 m/s). At 1e-4, ``B`` is within 2 % of its value at 100 times the load for four
#: solids from a polymer to a 1 GPa steel (``tests/inputs/test_laws.py``).
B_FIT_MIN_LOAD = 1e-4


def _value(value: Any, key: str, what: str, name: str) -> float:
    """``value`` in ``LIMITS[key]`` (text in plain decimal accepted), else
    :class:`~pencore.errors.TargetError` naming ``name``, with a unit hint for a value that
    is in range once multiplied by 1e6 or 1e9 (MPa or GPa given as Pa)."""
    try:
        return number(value, key, what, allow_str=True, label=name)
    except InputError as exc:
        msg = str(exc)
        lim = LIMITS[key]
        v = as_float(value, allow_str=True)
        if lim.unit == "Pa" and v is not None and 0 < v < lim.lo:
            for factor, unit in ((1e6, "MPa"), (1e9, "GPa")):
                if lim.contains(v * factor):
                    msg += f" (in {unit}? {name} is in Pa: {v:g} {unit} is {v * factor:g})"
                    break
        raise TargetError(msg) from None


def _whole(value: Any, key: str, what: str, name: str) -> int:
    """``value`` as a whole number in ``LIMITS[key]``, else
    :class:`~pencore.errors.TargetError` naming ``name``."""
    try:
        return integer(value, key, f"{what}: {name}")
    except InputError as exc:
        raise TargetError(str(exc)) from None


def _flag(value: Any, what: str, name: str) -> bool:
    """``value`` as a bool (Python's or numpy's), else :class:`~pencore.errors.TargetError`."""
    try:
        return flag(value, f"{what}: {name}")
    except InputError as exc:
        raise TargetError(str(exc)) from None


def _plausible(value: float, lo: float, hi: float, name: str, unit: str, why: str) -> None:
    if not lo <= value <= hi:
        warnings.warn(
            f"{name} = {value:g} {unit} is outside {lo:g}-{hi:g} {unit}, {why}",
            PlausibilityWarning,
            stacklevel=_caller_level(),  # the user's call, as pencore's other warnings
        )


def forrestal_s(fc: float) -> float:
    """Forrestal's strength factor from the compressive strength, ``S = 82.6 fc^-0.544``.

    Parameters
    ----------
    fc : float
        Unconfined compressive strength (Pa); the fit takes it in MPa.

    Returns
    -------
    float
        ``S`` (dimensionless). Source: :data:`S_FC_SOURCE`.

    Examples
    --------
    >>> from pencore.inputs.laws import forrestal_s
    >>> print(f"{forrestal_s(13.5e6):.2f}")
    20.05
    """
    fc = _value(fc, "fc", "concrete law", "fc")
    return 82.6 * (fc / 1e6) ** -0.544


def li_chen_s(fc: float) -> float:
    """Li & Chen's strength factor from the compressive strength, ``S = 72 fc^-0.5``.

    Parameters
    ----------
    fc : float
        Unconfined compressive strength (Pa); the form takes it in MPa.

    Returns
    -------
    float
        ``S`` (dimensionless). Source: :data:`S_LI_CHEN_SOURCE` (their Eq. 21, a
        simplification of ``82.6 fc^-0.544`` that makes their impact number go as
        ``fc^-1/2``; fitted to the same Sandia/WES shots, not to new ones).

    Examples
    --------
    >>> from pencore.inputs.laws import li_chen_s
    >>> print(f"{li_chen_s(36e6):.2f}")
    12.00
    """
    fc = _value(fc, "fc", "concrete law", "fc")
    return 72.0 * (fc / 1e6) ** -0.5


def _choice(value: Any, key: str, choices: tuple[str, ...]) -> str:
    """``value`` if it names one of ``choices``, else a one-line :class:`TargetError`."""
    if not isinstance(value, str) or value not in choices:
        raise TargetError(
            f"concrete law: {key} must be one of {', '.join(choices)}, got {brief(value)}"
        )
    return value


@keyword_hints  # before LAWS holds it
def concrete_law(
    fc: float,
    density: float,
    s: float | None = None,
    *,
    name: str = "concrete",
    crater_depth: float = 0.0,
    friction: float = 0.0,
    s_model: str | None = None,
    crater: str | None = None,
    size_term: str | None = None,
) -> Medium:
    """A concrete or grout by Forrestal's form, ``sigma_n = S fc + rho Vn^2``.

    Parameters
    ----------
    fc : float
        Unconfined compressive strength (Pa), in ``LIMITS["fc"]``.
    density : float
        Target density ``rho`` (kg/m^3).
    s : float, optional
        Forrestal's ``S`` when measured (fitted to shots); default from ``s_model``.
    name : str
        The medium's label.
    crater_depth : float
        Forrestal's crater region in calibers (0: off; Forrestal: 2), see
        :class:`~pencore.inputs.target.Medium`; or name it with ``crater``.
    friction : float
        Constant Coulomb friction coefficient (default 0).
    s_model : {"forrestal", "li_chen"}, optional
        ``S`` from fc when ``s`` is not given: ``"forrestal"`` (the default),
        ``S = 82.6 fc^-0.544`` (:func:`~pencore.inputs.laws.forrestal_s`); ``"li_chen"``, ``S = 72
        fc^-0.5``
        (:func:`~pencore.inputs.laws.li_chen_s`). Both are fits to the same Sandia/WES shots of
        12.9-76.2 mm
        rods; neither has a size term.
    crater : {"none", "forrestal", "li_chen"}, optional
        The crater region by name: ``"none"`` (the paper's model, the default),
        ``"forrestal"`` (2 calibers, Forrestal et al. 1994), ``"li_chen"``
        (``0.707 + H/d`` calibers, Li & Chen 2003 Eq. 25, H the nose length: resolved with
        the projectile when a run is prepared,
        :meth:`~pencore.inputs.target.Medium.for_projectile`).
        Give it or ``crater_depth``, not both.
    size_term : {"none", "fit"}, optional
        ``"fit"``: ``S`` falls with the projectile diameter, ``S(fc) f(d)`` with
        ``f = ((1 + d_ref/d0) / (1 + d/d0))^1/2`` (the form of Bazant's size-effect law), 1
        at ``d_ref = 25 mm``; ``d0`` a declared fit per ``s_model`` and ``crater`` to the
        Sandia/WES shots and Wu et al.'s scaled series
        (:mod:`pencore.studies.validation.size_term`, :data:`~pencore.inputs.laws.SIZE_TERM_FILE`),
        applied with
        the projectile's diameter when a run is prepared. Not a published law. Needs ``S``
        from fc (not a given ``s``) and a named crater (not ``crater_depth``). Default
        ``"none"``.

    Returns
    -------
    Medium
        Coefficients ``(S fc, 0, rho)``; the ``source`` names ``S`` and where it is from.

    Raises
    ------
    TargetError
        A value out of its range (one line; a hint when fc looks like MPa).

    Warns
    -----
    PlausibilityWarning
        fc outside the 13.5-108 MPa of the measured shots
        (:data:`~pencore.inputs.laws.FC_SHOTS`), or a density outside 1500-3000 kg/m^3.

    Examples
    --------
    >>> import pencore
    >>> c40 = pencore.concrete_law(fc=40e6, density=2300.0)
    >>> print(f"S = {c40.coefficients[0] / 40e6:.2f}, a0 = {c40.coefficients[0]:.4g} Pa")
    S = 11.10, a0 = 4.441e+08 Pa
    >>> paper = pencore.concrete_law(fc=13.5e6, density=1960.0, s=21.0)
    >>> paper.coefficients == pencore.get_target("concrete").medium.coefficients
    True
    >>> pencore.concrete_law(fc=40, density=2300.0)
    Traceback (most recent call last):
    ...
    pencore.errors.TargetError: concrete law: fc must be in [1e+06, 5e+08] Pa, got 40 (in MPa? ...
    """
    what = "concrete law"
    fc = _value(fc, "fc", what, "fc")
    rho = _value(density, "medium_density", what, "density")
    _plausible(
        fc / 1e6,
        FC_SHOTS[0] / 1e6,
        FC_SHOTS[1] / 1e6,
        "fc",
        "MPa",
        "the range of the measured shots the form was built on (S(fc) is extrapolated)",
    )
    _plausible(rho, *CONCRETE_DENSITY, "density", "kg/m^3", "that of grouts and concretes")
    if s is not None and s_model is not None:
        raise TargetError(f"{what}: give s or s_model, not both (s = {brief(s)})")
    model = "forrestal" if s_model is None else _choice(s_model, "s_model", S_MODELS)
    if s is None and model == "li_chen":
        s_val = li_chen_s(fc)
        s_from = f"S = 72 fc^-0.5 = {s_val:.4g} (fc in MPa; {S_LI_CHEN_SOURCE})"
    elif s is None:
        s_val = forrestal_s(fc)
        s_from = f"S = 82.6 fc^-0.544 = {s_val:.4g} (fc in MPa; {S_FC_SOURCE})"
    else:
        s_val = _value(s, "s_factor", what, "S")
        s_from = f"S = {s_val:g} given"
    crater_rule = ""
    crater_given = crater_depth not in (0, 0.0)  # by number, not by a named crater
    if crater is not None:
        crater = _choice(crater, "crater", CRATERS)
        if crater_depth not in (0, 0.0):
            raise TargetError(
                f"{what}: give crater or crater_depth, not both "
                f"(crater_depth = {brief(crater_depth)})"
            )
        if crater == "forrestal":
            crater_depth = FORRESTAL_CRATER
            s_from += "; crater 2 calibers (Forrestal et al., IJIE 15 (1994) 395-405)"
        elif crater == "li_chen":
            crater_rule = "li_chen"
            s_from += "; crater 0.707 + H/d calibers (Li & Chen 2003, Eq. 25)"
    term = None
    if size_term is None:  # the default law: the record's (DEFAULT_RECORD_LAW) when S is a form
        size_term = RECORD_LAWS[DEFAULT_RECORD_LAW]["size_term"]
        if s is not None or crater_given:
            size_term = "none"
    if _choice(size_term, "size_term", SIZE_TERMS) == "fit":
        if s is not None or crater_given:
            given = f"s = {brief(s)}" if s is not None else f"crater_depth = {brief(crater_depth)}"
            raise TargetError(
                f"{what}: size_term 'fit' was fitted with S from fc and a named crater, not "
                f"with a given {given.split(' = ')[0]} ({given})"
            )
        spec = size_term_constants()
        key = f"{model}/{crater or 'none'}"
        d0 = float(spec["constants"][key]["d0_m"])
        term = SizeTerm(
            d_ref=float(spec["d_ref_m"]),
            d0=d0,
            exponent=float(spec["exponent"]),
            source=f"declared fit {key}, d0 = {d0:.4g} m ({spec['fitted_by']}, {spec['date']})",
            s_ref=s_val,
        )
        s_from += (
            f"; size term f(d) = ((1 + d_ref/d0) / (1 + d/d0))^{float(spec['exponent']):g}, "
            f"d_ref = {float(spec['d_ref_m']):g} m, d0 = {d0:.4g} m (declared fit {key}; "
            "set with the projectile)"
        )
    return Medium(
        name,
        (s_val * fc, 0.0, rho),
        (0.0,),
        (_value(friction, "friction", what, "friction"),),
        rho,
        f"concrete law (Forrestal): S fc + rho Vn^2, fc = {fc / 1e6:g} MPa, "
        f"rho = {rho:g} kg/m3, {s_from}",
        crater_depth=_value(crater_depth, "crater_depth", what, "crater_depth"),
        crater_rule=crater_rule,
        size_term=term,
        fc=fc,
        record_law=_record_law(s, crater_given, friction, model, crater, size_term),
    )


def _record_law(
    s: Any, crater_given: bool, friction: Any, model: str, crater: str | None, size_term: str
) -> str:
    """The record's name of a concrete law (:data:`pencore.inputs.record.RECORD_LAWS`), or
    "" for one the record did not score (a given S or crater depth, friction)."""
    if s is not None or crater_given or friction not in (0, 0.0):
        return ""
    options = {"s_model": model, "crater": crater or "none", "size_term": size_term}
    return next((k for k, v in RECORD_LAWS.items() if v == options), "")


@dataclass(frozen=True)
class CavityExpansion:
    """The spherical cavity-expansion constants of an elastic-plastic, power-law hardening
    solid (:func:`~pencore.inputs.laws.cavity_expansion`).

    Attributes
    ----------
    a : float
        Quasi-static radial stress at the cavity over ``Y``.
    b : float
        Inertial coefficient on ``rho V^2`` (3/2: incompressible).
    k : float
        ``E / (3 (1 - nu) Y)``; ``k^(1/3)`` is the plastic-zone over cavity radius of an
        elastic-perfectly plastic solid (Hill).
    integral : float
        ``I_n`` (see the module docstring).
    integral_error : float
        Estimated absolute error of ``integral`` (quadrature).
    """

    a: float
    b: float
    k: float
    integral: float
    integral_error: float

    @property
    def plastic_zone_ratio(self) -> float:
        """``c/a = k^(1/3)`` of Hill's elastic-perfectly plastic solution."""
        return self.k ** (1.0 / 3.0)


def cavity_expansion(
    youngs_modulus: float,
    poisson_ratio: float,
    yield_strength: float,
    hardening_exponent: float,
) -> CavityExpansion:
    """Quasi-static and inertial constants of the spherical cavity expansion (module
    docstring: ``A = 2/3 [1 + K^n I_n]``, ``B = 3/2``).

    Parameters
    ----------
    youngs_modulus : float
        ``E`` (Pa).
    poisson_ratio : float
        ``nu``, 0 to 1/2.
    yield_strength : float
        ``Y`` (Pa), with ``E / (3 (1 - nu) Y) > 1``.
    hardening_exponent : float
        ``n`` of ``sigma = Y (E eps / Y)^n``, 0 (elastic-perfectly plastic) to below 1.

    Returns
    -------
    CavityExpansion

    Raises
    ------
    TargetError
        A value out of its range, or a yield strength so high that no plastic zone forms.

    Examples
    --------
    Elastic-perfectly plastic: Hill's limit pressure.

    >>> import math
    >>> from pencore.inputs.laws import cavity_expansion
    >>> ce = cavity_expansion(200e9, 0.3, 1e9, 0.0)
    >>> print(f"A = {ce.a:.6f}, Hill {2 / 3 * (1 + math.log(200e9 / (3 * 0.7 * 1e9))):.6f}")
    A = 3.704253, Hill 3.704253
    """
    what = "metal law"
    e = _value(youngs_modulus, "youngs_modulus", what, "E")
    nu = _value(poisson_ratio, "poisson_ratio", what, "nu")
    y = _value(yield_strength, "yield_strength", what, "Y")
    n = _value(hardening_exponent, "hardening_exponent", what, "n")
    k = e / (3.0 * (1.0 - nu) * y)
    if not k > 1.0:
        raise TargetError(
            f"{what}: E / (3 (1 - nu) Y) must be > 1 for a plastic zone to form, got "
            f"{k:.4g} (E = {e:g} Pa, nu = {nu:g}, Y = {y:g} Pa)"
        )
    plausible(e / y, "modulus_over_yield", f"{what} (E = {e:g} Pa, Y = {y:g} Pa)")
    integral, err = _hardening_integral(n, math.log(k))
    return CavityExpansion(
        a=2.0 / 3.0 * (1.0 + k**n * integral), b=1.5, k=k, integral=integral, integral_error=err
    )


def _hardening_integral(n: float, upper: float) -> tuple[float, float]:
    """``integral_0^upper (-ln(1 - e^-u))^n du`` and its error estimate (adaptive
    Gauss-Kronrod, QUADPACK's QAGS: its extrapolation handles the ``(-ln u)^n`` end)."""
    if n == 0.0:
        return upper, 0.0
    from scipy.integrate import quad

    val, err = quad(
        lambda u: (-math.log(-math.expm1(-u))) ** n, 0.0, upper, epsabs=0.0, epsrel=1e-12, limit=200
    )
    return float(val), float(err)


@dataclass(frozen=True)
class CompressibleInertia:
    """The dynamic cavity expansion of a compressible elastic-perfectly plastic solid
    (:func:`~pencore.inputs.laws.compressible_inertia`).

    Attributes
    ----------
    b : float
        Least-squares slope of ``sigma_r / Y - a0`` against ``rho V^2 / Y``.
    a0 : float
        ``sigma_r / Y`` of the solution as ``V -> 0``.
    speeds : tuple of float
        Cavity speeds ``V`` (m/s) of the solutions the fit uses.
    stresses : tuple of float
        ``sigma_r / Y`` at the cavity for each speed.
    max_solvable_speed : float
        The fastest cavity (m/s) this solution can open: the elastic-plastic boundary then
        runs at the plastic bulk wave speed (beyond it a shock forms, not modelled).
    """

    b: float
    a0: float
    speeds: tuple[float, ...]
    stresses: tuple[float, ...]
    max_solvable_speed: float


def _epp_cavity(gamma: float, e: float, nu: float, y: float, rtol: float) -> tuple[float, float]:
    """``(V / c, sigma_r / Y)`` at the cavity wall of the similarity solution whose
    elastic-plastic boundary runs at ``xi = gamma`` (see the module docstring)."""
    from scipy.integrate import solve_ivp

    mu = e / (2.0 * (1.0 + nu))
    lam = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    k_bulk = e / (3.0 * (1.0 - 2.0 * nu))
    a = math.sqrt((lam + 2.0 * mu) / e)
    amp = y * gamma / (6.0 * mu * a * (a * a / gamma**2 - 1.0))  # yield at xi = gamma
    eta0 = 6.0 * amp * (a / gamma - 1.0)
    s0 = (lam * eta0 + 4.0 * mu * amp * (a**3 / gamma**3 - 1.0)) / y
    u0 = 3.0 * amp * a * (a * a / gamma**2 - 1.0)
    e_y, y_k, e_k = e / y, y / k_bulk, e / k_bulk

    def rhs(xi: float, state: np.ndarray) -> list[float]:
        sr, u = state
        one_eta = 1.0 - (sr - 2.0 / 3.0) * y_k
        w = u - xi
        ds = (-2.0 / xi + e_y * w * 2.0 * u / (xi * one_eta)) / (1.0 - e_k * w * w / one_eta**2)
        return [ds, -2.0 * u / xi - w * y_k * ds / one_eta]

    def wall(xi: float, state: np.ndarray) -> float:
        return state[1] - xi

    wall.terminal = True  # type: ignore[attr-defined]
    sol = solve_ivp(
        rhs,
        (gamma, 1e-9 * gamma),
        [s0, u0],
        method="DOP853",
        events=wall,
        rtol=rtol,
        atol=1e-14,
    )
    if not sol.t_events[0].size:
        raise TargetError("metal law: the cavity-expansion solution found no cavity wall")
    return float(sol.t_events[0][0]), float(sol.y_events[0][0][0])


def compressible_inertia(
    youngs_modulus: float,
    poisson_ratio: float,
    yield_strength: float,
    density: float,
    max_speed: float = 1000.0,
    n_points: int = 16,
    rtol: float = 1e-10,
) -> CompressibleInertia:
    """Inertial coefficient ``B`` of the compressible elastic-perfectly plastic spherical
    cavity expansion (module docstring), fitted over cavity speeds up to ``max_speed``.

    Parameters
    ----------
    youngs_modulus, poisson_ratio, yield_strength : float
        ``E`` (Pa), ``nu`` (below 1/2), ``Y`` (Pa).
    density : float
        ``rho`` (kg/m^3).
    max_speed : float
        Upper end of the fit (m/s): the speeds of your impacts.
    n_points : int
        Solutions in the fit, at elastic-plastic boundary speeds evenly spaced up to the
        one whose cavity opens at ``max_speed``.
    rtol : float
        Relative tolerance of the ODE integration.

    Returns
    -------
    CompressibleInertia

    Raises
    ------
    TargetError
        A value out of its range, ``nu = 1/2`` (use ``inertia="incompressible"``), or a
        ``max_speed`` beyond what the solution can open.

    Examples
    --------
    >>> from pencore.inputs.laws import compressible_inertia
    >>> ci = compressible_inertia(68.9e9, 0.33, 276e6, 2710.0, max_speed=1000.0)
    >>> print(f"B = {ci.b:.3f}, A0 = {ci.a0:.3f}")
    B = 1.147, A0 = 3.891
    """
    from scipy.optimize import brentq

    what = "metal law"
    e = _value(youngs_modulus, "youngs_modulus", what, "E")
    nu = _value(poisson_ratio, "poisson_ratio", what, "nu")
    y = _value(yield_strength, "yield_strength", what, "Y")
    rho = _value(density, "medium_density", what, "density")
    v_max = _value(max_speed, "max_speed", what, "max_speed")
    n_fit = _whole(n_points, "fit_points", what, "n_points")
    tol = _value(rtol, "rtol", what, "rtol")
    if nu >= 0.5:
        raise TargetError(
            f"{what}: the compressible solution needs nu < 0.5, got {nu:g} (an incompressible "
            "solid: inertia='incompressible', B = 3/2)"
        )
    k = e / (3.0 * (1.0 - nu) * y)
    if not k > 1.0:
        raise TargetError(
            f"{what}: E / (3 (1 - nu) Y) must be > 1 for a plastic zone to form, got "
            f"{k:.4g} (E = {e:g} Pa, nu = {nu:g}, Y = {y:g} Pa)"
        )
    v_fit = math.sqrt(B_FIT_MIN_LOAD * y / rho)
    if v_max < v_fit:
        slip = f" (in km/s? {v_max:g} km/s is {v_max * 1e3:g} m/s)" if v_max * 1e3 >= v_fit else ""
        raise TargetError(
            f"{what}: max_speed must be at least {v_fit:.4g} m/s for this solid (rho V^2 / Y "
            f">= {B_FIT_MIN_LOAD:g} at the top of the fit; below it the inertial stress is "
            f"lost in the cavity solution's numerical error and B means nothing), got "
            f"{v_max:g}{slip}"
        )
    c = math.sqrt(e / rho)
    a = math.sqrt((1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu)))
    bulk = math.sqrt(1.0 / (3.0 * (1.0 - 2.0 * nu)))
    g_cap = (1.0 - 1e-6) * min(a, bulk)
    beta_cap = _epp_cavity(g_cap, e, nu, y, tol)[0]
    if v_max / c >= beta_cap:
        raise TargetError(
            f"{what}: max_speed must be below {beta_cap * c:.4g} m/s, the fastest cavity the "
            f"compressible solution opens (the plastic front then runs at the bulk wave "
            f"speed), got {v_max:g}"
        )
    plausible(v_max, "max_speed", what)
    g_hi = brentq(lambda g: _epp_cavity(g, e, nu, y, tol)[0] - v_max / c, 1e-6, g_cap, xtol=1e-13)
    a0 = _epp_cavity(1e-6 * g_hi, e, nu, y, tol)[1]
    sols = [_epp_cavity(g_hi * j / n_fit, e, nu, y, tol) for j in range(1, n_fit + 1)]
    x = np.array([e / y * b * b for b, _ in sols])
    ds = np.array([sr - a0 for _, sr in sols])
    return CompressibleInertia(
        b=float(x @ ds / (x @ x)),
        a0=a0,
        speeds=tuple(b * c for b, _ in sols),
        stresses=tuple(sr for _, sr in sols),
        max_solvable_speed=beta_cap * c,
    )


@keyword_hints  # before LAWS holds it
def metal_law(
    youngs_modulus: float,
    poisson_ratio: float,
    yield_strength: float,
    hardening_exponent: float,
    density: float,
    *,
    inertia: str = "compressible",
    max_speed: float = 1000.0,
    name: str = "metal",
    finite_sphere: bool = False,
    friction: float = 0.0,
) -> Medium:
    """A metal by the spherical cavity expansion, ``sigma_n = A Y + B rho Vn^2``.

    Parameters
    ----------
    youngs_modulus, poisson_ratio, yield_strength, hardening_exponent : float
        ``E`` (Pa), ``nu``, ``Y`` (Pa), ``n`` (see :func:`~pencore.inputs.laws.cavity_expansion`).
    density : float
        Target density (kg/m^3).
    inertia : {"compressible", "incompressible"}
        ``B`` from the compressible elastic-perfectly plastic solution fitted up to
        ``max_speed`` (:func:`~pencore.inputs.laws.compressible_inertia`), or the
        incompressible 3/2.
    max_speed : float
        Upper end (m/s) of the compressible fit: the speeds of your impacts.
    name : str
        The medium's label.
    finite_sphere : bool
        Also set the medium's free-surface reduction of a cavity in a finite sphere
        (``plastic_zone_ratio = (E / (3 (1 - nu) Y))^(1/3)``, Hill).
    friction : float
        Constant Coulomb friction coefficient (default 0).

    Returns
    -------
    Medium
        Coefficients ``(A Y, 0, B rho)``: ``A`` of
        :func:`~pencore.inputs.laws.cavity_expansion`, ``B`` of
        :func:`~pencore.inputs.laws.compressible_inertia` (or 3/2).

    Examples
    --------
    6061-T6511 aluminium with handbook elastic constants (E = 68.9 GPa, nu = 0.33),
    the source's Y = 276 MPa and an assumed n = 0.051 (see the user guide):

    >>> import pencore
    >>> al = pencore.metal_law(68.9e9, 0.33, 276e6, 0.051, 2710.0, max_speed=2000.0)
    >>> a0, a1, a2 = al.coefficients
    >>> print(f"A = {a0 / 276e6:.3f}, B = {a2 / 2710.0:.3f}")
    A = 4.342, B = 1.061
    """
    what = "metal law"
    # every input first, then the solutions: a refusal comes before any warning
    e = _value(youngs_modulus, "youngs_modulus", what, "E")
    nu = _value(poisson_ratio, "poisson_ratio", what, "nu")
    y = _value(yield_strength, "yield_strength", what, "Y")
    n = _value(hardening_exponent, "hardening_exponent", what, "n")
    rho = _value(density, "medium_density", what, "density")
    v_max = _value(max_speed, "max_speed", what, "max_speed")  # whatever the inertia
    sphere = _flag(finite_sphere, what, "finite_sphere")
    mu = _value(friction, "friction", what, "friction")
    if inertia not in ("compressible", "incompressible"):
        raise TargetError(
            f"{what}: inertia must be 'compressible' or 'incompressible', got {brief(inertia)}"
        )
    if inertia == "compressible":
        b = compressible_inertia(e, nu, y, rho, v_max).b
        b_from = f"B = {b:.4g} (compressible, fitted up to {v_max:g} m/s)"
    ce = cavity_expansion(e, nu, y, n)
    if inertia == "incompressible":
        b = ce.b
        b_from = "B = 1.5 (incompressible)"
    return Medium(
        name,
        (ce.a * y, 0.0, b * rho),
        (0.0,),
        (mu,),
        rho,
        f"metal law (spherical cavity expansion; quasi-static A with power-law hardening by "
        f"Forrestal, Okajima & Luk 1988 with Hill's compressible elastic zone, inertial B of "
        f"the elastic-perfectly plastic solution, no strain-rate term): E = {e / 1e9:g} GPa, "
        f"nu = {nu:g}, Y = {y / 1e6:g} MPa, n = {n:g}, rho = {rho:g} kg/m3; A = {ce.a:.4g}, "
        f"{b_from}",
        plastic_zone_ratio=ce.plastic_zone_ratio if sphere else 0.0,
    )


@keyword_hints  # before LAWS holds it
def soil_law(
    a: float,
    tau0: float,
    b: float,
    density: float,
    *,
    name: str = "soil",
    friction: float = 0.0,
) -> Medium:
    """A soil by the Forrestal-Luk form of paper Table 1, ``sigma_n = A tau0 + B rho Vn^2``.

    Parameters
    ----------
    a, b : float
        Forrestal and Luk's dimensionless factors ``A`` and ``B``.
    tau0 : float
        Shear strength (Pa).
    density : float
        Soil density (kg/m^3).
    name : str
        The medium's label.
    friction : float
        Constant Coulomb friction coefficient (default 0).

    Returns
    -------
    Medium
        Coefficients ``(A tau0, 0, B rho)``.

    Examples
    --------
    The paper's soil (Table 1):

    >>> import pencore
    >>> s = pencore.soil_law(a=1.718, tau0=10e6, b=2.215, density=1860.0)
    >>> s.coefficients == pencore.get_target("soil").medium.coefficients
    True
    """
    what = "soil law"
    a_ = _value(a, "soil_factor", what, "A")
    tau = _value(tau0, "shear_strength", what, "tau0")
    b_ = _value(b, "soil_factor", what, "B")
    rho = _value(density, "medium_density", what, "density")
    return Medium(
        name,
        (a_ * tau, 0.0, b_ * rho),
        (0.0,),
        (_value(friction, "friction", what, "friction"),),
        rho,
        f"soil law (Forrestal & Luk 1992, paper Table 1 form): A tau0 + B rho Vn^2, A = {a_:g}, "
        f"tau0 = {tau / 1e6:g} MPa, B = {b_:g}, rho = {rho:g} kg/m3",
    )


#: The short names ``pencore.inputs.laws.concrete(...)`` etc.
concrete = concrete_law
metal = metal_law
soil = soil_law

#: Law name -> (function, YAML keys: required, optional).
LAWS: dict[str, tuple[Any, tuple[str, ...], tuple[str, ...]]] = {
    "concrete": (
        concrete_law,
        ("fc", "density"),
        ("s", "crater_depth", "friction", "s_model", "crater", "size_term"),
    ),
    "metal": (
        metal_law,
        ("youngs_modulus", "poisson_ratio", "yield_strength", "hardening_exponent", "density"),
        ("inertia", "max_speed", "finite_sphere", "friction"),
    ),
    "soil": (soil_law, ("a", "tau0", "b", "density"), ("friction",)),
}

#: Keys a law mapping may hold besides its law's own.
_COMMON = ("law", "name", "free_surface_depth", "plastic_zone_ratio")


def medium_from_law(d: Mapping[str, Any], what: str = "medium") -> Medium:
    """A medium from a mapping ``{law: concrete | metal | soil, ...}`` (the YAML form).

    Parameters
    ----------
    d : mapping
        ``law`` and the law's inputs (SI: Pa, kg/m^3), as the keyword arguments of
        :func:`concrete_law`, :func:`metal_law`, :func:`soil_law`; optionally ``name`` and
        the depth windows of :class:`~pencore.inputs.target.Medium`
        (``free_surface_depth``, ``plastic_zone_ratio``; ``crater_depth`` for concrete).
    what : str
        Where the mapping comes from, for messages.

    Returns
    -------
    Medium

    Raises
    ------
    InputError
        An unknown law or key, a missing input, a value out of its range.

    Examples
    --------
    >>> from pencore.inputs.laws import medium_from_law
    >>> m = medium_from_law({"law": "concrete", "fc": "40.0e6", "density": 2300})
    >>> print(f"{m.coefficients[0]:.4g} Pa")
    4.441e+08 Pa
    """
    if not isinstance(d, Mapping):
        raise InputError(
            f"{what}: a law must be a mapping {{law: {' | '.join(LAWS)}, ...}} of the law's "
            f"inputs, got {brief(d)} ({type(d).__name__})"
        )
    law = d.get("law")
    if not isinstance(law, str) or law not in LAWS:
        raise InputError(f"{what}: law must be one of {', '.join(LAWS)}, got {brief(law)}")
    func, required, optional = LAWS[law]
    check_keys(d, (*_COMMON, *required, *optional), f"{what} ({law} law)")
    missing = [k for k in required if k not in d]
    if missing:
        raise InputError(f"{what} ({law} law): missing key {brief(missing[0])}")
    kwargs = {k: d[k] for k in (*required, *optional) if k in d}
    medium = func(**kwargs, name=str(d.get("name", law)))
    windows = {}
    for k in ("free_surface_depth", "plastic_zone_ratio"):
        if k in d:
            windows[k] = number(d[k], k, what, allow_str=True)
    if windows:
        medium = replace(medium, **windows)
    return medium


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
