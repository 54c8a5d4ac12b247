"""Folding chairs: the side frames that run from the front feet up into the back (one bent tube or bar each
side), the seat hinged to them at its rear, the rear leg frame hung under the seat and crossing the front legs
in an X, and what they are made of (steel tube and pressed steel, or hardwood bars and slats).

Built in world coordinates at rest, open, standing on z = 0, the sitter facing +X. As in the real chairs, the
back posts and the front legs are one part (the body): each side member rises from its front foot, raked
forward, bends under the seat's rear and leans back up into the back. The rear legs cross the front legs under
the seat and carry its middle on their top rail. Folding is one motion: lifting the seat's front turns it about
its rear edge until it stands against the back, in front of the back panel (the hinge is the seat's top rear
edge, ahead of the back's face, so the folded seat never enters it); the rear legs, hinged under the seat, turn
back against the seat's turn (``Layout.couple``: one DoF, as the real linkage) so that their feet swing forward
under the chair and close on the front feet, the X scissoring shut. The real chair lifts off the floor as it
folds; here the front feet stay down and the rear legs rise with the seat, never through the floor.

Designs (real product types; sizes below with their sources):

* ``metal``: a steel folding chair, 22 mm tube, a pressed-steel seat and a curved steel back panel (Cosco
  all-steel folding chair, Lifetime 42804, Samsonite 2200 series);
* ``padded``: a steel folding chair with vinyl-covered foam pads on its seat and back (Flash Furniture
  Hercules padded, Cosco padded folding chairs);
* ``wooden``: a hardwood slatted folding chair, 30 x 20 mm bars, slats across the seat and the back (IKEA
  Nisse-style beech chairs, Flash Furniture Hercules wood folding chair, Gaudi-style cafe chairs).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.frames import Frame


@dataclass(frozen=True)
class Design:
    """A design's seat height, width, depth and back-top height ranges (m), its bar (tube radius or bar
    width x depth, m)."""

    seat: tuple[float, float]
    width: tuple[float, float]
    depth: tuple[float, float]
    top: tuple[float, float]
    bar: tuple[float, float]


# Listings (inches converted): Cosco all-steel folding chair 17.75 W x 18.25 D x 30.5 H in, seat 17.5 in high,
# 4.5 kg; Lifetime 42804 18.5 x 20 x 31.5 in, 3.9 kg; Samsonite 2200 18 in seat, 4.1 kg. Flash Furniture Hercules
# wood folding chair 17.5 W x 18.25 D x 31.25 H in, seat 17.5 in, 3.6 kg; Flash Furniture Hercules padded
# folding chair (1 in vinyl-covered foam on seat and back, 1 in tube) 18 W x 20 D x 33 H in, 5.4 kg; IKEA-style
# beech slatted chairs 0.43-0.46 m seat height, 0.41-0.44 m wide, 3.5-5 kg.
DESIGNS = {
    "metal": Design((0.43, 0.46), (0.40, 0.46), (0.36, 0.41), (0.76, 0.82), (0.011, 0.011)),
    "padded": Design((0.44, 0.47), (0.42, 0.47), (0.38, 0.42), (0.78, 0.84), (0.0125, 0.0125)),
    "wooden": Design((0.43, 0.46), (0.41, 0.45), (0.36, 0.40), (0.78, 0.84), (0.03, 0.02)),
}
# Side profile, in seat depths from the seat's middle (Cosco / Lifetime side views: the front feet under the
# seat's front half, the rear feet behind the back, the back leaning back ~9 degrees, the X under the seat).
KNEE = -0.45  # the side members' bend, under the seat's rear
FRONT_FOOT = 0.55  # ahead of the bend
BACK_LEAN = 0.16  # the back's top behind the bend
REAR_FOOT = -0.30  # behind the bend
REAR_TOP = 0.6  # the rear legs' top rail under the seat, from its rear edge
GAP = 0.004  # m, between moving frames and what they pass
SLATS = {"seat": (4, 6), "back": (2, 3)}  # slats of a wooden chair's seat and back (product photos)
STEEL_SHEET = 0.0009  # m, a pressed-steel seat pan or back panel (20 ga)
PAD = 0.025  # m, a padded chair's foam pad (1 in)
BACK_FACE = {"metal": 0.002, "padded": 0.0155 + PAD / 2, "wooden": 0.006}  # the back's front ahead of its posts


@dataclass(frozen=True)
class Chair:
    """Where a chair's parts go: the design, seat height ``hs``, half width ``hw`` (to the side members' centre
    lines), seat depth ``sd``, back top ``ht``, the side members' bend ``xk``, ``zk``, the back's top ``xt``,
    the front feet ``xf`` and the rear feet ``xb``, the bar sizes."""

    design: str
    hs: float
    hw: float
    sd: float
    ht: float
    xk: float
    zk: float
    xt: float
    xf: float
    xb: float
    bar: tuple[float, float]

    @property
    def metal(self) -> bool:
        """A steel-tube frame (the metal and the padded chair)."""
        return self.design != "wooden"

    def post_x(self, z: float) -> float:
        """The back posts' centre line at height ``z`` (from the bend up)."""
        return self.xk + (self.xt - self.xk) * (z - self.zk) / (self.ht - self.zk)

    def front_x(self, z: float) -> float:
        """The front legs' centre line at height ``z`` (from the floor to the bend)."""
        return self.xf + (self.xk - self.xf) * z / self.zk

    @property
    def lean(self) -> float:
        """The back's lean from the vertical (rad)."""
        return math.atan2(self.xk - self.xt, self.ht - self.zk)

    @property
    def half_bar(self) -> float:
        """Half the bars' size across the chair (Y)."""
        return self.bar[0] if self.metal else self.bar[1] / 2

    @property
    def rear_hw(self) -> float:
        """The rear legs' half width: just outside the side members and their feet caps."""
        return self.hw + 2 * self.foot_r + GAP

    @property
    def foot_r(self) -> float:
        """The feet caps' radius."""
        return self.bar[0] + 0.002 if self.metal else 0.5 * max(self.bar) + 0.002

    @property
    def seat_hw(self) -> float:
        """The seat's half width: just inside the side members."""
        return self.hw - 2 * self.half_bar - GAP


