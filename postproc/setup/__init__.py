"""The machine set-up: the parameters of one controller installation, kept as XML.

``machine_setup`` (``MachineSetup``, ``load_setup``), its groups of parameters (``groups``: ``<Input>``,
``<Output>``, ``<Cycles>``...), the machine's geometry (``machine``: axes, work offsets), the plain records
they are made of (``record``), how a file is loaded and merged (``load``) and validated at that boundary
(``validate``), and the base set-ups a file may extend (``bases/``).
"""
