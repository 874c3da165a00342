"""``pencore.errors``: a Ctrl-C in disguise is told apart from a broken import."""

from __future__ import annotations

from pencore.errors import interrupted_import


def _raised_from(cause: BaseException) -> ImportError:
    try:
        try:
            raise cause
        except BaseException as exc:
            raise ImportError("initialization failed") from exc
    except ImportError as exc:
        return exc


def test_an_import_error_raised_from_ctrl_c_is_ctrl_c():
    assert interrupted_import(_raised_from(KeyboardInterrupt()))


def test_an_import_error_raised_while_handling_ctrl_c_is_ctrl_c():
    try:
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt:
            raise ImportError("initialization failed")  # noqa: B904 (the implicit context)
    except ImportError as exc:
        assert interrupted_import(exc)


def test_other_import_errors_and_other_exceptions_are_not():
    assert not interrupted_import(ImportError("No module named 'scipy'"))
    assert not interrupted_import(_raised_from(OSError("gone")))
    assert not interrupted_import(KeyboardInterrupt())  # a plain one is not disguised
    assert not interrupted_import(ValueError("x"))
