"""Public names of a package, imported from their submodules on first use (PEP 562).

A package's ``__init__`` declares which submodule defines each of its public names::

    __getattr__, __dir__, __all__ = attach(__name__, {"read_netcdf": "netcdf"})

``from pencore.io import read_netcdf`` and ``pencore.io.read_netcdf`` then import
``pencore.io.netcdf`` at that moment, not when the package is imported: a process that
uses one light submodule (the command line's option parsing, a figure job) does not pay for
the heavy ones (numba, scipy, xarray). ``dir(package)`` lists the public names only, and a
submodule accessed as an attribute (``pencore.search``) is imported too.
"""

import importlib
from collections.abc import Callable


def attach(
    package: str, exports: dict[str, str], defined: tuple[str, ...] = ()
) -> tuple[Callable[[str], object], Callable[[], list[str]], list[str]]:
    """``(__getattr__, __dir__, __all__)`` of ``package``, whose public names are the keys
    of ``exports`` (each value names the submodule, relative to ``package``, that defines
    it) and the names in ``defined``, which the package defines itself."""

    def __getattr__(name: str) -> object:
        module = exports.get(name)
        if module is not None:
            value = getattr(importlib.import_module(f"{package}.{module}"), name)
            vars(importlib.import_module(package))[name] = value  # next time a plain lookup
            return value
        try:
            return importlib.import_module(f"{package}.{name}")
        except ModuleNotFoundError as exc:
            if exc.name != f"{package}.{name}":
                raise  # the submodule exists but something it imports does not
            raise AttributeError(f"module {package!r} has no attribute {name!r}") from None

    names = [*defined, *exports]

    def __dir__() -> list[str]:
        return sorted(names)

    return __getattr__, __dir__, names
