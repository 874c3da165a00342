"""The docs pages: every module in the API reference, the generated tables built from
their files, and the few numbers typed in the prose equal to the files that hold them."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest
import yaml

REPO = Path(__file__).resolve().parents[2]
DOCS = REPO / "docs"


def _page(name: str) -> str:
    return (DOCS / name).read_text()


def test_developer_reference_reaches_every_module():
    """docs/api/modules.md lists packages and top-level modules with a recursive
    autosummary: every public module of src/pencore is one of them or inside one."""
    listed = set(re.findall(r"^   (pencore[\w.]*)$", _page("api/modules.md"), re.M))
    src = REPO / "src"
    modules = {
        ".".join(p.relative_to(src).with_suffix("").parts).removesuffix(".__init__")
        for p in (src / "pencore").rglob("*.py")
    }
    public = {m for m in modules if not any(part.startswith("_") for part in m.split(".")[1:])}
    public -= {"pencore"}  # the API reference (docs/api/index.md) documents its names
    unreached = {m for m in public if not any(m == e or m.startswith(e + ".") for e in listed)}
    assert unreached == set(), "modules missing from docs/api/modules.md"
    assert listed - modules == set(), "docs/api/modules.md lists modules that do not exist"


def test_api_reference_documents_every_public_name():
    """docs/api/index.md gives each name of pencore.__all__ its own page (autosummary)."""
    import pencore

    text = _page("api/index.md")
    listed = set(re.findall(r"^   (\w+)$", text, re.M))
    assert set(pencore.__all__) - {"__version__"} <= listed
    import pencore.closedform

    assert set(pencore.closedform.__all__) <= listed


def test_every_generated_include_has_a_generator(gen):
    includes = set()
    for page in DOCS.rglob("*.md"):
        if "_build" in page.parts or "_generated" in page.parts:
            continue
        includes |= set(re.findall(r"_generated/([\w.-]+\.md)", page.read_text()))
    assert includes <= set(gen.PAGES), includes - set(gen.PAGES)


@pytest.mark.parametrize("name", ["headline.md", "comparison.md", "ballistic_limit.md"])
def test_generated_tables_come_from_the_archive(gen, name):
    import pandas as pd

    text = gen.PAGES[name]()
    if name == "ballistic_limit.md":
        import xarray as xr

        with xr.open_dataset(REPO / "results/archive/perforation/ballistic_limit.nc") as ds:
            assert f"{float(ds.v_bl.values[0, 0]):.4g}" in text
        return
    table = pd.read_csv(REPO / "results/archive/paper_comparison.csv")
    vcr = table[table.quantity == "Vcr of #2 at 45 deg obliquity (Fig. 7)"].pencore_value
    digits = 5 if name == "headline.md" else 6
    assert f"{float(vcr.iloc[0]):.{digits}g}" in text


def test_no_markdown_page_holds_a_template_field():
    """The docs read the same on GitHub, in a terminal and in the site: no page holds a
    field only the site's build fills (``{{ name }}``)."""
    pages = [REPO / "README.md", *DOCS.rglob("*.md")]
    pages = [p for p in pages if not {"_build", "_generated", "auto_examples"} & set(p.parts)]
    assert len(pages) > 20
    held = [p.relative_to(REPO).as_posix() for p in pages if "{{" in p.read_text()]
    assert not held, f"template fields in {held}"


def test_the_numbers_written_into_the_pages_are_current(gen):
    """Each ``<!-- n:name -->value<!-- /n -->`` of a page holds what its file gives now
    (the archive, the benchmarks, the package's constants: ``pencore_docs.numbers()``)."""
    numbers = gen.numbers()
    used = set()
    for page in gen.number_pages():
        text = page.read_text()
        used |= set(re.findall(r"<!-- n:(\w+) -->", text))
        assert gen.with_numbers(text, numbers) == text, (
            f"{page.relative_to(REPO)} has stale numbers: run "
            "`python docs/_ext/pencore_docs.py --readme`"
        )
        # a line that starts with the comment would be an HTML block to Markdown
        starts = [ln for ln in text.splitlines() if ln.lstrip().startswith("<!-- n:")]
        assert not starts, (page.name, starts)
    assert {"warmup_cpu", "reproduction_wall", "ensemble_ms_per_sample"} <= used


def test_a_stale_number_is_rewritten_and_an_unknown_one_named(gen):
    text = "takes <!-- n:a -->1 s<!-- /n --> and <!-- n:b -->2<!-- /n --> m"
    assert gen.with_numbers(text, {"a": "3 s", "b": "2"}) == (
        "takes <!-- n:a -->3 s<!-- /n --> and <!-- n:b -->2<!-- /n --> m"
    )
    with pytest.raises(KeyError, match="n:b"):
        gen.with_numbers(text, {"a": "3 s"})


