"""A toolpath event as its JSON line, written here rather than by json's encoder for the events a
toolpath is made of (compiled with the simulator: a CAM program writes one a block).

The text is json's: ``json.JSONEncoder(allow_nan=False).encode`` (``", "`` and ``": "`` between items,
ASCII escapes, a float as ``float.__repr__``), held to it on any event by ``tests/test_toolpath_numbers.py``.
Two things make json's encoder cost what a simulated block costs: it escapes every key of every event
again, and it spells each float with ``float.__repr__``, a shortest round-trip conversion of about 3,500
instructions (six floats a move under a tool length). A toolpath's floats are ``num``'s: a whole number of
millionths, nearest the decimal of those millionths. Such a float's shortest round-trip spelling is that
decimal (at most 14 significant digits below 1e8, and two decimals of at most 15 digits are never the
same float), which integer arithmetic writes; a float that is not one (``units / 1e6`` differs) or lies
where ``repr`` writes an exponent goes to ``float.__repr__``. An event holding anything but str keys and
str, int, bool, None, float or such a dict values is handed whole to ``fallback`` (json's own encoder).

The lines go into one growing buffer of ASCII bytes, ``librt.strings.BytesWriter`` (mypy's run-time library, the
build's own compiler's: compiled, its ``append`` of a byte and its ``write`` of a text are C linked into the module,
a few machine instructions and a copy): a number's digits a byte at a time, from integer arithmetic, a key or a
fixed text (``b', "move": "feed"'``, the feed's ``b', "f": 1500'``) written whole; a chunk of lines goes to a binary
file as it is (JSON is ASCII here: json's escapes), not through a text file's encoder. Three writers came before it:
a ``StringWriter`` of text (its ``write`` a call through the library's table, ~65 instructions, and the text file's
UTF-8 copy of every chunk, ~150 a line: branch tpwall3), a list of pieces joined once a chunk of lines (each piece an
append, its share of the join and of the list's clearing, ~140 instructions compiled, some 21 a move under a tool
length, the digits from tables of texts that missed the cache: branches tpwall, tpwall2), and json's encoder.
Measured with callgrind at 10k blocks of the bench's CAM program (branch tpwall3): the writer ~5,500 -> ~4,100
instructions a move, the join's ~1,600 gone (a float's digits cost about what its tabled pieces did, ~280).
"""

from __future__ import annotations

from json.encoder import encode_basestring_ascii
from typing import Any, Callable, Final, Iterable

from librt.strings import BytesWriter
from mypy_extensions import i64, mypyc_attr, u8

from ..geometry.arcs import PLACES
from .events import ROUND
from .move_record import MoveRecord

