"""Files: netCDF with provenance (:mod:`~pencore.io.netcdf`), atomic, durable writes
(:mod:`~pencore.io.atomic`), the check of result files (:mod:`~pencore.io.results`), and
the reader of CSV tables with a ``#`` provenance header (:mod:`~pencore.io.tables`).

``__all__`` lists the public names; each is imported from its module on first use, so the
command line's use of :mod:`~pencore.io.atomic` does not load xarray.
"""

from pencore._lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "read_netcdf": "netcdf",
        "write_netcdf": "netcdf",
        "downsample": "netcdf",
        "provenance_attrs": "netcdf",
        "readable_netcdf": "results",
        "set_aside_unreadable": "results",
        "atomic_path": "atomic",
        "read_table": "tables",
    },
)
del attach
