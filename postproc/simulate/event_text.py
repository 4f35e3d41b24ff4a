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

The line is one list of pieces joined once: a key with the separator (or the opening brace) before it, a
number's whole part, its decimals from tables (one piece where they are at most four, as a CAM program's are;
else the first three and the rest), the closing brace with the line end (no string is built per number, none
per item; compiled, building a string costs ~500 instructions, an append ~50, and each piece ~90 more in the
join and the list's clearing). A move record's fixed texts are fewer pieces still: its line number's last digits
with its kind and their keys, its feed with its key (spelt once while the feed stays), the controlled point's key
with its first axis and whole part, its last short fraction with the two closing braces and the line end.
"""

from __future__ import annotations

from json.encoder import encode_basestring_ascii
from typing import Any, Callable, Final, Iterable

from mypy_extensions import i64, mypyc_attr

from ..geometry.arcs import PLACES
from .move_record import MoveRecord

_PLACES: Final = 6
_UNITS: Final = 1_000_000
_SCALE: Final = 1e6
_SMALLEST: Final = 1e-4
"""``float.__repr__`` writes an exponent below this (``9e-05``) and from 1e16 on."""
_LARGEST: Final = 1e8
"""Below this a whole number of millionths has at most 14 digits (one float per decimal)."""
_TABLED: Final = 1000
_FIRST: Final = [f".{n:03d}" for n in range(_TABLED)]
"""The point and a number's first three decimals, the others following."""
_REST: Final = [f"{n:03d}".rstrip("0") for n in range(_TABLED)]
"""Decimals four to six (trailing zeros dropped; never all zero where used)."""
_SHORT_STEP: Final = 100
_PAIRS: Final = 100
_PAIR_FIRST: Final = [f".{n:02d}" for n in range(_PAIRS)]
"""A fraction of at most four decimals (a whole number of ``_SHORT_STEP`` millionths, as a CAM program writes its
coordinates), in ten-thousandths: its point and first two decimals where two follow (``".95"`` of ``.9596``)..."""
_PAIR_REST: Final = [f"{n:02d}".rstrip("0") for n in range(_PAIRS)]
"""... then those two (trailing zeros dropped; never 0 where used) ..."""
_PAIR_ONLY: Final = [".0"] + [f".{n:02d}".rstrip("0") for n in range(1, _PAIRS)]
"""... or the point and its first two decimals alone (``".0"`` for none: an integral float below 1e16, which repr
writes with its digits and ".0"). Tables of a hundred short texts, not one of ten thousand made as met: a piece
more a number (~110 instructions) but tables that stay in the first-level cache, where the big one's texts,
met at random, missed the cache at each look-up (``perf record`` at 300k blocks: a tenth of ``toolpath``'s
time in one increment of the looked-up text's reference count)."""
_WHOLE: Final = [str(n) for n in range(_TABLED)]
_NEGATIVE: Final = [f"-{n}" for n in range(_TABLED)]
"""A number's whole part below 1000 (a CAM coordinate's), with its sign."""
_PADDED: Final = [f"{n:03d}" for n in range(_TABLED)]
"""A line number's last three digits (``_KindTexts.padded``)."""
_KEYS: Final[dict[str, str]] = {}
"""Key -> its text as an object's first item, with the object's opening brace (``'{"line": '``): a toolpath
has a dozen keys."""
_LATER_KEYS: Final[dict[str, str]] = {}
"""Key -> its text after another item (``', "x": '``)."""
_WORDS: Final[dict[str, str]] = {}
"""Short string values (``"feed"``, ``"XY"``, ``"cw"``) -> their text; at most ``_MOST_WORDS`` kept."""
_MOST_WORDS: Final = 512
_PLACES_KEPT: Final = 32
"""Items of an object whose key texts ``_SEEN_KEYS`` keeps, at each of two depths (an event, its controlled point)."""
_SEEN_KEYS: Final[list[object]] = [None] * (2 * _PLACES_KEPT)
"""The key met last at each place (an item's index, plus ``_PLACES_KEPT`` inside a nested object), and in
``_SEEN_TEXTS`` its text there: the events of a toolpath come in runs of one shape (a CAM program's moves), so
the key at a place is most often the very string met there before, and one identity test replaces a
dictionary look-up (~130 instructions compiled, ten an event)."""
_SEEN_TEXTS: Final[list[str]] = [""] * (2 * _PLACES_KEPT)
_SEEN_VALUES: Final[list[object]] = [None] * (2 * _PLACES_KEPT)
"""The int or str value met last at each place, and in ``_SEEN_VALUE_TEXTS`` its text (a move's kind, its feed)."""
_SEEN_VALUE_TEXTS: Final[list[str]] = [""] * (2 * _PLACES_KEPT)
assert _PLACES == PLACES and _UNITS == 10 ** PLACES == _SCALE and _TABLED ** 2 == _UNITS
# Final: compiled, a constant is a C constant, not a look-up in the module's dictionary (17 a float)


def float_text(value: float) -> str:
    """``float.__repr__(value)``; ValueError for a value that is not finite (json's ``allow_nan=False``)."""
    parts: list[str] = []
    _float_parts(value, parts)
    return "".join(parts)


def _float_parts(value: float, parts: list[str]) -> None:
    """Append ``float_text(value)`` to ``parts``, in pieces."""
    if _SMALLEST <= value < _LARGEST or -_LARGEST < value <= -_SMALLEST:
        units = i64(value * _SCALE + (0.5 if value > 0.0 else -0.5))  # (|units| < 1e14: exact as a float)
        if float(units) / _SCALE == value:
            magnitude = -units if units < 0 else units
            whole = magnitude // _UNITS
            fraction = magnitude - whole * _UNITS
            if whole < _TABLED:
                parts.append(_NEGATIVE[whole] if units < 0 else _WHOLE[whole])
            else:
                parts.append(str(-whole) if units < 0 else str(whole))
            _fraction_parts(fraction, parts)
            return
    if value - value != 0.0:  # inf - inf and nan - nan are nan
        raise ValueError(f"Out of range float values are not JSON compliant: {value!r}")
    parts.append(float.__repr__(value))


def _fraction_parts(fraction: i64, parts: list[str]) -> None:
    """Append the point and the decimals of ``fraction`` millionths (``_float_parts``' number after its whole part):
    one or two pieces where they are at most four (``_PAIR_*``), else two (the first three decimals and the rest)."""
    if fraction % _SHORT_STEP == 0:
        index = fraction // _SHORT_STEP
        high = index // _PAIRS
        low = index - high * _PAIRS
        if low == 0:
            parts.append(_PAIR_ONLY[high])
        else:
            parts.append(_PAIR_FIRST[high])
            parts.append(_PAIR_REST[low])
        return
    high = fraction // _TABLED
    parts.append(_FIRST[high])
    parts.append(_REST[fraction - high * _TABLED])  # (never 0: the fraction is no multiple of _SHORT_STEP)


def _key_text(key: str, later: bool) -> str:
    known = _LATER_KEYS if later else _KEYS
    text = known.get(key)
    if text is None:
        text = (", " if later else "{") + encode_basestring_ascii(key) + ": "
        if len(known) < _MOST_WORDS:
            known[key] = text
    return text


def _word_text(value: str) -> str:
    text = _WORDS.get(value)
    if text is None:
        text = encode_basestring_ascii(value)
        if len(value) <= 16 and len(_WORDS) < _MOST_WORDS:
            _WORDS[value] = text
    return text


def _other_text(value: object) -> str | None:
    """The text of a scalar the loop does not write itself, or None: not an event's value. Subclasses as
    json writes them: a bool before an int, an int by its base's ``__repr__``."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return int.__repr__(value)
    if value is None:
        return "null"
    return None


def _items_parts(items: dict[Any, Any], parts: list[str], place: int) -> bool:
    """Append the object ``items`` to ``parts``, its opening brace with its first key and its items, not its
    closing brace (``write_lines`` appends it with the line end); False where json must write it. ``place``:
    where the texts of its first item are kept (``_SEEN_KEYS``: 0, or ``_PLACES_KEPT`` for a nested object). A
    float of a controlled point that is the programmed point's is spelt again: remembering where each float's
    pieces lay cost more than spelling the two again (callgrind, a move under a tool length)."""
    end = place + _PLACES_KEPT if place < 2 * _PLACES_KEPT else 0  # an object nested deeper keeps none
    first = place
    for key, value in items.items():
        if not isinstance(key, str):
            return False
        kept = place < end
        if kept and _SEEN_KEYS[place] is key:
            parts.append(_SEEN_TEXTS[place])
        else:
            known = _LATER_KEYS.get(key) if place != first else _KEYS.get(key)
            text = known if known is not None else _key_text(key, place != first)
            parts.append(text)
            if kept:
                _SEEN_KEYS[place] = key
                _SEEN_TEXTS[place] = text
        if isinstance(value, float):
            _float_parts(value, parts)
        elif type(value) is int or isinstance(value, str):
            if kept and _SEEN_VALUES[place] is value:  # a move's kind, its feed: the object of the event before
                parts.append(_SEEN_VALUE_TEXTS[place])
            else:
                if isinstance(value, str):
                    word = _WORDS.get(value)
                    text = word if word is not None else _word_text(value)
                else:
                    text = str(value)  # int's own spelling, without a method look-up (a line number each event)
                parts.append(text)
                if kept:
                    _SEEN_VALUES[place] = value
                    _SEEN_VALUE_TEXTS[place] = text
        elif isinstance(value, dict):
            if not value:
                parts.append("{}")
            else:
                if not _items_parts(value, parts, _PLACES_KEPT if first == 0 else 2 * _PLACES_KEPT):
                    return False
                parts.append("}")
        else:
            other = _other_text(value)
            if other is None:
                return False
            parts.append(other)
        place += 1
    return True


# the texts of a record's fixed keys, each after the item before it (the line's first, with the brace)
_KEYS_LINE: Final = '{"line": '
_KEY_MOVE: Final = ', "move": '
_KEY_F: Final = ', "f": '
_KEY_FEED_MODE: Final = ', "feed_mode": '
_KEY_PLANE: Final = ', "plane": '
_KEY_CONTROLLED: Final = ', "controlled": '


@mypyc_attr(allow_interpreted_subclasses=True)
class _KeyTexts:
    """The texts of a record's axis keys (``MoveRecord.keys``: one tuple a simulation), kept for the tuple met last,
    and the texts of the kind and feed met last: each a fixed key joined with its value, and with the piece of the
    line next to it, one piece of the line where there were two (and ``str`` of the feed made once, not at every
    move). The feed's text stands alone: joined with the controlled point's first key and whole part (one piece
    less a move) it made a table of whole parts for each feed, two thirds of the writer's keyed texts (2,700 of
    4,150 at 300k blocks), each met again after the others' feeds had pushed it out of the cache (perf at 300k
    blocks: the look-ups of tabled texts 5-6 % of the run, most at the keyed whole parts; 3 % with one table a key,
    ``first`` sharing ``later``'s)."""

    def __init__(self) -> None:
        self.keys: tuple[str, ...] = ()
        self.later: list[_KeyedNumbers] = []
        """Each key after another item (``', "x": '``), with the numbers after it."""
        self.first: list[_KeyedNumbers] = []
        """Each key as the controlled point's, the first with the ``controlled`` key and the object's brace before
        it (``', "controlled": {"x": '``), the others ``later``'s own (the same texts: a table of whole parts a
        key, not two; a controlled Z's whole parts, the length above the programmed Z's, share it)."""
        self.kind: str | None = None
        self.kind_texts = _KindTexts("")
        """The texts of the kind ``kind`` (``', "move": "feed"'``, with the line number before it)."""
        self.kinds: dict[str, _KindTexts] = {}
        """Each kind met -> its texts (a program's moves alternate between a few kinds)."""
        self.f: object = None
        self.f_text = ""
        """``', "f": 1500'`` for the feed object ``f`` (a feed changes rarely: the simulator writes one object)."""

    def update(self, keys: tuple[str, ...]) -> None:
        self.keys = keys
        self.later = [_KeyedNumbers(_key_text(key, True)) for key in keys]
        self.first = [_KeyedNumbers(_KEY_CONTROLLED + _key_text(key, False)) if i == 0 else self.later[i]
                      for i, key in enumerate(keys)]  # (after the first, a key's texts are ``later``'s: one table)

    def kind_of(self, kind: str) -> _KindTexts:
        """The texts of ``kind``, kept as ``kind_texts``."""
        texts = self.kinds.get(kind)
        if texts is None:
            word = _WORDS.get(kind)
            texts = _KindTexts(_KEY_MOVE + (word if word is not None else _word_text(kind)))
            self.kinds[kind] = texts
        self.kind = kind
        self.kind_texts = texts
        return texts

    def feed(self, f: float | int) -> None:
        """Spell the feed ``f`` (``f_text``), kept for the object ``f``."""
        spelt: list[str] = [_KEY_F]
        _number_parts(f, spelt)
        self.f_text = "".join(spelt)
        self.f = f