def test_ensemble_page_shows_the_shipped_case():
    block = re.search(r"```yaml\n(ensemble:.*?)```", _page("user-guide/ensembles.md"), re.S)
    shown = yaml.safe_load(block.group(1))["ensemble"]["cases"][0]
    shipped = yaml.safe_load((REPO / "config/config.yaml").read_text())["ensemble"]["cases"][0]
    assert shown == shipped
    large = yaml.safe_load((REPO / "config/ensemble_large.yaml").read_text())
    case = large["ensemble"]["cases"][0]
    text = _page("user-guide/ensembles.md")
    assert f"N = {case['n_samples']:,}".replace(",", " ") in text
    assert f"in {case['n_chunks']} chunks" in text


def test_typed_numbers_equal_their_sources():
    from pencore.studies.attribution.settings import TOLERANCE

    assert f"{100 * TOLERANCE:g} %" in _page("results/attribution.md")
    min_job_age = re.search(r"MinJobAge=(\d+)", (REPO / ".ci/slurm.sh").read_text()).group(1)
    assert f"uses {min_job_age} s" in _page("user-guide/cluster.md")
    python = tomllib.loads((REPO / "pyproject.toml").read_text())["project"]["requires-python"]
    assert f"Python {python.removeprefix('>=')} or newer" in _page("getting-started.md")


def test_no_reference_to_documents_not_in_the_repository():
    pages = [REPO / "README.md", *DOCS.rglob("*.md")]
    for page in pages:
        if "_build" in page.parts or "_generated" in page.parts:
            continue
        text = page.read_text()
        assert "paper guide" not in text.lower() and "../shared" not in text, page
        for link in re.findall(r"\]\(([^)#:]+)(?:#[^)]*)?\)", text):
            if link.startswith("http") or "auto_examples" in link:
                continue
            assert (page.parent / link).exists() or (page.parent / f"{link}.md").exists(), (
                f"{page.relative_to(REPO)} links to {link}, which does not exist"
            )


@pytest.mark.parametrize(
    "column, value, word",
    [
        ("pencore_value", "nan", "pencore_value = 'nan'"),
        ("pencore_value", "some text", "pencore_value = 'some text'"),
        ("paper_value", "inf", "paper_value = 'inf'"),
        ("paper_value", "0", "paper_value = '0'"),
        ("difference", "nan", "difference = 'nan'"),
    ],
)
def test_a_comparison_value_that_is_not_a_number_stops_the_build(
    gen, tmp_path, monkeypatch, column, value, word
):
    # a value row renders as a number and a relative difference: nan or stray text
    # there would print "+nan %" in the README and the docs; the build stops naming it
    import pandas as pd

    table = pd.read_csv(gen.COMPARISON, dtype=str, keep_default_na=False)
    row = table.index[table["quantity"] == "Vcr of #2 at 45 deg obliquity (Fig. 7)"][0]
    table.loc[row, column] = value
    bad = tmp_path / "paper_comparison.csv"
    table.to_csv(bad, index=False)
    monkeypatch.setattr(gen, "COMPARISON", bad)
    with pytest.raises(ValueError, match="row 'Vcr of #2 at 45 deg") as info:
        gen.PAGES["headline.md"]()
    assert word in str(info.value) and "\n" not in str(info.value)


def test_an_archived_dataset_of_another_study_stops_the_build(gen, tmp_path, monkeypatch):
    # a valid netCDF in the wrong place (a trajectory where the ballistic limits belong)
    # is named with both studies, not a KeyError on the variable it lacks
    import shutil

    archive = tmp_path / "results" / "archive"
    (archive / "perforation").mkdir(parents=True)
    shutil.copy(
        gen.ARCHIVE / "fig7" / "trajectories.nc", archive / "perforation" / "ballistic_limit.nc"
    )
    monkeypatch.setattr(gen, "REPO", tmp_path)
    monkeypatch.setattr(gen, "ARCHIVE", archive)
    with pytest.raises(ValueError) as info:
        gen.ballistic_limit_table()
    text = str(info.value)
    assert "results/archive/perforation/ballistic_limit.nc holds the study 'section4/fig7'" in text
    assert "not 'perforation/ballistic_limit'" in text and "\n" not in text


