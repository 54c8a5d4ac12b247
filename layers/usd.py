"""The USD asset: an interface layer and a payload of physics, materials and geometry layers.

Layout (docs/format.md describes every file of an object folder)::

    <name>.usda                 defaultPrim, kind=component, assetInfo, class label, payload
    payload/contents.usda       sublayers physics.usda, materials.usda, geometry.usdc
    payload/geometry.usdc       link Xforms (flat siblings), visual and collision meshes, grasp frames
    payload/materials.usda      UsdPreviewSurface materials, texture readers, bindings
    payload/physics.usda        articulation root, bodies, mass, colliders, joints, drives

Links are sibling Xforms under the root with rigid world transforms; a joint's
``physics:axis`` is always ``X``, the real direction carried by ``localRot0`` and
``localRot1`` (identical, because every link frame is world-aligned at rest).

A joint's return spring (:mod:`infmob_usd.springs`) is its ``PhysicsDriveAPI`` drive: ``stiffness`` and
``targetPosition`` at the spring's zero (beyond the rest stop: a preload), with the joint's damping.
PhysX articulation joints have no separate spring (``PhysxJointAPI`` has none); a force drive of
stiffness ``k`` towards ``q_ref`` is the spring ``-k (q - q_ref)``, and every UsdPhysics reader
(PhysX, Isaac Sim, Newton's ``target_ke`` / ``target_q``) reads it. A joint without a spring keeps
stiffness 0 (the drive is its damping only). The drive's ``maxForce`` is the joint's effort, plus, on
a spring, the spring's force at the far stop (PhysX caps the whole drive force, spring included).
Coupled joints: :func:`_mimic`.

The geometry and interface layers are authored directly as Sdf specs (no
``Usd.Stage``, which recomposes on every edit), and the per-corner normals and UVs of every
visual mesh of the object are computed in one vectorised pass: together ~5x faster than
authoring through the stage API, with the same specs and values. The contents, materials and
physics layers (metadata, many small prims, no arrays) are written as text in Sdf's own form (:class:`_Spec`),
byte for byte what Sdf saves of the same specs, in a tenth of the time.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from pxr import Gf, Sdf, Vt

from infmob_usd.effort import free_inertias
from infmob_usd.mass import principal

from .common import visual_meshes, write_file
from .meta import simready_metadata
from .mjcf import LIMIT_SOLREF

PAYLOAD = "payload"
SUBLAYERS = ("physics.usda", "materials.usda", "geometry.usdc")

_MAPS = {  # texture map -> (UsdPreviewSurface input, its type, reader output, output type, colour space)
    "basecolor": ("diffuseColor", "color3f", "rgb", "float3", "sRGB"),
    "roughness": ("roughness", "float", "r", "float", "raw"),
    "metallic": ("metallic", "float", "r", "float", "raw"),
    "normal": ("normal", "normal3f", "rgb", "float3", "raw"),
}

_T = Sdf.ValueTypeNames
_TYPES = {
    "bool": _T.Bool, "int": _T.Int, "float": _T.Float, "float2": _T.Float2, "float3": _T.Float3,
    "float4": _T.Float4, "double3": _T.Double3, "point3f": _T.Point3f, "color3f": _T.Color3f,
    "normal3f": _T.Normal3f, "quatf": _T.Quatf, "token": _T.Token, "string": _T.String,
    "asset": _T.Asset, "token[]": _T.TokenArray, "int[]": _T.IntArray, "float3[]": _T.Float3Array,
    "point3f[]": _T.Point3fArray, "normal3f[]": _T.Normal3fArray, "texCoord2f[]": _T.TexCoord2fArray,
}
_DEF = Sdf.SpecifierDef
# the Sdf calls made per mesh (~130 meshes, ~1,300 specs per object), looked up once
_new_attr, _copy_spec = Sdf.AttributeSpec, Sdf.CopySpec
_vec3f, _vec2f, _ints = Vt.Vec3fArray.FromNumpy, Vt.Vec2fArray.FromNumpy, Vt.IntArray.FromNumpy
_POINTS, _INTS, _FLOAT3S = _T.Point3fArray, _T.IntArray, _T.Float3Array
_NORMALS, _TEXCOORDS, _DOUBLE3 = _T.Normal3fArray, _T.TexCoord2fArray, _T.Double3
_VISUAL, _HULL = Sdf.Path("/Visual"), Sdf.Path("/Hull")  # in _templates()
_UNIFORM, _VARYING = Sdf.VariabilityUniform, Sdf.VariabilityVarying
_ORIENT_ONLY = Gf.Quatf(1.0)
# a collider's physics (physics.usda, under <root>/<link>/collisions): as Sdf writes the prim at depth 3
# MuJoCo's and Newton's collider schemas name the runtimes' convex-hull mesh collision (SimReady MUJOCO.COL.001,
# NEWTON.COL.001); their attributes keep the schemas' defaults
_COLLIDER_APIS = ", ".join(f'"{api}"' for api in (
    "PhysicsCollisionAPI", "PhysicsMeshCollisionAPI", "MaterialBindingAPI", "MjcCollisionAPI", "NewtonCollisionAPI",
    "NewtonMeshCollisionAPI"))
_COLLIDER = """            over "hull_{i:03d}" (
                prepend apiSchemas = [""" + _COLLIDER_APIS + """]
            )
            {{
                rel material:binding:physics = <{material}>
                uniform token physics:approximation = "convexHull"
            }}
