"""The USD in Isaac Sim's layout (``--usd-layout isaac``): the default layout's content, split into Isaac Sim's
layers with one variant set per physics runtime (SimReady FET_000_PHYSX/NEWTON/MUJOCO, FET_100_ISAAC)."""

import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from pxr import Sdf, Usd

import infmob_usd
from infmob_usd.errors import OutputError
from infmob_usd.layers import parse_formats
from infmob_usd.validate.simready import available

RUNTIME_PREFIXES = {"physx": ("Physx", "physx"), "newton": ("Newton", "newton:"), "mujoco": ("Mjc", "mjc:")}


@pytest.fixture(scope="module")
def pair(tmp_path_factory):
    """A microwave (coupled-free, springs, glass, grasps) written in both layouts."""
    obj = infmob_usd.generate("microwave", 0, texture_size=16)
    out = tmp_path_factory.mktemp("layouts")
    return (infmob_usd.save(obj, out / "payload" / "microwave", formats="usd,urdf"),
            infmob_usd.save(obj, out / "isaac" / "microwave", formats="isaac,urdf"))


def _tokens(layer: Sdf.Layer) -> set[str]:
    """Every applied schema and property name authored in ``layer``."""
    found = set()

    def visit(path):
        spec = layer.GetObjectAtPath(path)
        if isinstance(spec, Sdf.PrimSpec):
            if spec.HasInfo("apiSchemas"):
                found.update(spec.GetInfo("apiSchemas").GetAddedOrExplicitItems())
            found.update(p.name for p in spec.properties)
    layer.Traverse(Sdf.Path.absoluteRootPath, visit)
    return found


def test_the_isaac_layout_has_isaac_sims_layers_and_a_variant_set_per_runtime(pair):
    _, isaac = pair
    name = isaac.name
    for f in ("payloads/base.usda", "payloads/geometries.usdc", "payloads/instances.usda", "payloads/materials.usda",
              "payloads/physics.usda", *(f"runnables/physics/{r}.usda" for r in RUNTIME_PREFIXES)):
        assert (isaac / f).is_file(), f
    assert not (isaac / "payload").exists()
    stage = Usd.Stage.Open(str(isaac / f"{name}.usda"))
    prim = stage.GetDefaultPrim()
    for runtime in ("PhysX", "Newton", "MuJoCo"):
        vset = prim.GetVariantSets().GetVariantSet(runtime)
        assert vset.GetVariantNames() == ["Disabled", "Enabled"] and vset.GetVariantSelection() == "Disabled"
    meta = Sdf.Layer.FindOrOpen(str(isaac / f"{name}.usda")).customLayerData["SimReady_Metadata"]
    assert meta["Variants"]["Physics"]["MuJoCo"] == {"prim": f"/{name}", "variantSetName": "MuJoCo",
                                                     "activateOption": "Enabled"}


def test_each_runtime_keeps_its_schemas_in_its_own_layer_and_the_base_is_neutral(pair):
    _, isaac = pair
    neutral = set()
    for f in ("physics.usda", "instances.usda", "materials.usda", "geometries.usdc"):
        neutral |= _tokens(Sdf.Layer.FindOrOpen(str(isaac / "payloads" / f)))
    every_prefix = tuple(p for pair in RUNTIME_PREFIXES.values() for p in pair)
    assert neutral and not [t for t in neutral if t.startswith(every_prefix)]
    for runtime, own in RUNTIME_PREFIXES.items():
        tokens = _tokens(Sdf.Layer.FindOrOpen(str(isaac / "runnables" / "physics" / f"{runtime}.usda")))
        assert tokens and all(t.startswith(own) for t in tokens), (runtime, sorted(tokens)[:5])


def _flat(stage: Usd.Stage, folder: Path) -> dict:
    """Every prim's type, applied schemas (as a set) and attribute and relationship values, by path (an asset
    path as written and as resolved, relative to ``folder``)."""
    def value(v):
        if isinstance(v, Sdf.AssetPath):
            return v.path, Path(v.resolvedPath).relative_to(folder) if v.resolvedPath else None
        return v
    out = {}
    for prim in stage.Traverse():
        attrs = {a.GetName(): value(a.Get()) for a in prim.GetAttributes() if a.HasAuthoredValue()}
        rels = {r.GetName(): [str(t) for t in r.GetTargets()] for r in prim.GetRelationships()}
        out[str(prim.GetPath())] = (prim.GetTypeName(), frozenset(prim.GetAppliedSchemas()), attrs, rels)
    return out


