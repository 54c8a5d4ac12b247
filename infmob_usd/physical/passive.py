"""Passive joint dynamics per joint role: doors stay where they are left, knobs do not spin freely.

Units: damping is N*m*s/rad (rotations) or N*s/m (slides); friction is N*m
(rotations) or N (slides); effort likewise N*m or N; velocity rad/s or m/s.
"""

from __future__ import annotations

from dataclasses import dataclass


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
    # friction hinges and counterbalanced stands: the friction is sized on the load (effort.holding), this is its least
    "holding": Dynamics(damping=2.0, friction=0.5, effort=50.0, velocity=2.0),
    "lift_off": Dynamics(damping=0.5, friction=0.2, effort=10.0, velocity=2.0),  # as a lid: lifted by hand
    "plate": Dynamics(damping=1.0, friction=0.2, effort=50.0, velocity=2.0),       # plates in a rack
    "grate": Dynamics(damping=1.0, friction=0.2, effort=50.0, velocity=2.0),       # oven grates
    "toggle": Dynamics(damping=0.02, friction=0.01, effort=2.0, velocity=6.0),     # switch bats, rockers: as knobs
    "default": Dynamics(damping=1.0, friction=0.2, effort=50.0, velocity=2.0),
}


def dynamics(role: str) -> Dynamics:
    return DYNAMICS.get(role, DYNAMICS["default"])
