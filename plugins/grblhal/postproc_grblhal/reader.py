"""grblHAL reader: the grbl family's reader (``%`` as an inert comment), naming grblHAL in errors. ``/`` at the
start of a block skips it when the operator's block delete switch is on [V: grblHAL core ``gcode.c``
``gc_normalize_block``, ``sys.flags.block_delete_enabled``], as RS274/NGC reads it. Parameters, expressions and
o-words are read only for a build with them (``<Controller expressions="true">``, ``program``).

Numbered o-word subroutines are read as grblHAL runs them, from ``ngc_flowctrl.c`` (stored commit f80fc34) [V]:
the flow registers ``o<n> sub`` when it passes the definition (``add_sub``) and skips its body, and ``o<n> call``
finds only a registered sub (else "flow control syntax error"): a call stands after its sub's ``endsub`` in the
text, or inside that sub's own body (a recursion: the body runs only once the definition has registered the sub;
grblHAL bounds the nesting at 10 calls, ``program.CALL_LEVELS``); a located error otherwise (stricter than grblHAL
for a call inside a sub's body of a sub defined after it, which runs when both definitions are passed before the
first call). A call's arguments are ``GrblhalVariables``'. What is not modelled is a located
error: a named sub (``o<name> sub``/``call``: the file ``<name>.macro`` on the controller's file system), a
call with 29 arguments (``#30`` left unset), and a return outside the body of the sub it names (grblHAL hands
one in the main program to a G65 macro plugin).
"""

from __future__ import annotations

from typing import Iterable, Iterator

from postproc.interp.control import CONTROL, Call, Return, SubEnd, SubStart
from postproc.errors import Location, ParseError
from postproc.grbl_family.reader import GrblFamilyReader
from postproc.ir import Block

NAMED = ("a named grblHAL subroutine (o<name> sub, o<name> call) is the file <name>.macro on the controller's file "
         "system, not modelled by this dialect: number the sub (o100 sub) or flatten the program")
BEFORE = ("grblHAL finds a sub only once the program has passed its definition (ngc_flowctrl.c registers "
          "o{name} sub when the flow reaches it): write o{name} sub .. o{name} endsub before this call")
TWENTY_NINE = ("a grblHAL call with 29 arguments leaves #30 unset (ngc_flowctrl.c fills the arguments not given "
               "only below 29): give 30 or fewer than 29")
OUTSIDE = ("a grblHAL return outside the body of the sub it names (M99, or o<n> return in the main program, is "
           "handed to a G65 macro plugin there): not modelled")


class GrblhalReader(GrblFamilyReader):
    DIALECT = "grblHAL"

    def parametric(self) -> bool:
        """o-words, parameters and expressions where the set-up enables grblHAL's expressions."""
        return bool(self.ctx.setup.controller.expressions)

    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        defined: set[str] = set()
        body: str | None = None
        for block in super().read(lines):
            statement = block.sections.get(CONTROL)
            if isinstance(statement, (SubStart, SubEnd, Call, Return)):
                problem = _problem(statement, defined, body)
                if problem is not None:
                    self.ctx.diagnostics.error(ParseError(problem, Location(self.ctx.file, block.line, 1)), block.text)
                    yield Block(block.line, block.text, block.eol)  # kept as text, as every refused line
                    continue
                if isinstance(statement, SubStart):
                    body = statement.name
                elif isinstance(statement, SubEnd):
                    defined.add(statement.name)
                    body = None
            yield block


def _problem(statement: SubStart | SubEnd | Call | Return, defined: set[str], body: str | None) -> str | None:
    """What grblHAL would not run as this dialect simulates it (module docstring); None: nothing."""
    name = statement.name
    if isinstance(statement, Return):
        return None if body is not None and name == body else OUTSIDE
    if not isinstance(name, str) or not name.isdigit():
        return NAMED
    if isinstance(statement, Call):
        if name not in defined and name != body:  # its own body runs only once its definition registered it
            return BEFORE.format(name=name)
        if len(statement.args) == 29:
            return TWENTY_NINE
    return None
