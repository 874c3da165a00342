"""Rules attribution_settings_<k>: thin adapter to
pencore.studies.attribution.settings.run_setting, once per setting of the job."""

from _common import start_log

from pencore.io.netcdf import write_netcdf
from pencore.studies.attribution.settings import NUMBERS, gather, run_setting

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
settings = [dict(s) for s in smk.params.settings]
log = start_log(smk, f"attribution_{smk.rule}")
for setting, path in zip(settings, smk.output.nc, strict=True):
    log.info("setting %s: %s", setting["name"], setting.get("choices"))
    ds = run_setting(setting)
    write_netcdf(ds, path, config_slice={"attribution.setting": setting}, study="attribution")
    one = gather([ds])
    for k, (label, units) in NUMBERS.items():
        log.info("%s: %.6g %s (paper %.6g)", label, float(one[f"value_{k}"][0]), units,
                 float(one[f"paper_{k}"]))  # fmt: skip
