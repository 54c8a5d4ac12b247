"""Simulator checks of a written object folder: SAPIEN 3 and ManiSkill 3, physics only, on CPU.

The URDF of an object folder is loaded the way a user's simulator loads it, into a physics-only
CPU scene (``sapien.Scene([PhysxCpuSystem()])``: no renderer, no Vulkan device), with the root
link fixed, and compared with ``metadata.json``; then the articulation is driven and left to rest.

Checks
------
``sapien_load``
    The URDF loads; links, joints, joint types, limits, masses, collision shapes and joint frames
    (pivot and axis at rest) agree with ``metadata.json`` and the URDF; SAPIEN logged no warning
    or error (a missing mesh file, a zero mass ... are logged, not raised, by SAPIEN).
``reach``
    Every movable joint, driven alone while stiff drives hold the others at rest, reaches its
    upper and then its lower limit to within 5 % of its range, i.e. covers >= 95 % of the range
    each way (continuous joints: +pi/2 and -pi/2, within 5 % of pi), with gravity compensated
    in joint space. Fails on a joint that another link or the ground blocks (PhysX ignores
    contacts between a link and its parent), or whose limits are empty.
``rest``
    Passive joints (drive stiffness 0, the URDF ``<dynamics damping>``, the URDF
    ``<dynamics friction>`` mapped to PhysX's friction coefficient by
    :func:`physx_friction_coefficient`), gravity on, :data:`REST_TIME` (2 s): no prismatic joint
    moves more than :data:`REST_MAX_PRISMATIC` (1 mm), no revolute or continuous joint more than
    :data:`REST_MAX_REVOLUTE` (1 degree), and qpos stays finite. Sleeping is switched off for
    the run: PhysX puts an articulation that moves slower than its sleep threshold to sleep
    after ~0.4 s, which freezes a part sagging at a few degrees per second (and makes the
    result depend on what ran before).
``maniskill_load``
    The URDF loads through ManiSkill's own URDF loader into a CPU ``ManiSkillScene`` without a
    renderer, fixed base, with the links and active joints of ``metadata.json``.

More SAPIEN checks plug in with :func:`sapien_check`: a function of a :class:`SimContext`
returning a :class:`CheckResult`. :func:`check_sapien` loads the object once, runs each
registered check on the same scene (state reset in between) and times it.

SAPIEN pitfalls handled here
----------------------------
* A URDF ``<visual>`` with a ``<material>`` makes SAPIEN's loader create a ``RenderMaterial``
  at parse time, which needs a rendering device even with ``render_backend="none"`` in
  ManiSkill; our writer therefore puts colours in the MTL only, and both stock loaders
  work headless. Visual records are cleared before building the SAPIEN scene (physics only).
* SAPIEN 3.0.3's URDF loader applies ``<dynamics damping>`` (as drive damping) but not
  ``<dynamics friction>``, nor ``<limit effort velocity>``: joints keep PhysX friction
  coefficient 0.05, an infinite force limit and a velocity limit of 100. The ``rest`` check
  applies the URDF friction itself (:func:`physx_friction_coefficient`).
* PhysX joint friction is not a force: it is a unitless coefficient ``c`` bounding the resisting
  force or torque by ``c (|F| + |T|)``, with ``[F, T]`` the constraint wrench the joint
  transmits. A joint that nothing presses (a vertical slide: gravity acts along its free axis,
  the constraint carries nothing) has no friction in PhysX whatever ``c`` is, and a loaded
  joint creeps slowly instead of sticking (measured: a 2 kg slide 37 degrees off vertical, with 1.5
  times the sticking coefficient, still creeps ~9 mm/s). Friction is weaker still on light
  parts (small inertia) and behind other joints: a 0.24 kg part on the second hinge of a
  flip_revolute chain, 0.07 N m of gravity torque, sags at the damping-limited rate whatever
  the coefficient (even 50 only slows it by ~40 %). MuJoCo's ``frictionloss`` would hold both.
* A URDF ``<mimic>`` between two joints of one parent is built with its multiplier inverted by
  SAPIEN 3.0.3's loader; :func:`load_sapien` builds mimics itself (:func:`_build_mimics`). Return
  springs are not in a URDF: :func:`apply_springs` sets them from ``metadata.json``.
* A joint axis of norm < 1e-3 silently becomes ``1 0 0``; a zero or missing mass is silently
  replaced by the mass of the collision shapes at density 1000; a missing collision mesh is
  logged and skipped. The load check compares against metadata to catch all three.
* SAPIEN logs from C++ straight to file descriptor 2; :func:`capture_native_log` redirects
  that descriptor to read the log back (and re-emits it, so nothing is swallowed).
"""

from __future__ import annotations

import contextlib
import ctypes
import json
import logging
import math
import os
import re
import sys
import tempfile
import time
import warnings
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from infmob_usd.joints import one_mode

from .files import gate_joints, mode_excludes
from .result import CheckResult

__all__ = [
    "CheckResult",
    "JointState",
    "NativeLog",
    "RestRun",
    "SAPIEN_CHECKS",
    "SimContext",
    "SimUnavailableError",
    "capture_native_log",
    "check_maniskill",
    "check_sapien",
    "load_maniskill",
    "load_sapien",
    "physx_friction_coefficient",
    "sapien_check",
]

INSTALL_HINT = "pip install -e .[sim]"

# Tolerances against metadata.json (the URDF writes 6 significant digits).
POS_TOL = 1e-3  # m, joint pivot at rest
AXIS_TOL = 1e-3  # 1 - |cos| between simulated and declared joint axis
LIMIT_TOL = 1e-4  # absolute, on top of a relative 1e-5
MASS_RTOL = 1e-3

# Drive check: acceleration-mode drives (gains independent of the link's mass), a joint velocity
# cap so that a traversal takes about 1 / DRIVE_SPEED s (no tunnelling through thin panels).
DRIVE_STIFFNESS = 1.0e4  # 1/s^2  (omega = 100 rad/s; gravity sag g/K ~ 1 mm)
DRIVE_DAMPING = 200.0  # 1/s    (critical: 2 sqrt(K))
DRIVE_SPEED = 2.5  # ranges per second
DRIVE_TOL = 0.05  # fraction of the range: "reach" wants >= 95 % of the range covered
DRIVE_MAX_TIME = 2.0  # s of simulated time per target
CONTINUOUS_TARGET = math.pi / 2
CHECK_EVERY = 6  # steps between convergence tests

REST_TIME = 2.0  # s of passive simulation
REST_MAX_PRISMATIC = 1e-3  # m
REST_MAX_REVOLUTE = math.radians(1.0)  # rad (revolute and continuous)
FRICTION_MAX = 10.0  # cap of the PhysX friction coefficient for joints that carry ~no load

# Native log lines that fail a check, and the ones known to be harmless.
_LOG_LEVEL = re.compile(r"\[(warn|warning|error|critical)\]\s*(.*)", re.IGNORECASE)
BENIGN_LOG_PATTERNS: list[re.Pattern[str]] = []
_QUIET_WARNINGS = (DeprecationWarning, PendingDeprecationWarning, FutureWarning, ImportWarning)

