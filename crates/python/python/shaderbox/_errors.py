"""Exceptions and diagnostics."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable, List, Optional, Tuple


class Error(RuntimeError):
    """Base class of shaderbox's own errors."""


@dataclass(frozen=True)
class Diagnostic:
    """One compiler or linker message, located in its shader's source.

    ``line`` and ``column`` are 1-based (``column`` counts bytes); they are
    ``None`` for messages about the whole program. ``stage`` is
    ``"vertex"`` or ``"fragment"`` (``None`` likewise).
    """

    severity: str
    code: str
    message: str
    line: Optional[int] = None
    column: Optional[int] = None
    stage: Optional[str] = None
    source_string: Optional[int] = None
    notes: Tuple[str, ...] = field(default_factory=tuple)

    def __str__(self) -> str:
        where = ""
        if self.line is not None:
            where = f"{self.source_string or 0}:{self.line}({self.column or 0}): "
        return f"{where}{self.severity}: {self.message}"


class Diagnostics(List[Diagnostic]):
    """A list of :class:`Diagnostic` with the renderings of the whole report.

    ``text`` is the rich rendering (each message with its source line and a
    caret), ``info_log`` the GL info log; ``ok`` is whether there is no
    error. ``str()`` gives ``text``.
    """

    def __init__(self, items: Iterable[Diagnostic] = (), *, text: str = "", info_log: str = "", ok: bool = True):
        super().__init__(items)
        self.text = text
        self.info_log = info_log
        self.ok = ok

    @property
    def errors(self) -> List[Diagnostic]:
        return [d for d in self if d.severity == "error"]

    @property
    def warnings(self) -> List[Diagnostic]:
        return [d for d in self if d.severity == "warning"]

    def __str__(self) -> str:
        return self.text

    def __repr__(self) -> str:
        return f"Diagnostics(ok={self.ok}, {list.__repr__(self)})"

    def _repr_pretty_(self, p, cycle) -> None:  # IPython shows the rich text
        p.text(self.text if self.text else ("ok" if self.ok else repr(self)))


def _diagnostics(report) -> Diagnostics:
    ok, diags, text, info_log = report
    items = [
        Diagnostic(
            severity=sev,
            code=code,
            message=msg,
            line=line,
            column=col,
            stage=stage,
            source_string=src,
            notes=tuple(notes),
        )
        for (stage, sev, code, msg, line, col, src, notes) in diags
    ]
    return Diagnostics(items, text=text, info_log=info_log, ok=ok)


class _ProgramError(Error):
    def __init__(self, what: str, diagnostics: Diagnostics):
        self.diagnostics = diagnostics
        self.text = diagnostics.text
        self.info_log = diagnostics.info_log
        first = diagnostics.errors[0] if diagnostics.errors else None
        where = f"{first.stage} shader, " if first and first.stage else ""
        summary = f"{what}: {where}{first}" if first else what
        super().__init__(f"{summary}\n{diagnostics.text}".rstrip())


class CompileError(_ProgramError):
    """A shader did not compile.

    ``diagnostics`` (a :class:`Diagnostics` list: severity, code, message,
    line, column, stage), ``text`` (rendered with the source lines) and
    ``info_log`` (the GL info log) say why.
    """

    def __init__(self, diagnostics: Diagnostics):
        stages = [s for s in ("vertex", "tessellation control", "tessellation evaluation", "geometry", "fragment", "compute") if any(d.stage == s for d in diagnostics.errors)]
        what = " and ".join(stages) + (" shaders" if len(stages) > 1 else " shader") if stages else "the shader"
        super().__init__(f"the {what} did not compile".replace("the the", "the"), diagnostics)


class LinkError(_ProgramError):
    """The shaders compiled but do not link into a program (same fields as
    :class:`CompileError`)."""

    def __init__(self, diagnostics: Diagnostics):
        super().__init__("the program did not link", diagnostics)


class GLError(Error):
    """A GL call was rejected (``code`` is the GL error, ``name`` its name)."""

    def __init__(self, code: int, name: str, during: str):
        self.code = code
        self.name = name
        super().__init__(f"{name} while {during}")
