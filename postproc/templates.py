"""Header and footer templates: jinja2 in a sandbox, with undefined names as errors.

Templates come from configuration files an integrator may not fully trust: the sandbox refuses
attribute access to internals, and every template error becomes a located ``ConfigError``.
"""

from __future__ import annotations

import contextlib
import signal
import threading
from typing import Any, Iterator

from jinja2 import StrictUndefined, TemplateError
from jinja2.exceptions import SecurityError
from jinja2.sandbox import SandboxedEnvironment

from .errors import ConfigError, Location
from .setup import MachineSetup

MAX_OUTPUT = 1 << 20
MAX_EXPONENT = 256
TIME_LIMIT = 5.0
"""Seconds a template may render (enforced with an interval timer in the main thread)."""


class _BoundedSandbox(SandboxedEnvironment):
    """The jinja2 sandbox, plus bounds on the operators that can exhaust memory or time
    (``9**9**9``, ``'x' * 10**9``): the sandbox alone only guards attribute access."""

    intercepted_binops = frozenset(["**", "*"])

    def call_binop(self, context: Any, operator: str, left: Any, right: Any) -> Any:
        if operator == "**" and isinstance(right, (int, float)) and abs(right) > MAX_EXPONENT:
            raise SecurityError(f"exponent {right} is larger than {MAX_EXPONENT}")
        if operator == "*":
            for seq, count in ((left, right), (right, left)):
                if isinstance(seq, (str, list, tuple)) and isinstance(count, int) and len(seq) * count > MAX_OUTPUT:
                    raise SecurityError(f"repetition would make more than {MAX_OUTPUT} items")
        return super().call_binop(context, operator, left, right)


_ENV = _BoundedSandbox(undefined=StrictUndefined, autoescape=False, keep_trailing_newline=True)


class _TimeLimit(Exception):
    pass


@contextlib.contextmanager
def _time_limit(seconds: float) -> Iterator[None]:
    """Stop a runaway template (nested loops) after ``seconds``; only possible in the main thread."""
    if threading.current_thread() is not threading.main_thread() or not hasattr(signal, "setitimer"):
        yield
        return

    def expire(signum: int, frame: Any) -> None:
        raise _TimeLimit()

    previous = signal.signal(signal.SIGALRM, expire)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def render(name: str, text: str, variables: dict[str, Any], source: str | None, first_line: int = 1) -> str:
    """Render one template. ``first_line`` is the line of the set-up file the template text starts on."""
    try:
        with _time_limit(TIME_LIMIT):
            result = _ENV.from_string(text).render(**variables)
    except TemplateError as exc:
        raise _located(name, exc, source, first_line) from None
    except _TimeLimit:
        raise ConfigError(f"template {name} ran longer than {TIME_LIMIT:g} s", Location(source or "<set-up>", first_line, 1)) from None
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
