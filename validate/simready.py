"""NVIDIA's published USD validators, run on a written object (``infmob validate --simready``).

One check, ``simready``, passes when all of these hold for the object's root layer:

* SimReady Foundation profile **Robotics-Prop 4.0.0** (``simready-validate`` with the installed
  ``simready-foundation-tier-core``): no failure of a requirement the profile makes mandatory, and these
  optional features pass too: multi-body physics ``FET_004_STANDARD``, SR.001 metadata ``FET_000_STANDARD``,
  display colour ``FET_010_STANDARD``, non-visual materials ``FET_007_STANDARD``, MuJoCo and Newton colliders
  ``FET_003/004_MUJOCO``, ``FET_003/004_NEWTON``, OpenPBR surfaces ``FET_006_OPENPBR``, and grasp vectors
  ``FET_005_STANDARD`` where the object has a part to operate (a vase without a lid has none);
* the features ``FET_024_STANDARD`` (articulation), ``FET_022_STANDARD`` (driven joints) and
  ``FET_024_NEWTON`` (Newton's articulation root) of profile **Robot-Body 3.0.0** pass; its other optional
  features are a robot's (a robot type, ROS bridge graphs, MuJoCo actuators, Isaac's robot folder) or have no
  validator (RM.002);
* ``omniverse-asset-validator``'s default rules report no failure or error (its warnings are reported by
  ``omni_asset_validate``, not judged here: a new category's mesh may still carry one);
* of an object in the Isaac layout (``--usd-layout isaac``), also the runtime variant features
  ``FET_000_PHYSX/NEWTON/MUJOCO`` and Isaac's composition ``FET_100_ISAAC``.

The driven-joint rules (DJ.*) import ``pxr.PhysxSchema``, which only Kit / Isaac Sim's own USD build has;
with ``usd-core`` the import fails and those rules quietly find nothing. :func:`install_physx_shim` maps
the codeless ``PhysxSchema`` of ``physx-usd-schemas`` to ``pxr.PhysxSchema`` before the rules load, so
they really run (``tests/test_simready.py`` proves it with a deliberately broken file).
Install with ``pip install -e '.[simready]'``.
"""

from __future__ import annotations

import contextlib
import io
import logging
import sys
import time
from pathlib import Path

from .result import CheckResult

PROP = ("Robotics-Prop", "4.0.0")
# optional in the profile, required by us: multi-body physics; SR.001 metadata; display colour; non-visual
# (lidar/radar) materials; MuJoCo's and Newton's collider schemas; OpenPBR surfaces
PROP_OPTIONAL = ("FET_004_STANDARD", "FET_000_STANDARD", "FET_010_STANDARD", "FET_007_STANDARD",
                 "FET_003_MUJOCO", "FET_004_MUJOCO", "FET_003_NEWTON", "FET_004_NEWTON", "FET_006_OPENPBR")
GRASP_FEATURE = "FET_005_STANDARD"  # grasp vectors: required of an object with a part to operate
# required of the Isaac layout (--usd-layout isaac): a variant set per physics runtime, Isaac Sim's layers
ISAAC_FEATURES = ("FET_000_PHYSX", "FET_000_NEWTON", "FET_000_MUJOCO", "FET_100_ISAAC")
BODY = ("Robot-Body", "3.0.0")
BODY_FEATURES = ("FET_024_STANDARD", "FET_022_STANDARD", "FET_024_NEWTON")  # articulation, driven joints, Newton's
PACKAGES = ("simready-validate", "simready-foundation-tier-core", "omniverse-asset-validator",
            "usd-validation-nvidia", "physx-usd-schemas")
INSTALL_HINT = "the simready check needs NVIDIA's validators: pip install -e '.[simready]'"

_STATE: dict = {}