@mypyc_attr(allow_interpreted_subclasses=True)
class _KindTexts:
    """A move kind's text (``', "move": "feed"'``) joined with the line number before it: ``'{"line": 80, "move":
    "feed"'`` for a line below ``_TABLED`` (made the first time met), the last three digits with it (``'345, "move":
    "feed"'``) for one below ``_LINES_TABLED`` (``_LINE_HIGH`` before them). The latter are made all at once, in
    order, when the kind is first met: a program's lines come in order, so each text is met once every thousand
    lines, long out of the cache; made one after another they lie one after another in memory, where the
    processor fetches the next before it is read (made as met, each lay wherever the blocks of its time left room:
    perf at 300k blocks, ~2% of ``toolpath``'s time in the reference-count increment of the text looked up)."""

    def __init__(self, text: str) -> None:
        self.text = text
        self.low: list[str | None] = [None] * _TABLED
        self.padded: list[str] = [_PADDED[n] + text for n in range(_TABLED)]


@mypyc_attr(allow_interpreted_subclasses=True)
class _KeyedNumbers:
    """A record's key text joined with the whole part of the number that follows it (``', "x": 12'``), made the first
    time that whole part follows the key: one piece where there were two (compiled, each piece of a line costs an
    append and its share of the join, ~110 instructions; a move writes six numbers under a tool length)."""

    def __init__(self, text: str) -> None:
        self.text = text
        """The key's text (``', "x": '``)."""
        self.wholes: list[str | None] = [None] * _TABLED
        """Whole part (below ``_TABLED``) -> the key's text with it, where made."""
        self.negatives: list[str | None] = [None] * _TABLED
        """The same for a negative number's whole part (``', "x": -0'``)."""

    def whole(self, whole: int, negative: bool) -> str:
        """The key's text with the whole part ``whole`` (below ``_TABLED``), its sign before it where ``negative``.
        Made with the others of its ``_KEYED_RUN`` (its neighbours: a CAM program's next points), one after another:
        made one at a time as met, each lay wherever the blocks of its time left room, and missed the cache at
        each look-up (perf at 300k blocks: ~3% of ``toolpath``'s time in its reference-count increment)."""
        table = self.negatives if negative else self.wholes
        piece = table[whole]
        if piece is None:
            text = self.text
            first = whole - whole % _KEYED_RUN
            for n in range(first, min(first + _KEYED_RUN, _TABLED)):
                if table[n] is None:
                    table[n] = text + (_NEGATIVE[n] if negative else _WHOLE[n])
            piece = table[whole]
            assert piece is not None
        return piece


