"""The USD asset: an interface layer and a payload of physics, materials and geometry layers.

Layout (see ../shared/USD.md)::

    <name>.usda                 defaultPrim, kind=component, assetInfo, class label, payload
    payload/contents.usda       sublayers physics.usda, materials.usda, geometry.usdc
    payload/geometry.usdc       link Xforms (flat siblings), visual and collision meshes
    payload/materials.usda      UsdPreviewSurface materials, texture readers, bindings
    payload/physics.usda        articulation root, bodies, mass, colliders, joints, drives

Links are sibling Xforms under the root with rigid world transforms; a joint's
``physics:axis`` is always ``X``, the real direction carried by ``localRot0`` and
``localRot1`` (identical, because every link frame is world-aligned at rest).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from pxr import Gf, Kind, Sdf, Usd, UsdGeom, UsdPhysics, UsdSemantics, UsdShade, Vt

from infmob_usd.mass import principal

from .common import centred_hulls, merge_pieces, visual_groups

PAYLOAD = "payload"
SUBLAYERS = ("physics.usda", "materials.usda", "geometry.usdc")

_MAPS = {  # texture map -> (UsdPreviewSurface input, reader output, colour space)
    "basecolor": ("diffuseColor", "rgb", "sRGB"),
    "roughness": ("roughness", "r", "raw"),
    "metallic": ("metallic", "r", "raw"),
    "normal": ("normal", "rgb", "raw"),
}


def axis_quat(axis: np.ndarray) -> Gf.Quatf:
    """The rotation taking +X onto ``axis``, as a unit quaternion."""
    q = Gf.Rotation(Gf.Vec3d(1, 0, 0), Gf.Vec3d(*map(float, axis))).GetQuat()
    return Gf.Quatf(q.GetReal(), Gf.Vec3f(q.GetImaginary()))


def _stage_metadata(stage: Usd.Stage, root: str) -> None:
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdPhysics.SetStageKilogramsPerUnit(stage, 1.0)
    stage.SetDefaultPrim(stage.GetPrimAtPath(f"/{root}"))


def _label(prim: Usd.Prim, label: str) -> None:
    UsdSemantics.LabelsAPI.Apply(prim, "class").CreateLabelsAttr().Set([label])


def _mesh(stage: Usd.Stage, path: str, vertices: np.ndarray, faces: np.ndarray) -> UsdGeom.Mesh:
    mesh = UsdGeom.Mesh.Define(stage, path)
    pts = Vt.Vec3fArray.FromNumpy(np.asarray(vertices, np.float32))
    mesh.CreatePointsAttr(pts)
    mesh.CreateFaceVertexCountsAttr(Vt.IntArray([3] * len(faces)))
    mesh.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(np.asarray(faces, np.int32).ravel()))
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    mesh.CreateExtentAttr(UsdGeom.Mesh.ComputeExtent(pts))
    return mesh


def write_usd(obj, folder: Path) -> Path:
    """Write the USD layers of ``obj`` into ``folder`` and return the interface layer path."""
    name = obj.name
    payload = folder / PAYLOAD
    payload.mkdir()
    layers = {n: Sdf.Layer.CreateNew(str(payload / n)) for n in SUBLAYERS}
    contents = Sdf.Layer.CreateNew(str(payload / "contents.usda"))
    contents.subLayerPaths = [f"./{n}" for n in SUBLAYERS]
    stage = Usd.Stage.Open(contents)
    root = f"/{name}"

    # -- geometry: link transforms, visual meshes, collision meshes --------------
    stage.SetEditTarget(Usd.EditTarget(layers["geometry.usdc"]))
    UsdGeom.Xform.Define(stage, root)
    for link in obj.links:
        lp = f"{root}/{link.name}"
        xf = UsdGeom.Xform.Define(stage, lp)
        xf.AddTranslateOp().Set(Gf.Vec3d(*map(float, link.origin)))
        xf.AddOrientOp().Set(Gf.Quatf(1.0))
        _label(xf.GetPrim(), link.label)
        for vname, _slot, pieces, role in visual_groups(link):
            verts, faces, normals, uvs = merge_pieces(pieces)
            mesh = _mesh(stage, f"{lp}/visuals/{vname}", verts, faces)
            mesh.CreateNormalsAttr(Vt.Vec3fArray.FromNumpy(normals.reshape(-1, 3).astype(np.float32)))
            mesh.SetNormalsInterpolation(UsdGeom.Tokens.faceVarying)
            st = UsdGeom.PrimvarsAPI(mesh).CreatePrimvar(
                "st", Sdf.ValueTypeNames.TexCoord2fArray, UsdGeom.Tokens.faceVarying)
            st.Set(Vt.Vec2fArray.FromNumpy(uvs.reshape(-1, 2).astype(np.float32)))
            if role:
                _label(mesh.GetPrim(), role)
        for i, (centre, hv, hf) in enumerate(centred_hulls(link)):
            col = _mesh(stage, f"{lp}/collisions/hull_{i:03d}", hv, hf)
            col.AddTranslateOp().Set(Gf.Vec3d(*map(float, centre)))
            col.CreatePurposeAttr(UsdGeom.Tokens.guide)

    # -- materials ------------------------------------------------------------
    stage.SetEditTarget(Usd.EditTarget(layers["materials.usda"]))
    looks = f"{root}/Looks"
    UsdGeom.Scope.Define(stage, looks)
    materials = {}
    for slot, look in obj.materials.items():
        mat = UsdShade.Material.Define(stage, f"{looks}/{slot}")
        surf = UsdShade.Shader.Define(stage, f"{looks}/{slot}/PreviewSurface")
        surf.CreateIdAttr("UsdPreviewSurface")
        surf.CreateInput("opacity", Sdf.ValueTypeNames.Float).Set(float(look.opacity))
        surf.CreateInput("useSpecularWorkflow", Sdf.ValueTypeNames.Int).Set(0)
        mat.CreateSurfaceOutput().ConnectToSource(surf.ConnectableAPI(), "surface")
        reader = UsdShade.Shader.Define(stage, f"{looks}/{slot}/TexCoordReader")
        reader.CreateIdAttr("UsdPrimvarReader_float2")
        reader.CreateInput("varname", Sdf.ValueTypeNames.String).Set("st")
        reader.CreateOutput("result", Sdf.ValueTypeNames.Float2)
        for tex, (inp, out, space) in _MAPS.items():
            t = UsdShade.Shader.Define(stage, f"{looks}/{slot}/{tex}Texture")
            t.CreateIdAttr("UsdUVTexture")
            t.CreateInput("file", Sdf.ValueTypeNames.Asset).Set(Sdf.AssetPath(f"../textures/{slot}_{tex}.png"))
            t.CreateInput("sourceColorSpace", Sdf.ValueTypeNames.Token).Set(space)
            t.CreateInput("wrapS", Sdf.ValueTypeNames.Token).Set("repeat")
            t.CreateInput("wrapT", Sdf.ValueTypeNames.Token).Set("repeat")
            t.CreateInput("st", Sdf.ValueTypeNames.Float2).ConnectToSource(reader.ConnectableAPI(), "result")
            if tex == "normal":
                t.CreateInput("scale", Sdf.ValueTypeNames.Float4).Set(Gf.Vec4f(2, 2, 2, 1))
                t.CreateInput("bias", Sdf.ValueTypeNames.Float4).Set(Gf.Vec4f(-1, -1, -1, 0))
            vtype = Sdf.ValueTypeNames.Float3 if out == "rgb" else Sdf.ValueTypeNames.Float
            t.CreateOutput(out, vtype)
            itype = Sdf.ValueTypeNames.Normal3f if tex == "normal" else (
                Sdf.ValueTypeNames.Color3f if tex == "basecolor" else Sdf.ValueTypeNames.Float)
            surf.CreateInput(inp, itype).ConnectToSource(t.ConnectableAPI(), out)
        materials[slot] = mat
    for link in obj.links:
        for vname, slot, _pieces, _role in visual_groups(link):
            prim = stage.OverridePrim(f"{root}/{link.name}/visuals/{vname}")
            UsdShade.MaterialBindingAPI.Apply(prim).Bind(materials[slot])

    # -- physics --------------------------------------------------------------
    stage.SetEditTarget(Usd.EditTarget(layers["physics.usda"]))
    UsdPhysics.ArticulationRootAPI.Apply(stage.OverridePrim(root))
    origins = {link.name: link.origin for link in obj.links}
    for link in obj.links:
        prim = stage.OverridePrim(f"{root}/{link.name}")
        UsdPhysics.RigidBodyAPI.Apply(prim)
        mass = UsdPhysics.MassAPI.Apply(prim)
        moments, axes = principal(link.inertia)
        # Gf matrices act on row vectors: the rotation whose columns are the axes is axes.T
        q = Gf.Matrix3d(*axes.T.ravel().tolist()).ExtractRotation().GetQuat()
        mass.CreateMassAttr(float(link.mass))
        mass.CreateCenterOfMassAttr(Gf.Vec3f(*map(float, link.com)))
        mass.CreateDiagonalInertiaAttr(Gf.Vec3f(*map(float, moments)))
        mass.CreatePrincipalAxesAttr(Gf.Quatf(q.GetReal(), Gf.Vec3f(q.GetImaginary())))
        n_hulls = sum(len(p.convex) for p in link.pieces)
        for i in range(n_hulls):
            cp = stage.OverridePrim(f"{root}/{link.name}/collisions/hull_{i:03d}")
            UsdPhysics.CollisionAPI.Apply(cp)
            UsdPhysics.MeshCollisionAPI.Apply(cp).CreateApproximationAttr(UsdPhysics.Tokens.convexHull)
    joints = f"{root}/Joints"
    UsdGeom.Scope.Define(stage, joints)
    base = UsdPhysics.FixedJoint.Define(stage, f"{joints}/root_joint")
    base.CreateBody1Rel().SetTargets([Sdf.Path(f"{root}/{obj.links[0].name}")])
    for j in obj.joints:
        path = f"{joints}/{j.name}"
        if j.type == "fixed":
            uj = UsdPhysics.FixedJoint.Define(stage, path)
            rot = Gf.Quatf(1.0)
        elif j.type == "prismatic":
            uj = UsdPhysics.PrismaticJoint.Define(stage, path)
            uj.CreateLowerLimitAttr(float(j.lower))
            uj.CreateUpperLimitAttr(float(j.upper))
        else:
            uj = UsdPhysics.RevoluteJoint.Define(stage, path)
            if j.type == "revolute":
                uj.CreateLowerLimitAttr(math.degrees(j.lower))
                uj.CreateUpperLimitAttr(math.degrees(j.upper))
        if j.type != "fixed":
            uj.CreateAxisAttr(UsdPhysics.Tokens.x)
            rot = axis_quat(j.axis)
            drive_kind = "linear" if j.type == "prismatic" else "angular"
            drive = UsdPhysics.DriveAPI.Apply(uj.GetPrim(), drive_kind)
            drive.CreateTypeAttr("force")
            drive.CreateStiffnessAttr(0.0)
            # USD angular damping is per degree; URDF's is per radian
            damping = j.damping if j.type == "prismatic" else j.damping * math.pi / 180
            drive.CreateDampingAttr(float(damping))
            drive.CreateMaxForceAttr(float(j.effort))
            uj.GetPrim().CreateAttribute("physxJoint:jointFriction", Sdf.ValueTypeNames.Float).Set(
                float(j.friction))
        uj.CreateBody0Rel().SetTargets([Sdf.Path(f"{root}/{j.parent}")])
        uj.CreateBody1Rel().SetTargets([Sdf.Path(f"{root}/{j.child}")])
        local0 = np.asarray(origins[j.child]) - np.asarray(origins[j.parent])
        uj.CreateLocalPos0Attr(Gf.Vec3f(*map(float, local0)))
        uj.CreateLocalRot0Attr(rot)
        uj.CreateLocalPos1Attr(Gf.Vec3f(0.0))
        uj.CreateLocalRot1Attr(rot)
        uj.CreateCollisionEnabledAttr(False)

    stage.SetEditTarget(Usd.EditTarget(contents))
    _stage_metadata(stage, name)
    for layer in layers.values():
        layer.Save()
    contents.Save()
    return _write_interface(obj, folder)


def _write_interface(obj, folder: Path) -> Path:
    name = obj.name
    path = folder / f"{name}.usda"
    stage = Usd.Stage.CreateNew(str(path))
    prim = UsdGeom.Xform.Define(stage, f"/{name}").GetPrim()
    _stage_metadata(stage, name)
    Usd.ModelAPI(prim).SetKind(Kind.Tokens.component)
    Usd.ModelAPI(prim).SetAssetInfo({
        "name": name,
        "identifier": Sdf.AssetPath(f"./{name}.usda"),
        "version": obj.version,
    })
    lo, hi = obj.bounds()
    UsdGeom.ModelAPI.Apply(prim).SetExtentsHint(Vt.Vec3fArray([Gf.Vec3f(*map(float, lo)),
                                                                Gf.Vec3f(*map(float, hi))]))
    _label(prim, obj.category)
    prim.GetPayloads().AddPayload(f"./{PAYLOAD}/contents.usda")
    stage.GetRootLayer().Save()
    return path
