"""grblHAL's parameters in a call: LinuxCNC's (``NgcVariables``: ``#1``-``#30`` and names without ``_`` local to
a call, the rest global) but for the arguments a call does not give and for ``#<_value>``.

From grblHAL core ``ngc_flowctrl.c`` (``NGCFlowCtrl_Call``, ``NGCFlowCtrl_EndSub``, ``NGCFlowCtrl_Return``) and
``ngc_params.c`` (stored commit f80fc34d503bd62391a23b197b3e0ee66ce00cb7) [V]:
- the call evaluates its ``[..]`` arguments into ``#1``.. ``#n``, then fills ``#n+1``-``#30`` with the caller's
  values of those parameters (``ngc_param_get`` before ``stack_push``, in the caller's context), and only then
  opens the callee's context. So an argument not given is inherited, where rs274 reads 0. (With exactly 29
  arguments the fill loop is skipped and ``#30`` is left unset in C: the reader refuses such a call.)
- once the callee's level is open, the call sets ``#<_value>`` and ``#<_value_returned>`` to 0 (rs274 leaves
  them as they were: the callee reads what the last return left).
- ``endsub``/``return`` first unwinds the call (``stack_unwind_sub``: the callee's parameters are gone), then
  evaluates its ``[..]``, with the caller's parameters (``SubprogramRules.value_in_caller``), and sets
  ``#<_value>`` to it and ``#<_value_returned>`` to 1; without a value it sets only ``#<_value_returned>`` to 0,
  ``#<_value>`` keeping what the call or a call inside it set (rs274 sets it to 0).
- the flow passing a definition runs nothing of its ``endsub [v]`` (``skip_sub``: rs274 sets ``#<_value>``).
- nothing sets them before the first call (``ngc_params_init`` does not; ``ngc_expr.c`` reads a name never set as
  an error, "bad number format"): a read before then is an error, as for any name not set (rs274 reads 0).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable, ClassVar

from postproc.ir.expr import Value
from postproc.rs274.variables import NgcVariables

if TYPE_CHECKING:
    from postproc.frames.parameters import FrameReadings

CALL_ARGUMENTS = 30
"""``#1``-``#30``: a call's arguments and the parameters local to it."""


class GrblhalVariables(NgcVariables):
    """grblHAL's parameters (module docstring)."""

    __slots__ = ()
    RETURN_RULE: ClassVar[str] = ("a call sets #<_value> and #<_value_returned> to 0, a return without a value "
                                  "sets only #<_value_returned> to 0")

    def __init__(self, increment: Callable[[], float], frames: FrameReadings | None = None,
                 machine_mm: float = 1.0) -> None:
        super().__init__(increment, frames, machine_mm)
        del self.globals_["_value"], self.globals_["_value_returned"]  # (module docstring: none before a call)

    def enter(self, args: dict[int, Value], new_level: bool) -> None:
        """An o-word call: the given arguments, and the caller's ``#k`` for every ``k`` not given."""
        if not new_level:
            super().enter(args, new_level)
            return
        inherited = {k: v for k, v in self.numbered[-1].items() if 1 <= k <= CALL_ARGUMENTS}
        inherited.update({k: v for k, v in args.items() if v is not None})
        self.numbered.append(inherited)
        self.named.append({})
        self.globals_["_value"] = 0.0
        self.globals_["_value_returned"] = 0.0

    def leave(self, new_level: bool, value: Value = None) -> None:
        """Back in the caller (module docstring): a return without a value leaves ``#<_value>`` as it is."""
        if value is not None:
            super().leave(new_level, value)
            return
        if len(self.numbered) > 1:
            self.numbered.pop()
            self.named.pop()
        self.globals_["_value_returned"] = 0.0
