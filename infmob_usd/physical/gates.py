"""The ``requires_open`` gates of a joint as the physics passes read them: a joint moves only with the joints of
its gate chain fully open (:func:`~infmob_usd.joints.gate_chain`), so where those carry it (a flap on an
oven door, a divider in a suitcase lid) its limits and its rest are judged with them open."""

from __future__ import annotations

import numpy as np

from ..blueprint import descendants
from ..joints import gate_chain
from ..rotation import axis_angle


def gate_names(joint, groups) -> list[str]:
    """The joints that must be open before ``joint`` moves: those of its ``requires_open`` part, then those
    its part's joints require open in turn (the tines on a rack behind a dishwasher's door). ``groups``:
    part -> its movable joints."""
    requires = [(part, g.requires_open) for part, gate in groups.items() for g in gate]
    return [g.name for part in gate_chain(joint.requires_open, requires) for g in groups.get(part, [])]


def carrying_gates(joints) -> dict[str, list]:
    """Joint name -> the joints of its gate chain that carry it (its ancestors), innermost first, for every
    movable joint that has one; a gate beside it (a dishwasher's door beside its racks) moves none of what it
    moves and is left out."""
    movable = [j for j in joints if j.movable]
    groups: dict[str, list] = {}
    for j in movable:
        groups.setdefault(j.group, []).append(j)
    by_name = {j.name: j for j in movable}
    out = {}
    for j in movable:
        if not j.requires_open:
            continue
        gates = [by_name[n] for n in gate_names(j, groups)]
        carried = [(len(descendants(joints, g.child)), k, g) for k, g in enumerate(gates)
                   if j.child in descendants(joints, g.child)]
        if carried:
            out[j.name] = [g for _, _, g in sorted(carried, key=lambda c: (c[0], c[1]))]
    return out


def open_motion(gates) -> tuple[np.ndarray, np.ndarray]:
    """``(R, t)``: the rigid motion (world, from rest) that ``gates`` (innermost first, each at its upper
    limit) give what they carry: a world point ``p`` at rest goes to ``R @ p + t``."""
    rot, shift = np.eye(3), np.zeros(3)
    for g in gates:
        if g.type not in ("prismatic", "revolute"):
            continue  # a knob turning all round opens nothing
        axis = np.asarray(g.axis, float)
        if g.type == "prismatic":
            r, d = np.eye(3), float(g.upper) * axis / np.linalg.norm(axis)
        else:
            pivot = np.asarray(g.origin, float)
            r = axis_angle(axis, float(g.upper))
            d = pivot - r @ pivot
        rot, shift = r @ rot, r @ shift + d
    return rot, shift
