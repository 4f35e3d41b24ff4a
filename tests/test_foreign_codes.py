"""The set-up's ``<ForeignCodes>`` (``postproc/setup/foreign_codes.py``, issue 26): what a machine-specific M code
of another controller family becomes on the target machine: left out with a comment (``omit``, only for a
code that acts on nothing), or a machine code of the target, which the target's own reader must read back as
one; ``config check`` validates the element, ``config dump`` writes it back, and ``verify`` compares a mapped
code and lists an omitted one.

Expected outputs are written by hand from the rules above (Haas M31/M33: chip auger forward/stop, action
none; M88: through-spindle coolant on, action coolant-on; the family defaults in dialects/fanuc/machine_codes.py).
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import read_program, translate
from postproc.errors import ConfigError, Diagnostics, ErrorLevel, ErrorList
from postproc.ir import MachineFunction, NativeCode
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

SOURCE = "O0001\nG90 G21 G54\nM31\nG0 X10. Y10. Z5. M33\nM30\n"
"""A Haas program: the chip auger on, a move with the auger stopped in its block."""


def _setup(tmp_path: Path, mapping: str, codes: str = "", variant: str = "haas") -> MachineSetup:
    path = tmp_path / "machine.xml"
    path.write_text(f'<MachineSetup name="t" dialect="fanuc"><Controller variant="{variant}"/>'
                    f"{codes}<ForeignCodes>{mapping}</ForeignCodes></MachineSetup>")
    return load_setup(path)


OMIT_BOTH = '<M family="fanuc" number="31" to="omit"/><M family="fanuc" number="33" to="omit"/>'
TO_M133 = '<M family="fanuc" number="31" to="omit"/><M family="fanuc" number="33" to="M133"/>'


def _translate(target: str, setup: MachineSetup, text: str = SOURCE, mode: str = "error") -> list[str]:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source="fanuc", target=target, setup=setup,
              on_unsupported=mode, diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue().splitlines()


def _errors(target: str, setup: MachineSetup, text: str = SOURCE) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(target, setup, text)
    return [str(e) for e in caught.value.errors]


# -- the set-up ------------------------------------------------------------------------------------

CANONICAL = """<?xml version='1.0' encoding='UTF-8'?>
<MachineSetup name="t" dialect="fanuc">
  <Controller variant="haas"/>
  <MachineCodes>
    <M number="133" name="conveyor stop"/>
  </MachineCodes>
  <ForeignCodes>
    <M family="fanuc" number="31" to="omit"/>
    <M family="fanuc" number="33" to="M133"/>
  </ForeignCodes>
