"""The fast lane: every speed-only shortcut of a run, in one place above the family bases.

The classes dialects extend (the word writer, the block syntax, the cycle resolver) each write or read one
way; a shortcut here copies part of that way for the commonest blocks, is chosen per run by the lane itself
where the classes it copies are the base's own, and is held to the general path by a differential
property test. A plugin declares nothing for it.

* ``lane``: the writer's lane (``install``), ``straight``: its shortcuts (``StraightLane``, ``CopyLane``);
  ``tests/test_straight_moves.py``.
* ``reading``: the reading lanes (``install_reading``), ``plain``: the plain-block lane of the block syntax
  and ``plain_ngc`` the RS274/NGC one (``tests/test_plain_blocks.py``), ``holes``: the next-hole lane of the
  cycle resolver (``tests/test_cycle_repeat.py``).
* ``expansion_moves``: the expansion-move lane (``install_expansion``), an expanded cycle's straight moves
  written without the writer's item dispatch (``tests/test_expansion_moves.py``).
* ``setup_values``: the set-up lane (``plain_record``), a set-up file's plainly spelt values read without
  pydantic, which decides the rest (``tests/test_setup_values.py``).

Nothing is imported here: a run imports the lanes it installs, with the modules they copy.
"""
