"""Plane and arc geometry every part of the core shares, with no dependency on a dialect, the simulator or a
writer: arc centres and lengths (``arcs``), how far an I/J/K arc's end may lie off its circle (``arc_end``),
how far apart two arc paths cut (``arc_paths``), polar points (``polar``), a thread move's lead
(``thread_lead``)."""
