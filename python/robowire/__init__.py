"""robowire: BuWizz3, NAVBOT-ES02 and OSP codecs, built from the C++ library's tables.

    from robowire import buwizz3, navbot, osp
    buwizz3.decode(data)            # -> dict, as `robowire decode --json` prints it
    buwizz3.encode("set_motor_data", power=[100, -100, 0, 0, 0, 0])  # -> bytes
    read_log("session.txt")         # -> the records of `robowire decode --file session.txt --json`
"""
from __future__ import annotations

TYPE_CHECKING = False  # (typing is imported by type checkers only: it costs milliseconds at import)

from ._errors import DecodeError, EncodeError

try:
    from . import _robowire
except ImportError as _e:  # the sources in python/robowire, not the installed package
    raise ImportError(f"robowire's compiled part is missing in {__path__[0]}: this is the source tree, not the "
                      "installed package; run from another directory, or install it (docs/python.md)") from _e
from . import buwizz3, navbot, osp  # noqa: E402 (after _robowire)
from .logs import LogRecords, csv_columns, plot, read_log, to_csv  # noqa: E402

if TYPE_CHECKING:
    from typing import Any, Optional

__all__ = ["DecodeError", "EncodeError", "buwizz3", "navbot", "osp", "protocols", "schema", "error_codes", "__version__",
           "read_log", "to_csv", "csv_columns", "plot", "LogRecords"]
__version__ = "0.1.0"

#: The protocols' names, in the order of `robowire list` (their descriptors).
protocols: "list[str]" = list(_robowire.protocols)

#: Every error code (the values of DecodeError.code / EncodeError.code) and its text.
error_codes: "dict[str, str]" = {k: v for k, v in _robowire.error_codes.items() if k != "ok"}


def schema(protocol: Optional[str] = None) -> dict[str, Any]:
    """The tables: every message, field, wire type, range, unit, enum and flag bit,
    in the format of `robowire list --json` (docs/python.md)."""
    import json

    if protocol is not None and protocol not in protocols:
        raise KeyError(f"unknown protocol {protocol!r} ({', '.join(protocols)})")
    result: dict[str, Any] = json.loads(_robowire.schema_json(protocol or ""))
    return result
