"""The input gate for text and files: short quotes of bad values, and bounded YAML.

Every door that reads user text (the API's YAML paths, the command line's
``--projectile FILE`` / ``--target FILE`` / ``--numerics KEY=VALUE``, the Table-3 geometry
file) reads it here, and every message that quotes a user value quotes it through
:func:`brief`, so a hostile value never floods a message. Numbers are then checked
against their ranges by :mod:`pencore.inputs.limits`.

A YAML file is refused, with one :class:`~pencore.errors.InputError` naming the file,
before it can hang or exhaust the process:

* unless it is a regular file (a FIFO, a character device such as ``/dev/zero``, a
  directory or a socket is refused before a byte is read; the file is opened
  non-blocking, so a FIFO cannot block the open either);
* when it is larger than :data:`MAX_YAML_BYTES`;
* when it nests deeper than :data:`MAX_YAML_DEPTH`;
* when it holds more than :data:`MAX_YAML_NODES` values, or its aliases would expand it
  beyond that (an "alias bomb": a few hundred bytes that expand to billions of values);
  the count is checked as the document is composed, so a file is refused after at most
  that many values, whatever its size;
* when a mapping repeats a key (YAML would silently keep the last value); a merge key
  (``<<: *anchor``) is YAML, and the mapping's own keys override the merged ones;
* when it is not YAML: a control character (BEL, ESC, NUL), bad syntax, a tag pencore
  does not construct; the message gives the line and column.

The text is scanned by libyaml's C parser when PyYAML has it
(:data:`~pencore.inputs.gate.FAST_YAML`), by
PyYAML's Python one otherwise; ``benchmarks/bench_parse.py`` measures the worst inputs
within these bounds.

Text is a number only in plain ASCII decimal notation (:data:`DECIMAL`, read by
:func:`decimal`): an optional sign, digits without leading zeros, an optional fraction
and an optional exponent (``5``, ``-0.25``, ``.5``, ``1e6``, ``2.5E-3``), or the words
``inf``, ``infinity`` and ``nan`` in any letter case. Everything else Python's
:class:`float` reads is not a number: digit separators (``1_0``), digits of other
scripts (``١``), surrounding blanks, leading zeros (``0750``). The YAML reader holds its
own numbers to the same notation: a scalar that YAML 1.1 would read as a number in
another form (``1_0``, ``0750``, which it reads as the octal 488, ``0x10``, ``0b11``, the
base-60 ``1:30``) stays text, which no number accepts. YAML's own ``.inf``, ``-.inf``
and ``.nan`` are numbers.
"""

from __future__ import annotations

import os
import re
import stat
from typing import Any

import yaml

from pencore.errors import InputError
from pencore.io.outputs import file_kind, note_input

__all__ = [
    "brief",
    "brief_path",
    "DECIMAL",
    "DECIMAL_WORDS",
    "decimal",
    "read_yaml",
    "read_text",
    "load_yaml_text",
    "MAX_YAML_BYTES",
    "MAX_YAML_DEPTH",
    "MAX_YAML_NODES",
    "FAST_YAML",
    "MAX_QUOTE",
]

#: Largest YAML input (bytes): 16 MiB, ~35 times a 10 000-row friction table.
MAX_YAML_BYTES = 16 * 1024 * 1024
#: Deepest nesting of YAML collections (a target file needs 5 levels).
MAX_YAML_DEPTH = 64
#: Most values (nodes) a YAML document may hold, its aliases expanded: 6 times the
#: ~30 000 of a 10 000-row friction table (the longest the limits table admits), and
#: few enough that the worst document is parsed in seconds (``benchmarks/bench_parse.py``).
MAX_YAML_NODES = 200_000
#: Longest quote of a user value in a message (characters of its ``repr``).
MAX_QUOTE = 60


#: The text :func:`decimal` reads as a number: plain ASCII decimal notation without
#: leading zeros, or the words inf, infinity and nan (any letter case), signed or not.
DECIMAL = re.compile(
    r"[+-]?(?:(?:0|[1-9][0-9]*)(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?"
    r"|[+-]?(?:inf|infinity|nan)",
    re.IGNORECASE,
)

#: How messages describe the text :data:`DECIMAL` admits.
DECIMAL_WORDS = "written in plain decimal (such as 5, -0.25 or 1.5e-3)"

#: YAML's own words for the special floats (``.inf``, ``-.Inf``, ``.NAN``, ...).
_YAML_SPECIAL = re.compile(r"[+-]?\.(?:inf|nan)", re.IGNORECASE)