_KEYED_RUN: Final = 50
"""The whole parts whose ``_KeyedNumbers`` texts are made together."""


_RECORD_KEYS: Final = _KeyTexts()


def _number_parts(value: float | int, parts: list[str]) -> None:
    """A record's number (``num``'s: an int or a float) as json writes it."""
    if isinstance(value, float):
        _float_parts(value, parts)
    else:
        parts.append(str(value))


def _keyed_number_parts(value: float | int, keyed: _KeyedNumbers, parts: list[str]) -> None:
    """A record's key and its number as json writes them (``keyed.text``, then ``_number_parts``), the key and the
    number's whole part in one piece where it is tabled (``_KeyedNumbers``)."""
    if isinstance(value, float):
        _keyed_float_parts(value, keyed, parts, None)
    elif 0 <= value < _TABLED:
        parts.append(keyed.whole(value, False))
    elif -_TABLED < value < 0:
        parts.append(keyed.whole(-value, True))
    else:
        parts.append(keyed.text)
        parts.append(str(value))


def _keyed_float_parts(value: float, keyed: _KeyedNumbers, parts: list[str], tail: _Tail | None) -> None:
    """``_keyed_number_parts`` of a float (a float parameter: compiled, unboxed once, where a union's value was
    unboxed again at each comparison; the units machine integers, ``i64``, not tagged ones checked at each step).
    ``tail``: the fixed text that follows the number (``_CLOSING``), a short fraction joined with it in one piece."""
    if _SMALLEST <= value < _LARGEST or -_LARGEST < value <= -_SMALLEST:  # (as ``_float_parts``)
        units = i64(value * _SCALE + (0.5 if value > 0.0 else -0.5))
        if float(units) / _SCALE == value:
            negative = units < 0
            magnitude = -units if negative else units
            whole = magnitude // _UNITS
            if whole < _TABLED:
                piece = keyed.negatives[whole] if negative else keyed.wholes[whole]
                parts.append(piece if piece is not None else keyed.whole(whole, negative))
                fraction = magnitude - whole * _UNITS
                if fraction % _SHORT_STEP == 0:  # ``_fraction_parts``' first case here: a call less a number
                    index = fraction // _SHORT_STEP
                    high = index // _PAIRS
                    low = index - high * _PAIRS
                    if tail is None:
                        if low == 0:
                            parts.append(_PAIR_ONLY[high])
                        else:
                            parts.append(_PAIR_FIRST[high])
                            parts.append(_PAIR_REST[low])
                    elif low == 0:
                        parts.append(tail.onlys[high])
                    else:
                        parts.append(_PAIR_FIRST[high])
                        parts.append(tail.rests[low])
                    return
                _fraction_parts(fraction, parts)
                if tail is not None:
                    parts.append(tail.text)
                return
    parts.append(keyed.text)
    _float_parts(value, parts)
    if tail is not None:
        parts.append(tail.text)


