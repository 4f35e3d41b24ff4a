"""The machine's geometry in a set-up: axis travel and home (``<Axes>``), work offsets (``<WorkOffsets>``)
and tool offsets (``<Tools>``), in the set-up's machine units (``<Machine units>``).

Kept apart from ``postproc.setup.machine_setup`` (the controller's parameters) because only the travel check
(``postproc.simulate.travel``) reads them: they say where the program's points are on the machine.
Each entry is keyed (axis letter, work-system number, tool number), so a set-up that ``extends`` another
overrides one entry, or one attribute of one entry, without repeating the rest.

The annotations are evaluated where the module loads (no ``from __future__ import annotations``): the set-up lane
reads the field types of each entry class a set-up file fills (``typing.get_type_hints``,
``postproc.fast.setup_values``), and as text each type was compiled there (``typing.ForwardRef``), the run's
first compile also building the interpreter's syntax-tree types: ~12M instructions of a ``--machine`` run whose
set-up gives tools or axes (callgrind). Evaluated here, in byte code, they cost the import nothing more
(``import postproc.setup.machine``: 3.2M instructions; 3.7M with the annotations as text).
"""

from typing import Any, ClassVar, Literal

from ..records import record
from .record import MAX_COORDINATE, ROTARY_AXES as ROTARY_AXES, pydantic_config, setting, values

__all__ = ["MAX_COORDINATE", "AxisTravel", "WorkOffsetData", "ToolData", "CONTAINERS", "entry_values"]

AXIS_LETTERS = "XYZABCUVW"


def coordinate(alias: str | None = None) -> Any:
    """An optional length or angle (absent: unknown), bounded by ``MAX_COORDINATE``."""
    return setting(None, ge=-MAX_COORDINATE, le=MAX_COORDINATE, alias=alias)


@record(frozen=True)
class Entry:
    """One keyed entry, stored as the attributes of one element (a plain record: see
    ``postproc.setup.record``). The entries are records (``postproc.records``), not ``@dataclass(frozen=True)``:
    every run imports this module, and the four classes' generated methods cost ~22M instructions of its
    start-up (cachegrind, ``import postproc.setup.machine`` after the command line)."""

    __pydantic_config__: ClassVar[dict[str, Any]] = pydantic_config(None)
    TAG: ClassVar[str] = ""
    KEY: ClassVar[str] = ""
    """The attribute naming the entry (an ``extends`` child overrides the entry with the same key)."""

    def key(self) -> str:
        return str(getattr(self, self.KEY))


@record(frozen=True)
class AxisTravel(Entry):
    """``<Axis name="X" min="-762.0" max="0.0" home="0.0"/>``: the axis's travel in machine coordinates
    and its reference (home) position, where G28 goes."""

    TAG = "Axis"
    KEY = "name"
    name: Literal["X", "Y", "Z", "A", "B", "C", "U", "V", "W"]
    minimum: float | None = coordinate(alias="min")
    maximum: float | None = coordinate(alias="max")
    """Travel limits (machine coordinates). A rotary axis without them turns without limit."""
    home: float | None = coordinate()
    """The reference position (machine coordinates); unknown when absent (a G28 on a checked axis is
    then an error rather than a guess)."""
    rapid: float | None = setting(None, gt=0, le=1_000_000)
    """The axis's rapid traverse rate (set-up units, or degrees, per minute), for ``postproc info``'s run
    time; unknown when absent."""

    def __post_init__(self) -> None:
        if self.minimum is not None and self.maximum is not None and self.minimum >= self.maximum:
            raise ValueError(f"axis {self.name}: min {self.minimum:g} is not below max {self.maximum:g}")
        if self.home is not None and not self.within(self.home):
            raise ValueError(f"axis {self.name}: home {self.home:g} is outside the travel")

    def within(self, value: float) -> bool:
        return ((self.minimum is None or value >= self.minimum)
                and (self.maximum is None or value <= self.maximum))

    def limited(self) -> bool:
        return self.minimum is not None or self.maximum is not None