def decimal(text: str) -> float | None:
    """``text`` as a float when it is plain ASCII decimal (:data:`DECIMAL`), else None."""
    if not DECIMAL.fullmatch(text):
        return None
    return float(text)


def brief(value: Any, limit: int = MAX_QUOTE) -> str:
    """``repr(value)`` cut to ``limit`` characters, saying how long it was.

    An integer too long for :func:`repr` (Python refuses over 4300 digits) is described
    by its number of digits; a value whose ``repr`` fails is named by its type.
    """
    if isinstance(value, int) and not isinstance(value, bool):
        digits = _int_digits(value)
        if digits > limit:
            return f"an integer of {digits} digits"
    try:
        text = repr(value)
    except Exception:  # noqa: BLE001 - any object a user passes
        return f"a {type(value).__name__}"
    if len(text) <= limit:
        return text
    return f"{text[: limit - 3]}... ({len(text)} characters)"


def brief_path(path: Any, limit: int = 200) -> str:
    """A path quoted for a message: whole up to ``limit`` characters, else its end
    (where the file name is)."""
    text = str(path)
    if len(text) <= limit:
        return repr(text)
    return repr("..." + text[-(limit - 3) :])


def _int_digits(value: int) -> int:
    """Decimal digits of ``value`` (estimated from its bits when too long to print)."""
    n = abs(value)
    if n.bit_length() < 13_000:  # str() refuses over 4300 digits
        return len(str(n))
    return int(n.bit_length() * 0.30103) + 1


class _PyEventSource(yaml.reader.Reader, yaml.scanner.Scanner, yaml.parser.Parser):
    """PyYAML's pure-Python reader, scanner and parser: the event source whose errors
    the gate reports (its words and bounds do not change with the libyaml build)."""

    def __init__(self, stream: str) -> None:
        yaml.reader.Reader.__init__(self, stream)
        yaml.scanner.Scanner.__init__(self)
        yaml.parser.Parser.__init__(self)


#: libyaml's C parser when PyYAML was built with it (``yaml.__with_libyaml__``), else None.
try:
    from yaml.cyaml import CParser as _CParser
except ImportError:  # pragma: no cover - PyYAML built without libyaml
    _CParser = None
#: True when PyYAML has libyaml's C parser, which then scans the text. Composition stays
#: in Python either way (the bounded loader), so the gate's depth and count bounds
#: hold for both; libyaml only makes the scanning fast. A document libyaml refuses is read
#: again with PyYAML's Python parser, so that what the user is told (and which bound
#: refuses it) is the gate's, whatever libyaml version PyYAML bundles: libyaml 0.2.5 as
#: bundled from PyYAML 6.0.3 on stops deep flow nesting with its own words before the
#: gate's bound can be checked (its scanner reads ahead over every ``[``).
FAST_YAML: bool = bool(getattr(yaml, "__with_libyaml__", False)) and _CParser is not None


#: Keys that are not keys: YAML's merge key ``<<`` and its value key ``=``.
_MERGE_TAGS = ("tag:yaml.org,2002:merge", "tag:yaml.org,2002:value")


class _BoundedLoader(
    yaml.composer.Composer, yaml.constructor.SafeConstructor, yaml.resolver.Resolver
):
    """yaml's safe loader with bounded depth and node count, refusing duplicate keys.

    The composer is PyYAML's Python one on top of an event source (:class:`_PyLoader`,
    :class:`_FastLoader`); libyaml's compiled composer recurses once per level on the C
    stack and crashes the process on deep nesting, before any bound can be checked.
    """

    def __init__(self, stream: str) -> None:
        yaml.composer.Composer.__init__(self)
        yaml.constructor.SafeConstructor.__init__(self)
        yaml.resolver.Resolver.__init__(self)
        self._depth = 0
        self._nodes = 0
        self._checked: set[int] = set()

    def compose_node(self, parent: Any, index: Any) -> Any:
        self._nodes += 1
        if self._nodes > MAX_YAML_NODES:
            raise _Refused(f"holds more than {MAX_YAML_NODES} values")
        self._depth += 1
        if self._depth > MAX_YAML_DEPTH:
            raise _Refused(f"nests deeper than {MAX_YAML_DEPTH} levels")
        try:
            return super().compose_node(parent, index)
        finally:
            self._depth -= 1

    def flatten_mapping(self, node: Any) -> None:
        """Refuse a key the mapping itself repeats, then merge its ``<<`` keys (a key
        written in the mapping overrides a merged one: that is what a merge key is for)."""
        if id(node) not in self._checked:
            self._checked.add(id(node))
            seen: set[Any] = set()
            for key_node, _ in node.value:
                if key_node.tag in _MERGE_TAGS:
                    continue
                key = self.construct_object(key_node, deep=True)
                try:
                    dup = key in seen
                    seen.add(key)
                except TypeError:  # an unhashable key: yaml itself refuses it
                    continue
                if dup:
                    line = key_node.start_mark.line + 1
                    raise _Refused(f"repeats the key {brief(key)} (line {line})")
        super().flatten_mapping(node)


