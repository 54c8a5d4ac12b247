"""MuJoCo checks of a written object folder (MJCF, or the URDF as MuJoCo reads it).

``mujoco`` (one check, on ``<name>.xml``)
    * the MJCF loads in MuJoCo (no warning), with the movable joints of ``metadata.json``;
    * **rest**: gravity on, no push, :data:`REST_TIME` (2 s): no slide moves more than 1 mm and no
      hinge more than 1 degree;
    * **push**: each movable joint, pushed alone with its own effort (the MJCF
      ``actuatorfrcrange``, which MuJoCo also reads from a URDF's ``<limit effort>``) from rest
      towards its upper limit and from its upper limit back to rest, for :data:`PUSH_TIME` each,
      stays within its limits + 5 % of its range at every step (MuJoCo's limits are soft: an effort
      far above what the part weighs drives it through its stop);
    * **contacts**: at rest, no contact between bodies that are not parent and child (after
      the MJCF's ``contact/exclude`` pairs, which name the real parent and child of compound chains).

:func:`push_joints` and :func:`rest_motion` work on any ``MjModel`` (the push test also runs them
on the URDF).
"""

from __future__ import annotations

import json
import math
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .files import gate_joints
from .result import CheckResult

REST_TIME = 2.0  # s
REST_MAX_PRISMATIC = 1e-3  # m
REST_MAX_REVOLUTE = math.radians(1.0)  # rad
PUSH_TIME = 1.0  # s per joint and direction
PUSH_TOL = 0.05  # fraction of a joint's range a push may take it past a limit
CONTACT_TOL = 1e-4  # m: contacts at rest deeper than this (MuJoCo reports touching hulls at 0 distance)
INSTALL_HINT = "pip install -e .[sim]"


class MujocoUnavailableError(RuntimeError):
    """MuJoCo is not installed."""


def import_mujoco():
    try:
        import mujoco
    except ImportError:  # pragma: no cover - depends on the environment
        raise MujocoUnavailableError(f"the mujoco check needs MuJoCo: {INSTALL_HINT}") from None
    return mujoco


def load_model(path: str | Path):
    """``MjModel`` of an MJCF or URDF file (MuJoCo's own parser, relative paths from the file)."""
    mujoco = import_mujoco()
    return mujoco.MjModel.from_xml_path(str(path))


@dataclass
class Push:
    """One push: joint ``joint`` pushed with ``effort`` towards ``side``, and how far it went."""

    joint: str
    side: str  # "upper" | "lower"
    effort: float
    excess: float  # furthest past a limit, as a fraction of its range (<= 0: inside; -1: no limits)
    travel: float  # fraction of the pushed joint's range covered towards ``side``
    other: str  # the other limited joint that went furthest past a limit meanwhile ("" if none)
    other_excess: float  # its excess (reported, not judged: a 5 g button on a slammed door is
    #                      thrown past its soft stop whatever its own effort)
    rest: float = -1.0  # the same joint's furthest past a limit left alone (no push, gravity on) for
    #                     as long: where a stop carries weight, a soft stop's sag (see :func:`rest_excess`)
    pushed: float = -1.0  # how far past a limit the push took it beyond where it rests past that same
    #                       limit (fraction of its range): what its effort did, the push test's measure
    span: float = 0.0  # the joint's range (m or rad; 0: no limits)
    prismatic: bool = False

    @property
    def rest_ok(self) -> bool:
        """Its rest sag is within :data:`PUSH_TOL` of its range or the rest check's 1 mm / 1 degree."""
        if self.span <= 0:
            return True
        return self.rest <= max(PUSH_TOL, (REST_MAX_PRISMATIC if self.prismatic else REST_MAX_REVOLUTE) / self.span)


def _past(q, lo, hi, span) -> np.ndarray:
    """``(2, n)``: how far each joint is past its lower (row 0) and upper (row 1) limit, per range."""
    return np.stack([(lo - q) / span, (q - hi) / span])


