"""Effort, velocity and armature of every movable joint, from what the joint moves and its role.

A joint's effort limit (URDF ``<limit effort>``, USD ``maxForce``, MJCF ``actuatorfrcrange``) is
the largest force (N, slides) or torque (N m, rotations) that should drive it. It used to come
from a role table (20 N on a 5 g button); a simulator that pushes a joint with its effort then
drives it through its stops. Here it is derived from the **moving subtree** (every link the joint
carries, rigid at rest) and the joint's **role**:

* ``m_eff``: the subtree's mass (slides) or its moment of inertia about the joint axis
  (rotations) with every other joint free (:func:`free_inertias`), so that ``effort / m_eff`` is
  the acceleration the effort gives the part;
* ``arm``: for rotations, the subtree's radius of gyration about the axis, ``sqrt(I / m)``:
  where a hand's force acts, on average (for slides, 1 m);
* the role's **weight multiple** ``k`` and **hand force** ``hand`` (:data:`ROLES`): a hand pushes a
  part with about ``k`` times its weight, ``k m g arm``, and never with more than ``hand`` N at the
  arm. A drawer is pushed with more than its weight, a button with a small multiple of its;
* the **stop budget**: simulators keep limits with stiff springs, not walls. MuJoCo's default
  (``solref 0.02 1``, ``solimp 0.9 0.95 0.001``) lets a joint pressed with acceleration ``a`` sit
  ``a * C_SOFT`` past its stop (:data:`C_SOFT`, the worst case of its impedance curve), and a joint
  arriving at speed ``v`` overshoot by ``v * C_IMPACT``; the speed is what the push (plus the
  largest acceleration gravity adds along the joint) reaches over the range, or the terminal speed
  the joint's damping allows. The effort is the largest whose :func:`overshoot` stays within
  :data:`STOP_SHARE` of the range: pushed with its own effort, a joint stays within its limits
  + 5 % (the ``mujoco`` check and the push test measure it). For parts with a short travel (a
  1.6 mm button, a 0.3 rad tilt) this bound, not the hand, sets the effort.

Velocity limits come from the role's **hand speed** (m/s) at the arm: ``speed`` for slides,
``speed / arm`` for rotations (a door's edge moves at about 1 m/s, a knob's rim at 0.2 m/s).

Damping (from the role, :mod:`infmob_usd.physical`) is capped at :data:`DAMPING_RATE_MAX` times
``m_eff``, so explicit integrators can step it.

Armature (MJCF ``armature``, PhysX joint armature) is the hardware that moves with the joint and
is not modelled as a link (hinge pins, runner carriages, bearings): :data:`ARMATURE_SHARE` of
``m_eff``, raised where a stop holds the subtree's weight until MuJoCo's soft stop sags less than
:data:`SAG_SHARE` of the range (a light lamp arm carrying a head).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from .blueprint import descendants
from .springs import GRAVITY_HOLD, SPRINGS, couple_limits, spring

G = 9.81
"""m/s^2, standard gravity."""

C_SOFT = 4.5e-5
"""s^2: how far past its stop a joint pressed with acceleration ``a`` settles, per unit ``a``, with
MuJoCo's default soft limits: ``(1 - d0) dmax^2 tc^2 / d0^2`` with ``d0 = 0.9``, ``dmax = 0.95``,
``tc = 0.02`` s (the steady state of MuJoCo's constraint ``a1 + d (b v + k r) = (1 - d) a0``, at the
start of its impedance curve where it is softest). Measured: a 5 g slide pressed at 10 m/s^2 sits
0.37 mm past its stop, 3.7e-5 s^2."""

C_IMPACT = 0.0075
"""s: how far past its stop a joint arriving at speed ``v`` overshoots, per unit ``v``, in MuJoCo's
default soft limit (a critically damped spring of time constant ``dmax tc`` = 19 ms: ``v dmax tc / e``
= 0.0070 s, rounded up). Measured: a 3 kg slide pushed with 50 N over 0.4 m arrives at ~3.6 m/s
and overshoots 17 mm, 4.8 ms per m/s."""

STOP_SHARE = 0.04
"""Fraction of a joint's range that effort plus gravity may take it past a stop (the checks allow
0.05; the rest is a margin for the other joints and for contacts)."""

ARMATURE_SHARE = 0.05
"""Armature as a fraction of ``m_eff`` (at least)."""

SAG_SHARE = 0.01
"""Fraction of its range a joint may sag into the stop that holds its subtree's weight, in MuJoCo
(whose soft stop is as stiff as the inertia the joint meets: a light link in a chain that carries a
heavy head sags ~10 % of its range). Armature raises that inertia where needed; only the MJCF
carries armature (URDF has no place for it)."""

MJ_STEP = 0.002
"""s: MuJoCo's default time step, the one the MJCF keeps."""