def chair(design: str, t: float, u: float) -> Chair:
    """The chair of ``design`` at ``t`` of its size ranges, its back ``u`` of its height range."""
    d = DESIGNS[design]

    def at(r, f):
        return r[0] + f * (r[1] - r[0])

    hs, width, sd, ht = at(d.seat, t), at(d.width, t), at(d.depth, t), at(d.top, u)
    xk = KNEE * sd
    zk = hs - (0.02 if design != "wooden" else 0.04) - 0.03  # under the seat's rails
    return Chair(design, hs, width / 2, sd, ht, xk, zk, xk - BACK_LEAN * sd, xk + FRONT_FOOT * sd,
                 xk + REAR_FOOT * sd, d.bar)


def bar(p0, p1, c: Chair, slot: str) -> g.Piece:
    """A frame member from ``p0`` to ``p1``: a steel tube (solid to the simulator, massed as 1.2 mm wall) or a
    rectangular hardwood bar, its wide side facing along X."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    if c.metal:
        return g.cylinder(p0, p1, c.bar[0], slot, None).replace(wall=0.0012)
    length = float(np.linalg.norm(p1 - p0))
    axis = Frame.at(tuple((p0 + p1) / 2), z=tuple((p1 - p0) / length), x=(1, 0, 0))
    return g.box((c.bar[0], c.bar[1], length), (0, 0, 0), slot, bevel=0.003).transformed(axis.matrix)


def back_frame(c: Chair, slot: str, panel_slot: str, foot_slot: str) -> list[g.Piece]:
    """The side members from the front feet up through the bend into the back posts, the back panel (or slats)
    between the posts, a stretcher across the front legs above the feet, the feet caps."""
    pieces = []
    for y in (-c.hw, c.hw):
        knee = (c.xk, y, c.zk)
        pieces.append(bar((c.xf, y, 0.012), knee, c, slot))
        pieces.append(bar(knee, (c.xt, y, c.ht), c, slot))
        if c.metal:  # the tube's bend
            pieces.append(g.sphere(knee, c.bar[0], slot).replace(wall=0.0012))
        pieces.append(_foot(c.xf, y, foot_slot, c))
    zs = 0.12
    pieces.append(bar((c.front_x(zs), -c.hw + c.half_bar, zs), (c.front_x(zs), c.hw - c.half_bar, zs), c, slot))
    pieces += _back(c, panel_slot)
    return pieces


def _foot(x: float, y: float, slot: str, c: Chair) -> g.Piece:
    return g.cylinder((x, y, 0.0), (x, y, 0.014), c.foot_r, slot, None)


def _back(c: Chair, slot: str) -> list[g.Piece]:
    """A curved pressed-steel back panel across the posts' upper part, or 2-3 wooden slats."""
    z1 = c.ht - 0.02
    z0 = z1 - (0.2 if c.metal else 0.26)
    inner = c.hw - c.half_bar
    if c.metal:  # one pressed sheet: the panel's two faces are its two sides
        return [_curved_panel(c, z0, z1, inner + 0.5 * c.half_bar, 0.03, slot).replace(sheet=STEEL_SHEET / 2)]
    n = 3 if c.ht > 0.81 else 2
    pitch = (z1 - z0) / n
    return [_curved_panel(c, z0 + k * pitch + 0.01, z0 + (k + 1) * pitch - 0.01, inner, 0.015, slot, t=0.012)
            for k in range(n)]


