"""Checks of a scene folder (``scene.json`` + ``objects/``): it loads, nothing overlaps, it rests, and every
joint of every object reaches its range inside the room.

:func:`load_sapien_scene` builds the scene in SAPIEN 3 (CPU physics) from ``scene.json`` and the objects'
URDFs: the room's boxes as static colliders, each object at its pose, its root fixed or free as the scene
says, coupled joints and return springs as the single-object loader sets them.

:func:`check_scene` runs, in order:

* ``scene_load``: SAPIEN builds every object; MuJoCo compiles ``scene.xml``; the USD stage opens with one
  ``PhysicsScene`` and every object's articulation root.
* ``scene_overlap``: after one step at rest no two bodies of different objects (or an object and the room)
  are in contact deeper than :data:`PENETRATION`.
* ``scene_rest``: 2 s passive under gravity: no object's joint moves more than 1 mm / 1 degree and no free
  object's root more than :data:`FREE_MOVE`.
* ``scene_reach``: every joint of every fixed object driven to both ends of its range from rest, inside the
  room with its neighbours in place: a door that hits a wall, a neighbour or an open dishwasher fails.
"""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import numpy as np

from .files import scene_refusals
from .result import CheckResult

PENETRATION = 0.002  # m
FREE_MOVE = 0.002  # m: a free object's root over the rest run


def _quat_z(yaw_deg: float) -> list[float]:
    h = math.radians(yaw_deg) / 2
    return [math.cos(h), 0.0, 0.0, math.sin(h)]


def load_sapien_scene(folder, scene_json=None, timestep: float = 1 / 240):
    """``(sapien.Scene, {placed id: SimContext})`` of the scene folder (SimContext: see :mod:`.sim`); a scene
    naming files outside its folder raises ``ValueError`` before anything is loaded."""
    folder = Path(folder)
    rec = scene_json if isinstance(scene_json, dict) else json.loads(
        Path(scene_json or folder / "scene.json").read_text())
    refused = scene_refusals(folder, rec)
    if refused:
        raise ValueError(f"{folder}: {refused[0]}")
    return _sapien_scene(folder, rec, timestep)


def _sapien_scene(folder: Path, rec: dict, timestep: float = 1 / 240):
    """:func:`load_sapien_scene` of a scene record already checked by :func:`scene_refusals` (the checks load
    the scene once per fixed object: the files are checked once, in :func:`check_scene`)."""
    from sapien.wrapper.urdf_loader import URDFLoader

    from .sim import _build_mimics, _context, _find_urdf, _import_sapien, _read_meta, _sapien_defaults, apply_springs

    sapien = _import_sapien()
    _sapien_defaults(sapien.physx)  # as every object check: not the defaults whatever ran before left
    scene = sapien.Scene([sapien.physx.PhysxCpuSystem()])
    scene.set_timestep(timestep)
    room = scene.create_actor_builder()
    for box in rec["room"]["boxes"]:
        lo, hi = np.array(box["min"]), np.array(box["max"])
        room.add_box_collision(sapien.Pose(((lo + hi) / 2).tolist()), ((hi - lo) / 2).tolist())
    room.build_static(name="room")
    contexts = {}
    for o in rec["objects"]:
        obj_folder = folder / o["folder"]
        meta = _read_meta(obj_folder)
        urdf = _find_urdf(obj_folder, meta)
        loader = URDFLoader()
        loader.set_scene(scene)
        builders, _, _ = loader.parse(str(urdf))
        builder = builders[0]
        for link in builder.link_builders:
            link.visual_records = []
        art = builder.build(fix_root_link=bool(o["fixed"]), build_mimic_joints=False)
        art.name = o["id"]
        _build_mimics(art, builder.mimic_joint_records)
        art.set_root_pose(sapien.Pose(o["position"], _quat_z(o["yaw"])))
        apply_springs(art, meta)
        contexts[o["id"]] = _context(obj_folder, meta, urdf, scene, art)
    return scene, contexts


def _load(folder: Path, rec: dict) -> list[str]:
    import mujoco
    from pxr import Usd, UsdPhysics

    problems = []
    try:
        mujoco.MjModel.from_xml_path(str(folder / "scene.xml"))
    except Exception as e:  # noqa: BLE001 - reported as the check's finding
        problems.append(f"MuJoCo: {' '.join(str(e).split())[:200]}")
    stage = Usd.Stage.Open(str(folder / "scene.usda"))
    scenes = [p for p in stage.Traverse() if p.IsA(UsdPhysics.Scene)]
    roots = [p for p in stage.Traverse() if p.HasAPI(UsdPhysics.ArticulationRootAPI)]
    if len(scenes) != 1:
        problems.append(f"USD: {len(scenes)} PhysicsScene prims (want 1)")
    if len(roots) != len(rec["objects"]):
        problems.append(f"USD: {len(roots)} articulation roots for {len(rec['objects'])} objects")
    return problems


def _overlaps(scene, contexts) -> list[str]:
    owner = {}
    for oid, ctx in contexts.items():
        for link in ctx.articulation.links:
            owner[link.entity.per_scene_id] = oid
    scene.step()
    worst: dict[tuple[str, str], float] = {}
    for c in scene.get_contacts():
        a, b = (owner.get(body.entity.per_scene_id, "room") for body in c.bodies)
        if a == b:
            continue
        depth = max((-p.separation for p in c.points), default=0.0)
        if depth > PENETRATION:
            key = tuple(sorted((a, b)))
            worst[key] = max(worst.get(key, 0.0), depth)
    return [f"{a} and {b} overlap {d * 1000:.0f} mm" for (a, b), d in sorted(worst.items(), key=lambda kv: -kv[1])]


