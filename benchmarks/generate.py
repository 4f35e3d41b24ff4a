"""Write deterministic Fanuc benchmark programs: CAM-style milling of exactly N blocks (lines),
rows of canned-cycle holes, or a parametric bolt-circle loop.

Usage: python benchmarks/generate.py N OUT.nc [--seed S] [--kind cam|cycles|macro]
       (cycles: N holes; macro: N holes, as circles of 100 holes)

The CAM program is streamed operation by operation (each operation is a short list of
blocks), so memory does not grow with N.  Numbers are written Fanuc-style: trailing
zeros dropped but the decimal point kept (``Z0.``, ``X-12.5``), and about 1 in 80
axis values written without a decimal point in least increments (``Y1500`` = 1.5 mm).
"""
from __future__ import annotations

import argparse
import math
import random
from collections.abc import Iterator
from typing import TextIO

HEADER_BLOCKS = 7  # %, O-line and five numbered header blocks
FOOTER_BLOCKS = 5  # final retract, M09, G28, M30, %
MIN_BLOCKS = HEADER_BLOCKS + FOOTER_BLOCKS

X_RANGE = (-80.0, 180.0)
Y_RANGE = (-60.0, 110.0)
SAFE_Z = "5."
FEEDS = ("800.", "1200.", "1500.", "2000.", "2500.", "3000.")


def clamp(value: float, bounds: tuple[float, float]) -> float:
    return min(max(value, bounds[0]), bounds[1])


