"""The robot check (``infmob validate --robot``): a floating Panda gripper opens every annotated joint.

For each target of an object folder's ``annotations.json`` (schema ``infmob-annotations/1``; only its
documented fields are read), in a physics-only SAPIEN 3 scene on the CPU:

1. the object is put at rest, with the joints the target ``requires_open`` set open; every joint,
   the operated one included, is passive with its real dynamics (URDF damping, URDF friction as PhysX
   coefficients, return springs: :meth:`~.sim.SimContext.make_passive`);
2. the Panda hand bundled with ManiSkill (``panda_v2_gripper.urdf``, the ``floating_panda_gripper`` robot:
   six virtual joints carry the hand, two prismatic fingers) appears :data:`PREGRASP` back from the first
   grasp frame, fingers open, and moves along ``approach`` to the grasp (and up to :data:`INSET` further,
   towards the middle of the handle's box);
3. the fingers close along ``closing`` with the Panda hand's continuous grip force (:data:`GRIP_FORCE`).
   When the hand cannot get to a grasp or closes on nothing, or a hold taken does not open the part (up to
   :data:`HOLDS` holds, each from the object at rest again), the next annotated grasp is tried, each also
   turned a quarter about its approach where the handle's box fits between the fingers that way and, for a
   knob turned in place, wound back about its approach by half its turn (:func:`wound_back`), then each
   tilted by :data:`TILTS` about its closing axis (the same hold reached at a slant). A ``press`` or
   ``push`` is done with the closed fingers' tips on the grasp point, without a grasp, the hand turned any
   way about the approach and tilted about either axis across it;
4. the hand follows ``path`` (the grasp point over the joint's range) through a compliant controller:
   PhysX drives on the six virtual joints with a stiffness, damping and a force / torque limit
   (:data:`ARM_FORCE`, :data:`ARM_TORQUE`: what a Panda arm exerts at its hand), their target moving along
   the path at :data:`SPEED` but never more than :data:`LEAD` ahead of where the hand is (up to ``LEAD``
   past the path's end: a compliant hand lags its target by force / stiffness; the hand's place on the
   path is read less its inset past the grasp point); the path rides on the operated joint's parent as
   that is now (tines on a rack pulled out, a tote that gives way on its shelf under the pull); the hand turns
   as the path's tangent turns (a door's handle turns with the door). A path that is a point (a knob held
   on its axis) is turned in place about the joint's axis, read from the loaded URDF; held wound back, or
   when turning it in one hold did not open it, it is turned at most :data:`REGRIP` per hold: then the
   fingers open, the hand turns back and takes hold again (a dial turned 330 degrees in one hold sweeps the
   hand's body through everything around it).

Success: the joint passes ``rest + open_threshold * (open - rest)`` while both fingers still touch the
operated link (a press or push: the joint passing is enough). A failure names why: ``approach blocked by
LINK``, ``missed handle`` (the fingers closed on nothing, or on another link), ``slipped``, ``blocked by
LINK`` (the moving part presses on another link), ``gripper blocked by LINK``, ``held at its joint limit``
(the path pushes the joint against a stop), ``too stiff`` (the arm pulls with its full force and the joint
does not follow), ``stalled``; when every hold fails, the reason of the one that moved the part furthest,
else the first grasp's.

The scene has no floor (an appliance stands on a counter, and the hand may pass below the counter's edge;
a part swinging into the floor is the ``reach`` check's finding). The gripper's fingers carry ManiSkill's
material for them (friction 2.0); gravity is off on the hand, as an
arm would hold its weight. One :class:`~.result.CheckResult` named ``robot`` per target, detail
``JOINT (part_class): ... [s]`` (wall seconds of that target), so the validate summary table counts opened
joints per category.
"""

from __future__ import annotations

import math
import re
import statistics
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from infmob_usd.annotations import AnnotationError
from infmob_usd.annotations import load as load_annotations

from .result import CheckResult

__all__ = ["AnnotationError", "Attempt", "Gripper", "check_robot", "read_annotations", "robot_table", "run_target"]

