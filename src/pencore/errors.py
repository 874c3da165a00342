"""Every exception pencore raises on purpose, in one place.

The command line turns :class:`InputError` and :class:`ConfigError` into exit status 2,
:class:`SolverError` and :class:`WriteError` into exit status 1, each with a one-line
message; a Python caller can catch them by these classes.

=================  ==========================================================
class              raised when
=================  ==========================================================
InputError         a name, file or value given by the user is not valid
ArgumentError      a call whose arguments do not bind (a misspelt keyword)
GeometryError      a projectile definition does not describe a valid body
TargetError        a target definition cannot be used
ConfigError        a workflow configuration cannot be run
SolverError        an integration could not finish
WriteError         a file could not be written (nothing was left behind)
ResultError        a result file cannot be read (corrupt or truncated)
=================  ==========================================================

A call whose arguments do not bind (a misspelt keyword, a missing argument) is an
:class:`ArgumentError` (an :class:`InputError` and a ``TypeError``) naming the closest
keyword (:func:`keyword_hints`, given to every public function and class by
:func:`hint_keywords`).

One warning class, :class:`PlausibilityWarning`, marks a value that is allowed but
implausible: where a law is extrapolated, or of a size that suggests a slip of unit
(the likely slip is named); it never stops a run. Its subclass :class:`RigidRegimeWarning`
marks an impact outside the rigid regime (:mod:`pencore.inputs.regime`).
"""

from __future__ import annotations

import difflib
import functools
import inspect
from collections.abc import Callable
from typing import Any

__all__ = [
    "INTERRUPTED",
    "interrupted_import",
    "InputError",
    "ArgumentError",
    "GeometryError",
    "TargetError",
    "ConfigError",
    "SolverError",
    "WriteError",
    "ResultError",
    "PlausibilityWarning",
    "RigidRegimeWarning",
    "keyword_hints",
    "hint_keywords",
]

#: What the command line says when Ctrl-C ends it (exit status 130).
INTERRUPTED = "interrupted (Ctrl-C); nothing was written"


def interrupted_import(exc: BaseException) -> bool:
    """True when ``exc`` is a Ctrl-C in disguise: an ``ImportError`` raised because a
    ``KeyboardInterrupt`` landed while an extension module initialised. pybind11's modules
    (scipy's ``scipy.optimize._highspy._core``, which ``scipy.integrate`` imports) turn any
    exception of their initialisation into ``ImportError("initialization failed")`` raised
    from it, so a Ctrl-C during a lazy import of scipy would otherwise read as a broken
    installation."""
    if not isinstance(exc, ImportError):
        return False
    return isinstance(exc.__cause__, KeyboardInterrupt) or isinstance(
        exc.__context__, KeyboardInterrupt
    )


class InputError(ValueError):
    """Bad user input: a name, file or value that pencore cannot use.

    Raised by every public function before any work is done (nothing is written): an
    unknown projectile or target name, a YAML file that cannot be read or holds an unknown
    key, a number out of its range (:data:`pencore.inputs.limits.LIMITS`) or of the wrong
    type (text or a boolean where a number belongs), a bad search bracket. The message is
    one line naming the offending value and what is allowed; the command line prints it
    as ``pencore: error: ...`` and exits with status 2. A subclass of :class:`ValueError`.

    Examples
    --------
    >>> import pencore
    >>> try:
    ...     pencore.simulate("p2", "soil", -5.0)
    ... except pencore.InputError as exc:
    ...     print(exc)
    velocity must be in (0, 10000] m/s, got -5.0
    """


class ArgumentError(InputError, TypeError):
    """A call to a public function whose arguments do not bind: a misspelt keyword (named
    with the closest one), a missing argument, one given twice or too many.

    An :class:`InputError` (one line; the command line's exit status 2) and, as Python's
    own error for such a call, a :class:`TypeError`.

    Examples
    --------
    >>> import pencore
    >>> try:
    ...     pencore.concrete_law(fc=40e6, densty=2300.0)
    ... except pencore.ArgumentError as exc:
    ...     print(str(exc).split(";")[0])
    concrete_law: unknown keyword 'densty' (did you mean 'density'?)
    """


class GeometryError(InputError):
    """A projectile definition that does not describe a valid body.

    Examples
    --------
    >>> import pencore
    >>> pencore.OgiveNose(crh=0.2, density=7850.0)
    Traceback (most recent call last):
    ...
    pencore.errors.GeometryError: ogive CRH must be in [0.5, 100], got 0.2
    """


class TargetError(InputError):
    """A target definition that cannot be used.

    Examples
    --------
    >>> import pencore
    >>> pencore.Layer(pencore.get_target("soil").medium, "1 m")
    Traceback (most recent call last):
    ...
    pencore.errors.TargetError: layer thickness must be a number of m, got '1 m' (str)
    """


