"""Files: netCDF with provenance (:mod:`netcdf`) and atomic, durable writes (:mod:`atomic`)."""