@record(frozen=True)
class WorkOffsetData(Entry):
    """``<Offset number="1" x="-400.0" y="-250.0" z="-500.0"/>``: where a work system's zero is in machine
    coordinates, as the operator set it (1 = G54 ... 6 = G59; 0 = the external offset added to all)."""

    TAG = "Offset"
    KEY = "number"
    number: int = setting(ge=0, le=6)
    x: float | None = coordinate()
    y: float | None = coordinate()
    z: float | None = coordinate()
    a: float | None = coordinate()
    b: float | None = coordinate()
    c: float | None = coordinate()
    u: float | None = coordinate()
    v: float | None = coordinate()
    w: float | None = coordinate()

    def axes(self) -> dict[str, float]:
        """Axis letter -> offset, for the axes the entry gives (an absent axis is unknown, not zero)."""
        return {a: v for a in AXIS_LETTERS if (v := getattr(self, a.lower())) is not None}


@record(frozen=True)
class ToolData(Entry):
    """``<Tool number="1" length="152.4" radius="5.0"/>`` (a mill's length register H1 and radius register
    D1) or ``<Tool number="1" x="-2.5" z="-1.2"/>`` (a lathe's offset 01 of ``T0101``): what the controller adds to the programmed
    point while the offset is in force.

    Fanuc's tool compensation memories [K: Fanuc Series 0i Model B connection manual (function)
    B-63833EN-1/02, 10.2 "Tool compensation memory"]: memory A holds one value per offset number, read as
    the length by ``H n`` and as the radius by ``D n`` (``offset``); memory B adds a wear value to it, still
    shared (``offsetWear``); memory C keeps separate geometry and wear for H and for D (``length``,
    ``lengthWear``, ``radius``, ``radiusWear``, as LinuxCNC's and Haas's tables do). One entry is of one
    kind: a shared value beside a separate one is an error. An entry with ``offset`` and no ``offsetWear``
    is memory A's: a program's wear write (``G10 L11``) sets its one value [K: the same manual, G10 for
    memory A]."""

    TAG = "Tool"
    KEY = "number"
    number: int = setting(ge=0, le=9999)
    name: str | None = setting(None, pattern=r'^[^"\x00-\x1f]{1,32}$')
    """The tool's name, which SINUMERIK selects it by (``T="DRILL_8"``) [K: 840D sl Fundamentals, "Tool change
    with T": tool management addresses a tool by its name; [?] the 32-character bound]. None: no name."""
    pocket: int | None = setting(None, ge=0, le=1000)
    """The tool changer's pocket holding the tool (a LinuxCNC tool table's ``P``) [K: LinuxCNC docs, "Tool
    Compensation", 2.1 "Tool Table Format": "The maximum pocket number is 1000"; 0 is the spindle of a random
    tool changer]. The program names a tool by its number (``T``), never by its pocket: the pocket is the
    machine's, written into the tool table a LinuxCNC machine or rs274 reads (``postproc.setup.tool_table_file``).
    None: not given (a table written for LinuxCNC puts the tool in the pocket of its number)."""
    comment: str | None = setting(None, pattern=r"^[^\x00-\x1f]{1,250}$")
    """What the tool is, as a LinuxCNC tool table's remark after ``;`` says it (kept through an import, a
    ``config dump`` and the table written back). None: no remark."""
    length: float | None = coordinate()
    """G43/G44 tool length: G43 adds it to Z, G44 subtracts it."""
    radius: float | None = coordinate()
    """Cutter radius G41/G42 offsets the path by (register D n; a negative radius puts the cutter on the
    other side, as Fanuc and LinuxCNC do). A LinuxCNC tool table gives diameters: halve them."""
    length_wear: float | None = coordinate(alias="lengthWear")
    radius_wear: float | None = coordinate(alias="radiusWear")
    """Wear added to the length and to the radius (Fanuc memory C's wear columns)."""
    diameter: float | None = coordinate()
    diameter_wear: float | None = coordinate(alias="diameterWear")
    """Haas's cutter compensation columns when they hold diameters (its setting 40, Tool Offset Measure:
    Diameter; the offsets page's DIA GEOMETRY and DIA WEAR) [K: Haas mill operator's manual]: ``D n``
    offsets the path by half of them. Instead of ``radius``/``radiusWear``, never beside them."""
    offset: float | None = coordinate()
    offset_wear: float | None = coordinate(alias="offsetWear")
    """Fanuc memory A/B: the one value of offset n (and its wear), the length of ``H n`` and the radius of
    ``D n`` alike."""
    x: float | None = coordinate()
    z: float | None = coordinate()
    """Lathe geometry offsets, added to X (as the set-up's X: diameter on a diameter lathe) and Z."""
    tip: int | None = setting(None, ge=0, le=9)
    """Lathe: the imaginary tool nose direction of the offset (Fanuc's T column, 0-9), whose nose radius is
    ``radius``: G41/G42 run the nose centre one radius beside the path and the imaginary tip (the point
    the offsets measure) is that centre moved by the radius in this direction
    (``postproc.compensation.nose``). Absent: 0, the nose centre is the point."""
    x_wear: float | None = coordinate(alias="xWear")
    z_wear: float | None = coordinate(alias="zWear")
    """Lathe wear offsets, added to the geometry ones [K: Fanuc Series 0i-TC/TD operator's manual, "Tool
    offset": the offset memory holds geometry and wear per offset number, both applied by ``T□□△△``;
    parameter LGN (5002#1) picks the geometry number: the wear number, as here, or the tool number]."""

    def __post_init__(self) -> None:
        if self.shared() and any(v is not None for v in (self.length, self.radius, self.length_wear,
                                                        self.radius_wear, self.diameter, self.diameter_wear)):
            raise ValueError(f"tool {self.number}: offset/offsetWear (one value for H and D: Fanuc memory A/B) "
                             "beside length/radius or diameter (separate H and D: memory C)")
        if self.by_diameter() and (self.radius is not None or self.radius_wear is not None):
            raise ValueError(f"tool {self.number}: diameter/diameterWear (Haas's columns by diameter) beside "
                             "radius/radiusWear: give the cutter by one of them")
        if (self.x is None) != (self.z is None):
            raise ValueError(f"tool {self.number}: a lathe offset gives {'x' if self.x is not None else 'z'} "
                             f"without {'z' if self.x is not None else 'x'} (give both; 0 where it is zero)")
        if self.x is None and (self.x_wear is not None or self.z_wear is not None):
            raise ValueError(f"tool {self.number}: xWear/zWear without the geometry x and z")

    def by_diameter(self) -> bool:
        """The entry gives its cutter by diameter (Haas's setting 40 on Diameter)."""
        return self.diameter is not None or self.diameter_wear is not None

    def lathe(self) -> tuple[float, float] | None:
        """The lathe offset (X, Z) in set-up units, geometry plus wear; None when the entry gives none."""
        if self.x is None or self.z is None:
            return None
        return self.x + (self.x_wear or 0.0), self.z + (self.z_wear or 0.0)

    def shared(self) -> bool:
        """The entry is one value for H and D (Fanuc memory A/B)."""
        return self.offset is not None or self.offset_wear is not None

    def geometry(self, quantity: str) -> float | None:
        """The "length" or "radius" the entry gives (None: not given)."""
        if self.shared():
            return self.offset
        if quantity == "length":
            return self.length
        return self.diameter / 2.0 if self.diameter is not None else self.radius

    def wear(self, quantity: str) -> float:
        """The wear the entry adds to its ``quantity`` (zero when not given)."""
        if self.shared():
            return self.offset_wear or 0.0
        if quantity == "length":
            return self.length_wear or 0.0
        return (self.diameter_wear or 0.0) / 2.0 if self.by_diameter() else self.radius_wear or 0.0


CONTAINERS: dict[str, type[Entry]] = {"Axes": AxisTravel, "WorkOffsets": WorkOffsetData, "Tools": ToolData}
"""Container element -> the entry class of its children."""


def entry_values(entry: Entry, only: set[str] | None = None) -> dict[str, Any]:
    """The entry's attributes as XML writes them (aliases, defaults left out), key first."""
    written = values(entry, by_alias=True, exclude_none=True)
    if only is not None:
        written = {k: v for k, v in written.items() if k in only or k == entry.KEY}
    return written