STEP_SHARE = 0.02
"""Fraction of its range a joint may travel in one :data:`MJ_STEP` when it arrives at a stop driven by
gravity and its effort from the other stop (:func:`drive`'s armature)."""

DAMPING_RATE_MAX = 60.0
"""1/s: a joint's damping is at most this times ``m_eff``. Simulators that apply joint damping
explicitly (Bullet, at its default 1/240 s step) are unstable once ``damping * dt / m_eff``
exceeds 2, and the joints of a chain couple (measured: office chair arms, a slide, a light turn and a
heavy pad in a chain, rang at 240 and were steady at 60); a role's damping (10 N m s for a slide)
put on a light revolute joint of a compound chain (5e-5 kg m^2) throws the chain through its limits."""

EFFORT_FLOOR = 0.01
"""The smallest effort, as a multiple of ``m_eff * G / arm``: where gravity alone uses the stop
budget the effort is not zero (simulators read zero as "no limit" or "cannot move")."""


@dataclass(frozen=True)
class Role:
    """How a hand drives a joint of this role: ``k`` weights, at most ``hand`` N, at ``speed`` m/s."""

    k: float
    hand: float
    speed: float
    why: str


ROLES: dict[str, Role] = {
    "hinge": Role(1.0, 60.0, 1.0, "doors and lids: swung with about their own weight; a door edge ~1 m/s"),
    "slide": Role(1.5, 80.0, 0.5, "drawers and racks: pulled a little harder than their weight, ~0.5 m/s"),
    "knob": Role(20.0, 10.0, 0.2, "knobs: light parts turned by fingertips, rim ~0.2 m/s"),
    "button": Role(20.0, 10.0, 0.05, "buttons: pressed with many times their weight, ~5 cm/s"),
    "turntable": Role(0.5, 5.0, 0.3, "turntable plates: turned by a motor, gently"),
    "swivel": Role(1.0, 30.0, 0.5, "lamp heads, arms, tilting screens: positioned by hand"),
    "holding": Role(1.0, 60.0, 1.0, "laptop lids, monitor tilts and stands: positioned by hand, held where put"),
    "telescope": Role(1.0, 60.0, 0.3, "sliding poles and lifts: raised against their weight"),
    "wheel": Role(0.5, 20.0, 2.0, "wheels and casters: rolled, not pushed"),
    "lid": Role(1.0, 20.0, 0.5, "hinged and screw lids, caps: lifted or turned by hand"),
    "lift_off": Role(1.0, 20.0, 0.5, "lift-off lids, stoppers, liners: lifted off their seat by hand"),
    "plate": Role(1.0, 20.0, 0.3, "plates in a rack: lifted out by hand"),
    "grate": Role(1.0, 40.0, 0.3, "oven grates: slid by hand"),
    "toggle": Role(20.0, 10.0, 0.05, "switch bats and rockers: flipped or pressed by a fingertip, as a button"),
    "default": Role(1.0, 40.0, 0.5, "anything else moved by hand"),
}


def role(name: str) -> Role:
    return ROLES.get(name, ROLES["default"])


@dataclass(frozen=True)
class Drive:
    """The derived limits of one joint and the figures they came from."""

    effort: float
    velocity: float
    armature: float
    damping: float  # the role's damping, capped at DAMPING_RATE_MAX * m_eff
    m_eff: float  # kg or kg m^2
    arm: float  # m
    a_gravity: float  # m/s^2 or rad/s^2, the most gravity adds along the joint
    a_stop: float | None  # the acceleration the stop budget allows (None: no stop)