@mypyc_attr(allow_interpreted_subclasses=True)
class _Tail:
    """A fixed text that follows a number in a line (a record's closing), joined with the short fractions' last
    pieces (``_PAIR_ONLY``, ``_PAIR_REST``): one piece where there were two."""

    def __init__(self, text: str) -> None:
        self.text = text
        self.onlys: list[str] = [only + text for only in _PAIR_ONLY]
        self.rests: list[str] = [rest + text for rest in _PAIR_REST]


_LINE_HIGH: Final[list[str | None]] = [None] * _TABLED
"""A line number's thousands (from 1) -> the line's opening text with them (``'{"line": 12'`` for 12,345), made the
first time met; ``_KindTexts.padded`` follows with the last three digits and the kind."""
_LINES_TABLED: Final = _TABLED * _TABLED


def _line_kind_parts(line: int, kind: _KindTexts, parts: list[str]) -> None:
    """Append a record's opening brace with its ``line`` and ``move`` items (``'{"line": 12345, "move": "feed"'``):
    from tables, one piece for a line below ``_TABLED`` and two below ``_LINES_TABLED``, where ``str`` of the number
    cost ~220 instructions a line (compiled; a line has a new number) and each piece ~110 in the append, the join
    and the list's clearing."""
    if 0 <= line < _TABLED:
        text = kind.low[line]
        if text is None:
            text = _KEYS_LINE + _WHOLE[line] + kind.text
            kind.low[line] = text
        parts.append(text)
    elif _TABLED <= line < _LINES_TABLED:
        high = line // _TABLED
        head = _LINE_HIGH[high]
        if head is None:
            head = _KEYS_LINE + _WHOLE[high]
            _LINE_HIGH[high] = head
        parts.append(head)
        parts.append(kind.padded[line - high * _TABLED])
    else:
        parts.append(_KEYS_LINE)
        parts.append(str(line))
        parts.append(kind.text)


