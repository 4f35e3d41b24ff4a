"""ISG's (Beckhoff TwinCAT CNC) cutter radius compensation, as far as its manual's text says it: why it is not
simulated (``Isg.CUTTER_RULES`` stays None; ``Isg.CUTTER_RULES_LACK`` says why in the verify report), so that a
``G41``/``G42`` towards or from ISG is compared as a setting, not as a path (docs/verify.md). Researched for
issue 26 (tool26); tags as in DIALECTS.md.

TF5200 programming manual (infosys.beckhoff.com, the stored pages):

* [V] "Tool radius compensation (TRC)" (tf5200_programming_manual/207729163): G40 (initial state)/G41/G42 are modal
  and act in the G17/G18/G19 plane with the radius of the D word in force; a negative radius swaps the side; a new
  D (or ``V.G.WZ_AKT.R``) changes the radius with TRC on.
* [V] the selection methods, same page and tccncprogramming/15556736651: G139 indirect (modal, initial state), G138
  direct, G236 direct on the path, G237 perpendicular, G238 at an inside corner, G239 without a block, G05
  tangential (one block). [V] tccncprogramming/15557090955 "Direct/indirect selection": the approach block is made
  with the next moving block, only where the first two moves are line-line or line-arc (an arc first is an error);
  its geometry for each transition angle is given by the figures only (no text there) [?].
* [V] tccncprogramming/15557104779 "Departing blocks at deselection": likewise line-line and arc-line only, the
  standard and the G138 departures in figures only [?].
* [V] tccncprogramming/15557092491 "Perpendicular selection and deselection (G237)": a linear block orthogonal to
  the programmed path, "before the first programmed motion block", makes the offset; deselection adds one that
  reverses it. Known in text, but not the initial state.
* [V] tccncprogramming/15556739211 "G25/G26": outside corners get transition blocks, linear (G25, modal, initial
  state) or circular (G26). [V] tf5200_programming_manual/207816715 "Generate compensation blocks", its table of
  blocks inserted by transition angle: 0-180 degrees (an inside corner) none, the two offset elements shortened to
  meet [V: tf5262 1116639243 "the two block elements are shortened"]; line-line 180-270: G25 none (the offset
  paths meet), G26 one arc; 270-360: G25 one line, G26 one arc; line-arc 180-270 one line (G25), 270-360 two
  lines; arc-arc two and three lines. Where those inserted lines start and end is in the figures only [?].

So the start-up and cancel moves of the state a program starts in are not known in text: a path
simulated from guesses could pass a wrong translation. Compensation stays a setting: kept native between the two
families (``G41`` ``D``), resolved into the path only from a source whose rules are simulated (LinuxCNC, Fanuc M)
towards a target without compensation, and ISG's ``G25``/``G26``/``G138``/``G139``/``G236``-``G239``/``G05`` and
Fagor's ``G136``-``G139`` are kept verbatim (round-trip, refused elsewhere by name, not simulated).
"""