"""


def axis_quat(axis: np.ndarray) -> Gf.Quatf:
    """The rotation taking +X onto ``axis``, as a unit quaternion."""
    q = Gf.Rotation(Gf.Vec3d(1, 0, 0), Gf.Vec3d(*map(float, axis))).GetQuat()
    return Gf.Quatf(q.GetReal(), Gf.Vec3f(q.GetImaginary()))


# -- Sdf authoring helpers -------------------------------------------------------


def _prim(parent, name: str, specifier=_DEF, type_name: str = "", schemas: tuple[str, ...] = ()) -> Sdf.PrimSpec:
    spec = Sdf.PrimSpec(parent, name, specifier, type_name)
    if schemas:
        spec.SetInfo("apiSchemas", Sdf.TokenListOp.Create(prependedItems=list(schemas)))
    return spec


def _attr(prim: Sdf.PrimSpec, name: str, type_name: str, value=None, uniform: bool = False,
          custom: bool = False) -> Sdf.AttributeSpec:
    spec = Sdf.AttributeSpec(prim, name, _TYPES[type_name], _UNIFORM if uniform else _VARYING, custom)
    if value is not None:
        spec.default = value
    return spec


def _label(prim: Sdf.PrimSpec, label: str) -> None:
    # UsdSemantics.LabelsAPI "class" instance; the caller adds "SemanticsLabelsAPI:class" to apiSchemas
    _attr(prim, "semantics:labels:class", "token[]", Vt.TokenArray([label]))


def _stage_metadata(layer: Sdf.Layer, root: str) -> None:
    layer.defaultPrim = root
    pseudo = layer.pseudoRoot
    pseudo.SetInfo("kilogramsPerUnit", 1.0)
    pseudo.SetInfo("metersPerUnit", 1.0)
    pseudo.SetInfo("upAxis", "Z")


def _link_xform(prim: Sdf.PrimSpec, origin) -> None:
    """A link's rigid transform: its rest origin and an identity orientation."""
    _attr(prim, "xformOp:translate", "double3", Gf.Vec3d(*map(float, origin)))
    _attr(prim, "xformOp:orient", "quatf", _ORIENT_ONLY)
    _attr(prim, "xformOpOrder", "token[]", Vt.TokenArray(["xformOp:translate", "xformOp:orient"]), uniform=True)


_TEMPLATES: Sdf.Layer | None = None


def _templates() -> Sdf.Layer:
    """Prims repeated many times per object, copied whole with ``Sdf.CopySpec`` (one call
    instead of one per spec): a visual Mesh and a collision Mesh."""
    global _TEMPLATES
    if _TEMPLATES is None:
        layer = Sdf.Layer.CreateAnonymous("infmob_usd_templates.usda")
        visual = _prim(layer.pseudoRoot, "Visual", _DEF, "Mesh")
        _attr(visual, "subdivisionScheme", "token", "none", uniform=True)
        hull = _prim(layer.pseudoRoot, "Hull", _DEF, "Mesh")
        _attr(hull, "subdivisionScheme", "token", "none", uniform=True)
        _attr(hull, "purpose", "token", "guide", uniform=True)
        _attr(hull, "visibility", "token", "invisible")  # never drawn: no visible twin of a visual mesh (VG.008)
        _attr(hull, "xformOpOrder", "token[]", Vt.TokenArray(["xformOp:translate"]), uniform=True)
        _TEMPLATES = layer
    return _TEMPLATES


def _from_template(templates: Sdf.Layer, template: Sdf.Path, layer: Sdf.Layer, path: Sdf.Path) -> Sdf.PrimSpec:
    """A copy of prim ``template`` of :func:`_templates` at ``path`` of ``layer``."""
    _copy_spec(templates, template, layer, path)
    return layer.GetPrimAtPath(path)


def _primvar(mesh: Sdf.PrimSpec, name: str, type_name, value, interpolation: str) -> None:
    """A varying attribute ``name`` of ``mesh`` with its ``interpolation`` (normals, UVs)."""
    spec = _new_attr(mesh, name, type_name, _VARYING, False)
    spec.default = value
    spec.SetInfo("interpolation", interpolation)