# SAPIEN joint types per URDF/metadata joint type.
_SIM_TYPES = {
    "fixed": {"fixed"},
    "prismatic": {"prismatic"},
    "revolute": {"revolute_unwrapped", "revolute"},
    "continuous": {"revolute"},
}


class SimUnavailableError(RuntimeError):
    """SAPIEN (or ManiSkill) cannot be imported: install the ``sim`` extra."""


# --------------------------------------------------------------------------- imports


_SAPIEN: Any = None
_MANISKILL: dict[str, Any] | None = None


def _import_sapien():
    """Import SAPIEN once, quietly; :class:`SimUnavailableError` if it cannot be imported."""
    global _SAPIEN
    if _SAPIEN is None:
        try:
            with warnings.catch_warnings():
                # physics-only use needs no Vulkan: SAPIEN's fallback warning is noise here
                warnings.filterwarnings("ignore", message=".*libvulkan.*")
                import sapien
                import sapien.physx  # noqa: F401
        except (ImportError, OSError) as exc:
            raise SimUnavailableError(
                f"SAPIEN is not importable ({exc}); install the simulators with `{INSTALL_HINT}`"
            ) from exc
        sapien.set_log_level("warn")
        _SAPIEN = sapien
    return _SAPIEN


def _import_maniskill() -> dict[str, Any]:
    """Import the few ManiSkill pieces used here, once per process (the import takes seconds)."""
    global _MANISKILL
    if _MANISKILL is None:
        _import_sapien()
        try:
            from mani_skill.envs.scene import ManiSkillScene
            from mani_skill.envs.utils.system.backend import parse_sim_and_render_backend
            from mani_skill.utils.building.urdf_loader import URDFLoader
        except (ImportError, OSError) as exc:
            raise SimUnavailableError(
                f"ManiSkill is not importable ({exc}); install the simulators with "
                f"`{INSTALL_HINT}`"
            ) from exc
        _MANISKILL = {
            "ManiSkillScene": ManiSkillScene,
            "parse_backend": parse_sim_and_render_backend,
            "URDFLoader": URDFLoader,
        }
    return _MANISKILL


# --------------------------------------------------------------------------- native log


@dataclass
class NativeLog:
    """Lines written to file descriptor 2 (SAPIEN's C++ log, PhysX errors) and Python warnings."""

    lines: list[str] = field(default_factory=list)

    @property
    def problems(self) -> list[str]:
        """Warning, error and critical messages, minus :data:`BENIGN_LOG_PATTERNS`."""
        out = []
        for line in self.lines:
            m = _LOG_LEVEL.search(line)
            if m and not any(p.search(line) for p in BENIGN_LOG_PATTERNS):
                out.append(f"{m.group(1).lower()}: {m.group(2).strip()}")
        return out


def _fflush_all() -> None:
    with contextlib.suppress(Exception):
        ctypes.CDLL(None).fflush(None)


@contextlib.contextmanager
def capture_native_log(echo: bool = True) -> Iterator[NativeLog]:
    """Redirect file descriptor 2 (and Python warnings) into a :class:`NativeLog`.

    Parameters
    ----------
    echo : bool
        Write what was captured back to ``sys.stderr`` afterwards, so nothing is swallowed.
    """
    log = NativeLog()
    sys.stderr.flush()
    _fflush_all()
    saved = os.dup(2)
    tmp = tempfile.TemporaryFile()
    try:
        os.dup2(tmp.fileno(), 2)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                yield log
            finally:
                _fflush_all()
                os.dup2(saved, 2)
        tmp.seek(0)
        text = tmp.read().decode("utf-8", errors="replace")
        log.lines += text.splitlines()
        for w in caught:
            if issubclass(w.category, _QUIET_WARNINGS):  # not about the asset: pass them on
                warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
            else:
                log.lines.append(f"[warning] {w.category.__name__}: {w.message}")
        if echo and text:
            sys.stderr.write(text)
    finally:
        os.close(saved)
        tmp.close()


# --------------------------------------------------------------------------- loading


def _sapien_defaults(physx) -> None:
    """Put PhysX's process-wide scene, shape, body and material defaults back to SAPIEN's own: ManiSkill sets
    them for its scenes (a 0.02 m contact offset, other solver iterations and friction), and a scene made after
    it in the same process would be judged with those: a check's result would depend on what ran before it."""
    physx.set_scene_config(physx.PhysxSceneConfig())
    physx.set_shape_config(physx.PhysxShapeConfig())
    physx.set_body_config(physx.PhysxBodyConfig())
    physx.set_default_material(0.3, 0.3, 0.1)


def load_sapien(urdf: str | Path, *, ground: bool = True, timestep: float = 1 / 240):
    """Load a URDF into a physics-only SAPIEN 3 scene on the CPU.

    Collision shapes come from the URDF (one convex hull per collision file), visuals are
    dropped (no renderer), inertials are taken as written, and the root link is fixed.

    Parameters
    ----------
    urdf : str or Path
        The URDF file; mesh paths are resolved relative to it.
    ground : bool
        Add a ground plane at z = 0 (physics only).
    timestep : float
        Simulation time step in seconds.

    Returns
    -------
    tuple of (sapien.Scene, sapien.physx.PhysxArticulation)

    Raises
    ------
    SimUnavailableError
        SAPIEN cannot be imported (``pip install -e .[sim]``).
    FileNotFoundError
        The URDF does not exist.
    RuntimeError
        The URDF does not describe exactly one articulation.
    """
    sapien = _import_sapien()
    from sapien.wrapper.urdf_loader import URDFLoader

    urdf = Path(urdf)
    if not urdf.is_file():
        raise FileNotFoundError(f"no URDF at {urdf}")
    _sapien_defaults(sapien.physx)
    scene = sapien.Scene([sapien.physx.PhysxCpuSystem()])
    scene.set_timestep(timestep)
    if ground:
        scene.add_ground(0.0, render=False)
    loader = URDFLoader()
    loader.set_scene(scene)
    loader.fix_root_link = True
    articulation_builders, actor_builders, _cameras = loader.parse(str(urdf))
    for builder in articulation_builders:
        for link_builder in builder.link_builders:
            link_builder.visual_records = []  # physics only: no render device needed
    if len(articulation_builders) != 1 or actor_builders:
        raise RuntimeError(
            f"{urdf.name}: {len(articulation_builders)} articulations and {len(actor_builders)} "
            "free bodies (want one articulation)"
        )
    builder = articulation_builders[0]
    articulation = builder.build(fix_root_link=True, build_mimic_joints=False)
    _build_mimics(articulation, builder.mimic_joint_records)
    return scene, articulation


