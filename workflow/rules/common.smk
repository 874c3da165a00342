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


def pencore_code_hash():
    """SHA-256 of the pencore package's Python source.

    Given to every solver rule as ``params.code``: Snakemake's ``code`` trigger sees only
    a rule's own script, so without this a change in the physics would not rerun the
    studies that depend on it.
    """
    import hashlib
    from pathlib import Path

    import pencore

    digest = hashlib.sha256()
    root = Path(pencore.__file__).parent
    for path in sorted(root.rglob("*.py")):
        digest.update(path.relative_to(root).as_posix().encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()


PENCORE_CODE = pencore_code_hash()