def install_physx_shim() -> str:
    """Make ``from pxr import PhysxSchema`` work; return where it comes from.

    Kit / Isaac Sim ship a compiled ``pxr.PhysxSchema``: kept when present. Otherwise the codeless
    ``physx_usd_schemas.PhysxSchema`` (importing the package registers the PhysX schemas with USD's
    plugin registry) is installed as ``pxr.PhysxSchema``. Call before the validators' rules are imported.
    """
    import pxr

    if "pxr.PhysxSchema" in sys.modules and not getattr(sys.modules["pxr.PhysxSchema"], "_infmob_shim", False):
        return "pxr.PhysxSchema"
    try:
        from pxr import PhysxSchema  # noqa: F401
        if not getattr(PhysxSchema, "_infmob_shim", False):
            return "pxr.PhysxSchema"
    except ImportError:
        pass
    import physx_usd_schemas
    from physx_usd_schemas import PhysxSchema

    PhysxSchema._infmob_shim = True
    sys.modules["pxr.PhysxSchema"] = PhysxSchema
    pxr.PhysxSchema = PhysxSchema
    _accept_codeless_classes()
    return f"physx-usd-schemas {physx_usd_schemas.__version__}"


def _accept_codeless_classes() -> None:
    """Let ``Usd.Prim.HasAPI`` take a codeless schema class, as it takes a compiled one.

    The rules call ``prim.HasAPI(PhysxSchema.PhysxMimicJointAPI)``; a codeless class is no ``TfType``, so
    USD raises. A class with ``_schemaName`` is looked up by that registered name instead; every other
    argument goes to USD's own ``HasAPI`` unchanged."""
    from pxr import Usd

    native = Usd.Prim.HasAPI
    if getattr(native, "_infmob_shim", False):
        return

    def has_api(prim, schema, *args, **kwargs):
        name = getattr(schema, "_schemaName", None)
        if isinstance(schema, type) and isinstance(name, str):
            schema = name
        return native(prim, schema, *args, **kwargs)

    has_api._infmob_shim = True
    Usd.Prim.HasAPI = has_api


def versions() -> dict[str, str]:
    """Installed versions of the validator packages (``"missing"`` when absent)."""
    from importlib.metadata import PackageNotFoundError, version

    out = {}
    for p in PACKAGES:
        try:
            out[p] = version(p)
        except PackageNotFoundError:
            out[p] = "missing"
    return out


def available() -> bool:
    """Whether every validator package is installed."""
    return "missing" not in versions().values()


def _quiet():
    """Silence the validators' chatter (INFO logs, deprecation warnings, prints) while they run."""
    stack = contextlib.ExitStack()
    stack.enter_context(contextlib.redirect_stdout(io.StringIO()))
    for name in ("", "simready", "simready.validate", "omni.asset_validator", "usd_validation_nvidia"):
        lg = logging.getLogger(name)
        old = lg.level
        lg.setLevel(logging.ERROR)
        stack.callback(lg.setLevel, old)
    return stack


def physx_schemas_known() -> bool:
    """Whether USD's schema registry knows the PhysX API schemas (``PhysicsJointStateAPI``). It does only
    when ``physx_usd_schemas`` was imported before the registry was first used in this process."""
    from pxr import Usd

    return Usd.SchemaRegistry().FindAppliedAPIPrimDefinition("PhysicsJointStateAPI") is not None


def _setup() -> dict:
    """Load the validators once per process (the shim first, so the PhysX-dependent rules see it)."""
    if _STATE:
        return _STATE
    shim = install_physx_shim()
    if not physx_schemas_known():
        raise RuntimeError("USD's schema registry was built before physx-usd-schemas registered the PhysX"
                           " schemas; run the validators in a fresh process")
    with _quiet():
        import simready.validate as sv
        from omni.asset_validator import ValidationEngine

        sv.initialize([], [], [])
    _STATE.update(sv=sv, engine=ValidationEngine, shim=shim)
    return _STATE


def _failing(summary: dict, feature: str) -> str | None:
    entry = summary.get(feature)
    if entry is None:
        return f"{feature} not evaluated"
    if entry.get("passed"):
        return None
    reqs = entry.get("failing requirements") or entry.get("optional requirements") or "?"
    return f"{feature}: {reqs}"


def _codes(issues) -> str:
    codes = sorted({i.requirement.code.split("simready.")[-1].split("usd.")[-1] for i in issues
                    if getattr(i, "requirement", None) is not None})
    return ", ".join(codes)


