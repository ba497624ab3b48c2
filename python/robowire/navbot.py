"""robowire.navbot: decode, encode and the helpers of the C++ library's navbot headers.

The API is described in docs/python.md; the generated stub navbot.pyi lists it.
"""
from __future__ import annotations

TYPE_CHECKING = False  # (typing is imported by type checkers only: it costs milliseconds at import)

from . import _errors, _robowire

if TYPE_CHECKING:
    from typing import Any

_ext = _robowire.navbot
globals().update(_errors.api_of(_ext))  # keywords checked: a surrogate keyword is a TypeError


def schema() -> dict[str, Any]:
    """This protocol's entry of robowire.schema()."""
    import json

    entry: dict[str, Any] = json.loads(_robowire.schema_json("navbot"))["protocols"][0]
    return entry


__all__ = [_n for _n in dir(_ext) if not _n.startswith("_")] + ["schema"]