_CLOSE: Final = "}"
_CLOSE_LINE: Final = "}\n"
_CLOSE_BOTH: Final = "}}"
_CLOSE_BOTH_LINE: Final = "}}\n"
"""A record's closing text: the event's brace (with the line end where ``write_lines`` writes it), after the
controlled point's brace where it has one (one piece)."""
_CLOSING: Final = _Tail(_CLOSE_BOTH_LINE)
"""The closing of a line that ends with its controlled point (a CAM program's moves under a tool length), joined
with its last short fraction."""


def _record_parts(record: MoveRecord, parts: list[str], line_end: bool) -> None:
    """Append the JSON text of ``record`` (``MoveRecord.event()``'s, with its closing brace and, where ``line_end``,
    the line end): field by field, in the order ``event()`` gives its keys, with no look-up or type test of a key
    (``tests/test_toolpath_numbers.py`` holds it to json's text of ``event()``)."""
    texts = _RECORD_KEYS
    keys = record.keys
    if keys is not texts.keys:
        texts.update(keys)
    kind = record.kind
    _line_kind_parts(record.line, texts.kind_texts if kind is texts.kind else texts.kind_of(kind), parts)
    later = texts.later
    point = record.point
    for i in range(len(keys)):
        value = point[i]
        if isinstance(value, float):  # (most often: the float's own call, not through the union's)
            _keyed_float_parts(value, later[i], parts, None)
        else:
            _keyed_number_parts(value, later[i], parts)
    centre = record.centre
    if centre is not None:  # an arc: its centre and plane
        centre_keys = record.centre_keys
        for i in range(len(centre_keys)):
            parts.append(_key_text(centre_keys[i], True))
            _number_parts(centre[i], parts)
        parts.append(_KEY_PLANE)
        plane = record.plane
        parts.append("null" if plane is None else _word_text(plane))
    f = record.f
    mode = record.feed_mode
    controlled = record.controlled
    if f is not None:
        if f is not texts.f:  # (identity: the same object has the same text; an equal one is spelt again)
            texts.feed(f)
        parts.append(texts.f_text)
    if mode is not None:
        parts.append(_KEY_FEED_MODE)
        parts.append(_word_text(mode))
    if controlled is None:
        parts.append(_CLOSE_LINE if line_end else _CLOSE)
        return
    ccentre = record.ccentre
    if not keys:
        parts.append(_KEY_CONTROLLED)
        if ccentre is None or not record.centre_keys:
            parts.append("{}")
            parts.append(_CLOSE_LINE if line_end else _CLOSE)
            return
    first = texts.first
    last = len(keys) - 1 if line_end and ccentre is None else -1  # the number the closing follows (-1: none)
    for i in range(len(keys)):
        value = controlled[i]
        keyed = first[i]
        if i == last:
            if isinstance(value, float):
                _keyed_float_parts(value, keyed, parts, _CLOSING)
            else:
                _keyed_number_parts(value, keyed, parts)
                parts.append(_CLOSE_BOTH_LINE)
            return
        if isinstance(value, float):
            _keyed_float_parts(value, keyed, parts, None)
        else:
            _keyed_number_parts(value, keyed, parts)
    if ccentre is not None:
        centre_keys = record.centre_keys
        for i in range(len(centre_keys)):
            parts.append(_key_text(centre_keys[i], i > 0 or len(keys) > 0))
            _number_parts(ccentre[i], parts)
    parts.append(_CLOSE_BOTH_LINE if line_end else _CLOSE_BOTH)


