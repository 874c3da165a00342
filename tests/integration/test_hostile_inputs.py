"""A catalogue of hostile inputs, door by door: each is refused with one short line.

Doors: the Python API (``pencore.simulate``, ``pencore.prepare``, the searches), YAML
files (``--projectile FILE`` / ``--target FILE``), the command line, and the output
paths. Classes: integers no float can hold, numbers written as text in any notation but
plain decimal, hostile files (alias bombs, deep nesting, repeated keys, FIFOs, devices,
directories, oversized files), writes that would replace a non-regular file, a
read-only file or the run's own input (every --out, --plot and --write of every command
and the Python writers, through the one output gate), an interrupted command saying what
it wrote, plots given a Dataset of another kind or an edited one, grids of searches
larger than the bound, workflow config keys naming a target, a set or a table that does
not exist, search arguments, standard output that cannot be written, ``NUMBA_*``
settings numba refuses (the damaged and unwritable numba caches are in
``tests/kernels/test_cache.py``). Every case
asserts the exit status (or exception), exactly one line, no traceback, that the line
quotes at most a short prefix of the value, that no file is left behind, and a time
bound (a hang guard: every case is refused before any integration, measured well under
a second each). Valid edge inputs are accepted.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import pencore
from pencore.cli.main import main
from pencore.errors import InputError
from pencore.inputs.gate import MAX_YAML_BYTES, MAX_YAML_DEPTH, MAX_YAML_NODES
from pencore.inputs.library import get_projectile, get_target
from pencore.search import critical, perforation

HANG_GUARD_S = 20.0
HUGE = 10**400
HUGE_TEXT = "1" * 400
#: Longest message line a refusal may print (a value is quoted by a short prefix).
MAX_LINE = 400

PROJECTILE_YAML = """\
name: probe
diameter: 0.0254
nose: {kind: ogive, crh: 3.0, density: 7850}
shank:
  - {length: 0.1, density: 7850}
"""
TARGET_YAML = """\
name: slab
layers:
  - medium: {name: m, coefficients: [1.0e7, 0.0, 100.0], friction: 0.1}
