"""The neutral steps of a reading pipeline that have no package of their own.

``program`` (``ProgramSyntax``: stores and runs a program that computes, over ``postproc.interp``) and
``modal_state`` (``ModalStateSyntax``: carries the modal state from block to block). The other syntax
objects live with what they read: the hole-cycle step in ``postproc.cycles.resolve``, the families' block
syntaxes in their family bases (``postproc.rs274``, ``postproc.isg_family``); the base class and the
pipeline are ``postproc.syntax``.
"""
