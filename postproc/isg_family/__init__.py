"""The ISG/Fagor family's public base: what the Beckhoff TwinCAT CNC (ISG kernel) and Fagor 8070
dialects share, so neither imports the other (DIALECTS.md 1.3, 1.4).

* ``lexer``: one block's lexical structure (``;`` and parenthesised comments, block skip, ``%``
  headers, ``N`` numbers and labels, DIN words, ``P``/``V.`` assignments, ``L``/``LL`` calls, where a
  ``$`` statement or a ``#`` command starts); a ``Grammar`` says where the dialects differ.
* ``expressions``: P parameters, ``V.`` variables and bracketed expressions, read and written.
* ``statements``: the ``$`` control statements, paired with a ``Nesting`` stack.
* ``taps``: the rigid tap strokes ``G331``/``G332``, which SINUMERIK spells and means as ISG does (its reader
  takes them from here, as it takes ``tool_data``).

Each dialect keeps its own code table, reader, writer and variables.
"""
