"""The postproc conformance suite on this dialect (settings in pyproject.toml)."""

from postproc.testing import ConformanceTests


class TestMach3(ConformanceTests):
    pass
