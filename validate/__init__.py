"""Reading finished object folders back, as a user's simulator would.

:func:`validate_object` runs the USD checks (:mod:`.usd_check`) and, with
``sim=True``, the simulator checks (:mod:`.sim`) of one folder. It never trusts
the model in memory: it reads the written files.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from .files import find_objects
from .result import CheckResult


@dataclass
class ObjectReport:
    folder: Path
    checks: list[CheckResult] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return bool(self.checks) and all(c.ok for c in self.checks)

    @property
    def failed(self) -> list[CheckResult]:
        return [c for c in self.checks if not c.ok]


def validate_object(folder: str | Path, sim: bool = True) -> ObjectReport:
    """Validate one object folder; ``sim`` adds the SAPIEN and ManiSkill checks."""
    from .usd_check import check_usd

    folder = Path(folder)
    report = ObjectReport(folder, check_usd(folder))
    if sim:
        from .sim import check_maniskill, check_sapien

        report.checks += check_sapien(folder)
        report.checks += check_maniskill(folder)
    return report


__all__ = ["CheckResult", "ObjectReport", "find_objects", "validate_object"]
