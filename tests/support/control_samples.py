"""Round-trip samples of the control-flow sections (``postproc.interp.control``), for ``tests/test_ir_xml.py``.

Each sample is a builder and the canonical XML written by hand (the expressions inside follow
``postproc.ir.expr``'s element names).
"""

from __future__ import annotations

from typing import Any, Callable

from postproc.interp.control import (
    Assign, Break, Call, Case, Continue, Default, Do, DoWhile, Else, ElseIf, EndFor, EndIf, EndRepeat,
    EndSwitch, EndWhile, For, Goto, GotoLabel, If, IfThen, Label, ModalCall, ModalCallCancel, Repeat, Return,
    SubEnd, SubStart, Switch, Until, While,
)
from postproc.ir.expr import Binary, Num, Var

Builder = Callable[[dict[str, type]], Any]


def v(n: int) -> Var:
    return Var(Num(float(n)))


LT = Binary("lt", v(1), Num(10.0))
LT_XML = ('<Binary op="lt">\n{i}  <Var>\n{i}    <Num value="1.0"/>\n{i}  </Var>\n'
          '{i}  <Num value="10.0"/>\n{i}</Binary>')


def _cond(tag: str, indent: str = "  ") -> str:
    return f"{indent}<{tag}>\n{indent}  " + LT_XML.format(i=indent + "  ") + f"\n{indent}</{tag}>"


ASSIGN_XML = ('<Assign>\n  <Set>\n    <Var>\n      <Num value="1.0"/>\n    </Var>\n    <Num value="2.5"/>\n'
              '  </Set>\n  <Set>\n    <Var name="_depth"/>\n    <Binary op="mul">\n      <Var>\n'
              '        <Num value="1.0"/>\n      </Var>\n      <Num value="2.0"/>\n    </Binary>\n  </Set>\n'
              '</Assign>')


def _assign() -> Assign:
    return Assign([(v(1), Num(2.5)), (Var(name="_depth"), Binary("mul", v(1), Num(2.0)))])


def _labelled(cls: type, name: str) -> list[tuple[Builder, str]]:
    return [(lambda c: cls("1"), f'<{name} label="1"/>'),
            (lambda c: cls("<outer>"), f'<{name} label="&lt;outer&gt;"/>')]


def _labelled_cond(cls: type, name: str) -> list[tuple[Builder, str]]:
    return [(lambda c: cls("1", LT), f'<{name} label="1">\n' + _cond("Cond") + f"\n</{name}>")]


