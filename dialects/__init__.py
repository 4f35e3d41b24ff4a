"""Built-in dialect plugins. Each registers through the ``postproc`` entry-point group like any plugin."""