def _rest(scene, contexts, duration: float = 2.0) -> tuple[list[str], str]:
    from .sim import _rest_limit

    start = {}
    for oid, ctx in contexts.items():
        ctx.reset()
        ctx.make_passive()
        start[oid] = np.array(ctx.articulation.get_root_pose().p)
        ctx.articulation.set_sleep_threshold(0.0)
    worst = {oid: np.zeros(len(ctx.joints)) for oid, ctx in contexts.items()}
    moved = {oid: 0.0 for oid in contexts}
    for _ in range(int(round(duration / scene.get_timestep()))):
        scene.step()
        for oid, ctx in contexts.items():
            q = np.asarray(ctx.articulation.qpos, float)
            worst[oid] = np.maximum(worst[oid], np.abs(q - ctx.rest_qpos))
            root = np.array(ctx.articulation.get_root_pose().p)
            moved[oid] = max(moved[oid], float(np.linalg.norm(root - start[oid])))
    problems = []
    for oid, ctx in contexts.items():
        for joint, d in zip(ctx.joints, worst[oid], strict=True):
            if not np.isfinite(d) or d > _rest_limit(joint)[0]:
                problems.append(f"{oid}/{joint.name} moved {d:.3g}")
        if moved[oid] > FREE_MOVE:
            problems.append(f"{oid} slid {moved[oid] * 1000:.1f} mm")
    most = max(moved.items(), key=lambda kv: kv[1])
    return problems, f"largest root motion {most[1] * 1000:.2f} mm ({most[0]})"


REACH_NEAR = 1.0  # m: objects this close to one (rest boxes) are loaded with it for its reach run


def _near(rec: dict, o: dict) -> dict:
    """``rec`` with only ``o`` and the objects whose rest boxes come within :data:`REACH_NEAR` of its own
    (whatever its doors and drawers could touch) and the room."""
    lo, hi = np.array(o["bounds"][0]) - REACH_NEAR, np.array(o["bounds"][1]) + REACH_NEAR
    keep = [x for x in rec["objects"] if x is o or (np.all(np.array(x["bounds"][0]) <= hi)
                                                     and np.all(np.array(x["bounds"][1]) >= lo))]
    return {**rec, "objects": keep}


def _reach(folder: Path, rec: dict) -> tuple[list[str], int, int]:
    """Every joint of every fixed object to both ends of its range from rest (parts it ``requires_open``
    held open), in the room with its neighbours at rest. Free items are not driven here: what they
    could hit is their own body (the object checks cover it), not the room."""
    from .sim import DRIVE_MAX_TIME, _reach_plans, _reach_runs

    problems, n, m = [], 0, 0
    for o in rec["objects"]:
        if not o["fixed"]:
            continue
        m += 1
        scene, contexts = _sapien_scene(folder, _near(rec, o))
        ctx = contexts[o["id"]]
        if not ctx.joints:
            continue
        for other in contexts.values():
            other.reset()
        failed, _, _ = _reach_runs(ctx, _reach_plans(ctx.meta)[0], int(round(DRIVE_MAX_TIME / ctx.timestep)))
        n += len(ctx.joints)
        if failed:
            missed = [m for i in sorted(failed) for m in failed[i]]
            problems.append(f"{o['id']}: {len(missed)} targets missed: {'; '.join(missed[:3])}")
    return problems, n, m


def check_scene(folder, reach: bool = True) -> list[CheckResult]:
    """Every check of :mod:`this module <infmob_usd.validate.scene>` on one scene folder."""
    folder = Path(folder)
    rec = json.loads((folder / "scene.json").read_text())
    refused = scene_refusals(folder, rec)
    if refused:  # nothing of it is loaded
        return [CheckResult("scene_load", False, "; ".join(refused[:3]))]
    t0 = time.perf_counter()
    try:
        scene, contexts = _sapien_scene(folder, rec)
    except Exception as e:  # noqa: BLE001 - a load failure is the finding
        return [CheckResult("scene_load", False, f"SAPIEN: {type(e).__name__}: {e}")]
    problems = _load(folder, rec)
    out = [CheckResult("scene_load", not problems, "; ".join(problems) or
                       f"{len(contexts)} objects in SAPIEN, MuJoCo and USD [{time.perf_counter() - t0:.1f} s]")]
    found = _overlaps(scene, contexts)
    out.append(CheckResult("scene_overlap", not found, "; ".join(found[:6]) or
                           f"no contact deeper than {PENETRATION * 1000:g} mm between objects or with the room"))
    found, info = _rest(scene, contexts)
    out.append(CheckResult("scene_rest", not found, "; ".join(found[:6]) + ("; " if found else "") + info))
    if reach:
        t0 = time.perf_counter()
        found, n, m = _reach(folder, rec)
        out.append(CheckResult("scene_reach", not found, "; ".join(found[:4]) or
                               f"{n} joints of the {m} fixed objects reach both ends in the room"
                               f" [{time.perf_counter() - t0:.0f} s]"))
    return out