def _build_mimics(articulation, records) -> None:
    """URDF ``<mimic>`` joints as PhysX fixed tendons, ``q = multiplier * q_leader + offset``. SAPIEN
    3.0.3's builder does this too, but for two joints of one parent it writes the tendon with the
    multiplier inverted (``q_leader = multiplier * q``: measured, a lid coupled at 3x its pedal turned
    a third of the pedal's angle); its case of a joint following its parent's joint is right, and any
    other coupling it drops without a word (raised here)."""
    for rec in records:
        joint = articulation.find_joint_by_name(rec.joint)
        lead = articulation.find_joint_by_name(rec.mimic)
        m, offset = float(rec.multiplier), float(rec.offset)
        if joint.parent_link == lead.child_link and joint.parent_link.parent is not None:
            links = [joint.parent_link.parent, joint.parent_link, joint.child_link]
            coef = [0.0, -m, 1.0]
        elif joint.parent_link == lead.parent_link:
            links = [joint.parent_link, joint.child_link, lead.child_link]
            coef = [0.0, 1.0, -m]
        else:
            raise RuntimeError(f"{rec.joint} mimics {rec.mimic}: PhysX tendons couple a joint to its parent's"
                               " or to a sibling's only")
        # the tendon's coefficients, and their reciprocals (PhysX's gearing of each link)
        articulation.create_fixed_tendon(links, coef, [0.0 if c == 0 else 1.0 / c for c in coef],
                                         rest_length=offset, stiffness=1e5)


def apply_springs(articulation, meta: dict) -> int:
    """Set every return spring of ``metadata.json`` (``joints[].spring``; a URDF has no element for one)
    as its joint's drive, the way a user's loader should: stiffness and the joint's damping, target the
    spring's zero (``reference``, beyond the rest stop). Returns how many were set."""
    springs = {j["name"]: (j["spring"], j["damping"]) for j in meta["joints"] if "spring" in j}
    n = 0
    for joint in articulation.get_active_joints():
        if joint.name in springs:
            _drive_spring(joint, *springs[joint.name])
            n += 1
    return n


def _drive_spring(joint, spring: dict, damping: float) -> None:
    """One return spring (``metadata.json`` ``joints[].spring``) as the joint's drive, friction off."""
    joint.set_drive_property(float(spring["stiffness"]), float(damping), mode="force")
    joint.set_drive_target(float(spring["reference"]))
    # PhysX's joint friction is a coefficient of the wrench the joint carries (see above): on a
    # lever holding its own weight SAPIEN's default 0.05 beats a spring sized to its mass; the
    # file's friction is below the spring's preload by design, so none here
    joint.set_friction(0.0)


def load_maniskill(urdf: str | Path, *, name: str = "object"):
    """Load a URDF through ManiSkill's URDF loader into a CPU ``ManiSkillScene`` with no renderer.

    Uses ``mani_skill.utils.building.urdf_loader.URDFLoader`` (via
    ``ManiSkillScene.create_urdf_loader``'s class), unmodified, on a scene built from
    ``parse_sim_and_render_backend("physx_cpu", "none")``. This works headless because our
    URDFs carry no ``<material>`` elements (SAPIEN would need a render device for them).

    Returns
    -------
    tuple of (ManiSkillScene, mani_skill.utils.structs.Articulation)
    """
    sapien = _import_sapien()
    ms = _import_maniskill()
    urdf = Path(urdf)
    if not urdf.is_file():
        raise FileNotFoundError(f"no URDF at {urdf}")
    backend = ms["parse_backend"]("physx_cpu", "none")
    scene = ms["ManiSkillScene"](
        [sapien.Scene([sapien.physx.PhysxCpuSystem()])], device=backend.device, backend=backend
    )
    loader = ms["URDFLoader"]()
    loader.set_scene(scene)
    loader.fix_root_link = True
    loader.name = name
    parsed = loader.parse(str(urdf))
    builders = parsed["articulation_builders"]
    if len(builders) != 1 or parsed["actor_builders"]:
        raise RuntimeError(
            f"{urdf.name}: {len(builders)} articulations and {len(parsed['actor_builders'])} "
            "free bodies (want one articulation)"
        )
    builders[0].initial_pose = sapien.Pose()
    articulation = builders[0].build(name=name, fix_root_link=True)
    return scene, articulation


# --------------------------------------------------------------------------- context


@dataclass
class JointState:
    """Drive and limit settings of one movable joint as loaded (restored between checks)."""

    stiffness: float
    damping: float
    friction: float
    max_velocity: float
    lower: float
    upper: float


@dataclass
class SimContext:
    """One loaded object, shared by the SAPIEN checks.

    Attributes
    ----------
    folder, urdf : Path
        The object folder and its URDF.
    meta : dict
        ``metadata.json``.
    scene, articulation
        The SAPIEN scene and fixed-base articulation.
    joints : list
        The movable (active) joints, in qpos order.
    loaded : list of JointState
        Their settings right after loading (URDF damping, SAPIEN friction ...).
    rest_qpos : numpy.ndarray
        The rest configuration: zero clipped into the limits.
    urdf_dynamics : dict
        ``joint name -> (damping, friction)`` from the URDF ``<dynamics>`` (0 where absent).
    """

    folder: Path
    urdf: Path
    meta: dict
    scene: Any
    articulation: Any
    joints: list
    loaded: list[JointState]
    rest_qpos: np.ndarray
    urdf_dynamics: dict[str, tuple[float, float]] = field(default_factory=dict)

    @property
    def timestep(self) -> float:
        return float(self.scene.get_timestep())

    def reset(self, qpos: np.ndarray | None = None) -> None:
        """Restore the loaded joint settings, zero drive targets, put the object at rest."""
        for j, s in zip(self.joints, self.loaded, strict=True):
            j.set_drive_property(s.stiffness, s.damping, mode="force")
            j.set_friction(s.friction)
            j.set_max_velocity(s.max_velocity)
        self.hold(self.rest_qpos if qpos is None else qpos)
        self.articulation.set_qf(np.zeros(self.articulation.dof, dtype=np.float32))

    def hold(self, qpos: np.ndarray) -> None:
        """Set the configuration, zero velocities, and drive targets equal to ``qpos``."""
        art = self.articulation
        qpos = np.asarray(qpos, dtype=np.float32)
        art.set_qpos(qpos)
        art.set_qvel(np.zeros(art.dof, dtype=np.float32))
        for j, q in zip(self.joints, qpos, strict=True):
            j.set_drive_target(float(q))
            j.set_drive_velocity_target(0.0)

    def step(self, n: int = 1, compensate_gravity: bool = False) -> None:
        """Step the scene; ``compensate_gravity`` applies SAPIEN's passive force (gravity,
        Coriolis) as joint forces before each step, as a robot controller would."""
        art = self.articulation
        for _ in range(n):
            if compensate_gravity:
                art.set_qf(art.compute_passive_force(gravity=True, coriolis_and_centrifugal=True))
            self.scene.step()

    def make_passive(self) -> list[float]:
        """Drives off (stiffness 0), the URDF damping and friction (as PhysX coefficients); a joint with a
        return spring in ``metadata.json`` keeps it, as :func:`apply_springs` sets it (a pressed button
        or a toaster lever is held by its spring, not by friction).

        Call after :meth:`reset` (at rest: the friction mapping uses the rest pose). Returns
        the friction coefficients set, in joint order.
        """
        springs = {j["name"]: j["spring"] for j in self.meta.get("joints", []) if j.get("spring")}
        coefficients = []
        for j, s in zip(self.joints, self.loaded, strict=True):
            damping, friction = self.urdf_dynamics.get(j.name, (s.damping, 0.0))
            if j.name in springs:
                _drive_spring(j, springs[j.name], damping)
                coefficients.append(0.0)
                continue
            c = physx_friction_coefficient(j, friction, self.gravity)
            j.set_drive_property(0.0, damping, mode="force")
            j.set_friction(c)
            coefficients.append(c)
        return coefficients

    @property
    def gravity(self) -> np.ndarray:
        return np.asarray(self.scene.get_physx_system().config.gravity, float)


