"""robowire.logs: logs of sessions (nRF Connect for Android and desktop, hex lines)
read by the command-line tool's own reader, as records, CSV tables and plots.

    for r in robowire.read_log("session.txt"):      # the records of `robowire decode --file --json`
        if r["type"] == "message": print(r["time"], r["message"], r["fields"])
    robowire.to_csv("session.txt", "status.csv", message="status")   # `--format csv --message status`
    robowire.plot("session.txt", ["battery_voltage", "motor_current"], "session.png")

The API is described in docs/python.md.
"""
from __future__ import annotations

TYPE_CHECKING = False  # (typing is imported by type checkers only)

import json
import os

from . import _robowire

if TYPE_CHECKING:
    from typing import IO, Any, Iterable, Iterator, Optional, Union

    Source = Union[str, "os.PathLike[str]", IO[bytes], IO[str]]

__all__ = ["LogRecords", "read_log", "to_csv", "csv_columns", "plot"]


class LogRecords:
    """The records of a log, decoded line by line as they are asked for (an iterator).

    Each record is a dict, the JSON line `robowire decode --file LOG --json` prints:
    type ("message" or "error"), line, time (ISO 8601 with milliseconds; absent
    for lines without a time), direction ("device_to_host", "host_to_device";
    absent when the line has none), uuid or handle, then for a message protocol,
    message and fields (as the protocol's decode() returns them), for an error
    error (and protocol, bytes, hints when known). After the last record,
    counters holds the CLI's summary (lines, frames, decoded, errors, ...) and
    status its exit status (0, or 1 when a line failed, 2 when the protocol
    could not be told).
    """

    def __init__(self, source: Source, protocol: Optional[str] = None, since: Optional[str] = None,
                 until: Optional[str] = None) -> None:
        self._reader = _robowire.LogReader(source, protocol or "", since, until)
        self._pending: list[str] = []
        self.counters: dict[str, Any] = {}
        self.name: str = self._reader.name

    def __iter__(self) -> LogRecords:
        return self

    def __next__(self) -> dict[str, Any]:
        while True:
            if self._pending:
                record: dict[str, Any] = json.loads(self._pending.pop())
                if record.get("type") == "counters":
                    self.counters = {k: v for k, v in record.items() if k != "type"}
                    continue
                return record
            text = self._reader.next()
            if not text:
                raise StopIteration
            self._pending = text.splitlines()[::-1]

    @property
    def status(self) -> Optional[int]:
        """The exit status of `robowire decode --file` (None until the last record was read)."""
        status: Optional[int] = self._reader.status
        return status


def read_log(source: Source, protocol: Optional[str] = None, *, since: Optional[str] = None,
             until: Optional[str] = None) -> LogRecords:
    """The records of a log (a path, or a file object open in binary or text mode),
    decoded line by line as they are iterated: the same records, from the same
    C++ code, as `robowire decode [protocol] --file LOG --json [--since T] [--until T]`.
    protocol: buwizz3, navbot or osp (None: the characteristic UUID of each line picks it).
    since, until: "YYYY-MM-DD[THH:MM[:SS[.mmm]]]" or "HH:MM[:SS[.mmm]]" (docs/cli.md).
    Raises OSError when the path cannot be read, ValueError for a bad argument."""
    return LogRecords(source, protocol, since, until)


# ---------------------------------------------------------------- CSV
def _csv_cell(s: str) -> str:
    if any(c in s for c in ',"\r\n'):
        return '"' + s.replace('"', '""') + '"'
    return s


def _shortest(v: float) -> str:
    """A double as C++'s std::to_chars(double) writes it: the shortest digits
    that read back as v, fixed or scientific, whichever is shorter (fixed on a tie)."""
    from decimal import Decimal

    if v == 0:
        return "-0" if str(v).startswith("-") else "0"
    sign, digit_tuple, exp = Decimal(repr(v)).normalize().as_tuple()
    assert isinstance(exp, int)
    ds = "".join(map(str, digit_tuple))
    first = exp + len(ds) - 1  # the exponent of the first digit
    if exp >= 0:
        fixed = ds + "0" * exp
    elif first >= 0:
        fixed = ds[:first + 1] + "." + ds[first + 1:]
    else:
        fixed = "0." + "0" * (-first - 1) + ds
    sci = ds[0] + ("." + ds[1:] if len(ds) > 1 else "") + "e" + ("-" if first < 0 else "+") + f"{abs(first):02d}"
    return ("-" if sign else "") + (fixed if len(fixed) <= len(sci) else sci)


def _physical_key(name: str) -> str:
    return name[:-4] if name.endswith("_raw") and len(name) > 4 else name + "_physical"


def _is_hex_array(f: dict[str, Any]) -> bool:
    return bool(f["array"] and f["type"] == "u8" and f["value"] == "int" and f["count"] >= 8 and not f["unit"])