def _signature_rows(text: str) -> list[tuple[str, list[str]]]:
    """``(pencore.name, [param or param=default, ...])`` of each call in a table row."""
    rows = re.findall(r"^\| `(pencore\.[\w.]+)\(([^)]*)\)` \|", text, re.M)
    return [(name, [p.strip() for p in args.split(",")]) for name, args in rows]


def _signature_mismatches(name: str, shown: list[str]) -> list[str]:
    """How the call ``shown`` for ``name`` differs from the function's signature: the
    positional parameters in order, with their defaults."""
    import importlib
    import inspect

    module, _, attr = name.rpartition(".")
    func = getattr(importlib.import_module(module), attr)
    positional = [
        p
        for p in inspect.signature(func).parameters.values()
        if p.kind is inspect.Parameter.POSITIONAL_OR_KEYWORD
    ]
    out = []
    if len(shown) != len(positional):
        out.append(f"{name}: {len(shown)} parameters shown, {len(positional)} in the signature")
    for item, param in zip(shown, positional, strict=False):
        pname, _, default = item.partition("=")
        if pname != param.name:
            out.append(f"{name}: {pname!r} where the signature has {param.name!r}")
        elif (param.default is inspect.Parameter.empty) != (default == ""):
            out.append(f"{name}: {pname} default shown {default or 'none'}, is {param.default}")
        elif default and float(default) != float(param.default):
            out.append(f"{name}: {pname}={default} shown, default is {param.default}")
    return out


def test_critical_values_table_shows_the_signatures():
    """The user guide's table of searches gives each function's positional parameters
    and defaults as ``inspect.signature`` has them."""
    import importlib

    import pencore

    rows = _signature_rows(_page("user-guide/critical-values.md"))
    shown = set()
    for name, _ in rows:  # the public name or the module path: the same function
        module, _, attr = name.rpartition(".")
        shown.add(getattr(importlib.import_module(module), attr))
    assert shown == {pencore.vcr, pencore.vci, pencore.omega_c, pencore.ballistic_limit}
    assert [m for name, shown in rows for m in _signature_mismatches(name, shown)] == []


def test_signature_check_catches_a_wrong_default_and_a_missing_one():
    shown = ["projectile", "target", "obliquity", "yaw=0", "lo", "hi=4000", "tol=5"]
    found = _signature_mismatches("pencore.vcr", shown)
    assert found == ["pencore.vcr: lo default shown none, is 100.0"]
    shown[4:6] = ["lo=100", "hi=3000"]
    assert _signature_mismatches("pencore.vcr", shown) == [
        "pencore.vcr: hi=3000 shown, default is 4000.0"
    ]


def test_commands_never_put_a_target_after_configfile():
    """``--configfile`` takes every word up to the next option, so a target written after
    its file is read as a second configuration file: the commands the config files and the
    docs give end the file list with an option or the end of the command."""
    import re

    texts = [p.read_text() for p in (REPO / "config").glob("*.yaml")]
    texts += [p.read_text() for p in (REPO / "docs").rglob("*.md")]
    texts.append((REPO / "README.md").read_text())
    for text in texts:
        joined = re.sub(r"\\\s*\n\s*#?\s*", " ", text)  # continuation lines, commented or not
        for m in re.finditer(r"snakemake [^\n]*?--configfile\s+(\S+)\s+([^\s\\]+)", joined):
            assert m.group(2).startswith("-") or m.group(2) in ("```", "#"), m.group(0)


def test_measurements_page_states_the_computed_aluminium_laws_inputs():
    """The measurements page types the computed aluminium law's fit range and hardening
    exponent: they must be the library entry's."""
    import yaml

    law = yaml.safe_load((REPO / "src/pencore/inputs/data/media.yaml").read_text())[
        "aluminium_cavity"
    ]["law"]
    page = _page("results/measurements.md")
    assert f"fitted up to {float(law['max_speed']):g} m/s" in page
    assert f"an assumed n = {law['n']:g}" in page


def test_errors_page_lists_the_output_gates_suffixes():
    """The output rules on the errors page name the suffixes each writer knows, as
    pencore.io.outputs holds them."""
    from pencore.io import outputs

    text = " ".join(_page("user-guide/errors.md").split())
    for suffixes in (
        outputs.TABLE_SUFFIXES,
        outputs.NETCDF_SUFFIXES,
        outputs.FIGURE_SUFFIXES,
        outputs.YAML_SUFFIXES,
    ):
        listed = [f"`{s}`" for s in suffixes]
        words = listed[0] if len(listed) == 1 else ", ".join(listed[:-1]) + " or " + listed[-1]
        assert words in text, words
