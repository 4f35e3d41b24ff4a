"""grblHAL's parameters in a call: LinuxCNC's (``NgcVariables``: ``#1``-``#30`` and names without ``_`` local to
a call, the rest global) but for the arguments a call does not give.

From grblHAL core ``ngc_flowctrl.c`` (``NGCFlowCtrl_Call``) and ``ngc_params.c`` (stored commit f80fc34) [V]:
the call evaluates its ``[..]`` arguments into ``#1``.. ``#n``, then fills ``#n+1``-``#30`` with the caller's
values of those parameters (``ngc_param_get`` before ``stack_push``, in the caller's context), and only then
opens the callee's context. So an argument not given is inherited, where rs274 reads 0. (With exactly 29
arguments the fill loop is skipped and ``#30`` is left unset in C: the reader refuses such a call.) A call sets
``#<_value>`` and ``#<_value_returned>`` to 0; an ``endsub``/``return`` with a value sets both (``_value_returned``
1), one without sets ``_value_returned`` 0: what ``NgcVariables`` does after a call.
"""

from __future__ import annotations

from postproc.ir.expr import Value
from postproc.rs274.variables import NgcVariables

CALL_ARGUMENTS = 30
"""``#1``-``#30``: a call's arguments and the parameters local to it."""


class GrblhalVariables(NgcVariables):
    """grblHAL's parameters (module docstring)."""

    __slots__ = ()

    def enter(self, args: dict[int, Value], new_level: bool) -> None:
        """An o-word call: the given arguments, and the caller's ``#k`` for every ``k`` not given."""
        if not new_level:
            super().enter(args, new_level)
            return
        inherited = {k: v for k, v in self.numbered[-1].items() if 1 <= k <= CALL_ARGUMENTS}
        inherited.update({k: v for k, v in args.items() if v is not None})
        self.numbered.append(inherited)
        self.named.append({})