def _minmax(v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per-column min and max of ``(n, 3)`` ``v`` (column by column on large arrays: ~20x faster)."""
    if len(v) < 512:
        return v.min(0), v.max(0)
    return (np.array([v[:, 0].min(), v[:, 1].min(), v[:, 2].min()]),
            np.array([v[:, 0].max(), v[:, 1].max(), v[:, 2].max()]))


def _mesh(mesh: Sdf.PrimSpec, points: np.ndarray, extent: np.ndarray, faces: np.ndarray, counts: dict) -> None:
    """Author a triangle mesh: float32 ``points`` (n, 3) and ``extent`` (2, 3), int32 ``faces`` (m, 3)."""
    m = len(faces)
    if m not in counts:
        counts[m] = Vt.IntArray.FromNumpy(np.full(m, 3, np.int32))
    _new_attr(mesh, "points", _POINTS, _VARYING, False).default = _vec3f(points)
    _new_attr(mesh, "faceVertexCounts", _INTS, _VARYING, False).default = counts[m]
    _new_attr(mesh, "faceVertexIndices", _INTS, _VARYING, False).default = _ints(faces.ravel())
    _new_attr(mesh, "extent", _FLOAT3S, _VARYING, False).default = _vec3f(extent)


def _unique_rows(a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The distinct rows of float32 ``a`` in first-seen order, and each row's index among them."""
    keys = np.ascontiguousarray(a).view(np.dtype((np.void, a.dtype.itemsize * a.shape[1]))).ravel()
    _, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
    order = np.argsort(first, kind="stable")  # np.unique sorts by bytes: renumber in first-seen order
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    return a[first[order]], rank[inverse.ravel()].astype(np.int32)


def _visual_meshes(obj):
    """Every visual mesh of ``obj``, per link: ``[(vname, slot, role, verts, lo, hi, faces, normals, uvs)]``
    with float32 verts, normals and uvs, and the float64 bounds ``lo``, ``hi`` of the verts; a mesh whose pieces
    touch is written as several (:func:`_weld_free`)."""
    out: dict[str, list] = {}
    for lname, meshes in visual_meshes(obj).items():
        out[lname] = []
        names = {m[0] for m in meshes}
        for vname, slot, role, *mesh in meshes:
            for name, v, f, n, uv in _weld_free(vname, names, *mesh):
                out[lname].append((name, slot, role, v.astype(np.float32), *_minmax(v), f,
                                   n.astype(np.float32), uv.astype(np.float32)))
    return out


def _weld_free(vname: str, names: set, v: np.ndarray, f: np.ndarray, n: np.ndarray, uv: np.ndarray) -> list:
    """A visual mesh as meshes none of which has two points at the same place: ``[(name, v, f, n, uv)]``.

    Pieces of one material that touch (the panels of a casing meeting edge to edge) put two points at one
    place; merged, their shared edges would belong to four faces (non-manifold), kept apart they are points a
    validator asks to merge (omniverse-asset-validator's WeldChecker, SimReady VG.016). So the pieces (runs of
    points whose faces stay among them, as :func:`~.common.visual_meshes` concatenates them) are dealt, in
    order, into the first mesh where none of their points is already present: usually two or three meshes,
    named ``vname``, ``vname_w1``, ...; a mesh without such points is returned as it is. A piece that touches
    itself (a wire loop whose ends meet) is cut there first (:func:`_untouching`)."""
    v32 = np.ascontiguousarray(v, dtype=np.float32) + np.float32(0)  # as written (float32; -0 is 0)
    _, inv = np.unique(v32.view(np.dtype((np.void, 12))).ravel(), return_inverse=True)
    if len(inv) == 0 or inv.max() + 1 == len(v):
        return [(vname, v, f, n, uv)]
    # a piece's points are one run of indices its faces never leave: cut where no face spans
    spans = np.zeros(len(v) + 1, int)
    np.add.at(spans, f.min(1) + 1, 1)
    np.add.at(spans, f.max(1) + 1, -1)
    cuts = np.flatnonzero(np.cumsum(spans)[1:-1] == 0) + 1
    piece = np.zeros(len(v), int)
    piece[cuts] = 1
    piece = np.cumsum(piece)
    pair = np.sort(inv * (piece[-1] + 1) + piece)
    touching = set((pair[1:][pair[1:] == pair[:-1]] % (piece[-1] + 1)).tolist())  # pieces touching themselves
    face_piece = piece[f[:, 0]]
    order = np.argsort(face_piece, kind="stable")
    taken: list[set] = []
    face_mesh = np.empty(len(f), int)
    for faces in np.split(order, np.flatnonzero(np.diff(face_piece[order])) + 1):
        for unit in (_untouching(faces, f, inv) if face_piece[faces[0]] in touching else (faces,)):
            points = set(inv[f[unit]].ravel().tolist())
            k = next((i for i, t in enumerate(taken) if t.isdisjoint(points)), len(taken))
            if k == len(taken):
                taken.append(set())
            taken[k] |= points
            face_mesh[unit] = k
    out = []
    for k in range(len(taken)):
        faces = np.flatnonzero(face_mesh == k)
        used, local = np.unique(f[faces], return_inverse=True)
        corners = (3 * faces[:, None] + np.arange(3)).ravel()
        name = vname if k == 0 else _free_name(f"{vname}_w{k}", names)
        out.append((name, v[used], local.reshape(-1, 3).astype(f.dtype), n[corners], uv[corners]))
    return out


def _untouching(faces: np.ndarray, f: np.ndarray, inv: np.ndarray) -> list[np.ndarray]:
    """The faces of one piece that has two points at one place, in parts none of which has: each face joins
    the first part where its corners' places are free or its own."""
    parts: list[tuple[dict, list]] = []
    for face in faces.tolist():
        part = next((p for p in parts if all(p[0].get(inv[x], x) == x for x in f[face])), None)
        if part is None:
            part = ({}, [])
            parts.append(part)
        part[0].update((inv[x], x) for x in f[face])
        part[1].append(face)
    return [np.array(m) for _, m in parts]


def _free_name(name: str, names: set) -> str:
    """``name``, or ``name_1``, ``name_2``... if a mesh of the link already has it (then reserved)."""
    base, i = name, 0
    while name in names:
        i += 1
        name = f"{base}_{i}"
    names.add(name)
    return name


def _bounds(obj, visuals) -> tuple[np.ndarray, np.ndarray]:
    """``obj.bounds()`` from the visual meshes' bounds: every piece is in one visual mesh."""
    lo = np.array([g[4] + link.origin for link in obj.links for g in visuals[link.name]])
    hi = np.array([g[5] + link.origin for link in obj.links for g in visuals[link.name]])
    return lo.min(0), hi.max(0)


def _hulls(obj) -> dict[str, list]:
    """Collision hulls per link: ``[(centre (3,), float32 vertices - centre, float32 extent, int32 faces,
    float32 outward face normals (m, 3), material slot)]``.

    As in the URDF (:func:`layers.common.collision_placements`): each hull sits at the centre of its bounds
    (a translate op) with its vertices around it. Vectorised over every hull of the object;
    the extent is the float32 vertices' bounds (the float64 bounds rounded: rounding is
    monotonic).
    """
    out: dict[str, list] = {link.name: [] for link in obj.links}
    owners, verts, faces, slots = [], [], [], []
    for link in obj.links:
        for piece in link.pieces:
            for v, f in piece.hulls():
                owners.append(link.name)
                verts.append(v)
                faces.append(f)
                slots.append(piece.material)
    if not owners:
        return out
    sizes = np.array([len(v) for v in verts])
    starts = np.cumsum(sizes) - sizes
    v_all = np.vstack(verts)
    lo, hi = np.minimum.reduceat(v_all, starts), np.maximum.reduceat(v_all, starts)
    centre = (lo + hi) / 2
    v32 = (v_all - np.repeat(centre, sizes, axis=0)).astype(np.float32)
    extent = np.stack([lo - centre, hi - centre], 1).astype(np.float32)
    fsizes = np.array([len(f) for f in faces])
    fends = np.cumsum(fsizes)
    f32 = np.vstack(faces).astype(np.int32)
    tri = v_all[f32 + np.repeat(starts, fsizes)[:, None]]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    n = (n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-30)).astype(np.float32)
    for i, name in enumerate(owners):
        fs = slice(fends[i] - fsizes[i], fends[i])
        out[name].append((centre[i], v32[starts[i]:starts[i] + sizes[i]], extent[i], f32[fs], n[fs], slots[i]))
    return out


# -- USD text layers, written as text --------------------------------------------------


def _tuple_text(value: tuple) -> list:
    """``(x, y, ...)`` as :meth:`_Spec.attr` lines hold it: the floats left for :func:`_usda` to format."""
    line: list = ["("]
    for i, x in enumerate(value):
        line += [", ", float(x)] if i else [float(x)]
    line.append(")")
    return line