ALL, JOINTS = "all", "all joints"
TCP_OFFSET = 0.1034  # m, panda_hand -> panda_hand_tcp (the middle of the finger pads), from the URDF
FINGER_OPEN = 0.04  # m per finger, the Panda hand's stroke (0.08 m between the fingers)
PREGRASP = 0.10  # m back from the grasp along the approach where the hand appears
INSET = 0.01  # m the hand may go past the grasp point towards the middle of the handle box
APPROACH_TIME = 0.6  # s
CLOSE_TIME = 0.4  # s
# Franka Emika Panda datasheet: continuous grip force 70 N, payload 3 kg, wrist joints 12 N m. The arm's
# force and torque at the hand are chosen (no datasheet value): a firm pull of 40 N per axis, 6 N m, half
# the wrist's limit, so that a part needing more than a person's easy pull fails as "too stiff"
GRIP_FORCE = 70.0  # N per finger drive
ARM_FORCE = 40.0  # N per translational axis
ARM_TORQUE = 6.0  # N m per rotational axis
ARM_STIFFNESS = 2000.0  # N/m (compliant: 40 N at 2 cm of tracking error)
ARM_DAMPING = 80.0  # N s/m (about critical for the hand's ~0.8 kg)
ROT_STIFFNESS = 60.0  # N m/rad
ROT_DAMPING = 1.5  # N m s/rad
SPEED = 0.25  # m/s along the path
LEAD = 0.05  # m the path target may run ahead of the hand's own place on the path
MIN_PATH = 0.0005  # m: a shorter path is a point (turned in place, if the joint turns)
TURN_SPEED = 1.5  # rad/s turning in place
TURN_LEAD = 0.35  # rad the turn may run ahead of the hand
REGRIP = math.radians(60)  # rad a knob is turned per hold: then the hand lets go, turns back and takes it again
RELEASE_TIME = 0.2  # s for the fingers to open (and the hand to settle) in a regrip
PRESS_ACTIONS = ("press", "push")  # pressed with the closed fingers' tips, no grasp
TILTS = tuple(math.radians(a) for a in (35, -35, 65, -65))  # slants tried when a hold's straight way in is blocked
HOLDS = 4  # holds taken (approached and closed on) before a target counts as failed: a robot tries again
FINGERTIP = 0.0095  # m from the TCP to the tips of the closed fingers (panda_v2_gripper.urdf)
STALL_TIME = 1.0  # s without 2 mm of progress along the path ends an attempt
SLIP_TIME = 0.25  # s without both fingers on the part before it counts as slipped
EXTRA_TIME = 2.0  # s allowed beyond the path length / SPEED
FINGER_FRICTION = 2.0  # ManiSkill's floating_panda_gripper finger material
CONTACT_EVERY = 4  # steps between contact queries
VIRTUAL = ["root_x_axis_joint", "root_y_axis_joint", "root_z_axis_joint",
           "root_x_rot_joint", "root_y_rot_joint", "root_z_rot_joint"]
FINGERS = ["panda_finger_joint1", "panda_finger_joint2"]
FINGER_LINKS = ("panda_leftfinger", "panda_rightfinger")


def read_annotations(folder: str | Path) -> list[dict] | None:
    """The targets of ``folder/annotations.json`` read and checked by :func:`infmob_usd.annotations.load`
    (``None`` when the file is absent; a file off the schema raises its one-line ``AnnotationError``)."""
    if not (Path(folder) / "annotations.json").is_file():
        return None
    return load_annotations(folder)["targets"]


# --------------------------------------------------------------------------- geometry


def _unit(v) -> np.ndarray:
    v = np.asarray(v, float)
    return v / max(float(np.linalg.norm(v)), 1e-12)


def hand_rotation(approach, closing) -> np.ndarray:
    """The hand's rotation (world) for an approach and a closing axis: the TCP's z along the approach,
    its y (the fingers' axis) along the closing axis, made orthogonal to the approach."""
    z = _unit(approach)
    y = _unit(np.asarray(closing, float) - z * float(np.dot(closing, z)))
    return np.column_stack([np.cross(y, z), y, z])


def rotation_between(a, b) -> np.ndarray:
    """The smallest rotation taking direction ``a`` to direction ``b``."""
    a, b = _unit(a), _unit(b)
    v, c = np.cross(a, b), float(np.dot(a, b))
    if c < -1 + 1e-9:  # opposite: half a turn about any axis across a
        axis = _unit(np.cross(a, [1.0, 0, 0] if abs(a[0]) < 0.9 else [0, 1.0, 0]))
        return 2 * np.outer(axis, axis) - np.eye(3)
    k = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    return np.eye(3) + k + k @ k / (1 + c)


def euler_xyz(r: np.ndarray) -> np.ndarray:
    """Angles ``(a, b, c)`` with ``r = Rx(a) Ry(b) Rz(c)`` (the order of the gripper's virtual joints)."""
    b = math.asin(max(-1.0, min(1.0, float(r[0, 2]))))
    return np.array([math.atan2(-r[1, 2], r[2, 2]), b, math.atan2(-r[0, 1], r[0, 0])])


class Path3:
    """A polyline by arc length: points, tangents, nearest place of a point."""

    def __init__(self, points):
        self.points = np.asarray(points, float)
        seg = np.diff(self.points, axis=0)
        self.lengths = np.linalg.norm(seg, axis=1)
        self.cum = np.concatenate([[0.0], np.cumsum(self.lengths)])
        self.length = float(self.cum[-1])

    def _segment(self, s: float) -> tuple[int, float]:
        s = min(max(s, 0.0), self.length)
        i = int(min(np.searchsorted(self.cum, s, side="right") - 1, len(self.lengths) - 1))
        return i, (s - self.cum[i]) / max(self.lengths[i], 1e-12)

    def at(self, s: float) -> np.ndarray:
        """The point at arc length ``s``; past the end, on the last chord's line (a compliant hand's target
        runs past the end so that the hand itself gets there against the part's resistance)."""
        if s > self.length:
            return self.points[-1] + (s - self.length) * _unit(self.points[-1] - self.points[-2])
        i, t = self._segment(s)
        return self.points[i] + t * (self.points[i + 1] - self.points[i])

    def tangent(self, s: float) -> np.ndarray:
        """The direction at ``s``, blended between the chords on either side of each chord's middle (the
        true tangent there for an arc), so that a turning hand turns smoothly and not in 11 steps."""
        i, t = self._segment(s)
        here = _unit(self.points[i + 1] - self.points[i])
        other = i - 1 if t < 0.5 else i + 1
        if not 0 <= other < len(self.lengths) or self.lengths[other] < 1e-9:
            return here
        w = abs(t - 0.5)
        return _unit((1 - w) * here + w * _unit(self.points[other + 1] - self.points[other]))

    def nearest(self, p) -> float:
        """Arc length of the path's point nearest to ``p``."""
        a, d = self.points[:-1], self.points[1:] - self.points[:-1]
        t = np.clip(np.einsum("ij,ij->i", np.asarray(p) - a, d) / np.maximum((d * d).sum(1), 1e-18), 0, 1)
        dist = np.linalg.norm(a + t[:, None] * d - p, axis=1)
        i = int(np.argmin(dist))
        return float(self.cum[i] + t[i] * self.lengths[i])