def _subtree(obj, j):
    """Masses ``(n,)``, world centres of mass ``(n, 3)`` and inertias ``(n, 3, 3)`` (world axes,
    about each centre) of the links joint ``j`` moves, at rest."""
    moved = descendants(obj.joints, j.child)
    links = [link for link in obj.links if link.name in moved]
    m = np.array([link.mass for link in links], float)
    c = np.array([np.asarray(link.origin, float) + np.asarray(link.com, float) for link in links])
    inertia = np.array([np.asarray(link.inertia, float) for link in links])
    return m, c, inertia


def _skew(v: np.ndarray) -> np.ndarray:
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def free_inertias(obj) -> dict[str, float]:
    """The inertia each movable joint meets when pushed with every other joint free, at rest:
    ``1 / (M^-1)[j, j]``, ``M`` the joint-space inertia of the whole object on its fixed base
    (composite rigid bodies, spatial inertias about the world origin). Kg for slides, kg m^2 for
    rotations. A knob on a door adds its mass to the door but not its spin; a lamp pole turning
    about its slide's axis adds all its mass to the slide; a screen on a two-hinge wall arm, pushed
    at its outer hinge, also swings the light inner arm back, so it meets less than its own inertia."""
    chain = [k for k in obj.joints if k.movable]  # parents precede children
    if not chain:
        return {}
    spatial = {}
    for link in obj.links:
        c = np.asarray(link.origin, float) + np.asarray(link.com, float)
        cx = _skew(c)
        m = float(link.mass)
        spatial[link.name] = np.block([[np.asarray(link.inertia, float) + m * cx @ cx.T, m * cx],
                                       [m * cx.T, m * np.eye(3)]])
    below = {k.name: descendants(obj.joints, k.child) for k in chain}
    composite = {k.name: sum(spatial[n] for n in below[k.name]) for k in chain}
    motion = []
    for k in chain:
        a = np.asarray(k.axis, float) / np.linalg.norm(k.axis)
        motion.append(np.concatenate([np.zeros(3), a]) if k.type == "prismatic"
                      else np.concatenate([a, np.cross(np.asarray(k.origin, float), a)]))
    n = len(chain)
    mass = np.zeros((n, n))
    for x in range(n):
        for y in range(x, n):
            kx, ky = chain[x], chain[y]
            if ky.child in below[kx.name]:  # kx is an ancestor of (or is) ky
                mass[x, y] = mass[y, x] = motion[x] @ composite[ky.name] @ motion[y]
    diag = np.diag(np.linalg.inv(mass))
    return {k.name: float(1.0 / d) for k, d in zip(chain, diag)}


def free_inertia(obj, j) -> float:
    """:func:`free_inertias` of one joint."""
    return free_inertias(obj)[j.name]


def overshoot(a: float, span: float, m_eff: float, a_gravity: float, damping: float) -> float:
    """How far past a stop a joint of range ``span`` goes when pushed with acceleration ``a``
    (m/s^2 or rad/s^2) plus gravity's ``a_gravity`` from its other stop: the steady press
    ``C_SOFT (a + a_g)`` plus the momentum it arrives with, ``C_IMPACT v``, with ``v`` the speed
    reached over the range, or the damping's terminal speed if lower."""
    acc = a + a_gravity
    v = math.sqrt(2.0 * acc * span)
    if damping > 0:
        v = min(v, acc * m_eff / damping)
    return C_SOFT * acc + C_IMPACT * v


def _stop_budget(span: float, m_eff: float, a_gravity: float, damping: float) -> float:
    """The largest push acceleration whose :func:`overshoot` is within ``STOP_SHARE * span``
    (negative where gravity alone uses the budget)."""
    limit = STOP_SHARE * span
    if overshoot(0.0, span, m_eff, a_gravity, damping) >= limit:
        return -1.0
    lo, hi = 0.0, 1.0
    while overshoot(hi, span, m_eff, a_gravity, damping) < limit and hi < 1e9:
        lo, hi = hi, hi * 4
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if overshoot(mid, span, m_eff, a_gravity, damping) < limit else (lo, mid)
    return lo


