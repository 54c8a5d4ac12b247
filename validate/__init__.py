"""Reading finished object folders back, as a user's simulator would.

:func:`validate_object` runs, on the written files only (never the model in memory):

* always: the USD checks (:mod:`.usd_check`): every ``pxr.UsdValidation`` validator,
  the UsdPhysics parse, joint-frame agreement, referenced files, USD/URDF agreement;
* always (unless ``mass=False``): ``mass``, the total and every moving part's mass within the
  ranges of real products in ``mass_ranges.csv`` (:mod:`.masses`);
* with ``sim`` (default): SAPIEN physics on CPU (:mod:`.sim`): the URDF loads
  (``sapien_load``) and every movable joint driven alone reaches both limits, from rest and from
  the all-open state (``reach``);
* with ``robot``: a floating Panda gripper opens every target of ``annotations.json`` (:mod:`.robot`):
  one ``robot`` result per annotated joint, or a skip when the folder has no annotations;
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

Every check runs under :func:`~.result.guarded`: a check that raises (a truncated usdc, a
garbage URDF, a deleted file ...) is reported as a failed check with the exception on one
line, and the other checks and objects go on. New checks should be added the same way.
"""

from __future__ import annotations

import json
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


FORMAT_FILES = {"usd": "{name}.usda", "urdf": "{name}.urdf", "mjcf": "{name}.xml", "glb": "{name}.glb"}
"""Where each format's main file lies in an object folder (as ``infmob_usd.layers.FORMATS`` writes it)."""


def formats_present(folder: Path) -> set[str]:
    """The formats an object folder holds: those ``metadata.json`` lists (a listed file that is gone is a
    damaged object, and its checks fail), else the files named after the object (its metadata's name,
    else the folder's), so a renamed folder is found too."""
    try:
        meta = json.loads((folder / "metadata.json").read_text())
    except (OSError, ValueError):
        meta = {}
    files = meta.get("files") if isinstance(meta, dict) else None
    if isinstance(files, dict):
        listed = {f for f in FORMAT_FILES if isinstance(files.get(f), str)}
        if listed:
            return listed
    name = meta.get("name") if isinstance(meta, dict) and isinstance(meta.get("name"), str) else folder.name
    return {f for f, pattern in FORMAT_FILES.items() if (folder / pattern.format(name=name)).is_file()}


def _skipped(names, fmt: str) -> list[CheckResult]:
    return [CheckResult(n, True, f"skipped: no {fmt.upper()} in this folder") for n in names]


def validate_object(folder: str | Path, sim: bool = True, physics: bool = False,
                    simready: bool = False, mass: bool = True, robot: bool = False) -> ObjectReport:
    """Validate one object folder (see the module docstring for what each flag adds).

    Every check runs under :func:`~.result.guarded`: one that raises is a failed check, never a crash.
    """
    if simready:  # the PhysX schemas must be registered before USD's schema registry is first used
        from .simready import available, install_physx_shim

        if available():
            install_physx_shim()
    from .usd_check import check_usd

    folder = Path(folder)
    present = formats_present(folder)
    report = ObjectReport(folder)
    if "usd" in present or "urdf" not in present:  # a folder with neither fails here, by name
        report.checks += guarded("usd", check_usd, folder)
        if simready:
            from .simready import check_simready

            report.checks += guarded("simready", check_simready, folder)
    else:
        report.checks += _skipped(["usd"] + (["simready"] if simready else []), "usd")
    if mass:
        from .masses import check_mass

        report.checks += guarded("mass", check_mass, folder)
    sapien = ["reach", "rest"] if physics else ["reach"]
    if (sim or physics) and "urdf" in present:
        from .sim import check_sapien

        report.checks += guarded("sapien_load", check_sapien, folder, checks=sapien)
    elif sim or physics:
        report.checks += _skipped(["sapien_load"] + sapien, "urdf")
    if robot:
        if "urdf" in present:
            from .robot import check_robot

            report.checks += guarded("robot", check_robot, folder)
        else:
            report.checks += _skipped(["robot"], "urdf")
    if physics:
        if "urdf" in present:
            from .physics import check_physics
            from .sim import check_maniskill

            report.checks += guarded("physics", check_physics, folder)
            report.checks += guarded("maniskill_load", check_maniskill, folder)
        else:
            report.checks += _skipped(["ground", "self_collision", "parent_child", "maniskill_load"], "urdf")
        if "mjcf" in present:
            from .mujoco_sim import check_mujoco

            report.checks += guarded("mujoco", check_mujoco, folder)
        else:
            report.checks += _skipped(["mujoco"], "mjcf")
    return report


__all__ = ["CheckResult", "ObjectReport", "find_objects", "formats_present", "guarded", "validate_object"]