class _Spec:
    """A prim of a ``.usda`` layer written as text, exactly as Sdf writes it: specifier, type, name,
    ``prepend apiSchemas``, properties in name order, children in the order made, 4-space indents.

    Float values stay Python floats in the property text until :func:`_usda` formats all floats of
    the layer with one ``str(Vt.FloatArray)``: USD's own shortest float32 form, as the Sdf writer
    prints them. Writing the materials and physics layers this way instead of one Sdf spec call per
    prim and property (~4,000 per object) takes a tenth of the time; ``tests/test_usd_writer.py``
    checks that Sdf reads each layer back and writes it out byte for byte the same.
    """

    __slots__ = ("head", "schemas", "props", "children")

    def __init__(self, specifier: str, type_name: str, name: str, schemas: tuple[str, ...] = ()):
        self.head = f'{specifier} {type_name} "{name}"' if type_name else f'{specifier} "{name}"'
        self.schemas = schemas
        self.props: list[tuple[str, list]] = []
        self.children: list[_Spec | str] = []

    def child(self, specifier: str, type_name: str, name: str, schemas: tuple[str, ...] = ()) -> _Spec:
        spec = _Spec(specifier, type_name, name, schemas)
        self.children.append(spec)
        return spec

    def child_text(self, text: str) -> None:
        """A child prim already written out, indented for its depth, without float values: the many
        colliders that differ only in name and material, one ``str.format`` each instead of a spec."""
        self.children.append(text)

    def attr(self, type_name: str, name: str, value=None, uniform: bool = False) -> None:
        """``value``: a float, a tuple of floats, an int or bool, or text as written (``'"force"'``)."""
        line = [f"{'uniform ' if uniform else ''}{type_name} {name}"]
        if value is not None:
            line.append(" = ")
            if isinstance(value, list):  # an array of floats or of tuples of floats
                line.append("[")
                for k, item in enumerate(value):
                    line += [", "] if k else []
                    line += _tuple_text(item) if isinstance(item, tuple) else [float(item)]
                line.append("]")
            elif isinstance(value, tuple):
                line += _tuple_text(value)
            elif isinstance(value, bool):
                line.append("1" if value else "0")
            elif isinstance(value, int):
                line.append(str(value))
            else:
                line.append(value if isinstance(value, str) else float(value))
        self.props.append((name, line))

    def connect(self, type_name: str, name: str, source: str) -> None:
        self.props.append((name, [f"{type_name} {name}.connect = <{source}>"]))

    def rel(self, name: str, target: str) -> None:
        self.props.append((name, [f"rel {name} = <{target}>"]))

    def write(self, out: list, indent: str) -> None:
        if self.schemas:
            listed = ", ".join(f'"{s}"' for s in self.schemas)
            out.append(f"{indent}{self.head} (\n{indent}    prepend apiSchemas = [{listed}]\n{indent})\n{indent}{{\n")
        else:
            out.append(f"{indent}{self.head}\n{indent}{{\n")
        inner = indent + "    "
        for _, line in sorted(self.props, key=lambda p: p[0]):
            out.append(inner)
            out += line
            out.append("\n")
        for i, spec in enumerate(self.children):
            if i or self.props:
                out.append("\n")
            if isinstance(spec, str):
                out.append(spec)
            else:
                spec.write(out, inner)
        out.append(f"{indent}}}\n")


def _usda(*roots: _Spec) -> str:
    """The text of a ``.usda`` layer without layer metadata holding ``roots``, as Sdf saves it."""
    out = ["#usda 1.0\n"]
    for spec in roots:
        out.append("\n")
        spec.write(out, "")
    out.append("\n")
    floats = [x for x in out if type(x) is float]  # exactly float: attr() made them with float()
    if floats:
        text = iter(str(Vt.FloatArray(floats))[1:-1].split(", "))
        out = [next(text) if type(x) is float else x for x in out]
    return "".join(out)


def contents_layer(name: str, sublayers: tuple[str, ...] = SUBLAYERS) -> str:
    """A layer of the stage metadata and ``sublayers`` (payload/contents.usda), as Sdf saves it."""
    return ("#usda 1.0\n(\n    defaultPrim = \"" + name + "\"\n    kilogramsPerUnit = 1\n    metersPerUnit = 1\n"
            "    subLayers = [\n" + ",\n".join(f"        @./{n}@" for n in sublayers) + "\n    ]\n"
            "    upAxis = \"Z\"\n)\n\n")



# -- the layers --------------------------------------------------------------------


def write_usd(obj, folder: Path) -> Path:
    """Write the USD layers of ``obj`` into ``folder`` and return the interface layer path."""
    name = obj.name
    payload = folder / PAYLOAD
    payload.mkdir()
    geometry = Sdf.Layer.CreateNew(str(payload / "geometry.usdc"))
    visuals = _visual_meshes(obj)
    hulls = _hulls(obj)
    _templates()
    with Sdf.ChangeBlock():
        _geometry(geometry, obj, visuals, hulls)
    write_file(payload / "physics.usda", _physics(obj, hulls))
    write_file(payload / "materials.usda", _materials(obj, visuals))
    write_file(payload / "contents.usda", contents_layer(name))
    geometry.Save()
    return _write_interface(obj, folder, _bounds(obj, visuals))


