"""Return springs and coupled joints: joint properties every writer carries in its own idiom.

**Return springs.** A joint whose role is in :data:`SPRINGS` (a push button, a toaster lever, a pen
plunger, a self-closing hinge, a pedal-driven lid) gets a linear spring that brings it back to rest
(its lower limit) when let go. The spring is sized from what it moves and a real return time:

* ``m_eff``: the inertia the joint meets (:func:`infmob_usd.effort.free_inertias`; kg or kg m^2) plus
  the armature the MJCF gives it (:mod:`infmob_usd.effort`);
* the spring's zero lies :data:`PRELOAD` of the range *beyond* the rest stop (``spring_ref =
  lower - PRELOAD * span``), so at rest the spring still presses the part onto its stop, as a real
  preloaded spring does; further where gravity pulls the part off its stop, until the spring holds it
  with :data:`GRAVITY_HOLD` times that pull (:func:`infmob_usd.effort.gravity_at_rest`);
* the natural frequency ``w = RETURN_UT / T`` with ``T`` the role's return time; ``stiffness =
  m_eff w^2``, and damping critical (``2 m_eff w``) or what :data:`~infmob_usd.effort.DAMPING_RATE_MAX`
  allows. Critically damped, released from its far stop (``1 + PRELOAD`` ranges from the spring's
  zero), the part is back on its rest stop after ``u`` natural periods with ``(1 + u) e^-u =
  PRELOAD / (1 + PRELOAD)``: ``u`` = 2.99 for a preload of 0.25; :data:`RETURN_UT` (4) leaves a margin;
* it arrives at its stop at about ``0.1 span w``, a gentle landing that the MJCF's stiff limits keep
  within 5 % of the range;
* the joint's Coulomb friction is at most :data:`FRICTION_SHARE` of what the spring has left at rest
  after gravity, or the part would stick where it was released.

A spring is sized on the mass and a return time, not on the force of the real part's spring: a real
5 g appliance button pushes back with 1-3 N and returns in a few milliseconds, a spring simulators
at a 2-4 ms step cannot land on its stop; ours returns in the role's time with ~0.01 N.

Writers: MJCF ``stiffness`` + ``springref`` on the joint; USD the joint's drive (stiffness and
``targetPosition`` = the spring's zero, :mod:`infmob_usd.layers.usd`); URDF has no spring, so
``metadata.json`` carries it (``joints[].spring``) and SAPIEN users set it as the joint's drive
(``set_drive_property(stiffness, damping)``, ``set_drive_target(reference)``), as
``validate/sim.py`` does.

**Coupled joints.** A category declares ``Layout.couple(follower, leader, ratio, offset)``:
``q_follower = ratio * q_leader + offset``. :func:`couple_limits` keeps the follower's limits the image
of the leader's (shortening the leader where the follower's range is shorter), so that every state the
leader reaches is one the follower can take. Writers: URDF ``<mimic>``, MJCF ``<equality><joint>``,
USD ``PhysxMimicJointAPI``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from .errors import ModelError

PRELOAD = 0.25
"""The spring's zero lies this fraction of the range beyond the rest stop: at rest it presses with a
quarter of the travel's worth of spring, at the far stop with 1.25 (a preloaded compression spring;
its force rises 5 : 1 over the travel)."""

RETURN_UT = 4.0
"""``w T``: natural periods (radians) a critically damped spring of :data:`PRELOAD` takes from the far
stop back to the rest stop is the root of ``(1 + u) e^-u = 0.2``, 2.99; 4 leaves a quarter of the
return time for the joint's friction and for the armature the MJCF adds (measured: at 3, a 8 g button
was still 6.9 % of its travel out after its 0.1 s in MuJoCo)."""

GRAVITY_HOLD = 2.0
"""At rest the spring presses the part on its stop with at least this many times the pull of gravity
along the joint (less, down to :data:`~infmob_usd.effort.LANDING_HOLD`'s last, where the excess would throw a
light part home too hard: :func:`infmob_usd.effort._sprung`)."""

FRICTION_SHARE = 0.5
"""A spring-returned joint's Coulomb friction is at most this share of the spring's force at rest, less
gravity's pull (a button whose friction beats its spring stays pressed)."""


@dataclass(frozen=True)
class ReturnSpring:
    """How fast a role's spring brings its part back: ``time`` s from the far stop to rest."""

    time: float
    source: str