def drive(obj, j, free: float | None = None, armature_floor: float = 0.0,
          damping_rate: float = DAMPING_RATE_MAX) -> Drive:
    """The effort, velocity and armature of movable joint ``j`` of ``obj`` (module docstring);
    ``free``: its :func:`free_inertia`, if known; ``armature_floor``: the least armature (kg or kg m^2) and
    ``damping_rate`` the damping cap over ``m_eff`` (1/s), both raised for a sprung part by :func:`_sprung`."""
    r = role(j.role)
    m, c, inertia = _subtree(obj, j)
    mass = float(m.sum())
    axis = np.asarray(j.axis, float)
    axis = axis / np.linalg.norm(axis)
    gravity = np.array([0.0, 0.0, -G])
    free = free_inertia(obj, j) if free is None else free
    if j.type == "prismatic":
        m_eff, arm = mass, 1.0
        a_gravity = abs(float(gravity @ axis))
        a_role = min(r.k * G, r.hand / mass)
        velocity = r.speed
    else:
        d = c - np.asarray(j.origin, float)
        perp = d - np.outer(d @ axis, axis)
        m_eff = float(np.einsum("i,nij,j->", axis, inertia, axis) + (m * (perp**2).sum(1)).sum())
        arm = max(math.sqrt(m_eff / mass), 1e-3)
        com_perp = np.linalg.norm((m[:, None] * perp).sum(0) / mass)
        # gravity torque about the axis is largest when the centre of mass is level with the axis
        g_perp = float(np.linalg.norm(gravity - (gravity @ axis) * axis))
        tau_gravity = mass * g_perp * float(com_perp)
        a_role = min(r.k * G / arm, r.hand / (mass * arm))
        velocity = r.speed / max(arm, 0.005)
    m_eff = min(m_eff, free)  # what the push accelerates: the rigid subtree, less what free joints let go
    if j.type != "prismatic":
        a_gravity = tau_gravity / m_eff
    damping = min(j.damping, damping_rate * m_eff)
    a_stop = None
    a = a_role
    if j.type != "continuous":
        a_stop = _stop_budget(j.upper - j.lower, m_eff, a_gravity, damping)
        a = min(a, a_stop)
    floor = EFFORT_FLOOR * G / arm
    effort = m_eff * max(a, floor)
    armature = max(ARMATURE_SHARE * m_eff, armature_floor)
    if j.type != "continuous" and a_gravity > 0 and j.stiffness == 0:  # a spring's preload holds its part
        # the stop holding the subtree's weight sags by C_SOFT * load / (m_eff + armature); the load is the
        # whole subtree's weight, also where a free joint lets part of it go (a lift-top's frame carries
        # the top resting on its own stop, a steamer tier the tiers above it)
        load = mass * a_gravity if j.type == "prismatic" else a_gravity * m_eff
        armature = max(armature, C_SOFT * load / (SAG_SHARE * (j.upper - j.lower)) - m_eff)
    if j.type != "continuous":
        # MuJoCo's limit acts from the step after the joint crosses it: a part arriving at v goes v * dt
        # past before anything holds it (a 12 g chair lever falling 0.24 rad at 10 rad/s: 8 % of its
        # range in one 2 ms step). Armature slows what gravity and the push give it (no damping counted)
        span = j.upper - j.lower
        load = (mass * a_gravity if j.type == "prismatic" else a_gravity * m_eff) + effort
        if j.stiffness > 0:  # a return spring holds the weight on its preload and lands the part softly by design
            load = effort
        if damping <= 0 or load / damping > STEP_SHARE * span / MJ_STEP:  # faster than that where damping allows
            armature = max(armature, 2.0 * MJ_STEP**2 * load / (STEP_SHARE**2 * span) - m_eff)
    return Drive(float(effort), float(velocity), float(armature), float(damping), m_eff, arm,
                 a_gravity, a_stop)


