# Configuration helpers of the Section 4 rules (workflow/rules/section4.smk); no rules here.
# Every study, its configuration entry, shared keys, dataset, parts, figure and title come
# from its record in pencore.workflowconfig.registry.
import re

from pencore.workflowconfig.parts import parts_of, round_robin
from pencore.workflowconfig.registry import STUDIES

S4 = config["section4"]
# dataset -> study
S4_BY_DATASET = {s.dataset: s.id for s in STUDIES.values()}


def s4_alternatives(items):
    """A wildcard constraint matching exactly these strings."""
    return "|".join(re.escape(item) for item in sorted(set(items)))


def s4_folder_and_name(dataset):
    """results/<folder>/<name>.nc -> (folder, name)."""
    folder, name = dataset.removeprefix("results/").rsplit("/", 1)
    return folder, name.removesuffix(".nc")


# the wildcards of the study and gather rules: folders and names of the studies' datasets
S4_SINGLE = [s4_folder_and_name(s.dataset) for s in STUDIES.values() if not s.split_by]
S4_SPLIT = [s4_folder_and_name(s.dataset) for s in STUDIES.values() if s.split_by]


def s4_study_of(wildcards):
    """The study whose dataset the job makes."""
    return S4_BY_DATASET[f"results/{wildcards.study}/{wildcards.name}.nc"]


def s4_params(study):
    """Config slice of one study: its entry, the shared keys it reads, numerics."""
    record = STUDIES[study]
    return {
        "study": canonical(S4[record.entry]),
        "shared": canonical({key: S4[key] for key in record.shared}),
        "numerics": canonical(config["numerics"]),
    }


def s4_part_name(part):
    if "obliquity" in part:
        return f"{part['projectile']}_{part['obliquity']:g}"
    return part["projectile"]


def s4_parts_by_name(study):
    """The parts of a split study by name (the stem of each part's file)."""
    return {s4_part_name(p): p for p in parts_of(study, S4[STUDIES[study].entry])}


def s4_part_file(study, name):
    return f"{STUDIES[study].parts_dir}/{name}.nc"


def s4_parts(study):
    return [s4_part_file(study, name) for name in s4_parts_by_name(study)]


def s4_part_jobs(study):
    """The part names of a split study dealt in turn into `section4.part_jobs` jobs."""
    return round_robin(list(s4_parts_by_name(study)), S4["part_jobs"])
