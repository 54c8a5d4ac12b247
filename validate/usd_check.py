"""USD checks of a written object: validators, physics parse, joint frames, files, URDF agreement."""

from __future__ import annotations

import functools
import math
import re
from pathlib import Path

import numpy as np
from pxr import Gf, Usd, UsdGeom, UsdPhysics, UsdUtils, UsdValidation

from .files import load_metadata, object_files, parse_urdf
from .result import CheckResult, guarded

POS_TOL = 1e-4  # m
ROT_TOL = 1e-3  # rad

_VALIDATORS = None


def _validators():
    global _VALIDATORS
    if _VALIDATORS is None:
        _VALIDATORS = UsdValidation.ValidationRegistry().GetOrLoadAllValidators()
    return _VALIDATORS


_MTLX_ID = re.compile(r"shaderId '(ND_\w+)'")


@functools.cache
def _materialx_nodedefs() -> frozenset[str] | None:
    """The nodedef names of MaterialX's standard library, or None without the MaterialX package."""
    try:
        import MaterialX as mx
    except ImportError:
        return None
    lib = mx.createDocument()
    mx.loadLibraries(mx.getDefaultDataLibraryFolders(), mx.getDefaultDataSearchPath(), lib)
    return frozenset(nd.getName() for nd in lib.getNodeDefs())


def _known_materialx_id(error) -> bool:
    """usd-core registers no MaterialX shader nodes, so its shader-id validator reports every MaterialX
    surface (the OpenPBR one beside each UsdPreviewSurface) as unknown: such an id is checked against
    MaterialX's own standard library instead (accepted unchecked where MaterialX is not installed)."""
    m = _MTLX_ID.search(error.GetMessage())
    if error.GetName().split(":")[-1] != "MissingShaderIdInRegistry" or m is None:
        return False
    nodedefs = _materialx_nodedefs()
    return nodedefs is None or m.group(1) in nodedefs


def usd_validators(stage: Usd.Stage) -> CheckResult:
    """Every registered ``pxr.UsdValidation`` validator: zero errors (MaterialX ids judged by MaterialX)."""
    errors = UsdValidation.ValidationContext(_validators()).Validate(stage)
    bad = [e for e in errors if e.GetType() == UsdValidation.ValidationErrorType.Error
           and not _known_materialx_id(e)]
    detail = "; ".join(f"{e.GetName()}: {e.GetMessage()[:160]}" for e in bad[:5])
    return CheckResult("usd_validators", not bad, detail or f"{len(_validators())} validators, 0 errors")


def _load_physics(stage: Usd.Stage) -> dict:
    fn = UsdPhysics.LoadUsdPhysicsFromRange
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        return fn(stage, ["/"])


def physics_parse(stage: Usd.Stage, meta: dict) -> CheckResult:
    """UsdPhysics parse: one articulation, one rigid body per link, the joints of the metadata."""
    parsed = _load_physics(stage)
    counts = {}
    for key, value in parsed.items():
        counts[str(key).split(".")[-1]] = len(value[0])
    want_links = len(meta["links"])
    want = {"RevoluteJoint": 0, "PrismaticJoint": 0, "FixedJoint": 1}  # + the root's joint to the world
    for j in meta["joints"]:
        want["PrismaticJoint" if j["type"] == "prismatic" else
             "FixedJoint" if j["type"] == "fixed" else "RevoluteJoint"] += 1
    problems = []
    if counts.get("Articulation", 0) != 1:
        problems.append(f"{counts.get('Articulation', 0)} articulations (want 1)")
    if counts.get("RigidBody", 0) != want_links:
        problems.append(f"{counts.get('RigidBody', 0)} rigid bodies (want {want_links})")
    for k, n in want.items():
        if counts.get(k, 0) != n:
            problems.append(f"{counts.get(k, 0)} {k} (want {n})")
    return CheckResult("usd_physics", not problems, "; ".join(problems) or
                       ", ".join(f"{k}={v}" for k, v in sorted(counts.items())))


def _local(pos, rot) -> Gf.Matrix4d:
    m = Gf.Matrix4d(1.0)
    m.SetRotateOnly(Gf.Quatd(rot))
    m.SetTranslateOnly(Gf.Vec3d(pos))
    return m


