"""Writing a scene: every distinct object once under ``objects/``, and three views of the room.

* ``scene.usda``: the root layer. ``/Scene/physicsScene`` (the one ``PhysicsScene``), ``/Scene/Room`` (floor,
  ceiling and walls as static box colliders, split around the openings doors and windows fill, and the room's
  fixtures: a worktop carried over a run's under-counter appliances) and
  ``/Scene/Objects/<id>``: each placed object an ``Xform`` that references its own object stage
  (``objects/<key>/<name>/<name>.usda``) with its pose; an object standing free (an item set down) has its
  fixed ``root_joint`` disabled, so it rests on what carries it. An object placed twice is written once and
  referenced twice (the same layers: USD loads them once).
* ``scene.json``: the room, and per object its folder, category, seed, overrides, pose, fixed or free,
  what it stands on (the ``on`` field: ``floor``, ``wall:<name>`` or ``<id>:<link>``) and its support regions
  (:mod:`infmob_usd.supports`, the object's frame at rest).
* ``scene.xml``: MuJoCo, one model attaching every object's MJCF (``<attach>``, prefix ``<id>/``), the room
  as static boxes; a free object's root is a free joint.
"""

from __future__ import annotations

import json
import math
import shutil
import tempfile
from pathlib import Path

import numpy as np

from . import check_output_dir, publish, write_object

SCENE_FILES = ("scene.usda", "scene.json", "scene.xml")
ROOM_COLOR = (0.85, 0.84, 0.8)  # walls, floor and ceiling; a fixture (a worktop) carries its own


def _r(x, n: int = 6):
    return [round(float(v), n) + 0.0 for v in np.ravel(x)]


def scene_record(s, folders: dict[str, str]) -> dict:
    """What ``scene.json`` holds (``folders``: object key -> folder relative to the scene folder)."""
    from infmob_usd._version import __version__

    room = s.room
    objects = []
    for p in s.placed:
        yaw = math.degrees(math.atan2(p.pose[1, 0], p.pose[0, 0]))
        objects.append({"id": p.id, "folder": folders[p.made.key], "name": p.made.obj.name,
                        "category": p.made.category, "seed": p.made.seed,
                        "overrides": {k: v for k, v in sorted(p.made.overrides.items())},
                        "position": _r(p.pose[:3, 3]), "yaw": round(yaw, 6) + 0.0, "fixed": p.fixed, "on": p.on,
                        "wall": p.wall,
                        "bounds": [_r(p.lo), _r(p.hi)],
                        "supports": [g.as_dict() for g in p.made.regions]})
    return {"name": s.name, "kind": s.kind, "seed": s.seed, "version": __version__, "texture_size": s.texture_size,
            "parameters": {k: (round(v, 9) if isinstance(v, float) else v) for k, v in s.params.items()},
            "overrides": s.overrides,
            "room": {"width": room.width, "depth": room.depth, "height": room.height,
                     "wall_thickness": room.wall_thickness,
                     "openings": [{"wall": o.wall, "start": round(o.start, 6), "end": round(o.end, 6),
                                   "bottom": round(o.bottom, 6), "top": round(o.top, 6), "filled_by": o.what}
                                  for o in room.openings],
                     "boxes": [{"name": n, "min": _r(lo), "max": _r(hi)} for n, lo, hi in room.wall_boxes()]
                     + [_fixture_record(f) for f in room.fixtures]},
            "objects": objects}


def _fixture_record(f) -> dict:
    """A fixture in ``scene.json``: its box, its flat colour, and the material it wears (an object's slot)."""
    rec = {"name": f.name, "min": _r(f.lo), "max": _r(f.hi), "color": _r(f.color, 4)}
    if f.wears is not None:
        rec["wears"] = {"object": f.wears[0], "slot": f.wears[1], "grain": "XY"[f.grain]}
    return rec


