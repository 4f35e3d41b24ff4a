"""``python -m postproc``: the command line (the process of the ``postproc`` command: postproc.commands.launch)."""

from .commands.launch import run

run()
