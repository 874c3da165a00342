# Helpers shared by the rule files (no rules here).


def canonical(value):
    """A config slice with mapping keys sorted at every level, for `params:`.

    Snakemake compares params with their previous value as written, key order included;
    sorting makes reordering or reformatting a config file no reason to rerun.
    """
    if isinstance(value, dict):
        return {key: canonical(value[key]) for key in sorted(value)}
    if isinstance(value, list):
        return [canonical(item) for item in value]
    return value