def _subtree_mass(link) -> float:
    total, stack = 0.0, [link]
    while stack:
        node = stack.pop()
        total += float(node.mass)
        stack += list(node.children)
    return total


def physx_friction_coefficient(joint, friction: float, gravity=(0.0, 0.0, -9.81)) -> float:
    """PhysX friction coefficient for a URDF ``<dynamics friction>`` (N, or N m for rotation).

    PhysX bounds a joint's friction force (or torque) by ``c (|F| + |T|)``, ``[F, T]`` the wrench
    the joint transmits to its child. At rest under gravity that wrench is the weight of
    everything the joint moves, taken by the constraint: the whole weight ``m g`` for a revolute
    or continuous joint, the part across the axis ``m g sqrt(1 - (a . g_hat)^2)`` for a prismatic
    joint (the part along the axis is what friction must hold). The coefficient is chosen so
    that this bound equals the URDF value at rest::

        c = friction / W,   W = m_subtree |g|  (revolute)  or  m_subtree |g x a|  (prismatic)

    capped at :data:`FRICTION_MAX` when the joint carries (almost) no load, e.g. a vertical
    slide, where PhysX cannot represent the friction at all. Measured on a 2 kg slide: the
    sticking threshold follows this formula (the torque part of the transmitted wrench, taken
    at the child's centre of mass, is zero for one body); above it the joint creeps slowly
    instead of sticking, below it it slides freely.
    """
    if not friction > 0:
        return 0.0
    g = np.asarray(gravity, float)
    weight = _subtree_mass(joint.child_link) * float(np.linalg.norm(g))
    if joint.type == "prismatic":
        axis = joint.get_global_pose().to_transformation_matrix()[:3, 0]
        g_hat = g / max(float(np.linalg.norm(g)), 1e-12)
        weight *= math.sqrt(max(0.0, 1.0 - float(axis @ g_hat) ** 2))
    if weight * FRICTION_MAX <= friction:
        return FRICTION_MAX
    return float(friction / weight)


SimCheck = Callable[[SimContext], CheckResult]
SAPIEN_CHECKS: dict[str, SimCheck] = {}


def sapien_check(name: str) -> Callable[[SimCheck], SimCheck]:
    """Register a SAPIEN check run by :func:`check_sapien` (in registration order)."""

    def register(fn: SimCheck) -> SimCheck:
        SAPIEN_CHECKS[name] = fn
        return fn

    return register


def _find_urdf(folder: Path, meta: dict) -> Path:
    rel = meta.get("files", {}).get("urdf")
    if rel:
        return folder / rel
    found = sorted(folder.glob("*.urdf"))
    return found[0] if found else folder / f"{folder.name}.urdf"


def _fmt(x: float) -> str:
    return f"{x:.4g}"


def _short(items: Sequence[str], n: int = 6) -> str:
    items = list(items)
    more = f" (+{len(items) - n} more)" if len(items) > n else ""
    return "; ".join(items[:n]) + more


def _movable(meta: dict) -> list[dict]:
    return [j for j in meta["joints"] if j["type"] != "fixed"]


# --------------------------------------------------------------------------- sapien_load


def _load_problems(ctx: SimContext) -> list[str]:
    """Everything in the loaded articulation that disagrees with metadata.json and the URDF."""
    sim_joints = {j.name: j for j in ctx.articulation.joints if j.name}
    return _structure_problems(ctx, sim_joints) + _joint_problems(ctx, sim_joints)


def _structure_problems(ctx: SimContext, sim_joints: dict) -> list[str]:
    """Links, joint names, masses and collision shapes of the loaded articulation against the files."""
    from .files import parse_urdf

    meta, art = ctx.meta, ctx.articulation
    problems: list[str] = []

    # links
    want_links = [link["name"] for link in meta["links"]]
    got_links = [link.name for link in art.links]
    if sorted(want_links) != sorted(got_links):
        missing = sorted(set(want_links) - set(got_links))
        extra = sorted(set(got_links) - set(want_links))
        problems.append(f"{len(got_links)} links (want {len(want_links)}); "
                        f"missing {missing}, unexpected {extra}")

    # joints: every joint by name and type, movable ones in the active list
    want_movable = [j["name"] for j in _movable(meta)]
    got_movable = [j.name for j in ctx.joints]
    if sorted(want_movable) != sorted(got_movable):
        problems.append(f"{len(got_movable)} movable joints (want {len(want_movable)}); "
                        f"missing {sorted(set(want_movable) - set(got_movable))}, "
                        f"unexpected {sorted(set(got_movable) - set(want_movable))}")
    missing_fixed = [j["name"] for j in meta["joints"] if j["name"] not in sim_joints]
    if missing_fixed and not problems:
        problems.append(f"joints missing in SAPIEN: {missing_fixed}")

    # masses (SAPIEN silently replaces a zero mass by density x collision volume)
    mass = {link.name: float(link.mass) for link in art.links}
    for link in meta["links"]:
        want = link.get("mass")
        got = mass.get(link["name"])
        if want is None or got is None:
            continue
        if not math.isclose(got, want, rel_tol=MASS_RTOL, abs_tol=1e-9):
            problems.append(f"link {link['name']}: mass {_fmt(got)} kg in SAPIEN, "
                            f"{_fmt(want)} kg in metadata")

    # collision shapes: one convex shape per <collision> (a missing file is skipped silently)
    try:
        urdf_model = parse_urdf(ctx.urdf)
        for link in art.links:
            want = len(urdf_model.links[link.name].collisions) if link.name in urdf_model.links else 0
            got = len(link.collision_shapes)
            if got != want:
                problems.append(f"link {link.name}: {got} collision shapes, URDF has {want}")
        for name, uj in urdf_model.joints.items():
            if uj.type != "fixed" and np.linalg.norm(uj.axis) < 1e-3:
                problems.append(f"joint {name}: URDF axis {uj.axis.tolist()} has no direction "
                                "(SAPIEN silently uses 1 0 0)")
    except Exception as exc:  # the URDF already loaded in SAPIEN: report, do not crash
        problems.append(f"URDF re-parse failed: {exc!r}")
    return problems


