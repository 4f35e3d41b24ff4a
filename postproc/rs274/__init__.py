"""The RS274 family base (Fanuc, LinuxCNC, grbl, ...): lexer, block syntax, writer, code tables."""
