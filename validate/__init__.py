"""Reading finished object folders back, as a user's simulator would.

:func:`validate_object` runs, on the written files only (never the model in memory):

* always: the USD checks (:mod:`.usd_check`): every ``pxr.UsdValidation`` validator,
  the UsdPhysics parse, joint-frame agreement, referenced files, USD/URDF agreement;
* with ``sim`` (default): SAPIEN physics on CPU (:mod:`.sim`): the URDF loads
  (``sapien_load``) and every movable joint driven alone reaches both limits (``reach``);
* with ``physics``: the plausibility checks of ``infmob validate --sim``: passive
  joints hold still under gravity (``rest``), the geometric ``ground``,
  ``self_collision`` and ``parent_child`` checks (:mod:`.physics`), and loading
  through ManiSkill (``maniskill_load``).

Every check runs under :func:`~.result.guarded`: a check that raises (a truncated usdc, a
garbage URDF, a deleted file ...) is reported as a failed check with the exception on one
line, and the other checks and objects go on. New checks should be added the same way.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from .files import find_objects
from .result import CheckResult, guarded


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


def validate_object(folder: str | Path, sim: bool = True, physics: bool = False) -> ObjectReport:
    """Validate one object folder (see the module docstring for what each flag adds)."""
    from .usd_check import check_usd

    folder = Path(folder)
    report = ObjectReport(folder, guarded("usd", check_usd, folder))
    if sim or physics:
        from .sim import check_sapien

        report.checks += guarded("sapien_load", check_sapien, folder,
                                 checks=["reach", "rest"] if physics else ["reach"])
    if physics:
        from .physics import check_physics
        from .sim import check_maniskill

        report.checks += guarded("physics", check_physics, folder)
        report.checks += guarded("maniskill_load", check_maniskill, folder)
    return report


__all__ = ["CheckResult", "ObjectReport", "find_objects", "guarded", "validate_object"]