# --------------------------------------------------------------------------- the gripper


def gripper_urdf() -> Path:
    """ManiSkill's floating Panda gripper URDF (the ``floating_panda_gripper`` robot's)."""
    from mani_skill import PACKAGE_ASSET_DIR

    return Path(PACKAGE_ASSET_DIR) / "robots" / "panda" / "panda_v2_gripper.urdf"


def _matrix(pose) -> np.ndarray:
    return np.asarray(pose.to_transformation_matrix(), float)


class Gripper:
    """The floating Panda hand in a scene: a fixed root placed per attempt near the grasp, six driven
    virtual joints (x, y, z, then rotations about x, y, z) carrying the hand, two driven fingers."""

    def __init__(self, scene):
        import sapien
        from sapien.wrapper.urdf_loader import URDFLoader

        loader = URDFLoader()
        loader.set_scene(scene)
        loader.fix_root_link = True
        builders, _actors, _cams = loader.parse(str(gripper_urdf()))
        for link_builder in builders[0].link_builders:
            link_builder.visual_records = []  # physics only
        self.art = builders[0].build(fix_root_link=True)
        self.art.set_name("floating_panda_gripper")
        self.art.set_root_pose(sapien.Pose([0, 0, -10.0]))
        joints = {j.name: j for j in self.art.get_active_joints()}
        self.virtual = [joints[n] for n in VIRTUAL]
        self.fingers = [joints[n] for n in FINGERS]
        self.index = {j.name: i for i, j in enumerate(self.art.get_active_joints())}
        material = sapien.physx.PhysxMaterial(FINGER_FRICTION, FINGER_FRICTION, 0.0)
        for link in self.art.links:
            link.disable_gravity = True  # an arm holds the hand's weight
            if link.name in FINGER_LINKS:
                for shape in link.collision_shapes:
                    shape.set_physical_material(material)
        for j in self.virtual[:3]:
            j.set_drive_property(ARM_STIFFNESS, ARM_DAMPING, ARM_FORCE, mode="force")
        for j in self.virtual[3:]:
            j.set_drive_property(ROT_STIFFNESS, ROT_DAMPING, ARM_TORQUE, mode="force")
        for j in self.fingers:
            j.set_drive_property(1e4, 100.0, GRIP_FORCE, mode="force")
        self.hand = self.art.find_link_by_name("panda_hand")
        self.root = np.eye(4)
        self.ids = {link.entity.per_scene_id: link.name for link in self.art.links}

    def _joint_values(self, tcp: np.ndarray) -> np.ndarray:
        hand = tcp.copy()
        hand[:3, 3] = tcp[:3, 3] - tcp[:3, 2] * TCP_OFFSET
        rel = np.linalg.inv(self.root) @ hand
        return np.concatenate([rel[:3, 3], euler_xyz(rel[:3, :3])])

    def place(self, tcp: np.ndarray, opening: float = FINGER_OPEN) -> None:
        """Put the hand's TCP at pose ``tcp`` (4x4, world), at rest, with the root there (virtual joints 0)."""
        import sapien

        hand = tcp.copy()
        hand[:3, 3] = tcp[:3, 3] - tcp[:3, 2] * TCP_OFFSET
        self.root = hand
        self.art.set_root_pose(sapien.Pose(hand))
        q = np.zeros(self.art.dof, dtype=np.float32)
        for j in self.fingers:
            q[self.index[j.name]] = opening
        self.art.set_qpos(q)
        self.art.set_qvel(np.zeros(self.art.dof, dtype=np.float32))
        self.move(tcp)
        self.grip(opening)

    def move(self, tcp: np.ndarray) -> None:
        """Drive the TCP towards pose ``tcp`` (4x4, world) through the compliant virtual joints (each angle
        taken within half a turn of where its joint is, so that a knob turned past 180 degrees goes on)."""
        values = self._joint_values(tcp)
        q = np.asarray(self.art.qpos, float)
        for i, j in enumerate(self.virtual[3:], start=3):
            now = q[self.index[j.name]]
            values[i] = now + (values[i] - now + math.pi) % (2 * math.pi) - math.pi
        for j, v in zip(self.virtual, values, strict=True):
            j.set_drive_target(float(v))

    def grip(self, opening: float) -> None:
        for j in self.fingers:
            j.set_drive_target(float(opening))

    def tcp(self) -> np.ndarray:
        m = _matrix(self.hand.entity_pose)
        m[:3, 3] += m[:3, 2] * TCP_OFFSET
        return m

    def opening(self) -> float:
        q = np.asarray(self.art.qpos, float)
        return float(sum(q[self.index[j.name]] for j in self.fingers))

    def force(self) -> float:
        """The translational drive force now (N, the norm over x, y, z), from each drive's error."""
        q = np.asarray(self.art.qpos, float)
        out = []
        for j in self.virtual[:3]:
            e = float(np.asarray(j.drive_target).ravel()[0]) - q[self.index[j.name]]
            out.append(min(ARM_FORCE, ARM_STIFFNESS * abs(e)))
        return float(np.linalg.norm(out))