</MachineSetup>
"""


def test_config_dump_writes_a_canonical_set_up_back_byte_for_byte(tmp_path: Path) -> None:
    path = tmp_path / "m.xml"
    path.write_text(CANONICAL)
    setup = load_setup(path)
    assert [(c.family, c.number, c.to) for c in setup.foreign_codes] == [("fanuc", "31", "omit"),
                                                                          ("fanuc", "33", "M133")]
    from lxml import etree
    dumped = etree.tostring(setup.make_xml_source(), pretty_print=True, xml_declaration=True, encoding="UTF-8")
    assert dumped.decode() == CANONICAL


def test_a_set_up_that_extends_another_dumps_only_its_own_mappings(tmp_path: Path) -> None:
    (tmp_path / "base.xml").write_text('<MachineSetup name="b"><ForeignCodes><M family="fanuc" number="31" '
                                       'to="omit"/></ForeignCodes></MachineSetup>')
    (tmp_path / "m.xml").write_text('<MachineSetup name="m" extends="base.xml"><ForeignCodes><M family="fanuc" '
                                    'number="33" to="M133"/></ForeignCodes></MachineSetup>')
    setup = load_setup(tmp_path / "m.xml")
    assert sorted(c.key() for c in setup.foreign_codes) == [("fanuc", "M31"), ("fanuc", "M33")]
    from lxml import etree
    own = etree.tostring(setup.make_xml_source()).decode()
    assert '<ForeignCodes><M family="fanuc" number="33" to="M133"/></ForeignCodes>' in own and 'number="31"' not in own


@pytest.mark.parametrize("body, message", [
    ('<ForeignCodes a="1"/>', "<ForeignCodes> takes no attributes, only <M> elements"),
    ('<ForeignCodes><G family="fanuc" number="187" to="omit"/></ForeignCodes>', "unknown element <G> in <ForeignCodes>"),
    ('<ForeignCodes><M family="fanuc" number="31" to="drop"/></ForeignCodes>', "<M> to:"),
    ('<ForeignCodes><M family="fanuc" number="31.5" to="omit"/></ForeignCodes>', "<M> number:"),
    ('<ForeignCodes><M number="31" to="omit"/></ForeignCodes>', "<M> family:"),
    ('<ForeignCodes><M family="fanuc" number="31" to="omit"/><M family="fanuc" number="031" to="M1"/></ForeignCodes>',
     "fanuc M31 is declared twice"),
])
def test_config_check_refuses_a_bad_declaration_at_its_line(body: str, message: str, tmp_path: Path) -> None:
    path = tmp_path / "m.xml"
    path.write_text(f'<MachineSetup name="t">\n{body}\n</MachineSetup>')
    with pytest.raises((ConfigError, ErrorList)) as caught:
        load_setup(path)
    assert message in str(caught.value) and ":2:" in str(caught.value), str(caught.value)


def test_config_check_refuses_a_family_no_installed_dialect_has_and_dump_writes_it_back(cli, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    path = tmp_path / "m.xml"
    path.write_text(CANONICAL.replace('family="fanuc" number="33"', 'family="fanucc" number="33"'))
    result = cli("config", "check", path)
    assert result.status == 1
    assert result.err_lines == [f"{path}:9:1: error: <ForeignCodes> family 'fanucc' is no installed dialect's family "
                                "(the families: fagor, fanuc, grbl, grblhal, gsk, isg, linuxcnc, mach3, siemens)"]
    path.write_text(CANONICAL)
    assert cli("config", "check", path).status == 0
    assert cli("config", "dump", path).out.decode() == CANONICAL


# -- translating ----------------------------------------------------------------------------------

@pytest.mark.parametrize("target, comment, move", [
    ("siemens", ";M31 omitted: chip auger forward of the fanuc family, left out by the set-up (ForeignCodes)",
     "G0 X10. Y10. Z5."),
    ("isg", "(M31 omitted: chip auger forward of the fanuc family, left out by the set-up [ForeignCodes])",
     "G00 X10. Y10. Z5."),
    ("grbl", "(M31 omitted: chip auger forward of the fanuc family, left out by the set-up [ForeignCodes])",
     "G0 X10. Y10. Z5."),
])
def test_an_omitted_code_is_a_comment_and_the_rest_of_its_block_is_kept(target: str, comment: str, move: str,
                                                                         tmp_path: Path) -> None:
    lines = _translate(target, _setup(tmp_path, OMIT_BOTH))
    assert comment in lines, lines
    assert [line for line in lines if line.startswith(move)] == [move + " " + _comment(target, "M33", "chip auger stop")]


def _comment(target: str, code: str, name: str) -> str:
    text = f"{code} omitted: {name} of the fanuc family, left out by the set-up "
    return f";{text}(ForeignCodes)" if target == "siemens" else f"({text}[ForeignCodes])"


@pytest.mark.parametrize("target", ["siemens", "isg", "fagor"])
def test_a_mapped_code_is_written_as_the_target_code(target: str, tmp_path: Path) -> None:
    lines = _translate(target, _setup(tmp_path, TO_M133))
    assert [line for line in lines if "M133" in line] == [("G0" if target == "siemens" else "G00") + " X10. Y10. Z5. M133"]


def test_a_code_written_with_a_leading_zero_is_the_same_code(tmp_path: Path) -> None:
    lines = _translate("siemens", _setup(tmp_path, TO_M133), SOURCE.replace("M33", "M033"))
    assert "G0 X10. Y10. Z5. M133" in lines, lines


def test_towards_linuxcnc_a_user_m_code_the_set_up_declares_is_read_and_simulated(tmp_path: Path) -> None:
    setup = _setup(tmp_path, TO_M133, '<MachineCodes><M number="133" name="conveyor stop"/></MachineCodes>')
    lines = _translate("linuxcnc", setup)
    assert "G0 X10. Y10. Z5. M133" in lines, lines
    block = read_program(["M133\n"], file="o.ngc", dialect="linuxcnc", setup=setup)[0]
    assert block.get("MachineFunction") == MachineFunction("linuxcnc", "M133", "M133", name="conveyor stop")
    undeclared = read_program(["M133\n"], file="o.ngc", dialect="linuxcnc")[0]
    assert undeclared.get("NativeCode") == NativeCode("linuxcnc", "M133 (user M code)", "M133")


@pytest.mark.parametrize("target, to, why", [
    ("grbl", "M133", "grbl does not read it: unknown M code M133"),
    ("mach3", "M77", "mach3 does not read it: unknown M code M77"),
])
def test_a_code_the_target_does_not_read_is_refused_at_the_source_code(target: str, to: str, why: str,
                                                                         tmp_path: Path) -> None:
    assert _errors(target, _setup(tmp_path, TO_M133.replace("M133", to))) == [
        f"in.nc:4:18: error: M33 (chip auger stop) of the fanuc family: the set-up's <ForeignCodes> makes it {to} on "
        f"{target}, but {why}"]


def test_towards_mach3_a_user_macro_the_set_up_declares_is_read_and_simulated(tmp_path: Path) -> None:
    """Mach3 runs a macro file for an M code it has no built-in for (M133.m1s, the integrator's): M100-M999 are
    read and written verbatim, and a declared one is the machine's function, as LinuxCNC's user M codes are."""
    setup = _setup(tmp_path, TO_M133, '<MachineCodes><M number="133" name="conveyor stop"/></MachineCodes>')
    lines = _translate("mach3", setup)
    assert "G0 X10.0000 Y10.0000 Z5.0000 M133" in lines, lines  # (Mach3's axis words are fixed-width)
    block = read_program(["M133\n"], file="o.tap", dialect="mach3", setup=setup)[0]
    assert block.get("MachineFunction") == MachineFunction("mach3", "M133", "M133", name="conveyor stop")
    undeclared = read_program(["M133\n"], file="o.tap", dialect="mach3")[0]
    assert undeclared.get("NativeCode") == NativeCode("mach3", "M133 (user M code)", "M133")


def test_a_code_the_target_reads_as_one_of_its_own_functions_is_refused(tmp_path: Path) -> None:
    """SINUMERIK's M3 is the spindle, not a machine function: mapped to it, the auger would start the spindle."""
    setup = _setup(tmp_path, '<M family="fanuc" number="31" to="M3"/><M family="fanuc" number="33" to="omit"/>')
    assert _errors("siemens", setup) == [
        "in.nc:3:1: error: M31 (chip auger forward) of the fanuc family: the set-up's <ForeignCodes> makes it M3 on "
        "siemens, but siemens reads it as SpindleControl, not as a machine-specific code of its own"]


def test_a_code_that_acts_on_the_machine_cannot_be_omitted(tmp_path: Path) -> None:
    """M88 switches the through-spindle coolant on (its action coolant-on): left out, the coolant would differ."""
    setup = _setup(tmp_path, '<M family="fanuc" number="88" to="omit"/>', variant="fanuc")
    assert _errors("isg", setup, "G90 G21\nG0 X1. M88\nM30\n") == [
        "in.nc:2:8: error: M88 (through-spindle coolant on) of the fanuc family: the set-up's <ForeignCodes> makes "
        "it omit on isg, but it acts on the machine (coolant-on): only a code that moves nothing and changes no "
        "spindle, coolant, feed or tool data may be omitted"]


def test_a_code_with_words_is_not_mapped_to_a_bare_code(tmp_path: Path) -> None:
    """An undeclared M code keeps its P (the ISO rule): a bare target code would lose it."""
    setup = _setup(tmp_path, '<M family="fanuc" number="77" to="M177"/>', variant="fanuc")
    assert _errors("siemens", setup, "G90 G21\nM77 P3\nM30\n") == [
        "in.nc:2:1: error: M77 of the fanuc family: the set-up's <ForeignCodes> makes it M177 on siemens, but it "
        "carries words (M77 P3) a code of siemens would not take over"]


def test_without_a_declaration_the_refusal_names_the_element(tmp_path: Path) -> None:
    setup = _setup(tmp_path, '<M family="fanuc" number="33" to="omit"/>')
    assert _errors("siemens", setup) == [
        "in.nc:3:1: error: M31 (chip auger forward), a machine-specific code of the fanuc family, has no equivalent "
        "in siemens (the target machine's set-up can say what it becomes there: <ForeignCodes><M family=\"fanuc\" "
        "number=\"31\" to=\"..\"/></ForeignCodes>, to=\"omit\" leaves it out with a comment, or to= a machine code "
        "of the target)"]


def test_within_the_family_a_mapping_does_not_apply(tmp_path: Path) -> None:
    """Fanuc to Fanuc: the code passes as written (the mapping is for another family's machine)."""
    lines = _translate("fanuc", _setup(tmp_path, OMIT_BOTH))
    assert "M31" in lines and "G0 X10. Y10. Z5. M33" in lines, lines


# -- verify -----------------------------------------------------------------------------------------

def _verify(out: list[str], setup: MachineSetup, target: str = "siemens") -> object:
    return verify_lines(io.StringIO(SOURCE), io.StringIO("\n".join(out) + "\n"), file_in="in.nc", file_out="out",
                        source="fanuc", target=target, setup=setup)


def test_verify_compares_a_mapped_code_and_lists_an_omitted_one(tmp_path: Path) -> None:
    setup = _setup(tmp_path, TO_M133)
    report = _verify(_translate("siemens", setup), setup)
    assert report.ok, report.summary()  # type: ignore[attr-defined]
    assert report.ignored == ["M31 (chip auger forward), a machine-specific code omitted by the set-up "  # type: ignore[attr-defined]
                              "(<ForeignCodes>): IN 1x from line 3, OUT none",
                              # the SINUMERIK's power-on G60 where Fanuc blends (tests/test_defects_siemens_path_start.py)
                              "path control: the siemens controller starts in exact stop (line 4) where the source's "
                              "blends, until the program sets a blending mode: every programmed point is reached"]
    assert "M33 (chip auger stop) became M133 by the set-up (<ForeignCodes>): compared, IN 1x from line 4" in \
        report.notes  # type: ignore[attr-defined]


@pytest.mark.parametrize("edit", [lambda line: line.replace(" M133", ""), lambda line: line.replace("M133", "M134")])
def test_verify_fails_where_the_mapped_code_is_missing_or_another(edit: object, tmp_path: Path) -> None:
    setup = _setup(tmp_path, TO_M133)
    out = [edit(line) for line in _translate("siemens", setup)]  # type: ignore[operator]
    report = _verify(out, setup)
    assert not report.ok  # type: ignore[attr-defined]
    assert report.mismatch.startswith("the machine codes the set-up's <ForeignCodes> maps differ: IN's become "  # type: ignore[attr-defined]
                                      "M133, OUT has ")
    assert report.mismatch_at[0] == 4  # type: ignore[attr-defined]


def test_the_toolpath_of_a_mapped_code_carries_it(tmp_path: Path) -> None:
    setup = _setup(tmp_path, TO_M133)
    events = list(toolpath_events(io.StringIO("\n".join(_translate("siemens", setup)) + "\n"), file="o.mpf",
                                  dialect="siemens", setup=setup,
                                  diagnostics=Diagnostics(warn_stream=io.StringIO())))
    assert [e["code"] for e in events if "code" in e] == ["M133"]