def _curved_panel(c: Chair, z0: float, z1: float, half: float, bow: float, slot: str, t: float = 0.004
                  ) -> g.Piece:
    """A panel between the back posts from ``z0`` to ``z1``, bowed ``bow`` back at its middle (a body-shaped
    back): a band of convex strips."""
    ys = np.linspace(-half, half, 9)
    pieces = []
    for y0, y1 in zip(ys[:-1], ys[1:]):
        pts = []
        for y in (y0, y1):
            dx = -bow * (1 - (y / half) ** 2)
            for z in (z0, z1):
                x = c.post_x(z) + dx
                pts += [(x - t / 2, y, z), (x + t / 2, y, z)]
        pieces.append(_hull_piece(np.asarray(pts), slot))
    return _joined(pieces, slot)


def _hull_piece(pts: np.ndarray, slot: str) -> g.Piece:
    import trimesh

    mesh = trimesh.convex.convex_hull(pts)
    return g.Piece(np.asarray(mesh.vertices), np.asarray(mesh.faces), slot, [np.asarray(mesh.vertices)])


def _joined(pieces: list[g.Piece], slot: str) -> g.Piece:
    verts, faces, convex, k = [], [], [], 0
    for p in pieces:
        verts.append(p.vertices)
        faces.append(p.faces + k)
        convex += list(p.convex)
        k += len(p.vertices)
    return g.Piece(np.vstack(verts), np.vstack(faces), slot, convex)


def seat_z(c: Chair) -> float:
    """The underside of the seat's rails."""
    return c.hs - (0.02 if c.metal else 0.04)


def seat_top(c: Chair) -> float:
    """The top of the seat (of its pad on a padded chair)."""
    return c.hs + (PAD if c.design == "padded" else 0.0)


def seat_x(c: Chair) -> tuple[float, float]:
    """The seat's rear and front edges: the rear just ahead of the back's face, so that the seat, turned up
    about its top rear edge, stands clear in front of the back."""
    top = seat_top(c)
    x0 = c.post_x(top) + (BACK_FACE[c.design] + GAP) / math.cos(c.lean)
    return x0, x0 + c.sd


def seat_folds(c: Chair) -> float:
    """How far the seat turns up: until it stands parallel to the back (rad)."""
    return math.pi / 2 - c.lean


def seat_hinge(c: Chair) -> Frame:
    """The seat's hinge along its top rear edge, across the chair; a positive turn lifts the seat's front."""
    return Frame.at((seat_x(c)[0], 0.0, seat_top(c)), z=(0, -1, 0), x=(1, 0, 0))


def legs_top(c: Chair) -> tuple[float, float]:
    """Where the rear legs' top rail runs under the seat: x, z of its centre (the legs' hinge)."""
    return seat_x(c)[0] + REAR_TOP * c.sd, seat_z(c) - c.half_bar - GAP


def legs_hinge(c: Chair) -> Frame:
    """The rear legs' hinge on their top rail under the seat: a positive turn swings their feet back, against
    the seat's lift, so that they close forward on the front legs as the seat folds."""
    xq, zq = legs_top(c)
    return Frame.at((xq, 0.0, zq), z=(0, 1, 0), x=(1, 0, 0))


def _turn(p, centre, a: float) -> np.ndarray:
    """``p`` (x, z) turned by ``a`` about ``centre`` in the side view, +X towards +Z."""
    d = np.subtract(p, centre)
    ca, sa = math.cos(a), math.sin(a)
    return np.array([centre[0] + ca * d[0] - sa * d[1], centre[1] + sa * d[0] + ca * d[1]])


def rear_foot(c: Chair, s: float, ratio: float) -> np.ndarray:
    """The rear feet (x, z) with the seat turned up ``s`` and the rear legs back ``ratio * s``."""
    hinge = (seat_x(c)[0], seat_top(c))
    return _turn(_turn((c.xb, 0.0), legs_top(c), -ratio * s), hinge, s)


