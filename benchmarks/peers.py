"""Parse-only runs of peer G-code libraries, one tool per process.

Usage: python benchmarks/peers.py TOOL FILE...   TOOL: gcode-lib | gcode-lib-state | gcodeparser | pygcode

Each function streams each FILE through the peer's parser and touches every parsed line
and word, so that lazy parsers really parse.  ``gcode-lib-state`` also tracks the modal
state and tool position line by line: the peer of ``postproc toolpath`` (and, over two
files, of ``postproc verify``).  Prints one JSON line
``{"tool": .., "items": .., "seconds": ..}`` (seconds: the parse alone); exits 3 when the peer is
not installed.
"""
from __future__ import annotations

import json
import sys
import time
from collections.abc import Callable

NOT_INSTALLED = 3


def parse_gcode_lib(path: str) -> int:
    """gcode-lib: ``parse_line`` per line -> GCodeLine(command, words{axis: float}, comment).

    Its word dict holds axis letters only (X Y Z E F R I J K); N/G/M/S/T stay in
    ``command``/``raw``.  ``gcode_lib.load`` would read the whole file into a list;
    the per-line call is its fastest, streaming path.
    """
    from gcode_lib import parse_line

    items = 0
    with open(path, encoding="ascii") as fh:
        for raw in fh:
            parsed = parse_line(raw)
            items += len(parsed.command) > 0
            for _letter, value in parsed.words.items():
                items += value is not None
    return items


def track_gcode_lib(path: str) -> int:
    """gcode-lib: ``parse_line`` then ``advance_state`` per line (G90/G91, G92, G0-G3 end points, F).

    Its position tracking needs a G word on the line: a modal ``X.. Y..`` block does not move its
    state, and arcs update only their end point, so it does less than a simulator.
    """
    from gcode_lib import ModalState, advance_state, parse_line

    state = ModalState()
    items = 0
    with open(path, encoding="ascii") as fh:
        for raw in fh:
            advance_state(state, parse_line(raw))
            items += state.x is not None
    return items


def parse_gcodeparser(path: str) -> int:
    """gcodeparser: ``parse_gcode_lines(file)`` yields GcodeLine(command, params) per G/M/T word.

    Needs ``Z0.`` spelled ``Z0.0`` (int('0.') fails) and silently drops blocks that
    carry no G/M/T word, i.e. modal ``X.. Y..`` lines.
    """
    from gcodeparser import parse_gcode_lines

    items = 0
    with open(path, encoding="ascii") as fh:
        for line in parse_gcode_lines(fh, include_comments=True):
            items += line.command[1] is not None
            for _letter, value in line.params.items():
                items += value is not None
    return items


def parse_pygcode(path: str) -> int:
    """pygcode: ``Line(text)`` -> block.words (Word objects) grouped into block.gcodes."""
    from pygcode import Line

    items = 0
    with open(path, encoding="ascii") as fh:
        for raw in fh:
            line = Line(raw)
            items += len(line.block.gcodes)
            for word in line.block.words:
                items += word.value is not None
    return items


TOOLS: dict[str, tuple[str, Callable[[str], int]]] = {
    "gcode-lib": ("gcode_lib", parse_gcode_lib),
    "gcode-lib-state": ("gcode_lib", track_gcode_lib),
    "gcodeparser": ("gcodeparser", parse_gcodeparser),
    "pygcode": ("pygcode", parse_pygcode),
}

PARSERS = ("gcode-lib", "gcodeparser", "pygcode")
"""The parse-only peers of translate."""

PARTIAL = frozenset({"gcodeparser"})  # skips blocks: its figures are not a full parse


def fanuc_decimals_copy(src: str, dst: str) -> None:
    """Copy src to dst with Fanuc's bare trailing point written out (``Z0.`` -> ``Z0.0``)."""
    import re

    bare_point = re.compile(r"(\d\.)(?![0-9])")
    with open(src, encoding="ascii") as fin, open(dst, "w", encoding="ascii") as fout:
        for line in fin:
            fout.write(bare_point.sub(r"\g<1>0", line))


def main(argv: list[str]) -> int:
    if len(argv) < 2 or argv[0] not in TOOLS:
        print(__doc__.splitlines()[2], file=sys.stderr)
        return 2
    tool, paths = argv[0], argv[1:]
    module, parse = TOOLS[tool]
    try:
        __import__(module)
    except ImportError:
        print(f"{tool}: not installed", file=sys.stderr)
        return NOT_INSTALLED
    start = time.perf_counter()
    items = sum(parse(path) for path in paths)
    seconds = time.perf_counter() - start
    print(json.dumps({"tool": tool, "items": items, "seconds": seconds}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