_PLACES: Final = 6
_UNITS: Final = 1_000_000
_SCALE: Final = 1e6
_SMALLEST: Final = 1e-4
"""``float.__repr__`` writes an exponent below this (``9e-05``) and from 1e16 on."""
_LARGEST: Final = 1e8
"""Below this a whole number of millionths has at most 14 digits (one float per decimal)."""
_DIGITS_BELOW: Final = 10 ** 15
"""An int whose magnitude is below this is spelt by ``_whole_into`` (a machine integer); a larger one by ``str``."""
_ZERO: Final = 48
_POINT: Final = 46
_MINUS: Final = 45
"""``ord`` of ``"0"``, ``"."`` and ``"-"``: the bytes ``BytesWriter.append`` takes."""
_KEYS: Final[dict[str, bytes]] = {}
"""Key -> its text as an object's first item, with the object's opening brace (``'{"line": '``): a toolpath
has a dozen keys."""
_LATER_KEYS: Final[dict[str, bytes]] = {}
"""Key -> its text after another item (``', "x": '``)."""
_WORDS: Final[dict[str, bytes]] = {}
"""Short string values (``"feed"``, ``"XY"``, ``"cw"``) -> their text; at most ``_MOST_WORDS`` kept."""
_MOST_WORDS: Final = 512
_PLACES_KEPT: Final = 32
"""Items of an object whose key texts ``_SEEN_KEYS`` keeps, at each of two depths (an event, its controlled point)."""
_SEEN_KEYS: Final[list[object]] = [None] * (2 * _PLACES_KEPT)
"""The key met last at each place (an item's index, plus ``_PLACES_KEPT`` inside a nested object), and in
``_SEEN_TEXTS`` its text there: the events of a toolpath come in runs of one shape (a CAM program's moves), so
the key at a place is most often the very string met there before, and one identity test replaces a
dictionary look-up (~130 instructions compiled, ten an event)."""
_SEEN_TEXTS: Final[list[bytes]] = [b""] * (2 * _PLACES_KEPT)
_SEEN_VALUES: Final[list[object]] = [None] * (2 * _PLACES_KEPT)
"""The int or str value met last at each place, and in ``_SEEN_VALUE_TEXTS`` its text (a move's kind, its feed)."""
_SEEN_VALUE_TEXTS: Final[list[bytes]] = [b""] * (2 * _PLACES_KEPT)
assert _PLACES == PLACES and _UNITS == 10 ** PLACES == _SCALE
# Final: compiled, a constant is a C constant, not a look-up in the module's dictionary (17 a float)


def float_text(value: float) -> str:
    """``float.__repr__(value)``; ValueError for a value that is not finite (json's ``allow_nan=False``)."""
    w = BytesWriter()
    _float_into(value, w)
    return w.getvalue().decode("ascii")


def _float_into(value: float, w: BytesWriter) -> None:
    """Write ``float_text(value)`` into ``w``: a whole number of millionths below 1e8 by its digits (a float
    parameter: compiled, unboxed once; the units machine integers, ``i64``), any other float by ``repr``."""
    units = _float_units(value)
    if units != _NO_UNITS:
        _units_into(units, w)
        return
    _repr_into(value, w)


_NO_UNITS: Final[i64] = -1_000_000_000_000_000_000
"""``_float_units`` of a float its digits do not spell (``repr`` does): beyond any float's units (below 1e14), and
a machine integer constant (compiled, ``-(2 ** 63)`` was a Python int object, converted at each comparison)."""


def _float_units(value: float) -> i64:
    """The whole number of millionths ``value`` is, where ``_units_into`` spells it as ``repr`` does (a float of
    ``num``'s, 1e-4 <= |value| < 1e8), else ``_NO_UNITS``: a record's controlled point spells its programmed point's
    own floats again from their units (``_record_into``)."""
    if _SMALLEST <= value < _LARGEST or -_LARGEST < value <= -_SMALLEST:
        k = (value * _SCALE + ROUND) - ROUND  # the nearest whole number of millionths, as a float (``events.ROUND``;
        if k / _SCALE == value:  # a tie is never such a float's: it lies within 0.03 of its ``k``)
            return i64(k)  # (|k| < 1e14: exact)
    return _NO_UNITS


def _units_into(units: i64, w: BytesWriter) -> None:
    """Write the float of ``units`` millionths (``_float_units``) as ``repr`` does."""
    if units < 0:
        w.append(_MINUS)
        units = -units
    whole = units // _UNITS
    _whole_into(whole, w)
    _fraction_into(units - whole * _UNITS, w)


def _repr_into(value: float, w: BytesWriter) -> None:
    """Write a float ``_float_units`` does not spell: by ``repr``; ValueError where it is not finite."""
    if value - value != 0.0:  # inf - inf and nan - nan are nan
        raise ValueError(f"Out of range float values are not JSON compliant: {value!r}")
    w.write(float.__repr__(value).encode("ascii"))


