"""The offset registers a program reads (H for tool length, D for cutter radius): what the program itself
wrote (a programmable data input of the neutral tables ``tool_length``, ``tool_length_wear``,
``cutter_offset``, ``cutter_offset_wear``), else the set-up's ``<Tools><Tool>``. Geometry written by the
program replaces the set-up's, wear written replaces the set-up's wear; the wear is added to the
geometry. A register the set-up declares shared by H and D (Fanuc memory A/B, ``<Tool offset>``) is one
value: a write of its length is its radius too. A register with neither is unknown: the simulation
refuses to guess it, and the error names the element that would give it. Translation reads
them too, where a target without a tool table needs the values written (``postproc.grbl_family.lengths``)."""

from __future__ import annotations

from ..errors import ProgramError
from ..ir import DataSetting
from ..setup.machine_setup import MachineSetup

TABLES = {"tool_length": ("length", False), "tool_length_wear": ("length", True),
          "cutter_offset": ("radius", False), "cutter_offset_wear": ("radius", True)}
"""Neutral table name -> (the register's quantity, whether it is the wear)."""
ENTRY = "tool_entry"
"""A whole entry of a tool table by tool number (LinuxCNC's): ``Z`` the length, ``R`` the radius, ``X`` and
``Y`` the offsets a mill's length offset applies along X and Y."""
SIDEWAYS = ("X", "Y")
"""The entry's offsets across the spindle axis (``ToolTable.sideways``)."""
LATHE_TABLES = {"lathe_offset": False, "lathe_offset_wear": True}
"""A lathe tool offset's geometry or wear (a family base reads the program's form, as ``postproc.rs274.
lathe_offset_input`` Fanuc T's ``G10 P X Z R Q``) -> whether it is the wear. Its values are keyed by meaning
(``LATHE_VALUES``, ``LATHE_TIP``), not by a family's letters."""
LATHE_VALUES = (("x", "x_increment"), ("z", "z_increment"), ("radius", "radius_increment"))
"""A lathe offset setting's value keys: (the key that sets the quantity, the key that adds to it), the quantity
the first (X as the set-up's ``<Tool x>`` reads it, Z, the tool nose radius), in program units."""
LATHE_TIP = "tip"
"""A lathe offset setting's value key that sets the offset's imaginary tool nose direction (``ToolTable.tip``)."""