FRICTION_SHARE = 0.25
"""A joint's Coulomb friction is at most this share of its effort, so that a push within the effort moves the
part with three quarters of it left over (a hinge's 0.5 N m from the role table would hold a 20 g scissors blade
whose effort is 0.02 N m). The friction of a joint that friction holds (:data:`HELD_ROLES`) is sized on its
load instead, and its effort raised by it."""

HELD_ROLES = ("holding", "toggle")
"""Roles whose joint friction keeps the part where it is put (a laptop lid's friction hinge, a switch's bat):
:func:`holding` sizes it on the load, and the effort is raised by it."""

HOLD_MARGIN = 1.3
"""A ``holding`` joint's friction over the largest load gravity puts on it: friction (constant-torque) hinges are
specified 20-50 % above the load torque so that a lid or a screen stays at any angle (Southco and Reell position
control hinge selection guides); 1.3 within that."""


def holding(obj, j) -> float:
    """The Coulomb friction (N m or N) that holds joint ``j``'s load anywhere in its range: :data:`HOLD_MARGIN`
    times the largest gravity torque about a hinge (its subtree's centre of mass level with the axis) or the
    subtree's weight along a slide; at least ``j.friction`` (:func:`assign_drives` passes the role's, capped at
    :data:`FRICTION_SHARE` of the effort)."""
    m, c, _ = _subtree(obj, j)
    axis = np.asarray(j.axis, float) / np.linalg.norm(j.axis)
    mass = float(m.sum())
    if j.type == "prismatic":
        load = mass * G * abs(float(axis[2]))
    else:
        d = c - np.asarray(j.origin, float)
        perp = d - np.outer(d @ axis, axis)
        com_perp = float(np.linalg.norm((m[:, None] * perp).sum(0) / max(mass, 1e-12)))
        load = mass * G * float(np.linalg.norm(np.array([0.0, 0.0, -1.0]) - (-axis[2]) * axis)) * com_perp
    return max(j.friction, HOLD_MARGIN * load)


SPRING_MARGIN = 1.2
"""A spring-returned joint's effort over what holds it at its far limit (:func:`against_spring`): a hand presses a
toaster's lever or a mop wringer's lever home with a fifth more than its spring, friction and weight push back with
there (a wringer lever's effort was 0.85 N m against 5.6 N m of spring: a robot at that effort stalls). With a
quarter more, a dispenser's push panel went 5.3 % of its range past its far stop in PyBullet; with a fifth, 1.1 %."""


def against_spring(obj, j) -> float:
    """What a hand must overcome to hold spring-returned joint ``j`` at its upper limit (N or N m): its spring there
    (``stiffness * (upper - spring_ref)``, the preload included), its friction, and the most that gravity pulls it
    back anywhere in its range (a hinge's load sampled over the range)."""
    m, c, _ = _subtree(obj, j)
    axis = np.asarray(j.axis, float) / np.linalg.norm(j.axis)
    weight = np.array([0.0, 0.0, -G]) * m[:, None]
    if j.type == "prismatic":
        back = -float(weight.sum(0) @ axis)
    else:
        d = c - np.asarray(j.origin, float)
        back = -math.inf
        for q in np.linspace(j.lower, j.upper, 17):  # Rodrigues: the subtree turned by q about the axis
            turned = (d * math.cos(q) + np.cross(axis, d) * math.sin(q)
                      + np.outer(d @ axis, axis) * (1.0 - math.cos(q)))
            back = max(back, -float(np.cross(turned, weight).sum(0) @ axis))
    return j.stiffness * (j.upper - j.spring_ref) + j.friction + max(back, 0.0)


SPRING_STEP_SHARE = 0.1
"""The most of its range a spring-returned joint may travel in one :data:`MJ_STEP` when its spring and an effort
that beats it (:data:`SPRING_MARGIN`) drive it from its far stop back into its rest stop (:func:`_spring_step`).
Measured in MuJoCo (MJCF) and PyBullet with such efforts: toaster levers (8 %) and wringer, refrigerator
and dispenser levers (6 %) stay within the push test's 5 % of their range past a stop; buttons of 0.1 s springs
(17 % and more) go 10-24 % past. Armature cannot slow them: the spring is sized on the inertia with the armature
(its return time), so the effort that beats it grows with the armature too. Those keep the stop budget's effort."""


