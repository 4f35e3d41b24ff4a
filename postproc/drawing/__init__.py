"""Drawings of a toolpath: a backplot as SVG or PNG, and verify's overlay of two toolpaths.

``backplot``, ``overlay``, the two surfaces they draw on (``canvas``) and the points they keep on disk
(``pointstore``).
"""