def _joint_problems(ctx: SimContext, sim_joints: dict) -> list[str]:
    """Joint types, limits and frames at rest (links are world-aligned at rest: axis world = local)."""
    meta, art = ctx.meta, ctx.articulation
    problems: list[str] = []
    ctx.articulation.set_qpos(np.zeros(art.dof, dtype=np.float32))
    for j in meta["joints"]:
        sj = sim_joints.get(j["name"])
        if sj is None:
            continue
        if sj.type not in _SIM_TYPES.get(j["type"], set()):
            problems.append(f"joint {j['name']}: SAPIEN type {sj.type!r} for URDF {j['type']!r}")
            continue
        pose = sj.get_global_pose()
        p = np.asarray(pose.p, float)
        if "origin" in j and np.linalg.norm(p - np.asarray(j["origin"], float)) > POS_TOL:
            problems.append(f"joint {j['name']}: pivot at rest {np.round(p, 4).tolist()}, "
                            f"metadata {j['origin']}")
        if j["type"] == "fixed":
            continue
        axis = pose.to_transformation_matrix()[:3, 0]
        want_axis = np.asarray(j.get("axis", axis), float)
        norm = np.linalg.norm(want_axis)
        if norm < 1e-9 or 1 - abs(float(axis @ want_axis) / norm) > AXIS_TOL:
            problems.append(f"joint {j['name']}: axis {np.round(axis, 4).tolist()} in SAPIEN, "
                            f"metadata {j.get('axis')}")
        lo, hi = (float(x) for x in sj.get_limit()[0])
        if j["type"] == "continuous":
            if np.isfinite(lo) or np.isfinite(hi):
                problems.append(f"joint {j['name']}: continuous but limited [{lo}, {hi}]")
            continue
        if not lo < hi:
            problems.append(f"joint {j['name']}: limits lower {_fmt(lo)} >= upper {_fmt(hi)}")
        for label, got, key in (("lower", lo, "lower"), ("upper", hi, "upper")):
            want = j.get(key)
            if want is not None and abs(got - want) > LIMIT_TOL + 1e-5 * abs(want):
                problems.append(f"joint {j['name']}: {label} {_fmt(got)} in SAPIEN, "
                                f"{_fmt(want)} in metadata")
        if lo < hi and not lo - LIMIT_TOL <= 0.0 <= hi + LIMIT_TOL:
            problems.append(f"joint {j['name']}: rest q=0 outside limits [{_fmt(lo)}, {_fmt(hi)}]")
    return problems


# --------------------------------------------------------------------------- reach


def _drive_targets(lo: float, hi: float) -> tuple[list[tuple[str, float]], float]:
    """Targets (upper first, then the full traverse to lower) and the tolerance for one joint."""
    if not (np.isfinite(lo) and np.isfinite(hi)):
        return [("+pi/2", CONTINUOUS_TARGET), ("-pi/2", -CONTINUOUS_TARGET)], DRIVE_TOL * math.pi
    return [("upper", hi), ("lower", lo)], DRIVE_TOL * (hi - lo)


REACH_BATCH = True  # drive joints whose swept boxes are apart together (see _reach_batches)
SWEEP_STEP = math.radians(5.0)  # rad between the poses a turning joint's swept box is built from
SWEEP_PAD = 0.01  # m added around every swept box


def _subtree(link) -> list:
    out, stack = [], [link]
    while stack:
        node = stack.pop()
        out.append(node)
        stack += list(node.children)
    return out


def _swept_box(ctx: SimContext, i: int, start_q: np.ndarray) -> np.ndarray:
    """Axis-aligned box (2 x 3) around everything joint ``i`` moves, over its whole drive.

    The union of the subtree's tight collision boxes at poses at most ``SWEEP_STEP`` apart over
    the driven range (a slide's two ends; a turn's sampled angles), the other joints at
    ``start_q``, grown by ``SWEEP_PAD`` plus the most a point at the subtree's radius from the
    pivot can bulge out between two sampled angles.
    """
    joint = ctx.joints[i]
    art = ctx.articulation
    lo, hi = (float(x) for x in joint.get_limit()[0])
    (_, lo), (_, hi) = sorted(_drive_targets(lo, hi)[0], key=lambda t: t[1])
    turning = joint.type != "prismatic"
    n = max(2, int(math.ceil((hi - lo) / SWEEP_STEP)) + 1) if turning else 2
    links = _subtree(joint.child_link)
    box = np.array([[np.inf] * 3, [-np.inf] * 3])
    q = np.array(start_q, dtype=np.float32)
    for value in np.linspace(lo, hi, n):
        q[i] = value
        art.set_qpos(q)
        for link in links:
            if not link.collision_shapes:  # a visual-only link touches nothing
                continue
            b = np.asarray(link.compute_global_aabb_tight(), float)
            box[0] = np.minimum(box[0], b[0])
            box[1] = np.maximum(box[1], b[1])
    art.set_qpos(np.asarray(start_q, dtype=np.float32))
    pad = SWEEP_PAD
    if turning and np.all(np.isfinite(box)):
        pivot = np.asarray(joint.get_global_pose().p, float)
        radius = float(np.max(np.linalg.norm(
            np.array([[box[a][0], box[b][1], box[c][2]] for a in (0, 1) for b in (0, 1) for c in (0, 1)])
            - pivot, axis=1)))
        pad += radius * (1 - math.cos((hi - lo) / (n - 1) / 2))
    return box + np.array([[-pad] * 3, [pad] * 3])


def _reach_batches(ctx: SimContext, requires: dict[str, list[str]], start_q: np.ndarray | None = None
                   ) -> list[list[int]]:
    """Movable joints (qpos indices) in batches that ``reach`` drives at the same time.

    Two joints share a batch only when the boxes swept by what they move (:func:`_swept_box`,
    the other joints at ``start_q``, default rest) are apart: then neither can touch the other's
    parts, and each meets exactly the contacts it would meet alone (the body, and parts held
    still; a part held in another's way is inside that part's box, so those two are never
    batched). A joint with an entry in ``requires`` (parts held open or closed for it) is driven
    alone. Greedy, in qpos order.
    """
    n = len(ctx.joints)
    if not REACH_BATCH or n < 2:
        return [[i] for i in range(n)]
    start = np.asarray(ctx.rest_qpos if start_q is None else start_q, dtype=np.float32)
    boxes = [_swept_box(ctx, i, start) for i in range(n)]
    batches: list[list[int]] = []
    for i, joint in enumerate(ctx.joints):
        if requires.get(joint.name) or not np.all(np.isfinite(boxes[i])):
            batches.append([i])
            continue
        for batch in batches:
            if requires.get(ctx.joints[batch[0]].name) or not np.all(np.isfinite(boxes[batch[0]])):
                continue
            if all(np.any(boxes[i][1] < boxes[k][0]) or np.any(boxes[k][1] < boxes[i][0]) for k in batch):
                batch.append(i)
                break
        else:
            batches.append([i])
    return batches


@dataclass
class _Plan:
    """How ``reach`` drives joints from one start state: from ``rest`` (gates of ``opened`` held at
    their upper limits) or from ``open`` (every limited joint at its upper limit, the joints of
    ``closed`` held at rest)."""

    start: str  # "rest" | "open"
    opened: dict[str, list[str]]  # joint -> joints held at their upper limit while it moves
    closed: dict[str, list[str]] = field(default_factory=dict)  # joint -> joints held at rest
    excludes: dict[str, list[str]] = field(default_factory=dict)  # joint -> the other modes of its fitting

    def start_q(self, ctx: SimContext, batch: list[int]) -> np.ndarray:
        names = [j.name for j in ctx.joints]
        q = np.array(ctx.rest_qpos, dtype=np.float32)
        if self.start == "open":
            for k, joint in enumerate(ctx.joints):
                hi = float(joint.get_limit()[0][1])
                if np.isfinite(hi):
                    q[k] = hi
            # one mode of each exclusive fitting open, a driven joint's own first (one_mode)
            rest = {n: float(ctx.rest_qpos[k]) for k, n in enumerate(names)}
            order = [names[i] for i in batch] + [n for k, n in enumerate(names) if k not in batch]
            one = one_mode({n: float(q[k]) for k, n in enumerate(names)}, order, self.excludes, rest)
            q = np.array([one[n] for n in names], dtype=np.float32)
        for i in batch:
            for req in self.opened.get(names[i], []):  # open the door before pulling its rack
                k = names.index(req)
                q[k] = float(ctx.joints[k].get_limit()[0][1])
            for req in self.closed.get(names[i], []):  # close the rack before closing the door
                q[names.index(req)] = ctx.rest_qpos[names.index(req)]
        return q

    def targets(self, lo: float, hi: float) -> tuple[list[tuple[str, float]], float]:
        targets, tol = _drive_targets(lo, hi)
        if self.start == "open" and np.isfinite(lo) and np.isfinite(hi):  # closed, then open again
            targets = [(f"{label} from all open", value) for label, value in reversed(targets)]
        return targets, tol