def _spring_step(j, d: Drive) -> float:
    """The share of its range sprung joint ``j`` travels in one :data:`MJ_STEP` arriving at its rest stop, pushed
    from its far stop by its spring and :data:`SPRING_MARGIN` times the spring's force there: the speed from the
    work of both over the range, ``v^2 = 2 W / (m_eff + armature)``, with ``k = (m_eff + armature) w^2``."""
    span = j.upper - j.lower
    pre = j.lower - j.spring_ref
    omega = math.sqrt(j.stiffness / (d.m_eff + d.armature))
    work = SPRING_MARGIN * (span + pre) + pre + 0.5 * span  # per unit k span, friction and gravity left out
    return omega * MJ_STEP * math.sqrt(2.0 * work / span)


LAND_TIME = 0.002
"""s: how far past its rest stop a sprung part goes, per unit of the speed it lands with (m/s or rad/s), in the
MJCF: MuJoCo holds a limit from the step after the part crosses it, so the part runs on for up to one
:data:`MJ_STEP` before the stop acts, and the MJCF's stiff stop (``solreflimit`` 4 ms, critically damped) takes
little more. Measured (MuJoCo 4.0, a keyboard key with armature 0.05-100 times its 5 g, landing at 2.5-54 ranges
a second, its travel varied over a step's phases): at most 1.7-2.0 ms."""

SPRING_DAMPING_RATE_MAX = 360.0
"""1/s: the damping of a sprung part whose landing needs more than :data:`DAMPING_RATE_MAX` allows (:func:`_sprung`)
is at most this times ``m_eff``: Bullet applies a URDF's damping explicitly and is unstable past ``damping * dt /
m_eff`` = 2 at its 1/240 s step (measured: a 5 g slide is steady at 1.7 and runs away at 3.7); 1.5 here."""

LANDING_ARMATURE = (0.0, 0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0)
"""Armatures, as multiples of ``m_eff``, that :func:`_sprung` tries in turn for a sprung part that lands too fast (0:
:data:`ARMATURE_SHARE`, the damping raised alone)."""

LANDING_HOLD = (2.0, 1.5, 1.25)
"""How many times gravity's pull a sprung part's spring holds it on its rest stop with
(:data:`~infmob_usd.springs.GRAVITY_HOLD` first), tried in turn by :func:`_sprung` where no armature lands it
within the budget in both readers: the hold's excess over the weight is what throws a light part home, and a URDF
reader meets it without the armature (a 5 g key of 2 mm: 6 % past at a hold of 2 and the most damping Bullet
steps, 1.4 % at 1.25). At 1.25 the part still rests on its stop with a quarter of its weight to spare."""

BULLET_STEP = 1.0 / 240.0
"""s: Bullet's default step (PyBullet's), at which a URDF reader steps a part: the URDF has no armature, Bullet
applies the joint's damping explicitly and drops its friction (:func:`landing_urdf`)."""


def landing(j, d: Drive, tau_gravity: float) -> float:
    """How far past its rest stop sprung joint ``j`` goes, as a share of its range, released from its far stop:
    its landing speed times :data:`LAND_TIME`. The speed is what the spring's work over the range leaves, less
    gravity's (its pull at rest ``tau_gravity`` towards the far stop, :func:`gravity_at_rest`), friction's and the
    damping's, on ``m_eff + armature``: stepped as MuJoCo does, :data:`MJ_STEP` with the damping implicit.
    Measured against MuJoCo on a 5 g key: 14.2 against 14.8 ranges a second, 52.8 against 53.5."""
    span = j.upper - j.lower
    inertia = d.m_eff + d.armature
    x, v = span, 0.0
    for _ in range(int(10.0 / MJ_STEP)):
        push = j.stiffness * (j.lower + x - j.spring_ref) - tau_gravity  # towards the rest stop
        if v == 0.0 and push <= j.friction:
            return 0.0  # friction holds it at the far stop: it never lands
        v = (v * inertia - MJ_STEP * (push - j.friction)) / (inertia + MJ_STEP * d.damping)
        x += MJ_STEP * v
        if x <= 0.0:
            return -v * LAND_TIME / span
        if v >= 0.0:
            return 0.0
    return 0.0