def _fraction_into(fraction: i64, w: BytesWriter) -> None:
    """Write the point and the decimals of ``fraction`` millionths (below a million), trailing zeros dropped
    (``".0"`` for none: an integral float, which repr writes with its digits and ".0"). Unrolled: each division by
    a constant is a multiplication compiled, where a loop's by a variable power of ten was a call."""
    w.append(_POINT)
    if fraction == 0:
        w.append(_ZERO)
        return
    d = fraction // 100_000
    w.append(u8(_ZERO + d))
    fraction -= d * 100_000
    if fraction == 0:
        return
    d = fraction // 10_000
    w.append(u8(_ZERO + d))
    fraction -= d * 10_000
    if fraction == 0:
        return
    d = fraction // 1000
    w.append(u8(_ZERO + d))
    fraction -= d * 1000
    if fraction == 0:
        return
    d = fraction // 100
    w.append(u8(_ZERO + d))
    fraction -= d * 100
    if fraction == 0:
        return
    d = fraction // 10
    w.append(u8(_ZERO + d))
    fraction -= d * 10
    if fraction != 0:
        w.append(u8(_ZERO + fraction))


def _whole_into(n: i64, w: BytesWriter) -> None:
    """Write the digits of ``n`` (not negative), as ``str`` spells it: three at a time from the right."""
    if n < 10:
        w.append(u8(_ZERO + n))
        return
    if n < 100:
        d = n // 10
        w.append(u8(_ZERO + d))
        w.append(u8(_ZERO + n - d * 10))
        return
    if n >= 1000:
        high = n // 1000
        _whole_into(high, w)
        n -= high * 1000
        d = n // 100
        w.append(u8(_ZERO + d))  # (zero-padded: the three digits below the thousands)
        n -= d * 100
    else:
        d = n // 100
        w.append(u8(_ZERO + d))
        n -= d * 100
    d = n // 10
    w.append(u8(_ZERO + d))
    w.append(u8(_ZERO + n - d * 10))


def _int_into(value: int, w: BytesWriter) -> None:
    """Write ``int.__repr__(value)`` into ``w`` (by its digits where it fits a machine integer)."""
    if -_DIGITS_BELOW < value < _DIGITS_BELOW:
        n = i64(value)
        if n < 0:
            w.append(_MINUS)
            n = -n
        _whole_into(n, w)
    else:
        w.write(int.__repr__(value).encode("ascii"))


def _number_into(value: float | int, w: BytesWriter) -> None:
    """A record's number (``num``'s: an int or a float) as json writes it."""
    if isinstance(value, float):
        _float_into(value, w)
    else:
        _int_into(value, w)


def _key_text(key: str, later: bool) -> bytes:
    known = _LATER_KEYS if later else _KEYS
    text = known.get(key)
    if text is None:
        text = ((", " if later else "{") + encode_basestring_ascii(key) + ": ").encode("ascii")
        if len(known) < _MOST_WORDS:
            known[key] = text
    return text


def _word_text(value: str) -> bytes:
    text = _WORDS.get(value)
    if text is None:
        text = encode_basestring_ascii(value).encode("ascii")
        if len(value) <= 16 and len(_WORDS) < _MOST_WORDS:
            _WORDS[value] = text
    return text


def _other_text(value: object) -> bytes | None:
    """The text of a scalar the loop does not write itself, or None: not an event's value. Subclasses as
    json writes them: a bool before an int, an int by its base's ``__repr__``."""
    if isinstance(value, bool):
        return b"true" if value else b"false"
    if isinstance(value, int):
        return int.__repr__(value).encode("ascii")
    if value is None:
        return b"null"
    return None


