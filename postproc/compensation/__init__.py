"""Tool compensation as the simulator applies it: the controlled point is the programmed point moved by
the tool length along Z (``tool_length``) and, under cutter radius compensation, by the cutter radius
beside the path (``cutter_radius``). Register values come from ``tool_table``; the controller's rules are
data (``rules``) chosen by the reading dialect, so another controller's rules are a new value, not new
geometry.

The simulation applies them; a translation for a target that lacks a feature resolves it with the same
modules (DESIGN.md, "Machine features the target lacks"): the register values a target without a tool
table needs written (``tool_table``).
"""
