"""Header and footer templates: jinja2 in a sandbox, with undefined names as errors.

Templates come from configuration files an integrator may not fully trust: the sandbox refuses
attribute access to internals, and every template error becomes a located ``ConfigError``.
"""

from __future__ import annotations

from typing import Any

from jinja2 import StrictUndefined, TemplateError
from jinja2.sandbox import SandboxedEnvironment

from .errors import ConfigError, Location
from .setup import MachineSetup

_ENV = SandboxedEnvironment(undefined=StrictUndefined, autoescape=False, keep_trailing_newline=True)
MAX_OUTPUT = 1 << 20


def render(name: str, text: str, variables: dict[str, Any], source: str | None, first_line: int = 1) -> str:
    """Render one template. ``first_line`` is the line of the set-up file the template text starts on."""
    try:
        result = _ENV.from_string(text).render(**variables)
    except TemplateError as exc:
        raise _located(name, exc, source, first_line) from None
    if len(result) > MAX_OUTPUT:
        raise ConfigError(f"template {name} renders more than {MAX_OUTPUT} characters",
                          Location(source or "<set-up>", first_line, 1))
    if result and not result.endswith("\n"):
        result += "\n"
    return result


def check_templates(setup: MachineSetup) -> None:
    """Compile the set-up's templates so syntax errors surface at ``config check``."""
    for name in ("header", "footer"):
        text = getattr(setup.templates, name)
        if text is None:
            continue
        try:
            _ENV.parse(text)
        except TemplateError as exc:
            raise _located(name, exc, setup.source, setup.template_lines.get(name, 1)) from None


def _located(name: str, exc: TemplateError, source: str | None, first_line: int) -> ConfigError:
    """A template error at its line in the set-up file (runtime errors carry the line only in the
    traceback jinja2 rewrites to point into the template)."""
    line = getattr(exc, "lineno", None)
    tb = exc.__traceback__
    while line is None and tb is not None:
        if tb.tb_frame.f_code.co_filename == "<template>":
            line = tb.tb_lineno
        tb = tb.tb_next
    return ConfigError(f"template {name}: {exc.message or exc}",
                       Location(source or "<set-up>", first_line + (line or 1) - 1, 1))