def _fixture_mesh(stage, path: str, box: dict, worn: dict) -> None:
    """A fixture as a box mesh with the UVs an object's piece gets (its grain along the run), wearing
    ``worn``'s (an object record's) material of the slot: a reference to that object's own material prim,
    so its textures and shading are the object's own."""
    from pxr import Gf, Sdf, UsdGeom, UsdPhysics, UsdShade, Vt

    from infmob_usd.primitives import box_between
    from infmob_usd.shading import corner_attributes

    lo, hi = np.array(box["min"]), np.array(box["max"])
    piece = box_between(lo - (lo + hi) / 2, hi - (lo + hi) / 2, box["wears"]["slot"])
    long = np.eye(3)[0 if box["wears"]["grain"] == "X" else 1]
    frame = np.column_stack([long, np.cross([0.0, 0.0, 1.0], long), [0.0, 0.0, 1.0]])
    normals, uvs = corner_attributes(piece.vertices, piece.faces, np.repeat(frame[None], len(piece.faces), 0))
    mesh = UsdGeom.Mesh.Define(stage, path)
    mesh.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(np.asarray(piece.vertices, np.float32)))
    mesh.CreateFaceVertexCountsAttr([3] * len(piece.faces))
    mesh.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(np.asarray(piece.faces, np.int32).ravel()))
    mesh.CreateNormalsAttr(Vt.Vec3fArray.FromNumpy(np.asarray(normals, np.float32)))
    mesh.SetNormalsInterpolation(UsdGeom.Tokens.faceVarying)
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    st = UsdGeom.PrimvarsAPI(mesh).CreatePrimvar("st", Sdf.ValueTypeNames.TexCoord2fArray,
                                                 UsdGeom.Tokens.faceVarying)
    st.Set(Vt.Vec2fArray.FromNumpy(np.asarray(uvs, np.float32)))
    mesh.AddTranslateOp().Set(Gf.Vec3d(*_r((lo + hi) / 2)))
    mesh.CreateDisplayColorAttr([Gf.Vec3f(*box["color"])])
    UsdPhysics.CollisionAPI.Apply(mesh.GetPrim())
    UsdPhysics.MeshCollisionAPI.Apply(mesh.GetPrim()).CreateApproximationAttr(UsdPhysics.Tokens.convexHull)
    look = UsdShade.Material.Define(stage, f"/Scene/Room/Looks/{box['name']}")
    look.GetPrim().GetReferences().AddReference(f"./{worn['folder']}/{worn['name']}.usda",
                                                f"/{worn['name']}/Looks/{box['wears']['slot']}")
    UsdShade.MaterialBindingAPI.Apply(mesh.GetPrim()).Bind(look)


def _root_joint_paths(usda: Path) -> list[str]:
    """Paths (below the default prim) of the fixed joints that tie an object's root to the world."""
    from pxr import Usd, UsdPhysics

    stage = Usd.Stage.Open(str(usda))
    root = stage.GetDefaultPrim().GetPath()
    out = []
    for prim in stage.Traverse():
        if prim.IsA(UsdPhysics.FixedJoint) and not UsdPhysics.Joint(prim).GetBody0Rel().GetTargets():
            out.append(str(prim.GetPath().MakeRelativePath(root)))
    return sorted(out)


def write_usd(s, rec: dict, folder: Path) -> None:
    from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics

    stage = Usd.Stage.CreateNew(str(folder / "scene.usda"))
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdPhysics.SetStageKilogramsPerUnit(stage, 1.0)
    top = UsdGeom.Xform.Define(stage, "/Scene")
    stage.SetDefaultPrim(top.GetPrim())
    physics = UsdPhysics.Scene.Define(stage, "/Scene/physicsScene")
    physics.CreateGravityDirectionAttr(Gf.Vec3f(0, 0, -1))
    physics.CreateGravityMagnitudeAttr(9.81)
    UsdGeom.Scope.Define(stage, "/Scene/Room")
    placed = {o["id"]: o for o in rec["objects"]}
    for box in rec["room"]["boxes"]:
        lo, hi = np.array(box["min"]), np.array(box["max"])
        if "wears" in box:
            _fixture_mesh(stage, f"/Scene/Room/{box['name']}", box, placed[box["wears"]["object"]])
            continue
        cube = UsdGeom.Cube.Define(stage, f"/Scene/Room/{box['name']}")
        cube.CreateSizeAttr(1.0)
        cube.AddTranslateOp().Set(Gf.Vec3d(*_r((lo + hi) / 2)))
        cube.AddScaleOp().Set(Gf.Vec3f(*_r(hi - lo)))
        cube.CreateDisplayColorAttr([Gf.Vec3f(*box.get("color", ROOM_COLOR))])
        UsdPhysics.CollisionAPI.Apply(cube.GetPrim())
    UsdGeom.Scope.Define(stage, "/Scene/Objects")
    free_joints: dict[str, list[str]] = {}
    for o in rec["objects"]:
        xf = UsdGeom.Xform.Define(stage, f"/Scene/Objects/{o['id']}")
        usda = f"./{o['folder']}/{o['name']}.usda"
        xf.GetPrim().GetReferences().AddReference(usda)
        xf.AddTranslateOp().Set(Gf.Vec3d(*o["position"]))
        xf.AddRotateZOp().Set(float(o["yaw"]))
        if not o["fixed"]:
            if o["folder"] not in free_joints:
                free_joints[o["folder"]] = _root_joint_paths(folder / o["folder"] / f"{o['name']}.usda")
            for rel in free_joints[o["folder"]]:
                over = stage.OverridePrim(xf.GetPath().AppendPath(Sdf.Path(rel)))
                over.CreateAttribute("physics:jointEnabled", Sdf.ValueTypeNames.Bool).Set(False)
    stage.GetRootLayer().Save()