def _plain_number(construct: Any, *, special: bool = False) -> Any:
    """A YAML constructor that builds the number ``construct`` builds when the scalar is
    plain decimal (:data:`DECIMAL`; with ``special``, also YAML's ``.inf`` and ``.nan``)
    and keeps any other form as its text."""

    def build(loader: yaml.SafeLoader, node: Any) -> Any:
        text = loader.construct_scalar(node)
        if DECIMAL.fullmatch(text) or (special and _YAML_SPECIAL.fullmatch(text)):
            return construct(loader, node)
        return text

    return build


_BoundedLoader.add_constructor(
    "tag:yaml.org,2002:int", _plain_number(yaml.SafeLoader.construct_yaml_int)
)
_BoundedLoader.add_constructor(
    "tag:yaml.org,2002:float", _plain_number(yaml.SafeLoader.construct_yaml_float, special=True)
)


class _PyLoader(_BoundedLoader, _PyEventSource):
    """The bounded loader on PyYAML's pure-Python scanner and parser."""

    def __init__(self, stream: str) -> None:
        _PyEventSource.__init__(self, stream)
        _BoundedLoader.__init__(self, stream)


if FAST_YAML:

    class _FastLoader(_BoundedLoader, _CParser):  # type: ignore[misc,valid-type]
        """The bounded loader on libyaml's scanner and parser."""

        def __init__(self, stream: str) -> None:
            _CParser.__init__(self, stream)
            _BoundedLoader.__init__(self, stream)


class _Refused(Exception):
    """A YAML document the gate refuses (the message says why)."""


def _expanded_nodes(node: Any) -> int:
    """Nodes of ``node`` with every alias expanded, counted without expanding them
    (memoised on the shared nodes, capped at ``MAX_YAML_NODES + 1``); a node that
    contains itself counts as too many."""
    cap = MAX_YAML_NODES + 1
    memo: dict[int, int] = {}
    open_: set[int] = set()
    stack: list[tuple[Any, bool]] = [(node, False)]
    while stack:  # post-order without recursion
        n, children_done = stack.pop()
        if id(n) in memo:
            continue
        children = _children(n)
        if children_done:
            open_.discard(id(n))
            memo[id(n)] = min(1 + sum(memo[id(c)] for c in children), cap)
            continue
        if any(id(c) in open_ for c in children) or n in children:
            return cap  # a recursive structure
        open_.add(id(n))
        stack.append((n, True))
        stack.extend((c, False) for c in children if id(c) not in memo)
    return memo[id(node)]


def _children(node: Any) -> list[Any]:
    if isinstance(node, yaml.SequenceNode):
        return list(node.value)
    if isinstance(node, yaml.MappingNode):
        return [n for pair in node.value for n in pair]
    return []


def load_yaml_text(text: str, what: str) -> Any:
    """Parse YAML ``text`` with the gate's bounds; ``what`` names it in messages.

    Every error the parser can raise (a control character, a surrogate, bad syntax, a
    tag without a constructor, a nesting or count bound) becomes one
    :class:`~pencore.errors.InputError` naming ``what`` and, where the parser knows it,
    the line and column.
    """
    if len(text) > MAX_YAML_BYTES:
        raise InputError(f"{what} is longer than {MAX_YAML_BYTES} characters")
    try:
        if FAST_YAML:
            try:
                return _parse(text, _FastLoader)
            except yaml.YAMLError:
                pass  # libyaml refused it: read it again in Python, for the gate's words
        return _parse(text, _PyLoader)
    except _Refused as exc:
        raise InputError(f"{what} {exc}") from None
    except yaml.reader.ReaderError as exc:
        raise InputError(f"{what} is not valid YAML: {_reader_problem(exc, text)}") from None
    except yaml.MarkedYAMLError as exc:
        raise InputError(f"{what} is not valid YAML: {_marked_problem(exc)}") from None
    except yaml.YAMLError as exc:
        first = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        raise InputError(f"{what} is not valid YAML: {brief(first, 200)[1:-1]}") from None
    except UnicodeError as exc:  # a lone surrogate in text given through the API
        where = _line_column(text, getattr(exc, "start", -1))
        raise InputError(
            f"{what} is not valid YAML: a character that is not Unicode text{where}"
        ) from None
    except RecursionError:
        raise InputError(f"{what} nests too deeply") from None


