"""pencore.workflowconfig.sources: a change in the plotting package changes only the
plotting hash, a change elsewhere only the physics hash; names count, order does not."""

from pathlib import Path

from pencore.workflowconfig.sources import (
    PACKAGE_ROOT,
    physics_source_hash,
    physics_sources,
    plotting_source_hash,
    plotting_sources,
    source_hash,
)


def _package(root: Path) -> Path:
    (root / "plotting").mkdir(parents=True)
    (root / "run").mkdir()
    (root / "plotting" / "figure.py").write_text("COLOUR = 'k'\n")
    (root / "run" / "impact.py").write_text("G = 9.81\n")
    return root


def test_each_rule_family_reruns_only_for_its_code(tmp_path):
    root = _package(tmp_path / "pkg")
    physics, plotting = physics_source_hash(root), plotting_source_hash(root)
    (root / "plotting" / "figure.py").write_text("COLOUR = 'r'\n")
    assert physics_source_hash(root) == physics and plotting_source_hash(root) != plotting
    plotting = plotting_source_hash(root)
    (root / "run" / "impact.py").write_text("G = 9.80665\n")
    assert physics_source_hash(root) != physics and plotting_source_hash(root) == plotting


def test_a_rename_changes_the_hash_and_the_order_does_not(tmp_path):
    root = _package(tmp_path / "pkg")
    files = physics_sources(root)
    assert source_hash(files, root) == source_hash(files[::-1], root)
    before = physics_source_hash(root)
    (root / "run" / "impact.py").rename(root / "run" / "launch.py")
    assert physics_source_hash(root) != before
    assert len(physics_source_hash(root)) == 64


def test_the_package_splits_into_the_two_families():
    physics, plotting = set(physics_sources()), set(plotting_sources())
    assert physics and plotting and not physics & plotting
    assert physics | plotting == set(PACKAGE_ROOT.rglob("*.py"))
    assert PACKAGE_ROOT / "workflowconfig" / "registry.py" in physics
