"""The USD asset in Isaac Sim's layout, with a variant set per physics runtime (``--usd-layout isaac``).

Layout (docs/format.md)::

    <name>.usda                     defaultPrim, kind=component, assetInfo, class label; payload base.usda;
                                    variant sets PhysX, Newton, MuJoCo (Disabled by default, Enabled adds
                                    the runtime's layer as a payload)
    payloads/base.usda              sublayers physics.usda, instances.usda, materials.usda, geometries.usdc
    payloads/geometries.usdc        link Xforms, visual and collision meshes, grasp frames (as payload/geometry.usdc)
    payloads/instances.usda         every visual mesh bound to its material, its display colour and opacity
    payloads/materials.usda         the materials (UsdPreviewSurface, OpenPBR, texture readers)
    payloads/physics.usda           runtime-neutral UsdPhysics only: articulation, bodies, mass, colliders, joints
    runnables/physics/physx.usda    PhysX's schemas and attributes (joint axes, mimic joints, velocity limits)
    runnables/physics/newton.usda   Newton's (collider schemas, joint armature, friction, limit stiffness)
    runnables/physics/mujoco.usda   MuJoCo's (collider schemas)

Isaac Sim's robot asset structure 3.0 names these layers (base, geometries, instances, materials, physics,
physx, mujoco) so one asset serves several physics runtimes without their attributes clashing; the SimReady
Foundation rules ISA.001 (performance layout) and RV.001-RV.011 (a runtime's data only in its own payload,
the neutral base free of every runtime's schemas) check it. The content is the default layout's
(:mod:`.usd`), byte for byte the same specs, moved: a runtime's schemas and attributes are recognised by
their namespace (``Physx*`` / ``physx*:``, ``Newton*`` / ``newton:``, ``Mjc*`` / ``mjc:``), so whatever
:func:`.usd._physics` authors for a runtime follows it here without a second list.

Opened as is, the stage is the neutral asset (every UsdPhysics reader simulates it); select a variant
(``prim.GetVariantSet("PhysX").SetVariantSelection("Enabled")``) for that runtime's tuning.
"""

from __future__ import annotations

from pathlib import Path

from pxr import Sdf

from . import usd
from .common import write_file

PAYLOADS = "payloads"
RUNNABLES = "runnables/physics"
BASE_SUBLAYERS = ("physics.usda", "instances.usda", "materials.usda", "geometries.usdc")
# variant set -> (payload file stem, schema prefix, attribute prefix)
RUNTIMES = {
    "PhysX": ("physx", "Physx", "physx"),
    "Newton": ("newton", "Newton", "newton:"),
    "MuJoCo": ("mujoco", "Mjc", "mjc:"),
}


def write_usd_isaac(obj, folder: Path) -> Path:
    """Write the USD layers of ``obj`` into ``folder`` in the Isaac layout; return the interface layer path."""
    name = obj.name
    payloads = folder / PAYLOADS
    payloads.mkdir()
    (folder / RUNNABLES).mkdir(parents=True)
    visuals = usd._visual_meshes(obj)
    hulls = usd._hulls(obj)
    geometry = Sdf.Layer.CreateNew(str(payloads / "geometries.usdc"))
    with Sdf.ChangeBlock():
        usd._geometry(geometry, obj, visuals, hulls)
    geometry.Save()
    physics = Sdf.Layer.CreateAnonymous(".usda")
    physics.ImportFromString(usd._physics(obj, hulls))
    for runtime, layer in split_runtimes(physics, name).items():
        write_file(folder / RUNNABLES / f"{RUNTIMES[runtime][0]}.usda", layer.ExportToString())
    write_file(payloads / "physics.usda", physics.ExportToString())
    write_file(payloads / "materials.usda", usd._materials(obj, visuals, bindings=False))
    write_file(payloads / "instances.usda", usd._instances(obj, visuals))
    write_file(payloads / "base.usda", usd.contents_layer(name, BASE_SUBLAYERS))
    return usd._write_interface(obj, folder, usd._bounds(obj, visuals), f"./{PAYLOADS}/base.usda", _variants)


def _runtime_of(token: str, prefix_index: int) -> str | None:
    for runtime, prefixes in RUNTIMES.items():
        if token.startswith(prefixes[prefix_index]):
            return runtime
    return None


def split_runtimes(layer: Sdf.Layer, name: str) -> dict[str, Sdf.Layer]:
    """Move every runtime's applied schemas and properties out of ``layer`` into a layer of its own (``over``
    specs at the same paths); ``layer`` keeps the neutral rest. Returns runtime -> its layer, in
    :data:`RUNTIMES` order, each with the stage metadata and ``defaultPrim`` ``name``."""
    out = {}
    for runtime in RUNTIMES:
        out[runtime] = Sdf.Layer.CreateAnonymous(".usda")
        usd._stage_metadata(out[runtime], name)
    pending = list(layer.rootPrims)
    while pending:
        spec = pending.pop(0)
        pending.extend(spec.nameChildren)
        if spec.HasInfo("apiSchemas"):
            items = list(spec.GetInfo("apiSchemas").prependedItems)
            for runtime in RUNTIMES:
                own = [s for s in items if _runtime_of(s, 1) == runtime]
                if own:
                    Sdf.CreatePrimInLayer(out[runtime], spec.path).SetInfo(
                        "apiSchemas", Sdf.TokenListOp.Create(prependedItems=own))
            spec.SetInfo("apiSchemas", Sdf.TokenListOp.Create(
                prependedItems=[s for s in items if _runtime_of(s, 1) is None]))
        for prop in list(spec.properties):
            runtime = _runtime_of(prop.name, 2)
            if runtime is not None:
                Sdf.CreatePrimInLayer(out[runtime], spec.path)
                Sdf.CopySpec(layer, prop.path, out[runtime], prop.path)
                spec.RemoveProperty(prop)
    return out


def _variants(layer: Sdf.Layer, prim: Sdf.PrimSpec, meta: dict) -> None:
    """The runtime variant sets on the root prim (SimReady RV.001/004/007: ``Disabled`` the default, ``Enabled``
    only the payload of ``runnables/physics/<runtime>.usda``) and their descriptors in the metadata (RV.003/
    006/009)."""
    physics = {}
    for runtime, (stem, _, _) in RUNTIMES.items():
        vset = Sdf.VariantSetSpec(prim, runtime)
        Sdf.VariantSpec(vset, "Disabled")
        enabled = Sdf.VariantSpec(vset, "Enabled")
        enabled.primSpec.payloadList.prependedItems = [Sdf.Payload(f"./{RUNNABLES}/{stem}.usda")]
        prim.variantSetNameList.prependedItems.append(runtime)
        prim.variantSelections[runtime] = "Disabled"
        physics[runtime] = {"prim": str(prim.path), "variantSetName": runtime, "activateOption": "Enabled"}
    meta["Variants"] = {"Physics": physics}
