"""Small hardware: handles (bar, bow, knob, edge pull), knobs, push buttons, hinge knuckles.

Every builder here returns an :class:`~infmob_usd.assembly.Assembly` whose
anchor ``"mount"`` is the mounting surface (z out of it) and whose support
points are where it touches that surface. Bars run along local x.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import IDENTITY


@dataclass(frozen=True)
class HandleSize:
    """A handle's real-product dimensions (metres)."""

    standoff: float  # face to bar centre line minus the bar radius
    bar_radius: float
    post_radius: float
    inset: float  # post centre from the bar end


# Cabinet bar pulls: 128-160 mm centres, 10-12 mm bar, ~30-35 mm projection (Häfele / Blum catalogues).
BAR = HandleSize(standoff=0.028, bar_radius=0.006, post_radius=0.0048, inset=0.02)


def bar_handle(length: float, material: str, size: HandleSize = BAR) -> Assembly:
    """A bar pull along local x: two posts out of the face and a bar across them.

    Support points ``mount_a`` / ``mount_b`` are the posts' feet on the face.
    """
    inset = min(size.inset, 0.15 * length)
    ends = (-length / 2 + inset, length / 2 - inset)
    z_bar = size.standoff + size.bar_radius
    pieces = [g.cylinder((x, 0, 0), (x, 0, size.standoff), size.post_radius, material, 12, name="handle")
              for x in ends]
    pieces.append(g.cylinder((-length / 2, 0, z_bar), (length / 2, 0, z_bar), size.bar_radius, material, 16,
                             name="handle"))
    return Assembly.single("handle", pieces, {"mount": IDENTITY},
                           {"mount_a": (ends[0], 0, 0), "mount_b": (ends[1], 0, 0)})


def knob_handle(radius: float, depth: float, material: str) -> Assembly:
    """A round cabinet knob: a stem and a wider cap (support point ``stem``)."""
    pieces = [g.cylinder((0, 0, 0), (0, 0, depth * 0.6), radius * 0.45, material, 16, name="handle"),
              g.cylinder((0, 0, depth * 0.55), (0, 0, depth), radius, material, 24, name="handle")]
    return Assembly.single("handle", pieces, {"mount": IDENTITY}, {"stem": (0, 0, 0)})


def edge_pull(length: float, material: str, depth: float = 0.018, lip: float = 0.012) -> Assembly:
    """A low-profile edge pull along local x: a flat lip standing off the face."""
    piece = g.box_between((-length / 2, -lip / 2, 0), (length / 2, lip / 2, depth), material, name="handle")
    return Assembly.single("handle", [piece], {"mount": IDENTITY},
                           {"mount_a": (-length / 2, 0, 0), "mount_b": (length / 2, 0, 0)})


BOW_PROJECTION = 0.03
"""m, face to the top of a bow pull: 27 mm (Cosmas 4390 bow pull, 4 in long, 1-1/16 in projection:
doorcorner.com/blogs/articles-and-advice/how-to-measure-hole-spacing-on-your-cabinet-hardware) to the ~32 mm
(1.25 in) a comfortable grip wants (engineerfix.com/what-size-handle-for-kitchen-cabinets)."""

BOW_WIRE = 0.005
"""m, radius of a bow pull's round wire: 10 mm, between the 3/8 and 1/2 in rod of bent-wire pulls."""


def bow_handle(length: float, material: str, projection: float = BOW_PROJECTION, wire: float = BOW_WIRE,
               segments: int = 12) -> Assembly:
    """A bow (D) pull along local x: one round wire rising square out of the face at both screw holes
    and arching over, ``projection`` from the face to its top; ``length`` is the hole centres (96-160 mm,
    shopmeraki.co hardware measuring guide: 128 mm the common European size). Support points ``mount_a`` /
    ``mount_b`` are the wire's feet on the face, as a bar pull's."""
    foot = 0.004  # a short straight rise out of each hole before the arch
    half, rise = length / 2, projection - wire - foot
    t = [math.pi * k / segments for k in range(segments + 1)]
    # an elliptic arch: square to the face at the feet (its tangent there is along z)
    path = [(-half * math.cos(a), 0.0, rise * math.sin(a)) for a in t]
    path = [(-half, 0.0, 0.0)] + [(x, y, z + foot) for x, y, z in path] + [(half, 0.0, 0.0)]
    piece = g.tube(path, wire, material, 12, name="handle")
    return Assembly.single("handle", [piece], {"mount": IDENTITY},
                           {"mount_a": (-half, 0, 0), "mount_b": (half, 0, 0)})


HANDLES = {"bar": bar_handle, "edge": edge_pull, "bow": bow_handle}
"""Handles that run along local x, by style name: ``HANDLES[style](length, material)``."""


def hinge_knuckle(length: float, radius: float, material: str) -> Assembly:
    """A hinge barrel along local z, centred on the origin (anchor ``"axis"``: z along the pin)."""
    piece = g.cylinder((0, 0, -length / 2), (0, 0, length / 2), radius, material, 12, name="hinge")
    return Assembly.single("hinge", [piece], {"axis": IDENTITY, "mount": IDENTITY})


def turn_button(length: float, material: str, stem: float = 0.008, thickness: float = 0.005) -> Assembly:
    """A turn-button latch: a flat bar along local x on a short stem, turning about the stem (local z)."""
    pieces = [g.cylinder((0, 0, 0), (0, 0, stem), 0.004, material, 12, name="latch"),
              g.box_between((-0.15 * length, -0.006, stem), (0.85 * length, 0.006, stem + thickness), material,
                            name="latch")]
    return Assembly.single("latch", pieces, {"mount": IDENTITY, "pivot": IDENTITY}, {"stem": (0, 0, 0)})
