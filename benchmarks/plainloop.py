"""The plain-loop baseline: stream, tokenize with one regex, reformat numbers, write.

Usage: python benchmarks/plainloop.py IN OUT

This is the speed reference for ``postproc translate --normalize``: the least work a
streaming G-code rewriter in pure Python can do.  Axis-type words get an explicit
decimal point (Fanuc's ``Y1500`` in least increments becomes ``Y1.5``), code words
(N G M T S H D P ...) are copied, comments pass through untouched.
"""
from __future__ import annotations

import re
import sys

WORD = re.compile(r"(\([^)]*\))|([A-Z])\s*([-+]?[0-9]*\.?[0-9]*)")
DECIMAL_LETTERS = frozenset("XYZIJKRQ")  # lengths: no decimal point = 0.001 mm
FEED_LETTER = "F"  # no decimal point = whole mm/min


def translate(src: str, dst: str) -> int:
    """Rewrite src to dst block by block; return the number of blocks."""
    findall = WORD.findall
    decimal_letters = DECIMAL_LETTERS
    blocks = 0
    with open(src, encoding="ascii") as fin, open(dst, "w", encoding="ascii") as fout:
        write = fout.write
        for line in fin:
            blocks += 1
            words = []
            for comment, letter, value in findall(line):
                if comment:
                    words.append(comment)
                    continue
                if letter in decimal_letters:
                    number = float(value) if "." in value else int(value) / 1000
                elif letter == FEED_LETTER:
                    number = float(value)
                else:
                    words.append(letter + value)  # code words: N G M T S H D P O
                    continue
                text = f"{number:.4f}".rstrip("0")
                words.append(letter + ("0." if text == "-0." else text))
            write(" ".join(words) + "\n" if words else line)  # no words: %, blank
    return blocks


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__.splitlines()[2])
    print(translate(sys.argv[1], sys.argv[2]))