SPRINGS: dict[str, ReturnSpring] = {
    "button": ReturnSpring(0.1, "momentary push buttons snap back within 50-100 ms (tactile switches: "
                                "contact bounce <= 5 ms, actuation 1.5-3 N); the slow end, for simulators' steps"),
    "plunger": ReturnSpring(0.1, "a spring-return plunger (pen, pump) is a push button's mechanism"),
    "lever": ReturnSpring(0.3, "a toaster's carriage lever is thrown up by its spring in a fraction of a second;"
                               " 0.3 s with the carriage it lifts"),
    "self_closing": ReturnSpring(4.5, "door closers are set at the factory to close a door in 4-5 s"
                                      " (EN 1154 closers, 'comfort zone' setting)"),
    "pedal_lid": ReturnSpring(1.0, "a pedal bin's lid falls shut when the pedal is let go; soft-close"
                                   " dampers slow the fall to about a second"),
}
"""Spring-returned roles and their return times, with the source of each figure."""


@dataclass(frozen=True)
class Spring:
    """A joint's return spring: ``stiffness`` (N/m or N m/rad) about ``reference`` (m or rad), the damping
    that goes with it and the friction it allows."""

    stiffness: float
    reference: float
    damping: float
    friction: float
    omega: float  # rad/s, sqrt(stiffness / m_eff)


def spring(role: str, lower: float, upper: float, m_eff: float, a_gravity: float, friction: float,
           damping_max: float, hold: float = GRAVITY_HOLD) -> Spring | None:
    """The return spring of a joint of ``role`` (None where the role has none): range ``[lower, upper]``,
    meeting ``m_eff``, pulled off its rest stop by gravity with ``a_gravity`` (m/s^2 or rad/s^2; 0 where
    gravity presses it onto its stop); ``friction``
    the role's, ``damping_max`` the largest damping the joint may have (module docstring); ``hold``: how many
    times gravity's pull the spring presses with at rest (:data:`GRAVITY_HOLD`; lowered where the part would
    otherwise land too hard, :func:`infmob_usd.effort._sprung`)."""
    r = SPRINGS.get(role)
    if r is None:
        return None
    span = upper - lower
    if not (span > 0 and math.isfinite(span)):
        raise ModelError(f"a {role} spring needs a limited range, got [{lower}, {upper}]")
    omega = RETURN_UT / r.time
    pre = max(PRELOAD * span, hold * a_gravity / omega**2)  # held on its stop against its weight
    stiffness = m_eff * omega**2
    damping = min(2.0 * m_eff * omega, damping_max)
    friction = min(friction, FRICTION_SHARE * m_eff * (omega**2 * pre - a_gravity))
    return Spring(stiffness, lower - pre, damping, max(friction, 0.0), omega)


def couple_limits(joints: list) -> list:
    """The model's joints with every coupled joint's limits the image of its leader's, and the leader's
    range shortened to what the follower's limits allow. Every joint rests at 0 in the written files, so
    the offset must map the leader's rest onto the follower's: it is 0 (the files carry it for readers
    that expect one)."""
    by_name = {j.name: j for j in joints}
    out = {j.name: j for j in joints}
    for j in joints:
        if j.mimic is None:
            continue
        leader, ratio, offset = j.mimic
        if offset != 0.0:
            raise ModelError(f"{j.name} follows {leader} with offset {offset:g}: both rest at 0, so the offset"
                             " must be 0 (declare the follower's rest where the leader's puts it)")
        lead = out[leader]
        # the leader's range whose image lies in the follower's
        a, b = sorted(((by_name[j.name].lower - offset) / ratio, (by_name[j.name].upper - offset) / ratio))
        lo, hi = max(lead.lower, a), min(lead.upper, b)
        if not (lo <= 0.0 <= hi) or hi - lo <= 0:
            raise ModelError(f"{j.name} = {ratio:g} * {leader} + {offset:g} has no common range with"
                             f" {leader} [{lead.lower:.4g}, {lead.upper:.4g}] inside its own limits"
                             f" [{j.lower:.4g}, {j.upper:.4g}]; fix the ratio, offset or limits")
        out[leader] = replace(lead, lower=lo, upper=hi)
        f = sorted((ratio * lo + offset, ratio * hi + offset))
        out[j.name] = replace(j, lower=f[0], upper=f[1])
    return [out[j.name] for j in joints]


__all__ = ["FRICTION_SHARE", "PRELOAD", "RETURN_UT", "SPRINGS", "ReturnSpring", "Spring", "couple_limits",
           "spring"]