def _feature_requirements(profile: tuple[str, str], features: tuple[str, ...]) -> list:
    """The requirements of ``features`` (their own, not their dependencies') in ``profile``."""
    from usd_validation_nvidia import ProfileRegistry

    found = ProfileRegistry().find_profile(*profile)
    if found is None:
        raise LookupError(f"profile {profile[0]} {profile[1]} is not registered")
    caps = {c.id: c for c in found.capabilities if c.id in features}
    if set(caps) != set(features):
        raise LookupError(f"profile {profile[0]} {profile[1]} lacks {sorted(set(features) - set(caps))}")
    return [r for f in features for r in caps[f].requirements]


def _run_requirements(stage, requirements: list, label: str):
    """Run exactly ``requirements`` on ``stage`` (as simready-validate runs one bucket of a profile)."""
    from usd_validation_nvidia import Capability, ValidationEngine  # simready-validate's engine

    cls = type(f"infmob_{label}", (Capability,), {"id": f"infmob_{label}", "version": "", "path": "",
                                                  "requirements": list(requirements)})
    cls.custom_data = {}
    engine = ValidationEngine(init_rules=False, variants=False)
    engine.enable_capability(cls())
    return engine.validate(stage)


def _rule_name(issue) -> str:
    rule = issue.rule
    return getattr(rule, "__name__", type(rule).__name__) if rule is not None else "?"


def run_simready(usd_path: str | Path) -> dict:
    """Every validator on one root layer: a dict of what failed (empty lists when nothing did).

    Returns
    -------
    dict
        ``prop``: failing Robotics-Prop 4.0.0 features (mandatory requirements, and FET_004_STANDARD);
        ``body``: failures of the requirements of FET_024/FET_022/FET_024_NEWTON of Robot-Body 3.0.0 (their
        dependency FET_004_STANDARD is judged in ``prop``); ``omni``: the default rules' failures and errors as
        ``"Rule: message"``; ``seconds``; ``shim``: where ``pxr.PhysxSchema`` came from.
    """
    from pxr import Usd

    st = _setup()
    sv, engine_cls = st["sv"], st["engine"]
    bad = ("FAILURE", "ERROR")  # by name: the two engines have their own IssueSeverity enums
    t0 = time.perf_counter()
    with _quiet():
        stage = Usd.Stage.Open(str(usd_path))
        prop = sv.validate_stage(stage, *PROP)
        body = _body_isaac(stage) if _isaac_layout(stage) else list(
            _run_requirements(stage, _feature_requirements(BODY, BODY_FEATURES), "robot_body").issues())
        omni = engine_cls(init_rules=True, variants=False).validate(stage)
    bad_prop = []
    if prop is None:
        bad_prop.append(f"profile {PROP[0]} {PROP[1]} not registered")
    else:
        bad_prop += [f"{f}: {e.get('failing requirements')}" for f, e in sorted(prop.features_summary.items())
                     if sv.is_blocking_failure(e)]
        wanted = PROP_OPTIONAL + ((GRASP_FEATURE,) if _has_grasps(stage) else ()) + (
            ISAAC_FEATURES if _isaac_layout(stage) else ())
        bad_prop += [m for f in wanted if (m := _failing(prop.features_summary, f))]
    bad_body = [f"{i.requirement.code.split('.', 3)[-1] if i.requirement else _rule_name(i)}: {i.message}"
                for i in body if i.severity.name in bad]
    bad_omni = [f"{_rule_name(i)}: {i.message}" for i in omni.issues() if i.severity.name in bad]
    return {"prop": bad_prop, "body": bad_body, "omni": bad_omni, "seconds": time.perf_counter() - t0,
            "shim": st["shim"]}


def _body_isaac(stage):
    """The Robot-Body features of an Isaac-layout asset: the runtime-neutral ones on the stage as opened, Newton's
    with its variant selected (the layout keeps each runtime's schemas in its own variant)."""
    neutral = [f for f in BODY_FEATURES if not f.endswith("_NEWTON")]
    issues = list(_run_requirements(stage, _feature_requirements(BODY, neutral), "robot_body").issues())
    prim = stage.GetDefaultPrim()
    vset = prim.GetVariantSets().GetVariantSet("Newton")
    before = vset.GetVariantSelection()
    vset.SetVariantSelection("Enabled")
    try:
        newton = [f for f in BODY_FEATURES if f.endswith("_NEWTON")]
        issues += list(_run_requirements(stage, _feature_requirements(BODY, newton), "robot_body").issues())
    finally:
        vset.SetVariantSelection(before)
    return issues