def landing_urdf(j, d: Drive, tau_gravity: float) -> float:
    """:func:`landing` in a URDF reader (PyBullet, the return spring set from ``metadata.json`` as the joint's
    torque): the spring as written (sized on ``m_eff`` + armature) throws the bare ``m_eff`` (a URDF has no
    armature), the damping is applied explicitly (:data:`BULLET_STEP`, semi-implicit Euler) and friction not at
    all (PyBullet drops a URDF's joint friction). Bullet holds a limit from the step after the part crosses it:
    the part goes up to one step's travel past, ``v BULLET_STEP``. Measured (PyBullet 3.2, the stovetop's 5 g
    key of 2 mm, hold 2, damping 200/s): 11.4 % estimated, 10.9 % at the worst phase of 20 released."""
    span = j.upper - j.lower
    x, v = span, 0.0
    for _ in range(int(10.0 / BULLET_STEP)):
        push = j.stiffness * (j.lower + x - j.spring_ref) - tau_gravity  # towards the rest stop
        if v == 0.0 and push <= 0.0:
            return 0.0
        v -= BULLET_STEP * (push + d.damping * v) / d.m_eff
        x += BULLET_STEP * v
        if x <= 0.0:
            return -v * BULLET_STEP / span
        if v >= 0.0:
            return 0.0
    return 0.0


def gravity_at_rest(obj, j) -> float:
    """The force (N, slides) or torque (N m, rotations) gravity puts on joint ``j`` at rest, towards its
    upper limit (negative: it presses the part onto its rest stop)."""
    m, c, _ = _subtree(obj, j)
    axis = np.asarray(j.axis, float) / np.linalg.norm(j.axis)
    weight = np.array([0.0, 0.0, -G]) * m[:, None]
    if j.type == "prismatic":
        return float(weight.sum(0) @ axis)
    return float(np.cross(c - np.asarray(j.origin, float), weight).sum(0) @ axis)


def assign_drives(obj):
    """A copy of ``obj`` with ``effort``, ``velocity``, ``armature`` (and a capped ``damping``) on every
    movable joint (limits final), a return spring on every joint of a spring-returned role (its
    damping and friction the spring's, :mod:`infmob_usd.springs`), and every coupled joint's limits the
    image of its leader's; ``obj`` is not modified."""
    obj = replace(obj, joints=couple_limits(obj.joints))
    joints = []
    free = free_inertias(obj)
    for j in obj.joints:
        if j.movable:
            if j.type != "continuous" and j.role in SPRINGS:
                j, d = _sprung(obj, j, free[j.name])
            else:
                d = drive(obj, j, free[j.name])
            effort = d.effort
            if j.stiffness > 0 and _spring_step(j, d) <= SPRING_STEP_SHARE:  # pressed home against its spring
                effort = max(effort, SPRING_MARGIN * against_spring(obj, j))
            # a role's friction is a figure for a typical part (0.5 N m on a hinge): on a light part it is
            # at most a share of what moves the part (a return spring sizes its own joint's friction)
            if j.stiffness == 0:
                j = replace(j, friction=min(j.friction, FRICTION_SHARE * effort))
            if j.role in HELD_ROLES:  # friction holds its load; the hand moves it against that friction too
                j = replace(j, friction=holding(obj, j))
                effort += j.friction
            elif j.stiffness > 0 and (hold := _round(holding(obj, j))) > j.friction:
                j = replace(j, hold_friction=hold)
            j = replace(j, friction=_round(j.friction))
            j = replace(j, effort=_round(effort), velocity=_round(d.velocity), armature=_round(d.armature),
                        damping=_round(d.damping))
        joints.append(j)
    return replace(obj, joints=_drive_followers(joints))


