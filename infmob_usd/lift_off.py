"""Lift-off parts: a part that rests on a seat and comes off it in the hand (a lid, a stopper, a vase's
liner, a cistern lid, a pull-off pan handle, a mug on a peg, a bin on its hooks).

A joint models such a part only while its seat still guides it: the travel of a lift-off slide is the
lift a hand gives before the part is free, not a slide through the air. A category declares the joint
with role ``lift_off`` and the most its mechanism allows, and where it knows it, how deep the part
engages its seat (:attr:`~infmob_usd.joints.JointSpec.engagement`: a mug on a 55 mm peg); :func:`capped`
shortens every slide of such a joint to :func:`lift` (the engagement and :data:`FREE`, or
:data:`LIFT_OFF`), and :meth:`~infmob_usd.category.Category.build` applies it to each blueprint, so every
category inherits the rule.
"""

from __future__ import annotations

from dataclasses import replace

from .joints import JointSpec

ROLE = "lift_off"

LIFT_OFF = 0.03
"""m: a hand's lift of a lift-off part. Seats guide a part over 10-20 mm (a cistern lid's locating lip
15 mm, a pot lid's flange and a stopper's plug 10-15 mm, a pan handle's clamp on its 14 mm lug); 30 mm
clears the deepest with 1 cm to spare, where the part is free in the hand and a joint no longer models it."""

FREE = 0.005
"""m: a part with a known seat depth is lifted this far past it: free of what locates it, and no further."""


def lift(engagement: float | None = None) -> float:
    """The travel of a lift-off slide: ``engagement`` (m, how far the seat guides the part) and :data:`FREE`,
    or :data:`LIFT_OFF` when the seat's depth is not known."""
    return LIFT_OFF if engagement is None else engagement + FREE


def capped_joint(spec: JointSpec) -> JointSpec:
    """``spec`` with each slide of a lift-off joint at most :func:`lift` of its engagement long (itself if
    none is longer)."""
    cap = lift(spec.engagement)
    if spec.role != ROLE or not any(d.type == "prismatic" and d.upper > cap for d in spec.dofs):
        return spec
    return replace(spec, dofs=tuple(replace(d, upper=cap) if d.type == "prismatic" and d.upper > cap
                                    else d for d in spec.dofs))


def capped(bp):
    """The blueprint ``bp`` with its lift-off slides capped (in place; returned for chaining)."""
    bp.joints[:] = [capped_joint(j) for j in bp.joints]
    return bp