class Program:
    """Tool position and random source shared by the operation generators."""

    def __init__(self, seed: int) -> None:
        self.rng = random.Random(seed)
        self.x, self.y, self.z = 0.0, 0.0, 50.0
        self.heading = 0.0
        self.op_no = 0
        self.mode = "G00"  # modal motion code last written

    # -- number formatting -------------------------------------------------
    def num(self, value: float, decimals: int) -> str:
        """Fanuc decimal spelling: ``12.5``, ``0.``, ``-3.``; trailing zeros dropped."""
        text = f"{value:.{decimals}f}".rstrip("0")
        return "0." if text == "-0." else text

    def axis(self, letter: str, value: float, decimals: int) -> tuple[str, float]:
        """An axis word and the value the control will see (1 in 80 in least increments)."""
        if self.rng.random() < 0.0125:
            microns = round(value * 1000)
            return f"{letter}{microns}", microns / 1000
        value = round(value, decimals)
        return letter + self.num(value, decimals), value

    # -- geometry ----------------------------------------------------------
    def surface_z(self, x: float, y: float) -> float:
        """A smooth 3D surface for finishing passes."""
        return -4.0 + 2.5 * math.sin(x / 17.0) * math.cos(y / 23.0)

    def step(self, length: float) -> tuple[float, float]:
        """Next point of a smooth random walk kept inside the part."""
        rng = self.rng
        self.heading += rng.gauss(0.0, 0.35)
        nx = self.x + length * math.cos(self.heading)
        ny = self.y + length * math.sin(self.heading)
        if not (X_RANGE[0] < nx < X_RANGE[1] and Y_RANGE[0] < ny < Y_RANGE[1]):
            cx, cy = sum(X_RANGE) / 2, sum(Y_RANGE) / 2
            self.heading = math.atan2(cy - self.y, cx - self.x) + rng.uniform(-0.6, 0.6)
            nx = self.x + length * math.cos(self.heading)
            ny = self.y + length * math.sin(self.heading)
        return nx, ny

    def comment(self, kind: str) -> str:
        self.op_no += 1
        return f"({kind} {self.op_no})"

    # -- operations (each returns a short list of blocks, without N) --------
    def surface(self) -> list[str]:
        """3D finishing: a long run of short G01 moves, mostly modal X Y Z."""
        rng = self.rng
        blocks = [self.comment("FINISH PASS")] if rng.random() < 0.5 else []
        first = True
        for _ in range(rng.randint(40, 400)):
            nx, ny = self.step(rng.uniform(0.15, 2.5))
            wx, self.x = self.axis("X", nx, 4)
            wy, self.y = self.axis("Y", ny, 4)
            words = self.motion("G01") + [wx, wy]
            wz, z = self.axis("Z", self.surface_z(self.x, self.y), 3)
            if z != self.z:
                words.append(wz)
                self.z = z
            if first or rng.random() < 0.02:
                words.append("F" + rng.choice(FEEDS))
            blocks.append(" ".join(words))
            first = False
        return blocks

    def arc(self, use_r: bool) -> str:
        """One G02/G03 arc in the XY plane from the current point, IJ or R form."""
        rng = self.rng
        radius = rng.uniform(1.5, 20.0)
        cw = rng.random() < 0.5
        sweep = math.radians(rng.uniform(15.0, 170.0 if use_r else 260.0))
        angle = rng.uniform(0.0, 2 * math.pi)
        cx = round(self.x + radius * math.cos(angle), 4)
        cy = round(self.y + radius * math.sin(angle), 4)
        radius = math.hypot(self.x - cx, self.y - cy)
        start = math.atan2(self.y - cy, self.x - cx)
        end = start - sweep if cw else start + sweep
        ex, ey = cx + radius * math.cos(end), cy + radius * math.sin(end)
        if not (X_RANGE[0] < ex < X_RANGE[1] and Y_RANGE[0] < ey < Y_RANGE[1]):
            return self.line(*self.step(1.0))  # arc would leave the part
        words = self.motion("G02" if cw else "G03", always=True)
        ix, iy = cx - self.x, cy - self.y
        wx, self.x = self.axis("X", ex, 4)
        wy, self.y = self.axis("Y", ey, 4)
        words += [wx, wy]
        if use_r:
            words.append("R" + self.num(radius, 4))
        else:
            words += ["I" + self.num(ix, 4), "J" + self.num(iy, 4)]
        self.heading = end - math.pi / 2 if cw else end + math.pi / 2
        return " ".join(words)

    def motion(self, code: str, always: bool = False) -> list[str]:
        """The motion word if the modal code changes (or always), as CAM posts write it."""
        if always or code != self.mode:
            self.mode = code
            return [code]
        return []

    def line(self, nx: float, ny: float) -> str:
        wx, self.x = self.axis("X", nx, 4)
        wy, self.y = self.axis("Y", ny, 4)
        return " ".join(self.motion("G01") + [wx, wy])

    def contour(self) -> list[str]:
        """2D contour at one depth: plunge, lines and arcs, retract."""
        rng = self.rng
        depth = -round(rng.uniform(0.5, 12.0), 1)
        blocks = [self.comment("CONTOUR")]
        self.x, self.y = self.step(rng.uniform(5.0, 30.0))
        wx, self.x = self.axis("X", self.x, 4)
        wy, self.y = self.axis("Y", self.y, 4)
        blocks.append(" ".join(self.motion("G00") + [wx, wy]))
        blocks.append(f"Z{SAFE_Z}")
        self.mode = "G01"
        blocks.append(f"G01 Z{self.num(depth, 3)} F300.")
        if rng.random() < 0.1:
            blocks.append("G04 P" + str(rng.choice((200, 500, 1000))))
        self.z = depth
        feed = "F" + rng.choice(FEEDS)
        for i in range(rng.randint(10, 120)):
            kind = rng.random()
            if kind < 0.7:
                block = self.line(*self.step(rng.uniform(0.5, 8.0)))
            else:
                block = self.arc(use_r=kind < 0.82)
            if i == 0:
                block += " " + feed
            blocks.append(block)
        blocks.append(" ".join(self.motion("G00") + [f"Z{SAFE_Z}"]))
        self.z = float(SAFE_Z)
        return blocks

    def side_arcs(self) -> list[str]:
        """A few XZ-plane (G18) arcs with I/K centres, then back to G17."""
        rng = self.rng
        blocks = [self.comment("XZ BLEND"), "G18"]
        for _ in range(rng.randint(2, 6)):
            radius = rng.uniform(1.0, 4.0)
            cw = rng.random() < 0.5
            dx = radius * (1 if rng.random() < 0.5 else -1)
            ex = self.x + 2 * dx if X_RANGE[0] < self.x + 2 * dx < X_RANGE[1] else self.x - 2 * dx
            i = (ex - self.x) / 2
            wx, self.x = self.axis("X", ex, 4)
            self.mode = "G02" if cw else "G03"
            blocks.append(f"{self.mode} {wx} Z{self.num(self.z, 3)} "
                          f"I{self.num(i, 4)} K0.")
        blocks.append("G17")
        return blocks

    def tool_change(self, tool: int, speed: int) -> list[str]:
        wx, self.x = self.axis("X", self.x, 4)
        wy, self.y = self.axis("Y", self.y, 4)
        self.z, self.mode = 50.0, "G00"
        return ["G00 Z50.", "M09", "G91 G28 Z0.", f"T{tool} M06",
                f"G90 G54 G00 {wx} {wy} S{speed} M03", f"G43 Z50. H{tool:02d}", "M08"]

    def drilling(self) -> list[str]:
        """Tool change, a G81 or G83 cycle with hole repeats, G80, back to T1."""
        rng = self.rng
        peck = rng.random() < 0.5
        tool = 3 if peck else 2
        blocks = [self.comment("PECK DRILL" if peck else "DRILL")]
        blocks += self.tool_change(tool, 1200 if peck else 1800)
        depth = self.num(-round(rng.uniform(3.0, 30.0), 2), 3)
        hx, hy = self.x, self.y
        holes = []
        for _ in range(rng.randint(3, 25)):
            hx = clamp(hx + rng.choice((-1, 1)) * rng.choice((6.35, 10.0, 12.5)), X_RANGE)
            hy = clamp(hy + rng.choice((-1, 0, 0, 1)) * 8.0, Y_RANGE)
            wx, self.x = self.axis("X", hx, 4)
            wy, self.y = self.axis("Y", hy, 4)
            holes.append(f"{wx} {wy}")
        if peck:
            peck_depth = self.num(rng.uniform(1.0, 4.0), 3)
            blocks.append(f"G99 G83 {holes[0]} Z{depth} R2. Q{peck_depth} F120.")
        else:
            blocks.append(f"G98 G81 {holes[0]} Z{depth} R2. F150.")
        blocks += holes[1:]
        blocks.append("G80")
        blocks += self.tool_change(1, 8000)
        return blocks

    def operations(self) -> Iterator[tuple[list[str], bool]]:
        """Endless (blocks, may_truncate) operations."""
        rng = self.rng
        while True:
            kind = rng.random()
            if kind < 0.012:
                yield self.drilling(), False
            elif kind < 0.02:
                yield self.side_arcs(), False
            elif kind < 0.45:
                yield self.contour(), True
            else:
                yield self.surface(), True


