"""The fast lane: every speed-only shortcut of a run, in one place above the family bases.

The classes dialects extend (the word writer, the block syntax, the cycle resolver) each write or read one
way; a shortcut here copies part of that way for the commonest blocks, is chosen per run by the lane itself
where the classes it copies are the base's own, and is held to the general path by a differential
property test. A plugin declares nothing for it.

* ``lane``: the writer's lane (``install``), ``straight``: its shortcuts (``StraightLane``, ``CopyLane``,
  ``SourceLane``, which puts a copied line into the output batch itself: ``Lane.put``);
  ``tests/test_straight_moves.py``.
* ``reading``: the reading lanes (``install_reading``), ``plain``: the plain-block lane of the block syntax
  (``read``, and ``read_marked`` for a canonical line whose words the Fanuc reader left unmade, ``Block.marks``,
  read where they stand in it, their numbers as the reader's scan read them: ``canonical_line.LineNumbers``) and
  ``plain_ngc`` the RS274/NGC one (``tests/test_plain_blocks.py``), ``holes``: the next-hole lane of the
  cycle resolver (``tests/test_cycle_repeat.py``).
* ``expansion_moves``: the expansion-move lane (``install_expansion``), an expanded cycle's straight moves
  written without the writer's item dispatch (``tests/test_expansion_moves.py``).
* ``setup_values``: the set-up lane (``plain_record``), a set-up file's plainly spelt values read without
  pydantic, which decides the rest (``tests/test_setup_values.py``).

Nothing is imported here: a run imports the lanes it installs, with the modules they copy.

What reads a line is not here, by decision (issue 30, item 2 of the review): each reading shortcut was either
the one algorithm or has gone, so the reading has one path, compiled or pure.

* The byte scan of a line of words (``rs274.canonical_line.scan_words``, ISO family) IS the family's reading of
  plain words, not a copy of it: ``rs274.lexer.lex_block`` reads every line's words with it, and the Fanuc
  reader reads a whole plain line with it (its block, block number and canonical hint from the one pass).
  The reader's second lane (a ``WORDS_ONLY`` full match and ``WORD.findall`` for the lines the scan left:
  lower case, tabs, ``;``) has gone: the scan reads those lines too. The regexes stay only as the scan's
  definition, which ``tests/test_canonical_line.py`` holds it to on random lines.
* ``rs274.ngc_lexer.plain_words`` is likewise RS274/NGC's one reading of plain words; its one-regex fallback
  (for a line that is not ASCII) has gone: such a line is the slow path's (``_slow_words``), which reads the
  same words (``tests/test_ngc_plain_words.py``).
* ``syntaxes.lines`` checks a chunk of lines with a few C calls (ASCII, no run of more than ``MAX_DIGITS``
  digits, no stray line separator, no long line) and a chunk that fails them line by line
  (``line_problem``): the chunk test is a sufficient condition for ``line_problem`` finding nothing, not a
  second check, so it never decides a line is wrong; ``tests/test_lines.py`` holds the two to the same lines
  and errors on random chunks, as it holds a stream read many lines at once to the same stream read a line
  at a time. Its lines come as runs too (``CheckedLines.runs``, what the Fanuc and RS274/NGC readers read): a
  stream's piece of lines that all end alike as their texts, split from that end by one ``str.split``, and any
  other lines with their ends, which the reader splits itself. That is the one way a reader reads, not a lane:
  the same lines split where they were split before (``tests/test_lines.py`` holds runs to the lines with their
  ends, and the readers' blocks read from runs to those read from lines, on random programs).
"""