def _drive_batch(ctx: SimContext, batch: list[int], plan: _Plan,
                 max_steps: int) -> tuple[dict[int, list[str]], tuple[float, str]]:
    """Drive the joints of ``batch`` together to the two targets of ``plan`` (from rest: upper,
    then lower; from the all-open state: lower, then upper), the other joints held at
    ``plan``'s start state.

    Returns ``({qpos index: its missed targets}, (largest displacement of a held joint, where))``.
    """
    ctx.reset()
    for j in ctx.joints:
        j.set_drive_property(DRIVE_STIFFNESS, DRIVE_DAMPING, mode="acceleration")
        j.set_friction(0.0)
    start_q = plan.start_q(ctx, batch)
    if not np.array_equal(start_q, np.asarray(ctx.rest_qpos, dtype=np.float32)):
        ctx.hold(start_q)
    for k in _coupled_to(ctx, batch):  # a pedal's lid follows its tendon, not a drive holding it
        ctx.joints[k].set_drive_property(0.0, 0.0, mode="acceleration")
    failed: dict[int, list[str]] = {}
    plans = {}
    for i in batch:
        joint = ctx.joints[i]
        lo, hi = (float(x) for x in joint.get_limit()[0])
        targets, tol = plan.targets(lo, hi)
        if not tol > 0:
            failed[i] = [f"{joint.name}: empty or inverted range [{_fmt(lo)}, {_fmt(hi)}]"]
            continue
        span = (hi - lo) if np.isfinite(hi - lo) else 2 * CONTINUOUS_TARGET
        joint.set_max_velocity(float(DRIVE_SPEED * span))
        plans[i] = (targets, tol)
    return failed, _drive_phases(ctx, batch, plans, start_q, failed, max_steps)


def _coupled_to(ctx: SimContext, batch: list[int]) -> set[int]:
    """Indices of the joints outside ``batch`` coupled to a joint of it (``metadata.json`` ``mimic``: its
    followers, its leader and the leader's other followers): they move with it, so no drive holds them."""
    names = [j.name for j in ctx.joints]
    lead = {j["name"]: j["mimic"]["joint"] for j in ctx.meta.get("joints", []) if j.get("mimic")}
    groups = [{n, *[f for f, m in lead.items() if m == n]} for n in {lead.get(names[i], names[i]) for i in batch}]
    return {names.index(n) for g in groups for n in g if n in names} - set(batch)


def _drive_phases(ctx: SimContext, batch: list[int], plans: dict, start_q: np.ndarray,
                  failed: dict[int, list[str]], max_steps: int) -> tuple[float, str]:
    """The two drives of :func:`_drive_batch`, missed targets added to ``failed``; returns the
    largest displacement of a held joint and where."""
    names = [j.name for j in ctx.joints]
    dead: set[int] = set()  # qpos not finite: no second target
    disturbed = (0.0, "")
    for phase in range(2):
        live = [i for i in plans if i not in dead]
        if not live:
            break
        starts = {i: float(ctx.articulation.qpos[i]) for i in live}
        for i in live:
            ctx.joints[i].set_drive_target(float(plans[i][0][phase][1]))
        q = np.asarray(ctx.articulation.qpos, float)
        for _ in range(0, max_steps, CHECK_EVERY):
            ctx.step(CHECK_EVERY, compensate_gravity=True)
            q = np.asarray(ctx.articulation.qpos, float)
            if not np.all(np.isfinite(q[live])) or all(
                    abs(q[i] - plans[i][0][phase][1]) <= plans[i][1] for i in live):
                break
        held = np.abs(q - start_q)
        held[batch] = 0.0
        if held.size and np.all(np.isfinite(held)) and held.max() > disturbed[0]:
            k = int(np.argmax(held))
            others = f" and {len(batch) - 1} more apart from it" if len(batch) > 1 else ""
            disturbed = (float(held[k]), f"{names[k]} while driving {names[batch[0]]}{others}")
        for i in live:
            label, target = plans[i][0][phase]
            if not np.isfinite(q[i]):
                failed.setdefault(i, []).append(f"{names[i]} -> {label}: qpos became {q[i]}")
                dead.add(i)
            elif abs(q[i] - target) > plans[i][1]:
                start = starts[i]
                moved = (q[i] - start) / (target - start) if target != start else 0.0
                failed.setdefault(i, []).append(
                    f"{names[i]} -> {label} {_fmt(target)}: stopped at {_fmt(q[i])} "
                    f"({moved:.0%} of the way from {_fmt(start)}, tol {_fmt(plans[i][1])})")
    return disturbed


def _reach_plans(meta: dict) -> list[_Plan]:
    """The two start states of ``reach`` from ``metadata.json``: rest, and all open.

    A joint that ``requires_open`` a part moves with that part's joints at their upper limits, and with
    those of the parts that part requires open in turn (:func:`.files.gate_joints`).
    From the all-open state, a joint moves with the other DoFs of its own part at rest (a
    compound joint's modes one at a time, as a tilt-and-turn sash works; the joints it ``excludes``) and, if it
    ``requires_closed`` parts, with their joints at rest, and so do the joints that
    ``requires_open`` a part held at rest (recursively: a rack cannot stay out of a closed
    door)."""
    groups: dict[str, list[str]] = {}
    for j in _movable(meta):
        groups.setdefault(j["group"], []).append(j["name"])
    gates = gate_joints(meta)
    opened = {j["name"]: gates.get(j["name"], []) for j in _movable(meta)}
    closed = {}
    for j in _movable(meta):
        names = {n for g in [j["group"], *(j.get("requires_closed") or [])] for n in groups.get(g, [])
                 if n != j["name"]} | set(j.get("excludes") or [])
        while True:
            more = {n for n, gates in opened.items() if n not in names and names.intersection(gates)}
            if not more:
                break
            names |= more
        closed[j["name"]] = sorted(names)
    return [_Plan("rest", opened), _Plan("open", opened, closed, mode_excludes(meta))]


