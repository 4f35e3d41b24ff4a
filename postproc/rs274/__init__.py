"""The RS274 family base (Fanuc, LinuxCNC, grbl, later GSK): what the family's dialects share, as
public names they subclass or call. It names no dialect and holds no dialect's codes.

* ``codes``: ``CodeTable`` (rows ``(spelling, modal group, kind, argument)``, read by key and
  inverted for writing) and ``g_key``.
* ``lexer``: the ISO lexer (``lex_block``, ``split_lines``, ``WORD``, ``WORDS_ONLY``, ``NUMBER``).
* ``ngc_lexer``: the RS274/NGC lexer (``;`` comments, blanks inside numbers) and ``NgcReader``.
* ``block_syntax``: ``WordBlockSyntax`` (ISO word rules through ``CODES``), ``col_of_word``,
  ``second_col``.
* ``ngc_block_syntax``: ``NgcWordBlockSyntax`` (RS274/NGC word rules).
* ``ngc_program``: ``NgcProgramSyntax`` (the o-word interpreter step LinuxCNC and grblHAL subclass).
* ``writer``: ``WordWriter`` (every code spelt from ``CODES``; no table of its own).
* ``cycle_words``: ``rs274_cycle_words`` (the family's hole-cycle letters, named from a table).
* ``subprogram_layout``: ``subprograms_after_callers`` (numbered subprograms after their callers, for a
  reader that finds one only after the call), with ``return_level``'s level a cycle needs.
"""
