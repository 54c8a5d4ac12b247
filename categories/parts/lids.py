"""The lift-off lid family: every closure that rests on a seat and lifts off it.

A lid of the family is an :class:`~infmob_usd.assembly.Assembly` whose ``seat`` anchor is where it rests
(its z the way it lifts) and whose ``top`` anchor is its upper face: the vessel closures
(:func:`.vessel.lift_off_lid`, :func:`.vessel.stopper`, :func:`.vessel.screw_cap`, :func:`.vessel.jar_lid`,
:func:`.vessel.dome_lid` ...) and a toilet cistern's lid (:func:`.sanitary.cistern_lid`). A category attaches
the lid's ``seat`` to its carrier's ``lid_seat`` and joins them with :func:`seat_joint`. Every lid of the family
knows its edge (:func:`rimmed`): where a hand takes a lid that has no knob, and a second hold beside its knob.
"""

from __future__ import annotations

from infmob_usd import joints as J
from infmob_usd.assembly import Assembly, Placed, SubPart
from infmob_usd.interaction import rim_grasp


def rimmed(lid: Assembly, part: str | None = None) -> Assembly:
    """``lid`` (an assembly with a ``seat`` anchor) whose lid part (``part``, default the root) carries the grasp
    on its edge: pinched along the seat's z (the way it lifts) from the side, else across its rim from above
    (:func:`infmob_usd.interaction.rim_grasp`). Unchanged if no pinch there fits a hand."""
    name = part or lid.root
    sub = lid.parts[name]
    grasp = rim_grasp(sub.pieces, lid.anchor("seat").z)
    if grasp is None:
        return lid
    parts = dict(lid.parts)
    parts[name] = SubPart(sub.label, (sub.pieces[0].with_grasps(grasp),) + sub.pieces[1:])
    return Assembly(parts, lid.joints, lid.anchors, lid.supports, lid.retrieved)


def seat_joint(parent: str, closure: Placed, lift: float, turns: bool = True) -> J.JointSpec:
    """A closure on its seat: lifts ``0..lift`` along the seat's z (its lower stop: gravity holds it
    down), turning freely about it unless ``turns`` is false. Its role is ``lift_off``: the core caps the
    lift at a hand's (:data:`infmob_usd.lift_off.LIFT_OFF`)."""
    s = closure.anchor("seat")
    if turns:
        return J.continuous_prismatic(parent, closure.root, tuple(s.origin), tuple(s.z), (0.0, lift), role="lift_off")
    return J.prismatic(parent, closure.root, tuple(s.origin), tuple(s.z), 0.0, lift, role="lift_off")
