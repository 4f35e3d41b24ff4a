"""grblHAL's lathe mode (``$32``, ``settings.mode == Mode_Lathe``): the RS274/NGC lathe words, read and written by
the shared modules ``postproc.rs274.ngc_lathe`` and ``ngc_lathe_writer`` (LinuxCNC's spelling), with what
grblHAL adds or lacks. From ``gcode.c`` (github.com/grblHAL/core, stored commit f80fc34) [V]:

* ``G7``/``G8`` exist only in lathe mode (else error 20, ``Status_GcodeUnsupportedCommand``); under G7 every X
  word is halved (``gc_block.values.xyz[X_AXIS] /= 2``, G91 increments too), arcs' I/K are not. So a lathe
  set-up (``<Input machineType="lathe">``) is read and written in lathe mode, and on a mill set-up G7, G8,
  G33, G96 and G97 are refused where read (G33 and G96 outside lathe mode are not modelled).
* ``G96 S.. D..``: S in m/min (G21) or ft/min (G20), converted to mm/min; the spindle turns at S / (2 pi r),
  r the X position in work coordinates (a radius), clamped at D, or at the spindle's maximum where the G96
  has no D; ``G97`` ends it. A feed move (G1-G3, G33) under G96 with the spindle stopped, or S 0, is error 41
  (``Status_GcodeSpindleNotRunning``): the writer refuses such a move.
* ``G33 X.. Z.. K..``: the planner's feed is K per spindle revolution along the path
  (``init_sync_motion``), so K is LinuxCNC's. It needs a spindle that reports its position (``get_data``:
  ``<Controller spindleSync="true">``). grblHAL takes a missing K from the last G33 and accepts an F beside
  it: this reader refuses both (stricter), the writer writes K every time and the F on a line before.
* ``G43 H`` applies the tool table's offsets on every axis (``tool_offset_apply``; ``TOOL_LENGTH_OFFSET_AXIS``
  -1 by default), so a Fanuc T turret index ``T0101`` is written ``T1 M6`` and ``G43 H1`` as for LinuxCNC, on a
  build with a tool table (``<Controller toolTable="true">``); without one the X offset has no word (G43.1's
  X would be halved under G7: not modelled) and the offset is refused (``GrblhalLatheWriter``).
* ``G76`` (``mc_thread``): LinuxCNC's words, with its own moves (``threading``): read into them, kept native in a
  grblHAL program. Another controller's threading cycle reaches grblHAL as G33 passes (its expansion), as it
  reaches LinuxCNC: no other cycle moves as grblHAL's (LinuxCNC's G76 first retracts from the drive line and
  leaves each pass at its own depth's retract, grblHAL's goes straight in and leaves at the next pass's; Fanuc T's
  G76 and G92 return to the start X after every pass).
"""

from __future__ import annotations

from typing import Final

from postproc.rs274.ngc_lathe import Said

GRBLHAL_SAID: Final = Said(
    s_missing="grblHAL: error 28, a value word missing",
    f_beside="grblHAL sets the feed rate from it, which this reader does not model",
    k_missing="grblHAL would take the last G33's K, which this reader does not model")
"""What grblHAL says, or does, where the shared reader refuses (``postproc.rs274.ngc_lathe``)."""
NOT_LATHE: Final = ("grblHAL runs G{num} in lathe mode only ($32, error 20 otherwise): a set-up with <Input "
                    "machineType=\"lathe\"/> reads and writes grblHAL's lathe mode")
NO_SYNC: Final = ("G33 needs a grblHAL spindle that reports its position (error 20 otherwise): a set-up with "
                  "<Controller spindleSync=\"true\"/> has one")
NO_SYNC_WRITTEN: Final = ("a thread move (G33) on a grblHAL spindle without an encoder: a set-up with <Controller "
                          "spindleSync=\"true\"/> has one")
