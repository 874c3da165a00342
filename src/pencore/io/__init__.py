"""Files: netCDF with provenance (:mod:`netcdf`), atomic, durable writes (:mod:`atomic`),
and the check of result files (:mod:`results`).

``__all__`` lists the public names; each is imported from its module on first use, so the
command line's use of :mod:`atomic` does not load xarray.
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
    },
)
del attach
