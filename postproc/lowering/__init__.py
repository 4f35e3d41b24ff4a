"""Lowering: pure IR-to-IR steps chosen from the target's capabilities, between reading and writing.

``lower`` runs them (the generic steps plugins register, then the target's own); the steps of the
program's frame and end (``program_frame``, ``program_end``), machine-specific codes
(``machine_functions``) and the set-up's template sequences (``sequences``). The cycles' own lowering
steps are in ``postproc.cycles`` and ``postproc.patterns``.
"""