# --------------------------------------------------------------------------- one attempt


@dataclass
class Attempt:
    """What happened to one annotated target."""

    joint: str
    part: str
    ok: bool
    reached: float  # fraction of rest -> open the joint was at when the attempt ended
    reason: str  # why it failed ("" when it opened)
    sim_time: float  # simulated seconds

    def describe(self) -> str:
        state = f"reached {round(self.reached, 2) + 0.0:.0%} of its range in {self.sim_time:.1f} s simulated"
        return f"opened, {state}" if self.ok else f"{self.reason}; {state}"


def _pose(rotation: np.ndarray, position) -> np.ndarray:
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = rotation, position
    return m


def _subtree_ids(link) -> set[int]:
    out, stack = set(), [link]
    while stack:
        node = stack.pop()
        out.add(node.entity.per_scene_id)
        stack += list(node.children)
    return out


class _Run:
    """The state of one attempt: the object, the gripper, the operated joint and the contacts."""

    def __init__(self, ctx, gripper: Gripper, target: dict):
        self.ctx, self.gripper, self.target = ctx, gripper, target
        self.scene, self.art = ctx.scene, ctx.articulation
        self.dt = ctx.timestep
        self.qi = [j.name for j in ctx.joints].index(target["joint"])
        self.link = self.art.find_link_by_name(target["link"])
        self.moving = _subtree_ids(self.link)
        parent = self.link.parent
        self.parent = parent.entity.per_scene_id if parent is not None else None
        self.names = {e.per_scene_id: e.name for e in self.scene.entities}
        self.fingers = {i for i, n in gripper.ids.items() if n in FINGER_LINKS}
        self.rest, self.open = float(target["rest"]), float(target["open"])
        self.time = 0.0
        self.opening = FINGER_OPEN  # per finger, how far the fingers open to let go in a regrip
        self.parent_rest: np.ndarray | None = None  # the parent link's pose with every joint at rest

    def fraction(self) -> float:
        q = float(np.asarray(self.art.qpos, float)[self.qi])
        return (q - self.rest) / (self.open - self.rest) if self.open != self.rest else 0.0

    def step(self, n: int = 1) -> None:
        for _ in range(n):
            self.scene.step()
        self.time += n * self.dt

    def contacts(self) -> list[tuple[int, int]]:
        """Body pairs (entity ids) pressing on each other now."""
        out = []
        for c in self.scene.get_contacts():
            if any(np.linalg.norm(p.impulse) > 1e-6 for p in c.points):
                out.append((c.bodies[0].entity.per_scene_id, c.bodies[1].entity.per_scene_id))
        return out

    def held(self, pairs) -> bool:
        """Both fingers press on the operated part."""
        on = {a if b in self.moving else b for a, b in pairs if (a in self.moving) != (b in self.moving)}
        return self.fingers <= on

    def gripper_on(self, pairs) -> list[str]:
        """Object links (other than the operated part) the gripper presses on."""
        grip = set(self.gripper.ids)
        return sorted({self.names.get(b if a in grip else a, "?") for a, b in pairs
                       if (a in grip) != (b in grip) and not {a, b} & self.moving})

    def blockers(self, pairs) -> list[str]:
        """What the moving part presses on, other than its parent and the gripper."""
        skip = self.moving | set(self.gripper.ids) | {self.parent}
        return sorted({self.names.get(b if a in self.moving else a, "?") for a, b in pairs
                       if (a in self.moving) != (b in self.moving) and (a if b in self.moving else b) not in skip})

    def fail(self, reason: str) -> Attempt:
        return Attempt(self.target["joint"], str(self.target.get("part_class")), False, self.fraction(),
                       reason, self.time)