def _items_into(items: dict[Any, Any], w: BytesWriter, place: int) -> bool:
    """Write the object ``items`` into ``w``, its opening brace with its first key and its items, not its closing
    brace (``write_lines`` writes it with the line end); False where json must write it (what was written of it
    then stays: the caller cuts it off). ``place``: where the texts of its first item are kept (``_SEEN_KEYS``: 0,
    or ``_PLACES_KEPT`` for a nested object)."""
    end = place + _PLACES_KEPT if place < 2 * _PLACES_KEPT else 0  # an object nested deeper keeps none
    first = place
    for key, value in items.items():
        if not isinstance(key, str):
            return False
        kept = place < end
        if kept and _SEEN_KEYS[place] is key:
            w.write(_SEEN_TEXTS[place])
        else:
            known = _LATER_KEYS.get(key) if place != first else _KEYS.get(key)
            text = known if known is not None else _key_text(key, place != first)
            w.write(text)
            if kept:
                _SEEN_KEYS[place] = key
                _SEEN_TEXTS[place] = text
        if isinstance(value, float):
            _float_into(value, w)
        elif type(value) is int or isinstance(value, str):
            if kept and _SEEN_VALUES[place] is value:  # a move's kind, its feed: the object of the event before
                w.write(_SEEN_VALUE_TEXTS[place])
            else:
                if isinstance(value, str):
                    word = _WORDS.get(value)
                    text = word if word is not None else _word_text(value)
                else:
                    text = str(value).encode("ascii")  # int's own spelling, without a method look-up (a line number each event)
                w.write(text)
                if kept:
                    _SEEN_VALUES[place] = value
                    _SEEN_VALUE_TEXTS[place] = text
        elif isinstance(value, dict):
            if not value:
                w.write(b"{}")
            else:
                if not _items_into(value, w, _PLACES_KEPT if first == 0 else 2 * _PLACES_KEPT):
                    return False
                w.write(b"}")
        else:
            other = _other_text(value)
            if other is None:
                return False
            w.write(other)
        place += 1
    return True


# the texts of a record's fixed keys, each after the item before it (the line's first, with the brace)
_KEYS_LINE: Final = b'{"line": '
_KEY_MOVE: Final = b', "move": '
_KEY_F: Final = b', "f": '
_KEY_FEED_MODE: Final = b', "feed_mode": '
_KEY_PLANE: Final = b', "plane": '
_KEY_CONTROLLED: Final = b', "controlled": '
_CLOSE: Final = b"}"
_CLOSE_LINE: Final = b"}\n"
_CLOSE_BOTH: Final = b"}}"
_CLOSE_BOTH_LINE: Final = b"}}\n"
"""A record's closing text: the event's brace (with the line end where ``write_lines`` writes it), after the
controlled point's brace where it has one."""


@mypyc_attr(allow_interpreted_subclasses=True)
class _KeyTexts:
    """The texts of a record's axis keys (``MoveRecord.keys``: one tuple a simulation), kept for the tuple met last,
    and the texts of the kind and feed met last, each a fixed key with its value (``', "move": "feed"'``,
    ``', "f": 1500'``: one text written where there were two, and the feed's number spelt once while it stays)."""

    def __init__(self) -> None:
        self.keys: tuple[str, ...] = ()
        self.later: list[bytes] = []
        """Each key after another item (``', "x": '``)."""
        self.first: list[bytes] = []
        """Each key in the controlled point: the first with the ``controlled`` key and the object's brace before it
        (``', "controlled": {"x": '``), the others ``later``'s."""
        self.kind: str | None = None
        self.kind_text = b""
        """``', "move": "feed", "x": '`` for the kind ``kind``: with the first axis key after it (a record's point
        follows its kind: one text written where there were two, ~65 instructions a move)."""
        self.kinds: dict[str, bytes] = {}
        """Each kind met -> its text (a program's moves alternate between a few kinds), for the keys ``keys``."""
        self.f: object = None
        self.f_text = b""
        """``', "f": 1500'`` for the feed object ``f`` (a feed changes rarely: the simulator writes one object)."""
        self.f_first = b""
        """``f_text`` with the controlled point's opening after it (``', "f": 1500, "controlled": {"x": '``): a
        record with a feed, no ``feed_mode`` and a controlled point writes it as one text."""

    def update(self, keys: tuple[str, ...]) -> None:
        self.keys = keys
        self.later = [_key_text(key, True) for key in keys]
        self.first = [_KEY_CONTROLLED + _key_text(key, False) if i == 0 else self.later[i]
                      for i, key in enumerate(keys)]
        self.kinds = {}  # (their texts hold the first key: spelt again for these keys)
        self.kind = None
        self.f = None

    def kind_of(self, kind: str) -> bytes:
        """The text of ``kind`` with the first axis key (``kind_text``), kept as ``kind_text``."""
        text = self.kinds.get(kind)
        if text is None:
            word = _WORDS.get(kind)
            text = _KEY_MOVE + (word if word is not None else _word_text(kind)) + (self.later[0] if self.later else b"")
            self.kinds[kind] = text
        self.kind = kind
        self.kind_text = text
        return text

    def feed(self, f: float | int) -> None:
        """Spell the feed ``f`` (``f_text``, ``f_first``), kept for the object ``f``."""
        spelt = BytesWriter()
        spelt.write(_KEY_F)
        _number_into(f, spelt)
        self.f_text = spelt.getvalue()
        self.f_first = self.f_text + (self.first[0] if self.first else b"")
        self.f = f


