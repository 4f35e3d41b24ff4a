"""Output: the writer base every dialect's writer extends, and what shapes the text it writes.

``writer_base`` (``Writer``), the set-up's line format (``line_format``), a block written in part under
``--on-unsupported warn`` (``partial_block``), header and footer templates in a sandbox (``templates``,
``template_values``, ``bounded``), and writing a file complete or not at all (``outfile``).
"""
