"""Reading finished object folders back, as a user's simulator would.

:func:`validate_object` runs, on the written files only (never the model in memory):

* always: the USD checks (:mod:`.usd_check`): every ``pxr.UsdValidation`` validator,
  the UsdPhysics parse, joint-frame agreement, referenced files, USD/URDF agreement;
* with ``sim`` (default): SAPIEN physics on CPU (:mod:`.sim`): the URDF loads
  (``sapien_load``) and every movable joint driven alone reaches both limits (``reach``);
* with ``simready``: NVIDIA's validators (:mod:`.simready`): SimReady Robotics-Prop 4.0.0, the
  articulation and driven-joint features of Robot-Body 3.0.0, omniverse-asset-validator's defaults;
* with ``physics``: the plausibility checks of ``infmob validate --sim``: passive
  joints hold still under gravity (``rest``), the geometric ``ground``,
  ``self_collision`` and ``parent_child`` checks (:mod:`.physics`), and loading
  through ManiSkill (``maniskill_load``).
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


def validate_object(folder: str | Path, sim: bool = True, physics: bool = False,
                    simready: bool = False) -> ObjectReport:
    """Validate one object folder (see the module docstring for what each flag adds)."""
    if simready:  # the PhysX schemas must be registered before USD's schema registry is first used
        from .simready import available, install_physx_shim

        if available():
            install_physx_shim()
    from .usd_check import check_usd

    folder = Path(folder)
    report = ObjectReport(folder, check_usd(folder))
    if simready:
        from .simready import check_simready

        report.checks += check_simready(folder)
    if sim or physics:
        from .sim import check_sapien

        report.checks += check_sapien(folder, checks=["reach", "rest"] if physics else ["reach"])
    if physics:
        from .physics import check_physics
        from .sim import check_maniskill

        report.checks += check_physics(folder)
        report.checks += check_maniskill(folder)
    return report


__all__ = ["CheckResult", "ObjectReport", "find_objects", "validate_object"]
