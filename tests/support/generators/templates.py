"""Fuzz kind "templates": values from users through a set-up's templates to every writer (issue 31, item 1).

Random file names and ``--define`` values - parentheses, ``;``, line breaks, ``%``, grbl's real-time
characters, non-ASCII, very long - and source comments that read as LinuxCNC's active ones, translated
with header, footer, operation-start and tool-change templates that write them (inside each target's
comments, and now and then outside one, which must be refused at the template). The check: the output
reads back in its dialect with the source's tool path (no value placed a live word), and the controller
rules of ``tests/support/output_rules.py`` hold (grbl: no real-time character, no line over its buffer).
"""

from __future__ import annotations

import io

from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import ConfigError, Diagnostics, ErrorList, PostprocError
from postproc.setup.machine_setup import MachineSetup
from postproc.setup.groups import Templates
from tests.support.fuzzing import WRITERS, _check_output, located
from tests.support.generators import Case

KIND = "templates"

PIECES = ["(", ")", "((", "))", ";", "\n", "\r", "\r\n", "%", "?", "!", "~", "\x18", "\x00", "\u2014", "\u00d8",
          "\u00e9", "\u0085", "\u2028", "\ue000", "\ue001", " G0 X-999. ", "X999", "M30", "MSG,", " LOGOPEN,/tmp/x",
          "ABORT,", "(MSG, hi)", "#1=5", "O1", "N10", "/", "$", "[", "]", "\\", "{{ 1 }}", "x" * 200, "A", "0"]
"""Bits of text that end a comment, start code, make a comment act, or trigger grbl, if written raw."""
VALUE = st.lists(st.one_of(st.sampled_from(PIECES), st.text(max_size=4)), max_size=8).map("".join)
NAME = VALUE.map(lambda s: s.replace("/", "_").replace("\x00", "_") or "p")

PROGRAMS = [
    "G21 G90 G0 X0. Y0. Z10.\nG1 Z-1. F100.\nX5. Y5.\nM30\n",
    "G21 G90\n(ROUGH POCKET)\nT1 M6\nG0 X1. Y2. Z5.\nG1 Z-1. F100.\n(FINISH)\nT2 M6\nG0 X3. Y4.\nM30\n",
    "G21 G90\n( MSG, operator)\n(LOGOPEN,/tmp/fuzz.log)\n(DEBUG, #1)\nG0 X1. Y1.\nM30\n",
    "G21 G90\n(\u00d8 10 \u2014 DRILL!?)\nG0 X1. Y1. Z5.\nG1 Z-2. F80.\nM30\n",
]
"""Fanuc sources: plain motion, operations named by a comment before their tool change, comments that act
in LinuxCNC, and comments grbl would act on."""


def _templates(semicolon: bool, outside: bool) -> Templates:
    def note(text: str) -> str:
        return f";{text}" if semicolon else f"({text})"
    header = note("PROGRAM {{ program }} FOR {{ machine }}") + "\n" + note("JOB {{ job }} FROM {{ source_file }}")
    if outside:
        header += "\n{{ job }}"
    return Templates(header=header, footer=note("END OF {{ program }} {{ job|upper }}"),
                     operation_start=note("OPERATION {{ operation }}: {{ name }} T{{ tool }}"))


@st.composite
def cases(draw: st.DrawFn) -> Case:
    target = draw(st.sampled_from([w for w in WRITERS if w != "gsk"]))  # gsk: a lathe; these are mill programs
    semicolon = target == "fagor" or draw(st.booleans()) and target in ("linuxcnc", "grbl", "isg", "mach3")
    outside = draw(st.integers(0, 9)) == 0
    setup = MachineSetup(name=draw(VALUE) or "m", templates=_templates(semicolon, outside))
    file = draw(NAME) + ".nc"
    job = draw(VALUE)
    program = draw(st.sampled_from(PROGRAMS))

    def run(text: str) -> str:
        out = io.StringIO()
        try:
            translate(io.StringIO(text), out, file=file, source="fanuc", target=target, setup=setup,
                                    defines={"job": job}, diagnostics=Diagnostics(warn_stream=io.StringIO()))
        except ErrorList as errs:
            for err in errs.errors:
                located(err)
            return "refused"
        except PostprocError as err:  # a template refused: at its line in the set-up
            assert isinstance(err, ConfigError), str(err)
            located(err)
            return "refused"
        assert not (outside and job), f"a value outside a comment was written:\n{out.getvalue()}"
        return _check_output("fanuc", target, text, out.getvalue(), setup, False)

    return Case(name=f"templates fanuc-{target}", target=target, program=program, run=run, setup=setup)