def _with_spring(obj, j, free: float, armature_floor: float, damping_rate: float, hold: float = GRAVITY_HOLD):
    """``(j, drive)`` of sprung joint ``j`` with its return spring sized on the inertia with the armature, and the
    armature on the spring's force: three rounds settle both (deterministic; the armature changes by < 1 % in the
    third). The spring's damping and friction go on the joint before the drive again: the stop budget uses them.
    ``hold``: the spring's hold against gravity (:func:`~infmob_usd.springs.spring`)."""
    role_friction = j.friction
    d = drive(obj, j, free, armature_floor, damping_rate)
    pull = max(gravity_at_rest(obj, j), 0.0)
    for _ in range(3):
        s = spring(j.role, j.lower, j.upper, d.m_eff + d.armature, pull / (d.m_eff + d.armature), role_friction,
                   damping_rate * d.m_eff, hold)
        j = replace(j, damping=s.damping, friction=_round(s.friction), stiffness=_round(s.stiffness),
                    spring_ref=_round(s.reference))
        d = drive(obj, j, free, armature_floor, damping_rate)
    return j, d


def _sprung(obj, j, free: float):
    """``(j, drive)`` of sprung joint ``j`` landing on its rest stop within :data:`STOP_SHARE` of its range when
    released from its far stop, both in the MJCF (:func:`landing`: MuJoCo, with the armature) and in a URDF reader
    (:func:`landing_urdf`: PyBullet, without it). A spring that holds a light part on its stop against its weight
    (:data:`~infmob_usd.springs.GRAVITY_HOLD`) throws it home with that weight's work over the range: a 5 g key of
    1.5 mm lands at 0.08 m/s, 9 % of its travel past its stop in MuJoCo, and 10 % in PyBullet. Where it does, the
    damping may rise to critical on the inertia with the armature (up to :data:`SPRING_DAMPING_RATE_MAX`, which
    Bullet's explicit damping still steps), and the armature through :data:`LANDING_ARMATURE`, and then the hold
    through :data:`LANDING_HOLD`, until it lands within in both: armature lowers what gravity's hold adds to the
    spring in MuJoCo (the spring keeps its return time on the inertia with it) and raises the critical damping
    that slows it in both; a lower hold leaves less of the spring's preload to throw it. Where none does, the
    gentlest landing of them (the worse of the two readers)."""
    tau_gravity = gravity_at_rest(obj, j)

    def past(sj, d):
        return max(landing(sj, d, tau_gravity), landing_urdf(sj, d, tau_gravity))

    sj, d = _with_spring(obj, j, free, 0.0, DAMPING_RATE_MAX)
    best = (past(sj, d), sj, d)
    m_eff = d.m_eff
    holds = LANDING_HOLD if tau_gravity > 0 else LANDING_HOLD[:1]  # the hold only sizes a spring against gravity
    for hold in holds:
        for share in LANDING_ARMATURE:
            if best[0] <= STOP_SHARE:
                return best[1], best[2]
            sj, d = _with_spring(obj, j, free, share * m_eff, SPRING_DAMPING_RATE_MAX, hold)
            worst = past(sj, d)
            if worst < best[0]:
                best = (worst, sj, d)
    return best[1], best[2]


def _drive_followers(joints: list) -> list:
    """``joints`` with every coupled leader's effort raised by what it takes to drive its followers: each
    follower's effort (its weight multiple, friction, spring) times ``|ratio|``, its load seen at the leader (a
    pedal bin's pedal opens a lid turning 5 times as far: 5 times the lid's effort at the pedal)."""
    extra: dict[str, float] = {}
    for j in joints:
        if j.mimic is not None:
            leader, ratio, _ = j.mimic
            extra[leader] = extra.get(leader, 0.0) + abs(ratio) * j.effort
    return [replace(j, effort=_round(j.effort + extra[j.name])) if j.name in extra else j for j in joints]


def _round(x: float) -> float:
    """Six significant digits: what the writers print, so files and the model agree."""
    return float(f"{x:.6g}")


__all__ = ["FRICTION_SHARE", "HELD_ROLES", "HOLD_MARGIN", "ROLES", "SPRING_MARGIN", "Drive", "Role", "against_spring",
           "assign_drives", "drive", "holding", "role"]
