"""The public surface: every entry point a user calls is a name of ``pencore``, each topic
subpackage lists its own public names, ``dir`` shows only those, the old import paths keep
working, and a process that only reads, analyses and plots results does not load the solver."""

from __future__ import annotations

import importlib
import inspect
import re
import subprocess
import sys

import pytest

import pencore

SUBPACKAGES = ["run", "search", "io", "analysis", "inputs", "integrators", "kernels", "cli"]

#: What a user is told to call (README, user guide, examples): each must be at the top.
ENTRY_POINTS = [
    "simulate",
    "prepare",
    "vcr",
    "vci",
    "omega_c",
    "ballistic_limit",
    "residual_velocity",
    "read_netcdf",
    "plot_run",
    "final_deviation",
    "turning_angle",
    "inflection_points_ds",
    "signed_curvature",
    "get_projectile",
    "get_target",
    "Projectile",
    "Target",
    "concrete_law",
    "metal_law",
    "soil_law",
    "Numerics",
    "InputError",
    "SolverError",
    "PlausibilityWarning",
    "RigidRegimeWarning",
]


@pytest.mark.parametrize("name", pencore.__all__)
def test_every_public_name_resolves(name):
    value = getattr(pencore, name)
    if name != "__version__":
        # documented where it is defined, and reachable by the same object at the top
        assert value.__module__.startswith("pencore."), name


def test_the_entry_points_are_public_names():
    assert set(ENTRY_POINTS) <= set(pencore.__all__)


def test_dir_shows_only_the_public_names():
    import pencore.run  # noqa: F401  (an imported submodule is not listed either)

    assert dir(pencore) == sorted(pencore.__all__)
    assert len(set(pencore.__all__)) == len(pencore.__all__)
    for helper in ("Any", "TYPE_CHECKING", "annotations", "importlib", "attach"):
        assert helper not in dir(pencore)


def test_an_unknown_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'simulat'"):
        pencore.simulat  # noqa: B018
    with pytest.raises(AttributeError, match="no attribute 'vcrr'"):
        pencore.search.vcrr  # noqa: B018


@pytest.mark.parametrize("sub", SUBPACKAGES)
def test_each_subpackage_lists_its_public_names(sub):
    module = importlib.import_module(f"pencore.{sub}")
    assert isinstance(module.__all__, list)
    for name in module.__all__:
        assert not name.startswith("_"), name
        assert getattr(module, name) is not None


@pytest.mark.parametrize("name", [n for n in pencore.__all__ if n != "__version__"])
def test_a_top_level_name_is_the_object_of_its_topic_subpackage(name):
    value = getattr(pencore, name)
    parts = value.__module__.split(".")
    if len(parts) > 2:  # pencore.<topic>.<module>: the topic package holds it too
        topic = importlib.import_module(".".join(parts[:2]))
        assert name in topic.__all__, (name, topic.__name__)
        assert getattr(topic, name) is value
    # the module that defines it is an import path that keeps working
    assert getattr(importlib.import_module(value.__module__), name) is value


def test_the_old_import_paths_keep_working():
    from pencore.analysis.turning import turning_angle
    from pencore.io.netcdf import read_netcdf
    from pencore.run.impact import simulate
    from pencore.search.critical import vcr
    from pencore.search.perforation import ballistic_limit

    assert (simulate, vcr, ballistic_limit, read_netcdf, turning_angle) == (
        pencore.simulate,
        pencore.vcr,
        pencore.ballistic_limit,
        pencore.read_netcdf,
        pencore.turning_angle,
    )


def test_a_figure_job_does_not_load_the_solver():
    """Reading, analysing and plotting results (the workflow's figure jobs) through the
    public names imports neither numba nor the solver: the names are imported on first
    use, from the submodule that defines each."""
    code = (
        "import sys, pencore, pencore.io, pencore.plotting, pencore.analysis\n"
        "from pencore import read_netcdf, final_deviation, turning_angle, InputError\n"
        "from pencore.io import read_netcdf\n"
        "dir(pencore)\n"
        "print(sorted(m for m in ('numba', 'pencore.run.impact', 'pencore.kernels')"
        " if m in sys.modules))\n"
        "pencore.simulate\n"
        "print('numba' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["[]", "True"]


# ---------------------------------------------------------------- keyword typos

#: The topic subpackages whose modules are public (their names, and the public names of
#: each module that defines one).
PUBLIC_PACKAGES = ["run", "search", "io", "analysis", "inputs", "plotting", "closedform"]


def _public_callables() -> list[tuple[str, object]]:
    """Every public function, class and public method: the names of ``pencore.__all__``,
    of each public subpackage, and of each module that defines one of them."""
    found: dict[int, tuple[str, object]] = {}
    modules = {}
    for owner in [pencore, *(importlib.import_module(f"pencore.{p}") for p in PUBLIC_PACKAGES)]:
        for name in owner.__all__:
            obj = getattr(owner, name)
            found.setdefault(id(obj), (f"{owner.__name__}.{name}", obj))
            module = getattr(obj, "__module__", "")
            if module.startswith("pencore.") and module != "pencore.errors":
                modules[module] = importlib.import_module(module)
    for module in modules.values():
        names = getattr(module, "__all__", None) or [
            n for n, v in vars(module).items()
            if not n.startswith("_") and getattr(v, "__module__", "") == module.__name__
        ]  # fmt: skip
        for name in names:
            obj = getattr(module, name)
            if getattr(obj, "__module__", "") == module.__name__:
                found.setdefault(id(obj), (f"{module.__name__}.{name}", obj))
    out = []
    for name, obj in found.values():
        if inspect.isclass(obj):
            if issubclass(obj, BaseException):
                continue
            out.append((name, obj))
            for attr, value in vars(obj).items():
                if not attr.startswith("_") and (
                    inspect.isfunction(value) or isinstance(value, staticmethod | classmethod)
                ):
                    out.append((f"{name}.{attr}", getattr(obj, attr)))
        elif inspect.isfunction(obj):
            out.append((name, obj))
    return out


def _keywords(obj: object) -> list[str]:
    params = inspect.signature(obj).parameters.values()
    return [
        p.name
        for p in params
        if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY) and p.name not in ("self", "cls")
    ]