def _push(name: str, side: str, effort: float, travel: float, limited: list[str], worst,
          rest: dict[str, tuple[float, float]] | None = None, span: float = 0.0, prismatic: bool = False) -> Push:
    """``worst``: ``(2, len(limited))`` from :func:`_past` over the push; ``rest``: name -> (past its lower,
    past its upper) left alone (:func:`rest_excess`)."""
    worst = np.asarray(worst, float)
    own = {n: float(w) for n, w in zip(limited, worst.max(0))}
    others = [(w, n) for n, w in own.items() if n != name]
    w, other = max(others) if others else (-1.0, "")
    if name in limited:
        k = limited.index(name)
        r = (rest or {}).get(name, (-1.0, -1.0))
        pushed = max(float(worst[0, k]) - max(r[0], 0.0), float(worst[1, k]) - max(r[1], 0.0))
        return Push(name, side, effort, own[name], float(travel), other, w, max(r), pushed, float(span), prismatic)
    return Push(name, side, effort, -1.0, float(travel), other, w)


def _joint_info(model):
    mujoco = import_mujoco()
    names = [mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, i) for i in range(model.njnt)]
    moving = [i for i in range(model.njnt)
              if int(model.jnt_type[i]) in (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))]
    return names, moving


def effort_of(model, i: int) -> float:
    """A joint's effort: its ``actuatorfrcrange`` (MuJoCo's reading of URDF ``<limit effort>``)."""
    if not model.jnt_actfrclimited[i]:
        raise ValueError(f"joint {i} has no effort limit (actuatorfrcrange)")
    lo, hi = model.jnt_actfrcrange[i]
    return float(min(-lo, hi))


def _limits(model, moving: list[int]) -> tuple[list[int], tuple]:
    """The limited joints among ``moving`` and ``(qpos addresses, lower, upper, range)`` of them."""
    limited = [i for i in moving if model.jnt_limited[i]]
    lo = np.array([model.jnt_range[i][0] for i in limited])
    hi = np.array([model.jnt_range[i][1] for i in limited])
    qadr = np.array([model.jnt_qposadr[i] for i in limited], int)
    return limited, (qadr, lo, hi, np.maximum(hi - lo, 1e-12))


def _run(mujoco, model, data, steps: int, bounds: tuple) -> np.ndarray:
    """Step ``data`` ``steps`` times (with whatever forces it holds): ``(2, n)`` the furthest each limited
    joint of ``bounds`` (:func:`_limits`) went past its lower and its upper limit, per range."""
    qadr, lo, hi, span = bounds
    worst = np.full((2, len(qadr)), -np.inf)
    for _ in range(steps):
        mujoco.mj_step(model, data)
        worst = np.maximum(worst, _past(data.qpos[qadr], lo, hi, span))
    return worst


def opened_by(meta: dict) -> dict[str, list[str]]:
    """Joint name -> the joints that must be open before it moves (``metadata.json``: those of the part it
    ``requires_open``, and of what that part requires in turn: :func:`.files.gate_joints`), for
    :func:`push_joints`."""
    return {name: gates for name, gates in gate_joints(meta).items() if gates}


def _follow(model, data, i: int) -> None:
    """Put the joints coupled to joint ``i`` (MJCF ``<equality><joint>``, ``joint1 = poly(joint2)``) where
    the coupling puts them, so a push from a limit starts from a consistent state."""
    mujoco = import_mujoco()
    for e in range(model.neq):
        if int(model.eq_type[e]) == int(mujoco.mjtEq.mjEQ_JOINT) and int(model.eq_obj2id[e]) == i:
            c = model.eq_data[e]
            f = int(model.eq_obj1id[e])
            q = float(data.qpos[model.jnt_qposadr[i]]) - float(model.qpos0[model.jnt_qposadr[i]])
            data.qpos[model.jnt_qposadr[f]] = model.qpos0[model.jnt_qposadr[f]] + c[0] + c[1] * q + c[2] * q**2


