"""The simulator: a block stream becomes the toolpath a controller would run.

``toolpath`` (events in execution order), ``travel`` (the set-up's axis limits) and ``verify`` (two
programs' toolpaths compared).
"""
