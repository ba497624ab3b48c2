"""robowire's exceptions: both are ValueError, so `except ValueError` catches them."""
from __future__ import annotations

TYPE_CHECKING = False  # (typing is imported by type checkers only: it costs milliseconds at import)

if TYPE_CHECKING:
    from typing import Optional, Sequence


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
