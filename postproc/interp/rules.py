"""How a dialect finds and ends numbered subprograms: data a dialect's ``ProgramSyntax`` sets
(``SUBPROGRAM_RULES``); the two families known today:

Fanuc: the subprograms are the ``O`` blocks after the main program's end (or library files), each runs
to ``M99`` or to the next ``O``, and ``M99`` in the main program starts it again.

LinuxCNC's Fanuc-style subprograms (checked with the packaged ``rs274``):
- ``M98 P<n>`` looks for ``O<n>`` from the call onward, in the calling file, and remembers what it found:
  an ``O<n>`` only before the call is "EOF in file ... seeking o-word: o<n>"; one found once is found again
  from anywhere. The first ``O<n>`` after the call wins. No library file is searched.
- The subprogram runs until ``M99`` (an ``O`` line on its way does nothing); running off the end of the
  file is "File ended with no percent sign or program end"; ``M2``/``M30`` in it end the program.
- ``M98`` to an ``o<n> sub`` is "'O.... sub' subroutine must be called with 'O.... call'", and
  ``o<n> call`` to an ``O<n>`` "Fanuc 'O....' subroutine must be called with 'M98'".
- ``M99`` in the main program ends it as ``M2`` does (the canonical calls are M2's).
- The flow passing an ``o<n> sub`` definition runs its ``endsub``: ``#<_value>`` is its value, or 0.
"""

from __future__ import annotations

from ..records import record


@record(frozen=True)
class SubprogramRules:
    forward_search: bool
    """``M98`` looks for ``O<n>`` from the call onward and the body runs to ``M99`` (LinuxCNC); else the
    store's subprograms after the main program's end (Fanuc)."""
    main_return_words: tuple[tuple[str, str], ...] | None
    """What ``M99`` in the main program runs instead (LinuxCNC: ``M2``); None: it restarts the program."""
    main_return_refused: bool = False
    """A return in the main program is an error (a dialect whose return ends only a subroutine)."""
    definition_runs_its_end: bool = False
    """The flow passing an ``o<n> sub`` definition skips its body but runs its ``endsub [v]`` as a return
    (rs274: ``o100 sub`` .. ``o100 endsub [6]`` met before any call leaves ``#<_value>`` 6 and
    ``#<_value_returned>`` 1; a plain ``endsub`` leaves both 0)."""
    value_in_caller: bool = False
    """A return's value (``endsub [v]``, ``return [v]``) is evaluated once the callee's level is gone, with the
    caller's parameters (grblHAL: ``ngc_flowctrl.c`` unwinds the call, then evaluates the expression); False:
    with the callee's (rs274)."""
    call_levels: int | None = None
    """The controller's own bound on nested calls, where it has one below the set-up's ``callDepth``: a call
    deeper than that is refused where the controller refuses it (grblHAL: 10). None: only the set-up's."""
    jumps_past_end: bool = False
    """A jump in the main program may land on a block after its end (M30): the run goes on from there, through
    the rest of the file, until a program end runs (SINUMERIK). False: such a jump is refused, since where
    the controller runs from there is not modelled."""
    flow_stack: int | None = None
    """The controller's stack of open flow constructs, where it has one: each loop, condition and call open
    where a construct opens is one entry (grblHAL: 20). A construct that would be one more is refused where
    it stands (``Structure``). None: no bound."""


STORED_PROGRAMS = SubprogramRules(forward_search=False, main_return_words=None)
"""The subprograms are the programs after the main program's end (or library files); a return in the
main program starts it again (Fanuc)."""