def _reach_runs(ctx: SimContext, plan: _Plan, max_steps: int) -> tuple[dict[int, list[str]], tuple[float, str], int]:
    """Every joint driven from ``plan``'s start, in batches (:func:`_reach_batches`); a joint that
    misses a target in a batch is driven again alone, and only that run counts. Returns the
    missed targets per joint, the largest displacement of a held joint, and the number of runs."""
    failures: dict[int, list[str]] = {}
    disturbed = (0.0, "")
    alone_only = {n: plan.opened.get(n, []) + plan.closed.get(n, []) for n in set(plan.opened) | set(plan.closed)}
    start = plan.start_q(ctx, []) if plan.start == "open" else None
    batches = _reach_batches(ctx, alone_only, start)
    for batch in batches:
        failed, moved = _drive_batch(ctx, batch, plan, max_steps)
        if moved[0] > disturbed[0]:
            disturbed = moved
        for i in sorted(failed):
            if len(batch) > 1:  # again alone: only a joint's own run decides
                alone, moved = _drive_batch(ctx, [i], plan, max_steps)
                if moved[0] > disturbed[0]:
                    disturbed = moved
                if i in alone:
                    failures[i] = alone[i]
            else:
                failures[i] = failed[i]
    return failures, disturbed, len(batches)


@sapien_check("reach")
def reach_check(ctx: SimContext) -> CheckResult:
    """Drive every movable joint to both ends of its range from rest and from the all-open
    state; the parts in its way held still.

    Drives are acceleration-mode PD (``DRIVE_STIFFNESS``, ``DRIVE_DAMPING``) on every joint,
    joint friction 0 (PhysX's coefficient model holds light parts), gravity compensated in joint
    space (SAPIEN's ``compute_passive_force`` as joint forces, as a robot controller does: a
    drive's gravity sag, g / K ~ 1 mm, would otherwise miss the 5 % of a 4 mm button), the
    driven joint's velocity capped at ``DRIVE_SPEED`` ranges per second. Only limits and
    contacts stop a joint. A target counts as reached when the joint is within ``DRIVE_TOL``
    (5 %) of its range from it, i.e. has covered >= 95 % of its range; each target gets
    ``DRIVE_MAX_TIME`` s of simulation.

    From rest: upper first, then the whole traverse to lower; a joint that ``requires_open``
    another part (metadata) is driven with that part's joints held fully open. From the
    all-open state (every limited joint at its upper limit, continuous joints at rest, of the
    modes that ``excludes`` each other the driven joint's or else the first; a robot that opened
    everything and now closes one part): lower first, then back to upper; the
    other DoFs of a compound joint, and the parts a joint ``requires_closed`` (metadata), are
    held at rest (:func:`_reach_plans`).

    Joints whose swept boxes are apart are driven together (:func:`_reach_batches`; a 144-bin
    rack is a few runs, not 144); a joint that misses a target in a batch is driven again
    alone, and only that run counts, so a batch can only save time, never change a verdict
    about a missed target.
    """
    max_steps = int(round(DRIVE_MAX_TIME / ctx.timestep))
    failures: dict[int, list[str]] = {}
    disturbed = (0.0, "")
    runs = 0
    for plan in _reach_plans(ctx.meta):
        failed, moved, n_runs = _reach_runs(ctx, plan, max_steps)
        for i, missed in failed.items():
            failures.setdefault(i, []).extend(missed)
        if moved[0] > disturbed[0]:
            disturbed = moved
        runs += n_runs
    ctx.reset()
    n = len(ctx.joints)
    info = f"held joints moved at most {disturbed[0]:.3g}" + (
        f" ({disturbed[1]})" if disturbed[1] else "")
    runs_text = f" in {runs} runs" if runs < 2 * n else ""
    if failures:
        missed = [m for i in sorted(failures) for m in failures[i]]
        return CheckResult("reach", False, f"{len(missed)} of {4 * n} targets missed: {_short(missed)}; {info}")
    return CheckResult("reach", True, f"{n} joints reached both ends from rest and from all open "
                                      f"(>= {1 - DRIVE_TOL:.0%} of the range){runs_text}; {info}")


# --------------------------------------------------------------------------- rest


def _rest_limit(joint) -> tuple[float, str]:
    """The allowed displacement of one joint at rest, and its unit for reports."""
    if joint.type == "prismatic":
        return REST_MAX_PRISMATIC, "mm"
    return REST_MAX_REVOLUTE, "deg"


def _in_unit(value: float, unit: str) -> str:
    return f"{value * 1000:.3g} mm" if unit == "mm" else f"{math.degrees(value):.3g} deg"


@dataclass
class RestRun:
    """What :func:`rest_displacement` measured, per movable joint in qpos order."""

    displacement: np.ndarray  # largest |q - q_rest| over the run, m or rad
    finite: bool  # qpos stayed finite
    coefficients: list[float]  # PhysX friction coefficients applied
    load: np.ndarray  # static gravity load at rest along each joint (N or N m), sign dropped


def rest_displacement(ctx: SimContext, duration: float = REST_TIME) -> RestRun:
    """Simulate the passive object from rest (:meth:`SimContext.make_passive`, gravity on)."""
    ctx.reset()
    coefficients = ctx.make_passive()
    art = ctx.articulation
    load = np.abs(np.asarray(art.compute_passive_force(gravity=True, coriolis_and_centrifugal=False),
                             float))
    sleep = float(art.sleep_threshold)
    art.set_sleep_threshold(0.0)  # PhysX would freeze a slowly sagging part after 0.4 s
    steps = max(1, int(round(duration / ctx.timestep)))
    worst = np.zeros(art.dof)
    finite = True
    try:
        for _ in range(steps):
            ctx.scene.step()
            q = np.asarray(art.qpos, float)
            if not np.all(np.isfinite(q)):
                finite = False
                break
            worst = np.maximum(worst, np.abs(q - ctx.rest_qpos))
    finally:
        art.set_sleep_threshold(sleep)
        ctx.reset()
    return RestRun(worst, finite, coefficients, load)


@sapien_check("rest")
def rest_check(ctx: SimContext) -> CheckResult:
    """Passive joints under gravity for 2 s: <= 1 mm (prismatic), <= 1 degree (revolute)."""
    run = rest_displacement(ctx)
    coefficients, finite = run.coefficients, run.finite
    largest: dict[str, tuple[float, str]] = {}
    failures = []
    for joint, disp, c, load in zip(ctx.joints, run.displacement, coefficients, run.load, strict=True):
        limit, unit = _rest_limit(joint)
        if disp > largest.get(unit, (-1.0, ""))[0]:
            largest[unit] = (float(disp), joint.name)
        if disp > limit:
            force = "N" if joint.type == "prismatic" else "N m"
            friction = ctx.urdf_dynamics.get(joint.name, (0.0, 0.0))[1]
            failures.append((disp / limit, f"{joint.name} moved {_in_unit(disp, unit)} (gravity load "
                                           f"{load:.3g} {force}, URDF friction {friction:g} {force}, "
                                           f"PhysX coefficient {c:.3g})"))
    per_unit = ", ".join(f"{'prismatic' if u == 'mm' else 'revolute'} {_in_unit(d, u)} ({n})"
                         for u, (d, n) in sorted(largest.items())) or "no movable joints"
    detail = (f"largest displacement: {per_unit} over {REST_TIME:g} s passive (URDF damping, "
              f"URDF friction as PhysX coefficients {_fmt(min(coefficients, default=0))}.."
              f"{_fmt(max(coefficients, default=0))}, gravity on); allowed "
              f"{REST_MAX_PRISMATIC * 1000:g} mm / {math.degrees(REST_MAX_REVOLUTE):g} deg")
    if not finite:
        return CheckResult("rest", False, "qpos became NaN/inf at rest; " + detail)
    if failures:
        failures.sort(key=lambda f: -f[0])
        return CheckResult("rest", False, f"{len(failures)} joints moved at rest: "
                           f"{_short([f for _, f in failures])}; {detail}")
    return CheckResult("rest", True, detail)