class ConfigError(ValueError):
    """A workflow configuration that cannot be run.

    Raised by the workflow's configuration check before any job starts; the message is
    one line naming the key path and the value (exit status 2). It is not an
    :class:`InputError`: catch both to catch every refused input.

    Examples
    --------
    >>> import pencore
    >>> issubclass(pencore.ConfigError, ValueError)
    True
    >>> issubclass(pencore.ConfigError, pencore.InputError)
    False
    """


class SolverError(RuntimeError):
    """The integration of a trajectory could not finish.

    Causes: the step size fell below ``numerics.h_min`` (a stiff or chattering contact:
    ``step_underflow``), the step budget ``max_steps`` or the wall-time budget
    ``max_wall`` ran out. The message names the cause, the state reached and the
    numerics to change; the command line exits with status 1.

    Examples
    --------
    >>> import pencore
    >>> try:
    ...     pencore.simulate("p2", "soil", 280.0, max_steps=10)
    ... except pencore.SolverError as exc:
    ...     print(str(exc).split(";")[0])
    step budget of 10 steps used up (raise numerics max_steps, or loosen rtol)
    """


class WriteError(OSError):
    """A file could not be written; nothing was left behind.

    Raised by :func:`~pencore.write_netcdf` and the workflow's writers: the destination
    is a directory or a protected input, no permission, the disk is full. The message is
    one line naming the path and the cause; ``errno`` is the operating system's error
    number when there is one. The command line exits with status 1.

    Parameters
    ----------
    message : str
        The one-line message.
    code : int, optional
        The operating system's error number.

    Examples
    --------
    A directory is never replaced by a file:

    >>> import tempfile
    >>> import xarray as xr
    >>> import pencore
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     try:
    ...         pencore.write_netcdf(xr.Dataset(), tmp, config_slice={}, study="example")
    ...     except pencore.WriteError as exc:
    ...         print(str(exc).split(": ", 1)[1])
    it is a directory, not a regular file; only a regular file is replaced
    """

    def __init__(self, message: str, code: int | None = None) -> None:
        super().__init__(message)
        self.errno = code


class ResultError(RuntimeError):
    """A result file that cannot be read (corrupt or truncated).

    Raised by :func:`~pencore.read_netcdf`; the message is one line naming the file and
    how to make it again.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> import pencore
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     bad = Path(tmp) / "bad.nc"
    ...     _ = bad.write_bytes(b"not a netCDF file")
    ...     try:
    ...         pencore.read_netcdf(bad)
    ...     except pencore.ResultError as exc:
    ...         print("cannot be read" in str(exc))
    True
    """


class PlausibilityWarning(UserWarning):
    """A value that is allowed but implausible; the run goes on.

    Issued (never raised) by every input door (the Python API, YAML files, the command
    line, the workflow configuration) for a value within its valid range but outside
    its plausible range (:data:`pencore.inputs.limits.PLAUSIBLE`, listed on the docs'
    errors page): a speed of 1.4 m/s (km/s meant?), a diameter of 9.5 m (cm meant?), a
    density of 7.85 kg/m^3 (g/cm^3 meant?); and by a law used outside the range it was
    built on (extrapolated). The message is one line naming the value and the range (and
    the likely slip); the command line prints it as ``pencore: warning: ...``. Silence it
    with the usual filters (``warnings.simplefilter("ignore", pencore.PlausibilityWarning)``,
    ``python -W``).

    Examples
    --------
    >>> import warnings
    >>> import pencore
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     p = pencore.Projectile("x", 9.5, pencore.OgiveNose(3.0, 7850.0))
    >>> print(caught[0].category.__name__, str(caught[0].message).split(" is ")[0])
    PlausibilityWarning diameter 9.5 m
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     _ = pencore.concrete_law(fc=150e6, density=2500.0)
    >>> issubclass(caught[0].category, pencore.PlausibilityWarning)
    True
    """


class RigidRegimeWarning(PlausibilityWarning):
    """An impact outside the rigid regime, where a rigid body's depth is not to be trusted.

    The nose-tip stress of the target's law at the striking speed is more than the
    declared bound times the projectile's yield strength (:mod:`pencore.inputs.regime`),
    where real noses deform or erode. The run goes on; issued once per prepared problem (a
    run, or a whole search). A subclass of :class:`PlausibilityWarning`: the same filters
    silence it, and the command line prints it as ``pencore: warning: ...``.

    Examples
    --------
    >>> import warnings
    >>> import pencore
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     _ = pencore.simulate("al_ogive_var4340", "aluminium", 2500.0)
    >>> print(caught[-1].category.__name__, str(caught[-1].message).split(" the nose")[0])
    RigidRegimeWarning rigid regime: at 2500 m/s
    """


# ---------------------------------------------------------------- keyword typos

#: Longest keyword quoted whole in a message (characters).
_MAX_KEYWORD = 60


