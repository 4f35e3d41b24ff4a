"""Mach3/Mach4 mill: a read-and-write dialect plugin, written as a third party would publish one.

A plugin needs only what this package shows: a code table (``codes.py``, read and written alike), a
reader (``reader.py``), a block syntax and its pipeline (``block_syntax.py``; ``mach3.xml``, also built in
Python by ``Mach3.python_pipeline``), a writer, a ``Dialect`` subclass with its capability flags, and
``hookimpl`` functions that register the dialect and its syntax object. It imports only public names of ``postproc`` and is found through its
entry point (``pyproject.toml``). docs/plugins.md walks through it.

The controller: Mach3's interpreter follows the NIST RS274/NGC interpreter (words, modal groups, order of
execution: M5/M9 before the block's motion), dwell ``G4 P`` in seconds (Mach3's default; its "G04 dwell
in ms" option is a machine setting this plugin does not model), no oriented spindle stop, an ATC through
the M6 macro, G73/G83 clearances from the machine's settings. This package writes every axis, centre and radius word with exactly four decimals
(``X15.0000``), as many Mach3 posts do.
"""

from __future__ import annotations

from typing import Callable

from postproc.syntaxes.comments import CommentSyntax
from postproc.rs274.cutter_rules import NIST_V3
from postproc.cycle_words import CycleWords
from postproc.dialect import Dialect, Lazy, Reader, Writer
from postproc.hookspecs import hookimpl
from postproc.rs274.arc_ends import RS274NGC_ARC_END
from postproc.rs274.order_of_execution import stops_after_motion
from postproc.rs274.return_level import return_level_in_force
from postproc.setup.machine_setup import MachineSetup
from postproc.syntaxes.syntax import Pipeline
from postproc.xmlio import XFactory



class Mach3(Dialect):
    NAME = "mach3"
    DESCRIPTION = "Mach3/Mach4 mill (RS274/NGC words, G73/G81/G83 kept, 4-decimal axis words)"
    READER = Lazy[type[Reader]](".reader:Mach3Reader")
    """Imported when a run first reads Mach3 (``Lazy``), as is the block syntax: a run that does not
    use this dialect does not pay for its modules."""
    WRITER = Lazy[type[Writer]](".writer:Mach3Writer")
    """Imported when a run first writes Mach3, as the reader is."""
    PIPELINE_FILE = "mach3.xml"
    CYCLE_WORDS = Lazy[CycleWords](".codes:CYCLE_WORDS")  # (its code table, imported where a run reads it)
    """R level, Q peck, P dwell (seconds), L repeats."""
    NATIVE_CYCLES = frozenset({"drill", "peck_chip", "peck_deep"})
    """G81, G73 and G83 are written as cycles; every other cycle is expanded into plain moves. The G73
    retract and G83 clearance are machine settings (Mach4's #5114/#5115), taken from the set-up's
    ``<Cycles peckRetract peckClearance>`` like Fanuc's parameters (``PECK_CLEARANCE_MM`` stays None): a
    peck cycle from a control with another clearance (LinuxCNC's fixed 0.254 mm) is expanded."""
    CYCLE_SEMANTICS = "rs274"
    """The cycles move by the RS274/NGC rules (``postproc.cycles.semantics``)."""
    ARC_END = RS274NGC_ARC_END
    """Taken as LinuxCNC's interpreter's rule [?]: Mach3 descends from the NIST RS274/NGC interpreter, whose
    own limit was 0.0005 in / 0.005 mm absolute [V: rs274ngc.hh TOLERANCE_INCH/MM as imported into EMC2 in
    2004], but Mach3's own limit is not published; Fusion 360's Mach3 post writes inch arcs to three
    decimals (0.001 in of rounding), which that old limit would refuse."""
    COMMENTS = CommentSyntax(parens=True, nested=False, semicolon=True)
    """``( )`` and ``;`` comments, as RS274/NGC [K: Mach3 G-code manual]; a template's values stand only
    inside them (``postproc.output.template_values``)."""
    SPINDLE_ORIENTATION = False
    """No M19: cycles that need an oriented stop follow the set-up's ``Cycles orientation``."""
    SYNCHRONISED_TAP = False
    """No spindle-synchronised (rigid) tap: Mach3's G84 is the floating tap holder's cycle, and Mach3 has no
    rigid tap code [V: Dynomotion's Mach3 plugin help, "Mach3 Plugin - Rigid Tapping": a rigid tap there is
    an M84 macro that hands the cycle to the motion card]. A rigid tap of another dialect (LinuxCNC
    ``G33.1``, Fanuc ``M29``+``G84``) is refused by name, never written as a floating tap's feed moves."""
    RIGID_TAP_LACK = ("its G84 is the floating tap holder's cycle and it has no rigid tap code [V: Dynomotion's "
                      "Mach3 plugin help, Mach3 Rigid Tapping]")
    """Said where a rigid tap of another family is refused (``SYNCHRONISED_TAP``)."""
    STOPS_BEFORE_MOTION = True
    """The RS274/NGC order of execution: M5 and M9 act before the block's motion."""
    FEED_BEFORE_UNITS = True
    """F in a block that changes units is in the old units [K: the Mach3Mill manual's order-of-execution
    table is the NIST RS274/NGC one: set feed rate (3) before set length units (12); not run on a
    Mach3 here]."""
    LOWERING = (stops_after_motion, return_level_in_force)
    """A moving block's spindle stop and coolant off go in a block of their own after it, where the
    source stopped after the motion (``postproc.rs274.order_of_execution``); a native cycle whose source
    assumed another return level gets its G98/G99 (``postproc.rs274.return_level``)."""
    START_RETURN_LEVEL = "initial"
    """G98 at program start [?: Mach3's reset modes are screen settings; this dialect has read G98 as the
    start level since it was written, and a LinuxCNC program leaving its cycles to G99 is written with G99]."""
    DWELL_UNIT = "seconds"
    """G4 P is in seconds."""
    CUTTER_RULES = NIST_V3
    """Cutter radius compensation as the NIST RS274/NGC version 3 interpreter runs it (its entry move, an
    arc around each outside corner, an inside corner an error) [?: Mach3's interpreter follows that one; not
    run on a Mach3 here]: simulated, resolved into moves for a target without compensation, and for one
    whose rules differ (LinuxCNC)."""

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline:
        """``mach3.xml``, built in Python (no XML is read when a program is: a faster start; the
        conformance suite checks that it is the file's pipeline)."""
        from postproc.cycles.resolve import CannedCycleResolveSyntax
        from postproc.syntaxes.modal_state import ModalStateSyntax
        from .block_syntax import Mach3BlockSyntax
        return Pipeline(cls.NAME, [Mach3BlockSyntax(), CannedCycleResolveSyntax("rs274"), ModalStateSyntax()])


@hookimpl
def postproc_register_dialects(register: Callable[[type], None]) -> None:
    register(Mach3)


@hookimpl
def postproc_register_xml(factory: XFactory) -> None:
    """The block syntax, imported when an element names it (``XFactory.register_lazy``)."""
    factory.register_lazy("Mach3BlockSyntax", f"{__name__}.block_syntax:Mach3BlockSyntax")
