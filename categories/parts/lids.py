"""The lift-off lid family: every closure that rests on a seat and lifts off it.

A lid of the family is an :class:`~infmob_usd.assembly.Assembly` whose ``seat`` anchor is where it rests
(its z the way it lifts) and whose ``top`` anchor is its upper face: the vessel closures
(:func:`.vessel.lift_off_lid`, :func:`.vessel.stopper`, :func:`.vessel.screw_cap`, :func:`.vessel.jar_lid`,
:func:`.vessel.dome_lid` ...) and a toilet cistern's lid (:func:`.sanitary.cistern_lid`). A category attaches
the lid's ``seat`` to its carrier's ``lid_seat`` and joins them with :func:`seat_joint`.
"""

from __future__ import annotations

from infmob_usd import joints as J
from infmob_usd.assembly import Placed


def seat_joint(parent: str, closure: Placed, lift: float, turns: bool = True) -> J.JointSpec:
    """A closure on its seat: lifts ``0..lift`` along the seat's z (its lower stop: gravity holds it
    down), turning freely about it unless ``turns`` is false. Its role is ``lift_off``: the core caps the
    lift at a hand's (:data:`infmob_usd.lift_off.LIFT_OFF`)."""
    s = closure.anchor("seat")
    if turns:
        return J.continuous_prismatic(parent, closure.root, tuple(s.origin), tuple(s.z), (0.0, lift), role="lift_off")
    return J.prismatic(parent, closure.root, tuple(s.origin), tuple(s.z), 0.0, lift, role="lift_off")