def joint_frames(stage: Usd.Stage) -> CheckResult:
    """world(body0) * local0 == world(body1) * local1 for every joint (no OpenUSD validator checks it)."""
    cache = UsdGeom.XformCache()
    worst, bad = 0.0, []
    n = 0
    for prim in stage.Traverse():
        if not prim.IsA(UsdPhysics.Joint):
            continue
        j = UsdPhysics.Joint(prim)
        b0, b1 = j.GetBody0Rel().GetTargets(), j.GetBody1Rel().GetTargets()
        if len(b1) != 1 or len(b0) > 1:
            bad.append(f"{prim.GetName()}: body0={len(b0)} body1={len(b1)} targets")
            continue
        w1 = _local(j.GetLocalPos1Attr().Get(), j.GetLocalRot1Attr().Get()) * \
            cache.GetLocalToWorldTransform(stage.GetPrimAtPath(b1[0]))
        if b0:
            w0 = _local(j.GetLocalPos0Attr().Get(), j.GetLocalRot0Attr().Get()) * \
                cache.GetLocalToWorldTransform(stage.GetPrimAtPath(b0[0]))
        else:  # attached to the world: the world frame is local0
            w0 = _local(j.GetLocalPos0Attr().Get(), j.GetLocalRot0Attr().Get())
            if not b0 and prim.IsA(UsdPhysics.FixedJoint):
                n += 1
                continue  # a fixed base joint may leave the world frame implicit
        dp = (w0.ExtractTranslation() - w1.ExtractTranslation()).GetLength()
        q0 = w0.ExtractRotationQuat()
        q1 = w1.ExtractRotationQuat()
        d = abs(Gf.Dot(q0, q1))
        da = 2 * math.acos(min(1.0, d))
        worst = max(worst, dp)
        n += 1
        if dp > POS_TOL or da > ROT_TOL:
            bad.append(f"{prim.GetName()}: frames differ by {dp * 1000:.2f} mm / {math.degrees(da):.2f} deg")
    return CheckResult("joint_frames", not bad, "; ".join(bad[:5]) or f"{n} joints agree (worst {worst:.1e} m)")


def _outside(folder: Path, base: Path, ref: str) -> bool:
    """Whether ``base/ref`` lies outside ``folder`` once ``..`` and symbolic links are resolved."""
    return not (base / ref).resolve().is_relative_to(folder.resolve())


def _non_finite_vertices(obj: Path) -> int:
    """How many ``v`` coordinates of an OBJ file are NaN or infinite (``ValueError``: not numbers)."""
    lines = re.findall(rb"(?m)^v[ \t]+([^\r\n#]*)", obj.read_bytes())
    if not lines:
        return 0
    values = np.array(b" ".join(lines).decode("ascii", "replace").split(), dtype=float)
    return int((~np.isfinite(values)).sum())


def files_exist(folder: Path, usd_path: Path, urdf: Path | None = None, urdf_required: bool = True) -> CheckResult:
    """Every layer, texture and mesh any file refers to exists inside the folder, by a relative path
    (no absolute path, no ``..`` or symbolic link out of it), and every OBJ vertex is finite."""
    layers, assets, unresolved = UsdUtils.ComputeAllDependencies(str(usd_path))
    missing = [str(p) for p in unresolved]
    absolute = [a for a in assets if not Path(a).resolve().is_relative_to(folder.resolve())]
    outside: list[str] = []
    urdf = urdf or object_files(folder)[1]
    refs = re.findall(r'filename="([^"]+)"', urdf.read_text()) if urdf.is_file() else []
    if not urdf.is_file() and urdf_required:
        missing.append(urdf.name)
    objs = []
    for ref in refs:
        if Path(ref).is_absolute():
            absolute.append(ref)
        elif _outside(folder, folder, ref):
            outside.append(ref)
        elif not (folder / ref).is_file():
            missing.append(ref)
        elif ref.lower().endswith(".obj"):
            objs.append(folder / ref)
    for mtl in (folder / "meshes").glob("*.mtl"):
        if _outside(folder, mtl.parent, mtl.name):
            outside.append(f"meshes/{mtl.name}")
            continue
        for line in mtl.read_text().splitlines():
            parts = line.split()
            if parts and parts[0].startswith(("map_", "norm")):
                if Path(parts[-1]).is_absolute():
                    absolute.append(f"{mtl.name}: {parts[-1]}")
                elif _outside(folder, mtl.parent, parts[-1]):
                    outside.append(f"{mtl.name}: {parts[-1]}")
                elif not (mtl.parent / parts[-1]).is_file():
                    missing.append(f"{mtl.name}: {parts[-1]}")
    nan = [f"{p.relative_to(folder)} ({n})" for p in dict.fromkeys(objs) if (n := _non_finite_vertices(p))]
    problems = ([f"missing {m}" for m in missing[:5]] + [f"absolute path {a}" for a in absolute[:5]]
                + [f"outside the folder (.. or a symbolic link): {o}" for o in outside[:5]]
                + [f"NaN or infinite vertex coordinates in {x}" for x in nan[:5]])
    return CheckResult("files", not problems, "; ".join(problems) or
                       f"{len(layers)} layers, {len(assets)} USD assets, {len(refs)} URDF meshes present")