CONTROL_SAMPLES: dict[str, list[tuple[Builder, str]]] = {
    "Assign": [(lambda c: _assign(), ASSIGN_XML)],
    "Goto": [
        (lambda c: Goto(Num(100.0)), '<Goto>\n  <Target>\n    <Num value="100.0"/>\n  </Target>\n</Goto>'),
        (lambda c: Goto(v(3), LT), '<Goto>\n  <Target>\n    <Var>\n      <Num value="3.0"/>\n    </Var>\n'
                                   '  </Target>\n' + _cond("Cond") + "\n</Goto>"),
    ],
    "IfThen": [(lambda c: IfThen(LT, Assign([(v(2), Num(0.0))])),
                "<IfThen>\n" + _cond("Cond") + '\n  <Assign>\n    <Set>\n      <Var>\n        <Num value="2.0"/>\n'
                '      </Var>\n      <Num value="0.0"/>\n    </Set>\n  </Assign>\n</IfThen>')],
    "If": _labelled_cond(If, "If"),
    "ElseIf": _labelled_cond(ElseIf, "ElseIf"),
    "Else": _labelled(Else, "Else"),
    "EndIf": _labelled(EndIf, "EndIf"),
    "While": _labelled_cond(While, "While"),
    "EndWhile": _labelled(EndWhile, "EndWhile"),
    "Do": _labelled(Do, "Do"),
    "DoWhile": _labelled_cond(DoWhile, "DoWhile"),
    "Repeat": [(lambda c: Repeat("100", Num(3.0)),
                '<Repeat label="100">\n  <Count>\n    <Num value="3.0"/>\n  </Count>\n</Repeat>')],
    "EndRepeat": _labelled(EndRepeat, "EndRepeat"),
    "Break": _labelled(Break, "Break"),
    "Continue": _labelled(Continue, "Continue"),
    "SubStart": [(lambda c: SubStart("<probe>"), '<SubStart name="&lt;probe&gt;"/>')],
    "SubEnd": [(lambda c: SubEnd("100"), '<SubEnd name="100"/>'),
               (lambda c: SubEnd("<f>", Num(2.0)),
                '<SubEnd name="&lt;f&gt;">\n  <Value>\n    <Num value="2.0"/>\n  </Value>\n</SubEnd>')],
    "Return": [(lambda c: Return(), "<Return/>"),
               (lambda c: Return(target=Num(40.0)),
                '<Return>\n  <Target>\n    <Num value="40.0"/>\n  </Target>\n</Return>'),
               (lambda c: Return("<f>", v(1)),
                '<Return name="&lt;f&gt;">\n  <Value>\n    <Var>\n      <Num value="1.0"/>\n    </Var>\n'
                '  </Value>\n</Return>')],
    "Call": [(lambda c: Call("2000", repeat=Num(3.0)),
              '<Call kind="sub" name="2000">\n  <Repeat>\n    <Num value="3.0"/>\n  </Repeat>\n</Call>'),
             (lambda c: Call(v(10), {1: Num(5.0), 26: Num(-2.0)}, kind="macro"),
              '<Call kind="macro">\n  <Name>\n    <Var>\n      <Num value="10.0"/>\n    </Var>\n  </Name>\n'
              '  <Arg n="1">\n    <Num value="5.0"/>\n  </Arg>\n  <Arg n="26">\n    <Num value="-2.0"/>\n'
              "  </Arg>\n</Call>")],
    "ModalCall": [(lambda c: ModalCall("9010", {18: Num(2.0)}),
                   '<ModalCall name="9010">\n  <Arg n="18">\n    <Num value="2.0"/>\n  </Arg>\n</ModalCall>')],
    "ModalCallCancel": [(lambda c: ModalCallCancel(), "<ModalCallCancel/>")],
    "ProgramSyntax": [(lambda c: c["ProgramSyntax"](), "<ProgramSyntax/>")],
    "For": [(lambda c: For("3", v(510), Num(0.0), Num(8.0), Num(1.0)),
             '<For label="3">\n  <Counter>\n    <Var>\n      <Num value="510.0"/>\n    </Var>\n  </Counter>\n'
             '  <Start>\n    <Num value="0.0"/>\n  </Start>\n  <End>\n    <Num value="8.0"/>\n  </End>\n'
             '  <Step>\n    <Num value="1.0"/>\n  </Step>\n</For>')],
    "EndFor": _labelled(EndFor, "EndFor"),
    "Until": _labelled_cond(Until, "Until"),
    "Switch": [(lambda c: Switch("2", v(1), 0.001),
                '<Switch label="2" tolerance="0.001">\n  <Value>\n    <Var>\n      <Num value="1.0"/>\n'
                '    </Var>\n  </Value>\n</Switch>')],
    "Case": [(lambda c: Case("2", Num(3.0)), '<Case label="2">\n  <Value>\n    <Num value="3.0"/>\n  </Value>\n</Case>')],
    "Default": _labelled(Default, "Default"),
    "EndSwitch": _labelled(EndSwitch, "EndSwitch"),
    "GotoLabel": [(lambda c: GotoLabel("LOOP"), '<GotoLabel label="LOOP"/>'),
                  (lambda c: GotoLabel("END_1", LT), '<GotoLabel label="END_1">\n' + _cond("Cond") + "\n</GotoLabel>")],
    "Label": [(lambda c: Label("LOOP"), '<Label name="LOOP"/>')],
}
