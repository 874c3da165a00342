# Reproduction workflow of Li & Flores-Johnson (IJIE 2011) with pencore.
#   python -m snakemake --cores 2                      # every study (rule all)
#   python -m snakemake --cores 2 results/validation/table2.csv
#   python -m snakemake --cores 2 archive              # refresh results/archive/
#   python -m snakemake --report results/report.html
# Physics lives in the pencore package; rules call it through thin workflow/scripts/.
import sys
from pathlib import Path

import yaml
from snakemake.exceptions import WorkflowError
from snakemake.utils import min_version, validate

from pencore.errors import ConfigError
from pencore.io.results import set_aside_unreadable
from pencore.workflowconfig.parts import remade_target, round_robin
from pencore.workflowconfig.config_check import check_config, one_line_warnings, read_config
from pencore.workflowconfig.config_check import schema_error_message, strict_schema_error
from pencore.workflowconfig.sources import physics_source_hash, plotting_source_hash

min_version("9.0")


configfile: "config/config.yaml"


# The configuration is read again through pencore's input gate (plain decimal numbers,
# repeated keys refused; Snakemake's reader takes 23:20 for 1400 and keeps the last of two
# sections), in Snakemake's order: this file's configfile, each --configfile, --config.
# A bad config stops here with one line naming the key path (Snakemake's own message
# would print the whole schema; pencore.workflowconfig.config_check adds what a schema cannot say).
try:
    _cli_files = [Path(f).absolute() for f in workflow.overwrite_configfiles]
    _own_files = [
        f
        for f in workflow.configfiles
        if Path(f).absolute() not in _cli_files
        and not workflow.config_settings.replace_workflow_config
    ]
    _overrides = workflow.config_settings.config_args
    if not isinstance(_overrides, (list, tuple)):
        _overrides = workflow.config_settings.config
    _gated = read_config([*_own_files, *_cli_files], _overrides)
    config.clear()
    config.update(_gated)
    with open(workflow.source_path("workflow/schemas/config.schema.yaml")) as f:
        _schema = yaml.safe_load(f)
    _type_error = strict_schema_error(config, _schema)
    if _type_error:
        raise ConfigError(_type_error)
    validate(config, "workflow/schemas/config.schema.yaml")
    with one_line_warnings():  # an implausible value: one line, the run goes on
        check_config(config, workflow.basedir)
except ConfigError as exc:
    raise WorkflowError(str(exc)) from None
except Exception:
    with open(workflow.source_path("workflow/schemas/config.schema.yaml")) as f:
        schema = yaml.safe_load(f)
    raise WorkflowError(schema_error_message(config, schema)) from None


# a result that cannot be opened (corrupt, truncated by a crash or a full disk) would
# pass as up to date: set it aside, so that this run makes it again (below)
SET_ASIDE = set_aside_unreadable("results")


report: "workflow/report/workflow.rst"


# Each rule file appends its final outputs to ALL_TARGETS (built by `rule all`) and the
# aggregated datasets to commit under results/archive/ to ARCHIVE_DATASETS (rule archive).
ALL_TARGETS = []
ARCHIVE_DATASETS = []
# Hashes of pencore's source as params.code (Snakemake's `code` trigger sees only a rule's
# own script): solver/study rules get the physics (all but pencore/plotting), figure rules
# the plotting package; physics changes reach figures through their dataset inputs.
# See pencore.workflowconfig.sources.
PHYSICS_CODE = physics_source_hash()
PLOTTING_CODE = plotting_source_hash()


include: "workflow/rules/common.smk"
include: "workflow/rules/validation.smk"
include: "workflow/rules/record.smk"
include: "workflow/rules/section4.smk"
include: "workflow/rules/attribution.smk"
include: "workflow/rules/ensemble.smk"
include: "workflow/rules/tables.smk"
# Perforation of finite slabs (beyond the paper)
include: "workflow/rules/perforation.smk"
include: "workflow/rules/near_surface.smk"
include: "workflow/rules/archive.smk"


# A file set aside above is made again: a final result because `all` asks for it; an
# intermediate one (an ensemble chunk part, a study part) because it is asked for here,
# as Snakemake would leave it missing while the result gathered from it is up to date.
for _path, _reason in SET_ASIDE:
    _remade = remade_target(str(_path), workflow.rules, ENSEMBLES)
    if _remade:
        ALL_TARGETS.append(_remade)
    print(
        f"pencore: {_path} cannot be read ({_reason}); set aside as {_path.name}.corrupt"
        + (" and made again" if _remade else "; no rule of this configuration makes it"),
        file=sys.stderr,
    )


rule all:
    default_target: True
    input:
        ALL_TARGETS,


# The longest jobs (priority 1) start first, so that the short ones fill the cores at the
# end; the first "N of M steps done" line then waits for one of them. Said before the wait
# (light: the DAG Snakemake has already built, no import).
onstart:
    _long = sorted(
        {
            j.rule.name
            for j in workflow.dag.needrun_jobs()
            if isinstance(j.rule.priority, int) and j.rule.priority > 0
        }
    )
    if _long:
        _n = sum(1 for j in workflow.dag.needrun_jobs() if j.rule.name in _long)
        _names = ", ".join(_long[:3]) + (", ..." if len(_long) > 3 else "")
        print(
            f"pencore: the {_n} longest jobs ({_names}) start first, so the first "
            "'N of M steps done' line comes when one of them ends; the short jobs "
            "fill the cores after them",
            file=sys.stderr,
        )