def _geometry(layer: Sdf.Layer, obj, visuals, hulls) -> None:
    """Link transforms, visual meshes (normals, UVs, part labels), collision meshes."""
    root = _prim(layer.pseudoRoot, obj.name, _DEF, "Xform")
    counts: dict = {}  # faceVertexCounts by face count
    templates = _templates()
    for link in obj.links:
        lp = _prim(root, link.name, _DEF, "Xform", ("SemanticsLabelsAPI:class",))
        _link_xform(lp, link.origin)
        _label(lp, link.label)
        if visuals[link.name]:
            vp = _prim(lp, "visuals", _DEF, "Scope")
            vpath = vp.path
            for vname, _slot, role, verts, lo, hi, faces, normals, uvs in visuals[link.name]:
                mesh = _from_template(templates, _VISUAL, layer, vpath.AppendChild(vname))  # subdivisionScheme
                _mesh(mesh, verts, np.array([lo, hi], np.float32), faces.astype(np.int32), counts)
                _primvar(mesh, "normals", _NORMALS, _vec3f(normals), "faceVarying")
                st, st_index = _unique_rows(uvs)
                _primvar(mesh, "primvars:st", _TEXCOORDS, _vec2f(st), "faceVarying")
                _new_attr(mesh, "primvars:st:indices", _INTS, _VARYING, False).default = _ints(st_index)
                if role:
                    mesh.SetInfo("apiSchemas", Sdf.TokenListOp.Create(prependedItems=["SemanticsLabelsAPI:class"]))
                    _label(mesh, role)
        if hulls[link.name]:
            cp = _prim(lp, "collisions", _DEF, "Scope")
            cpath = cp.path
            for i, (centre, hv, extent, hf, hn, _slot) in enumerate(hulls[link.name]):
                # subdivisionScheme, purpose, visibility, xformOpOrder
                col = _from_template(templates, _HULL, layer, cpath.AppendChild(f"hull_{i:03d}"))
                _mesh(col, hv, extent, hf, counts)
                _primvar(col, "normals", _NORMALS, _vec3f(hn), "uniform")
                _new_attr(col, "xformOp:translate", _DOUBLE3, _VARYING, False).default = Gf.Vec3d(*centre.tolist())
    _grasp_frames(root, obj)


def _grasp_frames(root: Sdf.PrimSpec, obj) -> None:
    """An Xform per grasp frame of every interaction target (:mod:`infmob_usd.interaction`) under the link
    that carries it, named ``grasp_<joint>_<i>``: at the grasp's position, z along its approach and y along
    its closing axis, with the target's facts as typed ``infmob:`` attributes (docs/format.md)."""
    from infmob_usd.grasps import Grasp
    from infmob_usd.interaction import grasp_rotation, quat_wxyz

    for t in getattr(obj, "interaction", []):
        link = root.nameChildren[t["link"]]
        for i, gd in enumerate(t["grasps"]):
            g = Grasp.make(gd["position"], gd["approach"], gd["closing"], gd["width"], gd["depth"])
            gp = _prim(link, f"grasp_{t['joint']}_{i}", _DEF, "Xform")
            w, x, y, z = quat_wxyz(grasp_rotation(g))
            _attr(gp, "xformOp:translate", "double3", Gf.Vec3d(*g.position))
            _attr(gp, "xformOp:orient", "quatf", Gf.Quatf(w, x, y, z))
            _attr(gp, "xformOpOrder", "token[]", Vt.TokenArray(["xformOp:translate", "xformOp:orient"]), uniform=True)
            for name, kind, value in (
                    ("joint", "string", t["joint"]), ("partClass", "token", t["part_class"]),
                    ("handleClass", "token", t["handle_class"] or ""), ("action", "token", t["action"]),
                    ("approach", "float3", Gf.Vec3f(*g.approach)), ("closing", "float3", Gf.Vec3f(*g.closing)),
                    ("width", "float", g.width), ("depth", "float", g.depth),
                    ("rest", "float", t["rest"]), ("open", "float", t["open"]),
                    ("openThreshold", "float", t["open_threshold"]),
                    ("closedThreshold", "float", t["closed_threshold"])):
                _attr(gp, f"infmob:{name}", kind, value, custom=True)
            _grasp_line(gp, f"grasp_identifier_{t['joint']}_{i}", g.width)


def _grasp_line(frame: Sdf.PrimSpec, name: str, width: float) -> None:
    """The grasp as SimReady's graspable vector (GSP.001): a guide line in the grasp frame along its closing
    axis (y), between the two fingers' openings, through the part the fingers close on."""
    half = float(width) / 2
    line = _prim(frame, name, _DEF, "BasisCurves")
    _attr(line, "type", "token", "linear", uniform=True)
    _attr(line, "curveVertexCounts", "int[]", Vt.IntArray([2]))
    _attr(line, "points", "point3f[]", Vt.Vec3fArray([Gf.Vec3f(0, -half, 0), Gf.Vec3f(0, half, 0)]))
    _attr(line, "extent", "float3[]", Vt.Vec3fArray([Gf.Vec3f(0, -half, 0), Gf.Vec3f(0, half, 0)]))
    _attr(line, "purpose", "token", "guide", uniform=True)  # drawn by tools that show guides, not rendered


def _materials(obj, visuals, bindings: bool = True) -> str:
    """``materials.usda``: one UsdPreviewSurface per slot, a UsdUVTexture per map written, and (``bindings``)
    the bindings (:func:`_instances` writes them alone).

    The object's :class:`~infmob_usd.materials.Wear` of each look is written as shader inputs:
    a ``UsdTransform2d`` (rotation, translation) between the UV reader and the textures, the
    tint as the base colour texture's ``inputs:scale`` and the roughness scale as the
    roughness texture's; see-through looks get ``inputs:opacity`` and ``inputs:ior``.
    """
    from infmob_usd.materials import FAMILIES
    from infmob_usd.materials.families import nonvisual
    densities = getattr(obj, "densities", {})
    root = _Spec("over", "", obj.name)
    looks = root.child("def", "Scope", "Looks")
    lpath = f"/{obj.name}/Looks"
    for slot, look in obj.materials.items():
        mpath = f"{lpath}/{slot}"
        maps = [m for m in _MAPS if m in obj.textures.get(slot, {})]
        mat = looks.child("def", "Material", slot, ("SemanticsLabelsAPI:material",))
        mat.attr("token[]", "semantics:labels:material", f'["{look.family}"]')
        base, coating, attributes = nonvisual(look.family, densities.get(slot), look.opacity)
        mat.attr("token", "omni:simready:nonvisual:base", f'"{base}"')
        mat.attr("token", "omni:simready:nonvisual:coating", f'"{coating}"')
        mat.attr("token[]", "omni:simready:nonvisual:attributes", f'["{attributes}"]')
        surf = _preview_surface(mat, mpath, look, maps, FAMILIES[look.family].ior)
        _open_pbr(mat, mpath, look, FAMILIES[look.family].ior)
        if maps:
            _preview_textures(mat, surf, mpath, slot, look.wear, maps)
    if bindings:
        _bindings(root, obj, visuals, lpath)
    return _usda(root)


