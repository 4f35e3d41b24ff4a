"""Header and footer templates: jinja2 in a sandbox, with undefined names as errors.

Templates come from configuration files an integrator may not fully trust: the sandbox refuses
attribute access to internals, bounds the operators that blow up (``**``, ``*``), and every render runs
in a child process with bounded memory and time (``postproc.output.bounded``): whatever a template does
(``'x'|center(10**9)``, a doubling loop, ``1/0``, ``{% include %}``, a recursive macro), it ends as a
``ConfigError`` at its line in the set-up file. ``config check`` renders every template with sample
values, so a template that would fail at translation time fails there first.

What ``{{ ... }}`` writes is a value, never code: it is marked while rendering and sealed into a comment
of the target afterwards (``postproc.output.template_values``).
"""

from __future__ import annotations

from typing import Any

from jinja2 import StrictUndefined, TemplateError
from jinja2.exceptions import SecurityError
from jinja2.sandbox import SandboxedEnvironment

from .bounded import MEMORY_LIMIT, run_bounded
from ..syntaxes.comments import CommentSyntax
from ..errors import ConfigError, Location
from .template_values import CLOSE, OPEN, mark, scrub, seal

MAX_OUTPUT = 1 << 20
MAX_EXPONENT = 256
TIME_LIMIT = 5.0
"""Seconds a template may render (the child process is killed after that)."""


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


_ENV = _BoundedSandbox(undefined=StrictUndefined, autoescape=False, keep_trailing_newline=True, finalize=mark)


def render(name: str, text: str, variables: dict[str, Any], source: str | None, first_line: int = 1,
           comments: CommentSyntax | None = None) -> str:
    """Render one template. ``first_line`` is the line of the set-up file the template text starts on;
    ``comments`` the target's comment syntax, where the values written must stand (None: no target
    known, values are made safe but not placed)."""
    return render_all(name, text, [variables], source, first_line, comments)[0]


def render_all(name: str, text: str, variable_sets: list[dict[str, Any]], source: str | None,
               first_line: int, comments: CommentSyntax | None = None) -> list[str]:
    """Render ``text`` once per variable set in one bounded child; the first failure is raised."""
    where = source or "<set-up>"
    if OPEN in text or CLOSE in text:
        raise ConfigError(f"template {name} holds the private-use character U+E000 or U+E001, which "
                          "postproc reserves", Location(where, first_line, 1))
    variable_sets = [scrub(v) for v in variable_sets]
    outcome = run_bounded(lambda: [_render_one(text, v) for v in variable_sets], TIME_LIMIT)
    if outcome.failure == "time":
        raise ConfigError(f"template {name} ran longer than {TIME_LIMIT:g} s", Location(where, first_line, 1))
    if outcome.failure is not None:
        raise ConfigError(f"template {name} needs more than {MEMORY_LIMIT >> 20} MiB of memory",
                          Location(where, first_line, 1))
    results: list[str] = []
    for each in outcome.value:
        if "error" in each:
            raise ConfigError(f"template {name}{each['error']}",
                              Location(where, first_line + (each["line"] or 1) - 1, 1))
        results.append(seal(name, each["text"], comments, Location(where, first_line, 1)))
    return results


def _render_one(text: str, variables: dict[str, Any]) -> dict[str, Any]:
    """In the child: the rendered text, or an error message and its template line (JSON-ready)."""
    try:
        result = _ENV.from_string(text).render(**variables)
    except TemplateError as exc:
        return {"error": f": {exc.message or exc}", "line": _template_line(exc)}
    except MemoryError as exc:  # the failed allocation is freed: there is room to say where
        return {"error": f" needs more than {MEMORY_LIMIT >> 20} MiB of memory", "line": _template_line(exc)}
    except RecursionError as exc:
        return {"error": ": recursion too deep", "line": _template_line(exc)}
    except Exception as exc:  # 1/0, range(10**9), {% include %} without a loader: all the template's fault
        return {"error": f": {exc or type(exc).__name__}", "line": _template_line(exc)}
    if len(result) > MAX_OUTPUT:
        return {"error": f" renders more than {MAX_OUTPUT} characters", "line": None}
    if result and not result.endswith("\n"):
        result += "\n"
    return {"text": result}


def _template_line(exc: BaseException) -> int | None:
    """The template line of an error: syntax errors carry it; runtime errors only in the traceback
    jinja2 rewrites to point into the template (the innermost template frame wins)."""
    line = getattr(exc, "lineno", None)
    if isinstance(line, int):
        return line
    tb = exc.__traceback__
    while tb is not None:
        if tb.tb_frame.f_code.co_filename == "<template>":
            line = tb.tb_lineno
        tb = tb.tb_next
    return line if isinstance(line, int) else None
