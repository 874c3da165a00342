"""Files: netCDF with provenance (:mod:`netcdf`) and atomic, durable writes (:mod:`atomic`)."""

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
