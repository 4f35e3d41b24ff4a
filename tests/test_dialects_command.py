"""``postproc dialects``: the table and the JSON both come from the dialect classes' declared flags."""

from __future__ import annotations

import json
from typing import ClassVar

from postproc.dialect import Dialect
from postproc.commands.dialect_table import dialect_info, render_table
from postproc.plugins import default_registry

REGISTRY = default_registry()


def _rows(text: str) -> dict[str, list[str]]:
    """The matrix of the table: row label -> cells (split on runs of two or more spaces)."""
    import re
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("capability "))
    rows: dict[str, list[str]] = {}
    for line in lines[start:]:
        if not line.strip():
            break
        label, *cells = re.split(r"\s{2,}", line.strip())
        rows[label] = cells
    return rows


def test_the_table_has_a_column_per_dialect_and_a_row_per_capability(cli):
    result = cli("dialects")
    assert result.status == 0, result.err
    rows = _rows(result.out.decode())
    names = sorted(REGISTRY.dialects)
    assert rows["capability"] == names
    for i, name in enumerate(names):
        cls = REGISTRY.dialect(name)
        assert rows["read"][i] == ("yes" if cls.READER else "no")
        assert rows["write"][i] == ("yes" if cls.WRITER else "no")
        for key, value in cls.capabilities().items():
            cell = rows[key][i]
            if isinstance(value, bool):
                assert cell == ("yes" if value else "no"), (name, key)
            elif isinstance(value, list) and len(",".join(value)) > 16:
                assert cell == f"{len(value)} (below)", (name, key)
                assert f"  {name} {key}: {', '.join(value)}" in result.out.decode()
            elif isinstance(value, list):
                assert cell == (",".join(value) or "-"), (name, key)


def test_known_flags_read_as_the_controllers_are():
    """Hand-checked against the dialects: grbl has no tool changer and no variables; Fanuc has both."""
    rows = _rows(render_table(dialect_info(REGISTRY.dialects)))
    col = {name: i for i, name in enumerate(rows["capability"])}
    assert rows["TOOL_CHANGER"][col["grbl"]] == "no"
    assert rows["PROGRAMS"][col["grbl"]] == "no"
    assert rows["PROGRAMS"][col["fanuc"]] == "yes"
    assert rows["MACHINE_TYPES"][col["gsk"]] == "lathe"
    assert rows["read"][col["mach3"]] == "yes"


def test_json_is_the_classes_capability_tables(cli):
    result = cli("dialects", "--format", "json")
    assert result.status == 0, result.err
    data = json.loads(result.out)
    assert sorted(data) == sorted(REGISTRY.dialects)
    for name, entry in data.items():
        cls = REGISTRY.dialect(name)
        assert entry == {"description": cls.DESCRIPTION, "reads": cls.READER is not None,
                         "writes": cls.WRITER is not None, "capabilities": json.loads(json.dumps(cls.capabilities()))}
    assert cli("dialects", "--json").out == result.out  # the older spelling still works


def test_a_flag_a_plugin_declares_appears_by_itself():
    class Probe(Dialect):
        NAME = "probe"
        DESCRIPTION = "a probe"
        PALLET_CHANGER: ClassVar[bool] = True
        """Not a real flag: it shows the table reads whatever the class declares."""

    rows = _rows(render_table(dialect_info({"probe": Probe, "fanuc": REGISTRY.dialect("fanuc")})))
    assert rows["capability"] == ["fanuc", "probe"]
    assert rows["PALLET_CHANGER"] == ["-", "yes"]


def test_a_wrong_format_is_usage(cli):
    assert cli("dialects", "--format", "xml").status == 2


def test_the_core_declares_no_family_and_each_dialect_shows_its_own():
    """The base class names no family; the rows come from each dialect's own declarations (hand-checked:
    Fanuc and Fagor run Fanuc's cycle rules, LinuxCNC, Mach3 and grblHAL RS274/NGC's, grbl, GSK, ISG and SINUMERIK
    (no native cycles written) none; the
    two lathe dialects read U/W as incremental X/Z)."""
    assert (Dialect.CYCLE_SEMANTICS, dict(Dialect.INCREMENTAL_AXES)) == ("", {})
    rows = _rows(render_table(dialect_info(REGISTRY.dialects)))
    shown = {name: (rows["CYCLE_SEMANTICS"][i], rows["INCREMENTAL_AXES"][i])
             for i, name in enumerate(rows["capability"])}
    assert shown == {"fagor": ("fanuc", "-"), "fanuc": ("fanuc", "U=X,W=Z"), "grbl": ("-", "-"), "grblhal": ("rs274", "-"),
                     "gsk": ("-", "U=X,W=Z"), "isg": ("-", "-"), "linuxcnc": ("rs274", "-"),
                     "mach3": ("rs274", "-"), "siemens": ("fanuc", "-")}