def _collisions_agree(root: Usd.Prim, folder: Path) -> list[str]:
    """Per link, the centroids of the URDF's collision hulls (origin xyz/rpy applied) match
    those of the USD's collision meshes (translate op applied) to 1e-5 m."""
    from .physics import load_model

    try:
        model = load_model(folder)
    except (OSError, ValueError) as e:
        return [f"URDF collisions unreadable: {e}"]
    problems = []
    for link in root.GetChildren():
        if not link.HasAPI(UsdPhysics.RigidBodyAPI):
            continue
        usd = []
        for prim in Usd.PrimRange(link):
            if prim.HasAPI(UsdPhysics.CollisionAPI) and prim.IsA(UsdGeom.Mesh):
                pts = np.array(UsdGeom.Mesh(prim).GetPointsAttr().Get(), float)
                m = UsdGeom.Xformable(prim).GetLocalTransformation()
                usd.append(pts.mean(0) + np.array(m.ExtractTranslation()))
        geo = model.links.get(link.GetName())
        urdf = [h.mean(0) for h in geo.hulls] if geo else []
        if len(usd) != len(urdf):
            problems.append(f"link {link.GetName()}: {len(usd)} USD collision hulls, {len(urdf)} in the URDF")
            continue
        if usd:
            d = np.linalg.norm(np.array(usd)[:, None] - np.array(urdf)[None], axis=2)
            worst = float(max(d.min(0).max(), d.min(1).max()))  # every hull has a twin, both ways
            if worst > 1e-5:
                problems.append(f"link {link.GetName()}: a collision hull is {worst * 1000:.3f} mm from its twin")
    return problems


def _png_size(data: bytes) -> tuple[int, int] | None:
    """``(width, height)`` from a PNG's IHDR chunk, without decoding it; ``None`` if it is no PNG."""
    if data[:8] != b"\x89PNG\r\n\x1a\n" or data[12:16] != b"IHDR" or len(data) < 24:
        return None
    return int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")


def textures_decode(folder: Path) -> CheckResult:
    """Every PNG under ``textures/`` decodes to a square image (a flipped byte passes ``files``) of the
    ``texture_size`` the metadata records (an 8192 px map slipped into a 16 px object is refused before
    it is decoded)."""
    import cv2

    try:
        want = load_metadata(folder).get("texture_size")
    except (OSError, ValueError, AttributeError):
        want = None
    want = want if isinstance(want, int) and not isinstance(want, bool) else None
    paths = sorted((folder / "textures").glob("*.png"))
    bad, sized = [], []
    for path in paths:
        data = path.read_bytes()
        size = _png_size(data)
        if want is not None and size is not None and size != (want, want):
            sized.append(f"{path.name} {size[0]}x{size[1]}")
            continue
        img = cv2.imdecode(np.frombuffer(data, np.uint8), cv2.IMREAD_UNCHANGED)
        if img is None or img.ndim < 2 or img.shape[0] != img.shape[1] or img.shape[0] < 1:
            bad.append(path.name)
    problems = ([f"{len(bad)} of {len(paths)} texture PNGs do not decode: {', '.join(bad[:5])}"] if bad else []) + (
        [f"{len(sized)} texture PNGs are not the {want} px texture_size of metadata.json: {', '.join(sized[:5])}"]
        if sized else [])
    return CheckResult("textures", bool(paths) and not problems, "; ".join(problems) or
                       (f"{len(paths)} texture PNGs decode" if paths else "no texture PNGs in textures/"))


