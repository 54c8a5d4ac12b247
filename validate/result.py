"""Check results shared by every validator, and :func:`guarded`: a check that raises is a failed check."""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any


@dataclass
class CheckResult:
    """One named check of one object: pass or fail, with the numbers that decided it."""

    name: str
    ok: bool
    detail: str = ""


_PXR = re.compile(r"Error in '[^']*' at line \d+ in file \S+ : '(.*?)'(?= Error in |$)")


def one_line(exc: BaseException, limit: int = 240) -> str:
    """``Type: message`` of an exception on one line (plain text: picklable, unlike ``pxr.Tf.Error``).

    OpenUSD's ``Error in 'function' at line N in file F : 'message'`` is cut to its message.
    """
    text = " ".join(str(exc).split()) or repr(exc)
    found = _PXR.findall(text)
    if found:
        text = found[0]
    if len(text) > limit:
        text = text[: limit - 3] + "..."
    return f"{type(exc).__name__}: {text}"


def guarded(name: str, fn: Callable[..., Any], *args: Any, **kwargs: Any) -> list[CheckResult]:
    """Run a check (returning one :class:`CheckResult` or a list of them) so that it cannot crash.

    Any exception becomes one failed check ``name`` whose detail is the exception on one line:
    a corrupt, truncated or missing file is a FAIL of that object, never the end of a run.
    """
    try:
        out = fn(*args, **kwargs)
    except Exception as exc:  # noqa: BLE001 - a broken file may raise anything (pxr, XML, OSError ...)
        return [CheckResult(name, False, f"crashed on this object: {one_line(exc)}")]
    return [out] if isinstance(out, CheckResult) else list(out)
