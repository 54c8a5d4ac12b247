"""Check results shared by every validator."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass
class CheckResult:
    """One named check of one object: pass or fail, with the numbers that decided it."""

    name: str
    ok: bool
    detail: str = ""