def _columns(fields: list[dict[str, Any]], prefix: str = "") -> list[str]:
    """The CSV header of a message (its schema fields): as the CLI's --format csv."""
    out: list[str] = []
    for f in fields:
        at = prefix + f["name"]

        def leaf(name: str, f: dict[str, Any] = f) -> None:
            if f["value"] == "record":
                out.extend(_columns(f["record"]["fields"], name + "."))
                return
            if f["unit"] and f["value"] == "int":
                raw = f["name"]
                if raw.endswith("_raw") and len(raw) > 4:
                    name = prefix + raw[:-4] + name[len(prefix) + len(raw):]
                name += "[" + f["unit"]["name"] + "]"
            out.append(name)

        if f["array"] and _is_hex_array(f):
            out.append(at)
        elif f["array"]:
            for i in range(f["count"]):
                leaf(f"{at}_{i}")
        else:
            leaf(at)
    return out


def _cells(fields: list[dict[str, Any]], values: Optional[dict[str, Any]], out: list[str]) -> None:
    """The CSV cells of a message's (or record's) decoded fields; values None: empty cells."""
    for f in fields:
        v = values.get(f["name"]) if values is not None else None
        physical = None
        if values is not None and f["unit"] and f["value"] == "int" and v is not None:
            physical = values[_physical_key(f["name"])]["value"]
        if f["array"] and _is_hex_array(f):
            out.append(" ".join(f"{b:02X}" for b in v) if v is not None else "")
            continue
        count = f["count"] if f["array"] else 1
        for i in range(count):
            e = (v[i] if f["array"] else v) if v is not None else None
            if f["value"] == "record":
                _cells(f["record"]["fields"], e, out)
            elif e is None:
                out.append("")
            elif f["value"] == "bool":
                out.append("true" if e else "false")
            elif f["value"] == "float":
                out.append(_shortest(float(e)))
            elif physical is not None:
                out.append("%.15g" % (physical[i] if f["array"] else physical))
            elif f["value"] in ("text", "enum"):
                out.append(_csv_cell(str(e)))
            elif isinstance(e, str):  # bytes, as hex
                out.append(e)
            else:
                out.append(str(int(e)))


_schemas: dict[str, dict[str, Any]] = {}


def _message_fields(protocol: str, message: str) -> list[dict[str, Any]]:
    if protocol not in _schemas:
        from . import schema

        _schemas[protocol] = {m["name"]: m for m in schema(protocol)["protocols"][0]["messages"]}
    fields: list[dict[str, Any]] = _schemas[protocol][message]["fields"]
    return fields


def csv_columns(protocol: str, message: str) -> list[str]:
    """The columns of a message's CSV table: time, line, direction, then one per field
    element with the unit in the name ("battery_voltage[V]", "motor_current_0[A]", ...)."""
    return ["time", "line", "direction"] + _columns(_message_fields(protocol, message))


def _csv_row(record: dict[str, Any]) -> str:
    cells = [_csv_cell(record.get("time", "")), str(record.get("line") or ""), record.get("direction", "")]
    _cells(_message_fields(record["protocol"], record["message"]), record["fields"], cells)
    return ",".join(cells) + "\n"


def to_csv(records_or_path: Union[Source, Iterable[dict[str, Any]]], file: Union[str, os.PathLike[str], IO[str]], *,
           message: str, protocol: Optional[str] = None) -> int:
    """Writes one message's table as `robowire decode [protocol] --file LOG --format csv
    --message M` does: time, line, direction, then a column per field element with
    physical values and the unit in the header. records_or_path: a log (a path or a
    file object open for reading: read by the CLI's reader, in C++), or records of
    read_log (the other messages and the errors among them are left out). file: a
    path or a text file object. Returns the number of rows written."""
    own = isinstance(file, (str, os.PathLike))
    out: IO[str] = open(file, "w", newline="") if isinstance(file, (str, os.PathLike)) else file
    rows = 0
    try:
        if isinstance(records_or_path, (str, os.PathLike)) or hasattr(records_or_path, "read"):
            reader = _robowire.LogReader(records_or_path, protocol or "", None, None, "csv", message)
            while True:
                text: str = reader.next()
                if not text:
                    break
                rows += text.count("\n")
                out.write(text)
            return max(rows - 1, 0)
        header = False
        for r in records_or_path:
            if r.get("type") != "message" or r.get("message") != message:
                continue
            if not header:
                out.write(",".join(_csv_cell(c) for c in csv_columns(r["protocol"], message)) + "\n")
                header = True
            out.write(_csv_row(r))
            rows += 1
        return rows
    finally:
        if own:
            out.close()


# ---------------------------------------------------------------- plots
def _series_columns(columns: list[str], field: str) -> list[str]:
    """The columns of `field` (its name without unit: "battery_voltage", "motor_current" for
    motor_current_0..5, "motor_current_2" for one of them)."""
    import re

    def base(c: str) -> str:
        return c.split("[", 1)[0]

    exact = [c for c in columns if base(c) == field]
    if exact:
        return exact
    return [c for c in columns if re.fullmatch(re.escape(field) + r"_\d+", base(c))]


def _time_of(record: dict[str, Any]) -> Any:
    from datetime import datetime

    t = record.get("time")
    if not t:
        return None
    return datetime.fromisoformat(t) if "T" in t else datetime.strptime(t, "%H:%M:%S.%f")


