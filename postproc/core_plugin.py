"""The core's own plugin: registers the neutral syntax objects and configuration nodes."""

from __future__ import annotations

from . import cycles
from .control import register_control
from .cycles.lowering import expand_canned_cycles
from .hookspecs import hookimpl
from .expr import register_expressions
from .ir import register_sections
from .lower import register_transform
from .setup import MachineSetup
from .syntax import Pipeline
from .syntaxes.modal_state import ModalStateSyntax
from .xmlio import XFactory


@hookimpl
def postproc_register_xml(factory: XFactory) -> None:
    register_sections(factory)
    register_expressions(factory)
    register_control(factory)
    for cls in (Pipeline, MachineSetup, ModalStateSyntax):
        cls.reg(factory)
    cycles.register(factory)


register_transform(expand_canned_cycles)