def _instances(obj, visuals) -> str:
    """The bindings of :func:`_materials` as a layer of their own (the Isaac layout's ``instances.usda``)."""
    root = _Spec("over", "", obj.name)
    _bindings(root, obj, visuals, f"/{obj.name}/Looks")
    return _usda(root)


def _preview_surface(mat: _Spec, mpath: str, look, maps: list[str], ior: float) -> _Spec:
    """The UsdPreviewSurface of a look, with constants for the maps not written (the textures room leaves out
    constant maps)."""
    mat.connect("token", "outputs:surface", f"{mpath}/PreviewSurface.outputs:surface")
    surf = mat.child("def", "Shader", "PreviewSurface")
    surf.attr("token", "info:id", '"UsdPreviewSurface"', uniform=True)
    surf.attr("float", "inputs:opacity", float(look.opacity))
    if look.opacity < 1.0:
        surf.attr("float", "inputs:ior", float(ior))
    surf.attr("int", "inputs:useSpecularWorkflow", 0)
    surf.attr("token", "outputs:surface")
    if "basecolor" not in maps:
        surf.attr("color3f", "inputs:diffuseColor",
                  tuple(float(c) * float(t) for c, t in zip(look.base_color, look.wear.tint)))
    if "roughness" not in maps:
        surf.attr("float", "inputs:roughness", _roughness(look))
    if "metallic" not in maps:
        surf.attr("float", "inputs:metallic", float(look.metallic))
    return surf


def _preview_textures(mat: _Spec, surf: _Spec, mpath: str, slot: str, wear, maps: list[str]) -> None:
    """The UV reader, this object's placement of the maps (``UsdTransform2d``) and a ``UsdUVTexture`` per map,
    connected to the preview surface."""
    reader = mat.child("def", "Shader", "TexCoordReader")
    reader.attr("token", "info:id", '"UsdPrimvarReader_float2"', uniform=True)
    reader.attr("string", "inputs:varname", '"st"')
    reader.attr("float2", "outputs:result")
    xf = mat.child("def", "Shader", "UVTransform")
    xf.attr("token", "info:id", '"UsdTransform2d"', uniform=True)
    xf.connect("float2", "inputs:in", f"{mpath}/TexCoordReader.outputs:result")
    xf.attr("float", "inputs:rotation", float(wear.uv_rotation))
    xf.attr("float2", "inputs:translation", tuple(map(float, wear.uv_offset)))
    xf.attr("float2", "outputs:result")
    for tex in maps:
        inp, itype, out, otype, space = _MAPS[tex]
        t = mat.child("def", "Shader", f"{tex}Texture")
        t.attr("token", "info:id", '"UsdUVTexture"', uniform=True)
        t.attr("asset", "inputs:file", f"@../textures/{slot}_{tex}.png@")
        t.attr("token", "inputs:sourceColorSpace", f'"{space}"')
        t.attr("token", "inputs:wrapS", '"repeat"')
        t.attr("token", "inputs:wrapT", '"repeat"')
        t.connect("float2", "inputs:st", f"{mpath}/UVTransform.outputs:result")
        if tex == "normal":
            t.attr("float4", "inputs:scale", (2.0, 2.0, 2.0, 1.0))
            t.attr("float4", "inputs:bias", (-1.0, -1.0, -1.0, 0.0))
        elif tex == "basecolor":
            t.attr("float4", "inputs:scale", (*map(float, wear.tint), 1.0))
        elif tex == "roughness":
            r = float(wear.roughness_scale)
            t.attr("float4", "inputs:scale", (r, r, r, 1.0))
        t.attr(otype, f"outputs:{out}")
        surf.connect(itype, f"inputs:{inp}", f"{mpath}/{tex}Texture.outputs:{out}")


def _bindings(root: _Spec, obj, visuals, lpath: str) -> None:
    """Each visual mesh bound to its slot's material, with what a viewer without the material draws (SimReady
    DISP.001): the look's mean colour, and its opacity where it is see-through."""
    for link in obj.links:
        if not visuals[link.name]:
            continue
        vp = root.child("over", "", link.name).child("over", "", "visuals")
        for vname, slot, *_ in visuals[link.name]:
            mesh = vp.child("over", "", vname, ("MaterialBindingAPI",))
            mesh.rel("material:binding", f"{lpath}/{slot}")
            look = obj.materials[slot]
            mesh.attr("color3f[]", "primvars:displayColor", [_display_colour(look)])
            if look.opacity < 1.0:
                mesh.attr("float[]", "primvars:displayOpacity", [float(look.opacity)])


def _open_pbr(mat: _Spec, mpath: str, look, ior: float) -> None:
    """The look as an OpenPBR surface on the MaterialX render context (SimReady VM.PBR.001), beside the
    UsdPreviewSurface: its mean colour, metalness and roughness as constants (the maps stay on the preview
    surface), see-through looks as transmission through a thin wall of the family's index."""
    mat.connect("token", "outputs:mtlx:surface", f"{mpath}/OpenPBR.outputs:out")
    pbr = mat.child("def", "Shader", "OpenPBR")
    pbr.attr("token", "info:id", '"ND_open_pbr_surface_surfaceshader"', uniform=True)
    pbr.attr("color3f", "inputs:base_color", _display_colour(look))
    pbr.attr("float", "inputs:base_metalness", float(look.metallic))
    pbr.attr("float", "inputs:specular_roughness", _roughness(look))
    pbr.attr("float", "inputs:specular_ior", min(3.0, max(1.0, float(ior))))
    if look.opacity < 1.0:
        pbr.attr("float", "inputs:transmission_weight", 1.0 - float(look.opacity))
        pbr.attr("bool", "inputs:geometry_thin_walled", True)
    pbr.attr("token", "outputs:out")


def _roughness(look) -> float:
    """A look's mean roughness as this object wears it, at most 1."""
    return min(1.0, float(look.roughness * look.wear.roughness_scale))


def _display_colour(look) -> tuple[float, ...]:
    """The base colour a look's texture averages to, tinted by its wear, in [0, 1] (linear, as diffuseColor)."""
    return tuple(min(1.0, max(0.0, float(c) * float(t))) for c, t in zip(look.base_color, look.wear.tint))