def push_joints(model, duration: float = PUSH_TIME, rest: bool = True,
                opened: dict[str, list[str]] | None = None) -> list[Push]:
    """Push every hinge or slide joint alone with its effort towards each limit (module docstring):
    from rest towards its upper limit, and from its upper limit back into its rest stop, the push
    that arrives fastest (``opened``: joint -> the joints of the part it ``requires_open``, which
    are put at their upper limit for that start, as a hand opens a door before pulling its rack).
    Each push is judged on the furthest it went past a limit at any step (its peak), not its end.

    A joint without limits (continuous) is pushed one way; only the other joints are judged then.
    Each :class:`Push` also carries the joint's :func:`rest_excess` over the same time (``rest``
    false: not run; the ``mujoco`` check judges the pushes themselves, and rests 2 s on its own).
    """
    mujoco = import_mujoco()
    data = mujoco.MjData(model)
    names, moving = _joint_info(model)
    limited, bounds = _limits(model, moving)
    steps = int(round(duration / model.opt.timestep))
    still = rest_excess(model, duration) if rest else {}
    slide = int(mujoco.mjtJoint.mjJNT_SLIDE)
    ids = {names[k]: k for k in moving}
    out = []
    for i in moving:
        effort = effort_of(model, i)
        sides = ("upper", "lower") if model.jnt_limited[i] else ("upper",)
        for side in sides:
            mujoco.mj_resetData(model, data)
            sign = 1.0 if side == "upper" else -1.0
            if side == "lower":  # from the other limit: the push crosses the whole range into the rest stop
                for k in [i, *(ids[n] for n in (opened or {}).get(names[i], []) if n in ids)]:
                    data.qpos[model.jnt_qposadr[k]] = model.jnt_range[k][1]
                    _follow(model, data, k)
            data.qfrc_applied[model.jnt_dofadr[i]] = sign * effort
            worst = _run(mujoco, model, data, steps, bounds)
            q_end = float(data.qpos[model.jnt_qposadr[i]])
            if model.jnt_limited[i]:
                a, b = model.jnt_range[i]
                travel = (q_end - a) / (b - a) if side == "upper" else (b - q_end) / (b - a)
            else:
                travel = q_end / math.pi
            out.append(_push(names[i], side, effort, travel, [names[k] for k in limited], worst, still,
                             float(np.diff(model.jnt_range[i])[0]) if model.jnt_limited[i] else 0.0,
                             int(model.jnt_type[i]) == slide))
    return out


def rest_excess(model, duration: float = PUSH_TIME) -> dict[str, tuple[float, float]]:
    """Every limited hinge or slide left alone (no push, gravity on) for ``duration``: name -> the
    furthest it went past its lower and past its upper limit, as fractions of its range (<= 0: inside).

    A joint whose stop carries weight (a cap on its seat, a telescoping pole collapsed) sits past it
    in MuJoCo whatever pushes it: its limits are soft, and the sag is set by MuJoCo's default
    ``solreflimit`` / ``solimplimit`` and the load, not by the file. Measured (MuJoCo 4.0): a part
    resting on a vertical slide's stop sits 0.37 mm past it, whatever its mass, and more where part
    of what the slide carries hangs on free joints of its own (``dof_invweight0``, which sets the
    stop's softness, counts those joints free, the load counts their weight): 0.56 mm under a pump
    head on its own slide, 0.59 mm under a lamp head on free arms. A URDF has no place for armature
    or limit softness (MuJoCo's URDF reader takes only ``compiler``, ``option`` and ``size`` from a
    ``<mujoco>`` element, and ``option``'s ``o_solref`` / ``o_solimp`` override contacts only), so a
    6 mm push-pull spout sits 7 % of its range past its stop in MuJoCo at rest."""
    mujoco = import_mujoco()
    names, moving = _joint_info(model)
    limited, bounds = _limits(model, moving)
    worst = _run(mujoco, model, mujoco.MjData(model), int(round(duration / model.opt.timestep)), bounds)
    return {names[i]: (float(worst[0, k]), float(worst[1, k])) for k, i in enumerate(limited)}