def _isaac_layout(stage) -> bool:
    """Whether the asset is in the Isaac layout (its root prim has the physics runtime variant sets)."""
    prim = stage.GetDefaultPrim()
    return bool(prim) and {"PhysX", "Newton", "MuJoCo"} <= set(prim.GetVariantSets().GetNames())  # RV.001/004/007


def _has_grasps(stage) -> bool:
    """Whether the object has a grasp frame (an operable part): GSP.001 asks for one grasp line at least."""
    from pxr import Usd

    return any(prim.GetTypeName() == "BasisCurves" and prim.GetName().startswith("grasp_identifier")
               for prim in Usd.PrimRange(stage.GetPseudoRoot()))


def _in_subprocess(usd_paths: list[str]) -> list[dict]:
    """:func:`run_simready` on each path in a fresh Python process (where the PhysX schemas can still be
    registered before USD's schema registry is built)."""
    import json
    import subprocess

    proc = subprocess.run([sys.executable, "-m", "infmob_usd.validate.simready", *usd_paths],
                          capture_output=True, text=True, check=False)
    lines = [ln for ln in proc.stdout.splitlines() if ln.startswith("{")]
    if proc.returncode != 0 or len(lines) != len(usd_paths):
        raise RuntimeError(f"validator process failed (status {proc.returncode}): {proc.stderr.strip()[-300:]}")
    return [json.loads(ln) for ln in lines]


def run_simready_anywhere(usd_paths: list[str]) -> list[dict]:
    """:func:`run_simready` on each path: in this process when it can, else in one fresh process."""
    if not _STATE:
        install_physx_shim()
    if physx_schemas_known():
        return [run_simready(p) for p in usd_paths]
    return _in_subprocess([str(p) for p in usd_paths])


def _result(r: dict) -> CheckResult:
    problems = [f"{PROP[0]} {PROP[1]}: {m}" for m in r["prop"]] + \
        [f"{BODY[0]} {BODY[1]} {'/'.join(BODY_FEATURES)}: {m[:200]}" for m in r["body"][:3]] + \
        [f"asset-validator: {m[:200]}" for m in r["omni"][:3]]
    detail = "; ".join(problems[:4]) if problems else \
        f"{PROP[0]} {PROP[1]} (+{len(PROP_OPTIONAL)} optional features), {BODY[0]} {BODY[1]} " \
        "FET_024/FET_022/FET_024_NEWTON, asset-validator defaults pass"
    return CheckResult("simready", not problems, f"{detail} [{r['seconds']:.2f} s]")


def check_simready(folder: str | Path) -> list[CheckResult]:
    """The ``simready`` check of one object folder (see the module docstring)."""
    folder = Path(folder)
    if not available():
        missing = [p for p, v in versions().items() if v == "missing"]
        return [CheckResult("simready", False, f"{', '.join(missing)} not installed; {INSTALL_HINT}")]
    try:
        r = run_simready_anywhere([str(folder / f"{folder.name}.usda")])[0]
    except Exception as e:  # a validator crash is a failed check, not a crashed run
        return [CheckResult("simready", False, f"validators raised {type(e).__name__}: {e}")]
    result = _result(r)
    if any("NP.005" in m for m in r["prop"]):
        root = folder.resolve().parent.name
        result = CheckResult("simready", False, (
            f"NP.005: SimReady takes the folder above {folder.name}/ as the asset's root and wants its name "
            f"('{root}') inside the file name {folder.name}.usda: keep the object in a folder named after its "
            f"category, as `infmob generate` writes it ({folder.name.rsplit('_', 1)[0]}/{folder.name}/); "
            + result.detail))
    return [result]


def main(argv: list[str] | None = None) -> int:
    """``python -m infmob_usd.validate.simready ROOT.usda...``: one JSON line per layer (what failed)."""
    import json

    paths = sys.argv[1:] if argv is None else argv
    install_physx_shim()
    for p in paths:
        print(json.dumps(run_simready(p)), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