def _compound_pairs(obj) -> list[tuple[str, str]]:
    """``(child, parent)`` for every real link whose joint chain reaches its real parent through dummy
    links (a compound joint): the pairs a simulator's parent-child contact filter misses."""
    parent_of = {j.child: j.parent for j in obj.joints}
    dummy = {link.name for link in obj.links if link.dummy}
    pairs = []
    for link in obj.links:
        p = parent_of.get(link.name)
        if link.dummy or p not in dummy:
            continue
        while p in dummy and p in parent_of:
            p = parent_of[p]
        pairs.append((link.name, p))
    return pairs


def _physics_materials(root: _Spec, obj) -> dict[str, str]:
    """One ``PhysicsMaterialAPI`` Material per material family worn: slot -> its path."""
    from infmob_usd.materials.families import CONTACT

    families = sorted({look.family for look in obj.materials.values()})
    scope = root.child("def", "Scope", "PhysicsMaterials")
    for fam in families:
        c = CONTACT[fam]
        mat = scope.child("def", "Material", fam, ("PhysicsMaterialAPI", "SemanticsLabelsAPI:material"))
        mat.attr("float", "physics:staticFriction", float(c.static))
        mat.attr("float", "physics:dynamicFriction", float(c.dynamic))
        mat.attr("float", "physics:restitution", float(c.restitution))
        mat.attr("token[]", "semantics:labels:material", f'["{fam}"]')
    return {slot: f"/{obj.name}/PhysicsMaterials/{look.family}" for slot, look in obj.materials.items()}


def _quat(q) -> tuple[float, float, float, float]:
    """A ``Gf.Quatf`` / ``Gf.Quatd`` as ``(real, i, j, k)``, the order USD writes."""
    return (q.GetReal(), *q.GetImaginary())


def _drive(uj, j, dp: str, per_unit: float) -> None:
    """The joint's force drive: its damping, and its return spring as stiffness towards the spring's zero
    (module docstring); ``maxForce`` the effort (N or N m), plus the spring's force at the far stop."""
    uj.attr("token", dp + "type", '"force"', uniform=True)
    uj.attr("float", dp + "stiffness", float(j.stiffness * per_unit))
    if j.stiffness > 0:
        uj.attr("float", dp + "targetPosition", float(j.spring_ref / per_unit))
    uj.attr("float", dp + "damping", float(j.damping * per_unit))
    uj.attr("float", dp + "maxForce", float(j.effort + j.stiffness * (j.upper - j.spring_ref)))


def _newton_joint(uj, j, per_unit: float, inertia: float) -> None:
    """What Newton's USD importer reads of a joint beyond UsdPhysics (its default resolver reads only the
    ``newton:`` namespace, not ``physxJointAxis:*``): armature (kg or kg m^2), Coulomb friction (N or
    N m) and the velocity limit (m/s or deg/s), as ``newton:armature``, ``newton:friction`` and
    ``newton:velocityLimit`` (Newton 1.8, ``newton/_src/usd/schemas.py``, ``SchemaResolverNewton``);
    and the limits' stiffness and damping (per degree on rotations), which Featherstone applies as a
    spring: Newton's defaults, the same for a 64 g jar lid and a 38 kg table top, make a light part's
    stop ring past its explicit step (NaN) and let a heavy one sag. Here they are the MJCF's limit
    (:data:`~infmob_usd.layers.mjcf.LIMIT_SOLREF`: natural frequency ``1 / (0.95 tc)``, critically
    damped) on the joint's ``inertia`` (what it moves, with its armature)."""
    uj.attr("float", "newton:armature", float(j.armature))
    uj.attr("float", "newton:friction", float(j.friction))
    uj.attr("float", "newton:velocityLimit", float(j.velocity / per_unit))
    if j.type != "continuous":
        w = 1.0 / (0.95 * LIMIT_SOLREF[0])
        uj.attr("float", "newton:limitStiffness", float(inertia * w * w * per_unit))
        uj.attr("float", "newton:limitDamping", float(2.0 * LIMIT_SOLREF[1] * inertia * w * per_unit))


def _mimic(uj, j, leader: str) -> None:
    """A coupled joint as PhysX's mimic joint (``PhysxMimicJointAPI:rotX``, physx-usd-schemas 25.11: the
    instance PhysX's parser probes on revolute and prismatic joints, whose axis is X here). PhysX's
    relation is ``q + gearing * q_leader + offset = 0``, so gearing is ``-ratio`` and offset ``-offset``,
    both in joint coordinates (rad, m), as Newton 1.8 reads them (``coef1 = -gearing``, ``coef0 =
    -offset``, unconverted). PhysX itself enforces mimic joints on rotations only."""
    m = "physxMimicJoint:rotX:"
    uj.rel(m + "referenceJoint", leader)
    uj.attr("token", m + "referenceJointAxis", '"rotX"', uniform=True)
    uj.attr("float", m + "gearing", float(-j.mimic[1]))
    uj.attr("float", m + "offset", float(-j.mimic[2]))


def _rigid_bodies(root, obj, hulls, contact: dict, rp: str) -> None:
    """Each link of ``obj`` under ``root``: rigid body, mass, principal inertia, the contact filter across a
    compound chain, and its collision hulls bound to their physics materials (``contact``)."""
    filtered = dict(_compound_pairs(obj))
    for link in obj.links:
        apis = ("PhysicsRigidBodyAPI", "PhysicsMassAPI") + (("PhysicsFilteredPairsAPI",) if link.name in filtered
                                                             else ())
        prim = root.child("over", "", link.name, apis)
        moments, axes = principal(link.inertia)
        # Gf matrices act on row vectors: the rotation whose columns are the axes is axes.T
        q = Gf.Matrix3d(*axes.T.ravel().tolist()).ExtractRotation().GetQuat()
        prim.attr("float", "physics:mass", float(link.mass))
        prim.attr("point3f", "physics:centerOfMass", tuple(map(float, link.com)))
        prim.attr("float3", "physics:diagonalInertia", tuple(map(float, moments)))
        prim.attr("quatf", "physics:principalAxes", _quat(q))
        if link.name in filtered:
            prim.rel("physics:filteredPairs", f"{rp}/{filtered[link.name]}")
        if hulls[link.name]:
            cp = prim.child("over", "", "collisions")
            for i, hull in enumerate(hulls[link.name]):  # collision APIs, convexHull, its physics material
                cp.child_text(_COLLIDER.format(i=i, material=contact[hull[5]]))