def _parse(text: str, loader_class: type) -> Any:
    """One bounded parse of ``text`` with ``loader_class`` (errors raised as they come)."""
    loader = loader_class(text)
    try:
        node = loader.get_single_node()
        if node is None:
            return None
        if _expanded_nodes(node) > MAX_YAML_NODES:
            raise _Refused(
                f"expands to more than {MAX_YAML_NODES} values through its aliases (an alias bomb?)"
            )
        return loader.construct_document(node)
    finally:
        loader.dispose()


def _line_column(text: str, index: int) -> str:
    """`` at line L, column C`` of character ``index`` of ``text`` (1-based), or ``""``."""
    if index < 0 or index > len(text):
        return ""
    line = text.count("\n", 0, index) + 1
    column = index - (text.rfind("\n", 0, index) + 1) + 1
    return f" at line {line}, column {column}"


def _reader_problem(exc: yaml.reader.ReaderError, text: str) -> str:
    """A reader error (a character YAML does not allow) in one line, located: the
    reader stops at the first such character, so its first occurrence is the one."""
    char = exc.character
    if isinstance(char, int):
        index = text.find(chr(char))
        name = f"U+{char:04X}"
    else:  # a byte that does not decode (a bytes stream)
        index = -1
        name = brief(char)
    return f"the character {name} is not allowed ({exc.reason}){_line_column(text, index)}"


def _marked_problem(exc: yaml.MarkedYAMLError) -> str:
    """A parser error in one line: what went wrong, at which line and column."""
    mark = exc.problem_mark or exc.context_mark
    problem = exc.problem or exc.context or type(exc).__name__
    if exc.context and exc.problem:
        problem = f"{exc.context}: {exc.problem}"
    where = f" at line {mark.line + 1}, column {mark.column + 1}" if mark is not None else ""
    return f"{brief(' '.join(str(problem).split()), 160)[1:-1]}{where}"


def read_yaml(path: str | os.PathLike[str], what: str) -> Any:
    """Read and parse the YAML file ``path`` with the gate's bounds (see the module).

    Parameters
    ----------
    path : path-like
        The file; must be a regular file of at most :data:`MAX_YAML_BYTES` bytes of
        UTF-8 text.
    what : str
        What the file is, for messages (``"projectile"``).

    Raises
    ------
    InputError
        One line naming the file (quoted short) and why it is refused.
    """
    name = f"{what} file {brief_path(path)}"
    text = read_text(path, name, "YAML")
    return load_yaml_text(text, name)


def read_text(path: str | os.PathLike[str], name: str, kind: str) -> str:
    """The UTF-8 text of the regular file ``path`` of at most :data:`MAX_YAML_BYTES`
    bytes (YAML inputs, data tables), else one :class:`~pencore.InputError` line
    starting with ``name`` (``kind`` names the format: ``"YAML"``, ``"CSV"``)."""
    try:
        st = os.stat(path)
    except OSError as exc:
        raise InputError(f"cannot read {name}: {exc.strerror or exc}") from None
    except ValueError:  # an embedded NUL
        raise InputError(f"cannot read {name}: the name holds a NUL character") from None
    if not stat.S_ISREG(st.st_mode):
        raise InputError(f"{name} is not a regular file ({file_kind(st.st_mode)})")
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as exc:
        raise InputError(f"cannot read {name}: {exc.strerror or exc}") from None
    try:
        st = os.fstat(fd)  # the file opened, not one swapped in after the stat
        if not stat.S_ISREG(st.st_mode):
            raise InputError(f"{name} is not a regular file ({file_kind(st.st_mode)})")
        if st.st_size > MAX_YAML_BYTES:
            raise InputError(f"{name} is {st.st_size} bytes; the limit is {MAX_YAML_BYTES} bytes")
        with os.fdopen(fd, "rb", closefd=False) as f:
            data = f.read(MAX_YAML_BYTES + 1)
    except OSError as exc:
        raise InputError(f"cannot read {name}: {exc.strerror or exc}") from None
    finally:
        os.close(fd)
    if len(data) > MAX_YAML_BYTES:
        raise InputError(f"{name} is larger than {MAX_YAML_BYTES} bytes")
    note_input(path)  # no writer of the same call may replace it
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        raise InputError(f"{name} is not a UTF-8 text ({kind}) file") from None
    return text