# --------------------------------------------------------------------------- entry points


def _read_meta(folder: Path) -> dict:
    return json.loads((folder / "metadata.json").read_text())


def _context(folder: Path, meta: dict, urdf: Path, scene, articulation) -> SimContext:
    joints = list(articulation.get_active_joints())
    loaded = []
    rest = []
    for j in joints:
        lo, hi = (float(x) for x in j.get_limit()[0])
        loaded.append(JointState(float(j.stiffness), float(j.damping), float(j.friction),
                                 float(j.max_velocity), lo, hi))
        rest.append(min(max(0.0, lo), hi) if lo <= hi else 0.0)
    return SimContext(folder, urdf, meta, scene, articulation, joints, loaded,
                      np.asarray(rest, dtype=float), _urdf_dynamics(urdf))


def _urdf_dynamics(urdf: Path) -> dict[str, tuple[float, float]]:
    """``joint name -> (damping, friction)`` from the URDF's ``<dynamics>`` elements."""
    from .files import parse_urdf

    return {j.name: (j.damping or 0.0, j.friction or 0.0) for j in parse_urdf(urdf).joints.values()
            if j.damping is not None or j.friction is not None}


def check_sapien(folder: str | Path, checks: Sequence[str] | None = None,
                 timestep: float = 1 / 240) -> list[CheckResult]:
    """Load one object folder in SAPIEN and run the simulator checks.

    Parameters
    ----------
    folder : str or Path
        An object folder (``metadata.json`` + URDF + meshes).
    checks : sequence of str, optional
        Names from :data:`SAPIEN_CHECKS` to run after ``sapien_load`` (default: all).
    timestep : float
        Simulation time step.

    Returns
    -------
    list of CheckResult
        ``sapien_load`` first, then one result per check. When loading fails, the other
        checks fail with "not run".

    Raises
    ------
    SimUnavailableError
        SAPIEN is not installed.
    """
    _import_sapien()
    folder = Path(folder)
    names = list(SAPIEN_CHECKS) if checks is None else list(checks)
    unknown = [n for n in names if n not in SAPIEN_CHECKS]
    if unknown:
        raise ValueError(f"unknown SAPIEN checks {unknown}; known: {list(SAPIEN_CHECKS)}")

    t0 = time.perf_counter()
    ctx = None
    try:
        meta = _read_meta(folder)
        urdf = _find_urdf(folder, meta)
        with capture_native_log() as log:
            scene, art = load_sapien(urdf, timestep=timestep)
        ctx = _context(folder, meta, urdf, scene, art)
        problems = [f"SAPIEN {p}" for p in log.problems] + _load_problems(ctx)
        detail = (_short(problems) if problems else
                  f"{len(art.links)} links, {len(ctx.joints)} movable joints as in metadata")
        load = CheckResult("sapien_load", not problems, detail)
    except SimUnavailableError:
        raise
    except Exception as exc:
        load = CheckResult("sapien_load", False, f"load failed: {type(exc).__name__}: {exc}")
    load.detail += f" [{time.perf_counter() - t0:.2f} s]"
    results = [load]
    if ctx is None:
        return results + [CheckResult(n, False, "not run: sapien_load failed") for n in names]

    for name in names:
        t0 = time.perf_counter()
        try:
            with capture_native_log() as log:
                result = SAPIEN_CHECKS[name](ctx)
            if log.problems:
                result = CheckResult(name, False, f"SAPIEN {_short(log.problems)}; {result.detail}")
        except Exception as exc:
            result = CheckResult(name, False, f"crashed: {type(exc).__name__}: {exc}")
        result.detail += f" [{time.perf_counter() - t0:.2f} s]"
        results.append(result)
    return results


class _LogCollector(logging.Handler):
    def __init__(self) -> None:
        super().__init__(logging.WARNING)
        self.messages: list[str] = []

    def emit(self, record: logging.LogRecord) -> None:
        self.messages.append(f"{record.levelname.lower()}: {record.getMessage()[:200]}")


def check_maniskill(folder: str | Path) -> list[CheckResult]:
    """Load one object folder through ManiSkill's URDF loader (CPU physics, no renderer).

    Returns
    -------
    list of CheckResult
        ``maniskill_load``: loads with a fixed base; link and active-joint names and counts as
        in ``metadata.json``; 10 physics steps keep qpos finite; no SAPIEN or ManiSkill
        warning logged.

    Raises
    ------
    SimUnavailableError
        SAPIEN or ManiSkill is not installed.
    """
    _import_maniskill()
    folder = Path(folder)
    t0 = time.perf_counter()
    collector = _LogCollector()
    ms_logger = logging.getLogger("mani_skill")
    ms_logger.addHandler(collector)
    try:
        meta = _read_meta(folder)
        urdf = _find_urdf(folder, meta)
        with capture_native_log() as log:
            scene, art = load_maniskill(urdf, name=meta.get("name", folder.name))
            for _ in range(10):
                scene.step()
            qpos = art.get_qpos().cpu().numpy()
        problems = [f"SAPIEN {p}" for p in log.problems]
        problems += [f"ManiSkill {m}" for m in collector.messages]
        want_links = sorted(link["name"] for link in meta["links"])
        got_links = sorted(link.name for link in art.links)
        if got_links != want_links:
            problems.append(f"{len(got_links)} links (want {len(want_links)}): missing "
                            f"{sorted(set(want_links) - set(got_links))}, unexpected "
                            f"{sorted(set(got_links) - set(want_links))}")
        want_joints = sorted(j["name"] for j in _movable(meta))
        got_joints = sorted(j.name for j in art.active_joints)
        if got_joints != want_joints:
            problems.append(f"{len(got_joints)} active joints (want {len(want_joints)}): missing "
                            f"{sorted(set(want_joints) - set(got_joints))}, unexpected "
                            f"{sorted(set(got_joints) - set(want_joints))}")
        root = art._objs[0].links[0].joint.type
        if root != "fixed":
            problems.append(f"root link joint {root!r}, want 'fixed'")
        if not np.all(np.isfinite(qpos)):
            problems.append("qpos not finite after 10 steps")
        detail = _short(problems) if problems else (
            f"{len(got_links)} links, {len(got_joints)} active joints, fixed base")
        result = CheckResult("maniskill_load", not problems, detail)
    except SimUnavailableError:
        raise
    except Exception as exc:
        result = CheckResult("maniskill_load", False,
                             f"load failed: {type(exc).__name__}: {exc}")
    finally:
        ms_logger.removeHandler(collector)
    result.detail += f" [{time.perf_counter() - t0:.2f} s]"
    return [result]
