"""python -m robowire plot LOG --fields battery_voltage,motor_current -o out.png

Draws fields of a log's messages over time (robowire.plot; needs matplotlib,
Debian: python3-matplotlib), and writes a message's CSV table (robowire.to_csv).
"""
from __future__ import annotations

import argparse
import sys


def main(argv: "list[str] | None" = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m robowire", description="robowire's log tools (docs/python.md)")
    commands = parser.add_subparsers(dest="command", required=True)
    p = commands.add_parser("plot", help="draw fields of a log's messages over time into an image")
    p.add_argument("log", help="an nRF Connect log or hex lines (- : stdin)")
    p.add_argument("--fields", required=True, help="field names as in the CSV header without unit, comma-separated "
                   "(battery_voltage,motor_current)")
    p.add_argument("-o", "--output", required=True, help="the image file (.png, .svg, .pdf)")
    p.add_argument("--message", help="the message type (default: the first in the log with every field)")
    p.add_argument("--protocol", choices=["buwizz3", "navbot", "osp"], help="the protocol (default: from the UUIDs)")
    p.add_argument("--title", help="the title above the plot")
    c = commands.add_parser("csv", help="write one message's CSV table (as robowire decode --format csv)")
    c.add_argument("log", help="an nRF Connect log or hex lines (- : stdin)")
    c.add_argument("--message", required=True, help="the message type (status, ...)")
    c.add_argument("-o", "--output", default="-", help="the CSV file (default -: stdout)")
    c.add_argument("--protocol", choices=["buwizz3", "navbot", "osp"], help="the protocol (default: from the UUIDs)")
    args = parser.parse_args(argv)

    from . import plot, to_csv

    source = sys.stdin.buffer if args.log == "-" else args.log
    try:
        if args.command == "plot":
            drawn = plot(source, args.fields.split(","), args.output, message=args.message, protocol=args.protocol,
                         title=args.title)
            print(f"{args.output}: {drawn['message']}: {', '.join(drawn['columns'])}; {drawn['points']} points",
                  file=sys.stderr)
        else:
            n = to_csv(source, sys.stdout if args.output == "-" else args.output, message=args.message,
                       protocol=args.protocol)
            print(f"{args.output}: {n} rows", file=sys.stderr)
    except (ValueError, ImportError, OSError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