_RECORD_KEYS: Final = _KeyTexts()


def _record_into(record: MoveRecord, w: BytesWriter, line_end: bool) -> None:
    """Write the JSON text of ``record`` (``MoveRecord.event()``'s, with its closing brace and, where ``line_end``,
    the line end): field by field, in the order ``event()`` gives its keys, with no look-up or type test of a key
    (``tests/test_toolpath_numbers.py`` holds it to json's text of ``event()``). A controlled point's float that is
    the programmed point's own object (under a tool length alone, its X and Y) is spelt again: copying its text from
    where it was written, a character at a time (``w[k]``, ~35 instructions a character compiled, keys between
    included), cost what it saved (callgrind, branch tpwall3); it is spelt from the units its programmed twin had
    (``_float_units`` once, not twice: ~100 instructions a float, branch tpmove). The lists are walked by ``zip``
    (compiled, an item taken unchecked, where an index was a checked call)."""
    texts = _RECORD_KEYS
    keys = record.keys
    if keys is not texts.keys:
        texts.update(keys)
    w.write(_KEYS_LINE)
    _int_into(record.line, w)
    kind = record.kind
    w.write(texts.kind_text if kind is texts.kind else texts.kind_of(kind))  # (with the first axis key)
    keyed = False
    point = record.point
    i = 0
    u0: i64 = _NO_UNITS  # the first three floats' units, for the controlled point's floats that are them
    u1: i64 = _NO_UNITS
    u2: i64 = _NO_UNITS
    units: i64
    for text, value in zip(texts.later, point):
        if keyed:
            w.write(text)
        keyed = True
        if isinstance(value, float):  # (most often: the float's own call, not through the union's)
            units = _float_units(value)
            if units != _NO_UNITS:
                _units_into(units, w)
            else:
                _repr_into(value, w)
            if i == 0:
                u0 = units
            elif i == 1:
                u1 = units
            elif i == 2:
                u2 = units
        else:
            _int_into(value, w)
        i += 1
    centre = record.centre
    if centre is not None:  # an arc: its centre and plane
        centre_keys = record.centre_keys
        for i in range(len(centre_keys)):
            w.write(_key_text(centre_keys[i], True))
            _number_into(centre[i], w)
        w.write(_KEY_PLANE)
        plane = record.plane
        w.write(b"null" if plane is None else _word_text(plane))
    f = record.f
    mode = record.feed_mode
    controlled = record.controlled
    keyed = False  # the controlled point's opening and first key are written (with the feed)
    if f is not None:
        if f is not texts.f:  # (identity: the same object has the same text; an equal one is spelt again)
            texts.feed(f)
        if mode is None and controlled is not None and keys:
            w.write(texts.f_first)
            keyed = True
        else:
            w.write(texts.f_text)
    if mode is not None:
        w.write(_KEY_FEED_MODE)
        w.write(_word_text(mode))
    if controlled is None:
        w.write(_CLOSE_LINE if line_end else _CLOSE)
        return
    ccentre = record.ccentre
    if not keys:
        w.write(_KEY_CONTROLLED)
        if ccentre is None or not record.centre_keys:
            w.write(b"{}")
            w.write(_CLOSE_LINE if line_end else _CLOSE)
            return
    i = 0
    for text, value, programmed in zip(texts.first, controlled, point):
        if keyed:
            keyed = False
        else:
            w.write(text)
        twin = value is programmed  # (the two objects, before ``value`` is read as a float)
        if isinstance(value, float):
            units = _NO_UNITS
            if twin and i < 3:  # (its units known: not unboxed and checked again)
                if i == 0:
                    units = u0
                elif i == 1:
                    units = u1
                else:
                    units = u2
            if units == _NO_UNITS:
                units = _float_units(value)
            if units != _NO_UNITS:
                _units_into(units, w)
            else:
                _repr_into(value, w)
        else:
            _int_into(value, w)
        i += 1
    if ccentre is not None:
        centre_keys = record.centre_keys
        for i in range(len(centre_keys)):
            w.write(_key_text(centre_keys[i], i > 0 or len(keys) > 0))
            _number_into(ccentre[i], w)
    w.write(_CLOSE_BOTH_LINE if line_end else _CLOSE_BOTH)


