"""The distribution's version: ``pyproject.toml`` reads it from here at build time (``[tool.setuptools.dynamic]``,
by setuptools' static reading of this file: nothing is imported), and ``postproc --version`` prints it without
``importlib.metadata``, which imports the email package and reads every installed distribution's metadata
(~100M instructions of ``--version``'s ~260M, pure build)."""

VERSION = "0.1.0"