def blocks(n: int, seed: int = 1234) -> Iterator[str]:
    """Yield exactly n program lines (with newline)."""
    if n < MIN_BLOCKS:
        raise ValueError(f"need at least {MIN_BLOCKS} blocks")
    prog = Program(seed)
    seq = 0

    def numbered(text: str) -> str:
        nonlocal seq
        seq += 10
        return f"N{seq} {text}\n"

    yield "%\n"
    yield "O1234 (PART)\n"
    yield numbered("G21 G17 G40 G49 G80 G90")
    yield numbered("T1 M06")
    yield numbered("G54 G00 X0. Y0. S8000 M03")
    yield numbered("G43 Z50. H01")
    yield numbered("M08")
    remaining = n - MIN_BLOCKS
    for op, may_truncate in prog.operations():
        if remaining == 0:
            break
        if len(op) > remaining:
            if not may_truncate:
                continue
            op = op[:remaining]
        for text in op:
            yield numbered(text)
        remaining -= len(op)
    yield numbered("G00 Z50.")
    yield numbered("M09")
    yield numbered("G91 G28 Z0.")
    yield numbered("M30")
    yield "%\n"


def write(n: int, out: TextIO, seed: int = 1234) -> None:
    """Stream an n-block program to out."""
    out.writelines(blocks(n, seed))


HOLES_PER_ROW = 25
"""Holes of one canned-cycle row (one cycle block, then one X Y block per further hole)."""