def event_text(event: dict[Any, Any] | MoveRecord, fallback: Callable[[Any], str]) -> str:
    """The JSON text of one event (without its line end)."""
    w = BytesWriter()
    if isinstance(event, MoveRecord):
        _record_into(event, w, False)
        return w.getvalue().decode("ascii")
    if not event:
        return "{}"
    if not _items_into(event, w, 0):
        return fallback(event)
    w.write(b"}")
    return w.getvalue().decode("ascii")


_CHUNK: Final = 256
"""Lines written at once by ``write_lines``."""


@mypyc_attr(allow_interpreted_subclasses=True)
class EventValueError(ValueError):
    """A value of ``event`` that JSON cannot hold (not finite): ``write_lines`` wrote the lines before it."""

    def __init__(self, message: str, event: dict[Any, Any]) -> None:
        super().__init__(message)
        self.event = event


def _cut(w: BytesWriter, length: int) -> BytesWriter:
    """``w`` holding its first ``length`` bytes: the lines before an event that failed or that json writes (rare)."""
    w.truncate(length)
    return w


def write_lines(events: Iterable[dict[Any, Any] | MoveRecord], write: Callable[[bytes], object],
                fallback: Callable[[Any], str]) -> None:
    """Write each event as its JSON line (``event_text``, in ASCII bytes) through ``write``, ``_CHUNK`` lines at a
    time: one ``bytes`` and one write a chunk, not a text and a text file's write a line (~2k instructions a toolpath
    event). The lines before an error (from ``events`` or an event's value: ``EventValueError``) are written before
    it propagates, as line by line."""
    w = BytesWriter()
    count = 0
    try:
        for event in events:
            mark = len(w)
            try:
                if isinstance(event, MoveRecord):
                    _record_into(event, w, True)
                elif not event:
                    w.write(b"{}\n")
                elif _items_into(event, w, 0):
                    w.write(b"}\n")
                else:
                    w = _cut(w, mark)
                    w.write((fallback(event) + "\n").encode("ascii"))
            except ValueError as err:
                w = _cut(w, mark)
                raise EventValueError(str(err), event.event() if isinstance(event, MoveRecord) else event) from None
            count += 1
            if count == _CHUNK:
                text = w.getvalue()
                w.truncate(0)  # (its buffer kept for the next chunk: a new writer grew it again, ~10 reallocations)
                count = 0
                write(text)
    finally:
        if len(w):
            write(w.getvalue())
