"""The grbl family base (grbl 1.1, grblHAL): what both dialect plugins share, as public names they subclass
or call (a plugin imports no other plugin). ``dialect`` (the family's dialect class, with the capabilities a
build chooses), ``text`` (line rules and comments), ``lengths`` (a length offset from a register written as
the dynamic offset), ``writer``, ``block_syntax``, ``reader``."""