def cycle_rows(holes: int) -> Iterator[str]:
    """Yield a Fanuc drilling program of exactly ``holes`` holes: rows alternating G81 and G83.

    Each row is a cycle block at its first hole, then one ``X.. Y..`` block per hole and ``G80``;
    a G83 row pecks Q3. from R2. to Z-12. (5 pecks a hole:
    Z-1., -4., -7., -10., -12.).  No tool change or length offset, so every target
    (grbl included) takes it without warnings.  The hole count is exact: the last row is shortened.
    """
    yield "%\n"
    yield "O3000 (ROWS OF HOLES)\n"
    yield "G21 G17 G40 G49 G80 G90\n"
    yield "G54 G00 X0. Y0. S1800 M03\n"
    yield "G00 Z10.\n"
    row = 0
    left = holes
    while left > 0:
        count = min(HOLES_PER_ROW, left)
        y = f"{(row % 40) * 5.}"
        for i in range(count):
            x = f"{i * 6.35:.2f}".rstrip("0")
            if i > 0:
                yield f"X{x} Y{y}\n"
            elif row % 2 == 0:
                yield f"G99 G81 X{x} Y{y} Z-5. R2. F150.\n"
            else:
                yield f"G98 G83 X{x} Y{y} Z-12. R2. Q3. F120.\n"
        yield "G80\n"
        left -= count
        row += 1
    yield "G00 Z50.\n"
    yield "M05\n"
    yield "M30\n"
    yield "%\n"


MACRO_HOLES = 100
"""Holes a bolt circle of the command line's ``--kind macro``."""


def bolt_circles(circles: int, holes: int) -> Iterator[str]:
    """Yield a Fanuc Custom Macro B program: ``circles`` concentric bolt circles of ``holes`` holes each,
    drilled by two nested WHILE loops (a parametric program: nothing is written out).

    Flattened, each hole is three moves (rapid over the hole, feed down, rapid up)."""
    yield "%\n"
    yield "O2000 (BOLT CIRCLES, NESTED WHILE)\n"
    yield "G21 G17 G40 G80 G90\n"
    yield "G54 G00 X0 Y0 S1800 M03\n"
    yield "G00 Z5.\n"
    yield f"#1={holes} (HOLES A CIRCLE)\n"
    yield f"#2={circles} (CIRCLES)\n"
    yield "#20=0\n"
    yield "WHILE [#20 LT #2] DO1\n"
    yield "#10=0\n"
    yield "#21=10.+#20*0.5 (RADIUS)\n"
    yield "WHILE [#10 LT #1] DO2\n"
    yield "#11=#10*360./#1+#20\n"
    yield "G00 X[60.+#21*COS[#11]] Y[40.+#21*SIN[#11]]\n"
    yield "G01 Z-3. F200.\n"
    yield "G00 Z5.\n"
    yield "#10=#10+1\n"
    yield "END2\n"
    yield "#20=#20+1\n"
    yield "END1\n"
    yield "G00 Z50.\n"
    yield "M05\n"
    yield "M30\n"
    yield "%\n"


def bolt_circle_executed(circles: int, holes: int) -> int:
    """Program lines the interpreter runs for :func:`bolt_circles` (its interpreted blocks).

    Counted from the program text: 6 straight lines before the outer loop (the G-code and ``#`` lines,
    not ``%`` nor the O line), per circle the outer WHILE test, ``#10=0``, the radius, per hole the 7
    lines from the inner WHILE test to END2, the inner test that ends the loop, ``#20=#20+1`` and END1;
    then the outer test that ends the loop and the 3 closing lines."""
    per_circle = 3 + holes * 7 + 1 + 2
    return 6 + circles * per_circle + 1 + 3


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("n", type=int, help="number of blocks (lines)")
    parser.add_argument("out", help="output .nc file")
    parser.add_argument("--seed", type=int, default=1234)
    parser.add_argument("--kind", choices=("cam", "cycles", "macro"), default="cam")
    args = parser.parse_args()
    if args.kind == "cam" and args.n < MIN_BLOCKS:
        parser.error(f"N must be at least {MIN_BLOCKS}")
    if args.kind != "cam" and args.n < 1:
        parser.error("N must be at least 1")
    with open(args.out, "w", encoding="ascii", newline="\n") as out:
        if args.kind == "cycles":
            out.writelines(cycle_rows(args.n))
        elif args.kind == "macro":
            out.writelines(bolt_circles(-(-args.n // MACRO_HOLES), MACRO_HOLES))
        else:
            write(args.n, out, args.seed)


if __name__ == "__main__":
    main()