def keyword_hints(function: Callable[..., Any]) -> Callable[..., Any]:
    """``function`` with its calls' argument errors as one :class:`ArgumentError` line: a
    keyword that is none of its parameters is named with the closest one
    (``concrete_law(fc=40e6, densty=2300)``: ``unknown keyword 'densty' (did you mean
    'density'?)``), and a missing or doubled argument is said in Python's words, prefixed
    with the function's name. A :class:`TypeError` raised inside the function, after its
    arguments were bound, is raised as it was. A call that binds costs one ``try``.

    Parameters
    ----------
    function : callable
        A Python function or method (not one taking ``**kwargs``, which checks its own
        keywords: :func:`pencore.inputs.numerics.keywords_checked`).

    Returns
    -------
    callable
        The checked function (``functools.wraps``: same name, docstring, signature).

    Examples
    --------
    >>> from pencore.errors import keyword_hints
    >>> @keyword_hints
    ... def law(fc, density):
    ...     return fc * density
    >>> law(fc=40e6, densty=2300.0)
    Traceback (most recent call last):
    ...
    pencore.errors.ArgumentError: law: unknown keyword 'densty' (did you mean 'density'?); its keywords: fc, density
    """  # noqa: E501
    if getattr(function, "__keyword_hints__", False):
        return function

    @functools.wraps(function)
    def hinted(*args: Any, **kwargs: Any) -> Any:
        try:
            return function(*args, **kwargs)
        except TypeError:
            problem = _call_problem(function, args, kwargs)
            if problem is None:  # the arguments bind: the error is the function's own
                raise
        raise ArgumentError(problem)

    hinted.__keyword_hints__ = True  # type: ignore[attr-defined]
    return hinted


def _call_problem(function: Callable[..., Any], args: tuple, kwargs: dict[str, Any]) -> str | None:
    """Why ``function(*args, **kwargs)`` cannot bind (one line), or None when it binds."""
    try:
        signature = inspect.signature(function)
    except (TypeError, ValueError):  # no signature to judge by
        return None
    try:
        signature.bind(*args, **kwargs)
    except TypeError as exc:
        reason = str(exc)
    else:
        return None
    name = function.__qualname__.removesuffix(".__init__")
    params = signature.parameters
    keywords = [
        k
        for k, p in params.items()
        if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY) and k not in ("self", "cls")
    ]
    if not any(p.kind is p.VAR_KEYWORD for p in params.values()):
        for key in kwargs:
            if key in keywords:
                continue
            lower = {k.lower(): k for k in keywords}
            hint = difflib.get_close_matches(key.lower(), list(lower), n=1, cutoff=0.6)
            tip = f" (did you mean {lower[hint[0]]!r}?)" if hint else ""
            quoted = repr(key) if len(key) <= _MAX_KEYWORD else f"{key[:_MAX_KEYWORD]!r}..."
            known = ", ".join(keywords) if keywords else "none"
            return f"{name}: unknown keyword {quoted}{tip}; its keywords: {known}"
    return f"{name}: {reason}"


def hint_keywords(namespace: dict[str, Any]) -> None:
    """Give :func:`keyword_hints` to every public function and class a module defines:
    each function of its ``__all__`` (without one, of its names not starting with ``_``)
    that takes a keyword (aliases stay one object),
    and each class's ``__init__`` and public methods. Called once at the end of each
    module of a public subpackage, so a function added to ``__all__`` gets it by
    construction (``tests/test_public_api.py`` walks the API and checks every one)."""
    module = namespace["__name__"]
    done: dict[int, Any] = {}
    public = namespace.get("__all__") or [n for n in list(namespace) if not n.startswith("_")]
    for name in public:
        obj = namespace.get(name)
        if getattr(obj, "__module__", None) != module:
            continue  # a re-export: hinted where it is defined
        if id(obj) in done:
            namespace[name] = done[id(obj)]
        elif inspect.isfunction(obj):
            namespace[name] = done[id(obj)] = _hinted(obj)
        elif inspect.isclass(obj):
            _hint_class(obj)
            done[id(obj)] = obj


def _takes_keywords(function: Callable[..., Any]) -> bool:
    """Whether ``function`` has a parameter given by keyword (not ``self``) and no
    ``**kwargs`` (a function with them checks its own keywords)."""
    params = inspect.signature(function).parameters.values()
    if any(p.kind is p.VAR_KEYWORD for p in params):
        return False
    return any(
        p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY) and p.name not in ("self", "cls")
        for p in params
    )


def _hinted(function: Callable[..., Any]) -> Callable[..., Any]:
    return keyword_hints(function) if _takes_keywords(function) else function


def _hint_class(cls: type) -> None:
    """``keyword_hints`` on the class's own ``__init__`` and public methods, in place."""
    for attr, value in list(vars(cls).items()):
        if attr.startswith("_") and attr != "__init__":
            continue
        if isinstance(value, staticmethod | classmethod):
            hinted = _hinted(value.__func__)
            if hinted is not value.__func__:
                setattr(cls, attr, type(value)(hinted))
        elif inspect.isfunction(value):
            hinted = _hinted(value)
            if hinted is not value:
                setattr(cls, attr, hinted)