def event_text(event: dict[Any, Any] | MoveRecord, fallback: Callable[[Any], str]) -> str:
    """The JSON text of one event (without its line end)."""
    parts: list[str] = []
    if isinstance(event, MoveRecord):
        _record_parts(event, parts, False)
        return "".join(parts)
    if not event:
        return "{}"
    if not _items_parts(event, parts, 0):
        return fallback(event)
    parts.append("}")
    return "".join(parts)


_CHUNK: Final = 256
"""Lines joined and written at once by ``write_lines``."""


@mypyc_attr(allow_interpreted_subclasses=True)
class EventValueError(ValueError):
    """A value of ``event`` that JSON cannot hold (not finite): ``write_lines`` wrote the lines before it."""

    def __init__(self, message: str, event: dict[Any, Any]) -> None:
        super().__init__(message)
        self.event = event


def write_lines(events: Iterable[dict[Any, Any] | MoveRecord], write: Callable[[str], object],
                fallback: Callable[[Any], str]) -> None:
    """Write each event as its JSON line (``event_text``) through ``write``, ``_CHUNK`` lines at a time: one join
    and one write a chunk, not a list, a join, a concatenation and a text file's write a line (~2k
    instructions a toolpath event). The lines before an error (from ``events`` or an event's value:
    ``EventValueError``) are written before it propagates, as line by line."""
    parts: list[str] = []
    count = 0
    try:
        for event in events:
            mark = len(parts)
            try:
                if isinstance(event, MoveRecord):
                    _record_parts(event, parts, True)
                elif not event:
                    parts.append("{}\n")
                elif _items_parts(event, parts, 0):
                    parts.append("}\n")
                else:
                    del parts[mark:]
                    parts.append(fallback(event) + "\n")
            except ValueError as err:
                del parts[mark:]
                raise EventValueError(str(err), event.event() if isinstance(event, MoveRecord) else event) from None
            count += 1
            if count == _CHUNK:
                text = "".join(parts)
                parts.clear()
                count = 0
                write(text)
    finally:
        if parts:
            text = "".join(parts)
            parts.clear()
            write(text)