def legs_ratio(c: Chair) -> float:
    """The rear legs' turn per unit of the seat's: the one that brings the rear feet onto the front legs when
    the seat is folded (the X shut), found by bisection (the feet move back as the ratio grows)."""
    lo, hi = 0.0, 2.0
    for _ in range(50):
        mid = (lo + hi) / 2
        x, z = rear_foot(c, seat_folds(c), mid)
        lo, hi = (mid, hi) if x > c.front_x(z) else (lo, mid)
    return (lo + hi) / 2


def rear_legs(c: Chair, slot: str, foot_slot: str) -> list[g.Piece]:
    """The rear leg frame, just outside the side members: two legs from the top rail under the seat back down
    to the rear feet (crossing the front legs), the top rail the seat rests on and a stretcher across just
    above the X (below it the stretcher would meet the front legs as the X shuts)."""
    hw = c.rear_hw
    xq, zq = legs_top(c)
    pieces = []
    for y in (-hw, hw):
        pieces.append(bar((xq, y, zq), (c.xb, y, 0.012), c, slot))
        pieces.append(_foot(c.xb, y, foot_slot, c))
    pieces.append(bar((xq, -hw, zq), (xq, hw, zq), c, slot))
    if c.metal:  # the tube bent round from the rail into the legs
        pieces += [g.sphere((xq, y, zq), c.bar[0], slot).replace(wall=0.0012) for y in (-hw, hw)]
    zx = (c.xb - c.xf) / ((c.xk - c.xf) / c.zk - (xq - c.xb) / zq)  # where the legs cross
    zs = zx + STRETCHER * (zq - zx)
    x = c.xb + (xq - c.xb) * zs / zq
    pieces.append(bar((x, -hw + c.half_bar, zs), (x, hw - c.half_bar, zs), c, slot))
    return pieces


STRETCHER = 0.3  # the rear legs' stretcher, from the X up to the top rail: it stays ahead of the front legs


def pads(c: Chair, slot: str) -> tuple[list[g.Piece], list[g.Piece]]:
    """A padded chair's vinyl-covered foam pads: on the seat pan, and on the front of the back panel."""
    x0, x1 = seat_x(c)
    hw = c.seat_hw
    z = seat_z(c) + 0.02
    seat_pad = g.box_between((x0 + 0.004, -hw + 0.01, z), (x1 - 0.004, hw - 0.01, z + PAD), slot, bevel=0.01)
    z1 = c.ht - 0.03
    z0 = z1 - 0.18
    half = c.hw - 2 * c.half_bar
    back = [_curved_panel(c, z0, z1, half, 0.03, slot, t=PAD).transformed(
        Frame.at((PAD / 2 + 0.003, 0, 0)).matrix)]
    return [seat_pad], back


def seat(c: Chair, slot: str) -> list[g.Piece]:
    """The seat: a pressed-steel pan with a rolled front edge over two side rails, or slats across two wooden
    rails; it lies on the rear legs' top rail."""
    x0, x1 = seat_x(c)
    hw = c.seat_hw
    z = seat_z(c)
    if c.metal:
        pan = g.box_between((x0, -hw + 0.005, z + 0.012), (x1, hw - 0.005, z + 0.02), slot, bevel=0.003)
        roll = g.cylinder((x1 - 0.008, -hw + 0.005, z + 0.012), (x1 - 0.008, hw - 0.005, z + 0.012), 0.008, slot)
        rails = [g.box_between((x0, y - 0.006, z), (x1 - 0.02, y + 0.006, z + 0.012), slot) for y in (-hw + 0.02,
                                                                                                      hw - 0.02)]
        # one pressed sheet: the pan's two faces are its two sides; the rails are folded channel of it
        return [pan.replace(sheet=STEEL_SHEET / 2), roll.replace(wall=STEEL_SHEET)] + [r.replace(sheet=STEEL_SHEET)
                                                                                    for r in rails]
    rails = [g.box_between((x0, y - 0.01, z), (x1, y + 0.01, z + 0.025), slot, bevel=0.003) for y in (-hw + 0.012,
                                                                                                     hw - 0.012)]
    n = 5 if c.sd > 0.38 else 4
    width = c.sd / n - 0.008
    slats = [g.box_between((x0 + k * c.sd / n + 0.004, -hw, z + 0.025), (x0 + k * c.sd / n + 0.004 + width, hw,
                                                                        z + 0.04), slot, bevel=0.003)
             for k in range(n)]
    return rails + slats
