"""The ``postproc`` command: its argument parsing and its subcommands' own helpers.

``cli`` (the stable interface of DESIGN.md), ``launch`` (the process), ``batch`` (translating folders,
locally or on a cluster), ``export`` (toolpath files), ``dialect_table`` (``postproc dialects``),
``program_xml`` (``postproc ir``) and ``progress`` (the progress bar).
"""