"""


def _check_line(line: str) -> None:
    assert "Traceback" not in line
    assert len(line) < MAX_LINE, line
    assert HUGE_TEXT[:80] not in line, line  # the value is not quoted whole


def _cli(argv: list[str], capsys, cwd: Path) -> tuple[int, str]:
    before = set(os.listdir(cwd))
    t0 = time.monotonic()
    status = main(argv)
    elapsed = time.monotonic() - t0
    err = capsys.readouterr().err
    assert elapsed < HANG_GUARD_S, elapsed
    assert set(os.listdir(cwd)) == before, "a file was left behind"
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("pencore: error: "), err
    _check_line(lines[0])
    return status, lines[0]


def _api(call) -> str:
    t0 = time.monotonic()
    with pytest.raises(InputError) as info:
        call()
    assert time.monotonic() - t0 < HANG_GUARD_S
    text = str(info.value)
    assert "\n" not in text.strip(), text
    _check_line(text)
    return text


SIM = ["simulate", "--projectile", "p2", "--target", "soil"]

# ------------------------------------------------------------ huge integers: API

IMPACT_ARGS = ["velocity", "obliquity", "yaw", "omega", "azimuth"]
NUMERICS_NUMBERS = [
    "n_nose", "n_shank", "n_face", "eps", "rtol", "max_travel", "v_stop", "t_max",
    "max_steps", "max_wall", "h_min", "n_gauss", "jacobian_age", "gravity",
]  # fmt: skip


@pytest.mark.parametrize("sign", [1, -1])
@pytest.mark.parametrize("arg", IMPACT_ARGS)
def test_api_huge_integer_impact_argument(arg, sign):
    kwargs = {"velocity": 300.0, arg: sign * HUGE}
    text = _api(lambda: pencore.simulate("p2", "soil", **kwargs))
    assert "integer of 401 digits" in text


@pytest.mark.parametrize("axis", [0, 1, 2])
def test_api_huge_integer_start(axis):
    start = [0.0, 0.0, 0.0]
    start[axis] = HUGE
    text = _api(lambda: pencore.simulate("p2", "soil", 300.0, start=tuple(start)))
    assert "start" in text


@pytest.mark.parametrize("sign", [1, -1])
@pytest.mark.parametrize("key", NUMERICS_NUMBERS)
def test_api_huge_integer_numerics(key, sign):
    if key == "max_wall" and sign > 0:  # a budget beyond any float is no budget: valid
        assert pencore.prepare("p2", "soil", {key: HUGE}).numerics.max_wall == float("inf")
        return
    text = _api(lambda: pencore.prepare("p2", "soil", {key: sign * HUGE}))
    assert key in text


@pytest.mark.parametrize(
    "field", ["diameter", "crh", "nose_density", "length", "shank_density"]
)  # fmt: skip
def test_api_huge_integer_projectile_mapping(field):
    d = {
        "name": "probe", "diameter": 0.0254,
        "nose": {"kind": "ogive", "crh": 3.0, "density": 7850},
        "shank": [{"length": 0.1, "density": 7850}],
    }  # fmt: skip
    if field == "diameter":
        d["diameter"] = HUGE
    elif field == "crh":
        d["nose"]["crh"] = HUGE
    elif field == "nose_density":
        d["nose"]["density"] = HUGE
    elif field == "length":
        d["shank"][0]["length"] = HUGE
    else:
        d["shank"][0]["density"] = HUGE
    _api(lambda: get_projectile(d))


@pytest.mark.parametrize("field", ["a0", "a2", "friction", "thickness", "crater_depth"])
def test_api_huge_integer_target_mapping(field):
    medium = {"name": "m", "coefficients": [1e7, 0.0, 100.0]}
    layer = {"medium": medium}
    if field == "a0":
        medium["coefficients"][0] = HUGE
    elif field == "a2":
        medium["coefficients"][2] = HUGE
    elif field == "friction":
        medium["friction"] = HUGE
    elif field == "thickness":
        layer["thickness"] = HUGE
    else:
        layer["crater_depth"] = HUGE
    _api(lambda: get_target({"name": "t", "layers": [layer]}))


def test_api_layer_medium_given_as_huge_text():
    from pencore.inputs.target import Layer, Target

    text = _api(lambda: pencore.simulate("p2", Target("t", (Layer(HUGE_TEXT, 0.1),)), 300.0))
    assert "got str '111" in text and "(402 characters)" in text
    assert "pencore.get_target(NAME).medium" in text


# ------------------------------------------------------------ huge integers: CLI

CLI_NUMBER_OPTIONS = [
    ["--velocity", HUGE_TEXT],
    ["--velocity", "300", "--obliquity", HUGE_TEXT],
    ["--velocity", "300", "--yaw", HUGE_TEXT],
    ["--velocity", "300", "--omega", HUGE_TEXT],
    ["--velocity", "300", "--start", HUGE_TEXT, "0", "0"],
    ["--velocity", "300", "--start", "0", HUGE_TEXT, "0"],
    ["--velocity", "300", "--start", "0", "0", HUGE_TEXT],
    ["--velocity", "300", "--crater-depth", HUGE_TEXT],
    ["--velocity", "300", "--free-surface-depth", HUGE_TEXT],
    ["--velocity", "-" + HUGE_TEXT],
]


@pytest.mark.parametrize("opts", CLI_NUMBER_OPTIONS, ids=lambda o: "-".join(o[-4:])[:30])
def test_cli_huge_number_option(opts, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    status, _ = _cli([*SIM, *opts], capsys, tmp_path)
    assert status == 2


@pytest.mark.parametrize("key", NUMERICS_NUMBERS)
def test_cli_huge_numerics_value(key, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    # (a positive budget beyond any float is no budget, which is valid)
    value = f"-{HUGE_TEXT}" if key == "max_wall" else HUGE_TEXT
    status, line = _cli(
        [*SIM, "--velocity", "300", "--numerics", f"{key}={value}"], capsys, tmp_path
    )
    assert status == 2
    assert key in line


def test_cli_huge_numerics_key(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    status, _ = _cli([*SIM, "--velocity", "300", "--numerics", f"{HUGE_TEXT}=1"], capsys, tmp_path)
    assert status == 2


#: --numerics values YAML reads as null (which in a mapping means the default).
EMPTY_NUMERICS = ["method=", "rtol=", "max_steps=~", "eps=null", "t_max= ", "jacobian=NULL"]


@pytest.mark.parametrize("option", EMPTY_NUMERICS)
def test_cli_empty_numerics_value(option, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    status, line = _cli([*SIM, "--velocity", "300", "--numerics", option], capsys, tmp_path)
    assert status == 2
    key = option.partition("=")[0]
    assert f"--numerics: {key!r} has no value" in line, line


# ------------------------------------------------------------ huge integers: YAML files

YAML_PROJECTILE_EDITS = {
    "diameter": ("diameter: 0.0254", f"diameter: {HUGE_TEXT}"),
    "crh": ("crh: 3.0", f"crh: {HUGE_TEXT}"),
    "nose-density": ("crh: 3.0, density: 7850", f"crh: 3.0, density: {HUGE_TEXT}"),
    "shank-length": ("length: 0.1", f"length: {HUGE_TEXT}"),
    "shank-density": ("length: 0.1, density: 7850", f"length: 0.1, density: -{HUGE_TEXT}"),
}
YAML_TARGET_EDITS = {
    "a0": ("[1.0e7, 0.0, 100.0]", f"[{HUGE_TEXT}, 0.0, 100.0]"),
    "a1": ("[1.0e7, 0.0, 100.0]", f"[1.0e7, {HUGE_TEXT}, 100.0]"),
    "a2": ("[1.0e7, 0.0, 100.0]", f"[1.0e7, 0.0, -{HUGE_TEXT}]"),
    "friction": ("friction: 0.1", f"friction: {HUGE_TEXT}"),
    "friction-table": ("friction: 0.1", f"friction: [[0, 0.1], [{HUGE_TEXT}, 0.2]]"),
    "thickness": ("friction: 0.1}", f"friction: 0.1}}\n    thickness: {HUGE_TEXT}"),
    "gap": ("layers:\n", f"layers:\n  - gap: {HUGE_TEXT}\n"),
}


@pytest.mark.parametrize("edit", list(YAML_PROJECTILE_EDITS))
def test_yaml_projectile_huge_integer(edit, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    old, new = YAML_PROJECTILE_EDITS[edit]
    assert old in PROJECTILE_YAML
    (tmp_path / "p.yaml").write_text(PROJECTILE_YAML.replace(old, new))
    status, line = _cli(
        ["simulate", "--projectile", "p.yaml", "--target", "soil", "--velocity", "300"],
        capsys,
        tmp_path,
    )
    assert status == 2
    assert "p.yaml" in line


@pytest.mark.parametrize("edit", list(YAML_TARGET_EDITS))
def test_yaml_target_huge_integer(edit, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    old, new = YAML_TARGET_EDITS[edit]
    assert old in TARGET_YAML
    (tmp_path / "t.yaml").write_text(TARGET_YAML.replace(old, new, 1))
    status, line = _cli(
        ["simulate", "--projectile", "p2", "--target", "t.yaml", "--velocity", "300"],
        capsys,
        tmp_path,
    )
    assert status == 2
    assert "t.yaml" in line


# ------------------------------------------------------------ numbers written as text

#: Text that Python's float() or YAML 1.1 reads as a number but pencore refuses.
EXOTIC_NUMBERS = {
    "separator": "1_0",  # float() and YAML 1.1: 10
    "arabic-indic": "\u0661",  # float(): 1
    "fullwidth": "\uff15",  # float(): 5
    "blanks": " 5 ",  # float(): 5
    "leading-zero": "0750",  # float(): 750; YAML 1.1: the octal 488
    "hexadecimal": "0x10",  # YAML 1.1: 16
    "binary": "0b11",  # YAML 1.1: 3
    "base-60": "1:30",  # YAML 1.1: 90
}
#: The forms Python's float() reads (the others never passed float()).
FLOAT_EXOTIC = ["separator", "arabic-indic", "fullwidth", "blanks", "leading-zero"]
#: (form, quoted): quoted, every form; plain, the forms YAML 1.1 reads as numbers.
YAML_EXOTIC = [(form, True) for form in EXOTIC_NUMBERS] + [
    (form, False) for form in ("separator", "leading-zero", "hexadecimal", "binary", "base-60")
]
NOTATION = "plain decimal"


@pytest.mark.parametrize(("form", "quoted"), YAML_EXOTIC, ids=lambda x: str(x))
def test_yaml_exotic_number_refused(form, quoted, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    text = EXOTIC_NUMBERS[form]
    value = f'"{text}"' if quoted else text
    (tmp_path / "t.yaml").write_text(
        f"name: t\nlayers:\n  - {{medium: concrete, thickness: {value}}}\n  - {{medium: soil}}\n"
    )
    status, line = _cli(
        ["simulate", "--projectile", "p2", "--target", "t.yaml", "--velocity", "300"],
        capsys,
        tmp_path,
    )
    assert status == 2
    assert "layer thickness" in line and NOTATION in line and repr(text) in line, line


@pytest.mark.parametrize("form", FLOAT_EXOTIC)
def test_api_mapping_exotic_number_refused(form):
    text = EXOTIC_NUMBERS[form]
    layer = {"medium": "concrete", "thickness": text}
    message = _api(lambda: get_target({"name": "t", "layers": [layer, {"medium": "soil"}]}))
    assert "layer thickness" in message and NOTATION in message, message


@pytest.mark.parametrize("form", FLOAT_EXOTIC)
def test_cli_exotic_number_option_refused(form, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    text = EXOTIC_NUMBERS[form]
    status, line = _cli([*SIM, f"--velocity={text}"], capsys, tmp_path)
    assert status == 2
    assert "--velocity" in line and NOTATION in line and repr(text) in line, line


@pytest.mark.parametrize("form", [f for f in EXOTIC_NUMBERS if f != "blanks"])
def test_cli_exotic_numerics_value_refused(form, capsys, tmp_path, monkeypatch):
    # (a --numerics value is a YAML scalar: blanks around it are not part of it)
    monkeypatch.chdir(tmp_path)
    text = EXOTIC_NUMBERS[form]
    status, line = _cli(
        [*SIM, "--velocity", "300", "--numerics", f"max_steps={text}"], capsys, tmp_path
    )
    assert status == 2
    assert "max_steps" in line and NOTATION in line, line


def test_yaml_text_that_yaml_1_1_reads_as_a_number_stays_text(tmp_path):
    path = tmp_path / "t.yaml"
    path.write_text("name: 1_0\ncoefficients: [1.0e7, 0.0, 100.0]\n")
    assert get_target(str(path)).name == "1_0"


# ------------------------------------------------------------ hostile files

ALIAS_BOMB = (
    'a: &a ["lol","lol","lol","lol","lol","lol","lol","lol","lol"]\n'
    + "".join(
        f"{chr(98 + i)}: &{chr(98 + i)} [{', '.join(['*' + chr(97 + i)] * 9)}]\n" for i in range(8)
    )
    + "name: *i\n"
)


def _hostile_file(kind: str, folder: Path) -> tuple[str, str]:
    """(path, a word the refusal must contain) of a hostile input file."""
    path = folder / f"{kind}.yaml"
    if kind == "alias-bomb":
        path.write_text(ALIAS_BOMB)
        return str(path), "alias"
    if kind == "recursive-alias":
        path.write_text("name: &a [*a]\n")
        return str(path), "alias"
    if kind == "deep-nesting":
        path.write_text("name: " + "[" * 5000 + "]" * 5000 + "\n")
        return str(path), f"deeper than {MAX_YAML_DEPTH}"
    if kind == "deep-mapping":
        path.write_text("".join("  " * i + f"k{i}:\n" for i in range(200)) + "  " * 200 + "v\n")
        return str(path), "deeper"
    if kind == "duplicate-key":
        path.write_text("name: a\nname: b\n")
        return str(path), "repeats the key 'name'"
    if kind == "duplicate-nested-key":
        path.write_text("nose: {kind: ogive, kind: cone}\n")
        return str(path), "repeats the key 'kind'"
    if kind == "fifo":
        os.mkfifo(path)
        return str(path), "a FIFO"
    if kind == "directory":
        path.mkdir()
        return str(path), "a directory"
    if kind == "dev-zero":
        return "/dev/zero", "a character device"
    if kind == "dev-null":
        return "/dev/null", "a character device"
    if kind == "oversized":
        with open(path, "wb") as f:
            f.truncate(MAX_YAML_BYTES + 1)
        return str(path), "bytes"
    if kind == "binary":
        path.write_bytes(b"\xff\xfe\x00\x01garbage")
        return str(path), "UTF-8"
    if kind == "not-a-mapping":
        path.write_text("- 1\n- 2\n")
        return str(path), "mapping"
    if kind == "syntax-error":
        path.write_text("name: [unclosed\n")
        return str(path), "not valid YAML"
    if kind in CONTROL_CHARACTERS:
        char = CONTROL_CHARACTERS[kind]
        path.write_text(f"name: probe\nnote: a{char}b\n")
        return str(path), f"U+{ord(char):04X} is not allowed"
    if kind == "too-many-values":
        path.write_text("name: x\nnote: [" + "1, " * MAX_YAML_NODES + "1]\n")
        return str(path), f"more than {MAX_YAML_NODES} values"
    if kind == "missing":
        return str(path), "No such file"
    raise AssertionError(kind)


#: Characters YAML does not allow anywhere in a document.
CONTROL_CHARACTERS = {"bel": "\x07", "esc": "\x1b", "nul": "\x00"}


HOSTILE_FILES = [
    "alias-bomb", "recursive-alias", "deep-nesting", "deep-mapping", "duplicate-key",
    "duplicate-nested-key", "fifo", "directory", "dev-zero", "dev-null", "oversized",
    "binary", "not-a-mapping", "syntax-error", "missing", *CONTROL_CHARACTERS,
    "too-many-values",
]  # fmt: skip


@pytest.mark.parametrize("role", ["--projectile", "--target"])
@pytest.mark.parametrize("kind", HOSTILE_FILES)
def test_cli_hostile_file(kind, role, capsys, tmp_path, monkeypatch):
    folder = tmp_path / "in"
    folder.mkdir()
    path, word = _hostile_file(kind, folder)
    monkeypatch.chdir(tmp_path)
    other = "soil" if role == "--projectile" else "p2"
    args = {"--projectile": other, "--target": other, role: path}
    status, line = _cli(
        ["simulate", "--projectile", args["--projectile"], "--target", args["--target"],
         "--velocity", "300"],
        capsys, tmp_path,
    )  # fmt: skip
    assert status == 2
    assert word in line, line


@pytest.mark.parametrize("kind", HOSTILE_FILES)
def test_api_hostile_file(kind, tmp_path):
    path, word = _hostile_file(kind, tmp_path)
    text = _api(lambda: get_target(path))
    assert word in text


@pytest.mark.parametrize("char", list(CONTROL_CHARACTERS.values()), ids=list(CONTROL_CHARACTERS))
def test_control_character_located_by_line_and_column(char, tmp_path):
    path = tmp_path / "t.yaml"
    path.write_text(f"name: t\ncoefficients: [1.0e7, 0.0, 1{char}00.0]\n")
    text = _api(lambda: get_target(str(path)))
    assert f"target file {str(path)!r} is not valid YAML: the character U+{ord(char):04X}" in text
    assert text.endswith("at line 2, column 29"), text  # 28 characters before it


@pytest.mark.parametrize("char", [*CONTROL_CHARACTERS.values(), "\ud800"])
def test_cli_numerics_value_with_a_control_character(char, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    status, line = _cli(
        [*SIM, "--velocity", "300", "--numerics", f"rtol=1e-5{char}"], capsys, tmp_path
    )
    assert status == 2
    # the value is not YAML, so it stays text, which is not plain decimal
    assert "rtol must be a number written in plain decimal" in line, line
    assert f"got {'1e-5' + char!r}" in line, line


def test_yaml_merge_keys_accepted(tmp_path):
    # a merge key (<<) takes the keys of an anchored mapping; the mapping's own keys win
    path = tmp_path / "t.yaml"
    path.write_text(
        "name: merged\nlayers:\n"
        "  - medium: &m {name: m, coefficients: [1.0e7, 0.0, 100.0], friction: 0.1}\n"
        "    thickness: 0.1\n"
        "  - medium: {<<: *m, name: rough, friction: 0.3}\n"
    )
    target = get_target(str(path))
    assert [lay.medium.name for lay in target.layers] == ["m", "rough"]
    assert target.layers[1].medium.coefficients == (1.0e7, 0.0, 100.0)
    assert target.layers[1].medium.friction_mu[0] == 0.3
    # a key repeated in the mapping itself is still refused, merged or not
    path.write_text("name: t\ncoefficients: &c [1.0e7, 0.0, 100.0]\nx: {<<: {a: 1}, b: 2, b: 3}\n")
    assert "repeats the key 'b' (line 3)" in _api(lambda: get_target(str(path)))


# ------------------------------------------------------------ writes


def _out_cases(folder: Path) -> dict[str, tuple[list[str], str, int]]:
    target = folder / "t.nc"  # a YAML target whose name ends in .nc
    target.write_text(TARGET_YAML)
    os.link(target, folder / "link.nc")
    os.mkfifo(folder / "fifo.nc")
    (folder / "dir.nc").mkdir()
    (folder / "other.txt").write_text("kept\n")
    os.symlink("other.txt", folder / "sym.nc")
    os.symlink("nowhere.nc", folder / "dangling.nc")
    base = ["simulate", "--projectile", "p2", "--target", str(target), "--velocity", "300"]
    long_name = "o" * 300 + ".nc"
    return {
        "out-is-symlink": ([*base, "--out", str(folder / "sym.nc")], "symbolic link", 2),
        "out-is-dangling-symlink": (
            [*base, "--out", str(folder / "dangling.nc")],
            "symbolic link",
            2,
        ),
        "out-name-too-long": ([*base, "--out", str(folder / long_name)], "too long", 2),
        "out-is-input": ([*base, "--out", str(target)], "input of this run", 2),
        "out-is-hard-link-of-input": ([*base, "--out", str(folder / "link.nc")], "input", 2),
        "out-is-fifo": ([*base, "--out", str(folder / "fifo.nc")], "a FIFO", 2),
        "out-is-directory": ([*base, "--out", str(folder / "dir.nc")], "directory", 2),
        "out-is-dev-null": (
            [*SIM, "--velocity", "300", "--out", "/dev/null"],
            "character device",
            2,
        ),
        "out-under-a-file": (
            [*base, "--out", str(target / "x.nc")],
            f"of '{target / 'x.nc'}' is not a directory: it is a regular file",
            2,
        ),
        "out-deep-under-a-file": (
            [*base, "--out", str(target / "sub" / "x.nc")],
            f"is not a directory: '{target}' is a regular file",
            2,
        ),
        "out-under-a-fifo": (
            [*base, "--out", str(folder / "fifo.nc" / "x.nc")],
            "is not a directory: it is a FIFO",
            2,
        ),
        "fit-table3-to-dev-null": (["fit-table3", "--write", "/dev/null"], "character device", 2),
        "fit-table3-to-fifo": (["fit-table3", "--write", str(folder / "fifo.nc")], "FIFO", 2),
    }


OUT_CASES = [
    "out-is-input", "out-is-hard-link-of-input", "out-is-fifo", "out-is-directory",
    "out-is-dev-null", "out-under-a-file", "out-deep-under-a-file", "out-under-a-fifo",
    "fit-table3-to-dev-null", "fit-table3-to-fifo", "out-is-symlink", "out-is-dangling-symlink",
    "out-name-too-long",
]  # fmt: skip


@pytest.mark.parametrize("case", OUT_CASES)
def test_cli_refuses_to_replace(case, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    argv, word, expected = _out_cases(tmp_path)[case]
    before = (tmp_path / "t.nc").read_text()
    t0 = time.monotonic()
    status = main(argv)
    assert time.monotonic() - t0 < HANG_GUARD_S
    err = capsys.readouterr().err.strip().splitlines()
    assert status == expected
    assert len(err) == 1 and err[0].startswith("pencore: error: "), err
    assert word in err[0], err
    assert (tmp_path / "t.nc").read_text() == before  # the input is untouched
    assert (tmp_path / "other.txt").read_text() == "kept\n"
    assert (tmp_path / "sym.nc").is_symlink() and (tmp_path / "dangling.nc").is_symlink()
    assert not [n for n in os.listdir(tmp_path) if "pencore-tmp" in n or "probe" in n]


# ------------------------------------------------------------ the one output gate

PLATE_YAML = "name: plate\nlayers:\n  - {medium: aluminium, thickness: 0.01}\n"

#: Every command that writes a file, its arguments (``{P}``: the projectile file, ``{T}``:
#: a plate target file) and the options that write, with a suffix each accepts.
WRITERS = {
    "simulate": (["--target", "soil", "--velocity", "300"], {"--out": ".nc", "--plot": ".png"}),
    "ballistic-limit": (["--target", "{T}"], {"--out": ".csv", "--plot": ".pdf"}),
    "vcr": (["--target", "concrete", "--obliquity", "30", "--lo", "200", "--hi", "900"],
            {"--out": ".csv", "--plot": ".png"}),
    "vci": (["--target", "soil", "--yaw", "1", "--threshold", "1"],
            {"--out": ".nc", "--plot": ".svg"}),
    "omega-c": (["--target", "soil", "--velocity", "300", "--hi", "100"],
                {"--out": ".csv", "--plot": ".png"}),
    "depth-curve": (["--target", "soil", "--velocities", "300"], {"--out": ".csv"}),
    "residual-velocity": (["--target", "{T}", "--velocities", "300"],
                          {"--out": ".nc", "--plot": ".png"}),
    "ballistic-table": (["--medium", "soil", "--thicknesses", "0.1"],
                        {"--out": ".csv", "--plot": ".png"}),
    "fit-table3": ([], {"--write": ".yaml"}),
}  # fmt: skip
#: What a destination is, and the words of its refusal.
BAD_DESTINATIONS = {
    "input": "input of this run",
    "read-only": "read-only (mode 0444)",
    "trailing-slash": "names a directory",
    "folder": "is a directory",
    "unknown-suffix": "must end in one of",
}
GATE_CASES = [
    (command, option, bad)
    for command, (_, options) in WRITERS.items()
    for option in options
    for bad in BAD_DESTINATIONS
    if not (command == "fit-table3" and bad == "input")  # it reads no file
]


@pytest.mark.parametrize("command, option, bad", GATE_CASES, ids=lambda x: str(x))
def test_every_writer_goes_through_the_output_gate(command, option, bad, capsys, tmp_path,
                                                    monkeypatch):  # fmt: skip
    # every --out, --plot and --write of every command: refused before any run, one line,
    # status 2, the file there untouched and nothing left beside it
    monkeypatch.chdir(tmp_path)
    extra, options = WRITERS[command]
    suffix = options[option]
    projectile = f"proj{suffix}"  # a projectile YAML file with the output's suffix
    (tmp_path / projectile).write_text(PROJECTILE_YAML)
    (tmp_path / "plate.yaml").write_text(PLATE_YAML)
    (tmp_path / f"keep{suffix}").write_text("keep me\n")
    (tmp_path / f"keep{suffix}").chmod(0o444)
    (tmp_path / f"d{suffix}").mkdir()
    dest = {
        "input": projectile,
        "read-only": f"keep{suffix}",
        "trailing-slash": f"o{suffix}/",
        "folder": f"d{suffix}",
        "unknown-suffix": "o.txt" if suffix != ".txt" else "o.dat",
    }[bad]
    argv = [command]
    if command != "fit-table3":
        argv += ["--projectile", projectile]
    argv += [a.replace("{T}", "plate.yaml") for a in extra] + [option, dest]
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir() if p.is_file()}
    status, line = _cli(argv, capsys, tmp_path)
    assert status == 2, line
    assert BAD_DESTINATIONS[bad] in line, line
    if bad == "unknown-suffix":
        assert ", ".join(options_suffixes(command, option)) in line, line
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir() if p.is_file()} == before


def options_suffixes(command: str, option: str) -> tuple[str, ...]:
    from pencore.io import outputs

    if (command, option) == ("simulate", "--out"):
        return outputs.NETCDF_SUFFIXES
    return {
        "--out": outputs.TABLE_SUFFIXES,
        "--plot": outputs.FIGURE_SUFFIXES,
        "--write": outputs.YAML_SUFFIXES,
    }[option]


def _read_back(tmp_path: Path) -> tuple[xr.Dataset, Path]:
    path = tmp_path / "run.nc"
    pencore.write_netcdf(xr.Dataset({"a": ("x", [1.0, 2.0])}), path, config_slice={}, study="t")
    return pencore.read_netcdf(path), path


def _figure():
    from pencore.plotting.style import new_figure

    return new_figure()


PY_WRITERS = {
    "write_netcdf-onto-its-source": (
        lambda d: pencore.write_netcdf(_read_back(d)[0], d / "run.nc", config_slice={}, study="t"),
        "input of this run",
    ),
    "write_netcdf-unknown-suffix": (
        lambda d: pencore.write_netcdf(xr.Dataset(), d / "x.h5", config_slice={}, study="t"),
        "must end in one of .nc",
    ),
    "write_netcdf-read-only": (
        lambda d: pencore.write_netcdf(xr.Dataset(), d / "keep.nc", config_slice={}, study="t"),
        "read-only",
    ),
    "write_netcdf-trailing-slash": (
        lambda d: pencore.write_netcdf(xr.Dataset(), f"{d}/o.nc/", config_slice={}, study="t"),
        "names a directory",
    ),
    "save_figure-unknown-suffix": (
        lambda d: pencore.plotting.save_figure(_figure(), d / "f.jpg"),
        "must end in one of .png, .pdf, .svg",
    ),
    "save_figure-read-only": (
        lambda d: pencore.plotting.save_figure(_figure(), d / "keep.png"),
        "read-only",
    ),
    "save_figure-folder": (lambda d: pencore.plotting.save_figure(_figure(), d), "directory"),
    "save_figure-second-path-bad": (
        # every path is checked before the first is written
        lambda d: pencore.plotting.save_figure(_figure(), d / "new.png", d / "keep.png"),
        "read-only",
    ),
    "write_table3_geometry-read-only": (
        lambda d: pencore.inputs.library.write_table3_geometry(
            pencore.inputs.library.table3_fit(), d / "keep.yaml"
        ),
        "read-only",
    ),
}


@pytest.mark.parametrize("case", list(PY_WRITERS))
def test_python_writers_go_through_the_output_gate(case, tmp_path):
    import pencore.inputs.library
    import pencore.plotting

    for name in ("keep.nc", "keep.png", "keep.yaml"):
        (tmp_path / name).write_text("keep me\n")
        (tmp_path / name).chmod(0o444)
    call, words = PY_WRITERS[case]
    if case == "write_netcdf-onto-its-source":  # outside any call: the Dataset's own file
        ds, path = _read_back(tmp_path)
        before = {p.name: p.read_bytes() for p in tmp_path.iterdir() if p.is_file()}
        with pytest.raises(pencore.WriteError) as info:
            pencore.write_netcdf(ds, path, config_slice={}, study="t")
    else:
        before = {p.name: p.read_bytes() for p in tmp_path.iterdir() if p.is_file()}
        with pytest.raises(pencore.WriteError) as info:
            call(tmp_path)
    text = str(info.value)
    assert words in text and "\n" not in text, text
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir() if p.is_file()} == before
    assert not [p for p in tmp_path.iterdir() if "pencore-tmp" in p.name]


def test_a_file_read_in_a_call_is_never_its_output(tmp_path):
    # any file read through the input gate while a call is open is protected, whatever
    # option or function read it
    import pencore.io.outputs as outputs

    (tmp_path / "proj.yaml").write_text(PROJECTILE_YAML)
    ds = xr.Dataset({"a": ("x", [1.0])})
    with outputs.output_call():
        get_projectile(str(tmp_path / "proj.yaml"))
        with pytest.raises(pencore.WriteError, match="input of this run"):
            pencore.write_netcdf(ds, tmp_path / "proj.yaml", config_slice={}, study="t")
    assert (tmp_path / "proj.yaml").read_text() == PROJECTILE_YAML


@pytest.mark.parametrize("interrupt", ["ctrl-c", "sigterm"])
def test_an_interrupted_command_says_what_is_on_disk(interrupt, capsys, tmp_path, monkeypatch):
    # the table is written, then the plot is interrupted: the line names the table kept
    import signal

    import pencore.plotting.run

    monkeypatch.chdir(tmp_path)

    def stopped(*args, **kwargs):
        if interrupt == "ctrl-c":
            raise KeyboardInterrupt
        raise SystemExit(128 + signal.SIGTERM)  # what pencore.io.atomic makes of SIGTERM

    monkeypatch.setattr(pencore.plotting.run, "plot_run", stopped)
    status = main([*SIM, "--velocity", "300", "--out", "t.nc", "--plot", "t.png"])
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1, err
    word = "interrupted (Ctrl-C)" if interrupt == "ctrl-c" else "terminated (SIGTERM)"
    assert status == (130 if interrupt == "ctrl-c" else 143)
    assert f"{word}; written completely before it: 't.nc'; nothing else was written" in err[0]
    assert "nothing was written" not in err[0]
    assert sorted(os.listdir(tmp_path)) == ["t.nc"]


def test_a_table_of_too_many_searches_is_refused_before_any_run(capsys, tmp_path, monkeypatch):
    from pencore.studies.common import MAX_SEARCHES

    monkeypatch.chdir(tmp_path)
    thicknesses = [f"{0.001 * (k + 1):g}" for k in range(200)]
    obliquities = [str(k) for k in range(-44, 45)]
    argv = ["ballistic-table", "--projectile", "p2", "--medium", "aluminium", "--thicknesses",
            *thicknesses, "--obliquities", *obliquities, "--out", "t.csv"]  # fmt: skip
    status, line = _cli(argv, capsys, tmp_path)
    assert status == 2
    assert f"200 x 89 = 17800 searches; at most {MAX_SEARCHES} are allowed" in line


# ------------------------------------------------------------ plots check their Dataset


def _plot_names() -> list[str]:
    import pencore.plotting

    return sorted(n for n in pencore.plotting.__all__ if n.startswith("plot_"))


def _datasets() -> dict[str, object]:
    from pencore.search.history import search_dataset
    from pencore.search.threshold import find_threshold

    run = pencore.simulate("p2", "soil", 300.0)
    search = search_dataset(find_threshold(lambda v: v >= 300.0, 100.0, 900.0, 50.0), "vcr",
                            "m s-1", "critical reverse velocity")  # fmt: skip
    return {
        "a-number": 42,
        "a-path": "run.nc",
        "an-empty-dataset": xr.Dataset(),
        "a-run": run,
        "a-search": search,
        "an-empty-run": run.isel(time=slice(0, 0)),
    }


@pytest.mark.parametrize("name", _plot_names())
def test_every_plot_checks_its_dataset(name):
    # a Dataset of another kind, an empty one, or no Dataset: one InputError line each
    import pencore.plotting

    plot = getattr(pencore.plotting, name)
    for kind, ds in _datasets().items():
        if (name, kind) in (("plot_run", "a-run"), ("plot_search", "a-search")):
            continue  # its own kind
        with pytest.raises(InputError) as info:
            plot(ds)
        text = str(info.value)
        assert "\n" not in text and name in text and len(text) < MAX_LINE, (kind, text)


TAMPERED = {
    "plot_run-empty": ("plot_run", lambda run, s, rv: run.isel(time=slice(0, 0)), "no point"),
    "plot_run-text-speed": (
        "plot_run", lambda run, s, rv: run.assign(speed=run.speed.astype(str)), "plot_run"
    ),
    "plot_search-quantity-renamed": (
        "plot_search", lambda run, s, rv: s.assign_attrs(quantity="v_bl"), "lacks"
    ),
    "plot_search-no-status": (
        "plot_search", lambda run, s, rv: s.drop_attrs(deep=False), "lacks"
    ),
    "plot_residual_velocity-text-fit": (
        "plot_residual_velocity",
        lambda run, s, rv: rv.assign_attrs(recht_ipson_a="one"),
        "must be a number",
    ),
    "plot_residual_velocity-no-fit": (
        "plot_residual_velocity",
        lambda run, s, rv: rv.drop_attrs(deep=False),
        "lacks the attribute(s) recht_ipson_a",
    ),
    "plot_residual_velocity-no-points": (
        "plot_residual_velocity", lambda run, s, rv: rv.isel(velocity=slice(0, 0)), "no point"
    ),
}  # fmt: skip


@pytest.mark.parametrize("case", list(TAMPERED))
def test_a_tampered_dataset_is_one_line(case):
    import pencore.plotting
    from pencore.studies.sweeps import residual_curve

    name, edit, words = TAMPERED[case]
    data = _datasets()
    plate = {"name": "plate", "layers": [{"medium": "aluminium", "thickness": 0.05}]}
    with pytest.warns(pencore.PlausibilityWarning):
        rv = residual_curve("p2", plate, [500.0, 900.0])
    with pytest.raises(InputError) as info:
        getattr(pencore.plotting, name)(edit(data["a-run"], data["a-search"], rv))
    assert words in str(info.value) and "\n" not in str(info.value), str(info.value)


@pytest.mark.parametrize("path", ["run.jpg", "folder", "folder/"])
def test_plot_run_to_a_bad_path_is_one_line(path, tmp_path):
    (tmp_path / "folder").mkdir()
    with pytest.raises(pencore.WriteError) as info:
        pencore.plot_run(pencore.simulate("p2", "soil", 300.0), path=str(tmp_path / path))
    assert "\n" not in str(info.value)
    assert sorted(os.listdir(tmp_path)) == ["folder"]


# ------------------------------------------------------------ search arguments

SEARCHES = {
    "vcr": lambda **kw: critical.vcr("p2", "soil", 45.0, **kw),
    "vci": lambda **kw: critical.vci("p2", "soil", 0.1, threshold_deg=1.0, **kw),
    "omega_c": lambda **kw: critical.omega_c("p2", "soil", 500.0, **kw),
    "ballistic_limit": lambda **kw: perforation.ballistic_limit("p2", "soil", **kw),
}
BAD_SEARCH_ARGS = {
    "lo-text": ({"lo": "100", "hi": 2000.0}, "lo"),
    "hi-nan": ({"lo": 100.0, "hi": float("nan")}, "hi"),
    "lo-above-hi": ({"lo": 2000.0, "hi": 100.0}, "lo < hi"),
    "hi-huge": ({"lo": 100.0, "hi": HUGE}, "hi"),
    "tol-text": ({"lo": 100.0, "hi": 2000.0, "tol": "5"}, "tol"),
    "tol-zero": ({"lo": 100.0, "hi": 2000.0, "tol": 0.0}, "tol"),
    "max-iter-nan": ({"lo": 100.0, "hi": 2000.0, "max_iter": float("nan")}, "max_iter"),
    "max-iter-fraction": ({"lo": 100.0, "hi": 2000.0, "max_iter": 2.5}, "max_iter"),
    "max-iter-huge": ({"lo": 100.0, "hi": 2000.0, "max_iter": HUGE}, "max_iter"),
    "scan-huge": ({"lo": 100.0, "hi": 2000.0, "scan": 10**12}, "scan"),
    "scan-one": ({"lo": 100.0, "hi": 2000.0, "scan": 1}, "scan"),
    "scan-text": ({"lo": 100.0, "hi": 2000.0, "scan": "5"}, "scan"),
}


@pytest.mark.parametrize("bad", list(BAD_SEARCH_ARGS))
@pytest.mark.parametrize("search", list(SEARCHES))
def test_search_arguments_refused_before_any_run(search, bad):
    kwargs, word = BAD_SEARCH_ARGS[bad]
    if search == "omega_c":  # bounds in rad/s: shift them inside the omega range
        kwargs = {
            k: (v / 1000.0 if k in ("lo", "hi") and isinstance(v, float) else v)
            for k, v in kwargs.items()
        }
    text = _api(lambda: SEARCHES[search](**kwargs))
    assert word in text


@pytest.mark.parametrize("fraction", [2.0, 0.0, -0.5, float("nan"), "0.5", HUGE])
def test_vci_fraction_refused(fraction):
    text = _api(lambda: critical.vci("p2", "soil", 0.1, 500.0, 2000.0, 1.0, fraction=fraction))
    assert "fraction" in text


# ------------------------------------------------------------ laws from material properties

#: Valid inputs of each law (SI), and the numeric ones the number gate checks.
LAW_INPUTS = {
    "concrete": dict(fc=40e6, density=2300.0, s=11.0, crater_depth=2.0, friction=0.1),
    "metal": dict(youngs_modulus=68.9e9, poisson_ratio=0.33, yield_strength=276e6,
                  hardening_exponent=0.05, density=2710.0, max_speed=800.0, friction=0.1),
    "soil": dict(a=1.718, tau0=10e6, b=2.215, density=1860.0, friction=0.1),
}  # fmt: skip
LAW_CASES = [(law, key) for law, d in LAW_INPUTS.items() for key in d]
#: Values the number gate refuses for every input, whatever its range.
LAW_HOSTILE = {"huge": HUGE, "huge-text": HUGE_TEXT, "separator": "1_0", "bool": True,
               "nan": float("nan"), "none": None, "list": [1.0], "blank": " 5"}  # fmt: skip


def _law(law: str, **change):
    from pencore.inputs.laws import LAWS

    return LAWS[law][0](**{**LAW_INPUTS[law], **change})


@pytest.mark.parametrize("hostile", list(LAW_HOSTILE))
@pytest.mark.parametrize(("law", "key"), LAW_CASES)
def test_every_law_input_goes_through_the_number_gate(law, key, hostile):
    """Each numeric input of each law is refused like any other input: one line
    naming it, before any computation (``s=None`` is Forrestal's S from fc)."""
    if (key, hostile) == ("s", "none"):
        pytest.skip("s=None means S from fc")
    text = _api(lambda: _law(law, **{key: LAW_HOSTILE[hostile]}))
    names = {"youngs_modulus": "E", "poisson_ratio": "nu", "yield_strength": "Y",
             "hardening_exponent": "n", "s": "S", "a": "A", "b": "B"}  # fmt: skip
    assert f"{names.get(key, key)} must be" in text, text


@pytest.mark.parametrize(("law", "key"), LAW_CASES)
def test_every_law_input_takes_text_and_numpy_scalars(law, key):
    """Plain-decimal text (the command line, YAML) and numpy scalars are the numbers
    they hold: the same medium to the bit."""
    value = LAW_INPUTS[law][key]
    ref = _law(law)
    assert _law(law, **{key: repr(value)}) == ref
    assert _law(law, **{key: np.float64(value)}) == ref


@pytest.mark.parametrize(("law", "key"), LAW_CASES)
def test_every_law_keyword_misspelt_is_named(law, key):
    kwargs = dict(LAW_INPUTS[law])
    kwargs[key + "x"] = kwargs.pop(key)
    from pencore.inputs.laws import LAWS

    text = _api(lambda: LAWS[law][0](**kwargs))
    assert f"did you mean {key!r}" in text


# ------------------------------------------------------------ standard output


@pytest.mark.parametrize(
    "redirect, word",
    [(">/dev/full", "cannot write to standard output"), (">&-", "standard output is closed")],
)
def test_cli_stdout_that_cannot_be_written(redirect, word, tmp_path):
    cmd = f"{sys.executable} -m pencore list"
    t0 = time.monotonic()
    proc = subprocess.run(
        f"{cmd} {redirect}", shell=True, cwd=tmp_path, capture_output=True, text=True,
        timeout=120,
    )  # fmt: skip
    assert time.monotonic() - t0 < HANG_GUARD_S
    assert proc.returncode == 1
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and word in lines[0], proc.stderr
    assert "Traceback" not in proc.stderr


@pytest.mark.parametrize("args", ["--version", "--help", "simulate --help"])
def test_cli_help_and_version_to_a_full_device(args, tmp_path):
    # argparse swallows a failed write of help or version text: the command says so
    proc = subprocess.run(
        f"{sys.executable} -m pencore {args} >/dev/full", shell=True, cwd=tmp_path,
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert proc.returncode == 1
    assert proc.stderr.strip().splitlines() == [
        "pencore: error: cannot write to standard output: disk full"
    ]


# ------------------------------------------------------------ numba's environment


@pytest.mark.parametrize("door", ["cli", "api"])
def test_numba_setting_numba_refuses(door, tmp_path):
    # numba stops at import on NUMBA_NUM_THREADS=0 ("must be > 0"): one line naming the
    # variable, exit 2 on the command line, InputError from the API; nothing written
    env = {**os.environ, "NUMBA_NUM_THREADS": "0"}
    if door == "cli":
        cmd = [sys.executable, "-m", "pencore", "simulate", "--projectile", "p2",
               "--target", "soil", "--velocity", "280", "--out", "r.nc"]  # fmt: skip
    else:
        code = (
            "import pencore\n"
            "try:\n    pencore.simulate('p2', 'soil', 280.0)\n"
            "except pencore.InputError as e:\n    print('InputError:', e)\n"
        )
        cmd = [sys.executable, "-c", code]
    t0 = time.monotonic()
    proc = subprocess.run(cmd, cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120)
    assert time.monotonic() - t0 < HANG_GUARD_S
    assert list(tmp_path.iterdir()) == []
    out = proc.stderr if door == "cli" else proc.stdout
    lines = out.strip().splitlines()
    assert len(lines) == 1, proc.stderr + proc.stdout
    _check_line(lines[0])
    assert "NUMBA_NUM_THREADS='0'" in lines[0] and "must be > 0" in lines[0]
    if door == "cli":
        assert proc.returncode == 2
        assert lines[0].startswith("pencore: error: numba refused its environment settings")
    else:
        assert proc.returncode == 0 and lines[0].startswith("InputError: numba refused")


@pytest.mark.parametrize("role", ["--projectile", "--target"])
@pytest.mark.parametrize("length", [256, 100_000])
def test_cli_names_longer_than_a_file_name_can_be(role, length, capsys, tmp_path, monkeypatch):
    # no file system can look such a name up (ENAMETOOLONG): it is an unknown name
    monkeypatch.chdir(tmp_path)
    argv = ["simulate", "--projectile", "p2", "--target", "soil", "--velocity", "300"]
    argv[argv.index(role) + 1] = "x" * length
    status, line = _cli(argv, capsys, tmp_path)
    assert status == 2 and f"unknown {role[2:]}" in line


def test_v_stop_below_the_creep_of_the_smoothed_step_is_refused(capsys, tmp_path, monkeypatch):
    # a body at rest creeps back out under the smoothed contact step (eps > 0): with
    # v_stop = 1e-300 a stopped projectile drifted out of a plate and ended `exited`
    assert "v_stop = 1e-300 m/s is below 10 eps" in _api(
        lambda: pencore.simulate("p2", "soil", 60.0, v_stop=1e-300)
    )
    monkeypatch.chdir(tmp_path)
    status, line = _cli([*SIM, "--velocity", "60", "--numerics", "v_stop=0.001"], capsys, tmp_path)
    assert status == 2 and "v_stop = 0.001 m/s" in line
    # the sharp law (eps = 0) has no creep, and v_stop = 10 eps is accepted
    pencore.prepare("p2", "soil", eps=0.0, v_stop=1e-300)
    plate = {"name": "plate", "layers": [{"medium": "aluminium", "thickness": 0.005}]}
    assert pencore.simulate("p2", plate, 60.0, v_stop=0.01, t_max=100).attrs["outcome"] == "stopped"


def test_api_names_with_a_nul_or_too_long():
    assert "NUL" in _api(lambda: pencore.get_target("a\x00b.yaml"))
    assert "unknown target" in _api(lambda: pencore.get_target("s" * 300))
    assert "unknown projectile" in _api(lambda: pencore.get_projectile("p" * 300))


# ------------------------------------------------------------ valid edge inputs


def test_valid_numpy_scalars_and_long_output_name(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    # numpy scalars are numbers
    medium = get_target("soil").medium.with_friction(np.float32(0.1))
    assert medium.friction_mu[0] == pytest.approx(0.1)
    pencore.prepare("p2", "soil", {"max_steps": np.int64(1000), "rtol": np.float32(1e-5)})
    # a 243-byte output name (the file-system limit is 255) is written
    name = "x" * 240 + ".nc"
    status = main([*SIM, "--velocity", "300", "--out", name])
    assert status == 0, capsys.readouterr().err
    assert (tmp_path / name).is_file()
    assert not [n for n in os.listdir(tmp_path) if "pencore-tmp" in n]


def test_valid_yaml_with_anchors_and_a_long_friction_table(tmp_path):
    rows = "\n".join(f"  - [{i * 0.2:.3f}, 0.1]" for i in range(10_000))
    path = tmp_path / "t.yaml"
    path.write_text(
        "name: anchored\nlayers:\n  - medium: &m {name: m, coefficients: [1.0e7, 0.0, 100.0]}\n"
        "    thickness: 0.1\n  - medium: *m\n"
    )
    target = get_target(str(path))
    assert len(target.layers) == 2
    path.write_text(f"name: rough\ncoefficients: [1.0e7, 0.0, 100.0]\nfriction:\n{rows}\n")
    assert len(get_target(str(path)).medium.friction_speeds) == 10_000


@pytest.mark.parametrize(
    "kwargs",
    [
        {"max_steps": 10**9},
        {"n_gauss": 64},
        {"max_wall": float("inf")},
        {"rtol": 1e-12},
        {"t_max": 100},
        {"eps": 0.1},  # the top of eps's range runs with the default v_stop
    ],
)
def test_valid_numerics_at_the_limits_accepted(kwargs):
    pr = pencore.prepare("p2", "soil", kwargs)
    for key, value in kwargs.items():
        assert getattr(pr.numerics, key) == value


def test_valid_numbers_written_as_text(capsys, tmp_path, monkeypatch):
    # text in plain decimal is a number in a YAML file (quoted too) and on the command line
    monkeypatch.chdir(tmp_path)
    (tmp_path / "t.yaml").write_text(
        'name: t\nlayers:\n  - {medium: concrete, thickness: "0.5"}\n'
        "  - {medium: {name: m, coefficients: [3e8, 0, +2e3], friction: .1}, thickness: 1E-1}\n"
    )
    target = get_target("t.yaml")
    assert [lay.thickness for lay in target.layers] == [0.5, 0.1]
    assert target.layers[1].medium.coefficients == (3e8, 0.0, 2e3)
    argv = [*SIM, "--velocity=+3e2", "--numerics", "max_wall=inf", "--numerics", "rtol=1E-5"]
    assert main(argv) == 0, capsys.readouterr().err
    assert "300 m/s" in capsys.readouterr().out


def test_negative_obliquity_on_the_command_line_as_in_the_api(capsys, tmp_path, monkeypatch):
    # the command line takes the obliquity range of the limits table, (-90, 90) deg
    monkeypatch.chdir(tmp_path)
    assert main([*SIM, "--velocity", "300", "--obliquity", "-30", "--out", "m.nc"]) == 0
    out = capsys.readouterr().out
    ds = pencore.simulate("p2", "soil", 300.0, -30.0)
    assert f"{float(ds['penetration_depth']):.6g} m" in out
    assert "obliquity -30 deg" in out
    with xr.open_dataset(tmp_path / "m.nc") as written:
        assert written.attrs["obliquity_deg"] == -30.0
        assert float(written.cm_x[-1]) == float(ds.cm_x[-1]) < 0.0


# ------------------------------------------------------------ workflow configuration

REPO = Path(__file__).resolve().parents[2]


def _config() -> dict:
    import yaml

    return yaml.safe_load((REPO / "config" / "config.yaml").read_text())


def _edit(cfg: dict, path: str, value) -> dict:
    node = cfg
    keys = path.split(".")
    for k in keys[:-1]:
        node = node[int(k)] if isinstance(node, list) else node[k]
    if isinstance(node, list):
        node[int(keys[-1])] = value
    else:
        node[keys[-1]] = value
    return cfg


BAD_CONFIG = [
    ("numerics", {"rtol": 0.5}, "rtol"),
    ("numerics", {"max_steps": HUGE}, "max_steps"),
    ("numerics", {"n_gauss": 0}, "n_gauss"),
    ("numerics", {"method": "RK45"}, "method"),
    ("numerics", {"rtoll": 1e-6}, "did you mean"),
    ("ensemble.cases.0.projectile", "p9", "unknown projectile"),
    ("ensemble.cases.0.target", "mud", "unknown target"),
    ("ensemble.cases.0.target", "missing/target.yaml", "No such file"),
    ("validation.measurements.0.projectile", "p7", "unknown projectile"),
    ("validation.measurements.0.target", "sand", "unknown target"),
    ("validation.fig5.cases.0.projectile", "concrete_crh9", "unknown projectile"),
    ("perforation.projectile", "p0", "unknown projectile"),
    ("perforation.medium", "steel", "unknown medium"),
    ("ensemble.cases.0.velocity_m_s", {"dist": "normal", "mean": 9000, "sd": 800}, "velocity"),
    ("ensemble.cases.0.yaw_deg", {"dist": "uniform", "min": -95, "max": 5}, "yaw"),
    ("ensemble.cases.0.yaw_deg", {"dist": "normal", "mean": 0, "sd": 10}, "90 deg"),
    ("ensemble.cases.0.omega_rad_s", {"dist": "normal", "mean": 0, "sd": 5000}, "omega"),
    ("ensemble.cases.0.azimuth_deg", {"dist": "uniform", "min": 0, "max": 720}, "azimuth"),
    ("perforation.ballistic_limit.thickness_m", [0.5, 0.0], "thickness"),
    ("perforation.ballistic_limit.thickness_m", [0.5, float("nan")], "thickness"),
    ("perforation.residual_velocity.thickness_m", -1.0, "thickness"),
    ("perforation.residual_velocity.thickness_m", HUGE, "thickness"),
    ("perforation.scan_points", 10**9, "scan_points"),
    ("perforation.scan_points", 1, "scan_points"),
    ("perforation.scan_points", 2.5, "scan_points"),
    ("validation.fig5.cases.0.v_min", 1500.0, "v_min"),
    ("validation.fig5.cases.2.v_min", 5000.0, "misses"),
    ("validation.fig5.cases.0.v_max", -10.0, "v_max"),
    # every key that names a thing: lists of targets, data tables, shot sets
    ("validation.measurements.1.targets", ["aluminium", "aluminum"], "unknown target"),
    ("validation.measurements.1.csv", "config/no_such_shots.csv", "cannot read"),
    ("validation.fig5.body_shots",
     {"config/concrete_ogive_shots.csv": {"forrestal1996_d12.9_crh3_fc13.6": "grout_crh3"}},
     "no set 'forrestal1996_d12.9_crh3_fc13.6' in"),
    ("validation.fig5.body_shots",
     {"config/concrete_ogive_shots.csv": {"forrestal1996_d12.9_crh3_fc13.5": "grout_crh9"}},
     "unknown projectile"),
    ("validation.fig5.body_shots", {"config/no_such.csv": {"a": "grout_crh3"}}, "cannot read"),
    ("validation.fig5.shots", ["config/aluminium_ogive_shots.csv", "config/typo.csv"],
     "validation.fig5.shots[1]: cannot read"),
    ("near_surface.csv", "config/oblique_ballistic_limit.csv", "near_surface.csv: cannot read"),
]  # fmt: skip


@pytest.mark.parametrize("path, value, word", BAD_CONFIG, ids=lambda x: str(x)[:40])
def test_workflow_config_refused_at_parse_time(path, value, word):
    from pencore.errors import ConfigError
    from pencore.workflowconfig.config_check import check_config

    cfg = _edit(_config(), path, value)
    t0 = time.monotonic()
    with pytest.raises(ConfigError) as info:
        check_config(cfg, REPO)
    assert time.monotonic() - t0 < HANG_GUARD_S
    text = str(info.value)
    assert "\n" not in text
    _check_line(text)
    assert word in text, text


@pytest.mark.parametrize("column, name", [("projectile", "al_ogive_var4430"),
                                          ("target", "aluminum")])  # fmt: skip
def test_a_measurement_table_row_naming_an_unknown_thing_is_refused(column, name, tmp_path):
    # a measurement table's rows may name their projectile and target: looked up at parse
    from pencore.errors import ConfigError
    from pencore.workflowconfig.config_check import check_config

    table = tmp_path / "shots.csv"
    table.write_text(
        "# a measured table\n"
        "test,velocity_m_s,obliquity_deg,yaw_deg,measured_depth_m,projectile,target,source\n"
        "1,500,0,0,0.1,al_ogive_var4340,aluminium,a source\n"
        f"2,600,0,0,0.1,{name if column == 'projectile' else 'al_ogive_var4340'},"
        f"{name if column == 'target' else 'aluminium'},a source\n"
    )
    cfg = _edit(_config(), "validation.measurements.0.csv", str(table))
    with pytest.raises(ConfigError) as info:
        check_config(cfg, REPO)
    text = str(info.value)
    assert f"validation.measurements[0].csv (row 2, column {column})" in text, text
    assert f"unknown {column}" in text and "\n" not in text, text


def test_shipped_workflow_configs_pass():
    import yaml

    from pencore.workflowconfig.config_check import check_config

    check_config(_config(), REPO)
    large = _config()
    large.update(yaml.safe_load((REPO / "config" / "ensemble_large.yaml").read_text()))
    check_config(large, REPO)


# ------------------------------------------------------------ messages that name the cause


def test_slow_impact_from_the_default_start_is_run():
    # the nose tip reaches 1.45 mm below the outermost ring: from the touching start a
    # speed of 1 mm/s reaches the target within t_max
    ds = pencore.simulate("p2", "soil", 1e-3)
    assert ds.attrs["outcome"] == "stopped"


def test_tiny_t_max_from_the_default_start_is_run():
    # the default start touches the target, so any t_max is a run: it ends by the time
    # limit after the one step t_max allows, not by a refusal
    ds = pencore.simulate("p2", "soil", 300.0, t_max=1e-12)
    assert ds.attrs["outcome"] == "time_limit"
    assert float(ds.time[-1]) == 1e-12 and ds.sizes["time"] == 2
    assert float(ds.speed[-1]) == pytest.approx(300.0, rel=1e-9)


def test_a_start_too_high_for_t_max_is_refused_naming_the_start():
    text = _api(lambda: pencore.simulate("p2", "soil", 300.0, start=(0.0, 10.0, 0.0), t_max=1e-3))
    assert "start height 10.35 m (centre of mass) is too high" in text
    assert "t_max = 0.001 s" in text


def test_a_one_micron_foil_is_perforated(tmp_path, capsys):
    # a layer thinner than every band of the body is resolved at the band scale: the
    # run takes hundreds of steps, not the millions half its thickness would need
    foil = {"name": "foil", "layers": [{"medium": "aluminium", "thickness": 1e-6}]}
    ds = pencore.simulate("p2", foil, 300.0)
    assert ds.attrs["outcome"] == "perforated" and ds.sizes["time"] < 10_000
    assert 299.99 < ds.attrs["residual_velocity"] < 300.0
    path = tmp_path / "foil.yaml"
    path.write_text("name: foil\nlayers:\n  - {medium: aluminium, thickness: 1.0e-6}\n")
    argv = ["simulate", "--projectile", "p2", "--target", str(path), "--velocity", "300"]
    assert main(argv) == 0
    assert "perforated" in capsys.readouterr().out


# ------------------------------------------------------------ workflow configuration: the gate

CONFIG_GATE = [
    # (text of a --configfile, what the one line says)
    ("archive:\n  max_points: 23:20\n", "archive.max_points: must be of type integer, got '23:20'"),
    ("archive: {max_points: 4}\narchive: {max_points: 3}\n", "repeats the key 'archive' (line 2)"),
    ("archive:\n  max_points: -0.0\n", "archive.max_points: must be of type integer, got -0.0"),
    ("archive:\n  max_points: 1_0\n", "must be of type integer, got '1_0'"),
    ("archive:\n  max_points: 4\x07\n", "U+0007 is not allowed"),
    ("- 1\n", "must hold a mapping of sections, got list"),
]  # fmt: skip


@pytest.mark.parametrize("text, word", CONFIG_GATE, ids=lambda x: str(x)[:30])
def test_workflow_config_read_through_the_gate(text, word, tmp_path):
    import yaml

    from pencore.errors import ConfigError
    from pencore.workflowconfig.config_check import read_config, strict_schema_error

    extra = tmp_path / "extra.yaml"
    extra.write_text(text)
    schema = yaml.safe_load((REPO / "workflow" / "schemas" / "config.schema.yaml").read_text())
    t0 = time.monotonic()
    try:
        cfg = read_config([REPO / "config" / "config.yaml", extra])
        message = strict_schema_error(cfg, schema)
    except ConfigError as exc:
        message = str(exc)
    assert time.monotonic() - t0 < HANG_GUARD_S
    assert message is not None and "\n" not in message
    _check_line(message)
    assert word in message, message


def test_workflow_config_merged_as_snakemake_merges_it(tmp_path):
    import yaml

    from pencore.errors import ConfigError
    from pencore.workflowconfig.config_check import check_config, read_config, strict_schema_error

    # a --configfile updates the shipped one section by section; --config KEY=VALUE on top
    extra = tmp_path / "extra.yaml"
    extra.write_text("numerics: {rtol: 1.0e-6}\narchive: {max_points: 300}\n")
    cfg = read_config([REPO / "config" / "config.yaml", extra], ["archive={max_points: 200}"])
    assert cfg["numerics"] == {"rtol": 1e-6} and cfg["archive"] == {"max_points": 200}
    assert cfg["validation"] == _config()["validation"]
    schema = yaml.safe_load((REPO / "workflow" / "schemas" / "config.schema.yaml").read_text())
    assert strict_schema_error(cfg, schema) is None
    check_config(cfg, REPO)
    # a --config value goes through the gate too
    with pytest.raises(ConfigError, match="U\\+001B is not allowed"):
        read_config([REPO / "config" / "config.yaml"], ["archive={max_points: 2\x1b}"])


@pytest.mark.parametrize(
    "path, value, word",
    [
        ("ensemble.cases.0.n_chunks", 10**5, "n_chunks must be in [1, 1000], got 100000"),
        ("ensemble.cases.0.n_chunks", 10**7, "n_chunks must be in [1, 1000], got 10000000"),
        ("ensemble.cases.0.n_samples", 10**9, "n_samples must be in [1, 1e+06], got 1000000000"),
    ],
)
def test_workflow_counts_refused_before_the_plan(path, value, word):
    from pencore.errors import ConfigError
    from pencore.workflowconfig.config_check import check_config

    t0 = time.monotonic()
    with pytest.raises(ConfigError) as info:
        check_config(_edit(_config(), path, value), REPO)
    assert time.monotonic() - t0 < 1.0
    assert word in str(info.value), info.value


# ------------------------------------------------------------ counts

COUNT_CASES = {
    "layers": (
        lambda: get_target({"name": "x", "layers": [{"medium": "soil", "thickness": 0.1}] * 10**5}),
        "number of layers must be in [1, 1000], got 100000",
    ),
    "shank-segments": (
        lambda: get_projectile(
            {
                "name": "p",
                "diameter": 0.0254,
                "nose": {"kind": "ogive", "crh": 3, "density": 7850},
                "shank": [{"length": 0.001, "density": 7850}] * 10**5,
            }
        ),
        "number of shank segments must be in [0, 1000], got 100000",
    ),  # fmt: skip
    "friction-rows": (
        lambda: get_target(
            {
                "name": "r",
                "coefficients": [1e7, 0, 100],
                "friction": [[i, 0.1] for i in range(10**6)],
            }
        ),
        "friction table rows must be in [1, 10000], got 1000000",
    ),
    "layer-objects": (
        lambda: pencore.Target("x", [pencore.Layer(get_target("soil").medium, 0.1)] * 10**5),
        "number of layers must be in [1, 1000], got 100000",
    ),
    "samples": (
        lambda: __import__("pencore.studies.ensemble", fromlist=["x"]).sample_conditions(
            {
                "name": "a",
                "projectile": "p2",
                "target": "soil",
                "n_samples": 10**9,
                "velocity_m_s": 300,
            }
        ),
        "n_samples must be in [1, 1e+06], got 1000000000",
    ),
}


def test_yaml_with_more_values_than_the_gate_admits_is_refused_at_the_count(tmp_path):
    # 10^5 layers in 3.5 MB: refused when the value count passes MAX_YAML_NODES, not parsed whole
    path = tmp_path / "t.yaml"
    path.write_text("name: x\nlayers:\n" + "  - {medium: soil, thickness: 0.1}\n" * 10**5)
    t0 = time.monotonic()
    text = _api(lambda: get_target(str(path)))
    assert time.monotonic() - t0 < 10.0
    assert f"holds more than {MAX_YAML_NODES} values" in text


def test_the_longest_friction_table_the_limits_admit_is_read(tmp_path):
    rows = "".join(f"  - [{i}, 0.1]\n" for i in range(10_000))
    path = tmp_path / "t.yaml"
    path.write_text(f"name: rough\ncoefficients: [1.0e7, 0.0, 100.0]\nfriction:\n{rows}")
    assert len(get_target(str(path)).medium.friction_speeds) == 10_000


# ------------------------------------------------------------ silent and raw cases


@pytest.mark.parametrize(
    "value",
    [np.timedelta64(300), np.datetime64("2020-01-01"), np.array(np.timedelta64(3, "s"))],
    ids=["timedelta64", "datetime64", "timedelta-array"],
)
def test_numpy_times_are_not_speeds(value):
    text = _api(lambda: pencore.simulate("p2", "soil", value))
    assert "velocity must be a number of m/s" in text


RAW_API = {
    "nose-kind-list": (
        lambda: get_projectile(
            {"name": "p", "diameter": 0.0254, "nose": {"kind": ["ogive"], "density": 7850}}
        ),
        "nose kind must be ogive, cone or flat, got ['ogive']",
    ),
    "layer-thickness-text": (
        lambda: pencore.Layer(get_target("soil").medium, "1"),
        "layer thickness must be a number of m, got '1' (str)",
    ),
    "cone-of-1e-6-deg": (
        lambda: get_projectile(
            {
                "name": "p",
                "diameter": 0.0254,
                "nose": {"kind": "cone", "half_angle_deg": 1e-6, "density": 7850},
            }
        ),
        "nose length 7.277e+05 m is beyond 100 m",
    ),  # fmt: skip
    "distribution-kind-list": (
        lambda: __import__("pencore.studies.ensemble", fromlist=["x"]).sample_conditions(
            {"name": "a", "projectile": "p2", "target": "soil", "velocity_m_s": {"dist": ["x"]}}
        ),
        "dist must be one of fixed, uniform, normal, got ['x']",
    ),
}


@pytest.mark.parametrize("case", [*COUNT_CASES, *RAW_API])
def test_api_refusals_are_one_line_naming_the_value(case):
    # counts refused naming the limit, and raw exceptions turned into one line
    call, word = {**COUNT_CASES, **RAW_API}[case]
    text = _api(call)
    assert word in text, text


def test_cli_out_with_a_trailing_slash_is_refused(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    status, line = _cli([*SIM, "--velocity", "300", "--out", "o.nc/"], capsys, tmp_path)
    assert status == 2
    assert "output file 'o.nc/': it ends in '/', which names a directory" in line


def test_cli_out_onto_a_read_only_file_is_refused(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    kept = tmp_path / "kept.nc"
    kept.write_bytes(b"keep me")
    kept.chmod(0o444)
    status, line = _cli([*SIM, "--velocity", "300", "--out", "kept.nc"], capsys, tmp_path)
    assert status == 2
    assert "output file 'kept.nc': it is read-only (mode 0444)" in line
    assert kept.read_bytes() == b"keep me"


def test_cli_v_stop_not_below_the_impact_speed_is_refused(capsys, tmp_path, monkeypatch):
    # the run would stop before its first step and report a depth of 0
    monkeypatch.chdir(tmp_path)
    argv = [*SIM, "--velocity", "300", "--numerics", "v_stop=1000"]
    status, line = _cli(argv, capsys, tmp_path)
    assert status == 2
    assert "v_stop = 1000 m/s is not below the impact speed 300 m/s" in line


def test_cli_non_ascii_out_under_an_ascii_locale(tmp_path):
    # an ASCII file-system encoding: the name arrives as undecodable bytes, which netCDF
    # cannot take; refused before the run, nothing written
    env = {**os.environ, "LC_ALL": "C", "PYTHONIOENCODING": "ascii", "PYTHONUTF8": "0"}
    env["PYTHONCOERCECLOCALE"] = "0"
    argv = [sys.executable, "-m", "pencore", *SIM, "--velocity", "300", "--out", "é.nc"]
    out = subprocess.run(argv, cwd=tmp_path, env=env, capture_output=True, timeout=120)
    assert out.returncode == 2, out.stderr
    lines = out.stderr.decode("ascii").strip().splitlines()
    assert len(lines) == 1 and "is not text in this locale's encoding (ascii)" in lines[0]
    assert list(tmp_path.iterdir()) == []
    # a UTF-8 file system with an ASCII standard output: written, the name shown escaped
    env = {**os.environ, "PYTHONIOENCODING": "ascii", "PYTHONUTF8": "1"}
    out = subprocess.run(argv, cwd=tmp_path, env=env, capture_output=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert b"Traceback" not in out.stderr and b"output:" in out.stdout
    assert b"\\xe9.nc" in out.stdout
    assert [p.name for p in tmp_path.iterdir()] == ["é.nc"]


# ------------------------------------------------------------ corrupt results made again


def test_a_corrupt_chunk_part_set_aside_is_asked_for_again():
    # an intermediate file set aside would stay missing while the gathered result is up
    # to date; the Snakefile asks for it in `all` when a rule of this configuration
    # still makes it (and not a part beyond n_chunks, left by an earlier configuration)
    from pencore.workflowconfig.parts import remade_target

    class Rule:
        def __init__(self, name: str, pattern: str) -> None:
            self.name, self.pattern = name, pattern

        def is_producer(self, path: str) -> bool:
            import re

            return re.fullmatch(self.pattern, path) is not None

    rules = [Rule("all", ".*"), Rule("ensemble_chunk", r"results/ensemble/\w+/parts/\d+\.nc")]
    ensembles = {"p2_soil_oblique": {"n_chunks": 4}}
    part = "results/ensemble/p2_soil_oblique/parts/1.nc"
    assert remade_target(part, rules, ensembles) == part
    assert remade_target("results/ensemble/p2_soil_oblique/parts/9.nc", rules, ensembles) is None
    assert remade_target("results/ensemble/gone/parts/0.nc", rules, ensembles) is None
    assert remade_target("results/other/x.nc", rules, ensembles) is None


# ------------------------------------------------------------ silent wrong answers


def _foreign() -> xr.Dataset:
    """A netCDF-like Dataset not made by pencore.simulate (no run variables or attrs)."""
    return xr.Dataset({"depth": ("row", [1.0, 2.0])}, attrs={"title": "someone's table"})


#: Calls that used to return a wrong answer without a word; each is now one InputError
#: line holding the words given.
SILENT_WRONG = {
    # a prepared problem must be the one the call names
    "prepared-other-projectile": (
        lambda: pencore.simulate("p2", "soil", 300.0, prepared=pencore.prepare("p1", "soil")),
        "prepared= holds projectile 'p1', but the call names projectile 'p2'",
    ),
    "prepared-other-target": (
        lambda: pencore.simulate("p1", "soil", 300.0, prepared=pencore.prepare("p1", "concrete")),
        "prepared= holds target 'concrete', but the call names target 'soil'",
    ),
    "prepared-other-numerics": (
        lambda: pencore.simulate(
            "p1", "soil", 300.0, prepared=pencore.prepare("p1", "soil"), rtol=1e-3
        ),  # fmt: skip
        "carries its own numerics",
    ),
    # a start inside the target
    "start-inside-target": (
        lambda: pencore.simulate("p2", "soil", 300.0, start=(0.0, -5.0, 0.0)),
        "start y must be >= 0 m",
    ),
    "start-as-set": (
        lambda: pencore.simulate("p2", "soil", 300.0, start={0.0, 1.0, 2.0}),
        "in order (a list, tuple or array), got {",
    ),
    # every function that takes a run's Dataset: a wrong type or a foreign Dataset
    "nose-direction-int": (lambda: pencore.nose_direction(42), "nose_direction needs"),
    "residual-velocity-foreign": (
        lambda: pencore.residual_velocity(_foreign()),
        "residual_velocity needs a Dataset made by pencore.simulate; this one lacks",
    ),
    "perforates-foreign": (lambda: pencore.perforates(_foreign()), "perforates needs"),
    "perforates-text": (lambda: pencore.perforates("run.nc"), "got str 'run.nc'"),
    "final-deviation-foreign": (
        lambda: pencore.final_deviation(_foreign()),
        "final_deviation needs a Dataset made by pencore.simulate; this one lacks the "
        "variable(s) vel_x",
    ),
    "reversed-in-target-foreign": (
        lambda: pencore.reversed_in_target(_foreign()),
        "lacks the attribute(s) reversed",
    ),
    "inflection-points-list": (
        lambda: pencore.inflection_points_ds([1, 2]),
        "inflection_points_ds needs a Dataset",
    ),
    # Recht-Ipson helpers
    "recht-ipson-negative-a": (lambda: pencore.recht_ipson(500.0, 300.0, a=-1), "a must be"),
    "recht-ipson-p-zero": (lambda: pencore.recht_ipson(500.0, 300.0, p=0.0), "p must be"),
    "recht-ipson-text": (lambda: pencore.recht_ipson("500", 300.0), "must be numbers"),
    "recht-ipson-nan": (
        lambda: pencore.recht_ipson([500.0, float("nan")], 300.0),
        "finite speeds >= 0 m/s, got nan (entry 1)",
    ),
    "fit-recht-ipson-unequal": (
        lambda: pencore.fit_recht_ipson([400.0, 500.0, 600.0], [100.0, 200.0]),
        "one residual speed per impact speed",
    ),
    "fit-recht-ipson-residual-above-impact": (
        lambda: pencore.fit_recht_ipson([400.0, 500.0, 600.0], [100.0, 600.0, 300.0]),
        "residual speed 600 m/s above its impact speed 500 m/s (entry 1)",
    ),
    # find_threshold's verdicts must be booleans, its verdict callable
    **{
        f"verdict-{name}": (
            lambda answer=answer: pencore.search.threshold.find_threshold(
                lambda v: answer, 0.0, 1.0, 0.1
            ),
            "must return True or False",
        )
        for name, answer in [
            ("no", "no"),
            ("none", None),
            ("nan", float("nan")),
            ("array", np.array([True, False])),
            ("one", 1),
        ]  # fmt: skip
    },
    "verdict-not-callable": (
        lambda: pencore.search.threshold.find_threshold(3, 0.0, 1.0, 0.1),
        "verdict must be a function",
    ),
    "threshold-bound-text": (
        lambda: pencore.search.threshold.find_threshold(lambda v: v > 0.5, "a", 1.0, 0.1),
        "search lower bound lo must be a finite number, got 'a'",
    ),
    "deviation-of-text": (
        lambda: pencore.deviation_from_normal("a", 0.0),
        "needs velocity components as numbers",
    ),
    "projectile-without-nose": (
        lambda: pencore.Projectile("x", 0.1, None),
        "nose must be an OgiveNose, ConeNose or FlatNose, got NoneType None",
    ),
}


@pytest.mark.parametrize("case", list(SILENT_WRONG))
def test_silent_wrong_answer_refused(case):
    call, words = SILENT_WRONG[case]
    assert words in _api(call)


def test_deviation_of_a_zero_velocity_has_no_direction():
    assert np.isnan(pencore.deviation_from_normal(0.0, 0.0))
    out = pencore.deviation_from_normal([0.0, 1.0], [0.0, -1.0])
    assert np.isnan(out[0]) and out[1] == pytest.approx(45.0)


def test_prepared_problem_named_as_it_was_prepared_runs():
    pr = pencore.prepare("p1", "concrete")
    a = pencore.simulate("p1", "concrete", 300.0, prepared=pr)
    b = pencore.simulate(pr.projectile, pr.target, 300.0, prepared=pr)
    c = pencore.simulate("p1", "concrete", 300.0)
    assert a.penetration_depth.item() == b.penetration_depth.item() == c.penetration_depth.item()


REPEATED_OPTIONS = [
    [*SIM, "--velocity", "300", "--velocity", "500"],
    [*SIM, "--velocity", "300", "--out", "a.nc", "--out", "b.nc"],
    [
        "simulate",
        "--projectile",
        "p1",
        "--projectile",
        "p2",
        "--target",
        "soil",
        "--velocity",
        "300",
    ],  # fmt: skip
]


REPEATED_OPTIONS.append([*SIM, "--velocity", "300", "--numerics", "rtol=1e-6",
                         "--numerics", "rtol=1e-7"])  # fmt: skip
# options of a mutually exclusive group: the same refusal as any other option
DEPTH_CURVE = ["depth-curve", "--projectile", "p2", "--target", "soil"]
REPEATED_OPTIONS.append([*DEPTH_CURVE, "--range", "100", "200", "2", "--range", "100", "300", "3"])
REPEATED_OPTIONS.append([*DEPTH_CURVE, "--velocities", "200", "--velocities", "300"])


@pytest.mark.parametrize(
    "argv",
    REPEATED_OPTIONS,
    ids=["velocity", "out", "projectile", "numerics-key", "group-range", "group-velocities"],
)
def test_cli_repeated_option_refused(argv, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "given twice" in err[0], err
    assert list(tmp_path.iterdir()) == []


def test_cli_empty_write_path_refused(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    status = main(["fit-table3", "--write", ""])
    err = capsys.readouterr().err.strip().splitlines()
    assert status == 2 and len(err) == 1 and "a file path is needed, got ''" in err[0]
    assert list(tmp_path.iterdir()) == []


def test_shot_repeated_with_a_leading_space_refused(tmp_path):
    from pencore.measured.shots import SHOT_COLUMNS, read_shot_table

    row = "al_ogive_var4340,600.0,0.12,0.5,0.0,true,1,725,paper"
    path = tmp_path / "shots.csv"
    path.write_text(f"{','.join(SHOT_COLUMNS)}\n12,{row}\n 12,{row}\n")
    assert "duplicate shots ['12']" in _api(lambda: read_shot_table(path))


# ------------------------------------------------------------ valid inputs accepted


def test_path_objects_name_projectile_and_target_files(tmp_path):
    (tmp_path / "p.yaml").write_text(PROJECTILE_YAML)
    (tmp_path / "t.yaml").write_text(TARGET_YAML)
    assert get_projectile(tmp_path / "p.yaml").name == "probe"
    assert get_target(tmp_path / "t.yaml").name == "slab"
    ds = pencore.simulate(tmp_path / "p.yaml", tmp_path / "t.yaml", 300.0)
    assert ds.attrs["outcome"] in ("stopped", "perforated")


def test_numpy_bool_is_a_flag():
    a = pencore.simulate("p2", "soil", 300.0, stop_at_reversal=np.bool_(True))
    b = pencore.simulate("p2", "soil", 300.0, stop_at_reversal=True)
    assert a.penetration_depth.item() == b.penetration_depth.item()
    assert "True or False" in _api(lambda: pencore.simulate("p2", "soil", 300.0,
                                                            stop_at_reversal=1))  # fmt: skip


# ------------------------------------------------------------ raw tracebacks closed


def test_write_netcdf_under_a_file_is_one_write_error(tmp_path):
    (tmp_path / "f.txt").write_text("a file\n")
    with pytest.raises(pencore.WriteError) as info:
        pencore.write_netcdf(xr.Dataset(), tmp_path / "f.txt" / "sub" / "x.nc",
                             config_slice={}, study="probe")  # fmt: skip
    assert "its folder" in str(info.value) and "cannot be made" in str(info.value)
    assert "\n" not in str(info.value)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["f.txt"]


def test_write_netcdf_under_a_read_only_folder_is_one_write_error(tmp_path, monkeypatch):
    """A folder the user may not write in (the permission error is raised by a stand-in for
    ``Path.mkdir``: root, who runs CI, writes into read-only folders)."""

    def refuse(self, *args, **kwargs):
        raise PermissionError(13, "Permission denied", str(self))

    monkeypatch.setattr(Path, "mkdir", refuse)
    with pytest.raises(pencore.WriteError, match="cannot be made") as info:
        pencore.write_netcdf(xr.Dataset(), tmp_path / "ro" / "x.nc", config_slice={}, study="p")
    assert "(permission denied); nothing was written" in str(info.value)
    assert "\n" not in str(info.value)
    monkeypatch.undo()
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("bad", [123, None, 4.5])
def test_read_netcdf_of_a_non_path(bad):
    assert "read_netcdf needs a file path" in _api(lambda: pencore.read_netcdf(bad))


#: Data files the CSV readers (shot tables, paper claims) get: each one InputError line.
BAD_CSV = {
    "empty": (b"", "holds no table (it is empty or only comments)"),
    "comments-only": (b"# a header\n# and nothing else\n", "holds no table"),
    "latin-1": ("shot,projectile\nété,p1\n".encode("latin-1"), "is not a UTF-8 text (CSV) file"),
    "binary": (b"\x7fELF\x02\x01\x01\x00\x00\x00" * 8, "binary file"),
}


@pytest.mark.parametrize("kind", list(BAD_CSV))
@pytest.mark.parametrize("reader", ["shot-table", "claims"])
def test_csv_readers_on_bad_files(kind, reader, tmp_path):
    from pencore.measured.shots import read_shot_table
    from pencore.paper.claims import load_claims

    data, words = BAD_CSV[kind]
    path = tmp_path / "data.csv"
    path.write_bytes(data)
    read = read_shot_table if reader == "shot-table" else load_claims
    text = _api(lambda: read(path))
    assert words in text, text


def test_one_text_cell_in_a_shot_table_names_its_row_and_value(tmp_path):
    from pencore.measured.shots import SHOT_COLUMNS, read_shot_table

    rows = [",".join(SHOT_COLUMNS)] + [
        f"s{i},al_ogive_var4340,{v},0.12,0.5,0.0,true,1,725,paper"
        for i, v in enumerate(["600.0", "700.0", "fast", "800"])
    ]
    path = tmp_path / "shots.csv"
    path.write_text("\n".join(rows) + "\n")
    text = _api(lambda: read_shot_table(path))
    assert "row 3 (shot 's2')" in text and "got 'fast'" in text, text
    path.write_text("\n".join(rows).replace("fast", "650") + "\n")
    assert read_shot_table(path)["velocity_m_s"].tolist() == [600.0, 700.0, 650.0, 800.0]


@pytest.mark.parametrize(
    ("call", "words"),
    [
        (lambda: pencore.simulate("p2", "soil", 300.0, obliquty=30.0),
         "simulate: unknown keyword 'obliquty' (did you mean 'obliquity'?)"),
        (lambda: pencore.simulate("p2", "soil", 300.0, Obliquity=30.0),
         "unknown keyword 'Obliquity' (did you mean 'obliquity'?)"),
        (lambda: pencore.simulate("p2", "soil", 300.0, rtoll=1e-6),
         "unknown keyword 'rtoll' (did you mean 'rtol'?)"),
        (lambda: pencore.prepare("p2", "soil", shnk="dafl"),
         "prepare: unknown keyword 'shnk' (did you mean 'shank'?)"),
        # a search's own keyword mistyped while a required one is missing: not "missing
        # 1 required positional argument" (a TypeError) but the typo, named
        (lambda: pencore.vcr("p2", "soil", obliquty=45.0),
         "vcr: unknown keyword 'obliquty' (did you mean 'obliquity'?)"),
        (lambda: pencore.vci("p2", "soil", yaww=0.1),
         "vci: unknown keyword 'yaww' (did you mean 'yaw'?)"),
        (lambda: pencore.omega_c("p2", "soil", velocty=1000.0),
         "omega_c: unknown keyword 'velocty' (did you mean 'velocity'?)"),
        (lambda: pencore.ballistic_limit("p2", "soil", obliquty=30.0),
         "unknown argument(s): obliquty (did you mean 'obliquity'?)"),
        (lambda: pencore.vci("p2", "soil"), "vci: missing a required argument: 'yaw'"),
    ],
    ids=["obliquty", "Obliquity", "rtoll", "prepare-shnk", "vcr-obliquty", "vci-yaww",
         "omega_c-velocty", "ballistic_limit-obliquty", "vci-missing"],
)  # fmt: skip
def test_keyword_typo_names_the_keyword_meant(call, words):
    assert words in _api(call)


@pytest.mark.parametrize("content", ["", "# comments only\n"], ids=["empty", "comments"])
def test_workflow_shot_table_read_at_parse_is_one_line(content, tmp_path):
    shots = tmp_path / "shots.csv"
    shots.write_text(content)
    extra = tmp_path / "extra.yaml"
    extra.write_text(f"validation:\n  fig5:\n    shots: [{shots}]\n")
    out = subprocess.run(
        [sys.executable, "-m", "snakemake", "-n", "--configfile", str(extra)],
        cwd=REPO, capture_output=True, text=True, timeout=300,
    )  # fmt: skip
    assert out.returncode != 0
    assert "holds no table (it is empty or only comments)" in out.stderr + out.stdout
    assert "pandas" not in out.stderr and "EmptyDataError" not in out.stderr


# ------------------------------------------------------------ unbounded lists


def test_workflow_list_longer_than_a_grid_refused_before_the_plan():
    from pencore.errors import ConfigError
    from pencore.workflowconfig.config_check import MAX_GRID, check_config

    t0 = time.monotonic()
    cfg = _edit(_config(), "perforation.ballistic_limit.thickness_m", [0.5] * 10**5)
    with pytest.raises(ConfigError) as info:
        check_config(cfg, REPO)
    assert time.monotonic() - t0 < 1.0
    assert f"the list has 100000 entries; at most {MAX_GRID}" in str(info.value)
