"""Passive joints at rest: each revolute joint neutral under gravity or pressed onto its rest stop."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..blueprint import descendants
from ..springs import SPRINGS

SPRUNG_LIGHT = 0.02
"""kg: a sprung part up to this mass rests on its spring, not on a counterweight (a few-gram button or key)."""
GRAVITY = np.array([0.0, 0.0, -9.81])
"""m/s^2, world."""

BALANCED = 2e-4
"""m; a revolute joint whose carried centre of mass lies this close to the vertical plane
through its axis (torque below ``BALANCED * g * mass``) is *neutral* under gravity."""

HEEL_SECTION = (0.008, 0.03)
"""m; the side of a counterweight heel's square section is 60 % of the carried link's extent
along the joint axis, within these bounds."""


def gravity_torque(links, joints, joint) -> tuple[float, float, np.ndarray]:
    """Gravity torque about ``joint``'s axis at rest (N m, positive = toward +q), the mass it
    carries (kg) and the carried centre of mass ``(3,)`` in world coordinates.

    The carried mass is every link of the joint's subtree with its real mass and centre of mass
    (:func:`~infmob_usd.mass.inertial`, as written to the files).
    """
    by_name = {link.name: link for link in links}
    mass, moment = 0.0, np.zeros(3)
    for name in descendants(joints, joint.child):
        link = by_name[name]
        mass += link.mass
        moment += link.mass * (np.asarray(link.origin, float) + link.com)
    com = moment / mass
    torque = float(np.cross(com - np.asarray(joint.origin, float), mass * GRAVITY) @ np.asarray(joint.axis, float))
    return torque, mass, com


def rest_on_stops(links, joints, densities: dict[str, float], walls: dict[str, float] | None = None):
    """Make every passive revolute joint neutral under gravity or pressed onto its rest stop.

    A *passive* joint is one with no drive: every joint of a generated object is (they only
    have damping and friction). This pass treats the joints declared ``revolute`` (single
    DoF; compound chains keep their declared limits). With ``tau`` the gravity torque at rest
    about the axis of everything the joint carries (:func:`gravity_torque`):

    * ``|tau| <= BALANCED * g * mass``: *neutral* (a swivel about Z, a head hanging under its
      pivot); unchanged.
    * gravity pushes toward negative q: if ``lower == 0`` the joint is *pressed onto its rest
      stop*; unchanged. If the range is two-sided (``lower < 0 < upper``) the core keeps the
      side that lifts the load: limits ``(0, upper)``.
    * gravity pushes toward positive q with a two-sided range: the axis is flipped and the
      limits become ``(0, -lower)`` (pressed onto the stop that was the lower side).
    * a spring-returned part of at most :data:`SPRUNG_LIGHT` (role in :data:`~infmob_usd.springs.SPRINGS`: a
      mouse button on its rear hinge) whose load pulls it off its rest stop is held there by its return spring,
      which the core sizes to hold :data:`~infmob_usd.springs.GRAVITY_HOLD` times that pull; unchanged (a heavier
      lever, a toilet's 50 g flush lever, keeps its counterweight, as real ones are balanced);
    * otherwise (rest is a stop and gravity pulls away from it: a lever's grip hanging off
      its axis) a *counterweight heel* is added to the child link: a bar of the child's
      heaviest material from the axis along the side opposite the carried centre of mass,
      as long as it must be to bring that centre onto the axis (moment ``rho A L^2 / 2``).

    The heel is solid (``wall=0``) whatever its family's wall; ``walls`` (slot -> m) mass the
    child's other pieces as :func:`~infmob_usd.model.build` did.

    Returns new ``(links, joints)`` lists; links and joints not changed are the same objects.
    """
    from ..mass import inertial
    from ..primitives import box_between

    links, joints = list(links), list(joints)
    index = {link.name: i for i, link in enumerate(links)}
    for k, j in enumerate(joints):
        if j.kind != "revolute" or j.type != "revolute":
            continue
        torque, mass, com = gravity_torque(links, joints, j)
        if abs(torque) <= BALANCED * abs(GRAVITY[2]) * mass:
            continue
        if torque < 0 and j.lower == 0:
            continue
        if torque < 0 and j.upper > 0:
            joints[k] = replace(j, lower=0.0)
            continue
        if torque > 0 and j.lower < 0:
            joints[k] = replace(j, axis=-np.asarray(j.axis, float), lower=0.0, upper=-j.lower)
            continue
        if j.role in SPRINGS and links[index[j.child]].mass <= SPRUNG_LIGHT:  # held by its return spring
            continue
        # a counterweight heel on the child: its moment about the axis cancels the carried one
        child = links[index[j.child]]
        if not child.pieces:
            continue
        axis, pivot = np.asarray(j.axis, float), np.asarray(j.origin, float)
        arm = com - pivot
        arm = arm - (arm @ axis) * axis  # the carried centre off the axis, perpendicular to it
        r = float(np.linalg.norm(arm))
        u = arm / r
        w = np.cross(axis, u)
        heaviest = max(child.pieces, key=lambda p: densities[p.material] * p.volume())
        rho = densities[heaviest.material]
        local = [v for p in child.pieces for v, _ in p.hulls()] or [p.vertices for p in child.pieces]
        along = np.vstack(local) @ axis
        side = float(np.clip(0.6 * np.ptp(along), *HEEL_SECTION))
        length = math.sqrt(2.0 * mass * r / (rho * side * side))
        # the bar in a frame (u, w, axis) at the pivot, at the carried centre's axial position
        centre = pivot + (float((com - pivot) @ axis)) * axis - 0.5 * length * u
        frame = np.eye(4)
        frame[:3, :3] = np.column_stack([u, w, axis])
        frame[:3, 3] = centre - np.asarray(child.origin, float)  # link-local
        heel = box_between([-length / 2, -side / 2, -side / 2], [length / 2, side / 2, side / 2],
                           heaviest.material, name="counterweight").transformed(frame).replace(wall=0.0)
        pieces = child.pieces + [heel]
        walls = walls or {}
        m, c, inertia = inertial((p, densities[p.material], walls.get(p.material, 0.0)) for p in pieces)
        links[index[j.child]] = replace(child, pieces=pieces, mass=m, com=c, inertia=inertia)
    return links, joints