def rest_motion(model, duration: float = REST_TIME) -> tuple[dict[str, float], object]:
    """Joints left alone under gravity for ``duration``: name -> largest |q - q0| (m or rad);
    and the ``MjData`` at the start (after one forward pass), for the contact check."""
    mujoco = import_mujoco()
    data = mujoco.MjData(model)
    names, moving = _joint_info(model)
    mujoco.mj_forward(model, data)
    start = mujoco.MjData(model)
    mujoco.mj_forward(model, start)
    adr = np.array([model.jnt_qposadr[i] for i in moving], int)
    q0 = data.qpos[adr].copy()
    worst = np.zeros(len(moving))
    for _ in range(int(round(duration / model.opt.timestep))):
        mujoco.mj_step(model, data)
        worst = np.maximum(worst, np.abs(data.qpos[adr] - q0))
    return {names[i]: float(w) for i, w in zip(moving, worst)}, start


def rest_contacts(model, data) -> list[tuple[str, str, float]]:
    """Contacts deeper than :data:`CONTACT_TOL` between bodies that are not parent and child."""
    mujoco = import_mujoco()
    out = []
    for c in data.contact[: data.ncon]:
        b1, b2 = int(model.geom_bodyid[c.geom1]), int(model.geom_bodyid[c.geom2])
        if model.body_parentid[b1] == b2 or model.body_parentid[b2] == b1:
            continue
        if -c.dist > CONTACT_TOL:
            out.append((mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, b1),
                        mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, b2), float(-c.dist)))
    return out


def _short(items, n: int = 5) -> str:
    items = list(items)
    return "; ".join(items[:n]) + (f" (+{len(items) - n} more)" if len(items) > n else "")


def check_mujoco(folder: str | Path) -> list[CheckResult]:
    """The ``mujoco`` check of one object folder (module docstring); skipped (passed, with a note)
    when the folder has no MJCF."""
    import_mujoco()
    folder = Path(folder)
    t0 = time.perf_counter()
    try:
        meta = json.loads((folder / "metadata.json").read_text())
        rel = meta.get("files", {}).get("mjcf")
        path = folder / rel if rel else folder / f"{folder.name}.xml"
        if not path.is_file():
            return [CheckResult("mujoco", True, f"skipped: no MJCF ({path.name}) in this folder")]
        result = _check(path, meta)
    except MujocoUnavailableError:
        raise
    except Exception as exc:
        result = CheckResult("mujoco", False, f"crashed: {type(exc).__name__}: {exc}")
    result.detail += f" [{time.perf_counter() - t0:.2f} s]"
    return [result]


def _check(path: Path, meta: dict) -> CheckResult:
    mujoco = import_mujoco()
    try:
        model = load_model(path)
    except Exception as exc:
        return CheckResult("mujoco", False, f"load failed: {exc}")
    problems = []
    names, moving = _joint_info(model)
    want = sorted(j["name"] for j in meta["joints"] if j["type"] != "fixed")
    got = sorted(names[i] for i in moving)
    if got != want:
        problems.append(f"{len(got)} movable joints, metadata has {len(want)}: missing "
                        f"{sorted(set(want) - set(got))}, unexpected {sorted(set(got) - set(want))}")
    motion, start = rest_motion(model)
    for i in moving:
        lim = REST_MAX_PRISMATIC if int(model.jnt_type[i]) == int(mujoco.mjtJoint.mjJNT_SLIDE) else REST_MAX_REVOLUTE
        if motion[names[i]] > lim or not math.isfinite(motion[names[i]]):
            unit = (f"{motion[names[i]] * 1000:.3g} mm" if lim == REST_MAX_PRISMATIC
                    else f"{math.degrees(motion[names[i]]):.3g} deg")
            problems.append(f"rest: {names[i]} moved {unit}")
    contacts = rest_contacts(model, start)
    problems += [f"contact at rest {a} / {b} {d * 1000:.2g} mm deep" for a, b, d in contacts]
    pushes = push_joints(model, rest=False, opened=opened_by(meta))
    bad = [p for p in pushes if not p.excess <= PUSH_TOL]
    problems += [f"push {p.joint} -> {p.side} with {p.effort:.3g}: {p.excess * 100:.1f} % of its range"
                 " past its limit" for p in bad]
    worst = max((p.excess for p in pushes), default=-1.0)
    if problems:
        return CheckResult("mujoco", False, _short(problems))
    return CheckResult("mujoco", True, f"{len(moving)} joints; rest, {len(pushes)} pushes "
                                       f"(worst {max(worst, 0) * 100:.2f} % past a limit), no contacts")