class ToolTable:
    """Tool lengths and cutter radii by register, in mm."""

    def __init__(self, setup: MachineSetup) -> None:
        self.tools = setup.tools
        self.touched_off = setup.machine.tool_lengths == "touched_off"
        """Every tool is touched off at its change (``<Machine toolLengths>``): every length reads zero."""
        self.mm = setup.machine.mm()
        """mm per set-up length unit (``<Machine units>``)."""
        self.written: dict[tuple[str, int], float] = {}
        self.wear: dict[tuple[str, int], float] = {}
        self.across: dict[int, dict[str, float]] = {}
        """X and Y offsets a program wrote into an entry (mm), by tool number."""
        self.tips: dict[int, int] = {}
        """Imaginary tool nose directions a program wrote (``G10 P.. Q..``), by offset register."""

    def write(self, setting: DataSetting, scale: float) -> bool:
        """A programmable data input into a tool table (values in program units, ``scale`` mm per unit);
        False when the setting is not a tool table's."""
        if setting.table == ENTRY:
            self._entry(setting, scale)
            return True
        if setting.table in LATHE_TABLES:
            self._lathe_offset(setting, scale)
            return True
        table = TABLES.get(setting.table)
        if table is None:
            return False
        quantity, wear = table
        value = setting.values.get("R")
        if not isinstance(value, (int, float)):
            return True  # no R: nothing written (an Expr never reaches the simulator)
        tool = self.tools.get(str(setting.index))
        if tool is not None and tool.by_diameter() and "radius" in self._sharing(quantity, setting.index):
            raise ProgramError(f"register {setting.index} is given by its diameter in the set-up (<Tool diameter>): "
                               "whether this write's R is a diameter or a radius (Haas setting 40) is not "
                               "confirmed [?]")
        if wear and tool is not None and tool.shared() and tool.offset_wear is None:
            wear = False  # memory A has no wear: G10 L11 writes the one value [K] (see ToolData)
        key = (quantity, setting.index)
        store = self.wear if wear else self.written
        if setting.incremental:
            known = store.get(key)
            if known is None:
                known = self._declared_wear(quantity, setting.index) if wear else self._declared(quantity,
                                                                                                setting.index)
            new = (known or 0.0) + value * scale
        else:
            new = value * scale
        for other in self._sharing(quantity, setting.index):
            store[(other, setting.index)] = new
        return True

    def _entry(self, setting: DataSetting, scale: float) -> None:
        """A whole tool table entry (LinuxCNC ``G10 L1``): Z its length, R its radius, each absolute; a word
        left out keeps the entry's value."""
        for letter, quantity in (("Z", "length"), ("R", "radius")):
            value = setting.values.get(letter)
            if isinstance(value, (int, float)):
                self.set(quantity, setting.index, value * scale)
        for axis in SIDEWAYS:
            value = setting.values.get(axis)
            if isinstance(value, (int, float)):
                self.across.setdefault(setting.index, {})[axis] = value * scale

    def _lathe_offset(self, setting: DataSetting, scale: float) -> None:
        """A lathe offset's geometry or wear written by the program (see ``LATHE_TABLES``); X as the set-up's
        ``<Tool x>`` reads (a diameter on a diameter lathe), mm."""
        wear = LATHE_TABLES[setting.table]
        register = setting.index
        store = self.wear if wear else self.written
        for quantity, increment in LATHE_VALUES:
            key = (quantity, register)
            value = setting.values.get(quantity)
            if isinstance(value, (int, float)):
                store[key] = value * scale
            step = setting.values.get(increment)
            if isinstance(step, (int, float)):
                known = store.get(key)
                if known is None:
                    known = self._declared_wear(quantity, register) if wear else self._declared(quantity, register)
                store[key] = (known or 0.0) + step * scale
        tip = setting.values.get(LATHE_TIP)
        if isinstance(tip, (int, float)):
            self.tips[register] = int(tip)

    def sideways(self, register: int) -> dict[str, float]:
        """The X and Y offsets of entry ``register`` that are not zero (mm): a mill's tool length offset
        applies them too ([V] LinuxCNC, ``postproc_linuxcnc.tool_entry``); none but what a program wrote."""
        return {axis: value for axis, value in self.across.get(register, {}).items() if value}

    def set_sideways(self, register: int, axis: str, value: float) -> None:
        """Write entry ``register``'s offset along ``axis`` (X or Y), mm, as the program's own."""
        self.across.setdefault(register, {})[axis] = value

    def set(self, quantity: str, register: int, value: float) -> None:
        """Write register ``register``'s ``quantity`` ("length" or "radius"), mm, as the program's own."""
        for other in self._sharing(quantity, register):
            self.written[(other, register)] = value

    def _sharing(self, quantity: str, register: int) -> tuple[str, ...]:
        """The quantities a write of ``quantity`` sets: both where the register is one value for H and D."""
        tool = self.tools.get(str(register))
        return ("length", "radius") if tool is not None and tool.shared() else (quantity,)

    def length(self, register: int) -> float:
        """The tool length in register ``register`` (mm), or a ProgramError naming what to add; zero on a
        machine whose tools are touched off."""
        if self.touched_off:
            return 0.0
        return self._value("length", register)

    def radius(self, register: int) -> float:
        """The cutter radius in register ``register`` (mm), or a ProgramError naming what to add."""
        return self._value("radius", register)

    def tip(self, register: int) -> int:
        """The imaginary tool nose direction of lathe offset ``register`` (``<Tool tip>``, Fanuc's numbers;
        0, the nose centre, when not given)."""
        written = self.tips.get(register)
        if written is not None:
            return written
        tool = self.tools.get(str(register))
        return 0 if tool is None or tool.tip is None else tool.tip

    def _value(self, quantity: str, register: int) -> float:
        if register == 0:
            return 0.0  # [V] Fanuc's D0 "always means 0" (B-63324EN/03, 15i-MA, 14.3 text, cncmanuals.com .../403);
            # [K] H00 too; [?] LinuxCNC's tool 0 is "no tool"
        key = (quantity, register)
        value = self.written.get(key)
        if value is None:
            value = self._declared(quantity, register)
        if value is None:
            raise ProgramError(f"the set-up gives tool {quantity} register {register} no value: add "
                               f"<Tool number=\"{register}\" {quantity}=\"..\"/> to its <Tools>, or write the "
                               f"register in the program")
        wear = self.wear.get(key)
        return value + (wear if wear is not None else self._declared_wear(quantity, register))

    def _declared(self, quantity: str, register: int) -> float | None:
        tool = self.tools.get(str(register))
        value = None if tool is None else tool.geometry(quantity)
        return None if value is None else float(value) * self.mm

    def _declared_wear(self, quantity: str, register: int) -> float:
        tool = self.tools.get(str(register))
        return 0.0 if tool is None else float(tool.wear(quantity)) * self.mm

    def lathe(self, register: int, diameter: bool) -> tuple[float, float] | None:
        """Lathe offset register ``register`` (``T0102``'s 2, LinuxCNC's lathe ``G43 H2``) as (X, Z) in mm,
        X a radius (the set-up's x is a diameter where ``diameter``); None when the set-up declares no
        lathe offsets for it (the selection is then compared, not applied: ``Moves.lathe_offset``).
        Register 0 is no offset."""
        if register == 0:
            return 0.0, 0.0
        x = self._lathe_axis("x", register)
        z = self._lathe_axis("z", register)
        if x is None or z is None:
            return None
        return x * (0.5 if diameter else 1.0), z

    def _lathe_axis(self, quantity: str, register: int) -> float | None:
        """Lathe offset ``register``'s X or Z (``quantity`` "x" or "z"), geometry plus wear, mm: what the program
        wrote (``G10 P``), else the set-up's ``<Tool x z xWear zWear>``; None when neither gives the geometry."""
        key = (quantity, register)
        tool = self.tools.get(str(register))
        geometry = self.written.get(key)
        if geometry is None:
            declared = None if tool is None or tool.x is None else tool.x if quantity == "x" else tool.z
            if declared is None:
                return None
            geometry = float(declared) * self.mm
        wear = self.wear.get(key)
        if wear is None:
            declared_wear = None if tool is None else tool.x_wear if quantity == "x" else tool.z_wear
            wear = 0.0 if declared_wear is None else float(declared_wear) * self.mm
        return geometry + wear
