"""The syntax objects of a reading pipeline that have no package of their own, and what they are made of.

``syntax`` (``Syntax``, the base class, and ``Pipeline``, which runs syntax objects over a block stream),
``lines`` (the check every program line passes before a reader lexes it), ``comments`` (``CommentSyntax``: a
controller's comment syntax as data), ``program`` (``ProgramSyntax``: stores and runs a program that computes,
over ``postproc.interp``), ``modal_state`` (``ModalStateSyntax``: carries the modal state from block to block),
``kept_lines`` and ``power_on_units``. The other syntax objects live with what they read: the hole-cycle step in
``postproc.cycles.resolve``, the families' block syntaxes in their family bases (``postproc.rs274``,
``postproc.isg_family``, ``postproc.grbl_family``).
"""
