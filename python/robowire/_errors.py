"""robowire's exceptions: both are ValueError, so `except ValueError` catches them."""
from __future__ import annotations

TYPE_CHECKING = False  # (typing is imported by type checkers only: it costs milliseconds at import)

if TYPE_CHECKING:
    from typing import Any, Optional, Sequence


class _CodecError(ValueError):
    """An error the library reports: its text, code, byte offset and field."""

    code: Optional[str]
    offset: int
    field: Optional[str]
    message: Optional[str]
    notes: list[str]

    def __init__(self, text: str, code: Optional[str] = None, offset: int = 0, field: Optional[str] = None,
                 message: Optional[str] = None, notes: Sequence[str] = ()) -> None:
        super().__init__(text)
        self.code = code
        self.offset = offset
        self.field = field
        self.message = message
        self.notes = list(notes)


class DecodeError(_CodecError):
    """Bytes that are not a valid message: .code (e.g. 'value_out_of_range'),
    .offset (the byte), .field (the field there, or None), .message (the
    message it was read as, or None), .notes (hints), str(): the whole line."""


class EncodeError(_CodecError):
    """A value that cannot be encoded: .code, .offset (the byte it would take),
    .field, .message; str(): the whole line."""


def _keyword_error(name: str, kwargs: dict[str, object], passes_fields: bool) -> None:
    """TypeError for a keyword that is not UTF-8 text (a lone surrogate), which the
    extension's argument matching cannot name; encode(name, **fields) passes it on
    as an unknown field (KeyError)."""
    for k in kwargs:
        if not k.isascii():
            try:
                k.encode()
            except UnicodeEncodeError:
                if passes_fields:
                    return
                raise TypeError(f"{name}() got an unexpected keyword argument {k!r}") from None


def keywords_checked(fn: Any) -> Any:
    """fn (a function or method of the extension), its keywords checked first."""
    import functools

    name = getattr(fn, "__name__", "function")

    def call(*args: Any, **kwargs: Any) -> Any:
        if kwargs and not all(map(str.isascii, kwargs)):  # the common case costs one C-level pass
            _keyword_error(name, kwargs, name == "encode" and len(args) == 1 and isinstance(args[0], str))
        return fn(*args, **kwargs)

    return functools.update_wrapper(call, fn)


def api_of(ext: Any) -> dict[str, Any]:
    """The public names of an extension submodule: functions and class methods
    wrapped by keywords_checked, the rest as they are."""
    out: dict[str, Any] = {}
    for n in dir(ext):
        if n.startswith("_"):
            continue
        obj = getattr(ext, n)
        if isinstance(obj, type) and not hasattr(obj, "__members__"):  # a class, not an enumeration
            ns = {m: keywords_checked(getattr(obj, m)) for m in dir(obj)
                  if not m.startswith("_") and callable(getattr(obj, m)) and not isinstance(getattr(obj, m), property)}
            ns["__init__"] = keywords_checked(obj.__init__)
            ns["__doc__"] = obj.__doc__
            ns["__module__"] = obj.__module__
            ns["__qualname__"] = obj.__qualname__
            obj = type(n, (obj,), ns)
        elif callable(obj) and not isinstance(obj, type) and n not in ("decode", "encode"):  # these two match their own
            obj = keywords_checked(obj)
        out[n] = obj
    return out