def plot(source: Source, fields: Iterable[str], out: Union[str, os.PathLike[str]], *, message: Optional[str] = None,
         protocol: Optional[str] = None, title: Optional[str] = None) -> dict[str, Any]:
    """Draws fields of one message type over time into an image file (PNG, SVG, PDF:
    from out's suffix), one panel per unit with the unit on its axis. fields: names
    as in the CSV header without unit ("battery_voltage", "motor_current" for all
    six motor_current_N, "accel_1"). message: the message type (default: the first
    one in the log that has every field). Needs matplotlib (Debian:
    python3-matplotlib). Returns what was drawn: {"message", "columns", "points"}.
    Raises ValueError for a field no message has, or when the log holds none."""
    wanted = [f.strip() for f in fields if f.strip()]
    if not wanted:
        raise ValueError("no field to plot (e.g. battery_voltage,motor_current)")
    import importlib

    try:  # (through importlib: matplotlib is optional, and typed in some versions only)
        matplotlib = importlib.import_module("matplotlib")
        matplotlib.use("Agg")
        plt = importlib.import_module("matplotlib.pyplot")
    except ImportError as e:
        raise ImportError("robowire plot needs matplotlib (Debian: apt-get install python3-matplotlib; "
                          "or pip install matplotlib)") from e
    from . import schema

    # the message types with every field: (protocol, message) -> the columns of each field
    candidates: dict[tuple[str, str], list[list[str]]] = {}
    known: set[str] = set()
    for p in schema(protocol)["protocols"]:
        for m in p["messages"]:
            if message and m["name"] != message:
                continue
            columns = csv_columns(p["name"], m["name"])[3:]
            per_field = [_series_columns(columns, f) for f in wanted]
            known.update(f for f, cs in zip(wanted, per_field) if cs)
            if all(per_field):
                candidates[(p["name"], m["name"])] = per_field
    if not candidates:
        unknown = [f for f in wanted if f not in known]
        where = f"message {message}" if message else "any message" + (f" of {protocol}" if protocol else "")
        if unknown:
            raise ValueError(f"unknown field{'s' if len(unknown) > 1 else ''} {', '.join(unknown)}: not in {where} "
                             "(the names of the CSV header without unit: robowire list --fields)")
        raise ValueError(f"no message has all of {', '.join(wanted)}" + (f" ({where})" if message else ""))

    chosen: Optional[tuple[str, str]] = None
    times: list[Any] = []
    lines: list[int] = []
    values: dict[str, list[float]] = {}
    for r in read_log(source, protocol):
        if r.get("type") != "message":
            continue
        key = (r["protocol"], r["message"])
        if chosen is None and key in candidates:
            chosen = key
        if key != chosen:
            continue
        columns = csv_columns(*key)
        cells: list[str] = []
        _cells(_message_fields(*key), r["fields"], cells)
        row = dict(zip(columns[3:], cells))
        times.append(_time_of(r))
        lines.append(r.get("line") or 0)
        for cs in candidates[key]:
            for c in cs:
                values.setdefault(c, []).append(float(row[c]) if row[c] not in ("", "true", "false") else
                                                float(row[c] == "true") if row[c] else float("nan"))
    if chosen is None:
        names = ", ".join(m for _, m in candidates)
        raise ValueError(f"no {names} message in {source!r}: nothing to plot")

    use_time = all(t is not None for t in times)
    x = times if use_time else lines
    by_unit: dict[str, list[str]] = {}
    for cs in candidates[chosen]:
        for c in cs:
            unit = c[c.index("[") + 1:-1] if c.endswith("]") else ""
            by_unit.setdefault(unit, []).append(c)
    fig, axes = plt.subplots(len(by_unit), 1, sharex=True, squeeze=False, figsize=(10, 2.6 * len(by_unit) + 0.8))
    for ax, (unit, cs) in zip(axes[:, 0], by_unit.items()):
        for c in cs:
            ax.plot(x, values[c], label=c.split("[", 1)[0], linewidth=1)
        ax.set_ylabel(unit or "value")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize="small", ncol=min(len(cs), 3))
    if use_time:  # the time of day on the axis, the date (when the log gives one) in its label
        dates = importlib.import_module("matplotlib.dates")
        axes[-1, 0].xaxis.set_major_formatter(dates.DateFormatter("%H:%M:%S"))
        days = sorted({t.date().isoformat() for t in times if t.year > 1900})
        axes[-1, 0].set_xlabel("time" + (f" ({days[0]}" + (f" to {days[-1]}" if len(days) > 1 else "") + ")" if days else ""))
    else:
        axes[-1, 0].set_xlabel("line")
    fig.suptitle(title or f"{chosen[0]} {chosen[1]}: {os.fspath(source) if isinstance(source, (str, os.PathLike)) else ''}")
    fig.tight_layout()
    fig.savefig(out)
    plt.close(fig)
    return {"message": chosen[1], "columns": [c for cs in candidates[chosen] for c in cs], "points": len(x)}
