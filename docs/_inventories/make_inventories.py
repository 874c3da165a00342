"""Write the intersphinx inventories the docs build reads offline (``docs/conf.py``).

The build has no network (CI reaches only the package registries), so the inventories of
numpy, scipy, xarray, matplotlib and Python are generated here, from the packages installed
beside pencore, instead of being downloaded from each project's site. Each entry names an
object as the project's own documentation does and points to the page that documents it,
by the URL pattern of that documentation (provenance below; checked against the published
pages, 2026):

========== ================================================ =====================================
project    base URL                                         page of ``name``
========== ================================================ =====================================
numpy      https://numpy.org/doc/stable/                    ``reference/generated/{name}.html``
scipy      https://docs.scipy.org/doc/scipy/                ``reference/generated/{name}.html``
xarray     https://docs.xarray.dev/en/stable/               ``generated/{name}.html``
matplotlib https://matplotlib.org/stable/                   ``api/_as_gen/{name}.html``
python     https://docs.python.org/3/                       ``library/{module}.html``
========== ================================================ =====================================

(numpy, scipy, xarray and matplotlib generate one page per object with Sphinx's
autosummary, named by the object's full name; the anchor is the full name. Python's
library reference has one page per module, the anchor is the full name.) The
inventories cover the public classes (with their methods and properties) and functions
of the modules listed in :data:`MODULES`, which include every one the docs refer to; a
reference to an object outside them fails the strict build (``-n -W``) and is added here.

Run from the repository with the docs extra installed, then commit the ``.inv`` files::

    python docs/_inventories/make_inventories.py
"""

from __future__ import annotations

import importlib
import inspect
import zlib
from pathlib import Path

HERE = Path(__file__).resolve().parent

#: project -> (base URL, modules whose public names are listed)
MODULES: dict[str, tuple[str, list[str]]] = {
    "numpy": (
        "https://numpy.org/doc/stable/",
        ["numpy", "numpy.linalg", "numpy.random", "numpy.polynomial.legendre"],
    ),
    "scipy": (
        "https://docs.scipy.org/doc/scipy/",
        [
            "scipy.optimize",
            "scipy.integrate",
            "scipy.interpolate",
            "scipy.linalg",
            "scipy.special",
            "scipy.stats",
        ],
    ),
    "xarray": ("https://docs.xarray.dev/en/stable/", ["xarray"]),
    "matplotlib": (
        "https://matplotlib.org/stable/",
        [
            "matplotlib",
            "matplotlib.figure",
            "matplotlib.axes",
            "matplotlib.pyplot",
            "matplotlib.colors",
            "matplotlib.lines",
            "matplotlib.ticker",
        ],
    ),
    "python": (
        "https://docs.python.org/3/",
        [
            "builtins",
            "pathlib",
            "os",
            "collections.abc",
            "dataclasses",
            "typing",
            "subprocess",
            "json",
            "argparse",
            "contextlib",
            "signal",
            "logging",
            "math",
        ],
    ),
}

#: Objects documented on a page of their own outside the pattern (numpy's typing aliases).
EXTRA: dict[str, list[tuple[str, str, str]]] = {
    "numpy": [
        ("numpy.typing.ArrayLike", "py:data", "reference/typing.html#numpy.typing.ArrayLike"),
        ("numpy.typing.NDArray", "py:data", "reference/typing.html#numpy.typing.NDArray"),
    ],
}


def page(project: str, module: str, name: str) -> str:
    """The documentation page (relative to the base URL) of ``name`` defined in ``module``."""
    if project == "python":
        # builtins' functions and types are on functions.html and stdtypes.html
        if module == "builtins":
            return "library/functions.html#" + name.removeprefix("builtins.")
        return f"library/{module}.html#{name}"
    if project == "numpy":
        return f"reference/generated/{name}.html#{name}"
    if project == "scipy":
        return f"reference/generated/{name}.html#{name}"
    if project == "xarray":
        return f"generated/{name}.html#{name}"
    if module == "matplotlib":  # the top-level functions share one page
        return f"api/matplotlib_configuration_api.html#{name}"
    return f"api/_as_gen/{name}.html#{name}"


def module_page(project: str, module: str) -> str:
    if project == "python":
        return f"library/{module}.html#module-{module}"
    if project == "numpy":
        return f"reference/index.html#module-{module}"
    if project == "scipy":
        return f"reference/{module.split('.')[1]}.html#module-{module}"
    if project == "xarray":
        return f"api.html#module-{module}"
    if module == "matplotlib":
        return "api/matplotlib_configuration_api.html#module-matplotlib"
    return f"api/{module.split('.')[1]}_api.html#module-{module}"


def public(module: object) -> list[str]:
    names = getattr(module, "__all__", None) or dir(module)
    return sorted(n for n in names if not n.startswith("_"))


def entries(project: str, modules: list[str]) -> list[tuple[str, str, str]]:
    out: dict[str, tuple[str, str]] = {}
    for modname in modules:
        module = importlib.import_module(modname)
        if modname != "builtins":
            out[modname] = ("py:module", module_page(project, modname))
        for attr in public(module):
            try:
                obj = getattr(module, attr)
            except AttributeError:
                continue
            if inspect.ismodule(obj):
                continue
            full = attr if modname == "builtins" else f"{modname}.{attr}"
            if inspect.isclass(obj):
                role = "py:exception" if issubclass(obj, BaseException) else "py:class"
                url = page(project, modname, full)
                if modname == "builtins" and role == "py:exception":
                    url = f"library/exceptions.html#{full}"
                out[full] = (role, url)
                for member in public(obj):
                    try:
                        raw = inspect.getattr_static(obj, member)
                    except AttributeError:
                        continue
                    kind = (
                        "py:attribute"
                        if isinstance(raw, property)
                        else "py:method"
                        if callable(raw) or isinstance(raw, (classmethod, staticmethod))
                        else None
                    )
                    if kind is None:
                        continue
                    if project == "python":
                        url = page(project, modname, full) + "." + member
                        if modname == "builtins":
                            url = f"library/stdtypes.html#{attr}.{member}"
                    else:
                        url = page(project, modname, f"{full}.{member}")
                    out[f"{full}.{member}"] = (kind, url)
            elif callable(obj):
                out[full] = ("py:function", page(project, modname, full))
            elif project == "python" and modname != "builtins":
                out[full] = ("py:data", page(project, modname, full))
    rows = [(name, role, url) for name, (role, url) in out.items()]
    return sorted(rows + EXTRA.get(project, []))


def write(project: str, version: str, rows: list[tuple[str, str, str]], path: Path) -> None:
    header = (
        "# Sphinx inventory version 2\n"
        f"# Project: {project}\n"
        f"# Version: {version}\n"
        "# The remainder of this file is compressed using zlib.\n"
    )
    body = "".join(
        f"{name} {role} 1 {url.replace('#' + name, '#$') if url.endswith('#' + name) else url} -\n"
        for name, role, url in rows
    )
    path.write_bytes(header.encode() + zlib.compress(body.encode(), 9))


def main() -> None:
    import platform

    for project, (_base, modules) in MODULES.items():
        if project == "python":
            version = ".".join(platform.python_version_tuple()[:2])
        else:
            version = importlib.import_module(project).__version__
        rows = entries(project, modules)
        write(project, version, rows, HERE / f"{project}.inv")
        print(f"{project} {version}: {len(rows)} objects")


if __name__ == "__main__":
    main()
