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
  ``self_collision`` and ``parent_child`` checks (:mod:`.physics`), loading
  through ManiSkill (``maniskill_load``), and the MJCF in MuJoCo (``mujoco``,
  :mod:`.mujoco_sim`: loads, rests, each joint pushed with its effort stays within
  its limits + 5 %, no contact at rest between links that are not parent and child).

A folder written without some format (``generate --formats``) is checked for what it
has: the checks that need a missing file are reported as passed with a detail
``skipped: no URDF`` (and so on), so a report says what was not checked.
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


FORMAT_FILES = {"usd": "{name}.usda", "urdf": "{name}.urdf", "mjcf": "{name}.xml", "glb": "{name}.glb"}
"""Where each format's main file lies in an object folder (as ``infmob_usd.layers.FORMATS`` writes it)."""


def formats_present(folder: Path) -> set[str]:
    """The formats whose main file is in ``folder``."""
    return {f for f, pattern in FORMAT_FILES.items() if (folder / pattern.format(name=folder.name)).is_file()}


def _skipped(names, fmt: str) -> list[CheckResult]:
    return [CheckResult(n, True, f"skipped: no {fmt.upper()} in this folder") for n in names]


def validate_object(folder: str | Path, sim: bool = True, physics: bool = False,
                    simready: bool = False) -> ObjectReport:
    """Validate one object folder (see the module docstring for what each flag adds)."""
    if simready:  # the PhysX schemas must be registered before USD's schema registry is first used
        from .simready import available, install_physx_shim

        if available():
            install_physx_shim()
    folder = Path(folder)
    present = formats_present(folder)
    report = ObjectReport(folder)
    if "usd" in present:
        from .usd_check import check_usd

        report.checks += check_usd(folder)
        if simready:
            from .simready import check_simready

            report.checks += check_simready(folder)
    else:
        report.checks += _skipped(["usd"] + (["simready"] if simready else []), "usd")
    sapien = ["reach", "rest"] if physics else ["reach"]
    if (sim or physics) and "urdf" in present:
        from .sim import check_sapien

        report.checks += check_sapien(folder, checks=sapien)
    elif sim or physics:
        report.checks += _skipped(["sapien_load"] + sapien, "urdf")
    if physics:
        if "urdf" in present:
            from .physics import check_physics
            from .sim import check_maniskill

            report.checks += check_physics(folder)
            report.checks += check_maniskill(folder)
        else:
            report.checks += _skipped(["ground", "self_collision", "parent_child", "maniskill_load"], "urdf")
        if "mjcf" in present:
            from .mujoco_sim import check_mujoco

            report.checks += check_mujoco(folder)
        else:
            report.checks += _skipped(["mujoco"], "mjcf")
    return report


__all__ = ["CheckResult", "ObjectReport", "find_objects", "formats_present", "validate_object"]
