# Reproduction workflow of Li & Flores-Johnson (IJIE 2011) with pencore.
#   python -m snakemake --cores 2                      # every study (rule all)
#   python -m snakemake --cores 2 results/validation/table2.csv
#   python -m snakemake --cores 2 archive              # refresh results/archive/
#   python -m snakemake --report results/report.html
# Physics lives in the pencore package; rules call it through thin workflow/scripts/.
from snakemake.utils import min_version, validate

from snakemake.exceptions import WorkflowError

from pencore.studies.config_check import ConfigError, validate_config
from pencore.studies.sources import physics_source_hash, plotting_source_hash

min_version("9.0")


configfile: "config/config.yaml"


# schema (types, signs, defaults), then relations between values; either error is one
# line with the key path and value (pencore.studies.config_check)
try:
    validate_config(config, lambda c: validate(c, "workflow/schemas/config.schema.yaml"))
except ConfigError as e:
    raise WorkflowError(str(e)) from None


report: "workflow/report/workflow.rst"


# Each rule file appends its final outputs to ALL_TARGETS (built by `rule all`) and the
# aggregated datasets to commit under results/archive/ to ARCHIVE_DATASETS (rule archive).
ALL_TARGETS = []
ARCHIVE_DATASETS = []
# Hashes of pencore's source as params.code (Snakemake's `code` trigger sees only a rule's
# own script): solver/study rules get the physics (all but pencore/plotting), figure rules
# the plotting package; physics changes reach figures through their dataset inputs.
# See pencore.studies.sources.
PHYSICS_CODE = physics_source_hash()
PLOTTING_CODE = plotting_source_hash()


include: "workflow/rules/common.smk"
include: "workflow/rules/validation.smk"
include: "workflow/rules/section4.smk"
include: "workflow/rules/tables.smk"
include: "workflow/rules/archive.smk"


rule all:
    default_target: True
    input:
        ALL_TARGETS,
