"""Folding chairs: the back frame that stands on its rear feet, the seat hinged at its rear, the front leg frame
hinged under the seat's front, and what they are made of (steel tube and pressed steel, or hardwood bars and
slats).

Built in world coordinates at rest, open, standing on z = 0, the sitter facing +X. The real chairs fold through a
linkage (pins and a link between the seat and the legs); here it is two limited hinges that stay consistent: the
seat turns up about its rear edge (the hinge across the chair at the back posts) and carries the front leg frame,
hinged under its front edge, whose turn is coupled to the seat's (``Layout.couple``) so that the legs stay
upright as they rise and fold in against the back frame.

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
SEAT_FOLDS = math.radians(85)  # the seat stands up against the back
LEGS_RAKE = 0.012  # m, the front feet behind the legs' hinge
GAP = 0.004  # m, between moving frames and what they pass
SLATS = {"seat": (4, 6), "back": (2, 3)}  # slats of a wooden chair's seat and back (product photos)
STEEL_SHEET = 0.0009  # m, a pressed-steel seat pan or back panel (20 ga)


@dataclass(frozen=True)
class Chair:
    """Where a chair's parts go: the design, seat height ``hs``, half width ``hw`` (to the frames' centre
    lines), seat depth ``sd``, back top ``ht``, the back posts' foot ``xr`` and top ``xt``, the bar sizes."""

    design: str
    hs: float
    hw: float
    sd: float
    ht: float
    xr: float
    xt: float
    bar: tuple[float, float]

    @property
    def metal(self) -> bool:
        """A steel-tube frame (the metal and the padded chair)."""
        return self.design != "wooden"

    def post_x(self, z: float) -> float:
        """The back posts' centre line at height ``z``."""
        return self.xr + (self.xt - self.xr) * z / self.ht

    @property
    def half_bar(self) -> float:
        """Half the bars' size across the chair (Y)."""
        return self.bar[0] if self.metal else self.bar[1] / 2


def chair(design: str, t: float, u: float) -> Chair:
    """The chair of ``design`` at ``t`` of its size ranges, its back ``u`` of its height range."""
    d = DESIGNS[design]

    def at(r, f):
        return r[0] + f * (r[1] - r[0])

    hs, width, sd, ht = at(d.seat, t), at(d.width, t), at(d.depth, t), at(d.top, u)
    xr, xt = -0.5 * sd, -0.58 * sd  # the back posts lean back ~5 degrees from their feet to the top
    return Chair(design, hs, width / 2, sd, ht, xr, xt, d.bar)


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
    """The back posts from the rear feet to the top, the back panel (or slats) between them, a stretcher
    across above the feet, the feet caps."""
    pieces = []
    for y in (-c.hw, c.hw):
        pieces.append(bar((c.xr, y, 0.012), (c.xt, y, c.ht), c, slot))
        pieces.append(_foot(c.xr, y, foot_slot, c))
    zs = 0.12
    pieces.append(bar((c.post_x(zs), -c.hw + c.half_bar, zs), (c.post_x(zs), c.hw - c.half_bar, zs), c, slot))
    pieces += _back(c, panel_slot)
    return pieces


def _foot(x: float, y: float, slot: str, c: Chair) -> g.Piece:
    r = c.bar[0] + 0.002 if c.metal else 0.5 * max(c.bar) + 0.002
    return g.cylinder((x, y, 0.0), (x, y, 0.014), r, slot, None)


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


def front_legs(c: Chair, slot: str, foot_slot: str) -> list[g.Piece]:
    """The front leg frame, inside the back posts: two legs from under the seat's front down to the front feet
    (splayed a little forward), a rail across under the seat's front (the seat rests on it) and a stretcher
    above the feet."""
    hw = c.hw - 2 * c.half_bar - GAP
    xt, zt = legs_top(c)
    xf = xt - LEGS_RAKE  # the feet a little behind the hinge: the legs hang against their rest stop
    pieces = []
    for y in (-hw, hw):
        pieces.append(bar((xt, y, zt), (xf, y, 0.012), c, slot))
        pieces.append(_foot(xf, y, foot_slot, c))
    for z in (0.12, zt):
        x = xt + (xf - xt) * (zt - z) / zt
        pieces.append(bar((x, -hw + c.half_bar, z), (x, hw - c.half_bar, z), c, slot))
    return pieces


def legs_top(c: Chair) -> tuple[float, float]:
    """Where the front legs' rail runs under the seat's front: x, z of its centre."""
    return seat_x(c)[1] - 0.03, seat_z(c) - 0.4 * max(c.bar) - 0.006  # the bars' corners turn clear of the seat


def legs_hinge(c: Chair) -> Frame:
    """The front legs' hinge on the seat's front (their rail): a positive turn swings their feet back as much
    as the seat lifts its front, so they stay upright while the seat carries them up against the back."""
    xt, zt = legs_top(c)
    return Frame.at((xt, 0.0, zt), z=(0, 1, 0), x=(1, 0, 0))


def seat_x(c: Chair) -> tuple[float, float]:
    x0 = c.post_x(c.hs) + c.half_bar + GAP
    return x0, x0 + c.sd


def seat_z(c: Chair) -> float:
    """The underside of the seat's rails."""
    return c.hs - (0.02 if c.metal else 0.04)


def seat_hinge(c: Chair) -> Frame:
    """The seat's hinge at its rear edge's underside, across the chair; a positive turn lifts the seat's
    front."""
    return Frame.at((seat_x(c)[0], 0.0, seat_z(c)), z=(0, -1, 0), x=(1, 0, 0))


PAD = 0.025  # m, a padded chair's foam pad (1 in)


def pads(c: Chair, slot: str) -> tuple[list[g.Piece], list[g.Piece]]:
    """A padded chair's vinyl-covered foam pads: on the seat pan, and on the front of the back panel."""
    x0, x1 = seat_x(c)
    hw = c.hw - 2 * c.half_bar - GAP
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
    rails; it lies on the front legs' rail."""
    x0, x1 = seat_x(c)
    hw = c.hw - 2 * c.half_bar - GAP
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