def _physics(obj, hulls) -> str:
    """``physics.usda``: articulation root, rigid bodies with mass, colliders bound to physics materials,
    joints with drives, joint state, PhysX joint-axis limits and friction, and contact filters across
    compound chains."""
    root = _Spec("over", "", obj.name, ("PhysicsArticulationRootAPI", "NewtonArticulationRootAPI"))
    # parts collide with each other (not with the part they hang on): what PhysX does by default, said for Newton
    root.attr("bool", "newton:selfCollisionEnabled", True)
    rp = f"/{obj.name}"
    origins = {link.name: link.origin for link in obj.links}
    contact = _physics_materials(root, obj)
    free = free_inertias(obj)
    identity = (1.0, 0.0, 0.0, 0.0)
    _rigid_bodies(root, obj, hulls, contact, rp)
    joints = root.child("def", "Scope", "Joints")
    joints.child("def", "PhysicsFixedJoint", "root_joint").rel("physics:body1", f"{rp}/{obj.links[0].name}")
    for j in obj.joints:
        if j.type == "fixed":
            uj = joints.child("def", "PhysicsFixedJoint", j.name)
            rot = identity
        else:
            drive = "linear" if j.type == "prismatic" else "angular"
            kind = "PhysicsPrismaticJoint" if j.type == "prismatic" else "PhysicsRevoluteJoint"
            mimic = ("PhysxMimicJointAPI:rotX",) if j.mimic is not None else ()
            uj = joints.child("def", kind, j.name, (f"PhysicsDriveAPI:{drive}", f"PhysicsJointStateAPI:{drive}",
                                                    f"PhysxJointAxisAPI:{drive}", "MjcJointAPI") + mimic)
            # USD angles are degrees: limits, angular velocity and angular damping (per degree; URDF's per radian)
            per_unit = 1.0 if j.type == "prismatic" else math.pi / 180
            if j.type == "prismatic":
                uj.attr("float", "physics:lowerLimit", float(j.lower))
                uj.attr("float", "physics:upperLimit", float(j.upper))
            elif j.type == "revolute":
                uj.attr("float", "physics:lowerLimit", math.degrees(j.lower))
                uj.attr("float", "physics:upperLimit", math.degrees(j.upper))
            uj.attr("token", "physics:axis", '"X"', uniform=True)
            rot = _quat(axis_quat(j.axis))
            _drive(uj, j, f"drive:{drive}:physics:", per_unit)
            # the written pose is joint coordinate 0, at rest
            uj.attr("float", f"state:{drive}:physics:position", 0.0)
            uj.attr("float", f"state:{drive}:physics:velocity", 0.0)
            # PhysX joint axis (current physx-usd-schemas): velocity limit (deg/s or m/s), Coulomb friction
            ax = f"physxJointAxis:{drive}:"
            velocity = float(j.velocity / per_unit)
            uj.attr("float", ax + "maxJointVelocity", velocity)
            # the joint-level name PhysX schemas before the per-axis API used; Isaac Lab's importers and
            # isaaclab-robot-doctor read this one
            uj.attr("float", "physxJoint:maxJointVelocity", velocity)
            uj.attr("float", ax + "staticFrictionEffort", float(j.friction))
            uj.attr("float", ax + "dynamicFrictionEffort", float(j.friction))
            armature = getattr(j, "armature", None)
            if armature is not None:
                uj.attr("float", ax + "armature", float(armature))
            _newton_joint(uj, j, per_unit, free[j.name] + j.armature)
            # MuJoCo's USD joint schema: the armature the MJCF writes (kg or kg m^2)
            uj.attr("float", "mjc:armature", float(j.armature))
            if j.mimic is not None:
                _mimic(uj, j, f"{rp}/Joints/{j.mimic[0]}")
        uj.rel("physics:body0", f"{rp}/{j.parent}")
        uj.rel("physics:body1", f"{rp}/{j.child}")
        local0 = np.asarray(origins[j.child]) - np.asarray(origins[j.parent])
        uj.attr("point3f", "physics:localPos0", tuple(map(float, local0)))
        uj.attr("quatf", "physics:localRot0", rot)
        uj.attr("point3f", "physics:localPos1", (0.0, 0.0, 0.0))
        uj.attr("quatf", "physics:localRot1", rot)
        uj.attr("bool", "physics:collisionEnabled", False)
    return _usda(root)


def _write_interface(obj, folder: Path, bounds, payload: str = f"./{PAYLOAD}/contents.usda", more=None) -> Path:
    """The root layer: the asset's prim with its metadata and ``payload``; ``more(layer, prim, metadata)`` adds
    to them before the layer is saved."""
    name = obj.name
    path = folder / f"{name}.usda"
    layer = Sdf.Layer.CreateNew(str(path))
    with Sdf.ChangeBlock():
        _stage_metadata(layer, name)
        prim = _prim(layer.pseudoRoot, name, _DEF, "Xform", ("GeomModelAPI", "SemanticsLabelsAPI:class"))
        prim.kind = "component"
        prim.assetInfo = {
            "name": name,
            "identifier": Sdf.AssetPath(f"./{name}.usda"),
            "version": obj.version,
        }
        lo, hi = bounds
        _attr(prim, "extentsHint", "float3[]", Vt.Vec3fArray([Gf.Vec3f(*map(float, lo)), Gf.Vec3f(*map(float, hi))]))
        _label(prim, obj.category)
        prim.payloadList.prependedItems = [Sdf.Payload(payload)]
        meta = simready_metadata(obj, bounds)
        meta["asset_extents"] = Gf.Vec3d(*meta["asset_extents"])
        meta["validation"] = {"profile": "Robotics-Prop", "profile_version": "4.0.0"}  # simready-validate's default
        # SR.001 reads these four directly in customLayerData (SR.003/SR.004 inside SimReady_Metadata)
        direct = {k: meta[k] for k in ("asset_name", "asset_type", "source_file", "usd_date_generated")}
        if more is not None:
            more(layer, prim, meta)
        layer.customLayerData = {"SimReady_Metadata": meta, **direct}
    layer.Save()
    return path