def write_mjcf(rec: dict, folder: Path) -> None:
    lines = [f'<mujoco model="{rec["name"]}">', '  <compiler angle="radian" autolimits="true"/>',
             '  <option timestep="0.002"/>', "  <asset>"]
    models = {}
    for o in rec["objects"]:
        if o["folder"] not in models:
            models[o["folder"]] = f"m{len(models)}"
            lines.append(f'    <model name="{models[o["folder"]]}" file="{o["folder"]}/{o["name"]}.xml"/>')
    lines += ["  </asset>", "  <worldbody>", '    <light pos="0 0 3" dir="0 0 -1" directional="true"/>']
    for box in rec["room"]["boxes"]:
        lo, hi = np.array(box["min"]), np.array(box["max"])
        c, h = _r((lo + hi) / 2), _r((hi - lo) / 2)
        lines.append(f'    <geom name="room/{box["name"]}" type="box" pos="{" ".join(map(str, c))}"'
                     f' size="{" ".join(map(str, h))}" rgba="{" ".join(map(str, box.get("color", ROOM_COLOR)))} 1"/>')
    for o in rec["objects"]:
        pos, yaw = " ".join(map(str, o["position"])), round(math.radians(o["yaw"]), 9)
        attach = f'<attach model="{models[o["folder"]]}" prefix="{o["id"]}/"/>'
        if o["fixed"]:
            lines.append(f'    <frame name="{o["id"]}" pos="{pos}" euler="0 0 {yaw}">{attach}</frame>')
        else:
            lines.append(f'    <body name="{o["id"]}" pos="{pos}" euler="0 0 {yaw}"><freejoint name="{o["id"]}/free"/>'
                         f'{attach}</body>')
    lines += ["  </worldbody>", "</mujoco>", ""]
    (folder / "scene.xml").write_text("\n".join(lines))


def _write_objects(s, tmp: Path, pool) -> dict[str, str]:
    """Every distinct object of ``s`` written once under ``tmp/objects/`` (in ``pool`` when given, all finished
    before this returns, even when one fails); ``{key: its folder, relative}``."""
    jobs, folders = [], {}
    for made in s.objects:
        where = tmp / "objects" / made.key
        where.mkdir(parents=True)
        jobs.append((made.obj, where))
        folders[made.key] = f"objects/{made.key}/{made.obj.name}"
    if pool is None:
        for obj, where in jobs:
            write_object(obj, where, None)
        return folders
    futures = [pool.submit(write_object, obj, where, None) for obj, where in jobs]
    for f in futures:
        f.exception()  # wait for every one: the caller removes tmp on failure
    for f in futures:
        f.result()
    return folders


def write_scene(s, out, pool=None) -> Path:
    """Write scene ``s`` into ``out/<name>/`` (atomically: built in a temporary folder beside it, then renamed);
    ``pool``: an executor the object folders are written in."""
    from infmob_usd.runs import new_run_id, temp_prefix

    out = check_output_dir(Path(out))
    final = out / s.name
    prefix = temp_prefix(s.name, new_run_id())
    tmp = Path(tempfile.mkdtemp(prefix=prefix, suffix=".tmp", dir=out))
    try:
        folders = _write_objects(s, tmp, pool)
        rec = scene_record(s, folders)
        (tmp / "scene.json").write_text(json.dumps(rec, indent=1, sort_keys=False) + "\n")
        write_usd(s, rec, tmp)
        write_mjcf(rec, tmp)
        publish(tmp, final, prefix)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return final