KEYWORD_TAKERS = [(n, o) for n, o in _public_callables() if _keywords(o)]


def test_the_walk_finds_the_public_api():
    names = {n.rsplit(".", 1)[-1] for n, _ in KEYWORD_TAKERS}
    expected = {"simulate", "concrete_law", "metal_law", "medium_from_law", "with_mass",
                "compressible_inertia", "plot_run", "read_netcdf", "Projectile",
                "Numerics"}  # fmt: skip
    assert expected <= names, expected - names
    assert len(KEYWORD_TAKERS) > 100


@pytest.mark.parametrize(("name", "obj"), KEYWORD_TAKERS, ids=[n for n, _ in KEYWORD_TAKERS])
def test_every_public_keyword_typo_is_one_line_with_a_hint(name, obj):
    """Each public function, class and method that takes keywords answers a misspelt
    keyword (its first keyword with its last letter doubled) with one InputError line
    that names the keyword meant, before any work is done."""
    keyword = _keywords(obj)[0]
    typo = keyword + keyword[-1]
    with pytest.raises(pencore.InputError) as info:
        obj(**{typo: 1})
    assert isinstance(info.value, pencore.ArgumentError) and isinstance(info.value, TypeError)
    text = str(info.value)
    assert "\n" not in text
    assert f"{typo!r}" in text and f"did you mean {keyword!r}" in text, text


@pytest.mark.parametrize(
    ("call", "words"),
    [
        (lambda: pencore.concrete_law(fc=40e6, densty=2300), "did you mean 'density'"),
        (lambda: pencore.get_projectile("p2").with_mass(mas=20), "did you mean 'mass'"),
        (lambda: pencore.metal_law(68.9e9, 0.33, 276e6, 0.05, 2710.0, maxspeed=800),
         "did you mean 'max_speed'"),
        (lambda: pencore.simulate(projectile="p2"), "simulate: missing a required argument"),
        (lambda: pencore.concrete_law(40e6, 2300.0, 21.0, "c"), "too many positional"),
        (lambda: pencore.Target(nme="t"), "did you mean 'name'"),
        (lambda: pencore.read_netcdf(pth="x.nc"), "did you mean 'path'"),
    ],
)  # fmt: skip
def test_the_issues_calls(call, words):
    with pytest.raises(pencore.InputError, match=re.escape(words)):
        call()


def test_a_type_error_inside_a_function_is_raised_as_it_was():
    """The hint is for a call whose arguments do not bind; a TypeError of the function's
    own work (after binding) is not turned into an input error."""
    from pencore.errors import keyword_hints

    @keyword_hints
    def f(x):
        return x + "a"

    with pytest.raises(TypeError, match="unsupported operand") as info:
        f(x=1)
    assert not isinstance(info.value, pencore.InputError)
    assert f(x="b") == "ba"
    long = "k" * 500
    with pytest.raises(pencore.InputError) as info:
        f(**{long: 1})
    assert len(str(info.value)) < 200


def test_no_module_holds_a_public_function_without_its_hints():
    """``hint_keywords`` replaces a module's public functions at the module's end; a
    table built before that (a dict of laws) would keep the unchecked function, so no
    module-level name or table of any pencore module may hold one."""
    import pkgutil

    modules = [importlib.import_module(m.name)
               for m in pkgutil.walk_packages(pencore.__path__, "pencore.")
               if m.name != "pencore.__main__"]  # fmt: skip
    unchecked = {
        id(v.__wrapped__): f"{m.__name__}.{n}"
        for m in modules
        for n, v in vars(m).items()
        if getattr(v, "__keyword_hints__", False)
    }

    def held(obj, depth=0):
        if id(obj) in unchecked:
            yield unchecked[id(obj)]
        if depth < 3 and isinstance(obj, dict | list | tuple | set | frozenset):
            for item in [*obj, *obj.values()] if isinstance(obj, dict) else obj:
                yield from held(item, depth + 1)

    assert len(unchecked) > 100
    found = [(f"{m.__name__}.{n}", h) for m in modules for n, v in vars(m).items()
             if not n.startswith("__") for h in held(v)]  # fmt: skip
    assert not found, found
