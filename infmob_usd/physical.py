"""Physical plausibility passes applied once, for every category.

* :func:`rest_on_ground` moves the object so its lowest point at rest is z = 0.
* :data:`DYNAMICS` gives passive joint dynamics per joint role, so doors stay
  where they are left and knobs do not spin freely.

Units: damping is N*m*s/rad (rotations) or N*s/m (slides); friction is N*m
(rotations) or N (slides); effort likewise N*m or N; velocity rad/s or m/s.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .blueprint import Blueprint
from .joints import Dof


@dataclass(frozen=True)
class Dynamics:
    damping: float
    friction: float
    effort: float
    velocity: float


DYNAMICS: dict[str, Dynamics] = {
    "hinge": Dynamics(damping=2.0, friction=0.5, effort=50.0, velocity=2.0),       # doors, lids
    "slide": Dynamics(damping=10.0, friction=1.0, effort=200.0, velocity=0.5),     # drawers, racks
    "knob": Dynamics(damping=0.02, friction=0.01, effort=2.0, velocity=6.0),       # knobs, dials
    "button": Dynamics(damping=1.0, friction=0.2, effort=20.0, velocity=0.2),      # push buttons
    "turntable": Dynamics(damping=0.1, friction=0.05, effort=5.0, velocity=3.0),   # plates that spin
    "swivel": Dynamics(damping=0.5, friction=0.5, effort=20.0, velocity=3.0),      # lamp heads, arms
    "telescope": Dynamics(damping=20.0, friction=5.0, effort=100.0, velocity=0.3),  # sliding poles
    "wheel": Dynamics(damping=0.01, friction=0.005, effort=5.0, velocity=20.0),
    "lid": Dynamics(damping=0.5, friction=0.2, effort=10.0, velocity=2.0),
    "default": Dynamics(damping=1.0, friction=0.2, effort=50.0, velocity=2.0),
}


def dynamics(role: str) -> Dynamics:
    return DYNAMICS.get(role, DYNAMICS["default"])


def rest_on_ground(bp: Blueprint) -> Blueprint:
    """Translate every part and joint so the lowest point at rest sits at z = 0."""
    dz = -float(bp.bounds()[0, 2])
    if abs(dz) < 1e-12:
        return bp
    offset = np.array([0.0, 0.0, dz])
    for part in bp.parts.values():
        part.pieces = [p.translated(offset) for p in part.pieces]
    bp.joints = [
        replace(j, dofs=tuple(
            Dof(d.type, tuple(np.asarray(d.origin) + offset), d.axis, d.lower, d.upper) for d in j.dofs
        ))
        for j in bp.joints
    ]
    return bp
