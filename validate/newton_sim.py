"""Newton (NVIDIA's physics engine) at rest on an object's USD, on the CPU.

:func:`rest_motion` imports ``<name>.usda`` with Newton's own USD importer (``ModelBuilder.add_usd``,
which needs ``newton-usd-schemas``; the base is welded to the world by the USD's fixed ``root_joint``;
the loader recipe is :func:`load`), leaves it under
gravity for :data:`REST_TIME` with the XPBD or the Featherstone solver, and returns how far each joint
moved (m or rad) and whether any coordinate went NaN. No contacts: the rest check is about joints,
limits, armature and drives, as SAPIEN's and MuJoCo's rest checks are.

What Newton 1.8 reads of our joints (``newton/_src/usd``): limits and drives from UsdPhysics (drive
stiffness / damping / target as ``target_ke`` / ``target_kd`` / ``target_q``, a return spring included),
``newton:armature``, ``newton:friction`` and ``newton:velocityLimit`` (its default resolver reads only
the ``newton:`` namespace, not ``physxJointAxis:*``), mimic joints from ``PhysxMimicJointAPI``. It moves a
drive target outside the limits to mid-range, so a preloaded spring's target is put back
(:func:`spring_targets`).
Featherstone uses armature and drives; XPBD uses the drives only (no armature), with hard limits, in
:data:`XPBD_ITERATIONS` parallel sweeps. Neither applies joint friction (their documented limitations),
so a part that only its joint friction holds (a lamp head, a tilted screen) is not held: it sags at the
rate its drive damping allows, less than 1 degree in :data:`REST_TIME`, not forever (docs/physics.md).

Command::

    python -m infmob_usd.validate.newton_sim [--seeds N] [--solvers xpbd,featherstone] [CATEGORY ...]

prints, per category, how many seeds stay within 1 mm / 1 degree with each solver, then per solver the
total, the joint that moved most for its limit, and the seconds spent in Newton. Exit status 1 if any
object moved. The first run compiles Newton's CPU kernels (minutes; cached by warp afterwards).
"""

from __future__ import annotations

import argparse
import math
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

REST_TIME = 0.5  # s
DT = 1e-3  # s
REST_MAX_PRISMATIC = 1e-3  # m
REST_MAX_REVOLUTE = math.radians(1.0)  # rad
SOLVERS = ("xpbd", "featherstone")
XPBD_ITERATIONS = 16
XPBD_RELAXATION = (0.35, 0.2)
"""XPBD's constraint iterations per step and its relaxation of linear and angular joint corrections
(Newton's defaults: 2 iterations, (0.7, 0.4); its own examples of stacks and chains use 10-20
iterations). XPBD solves the joints of a step in parallel and sums their corrections (a Jacobi sweep).
A light body between heavy ones converges slowly: the 10 g dummy link of a compound joint (a lift-off
pot lid, an oven grate's slide-and-lift) under a 1-2 kg part sank 1.3-1.6 mm through its stop at the
defaults, 0.3-0.4 mm with 8 iterations; a lamp's arm turned 1.8 deg, 0.4 with 8. A light body that
many heavier ones hang from overshoots: a dishwasher rack (175 g) carrying four baskets (230 g each)
and four tine rows went NaN within 0.05 s at any iteration count with the default relaxation, and
holds (0.01 mm) at half of it; 16 iterations at half relaxation converge as far as 8 at the default."""


def import_newton():
    try:
        import newton
        import warp as wp
    except ImportError:  # pragma: no cover - depends on the environment
        raise RuntimeError("the Newton rest check needs newton: pip install -e .[newton]") from None
    wp.config.quiet = True
    return newton, wp


def rest_motion(usd: str | Path, solver: str = "xpbd", duration: float = REST_TIME, dt: float = DT
                ) -> tuple[dict[str, float], dict[str, bool]]:
    """``usd`` left at rest under gravity for ``duration`` with Newton's ``solver`` (``xpbd`` or
    ``featherstone``): joint name -> the largest change of its coordinate (m or rad; NaN if it went
    NaN), and joint name -> whether it is prismatic."""
    newton, wp = import_newton()
    model = load(usd)
    s0, s1, control = model.state(), model.state(), model.control()
    newton.eval_fk(model, model.joint_q, model.joint_qd, s0)
    if solver == "xpbd":
        step = newton.solvers.SolverXPBD(model, iterations=XPBD_ITERATIONS, joint_linear_relaxation=XPBD_RELAXATION[0],
                                         joint_angular_relaxation=XPBD_RELAXATION[1])
    else:
        step = newton.solvers.SolverFeatherstone(model)
    q0 = model.joint_q.numpy().copy()
    worst = np.zeros_like(q0)
    q, qd = wp.zeros_like(model.joint_q), wp.zeros_like(model.joint_qd)
    steps = int(round(duration / dt))
    for k in range(steps):
        s0.clear_forces()
        step.step(s0, s1, control, None, dt)
        s0, s1 = s1, s0
        if k % 10 == 9 or k == steps - 1:
            newton.eval_ik(model, s0, q, qd)
            d = np.abs(q.numpy() - q0)
            worst = np.where(np.isnan(d) | np.isnan(worst), np.nan, np.maximum(worst, d))
    types, starts = model.joint_type.numpy(), model.joint_q_start.numpy()
    labels = model.joint_label
    motion, prismatic = {}, {}
    for j in range(model.joint_count):
        end = starts[j + 1] if j + 1 < model.joint_count else len(q0)
        if types[j] in (int(newton.JointType.PRISMATIC), int(newton.JointType.REVOLUTE)):
            name = str(labels[j]).rsplit("/", 1)[-1]
            motion[name] = float(np.max(worst[starts[j]:end]))
            prismatic[name] = types[j] == int(newton.JointType.PRISMATIC)
    return motion, prismatic


