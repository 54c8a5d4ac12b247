"""The push test: every movable joint pushed with its own URDF effort goes at most 5 % of its range past where it rests.

Each movable joint of an object, alone, is pushed with its effort (URDF ``<limit effort>``, MJCF
``actuatorfrcrange``) for one second each way (gravity on, fixed base, the file's damping, friction and
springs): in MuJoCo on the MJCF (:func:`~infmob_usd.validate.mujoco_sim.push_joints`) from rest
towards its upper limit and from its upper limit back into its rest stop, in PyBullet on the URDF
(:func:`push_bullet`) towards each limit from rest; at every step of every push each limited joint
must stay within 5 % of its range past where it rests, left alone for as long (the peak:
:attr:`~infmob_usd.validate.mujoco_sim.Push.pushed`), and rest within its limits + 5 % of its range
or 1 mm / 1 degree (:attr:`~.mujoco_sim.Push.rest_ok`). Where a stop carries weight, MuJoCo's soft
limit lets the part sit past it whatever pushes it (0.37-0.6 mm on a vertical slide with MuJoCo's
default limits; a URDF cannot stiffen them, the MJCF does:
:func:`~infmob_usd.validate.mujoco_sim.rest_excess`): that sag is MuJoCo's, what the push adds is
the effort's. Efforts come from :mod:`infmob_usd.effort`.

Command (the sweep behind the figures in docs/benchmarks.md)::

    python -m infmob_usd.validate.push [--seeds N] [--engines mujoco,pybullet|none] [--mujoco-check]
                                       [--bullet-from-upper] [--workers N] [CATEGORY ...]

prints per category how many objects passed in each engine (and the ``mujoco`` check of
``validate --sim`` on the MJCF with ``--mujoco-check``), the furthest a push took a joint past a
limit beyond its rest and the furthest a joint rested past one, each failing push, and the median
seconds the MJCF writer adds per object.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

from .mujoco_sim import PUSH_TIME, PUSH_TOL, Push, _past, _push, load_model, opened_by, push_joints


def _urdf_efforts(urdf: Path) -> dict[str, float]:
    out = {}
    for j in ET.parse(urdf).getroot().iter("joint"):
        lim = j.find("limit")
        if lim is not None and j.get("type") != "fixed":
            out[j.get("name")] = float(lim.get("effort"))
    return out


def _gears(pb, cid: int, body: int, info: list, urdf: Path) -> None:
    """PyBullet's URDF loader ignores ``<mimic>``: couple each hinge that follows a hinge with a gear constraint
    (``JOINT_GEAR``; the links are world-aligned at rest, so the axes compare in world terms), as a user must, so that
    a leader pushed with its effort drives its follower. A follower slide stays free (no gear for slides)."""
    index = {f[1].decode(): i for i, f in enumerate(info)}
    for j in ET.parse(urdf).getroot().iter("joint"):
        m = j.find("mimic")
        if m is None or j.get("type") != "revolute" or m.get("joint") not in index:
            continue
        lead, follow = index[m.get("joint")], index[j.get("name")]
        if info[lead][2] != pb.JOINT_REVOLUTE:
            continue
        ratio = float(m.get("multiplier", "1"))
        axis = np.asarray(info[lead][13], float)
        c = pb.createConstraint(body, lead, body, follow, pb.JOINT_GEAR, axis.tolist(), [0, 0, 0], [0, 0, 0],
                                physicsClientId=cid)
        pb.changeConstraint(c, gearRatio=float(axis @ np.asarray(info[follow][13], float)) / ratio, maxForce=1e4,
                            physicsClientId=cid)


def _pybullet():
    try:
        import pybullet as pb
    except ImportError:  # pragma: no cover - depends on the environment
        raise RuntimeError("the PyBullet push needs pybullet: pip install -e .[sim]") from None
    return pb


def _springs(urdf: Path) -> dict[str, tuple[float, float]]:
    """Joint name -> ``(stiffness, reference)`` of every return spring in the ``metadata.json`` beside ``urdf``
    (a URDF has no element for one; none where there is no metadata)."""
    meta = urdf.parent / "metadata.json"
    if not meta.is_file():
        return {}
    joints = json.loads(meta.read_text()).get("joints", [])
    return {j["name"]: (float(j["spring"]["stiffness"]), float(j["spring"]["reference"])) for j in joints
            if "spring" in j}


def _spring_torques(urdf: Path, limited: list[int], name: dict[int, str]):
    """``torques(q) -> {joint index: spring torque}`` of the return springs of ``metadata.json`` (:func:`_springs`)
    among the ``limited`` joints (``q``: their positions, in that order)."""
    springs = _springs(urdf)
    sprung = [k for k in limited if name[k] in springs]
    stiff = np.array([springs[name[k]][0] for k in sprung])
    zero = np.array([springs[name[k]][1] for k in sprung])
    at = [limited.index(k) for k in sprung]
    return lambda q: dict(zip(sprung, stiff * (zero - q[at]))) if sprung else {}


def _travel(info: tuple, q_end: float, side: str, limited: bool) -> float:
    """Fraction of its range joint ``info`` (PyBullet's joint info) covered towards ``side`` (half-turns where it
    has no limits)."""
    if not limited:
        return q_end / math.pi
    a, b = info[8], info[9]
    return (q_end - a) / (b - a) if side == "upper" else (b - q_end) / (b - a)


def push_bullet(urdf: str | Path, duration: float = PUSH_TIME, timestep: float = 1 / 240,
                opened: dict[str, list[str]] | None = None, from_upper: bool = False) -> list[Push]:
    """Push every movable joint of ``urdf`` alone with its URDF effort in PyBullet (DIRECT mode) towards
    each limit from rest, judged on the peak over each push; ``from_upper``: the push towards the
    lower limit starts from the upper one (``opened``: as :func:`~infmob_usd.validate.mujoco_sim.push_joints`).
    Return springs (``metadata.json``; PyBullet has none) act as joint torques ``stiffness * (reference - q)``
    every step, as a user sets them (SAPIEN's: :func:`~infmob_usd.validate.sim.apply_springs`).

    Not by default: Bullet holds a limit from the step after it is crossed, so a part falling onto its
    rest stop goes ``v dt`` past it (1/240 s: a 3 g bottle cap falling 16 mm, 9 % of its travel), and a
    URDF has no armature to slow it (the MJCF has, :mod:`infmob_usd.effort`).

    The base is fixed; PyBullet's default velocity motors are switched off so a joint is free
    but for its URDF damping; the effort is applied as a joint torque / force every step.
    """
    pb = _pybullet()
    urdf = Path(urdf)
    efforts = _urdf_efforts(urdf)
    cid = pb.connect(pb.DIRECT)
    try:
        pb.setGravity(0, 0, -9.81, physicsClientId=cid)
        pb.setTimeStep(timestep, physicsClientId=cid)
        body = pb.loadURDF(str(urdf), useFixedBase=True, flags=pb.URDF_USE_INERTIA_FROM_FILE,
                           physicsClientId=cid)
        count = pb.getNumJoints(body, physicsClientId=cid)
        info = [pb.getJointInfo(body, i, physicsClientId=cid) for i in range(count)]
        moving = [i for i, f in enumerate(info) if f[2] in (pb.JOINT_REVOLUTE, pb.JOINT_PRISMATIC)]
        name = {i: info[i][1].decode() for i in moving}
        _gears(pb, cid, body, info, urdf)
        limited = [i for i in moving if info[i][8] < info[i][9]]
        lo = np.array([info[i][8] for i in limited])
        hi = np.array([info[i][9] for i in limited])
        span = np.maximum(hi - lo, 1e-12)
        state = pb.saveState(physicsClientId=cid)
        steps = int(round(duration / timestep))

        index = {name[k]: k for k in moving}
        springs = _spring_torques(urdf, limited, name)

        def run(i: int | None, force: float) -> np.ndarray:
            """From rest (pushed down: from its upper limit), joint ``i`` (None: none) pushed with ``force``
            for ``duration``: the furthest each limited joint went past its lower and upper limit
            (``(2, n)``, fractions of its range)."""
            pb.restoreState(stateId=state, physicsClientId=cid)
            start = {}
            if from_upper and i is not None and force < 0 and i in limited:
                start = {k: info[k][9] for k in [i, *(index[n] for n in (opened or {}).get(name[i], [])
                                                     if n in index)] if k in limited}
            for k in moving:
                pb.resetJointState(body, k, start.get(k, 0.0), 0.0, physicsClientId=cid)
            pb.setJointMotorControlArray(body, moving, pb.VELOCITY_CONTROL, forces=[0.0] * len(moving),
                                         physicsClientId=cid)
            worst = np.full((2, len(limited)), -np.inf)  # (PyBullet answers None, not [], for no joints)
            q = np.array([s[0] for s in pb.getJointStates(body, limited, physicsClientId=cid) or ()])
            for _ in range(steps):
                torque = springs(q)
                if i is not None:
                    torque[i] = torque.get(i, 0.0) + force
                if torque:
                    pb.setJointMotorControlArray(body, list(torque), pb.TORQUE_CONTROL,
                                                 forces=[float(t) for t in torque.values()], physicsClientId=cid)
                pb.stepSimulation(physicsClientId=cid)
                q = np.array([s[0] for s in pb.getJointStates(body, limited, physicsClientId=cid) or ()])
                worst = np.maximum(worst, _past(q, lo, hi, span))
            return worst

        still = run(None, 0.0)
        rest = {name[k]: (float(still[0, n]), float(still[1, n])) for n, k in enumerate(limited)}
        out = []
        for i in moving:
            effort = efforts[name[i]]
            sides = ("upper", "lower") if i in limited else ("upper",)
            for side in sides:
                worst = run(i, (1.0 if side == "upper" else -1.0) * effort)
                travel = _travel(info[i], pb.getJointState(body, i, physicsClientId=cid)[0], side, i in limited)
                out.append(_push(name[i], side, effort, travel, [name[k] for k in limited], worst, rest,
                                 info[i][9] - info[i][8] if i in limited else 0.0, info[i][2] == pb.JOINT_PRISMATIC))
        return out
    finally:
        pb.disconnect(physicsClientId=cid)


def push_mujoco(path: str | Path, duration: float = PUSH_TIME, opened: dict[str, list[str]] | None = None
                ) -> list[Push]:
    """:func:`~infmob_usd.validate.mujoco_sim.push_joints` on an MJCF (or a URDF as MuJoCo reads it)."""
    return push_joints(load_model(path), duration, opened=opened)


ENGINES = {"mujoco": push_mujoco, "pybullet": push_bullet}


def failures(pushes: list[Push]) -> list[Push]:
    """Pushes that took their joint more than :data:`PUSH_TOL` of its range past a limit beyond where
    it rests (:attr:`Push.pushed`), or whose joint rests too far past one (:attr:`Push.rest_ok`)."""
    return [p for p in pushes if not p.pushed <= PUSH_TOL or not p.rest_ok]


def describe(p: Push) -> str:
    """One failing push, in words."""
    rest = f", resting {p.rest * 100:.1f} % past" if p.rest > 0 else ""
    return f"{p.joint} -> {p.side} ({p.effort:.3g}): {p.excess * 100:.1f} % past{rest}"


def _one(category: str, seed: int, engines: tuple[str, ...], mujoco_check: bool, out: str,
         bullet_from_upper: bool = False) -> dict:
    """Generate one object (URDF + MJCF, 16 px textures), push it in ``engines``, optionally run
    the ``mujoco`` check on its MJCF; a row of results."""
    import infmob_usd

    from .mujoco_sim import check_mujoco

    obj = infmob_usd.generate(category, seed=seed, texture_size=16)
    folder = infmob_usd.save(obj, Path(out) / category, formats="urdf,mjcf")
    files = {"mujoco": folder / f"{folder.name}.xml", "pybullet": folder / f"{folder.name}.urdf"}
    opened = opened_by(json.loads((folder / "metadata.json").read_text()))
    row = {"category": category, "seed": seed, "name": folder.name, "mjcf_s": obj.timings["mjcf"], "fails": {}}
    for e in engines:
        extra = {"from_upper": True} if e == "pybullet" and bullet_from_upper else {}
        pushes = ENGINES[e](files[e], opened=opened, **extra)
        row["fails"][e] = [describe(p) for p in failures(pushes)]
        row[e] = max([p.pushed for p in pushes] + [0.0])
        row[f"{e}_rest"] = max([p.rest for p in pushes] + [0.0])
    if mujoco_check:
        (r,) = check_mujoco(folder)
        row["check"] = (r.ok, r.detail)
    return row


def main(argv: list[str] | None = None) -> int:
    from concurrent.futures import ProcessPoolExecutor

    import infmob_usd

    ap = argparse.ArgumentParser(prog="python -m infmob_usd.validate.push", description=__doc__.split("\n")[0])
    ap.add_argument("categories", nargs="*", default=["all"])
    ap.add_argument("--seeds", type=int, default=5, help="seeds 0..N-1 per category (default 5)")
    ap.add_argument("--engines", default="mujoco,pybullet", help="push in these (comma list; `none`: no push)")
    ap.add_argument("--mujoco-check", action="store_true",
                    help="also run the mujoco check of validate --sim on the MJCF")
    ap.add_argument("--bullet-from-upper", action="store_true",
                    help="in PyBullet too, push towards the lower limit from the upper one (as in MuJoCo)")
    ap.add_argument("--workers", type=int, default=1)
    a = ap.parse_args(argv)
    cats = infmob_usd.list_categories() if a.categories in (["all"], []) else a.categories
    engines = tuple(e for e in a.engines.split(",") if e and e != "none")
    columns = [*engines] + (["mujoco_check"] if a.mujoco_check else [])
    print(f"{'category':18s}" + "".join(f"{c:>14s}" for c in columns)
          + "   worst past a limit: push (beyond rest) / rest")
    bad = 0
    mjcf_s = []
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp, ProcessPoolExecutor(max_workers=a.workers) as pool:
        for cat in cats:
            futs = [pool.submit(_one, cat, seed, engines, a.mujoco_check, tmp, a.bullet_from_upper)
                    for seed in range(a.seeds)]
            rows = [f.result() for f in futs]
            passed = {e: sum(not r["fails"][e] for r in rows) for e in engines}
            if a.mujoco_check:
                passed["mujoco_check"] = sum(r["check"][0] for r in rows)
            for r in rows:
                mjcf_s.append(r["mjcf_s"])
                for e in engines:
                    for f in r["fails"][e]:
                        print(f"  FAIL {e} push {r['name']} {f}")
                if a.mujoco_check and not r["check"][0]:
                    print(f"  FAIL mujoco check {r['name']}: {r['check'][1]}")
            bad += sum(a.seeds - v for v in passed.values())
            print(f"{cat:18s}" + "".join(f"{f'{passed[c]}/{a.seeds}':>14s}" for c in columns) + "   "
                  + " ".join(f"{e} {max(r[e] for r in rows) * 100:.2f} / "
                             f"{max(r[f'{e}_rest'] for r in rows) * 100:.2f} %" for e in engines), flush=True)
    print(f"\nMJCF writing (after the URDF wrote the meshes): median {np.median(mjcf_s) * 1000:.2f} ms per object"
          f" over {len(mjcf_s)} objects; {time.perf_counter() - t0:.0f} s in all")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
