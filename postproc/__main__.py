"""``python -m postproc``: the command line (the process of the ``postproc`` command: postproc.launch)."""

from .launch import run

run()