def load(usd: str | Path):
    """``usd`` as a Newton model on the CPU, by the loader recipe for our objects: Newton's USD importer
    with ``collapse_fixed_joints`` (Newton's own option: bodies welded by fixed joints become one body, and
    the base, welded to the world by ``root_joint``, becomes part of the world), then
    :func:`spring_targets`. A weld is exact in Featherstone's joint coordinates but a constraint among
    others in XPBD's parallel sweep: a dining table's base (10 kg) welded to the world under its two
    sliding top halves (38 kg each) and four telescoping legs diverged to NaN within 0.05 s, whatever
    the iterations; collapsed, it moves 0.15 mm."""
    newton, _ = import_newton()
    builder = newton.ModelBuilder()
    builder.add_usd(str(usd), collapse_fixed_joints=True)
    model = builder.finalize(device="cpu")
    spring_targets(model, usd)
    return model


def spring_targets(model, usd: str | Path) -> int:
    """Put back the drive targets of the USD's return springs, which Newton 1.8's builder moves to the
    middle of the range when they lie outside the limits (``ModelBuilder.JointDofConfig``, ``target_q``
    outside ``[limit_lower, limit_upper]``): a spring's zero lies beyond the rest stop (a preload, see
    :mod:`infmob_usd.springs`), and at mid-range it would hold a button half pressed. The loader recipe
    for Newton, as :func:`infmob_usd.validate.sim.apply_springs` is SAPIEN's. Returns how many were set."""
    from pxr import Usd

    stage = Usd.Stage.Open(str(usd))
    targets = model.joint_target_q.numpy()
    starts = model.joint_qd_start.numpy()
    n = 0
    for j, label in enumerate(model.joint_label):
        prim = stage.GetPrimAtPath(str(label))
        for drive, per in (("linear", 1.0), ("angular", math.pi / 180)):
            stiff = prim.GetAttribute(f"drive:{drive}:physics:stiffness") if prim else None
            target = prim.GetAttribute(f"drive:{drive}:physics:targetPosition") if prim else None
            if stiff and target and target.HasAuthoredValue() and (stiff.Get() or 0) > 0:
                targets[starts[j]] = target.Get() * per
                n += 1
    model.joint_target_q.assign(targets)
    return n


def _words(name: str, m: float, prismatic: bool) -> str:
    return f"{name} {m * 1000:.3g} mm" if prismatic else f"{name} {math.degrees(m):.3g} deg"


def moved(motion: dict[str, float], prismatic: dict[str, bool]) -> list[str]:
    """Joints that moved more than 1 mm / 1 degree, or went NaN, in words."""
    out = []
    for name, m in motion.items():
        lim = REST_MAX_PRISMATIC if prismatic[name] else REST_MAX_REVOLUTE
        if not m <= lim:
            out.append(_words(name, m, prismatic[name]))
    return out


def worst(motion: dict[str, float], prismatic: dict[str, bool]) -> tuple[float, str]:
    """The joint that moved most for its limit: (motion / limit, infinite if NaN; the joint in words)."""
    best = (0.0, "nothing moved")
    for name, m in motion.items():
        share = m / (REST_MAX_PRISMATIC if prismatic[name] else REST_MAX_REVOLUTE)
        share = math.inf if math.isnan(share) else share
        if share > best[0]:
            best = (share, _words(name, m, prismatic[name]))
    return best


def main(argv: list[str] | None = None) -> int:
    import infmob_usd

    ap = argparse.ArgumentParser(prog="python -m infmob_usd.validate.newton_sim", description=__doc__.split("\n")[0])
    ap.add_argument("categories", nargs="*", default=["all"])
    ap.add_argument("--seeds", type=int, default=5, help="seeds 0..N-1 per category (default 5)")
    ap.add_argument("--solvers", default=",".join(SOLVERS))
    a = ap.parse_args(argv)
    cats = infmob_usd.list_categories() if a.categories in (["all"], []) else a.categories
    solvers = a.solvers.split(",")
    total = dict.fromkeys(solvers, 0)
    seconds = dict.fromkeys(solvers, 0.0)
    most = {s: (0.0, "nothing moved") for s in solvers}
    with tempfile.TemporaryDirectory() as tmp:
        for cat in cats:
            passed = dict.fromkeys(solvers, 0)
            for seed in range(a.seeds):
                obj = infmob_usd.generate(cat, seed=seed, texture_size=16)
                folder = infmob_usd.save(obj, Path(tmp) / cat, formats="usd")
                for s in solvers:
                    t0 = time.perf_counter()
                    result = rest_motion(folder / f"{folder.name}.usda", s)
                    seconds[s] += time.perf_counter() - t0
                    fails = moved(*result)
                    passed[s] += not fails
                    share, words = worst(*result)
                    if share >= most[s][0]:
                        most[s] = (share, f"{folder.name} {words}")
                    for f in fails:
                        print(f"  FAIL {s} {folder.name} {f}", flush=True)
            for s in solvers:
                total[s] += passed[s]
            print(f"{cat:18s}" + "".join(f"{s} {passed[s]}/{a.seeds}  " for s in solvers), flush=True)
    n = len(cats) * a.seeds
    for s in solvers:
        print(f"{s}: {total[s]}/{n} at rest; worst {most[s][1]} ({most[s][0]:.2f} of the limit); "
              f"{seconds[s]:.0f} s in Newton", flush=True)
    return 0 if all(total[s] == n for s in solvers) else 1


if __name__ == "__main__":
    sys.exit(main())