def test_every_runtime_enabled_composes_exactly_the_default_layouts_asset(pair):
    """Nothing is lost or changed by the split: the Isaac stage with all three runtimes enabled is the default
    layout's stage, prim for prim and value for value."""
    payload, isaac = pair
    stage = Usd.Stage.Open(str(isaac / f"{isaac.name}.usda"))
    for runtime in ("PhysX", "Newton", "MuJoCo"):
        stage.GetDefaultPrim().GetVariantSet(runtime).SetVariantSelection("Enabled")
    got, want = _flat(stage, isaac), _flat(Usd.Stage.Open(str(payload / f"{payload.name}.usda")), payload)
    assert got.keys() == want.keys()
    for path in want:
        assert got[path][:2] == want[path][:2], path
        assert got[path][2] == want[path][2], path
        assert got[path][3] == want[path][3], path


def test_the_neutral_stage_has_no_runtimes_data_and_still_simulates(pair):
    """Opened as is (every runtime Disabled) the stage carries no PhysX, Newton or MuJoCo schema but all its
    UsdPhysics: bodies, colliders, joints with limits and drives."""
    _, isaac = pair
    stage = Usd.Stage.Open(str(isaac / f"{isaac.name}.usda"))
    schemas = {s for p in stage.Traverse() for s in p.GetAppliedSchemas()}
    assert not [s for s in schemas if s.startswith(("Physx", "Newton", "Mjc"))]
    assert {"PhysicsRigidBodyAPI", "PhysicsCollisionAPI", "PhysicsDriveAPI:angular"} <= schemas
    joints = [p for p in stage.Traverse() if p.GetTypeName() == "PhysicsRevoluteJoint"]
    assert joints and all(p.GetAttribute("physics:upperLimit").HasAuthoredValue() or
                          not p.GetAttribute("physics:lowerLimit").HasAuthoredValue() for p in joints)


def test_the_isaac_layout_is_byte_identical_per_seed(pair, tmp_path):
    _, isaac = pair
    again = infmob_usd.save(infmob_usd.generate("microwave", 0, texture_size=16), tmp_path / "microwave",
                            formats="isaac,urdf")
    files = sorted(p.relative_to(isaac) for p in isaac.rglob("*") if p.is_file())
    assert files == sorted(p.relative_to(again) for p in again.rglob("*") if p.is_file())
    for f in files:
        assert (isaac / f).read_bytes() == (again / f).read_bytes(), f


def test_usd_and_isaac_together_are_refused_in_one_line():
    with pytest.raises(OutputError, match="two layouts of the same USD file"):
        parse_formats("usd,isaac")


def test_the_cli_writes_the_isaac_layout(tmp_path):
    out = subprocess.run([sys.executable, "-m", "infmob_usd", "generate", "vase", "--seed", "1", "--texture-size",
                          "16", "--usd-layout", "isaac", "--formats", "usd,urdf", "--out", str(tmp_path)],
                         capture_output=True, text=True, check=False)
    assert out.returncode == 0, out.stderr
    folder = tmp_path / "vase" / "vase_000001"
    assert (folder / "payloads" / "base.usda").is_file() and (folder / "vase_000001.urdf").is_file()


needs_validators = pytest.mark.skipif(not available(), reason="needs the simready extra (NVIDIA validators)")


@needs_validators
def test_simready_meets_the_runtime_variant_and_isaac_composition_features(pair):
    """`validate --simready` requires FET_000_PHYSX/NEWTON/MUJOCO and FET_100_ISAAC of an Isaac-layout asset
    (each runtime's composition judged by NVIDIA's validator with that variant enabled)."""
    from infmob_usd.validate.simready import check_simready

    _, isaac = pair
    (result,) = check_simready(isaac)
    assert result.ok, result.detail
    broken = isaac.parent.parent / "broken" / "microwave" / isaac.name
    shutil.copytree(isaac, broken)
    physics = broken / "payloads" / "physics.usda"  # a PhysX attribute left in the neutral base: RV.011
    physics.write_text(physics.read_text().replace('float physics:mass', 'float physxRigidBody:sleepThreshold = 0\n'
                                                   '            float physics:mass', 1))
    (result,) = check_simready(broken)
    assert not result.ok and "FET_000_" in result.detail, result.detail


def test_isaaclab_robot_doctor_finds_every_limit_with_physx_enabled(pair, tmp_path):
    """Isaac Lab reads the PhysX variant: composed with it, the doctor finds every velocity limit (the neutral
    stage has none to give, by the runtime-isolation rule)."""
    doctor = shutil.which("isaaclab-robot-doctor", path=str(Path(sys.executable).parent))
    if doctor is None:
        pytest.skip("needs the simready extra (isaaclab-robot-doctor)")
    _, isaac = pair
    stage = Usd.Stage.Open(str(isaac / f"{isaac.name}.usda"))
    stage.GetDefaultPrim().GetVariantSet("PhysX").SetVariantSelection("Enabled")
    flat = tmp_path / f"{isaac.name}.usda"
    stage.Export(str(flat))
    out = subprocess.run([doctor, "check", str(flat)], capture_output=True, text=True, check=False)
    assert out.returncode == 0 and " 0 warnings" in out.stdout, out.stdout[-2000:]