def usd_urdf_agree(stage: Usd.Stage, folder: Path, meta: dict, urdf_path: Path | None = None) -> CheckResult:
    """The URDF has the same links and joints (type, parent, child, axis, limits) as the USD, and
    the same collision hulls in the same places (per link, the centroid of every hull)."""
    urdf = parse_urdf(urdf_path or object_files(folder)[1])
    root = stage.GetDefaultPrim()
    bodies = {p.GetName() for p in Usd.PrimRange(root) if p.HasAPI(UsdPhysics.RigidBodyAPI)}
    problems = []
    if bodies != set(urdf.links):
        problems.append(f"links differ: only USD {sorted(bodies - set(urdf.links))[:3]},"
                        f" only URDF {sorted(set(urdf.links) - bodies)[:3]}")
    cache = UsdGeom.XformCache()
    for prim in Usd.PrimRange(root):
        if not prim.IsA(UsdPhysics.Joint) or not UsdPhysics.Joint(prim).GetBody0Rel().GetTargets():
            continue
        name = prim.GetName()
        uj = urdf.joints.get(name)
        if uj is None:
            problems.append(f"joint {name} missing from URDF")
            continue
        j = UsdPhysics.Joint(prim)
        b0 = j.GetBody0Rel().GetTargets()[0].name
        b1 = j.GetBody1Rel().GetTargets()[0].name
        if (b0, b1) != (uj.parent, uj.child):
            problems.append(f"{name}: USD {b0}->{b1}, URDF {uj.parent}->{uj.child}")
        kind = ("prismatic" if prim.IsA(UsdPhysics.PrismaticJoint) else
                "fixed" if prim.IsA(UsdPhysics.FixedJoint) else "revolute")
        utype = "revolute" if uj.type == "continuous" else uj.type
        if kind != utype:
            problems.append(f"{name}: USD {kind}, URDF {uj.type}")
            continue
        if kind == "fixed":
            continue
        # world axis of the USD joint: localRot0 applied to its X axis, in body0's world frame
        rot = Gf.Matrix4d(1.0).SetRotateOnly(Gf.Quatd(j.GetLocalRot0Attr().Get()))
        w0 = cache.GetLocalToWorldTransform(stage.GetPrimAtPath(j.GetBody0Rel().GetTargets()[0]))
        axis = np.array((rot * w0).TransformDir(Gf.Vec3d(1, 0, 0)))
        if np.linalg.norm(axis - uj.axis / np.linalg.norm(uj.axis)) > 1e-4:
            problems.append(f"{name}: axis USD {axis.round(4)} vs URDF {uj.axis}")
        lo, hi = prim.GetAttribute("physics:lowerLimit").Get(), prim.GetAttribute("physics:upperLimit").Get()
        if uj.type == "continuous":
            if lo is not None and math.isfinite(lo):
                problems.append(f"{name}: continuous in URDF but limited in USD")
            continue
        scale = math.pi / 180 if kind == "revolute" else 1.0
        if lo is None or hi is None or uj.lower is None or abs(lo * scale - uj.lower) > 1e-5 or \
                abs(hi * scale - uj.upper) > 1e-5:
            problems.append(f"{name}: limits USD {lo},{hi} vs URDF {uj.lower},{uj.upper}")
    problems += _collisions_agree(root, folder)
    n_meta = len(meta["joints"])
    if len(urdf.joints) != n_meta:
        problems.append(f"URDF has {len(urdf.joints)} joints, metadata {n_meta}")
    return CheckResult("usd_urdf_agree", not problems, "; ".join(problems[:5]) or
                       f"{len(bodies)} links, {len(urdf.joints)} joints agree")


def _lists(meta: dict, fmt: str) -> bool:
    """Whether the object's metadata names a file of this format (written without: ``--formats``)."""
    files = meta.get("files")
    return not isinstance(files, dict) or fmt in files


def check_usd(folder: Path) -> list[CheckResult]:
    """All USD-side checks of one object folder."""
    folder = Path(folder)
    try:
        meta = load_metadata(folder)
        if not isinstance(meta, dict) or not isinstance(meta.get("links"), list) \
                or not isinstance(meta.get("joints"), list):
            raise ValueError("not an object's metadata (no links and joints lists)")
    except (OSError, ValueError) as e:
        return [CheckResult("metadata", False, f"metadata.json unreadable: {e}")]
    usd_path, urdf_path = object_files(folder, meta)
    try:
        str(usd_path.resolve()).encode("utf-8")
    except UnicodeEncodeError:
        return [CheckResult("usd_open", False, "the folder's path is not valid UTF-8 and OpenUSD opens only UTF-8"
                            " paths: rename the folder")]
    if not usd_path.is_file():
        return [CheckResult("usd_open", False, f"{usd_path.name} is missing")]
    try:
        stage = Usd.Stage.Open(str(usd_path))
    except Exception as e:  # noqa: BLE001 - pxr.Tf.ErrorException on a corrupt layer
        from .result import one_line

        return [CheckResult("usd_open", False, f"{usd_path.name} does not open: {one_line(e)}")]
    if stage is None:
        return [CheckResult("usd_open", False, f"{usd_path.name} does not open")]
    return [
        *guarded("usd_validators", usd_validators, stage),
        *guarded("usd_physics", physics_parse, stage, meta),
        *guarded("joint_frames", joint_frames, stage),
        *guarded("files", files_exist, folder, usd_path, urdf_path, urdf_required=_lists(meta, "urdf")),
        *guarded("textures", textures_decode, folder),
        *(guarded("usd_urdf_agree", usd_urdf_agree, stage, folder, meta, urdf_path) if _lists(meta, "urdf")
          else [CheckResult("usd_urdf_agree", True, "skipped: no URDF in this folder")]),
    ]