def _quat_matrix(q) -> np.ndarray:
    w, x, y, z = _unit(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def box_extent(box, direction) -> float | None:
    """The length of an annotation's oriented box along a link-frame direction (``None``: no box)."""
    if not isinstance(box, dict) or "size" not in box:
        return None
    r = _quat_matrix(box.get("quat_wxyz") or [1.0, 0.0, 0.0, 0.0])
    return float(np.abs(r.T @ _unit(direction)) @ np.asarray(box["size"], float))


def tilted(g: dict, axis, angle: float) -> dict:
    """Grasp ``g`` with its approach turned by ``angle`` (rad) about ``axis`` (unit, perpendicular to the
    approach), its closing axis turned with it: the same hold, reached from another side."""
    r = _about(_unit(axis), angle)
    return {**g, "approach": (r @ _unit(g["approach"])).tolist(), "closing": (r @ _unit(g["closing"])).tolist()}


def _turns_in_place(target: dict) -> bool:
    """A knob held on its axis: the annotated path is a point and the hand turns it."""
    path = np.asarray(target.get("path") or [[0.0, 0.0, 0.0]], float)
    return target.get("action") == "turn" and float(np.ptp(path, axis=0).max()) < MIN_PATH


def wound_back(target: dict, g: dict) -> dict | None:
    """Grasp ``g`` of a knob turned in place, the hand wound back about its approach by half the turn (up
    to half :data:`REGRIP`), as a person sets the wrist before turning, and marked ``regrip``: the knob is
    turned at most :data:`REGRIP` per hold (let go, turn back, take hold again). The hand's 0.2 m across the
    fingers then sweeps only either side of the annotated hold instead of all round (a grate above an
    oven's knobs, a lid beside a washer's dial). ``None`` when the knob's box does not fit between the open
    fingers that way, or the target gives no way round."""
    direction = target.get("direction")
    if not _turns_in_place(target) or direction is None:
        return None
    a, k = _unit(g["approach"]), _unit(g["closing"])
    d = np.asarray(direction, float) - a * float(np.dot(direction, a))  # where the closing axis turns to
    if np.linalg.norm(d) < 0.5:
        return None
    half = min(abs(float(target["open"]) - float(target["rest"])), REGRIP) / 2
    closing = _unit(math.cos(half) * k - math.sin(half) * _unit(d))
    extent = box_extent(target.get("box"), closing)
    if extent is None or extent > 2 * FINGER_OPEN - 0.005:
        return None
    return {**g, "closing": closing.tolist(), "width": max(float(g.get("width") or 0.0), extent), "regrip": True}


def grasp_candidates(target: dict) -> list[dict]:
    """The annotated grasps in order, each followed by itself turned a quarter about its approach when the
    handle's box fits between the open fingers that way (a knob or a short pull under a worktop, where the
    hand's 0.2 m across the fingers does not fit the annotated way) and, for a knob turned in place, wound
    back by half its turn (:func:`wound_back`); then each tilted by :data:`TILTS` about its closing axis (the
    fingers still close across the same stretch: a hold whose straight way in meets the hand's body on a
    neighbour, a shelf above or a stand below, taken at a slant), and for a press or push, whose shut
    fingers need no closing axis, about the other axis across the approach as well."""
    press = target.get("action") in PRESS_ACTIONS
    out = []
    for g in target["grasps"]:
        out.append(g)
        turned = np.cross(_unit(g["approach"]), _unit(g["closing"]))
        extent = box_extent(target.get("box"), turned)
        if press:  # shut fingers: the hand may be turned any way about its approach (its body flat)
            out.append({**g, "closing": turned.tolist()})
        elif extent is not None and extent <= 2 * FINGER_OPEN - 0.005:
            out.append({**g, "closing": turned.tolist(), "width": extent})
        back = wound_back(target, g)
        if back is not None:
            out.append(back)
    for g in target["grasps"]:
        axes = [g["closing"], np.cross(_unit(g["approach"]), _unit(g["closing"]))] if press else [g["closing"]]
        out += [tilted(g, axis, a) for a in TILTS for axis in axes]
    return out


def _grasp_frames(run: _Run, g: dict) -> tuple[np.ndarray, np.ndarray, float]:
    """The TCP pose at grasp ``g`` (world, moved up to :data:`INSET` towards the handle box's middle), the
    pre-grasp pose, and the finger opening (per finger) to approach with."""
    target = run.target
    link = _matrix(run.link.entity_pose)
    rot = link[:3, :3]
    approach = _unit(rot @ np.asarray(g["approach"], float))
    position = (link @ np.array([*map(float, g["position"]), 1.0]))[:3]
    inset = 0.0
    box = target.get("box")
    if isinstance(box, dict) and "center" in box:
        centre = (link @ np.array([*map(float, box["center"]), 1.0]))[:3]
        inset = min(INSET, max(0.0, float(np.dot(centre - position, approach))))
    hand = hand_rotation(approach, rot @ np.asarray(g["closing"], float))
    pre = _pose(hand, position - approach * PREGRASP)
    if target.get("action") in PRESS_ACTIONS:  # the closed fingers' tips on the surface
        return _pose(hand, position - approach * FINGERTIP), pre, 0.0
    width = float(g.get("width") or 2 * FINGER_OPEN)
    opening = min(FINGER_OPEN, width / 2 + 0.01)
    return _pose(hand, position + approach * inset), pre, opening


def _approach(run: _Run, grasp: np.ndarray, pre: np.ndarray, opening: float, grip: bool = True) -> str:
    """Move from the pre-grasp to the grasp and (with ``grip``) close the fingers; returns why it failed,
    or ""."""
    g = run.gripper
    g.place(pre, opening)
    n = max(1, int(round(APPROACH_TIME / run.dt)))
    for i in range(1, n + 1):
        t = pre.copy()
        t[:3, 3] = pre[:3, 3] + (grasp[:3, 3] - pre[:3, 3]) * (i / n)
        g.move(t)
        run.step()
    run.step(int(round(0.1 / run.dt)))
    miss = float(np.linalg.norm(g.tcp()[:3, 3] - grasp[:3, 3]))
    if miss > 0.01:
        on = run.gripper_on(run.contacts())
        return f"approach blocked by {', '.join(on) or 'the operated part'} ({miss * 1000:.0f} mm short)"
    if not grip:
        return ""
    g.grip(0.0)
    run.step(int(round(CLOSE_TIME / run.dt)))
    pairs = run.contacts()
    if run.held(pairs):
        return ""
    if g.opening() < 0.002:
        return "missed handle (the fingers closed on nothing)"
    on = run.gripper_on(pairs)
    return f"missed handle (fingers on {', '.join(on)})" if on else "missed handle (one finger on it)"


def _diagnose(run: _Run, pairs) -> str:
    """Why a held part stopped short: what blocks it, the arm's full force, or nothing found."""
    blocked = run.blockers(pairs)
    if blocked:
        return f"blocked by {', '.join(blocked)}"
    on = run.gripper_on(pairs)
    if on:
        return f"gripper blocked by {', '.join(on)}"
    limits = run.ctx.loaded[run.qi]
    q = float(np.asarray(run.art.qpos, float)[run.qi])
    span = max(abs(limits.upper - limits.lower), 1e-9)
    if run.gripper.force() >= 0.9 * ARM_FORCE and min(abs(q - limits.lower), abs(q - limits.upper)) < 0.01 * span:
        return "held at its joint limit (the path pushes against it)"
    if run.gripper.force() >= 0.9 * ARM_FORCE:
        return f"too stiff (the arm pulls with {ARM_FORCE:g} N and it does not follow)"
    return "stalled (the hand stopped on the path with no contact and little force)"


class PathMotion:
    """Along the annotated path (the grasp point over the range): progress is arc length (m); the hand turns
    as the path's tangent turns (a door's handle turns with the door). The path is the one annotated with the
    object at rest: it rides on the operated part's parent as the parent is now (``frame()``: the parent's
    pose now times the inverse of its pose at rest), so that a part whose parent is open (tines on a rack
    pulled out) or gives way under the pull (a tote sliding on its shelf as its lid is lifted) is followed
    where it is, as an arm's controller tracks the part in its hand."""

    speed, lead = SPEED, LEAD

    def __init__(self, path: Path3, grasp: np.ndarray, frame=None):
        self.path, self.frame = path, frame or (lambda: np.eye(4))
        self.grasp = np.linalg.inv(self.frame()) @ grasp  # in the path's frame (the parent at rest)
        self.length = path.length
        self.eps = min(0.002, path.length / 20)  # progress that is not a stall (a button travels ~2 mm)
        self.t0, self.offset = path.tangent(0.0), self.grasp[:3, 3] - path.at(0.0)
        self.here = 0.0  # the last progress read

    def progress(self, tcp: np.ndarray) -> float:
        local = (np.linalg.inv(self.frame()) @ tcp)[:3, 3]
        for _ in range(10):  # the offset turns with the tangent (as in pose): from the last place, refined
            here = self.path.nearest(local - rotation_between(self.t0, self.path.tangent(self.here)) @ self.offset)
            here, self.here = self.here, here
            if abs(here - self.here) < 1e-5:
                break
        return self.here

    def pose(self, here: float, goal: float) -> np.ndarray:
        turn = rotation_between(self.t0, self.path.tangent(here))  # the part turns as far as the hand has come
        return self.frame() @ _pose(turn @ self.grasp[:3, :3], self.path.at(goal) + turn @ self.offset)


def _about(axis: np.ndarray, angle: float) -> np.ndarray:
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


class TurnMotion:
    """Turning in place about the joint's axis (a knob grasped on its axis, whose path is a point): progress
    is the hand's angle about the axis (rad), unwrapped past half a turn."""

    speed, lead, eps = TURN_SPEED, TURN_LEAD, 0.02  # rad

    def __init__(self, pivot: np.ndarray, axis: np.ndarray, angle: float, grasp: np.ndarray):
        self.pivot, self.axis, self.grasp = pivot, _unit(axis) * (1 if angle >= 0 else -1), grasp
        self.length = abs(angle)
        k = int(np.argmin(np.abs(grasp[:3, :3].T @ self.axis)))  # the hand's axis most across the turn axis
        self.k = k
        self.ref, self.angle = self._across(grasp), 0.0
        self.back = 0.0  # rad the hand has been turned back by regrips (the knob stays where it was)

    def _across(self, tcp: np.ndarray) -> np.ndarray:
        v = tcp[:3, self.k]
        return _unit(v - self.axis * float(v @ self.axis))

    def progress(self, tcp: np.ndarray) -> float:
        u = self._across(tcp)
        a = math.atan2(float(np.cross(self.ref, u) @ self.axis), float(self.ref @ u))
        self.angle += (a - self.angle + math.pi) % (2 * math.pi) - math.pi  # unwrapped
        return self.angle + self.back

    def _hand(self, angle: float) -> np.ndarray:
        r = _about(self.axis, angle)
        return _pose(r @ self.grasp[:3, :3], self.pivot + r @ (self.grasp[:3, 3] - self.pivot))

    def pose(self, here: float, goal: float) -> np.ndarray:
        return self._hand(goal - self.back)

    def regrip(self, run: _Run) -> None:
        """Let go, turn the open hand back to where it took hold, and take hold again (the knob stays): how
        a hand turns a knob further than :data:`REGRIP`, its body sweeping only that much."""
        g = run.gripper
        g.grip(run.opening)
        run.step(int(round(RELEASE_TIME / run.dt)))
        start = self.angle
        n = max(1, int(round(start / TURN_SPEED / run.dt)))
        for i in range(1, n + 1):
            g.move(self._hand(start * (1 - i / n)))
            run.step()
            self.progress(g.tcp())
        run.step(int(round(RELEASE_TIME / run.dt)))
        self.progress(g.tcp())
        self.back += start - self.angle
        g.grip(0.0)
        run.step(int(round(CLOSE_TIME / run.dt)))


def _motion(run: _Run, grasp: np.ndarray):
    """How the hand moves the part: along the annotated path, or turning in place about the joint's axis
    when the path is a point (a knob held on its axis)."""
    root = _matrix(run.art.root.entity_pose)
    path = Path3([(root @ np.array([*map(float, p), 1.0]))[:3] for p in run.target["path"]])
    if path.length >= MIN_PATH:
        parent = run.ctx.joints[run.qi].parent_link  # the operated joint's (the link may ride on dummies)
        if parent is None or run.parent_rest is None:
            return PathMotion(path, grasp)
        back = np.linalg.inv(run.parent_rest)
        return PathMotion(path, grasp, lambda: _matrix(parent.entity_pose) @ back)
    joint = run.ctx.joints[run.qi]
    if joint.type not in ("revolute", "revolute_unwrapped"):
        return None
    frame = _matrix(joint.get_global_pose())  # PhysX: the joint's axis is its frame's x
    return TurnMotion(frame[:3, 3], frame[:3, 0], run.open - run.rest, grasp)


def _follow(run: _Run, grasp: np.ndarray, grip: bool, regrip: bool = False) -> Attempt:
    """Move the part with the compliant hand until the joint passes its open threshold; with ``grip`` the
    fingers must keep hold of it (a press or a push needs no hold); with ``regrip`` a knob turned in place is
    let go and taken again every :data:`REGRIP`."""
    motion = _motion(run, grasp)
    if motion is None:
        return run.fail(f"not attempted: the path is shorter than {MIN_PATH * 1000:g} mm and the joint does not"
                        " turn")
    threshold = float(run.target["open_threshold"])
    goal, best, best_time, lost = 0.0, 0.0, run.time, 0.0
    end = run.time + motion.length / motion.speed + EXTRA_TIME
    step = 0
    while run.time < end:
        here = motion.progress(run.gripper.tcp())
        if regrip and grip and isinstance(motion, TurnMotion) and motion.angle >= REGRIP:
            t0 = run.time
            motion.regrip(run)
            here, goal = motion.progress(run.gripper.tcp()), here
            end, best_time = end + run.time - t0, run.time
        goal = min(motion.length + motion.lead, goal + motion.speed * run.dt, here + motion.lead)
        run.gripper.move(motion.pose(here, goal))
        run.step()
        step += 1
        if here > best + motion.eps:
            best, best_time = here, run.time
        if step % CONTACT_EVERY:
            continue
        pairs = run.contacts()
        held = run.held(pairs) or not grip
        lost = 0.0 if held else lost + CONTACT_EVERY * run.dt
        if held and run.fraction() >= threshold:
            return Attempt(run.target["joint"], str(run.target.get("part_class")), True, run.fraction(), "",
                           run.time)
        if lost > SLIP_TIME:
            return run.fail("slipped (the fingers lost the part)")
        if run.time - best_time > STALL_TIME:
            return run.fail(_diagnose(run, pairs))
    return run.fail(_diagnose(run, run.contacts()))


def run_target(ctx, gripper: Gripper, target: dict, opened: dict[str, float] | None = None) -> Attempt:
    """One attempt at one annotated target (see the module docstring); ``opened``: joint -> open value of
    the other targets, used for the joints this one ``requires_open``."""
    names = [j.name for j in ctx.joints]
    if target["joint"] not in names:
        return Attempt(target["joint"], str(target.get("part_class")), False, 0.0,
                       "not a movable joint of the URDF", 0.0)
    q = ctx.rest_qpos.copy()
    for name in target.get("requires_open") or []:
        if name in names:
            i = names.index(name)
            q[i] = (opened or {}).get(name, ctx.loaded[i].upper)
    first, best, holds = None, None, 0
    grip = target.get("action") not in PRESS_ACTIONS
    for g in grasp_candidates(target):  # the next when one cannot be taken, or taken does not open it
        # a knob turned in place in one hold that does not open is taken the same way again, turned in holds
        # of at most REGRIP (the hand's body swept into a neighbour, or the fingers slipped over a long turn)
        ways = [g, {**g, "regrip": True}] if grip and not g.get("regrip") and _turns_in_place(target) else [g]
        for way in ways:
            taken, got = _hold(ctx, gripper, target, q, way, grip)
            if not taken:
                first = first or got
                break
            if got.ok:
                return got
            best = got if best is None or got.reached > best.reached else best
        else:
            holds += 1
        if holds >= HOLDS:
            break
    return best or first


def _hold(ctx, gripper: Gripper, target: dict, q: np.ndarray, g: dict, grip: bool) -> tuple[bool, Attempt]:
    """One hold ``g`` from the object at ``q``: ``(False, why the hand could not take it)`` or ``(True, what
    following the path with it did)``."""
    ctx.reset()  # the annotated path is the grasp point's with every joint at rest: its parent's pose then
    parent = ctx.joints[[j.name for j in ctx.joints].index(target["joint"])].parent_link
    parent_rest = None if parent is None else _matrix(parent.entity_pose)
    ctx.reset(q)
    ctx.make_passive()
    run = _Run(ctx, gripper, target)
    run.parent_rest = parent_rest
    grasp, pre, opening = _grasp_frames(run, g)
    # a regrip lets go of a knob as wide as its box across the hand (no wider: knobs stand beside it)
    a, k = _unit(g["approach"]), _unit(g["closing"])
    across = [box_extent(target.get("box"), d) for d in (k, np.cross(a, k))]
    run.opening = opening if None in across else min(FINGER_OPEN, max(opening, math.hypot(*across) / 2 + 0.005))
    why = _approach(run, grasp, pre, opening, grip)
    if why:
        return False, run.fail(why)
    return True, _follow(run, grasp, grip, bool(g.get("regrip")))


def check_robot(folder: str | Path) -> list[CheckResult]:
    """The robot check of one object folder: one ``robot`` result per annotated target."""
    from .sim import _context, _find_urdf, _read_meta, capture_native_log, load_sapien

    folder = Path(folder)
    targets = read_annotations(folder)
    if targets is None:
        return [CheckResult("robot", True, "skipped: no annotations.json in this folder")]
    if not targets:
        return [CheckResult("robot", True, "no annotated targets")]
    meta = _read_meta(folder)
    urdf = _find_urdf(folder, meta)
    with capture_native_log():
        # no floor: an appliance stands on a counter, where the hand passes below the counter's edge (a
        # part that swings into the floor is the reach check's finding)
        scene, art = load_sapien(urdf, ground=False)
        ctx = _context(folder, meta, urdf, scene, art)
        gripper = Gripper(scene)
    opened = {t["joint"]: float(t["open"]) for t in targets}
    results = []
    for target in targets:
        t0 = time.perf_counter()
        a = run_target(ctx, gripper, target, opened)
        results.append(CheckResult("robot", a.ok, f"{a.joint} ({a.part}): {a.describe()}"
                                                  f" [{time.perf_counter() - t0:.2f} s]"))
    return results


# --------------------------------------------------------------------------- summary

_DETAIL = re.compile(r"^(?P<joint>\S+) \((?P<part>[^)]*)\): (?P<what>[^;]*)")


def robot_table(rows) -> str:
    """The robot check's summary: joints opened / attempted per part class (rows) and category (columns),
    the median wall seconds per joint, and the count of each failure reason. ``rows`` as for
    :func:`~.report.summary_table`; skipped objects (no annotations) are left out."""
    from .report import seconds

    cells: dict[tuple[str, str], list[int]] = {}
    times: dict[str, list[float]] = {}
    reasons: dict[str, int] = {}
    categories: list[str] = []
    for row in rows:
        category, results = row[0], row[1]
        for r in results:
            m = _DETAIL.match(r.detail or "") if r.name == "robot" else None
            if not m:
                continue
            categories += [] if category in categories else [category]
            for key in ((m["part"], category), (m["part"], ALL), (JOINTS, category), (JOINTS, ALL)):
                c = cells.setdefault(key, [0, 0])
                c[0] += bool(r.ok)
                c[1] += 1
            s = seconds(r)
            for key in (category, ALL):
                times.setdefault(key, []).extend([] if s is None else [s])
            if not r.ok:
                reason = m["what"].split(" (")[0]
                reasons[reason] = reasons.get(reason, 0) + 1
    if not categories:
        return "robot: no annotated joints"
    columns = [*categories, ALL]
    parts = sorted({p for p, _c in cells if p != JOINTS})
    table = [["robot: joints opened", *columns]]
    for part in [*parts, JOINTS]:
        table.append([part, *(f"{cells[(part, c)][0]}/{cells[(part, c)][1]}" if (part, c) in cells else "-"
                              for c in columns)])
    table.append(["seconds per joint", *(f"{statistics.median(times[c]):.2f}" if times.get(c) else "-"
                                         for c in columns)])
    widths = [max(len(r[i]) for r in table) for i in range(len(columns) + 1)]
    lines = ["  ".join(cell.ljust(w) for cell, w in zip(r, widths)).rstrip() for r in table]
    if reasons:
        lines.append("failures: " + "; ".join(f"{n} {why}" for why, n in sorted(reasons.items(), key=lambda x: -x[1])))
    return "\n".join(lines)
