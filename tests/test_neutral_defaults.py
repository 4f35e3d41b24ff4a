"""The neutral core takes no dialect family's rules by default (issue 30 item 3): a hole cycle resolved under
rules no family has is refused, not moved by Fanuc's; a set-up that names no controller variant is the
dialect's own controller; the cutter compensation rule tables live in the rs274 family base."""

from __future__ import annotations

import pytest

from postproc.cycles.drilling import DrillingExpansion
from postproc.cycles.section import CannedCycle
from postproc.errors import ConfigError
from postproc.interp.evaluation import MappingEnv
from postproc.rs274.machine_codes import cutter_register_from_h, dwell_in_seconds
from postproc.setup.machine_setup import MachineSetup
from postproc.xmlio import lxml_etree


def _cycle(semantics: str) -> CannedCycle:
    return CannedCycle("drill", semantics=semantics, initial=10.0, r=2.0, bottom=-5.0, feed=100.0,
                       start={"X": 0.0, "Y": 0.0, "Z": 10.0}, position={"X": 1.0, "Y": 2.0})


@pytest.mark.parametrize("semantics", ["haas", "", "FANUC"])
def test_a_cycle_under_unknown_rules_is_refused_by_name(semantics: str) -> None:
    with pytest.raises(ConfigError, match=f"rules {semantics!r}, which are not modelled"):
        DrillingExpansion().expand(_cycle(semantics))
    with pytest.raises(ConfigError, match="known: fanuc, rs274"):
        DrillingExpansion().end(_cycle(semantics))


def test_a_cycle_read_from_xml_under_unknown_rules_is_refused() -> None:
    """An IR file's ``<CannedCycle semantics=...>`` is read as written; expanding it names the rules."""
    el = _cycle("fanuc").make_xml_source()
    el.set("semantics", "haas")
    cycle = CannedCycle.from_xml(lxml_etree().fromstring(lxml_etree().tostring(el)))
    assert cycle.semantics == "haas"
    with pytest.raises(ConfigError, match="'haas'"):
        DrillingExpansion().items(cycle)


def _point(x: float, y: float, z: float) -> dict[str, float]:
    return {"X": x, "Y": y, "Z": z}


@pytest.mark.parametrize("semantics, initial, moves", [
    # hand-derived from the table of postproc.cycles.semantics, the tool over X0 Y0 at the initial level, G98:
    # above R both families position at the initial level, go to R, feed to the bottom, return to the initial
    ("fanuc", 10.0, [("rapid", _point(1, 2, 10)), ("rapid", _point(1, 2, 2)), ("linear", _point(1, 2, -5)),
                     ("rapid", _point(1, 2, 10))]),
    ("rs274", 10.0, [("rapid", _point(1, 2, 10)), ("rapid", _point(1, 2, 2)), ("linear", _point(1, 2, -5)),
                     ("rapid", _point(1, 2, 10))]),
    # below R (Z1): Fanuc positions where the tool stands and returns there; RS274 rises to R first, positions
    # at R and returns to R (G98 to R when R is above the initial level)
    ("fanuc", 1.0, [("rapid", _point(1, 2, 1)), ("rapid", _point(1, 2, 2)), ("linear", _point(1, 2, -5)),
                    ("rapid", _point(1, 2, 1))]),
    ("rs274", 1.0, [("rapid", _point(0, 0, 2)), ("rapid", _point(1, 2, 2)), ("linear", _point(1, 2, -5)),
                    ("rapid", _point(1, 2, 2))]),
])
def test_the_known_rules_still_expand(semantics: str, initial: float, moves: list[tuple[str, dict[str, float]]]) -> None:
    cycle = _cycle(semantics)
    cycle.initial = initial
    cycle.start["Z"] = initial
    items = DrillingExpansion().items(cycle)
    assert [(m.mode, m.axes) for m in items] == moves  # type: ignore[attr-defined]


def test_a_mapping_environment_names_its_vacancy_rule() -> None:
    with pytest.raises(TypeError):
        MappingEnv({1: 2.0})  # type: ignore[call-arg]


def test_a_set_up_without_a_variant_is_the_dialects_own_controller() -> None:
    controller = MachineSetup().controller
    assert controller.variant is None
    assert not dwell_in_seconds(controller) and not cutter_register_from_h(controller)


def test_the_core_holds_no_controllers_cutter_rules() -> None:
    import postproc.compensation.rules as core
    from postproc.compensation.rules import CutterRules
    assert [name for name, value in vars(core).items() if isinstance(value, CutterRules)] == []
