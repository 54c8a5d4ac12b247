"""Small hardware: handles (bar, bow, knob, edge pull), knobs, push buttons, rocker switches, hinge knuckles and barrel
hinges.

Every builder here returns an :class:`~infmob_usd.assembly.Assembly` whose
anchor ``"mount"`` is the mounting surface (z out of it) and whose support
points are where it touches that surface. Bars run along local x.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.assembly import Assembly, SubPart
from infmob_usd.frames import IDENTITY, Frame
from infmob_usd.grasps import Grasp


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
    bar = g.cylinder((-length / 2, 0, z_bar), (length / 2, 0, z_bar), size.bar_radius, material, 16, name="handle")
    pieces.append(bar.with_grasps(bar_grasp(length, z_bar + size.bar_radius, size.bar_radius)))
    return Assembly.single("handle", pieces, {"mount": IDENTITY},
                           {"mount_a": (ends[0], 0, 0), "mount_b": (ends[1], 0, 0)})


def bar_grasp(length: float, top: float, radius: float, width: float | None = None,
              handle_class: str = "line_fixed_handle") -> Grasp:
    """The grasp of a handle along local x standing ``top`` off its face (local z out of it): the middle of
    its top, reached straight at the face, fingers closing across it (local y) ``radius`` deep, opening its
    ``width`` (default the bar's diameter). Its box spans the handle from the face to its top."""
    width = 2 * radius if width is None else width
    return Grasp.make((0, 0, top), (0, 0, -1), (0, 1, 0), width, radius, handle_class,
                      ((0, 0, top / 2), (length, max(width, 2 * radius), top), IDENTITY.rotation))


def knob_handle(radius: float, depth: float, material: str) -> Assembly:
    """A round cabinet knob: a stem and a wider cap (support point ``stem``); grasped across its cap."""
    cap = g.cylinder((0, 0, depth * 0.55), (0, 0, depth), radius, material, 24, name="handle")
    grasp = Grasp.make((0, 0, depth), (0, 0, -1), (0, 1, 0), 2 * radius, min(0.45 * depth / 2, radius),
                       "round_fixed_handle", ((0, 0, depth / 2), (2 * radius, 2 * radius, depth), IDENTITY.rotation))
    pieces = [g.cylinder((0, 0, 0), (0, 0, depth * 0.6), radius * 0.45, material, 16, name="handle"),
              cap.with_grasps(grasp)]
    return Assembly.single("handle", pieces, {"mount": IDENTITY}, {"stem": (0, 0, 0)})


def edge_pull(length: float, material: str, depth: float = 0.018, lip: float = 0.012) -> Assembly:
    """A low-profile edge pull along local x: a flat lip standing off the face."""
    piece = g.box_between((-length / 2, -lip / 2, 0), (length / 2, lip / 2, depth), material, name="handle")
    piece = piece.with_grasps(bar_grasp(length, depth, min(depth / 2, 0.01), width=lip))
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
    piece = g.tube(path, wire, material, 12, name="handle").with_grasps(bar_grasp(length + 2 * wire, projection, wire))
    return Assembly.single("handle", [piece], {"mount": IDENTITY},
                           {"mount_a": (-half, 0, 0), "mount_b": (half, 0, 0)})


HANDLES = {"bar": bar_handle, "edge": edge_pull, "bow": bow_handle}
"""Handles that run along local x, by style name: ``HANDLES[style](length, material)``."""

BAR_SPAN = (0.128, 0.32)
"""m, the bar pulls cabinet makers fit: 128 mm hole centres up to 320 mm (Häfele / Blum catalogues)."""
KNOB = (0.015, 0.025)
"""m, a cabinet knob's cap radius and projection: a 30 mm knob 25 mm proud."""


def handle(style: str, length: float, material: str = "handle") -> Assembly:
    """A furniture handle of ``style``: ``bar`` (``length`` clamped to :data:`BAR_SPAN`), ``knob``
    (:data:`KNOB`, ``length`` unused), else an edge pull ``length`` long; anchor ``mount``, bars along x."""
    if style == "bar":
        return bar_handle(min(max(length, BAR_SPAN[0]), BAR_SPAN[1]), material)
    if style == "knob":
        return knob_handle(*KNOB, material)
    return edge_pull(length, material)


def on_face(part: Assembly, at, across=(0, 1, 0)) -> list[g.Piece]:
    """The pieces of ``part`` mounted at point ``at`` of a front face (normal +X), its local x along
    ``across``: to fuse a handle into the part that carries it."""
    return list(part.attached("mount", to=Frame.at(at, z=(1, 0, 0), x=across)).pieces)


def hinge_knuckle(length: float, radius: float, material: str) -> Assembly:
    """A hinge barrel along local z, centred on the origin (anchor ``"axis"``: z along the pin)."""
    piece = g.cylinder((0, 0, -length / 2), (0, 0, length / 2), radius, material, 12, name="hinge")
    return Assembly.single("hinge", [piece], {"axis": IDENTITY, "mount": IDENTITY})


def barrel_hinge(length: float, radius: float, material: str, moving_share: float = 1 / 3, gap: float = 0.001,
                 sections: int = 16) -> tuple[list[g.Piece], list[g.Piece]]:
    """A visible barrel hinge in its pin's frame (local z along the pin, centred on the origin): three knuckles,
    the two end ones on the fixed side and the middle one (``moving_share`` of ``length``) on the moving side,
    ``gap`` apart, with the pin's domed heads proud of the ends. Decoration only: no collision (the joint is the
    core's and the knuckles turn in place about it), so a hinge can be shown where the simulator needs nothing.
    Returns (fixed pieces, moving pieces), both in the pin frame: place each with the joint's frame at rest,
    the moving ones on the part that turns."""
    h, m = length / 2, moving_share * length / 2

    def knuckle(z0: float, z1: float, r: float = radius) -> g.Piece:
        return g.cylinder((0, 0, z0), (0, 0, z1), r, material, sections, name="hinge").replace(convex=())

    head = 0.25 * radius  # the pin's heads, proud of each end
    fixed = [knuckle(-h, -m - gap), knuckle(m + gap, h), knuckle(-h - head, -h, 0.7 * radius),
             knuckle(h, h + head, 0.7 * radius)]
    return fixed, [knuckle(-m, m)]


def leaf(lo, hi, material: str, bevel: float = 0.0) -> g.Piece:
    """A hinge leaf or arm between corners ``lo`` and ``hi`` (in the pin frame of :func:`barrel_hinge`):
    decoration, without collision, joining knuckles to what carries them."""
    return g.box_between(lo, hi, material, bevel=bevel, name="hinge_leaf").replace(convex=())


def turn_button(length: float, material: str, stem: float = 0.008, thickness: float = 0.005) -> Assembly:
    """A turn-button latch: a flat bar along local x on a short stem, turning about the stem (local z)."""
    pieces = [g.cylinder((0, 0, 0), (0, 0, stem), 0.004, material, 12, name="latch"),
              g.box_between((-0.15 * length, -0.006, stem), (0.85 * length, 0.006, stem + thickness), material,
                            name="latch")]
    return Assembly.single("latch", pieces, {"mount": IDENTITY, "pivot": IDENTITY}, {"stem": (0, 0, 0)})


ROCKER = dict(length=0.021, width=0.015, bezel_h=0.0035, rim=0.0015, paddle_t=0.0045, throw=0.2, gap=0.0006)
"""A snap-in rocker switch (the KCD1 size of appliance and lamp-base switches: bezel 21-23 x 15 mm over a
19-21 x 13-15 mm panel cut-out, blogs.lcsc.com/blog/kcd1-switches-rocker-switches-guide): bezel length and
width (m), bezel height, rim width, paddle thickness, the paddle's tilt each side of level (rad: its two
positions ~23 degrees apart) and its clearance in the bezel."""


def rocker_switch(material: str, size: dict | None = None) -> Assembly:
    """A rocker switch on a mounting surface (local z out of it): a rectangular bezel (root part
    ``bezel``, to be merged into what carries it) and a paddle (part ``rocker``, label ``switch``) that
    tilts about the bezel's short axis (local y) through its middle. At rest the paddle is tilted down at
    its +x end ("off"); its joint turns it to the other stop, 2 ``throw`` away. Anchor ``mount`` is the
    surface, support points ``corner_a`` / ``corner_b`` the bezel's diagonal corners on it."""
    d = {**ROCKER, **(size or {})}
    L, W, hb, rim, t, th, gap = (d[k] for k in ("length", "width", "bezel_h", "rim", "paddle_t", "throw", "gap"))
    half_l, half_w = L / 2, W / 2
    il, iw = half_l - rim, half_w - rim  # the opening
    bezel = [g.box_between((-half_l, -half_w, 0.0), (half_l, -iw, hb), material),
             g.box_between((-half_l, iw, 0.0), (half_l, half_w, hb), material),
             g.box_between((-half_l, -iw, 0.0), (-il, iw, hb), material),
             g.box_between((il, -iw, 0.0), (half_l, iw, hb), material)]
    # the paddle: half-length a, so that tilted by ``th`` it keeps ``gap`` from the opening's ends
    a = (il - gap - 0.5 * t * math.sin(th)) / math.cos(th)
    zp = gap + a * math.sin(th) + 0.5 * t * math.cos(th)  # its lowest corner ``gap`` off the surface
    paddle = g.box_between((-a, -(iw - gap), -t / 2), (a, iw - gap, t / 2), material, bevel=0.2 * t)
    paddle = paddle.transformed(Frame.at((0, 0, zp)).turned("y", th).matrix)  # its +x end down
    # turning about -y lifts the +x end: from "off" at rest to "on" at 2 th
    joint = J.revolute("bezel", "rocker", (0, 0, zp), (0, -1, 0), 0.0, 2 * th, role="button")
    return Assembly({"bezel": SubPart("switch_bezel", tuple(bezel)), "rocker": SubPart("switch", (paddle,))},
                    (joint,), {"mount": IDENTITY}, {"corner_a": (-half_l, -half_w, 0), "corner_b": (half_l, half_w, 0)})
