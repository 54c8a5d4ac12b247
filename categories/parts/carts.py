"""Carts: a utility cart's shelves and posts, a shopping trolley's chassis and wire basket with its child-seat flap,
a hand truck's frame, wheels and folding toe plate, a serving trolley's tiers and drawer.

A cart stands on z = 0 centred on the z axis; it is pushed towards +x (its push handle at the back, -x), its
width along y. Every builder returns pieces or an :class:`~infmob_usd.assembly.Assembly` in that frame with the
anchors the others attach to (caster tips, the flap's hinge, the toe plate's hinge, the drawer's slide), so the
category places parts by name and never computes a coordinate. The casters are the seating casters
(``seating.caster``): a swivel caster's fork turns about its stem, a rigid caster's fork is fixed to the frame.

Sizes are data (:data:`SIZES` and the constants below), each figure beside the product it is read from.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame

from . import hardware
from .panels import drawer_box
from .seating import WHEEL_INSET

GAP = 0.004  # m, clearance between a moving part and its neighbours

# Outer sizes (length along x, width along y, height to the handle's top; metres), by design:
# utility carts: IKEA RASKOG 35 x 45 x 78 cm (3 shelves, 50 mm casters); Rubbermaid 4500 service cart
#   97 x 51 x 84 cm, 4091 with 3 shelves 114 x 48 x 98 cm (100-125 mm casters, 2 swivel + 2 rigid).
# shopping trolleys: Wanzl Tango 60 L 72 x 47 x 97 cm, GT 180 97 x 56 x 103 cm (125 mm swivel casters).
# hand trucks: Harper, Milwaukee 2-wheel hand trucks 46-56 cm wide, 112-132 cm tall, 10 in (254 mm) wheels,
#   a 36 x 20-36 cm toe plate.
# serving trolleys: IKEA FORHOJA kitchen cart 100 x 43 x 90 cm (a drawer, 2 shelves); bar carts 60-85 cm long,
#   40-48 cm wide, 80-90 cm tall.
SIZES = {
    "utility_cart": dict(length=(0.45, 1.0), width=(0.36, 0.55), height=(0.78, 0.98)),
    "shopping_trolley": dict(length=(0.72, 0.97), width=(0.47, 0.56), height=(0.97, 1.03)),
    "hand_truck": dict(length=(0.2, 0.3), width=(0.46, 0.56), height=(1.12, 1.32)),
    "serving_trolley": dict(length=(0.6, 0.95), width=(0.4, 0.48), height=(0.8, 0.9)),
}
CASTER_RADIUS = {"utility_cart": (0.025, 0.05), "shopping_trolley": (0.05, 0.0635),
                 "serving_trolley": (0.025, 0.04)}  # m: 50-100 mm, 100-127 mm, 50-80 mm wheels (listings above)
SHELF = dict(plate=0.012, lip=0.035, wall=0.008, sheet=0.003, bevel=0.006)  # moulded trays with raised lips
POST = 0.016  # m, a utility cart's post radius (Rubbermaid 32 mm posts)
PLATE = dict(over=0.004, thick=0.006, half=0.03)  # a caster's top plate under a post
HANDLE_TUBE = 0.013  # m, a push handle's tube radius (25-28 mm)
WIRE = 0.0025  # m, a trolley basket's wire radius (5 mm steel wire, Wanzl)
RAIL = 0.006  # m, its heavier rails' radius (12 mm)
# Child-seat flaps (Wanzl, Rehrig trolleys): a moulded 40 x 25 cm panel hung at the top of the basket's back,
# folding down 90 degrees into a seat.
FLAP = dict(width=0.4, height=0.25, thick=0.01)
FLAP_TURN = math.radians(90)
# Hand truck: 30 x 30 mm steel rails, 250-260 mm wheels 60-85 mm wide on an axle behind the rails, a 6 mm toe
# plate that folds up 90 degrees (Harper, Milwaukee convertible trucks).
TRUCK = dict(rail=0.015, wheel=(0.12, 0.13), tyre=0.07, axle_back=0.13, toe=(0.2, 0.36), plate=0.006,
             extends=0.25, tube=0.011, tyre_wall=0.006)
# (a telescoping loop handle on round tubes behind the rails rises ~25 cm: Harper / Magliner extension handles)
TOE_TURN = math.radians(90)
# Serving trolley: 18 mm boards or shelves, 30 mm legs, a drawer 10-12 cm deep under the top (IKEA FORHOJA).
SERVING = dict(board=0.018, leg=0.015, drawer=0.1, apron=0.02, rails=0.02)


@dataclass(frozen=True)
class CartSize:
    length: float
    width: float
    height: float
    z0: float  # where the frame starts: the casters' stem tops plus their plates, or the axle's height

    @property
    def hx(self) -> float:
        return self.length / 2

    @property
    def hy(self) -> float:
        return self.width / 2


def cart_size(design: str, shares: tuple[float, float, float], z0: float) -> CartSize:
    s = SIZES[design]
    length, width, height = (lo + f * (hi - lo) for (lo, hi), f in zip((s["length"], s["width"], s["height"]), shares))
    return CartSize(length, width, height, z0)


def corner_tips(c: CartSize, inset: float) -> list[Frame]:
    """Caster frames under four corners ``inset`` in from the sides (x pointing out along the diagonal): front
    pair first, then the back (handle) pair."""
    hx, hy = c.hx - inset, c.hy - inset
    return [Frame.at((sx * hx, sy * hy, 0.0), x=(sx, sy, 0.0), z=(0, 0, 1)) for sx in (1, -1) for sy in (1, -1)]


def caster_plates(tips: list[Frame], stem_top: float, material: str) -> list[g.Piece]:
    """The casters' top plates, bolted under the frame."""
    h = PLATE["half"]
    out = []
    for t in tips:
        x, y, _ = t.origin
        out.append(g.box_between((x - h, y - h, stem_top), (x + h, y + h, stem_top + PLATE["thick"]), material,
                                 bevel=0.002))
    return out


def _tray(x0, x1, y0, y1, z, material: str) -> list[g.Piece]:
    """A moulded tray shelf: a plate with lips round its edge, its underside at ``z``."""
    p, lip, w, b = SHELF["plate"], SHELF["lip"], SHELF["wall"], SHELF["bevel"]
    pieces = [g.box_between((x0, y0, z), (x1, y1, z + p), material, bevel=b),
              g.box_between((x0, y0, z), (x0 + w, y1, z + lip), material, bevel=0.003),
              g.box_between((x1 - w, y0, z), (x1, y1, z + lip), material, bevel=0.003),
              g.box_between((x0 + w, y0, z), (x1 - w, y0 + w, z + lip), material, bevel=0.003),
              g.box_between((x0 + w, y1 - w, z), (x1 - w, y1, z + lip), material, bevel=0.003)]
    return [pc.replace(sheet=SHELF["sheet"]) for pc in pieces]


def push_handle(c: CartSize, x: float, z: float, rise: float, reach: float, material: str) -> g.Piece:
    """A U push handle from the frame's back at ``x``, ``z`` out ``reach`` behind and ``rise`` up, across the
    width."""
    y = c.hy - 0.03
    path = [(x, -y, z), (x - reach, -y, z + rise), (x - reach, y, z + rise), (x, y, z)]
    return g.tube(path, HANDLE_TUBE, material, name="handle")


def utility_frame(c: CartSize, shelves: int, tips: list[Frame], material: str, post: str) -> list[g.Piece]:
    """A utility cart: ``shelves`` moulded trays on four corner posts over the caster plates, and a push handle
    at the back."""
    top = c.height - 0.1  # the top tray; the handle rises above it
    x0, x1, y0, y1 = -c.hx, c.hx, -c.hy, c.hy
    zs = np.linspace(c.z0 + 0.06, top, shelves)
    pieces = []
    for z in zs:
        pieces += _tray(x0, x1, y0, y1, z, material)
    for t in tips:
        x, y, _ = t.origin
        pieces.append(g.cylinder((x, y, c.z0), (x, y, top + SHELF["lip"]), POST, post).replace(sheet=0.0015))
    pieces.append(push_handle(c, x0 + 0.02, top + SHELF["lip"], 0.09, 0.08, post).replace(sheet=0.0015))
    return pieces


# -- shopping trolley ------------------------------------------------------------------------------------------
def _grid_side(a, b, h, step: float, material: str, rails: int = 4) -> list[g.Piece]:
    """A wire side from the bottom edge ``a``->``b`` up ``h``: vertical wires (decoration) every ``step`` and
    ``rails`` horizontal rails that collide."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    n = max(int(np.linalg.norm(b - a) / step), 2)
    pieces = []
    for k in range(n + 1):
        p = a + (b - a) * k / n
        pieces.append(g.cylinder(p, p + (0, 0, h), WIRE, material, 8).replace(convex=()))
    for k in range(rails):
        z = h * k / (rails - 1)
        pieces.append(g.cylinder(a + (0, 0, z), b + (0, 0, z), RAIL if k == rails - 1 else WIRE * 1.6, material, 8))
    return pieces


@dataclass(frozen=True)
class Basket:
    x0: float
    x1: float
    hy: float
    z0: float
    z1: float


def basket(c: CartSize) -> Basket:
    """The basket: from the back (handle end) forward, 80 % of the height under the handle."""
    return Basket(-c.hx + 0.08, c.hx, c.hy - 0.01, c.height - 0.5, c.height - 0.12)


def trolley_frame(c: CartSize, tips: list[Frame], material: str, trim: str) -> list[g.Piece]:
    """A shopping trolley: a chassis of two side tubes over the caster plates, two uprights from its back to the
    handle, a wire basket on them and a wire tray low on the chassis."""
    b = basket(c)
    pieces = []
    (fx, fy, _), (bx, by, _) = tips[0].origin, tips[2].origin
    zc = c.z0 + 0.02
    for s in (-1, 1):
        pieces.append(g.tube([(fx, s * fy, zc), (bx, s * by, zc), (b.x0, s * (b.hy - 0.02), b.z0 - 0.01),
                              (b.x0 - 0.06, s * (b.hy - 0.02), c.height - 0.04)], 0.011, material))
    pieces.append(push_handle(c, b.x0 - 0.06, c.height - 0.04, 0.02, 0.03, trim))
    pieces.append(g.cylinder((bx, -by, zc), (bx, by, zc), 0.011, material))
    # the basket: floor wires that collide, four wire sides
    h = b.z1 - b.z0
    for y in np.linspace(-b.hy, b.hy, 6):
        pieces.append(g.cylinder((b.x0, y, b.z0), (b.x1, y, b.z0), WIRE * 1.6, material, 8))
    for x in np.arange(b.x0, b.x1, 0.05):
        pieces.append(g.cylinder((x, -b.hy, b.z0), (x, b.hy, b.z0), WIRE, material, 8).replace(convex=()))
    corners = [(b.x0, -b.hy), (b.x1, -b.hy), (b.x1, b.hy), (b.x0, b.hy)]
    for (xa, ya), (xb, yb) in zip(corners, corners[1:] + corners[:1]):
        pieces += _grid_side((xa, ya, b.z0), (xb, yb, b.z0), h, 0.045, material)
    # a low wire tray between the side tubes
    for y in np.linspace(-fy + 0.03, fy - 0.03, 5):
        pieces.append(g.cylinder((bx + 0.05, y, zc + 0.03), (fx - 0.05, y, zc + 0.03), WIRE * 1.6, material, 8))
    return pieces


def flap_frame(c: CartSize) -> Frame:
    """The child-seat flap's hinge: along -y at the top of the basket's back, inside it; a positive turn swings
    the hanging flap's foot forward and up into a seat."""
    b = basket(c)
    return Frame.at((b.x0 + RAIL + GAP + FLAP["thick"] / 2, 0, b.z1 - RAIL - GAP), x=(1, 0, 0), z=(0, -1, 0))


def flap(c: CartSize, material: str) -> Assembly:
    """The child-seat flap hanging against the basket's back (anchor ``hinge``), with two leg openings."""
    at = flap_frame(c)
    x, _, z = at.origin
    w, h, t = FLAP["width"] / 2, FLAP["height"], FLAP["thick"] / 2
    pieces = [g.box_between((x - t, -w, z - h), (x + t, -0.06, z), material, bevel=0.003),
              g.box_between((x - t, 0.06, z - h), (x + t, w, z), material, bevel=0.003),
              g.box_between((x - t, -0.06, z - 0.08), (x + t, 0.06, z), material, bevel=0.003)]
    return Assembly.single("seat", pieces, {"hinge": at})


# -- hand truck ---------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Truck:
    """A hand truck: wheel radius, tyre width, the toe plate's depth; rails at y = +-``rail_y``."""

    wheel: float
    tyre: float
    toe: float
    rail_y: float


def truck(c: CartSize, wheel_share: float) -> Truck:
    lo, hi = TRUCK["wheel"]
    lo_t, hi_t = TRUCK["toe"]
    return Truck(lo + wheel_share * (hi - lo), TRUCK["tyre"], lo_t + wheel_share * (hi_t - lo_t), c.hy - 0.09)


def truck_frame(c: CartSize, t: Truck, material: str, grip: str, loop: bool = True) -> list[g.Piece]:
    """Two rails standing at x = 0 from the toe plate's hinge to the handle loop (without ``loop``: to their
    tops, an extension handle rising behind them), cross bars, and the axle brackets out behind to the wheels'
    axle."""
    r, y = TRUCK["rail"], t.rail_y
    z_low = TRUCK["plate"] + GAP + 0.01
    pieces = [g.box_between((-r, s * y - r, z_low), (r, s * y + r, c.height - 0.12), material, bevel=0.003)
              for s in (-1, 1)]
    for z in np.linspace(z_low + 0.3, c.height - 0.3, 3):
        pieces.append(g.box_between((-r, -y, z - 0.01), (r, y, z + 0.01), material, bevel=0.002))
    zt = c.height - 0.02
    if loop:
        path = [(0, -y, zt - 0.11), (-0.06, -y, zt), (-0.06, y, zt), (0, y, zt - 0.11)]
        pieces.append(g.tube(path, 0.014, material))
        pieces.append(g.cylinder((-0.06, -0.12, zt), (-0.06, 0.12, zt), 0.018, grip, name="handle"))
    else:
        pieces.append(g.box_between((-r, -y, zt - 0.13), (r, y, zt - 0.11), material, bevel=0.002))
    ax = axle(t)
    for s in (-1, 1):
        pieces.append(g.tube([(0, s * y, z_low + 0.02), (ax.origin[0], s * y, ax.origin[2])], 0.012, material))
    yo = wheel_y(t) - t.tyre / 2 - GAP
    pieces.append(g.cylinder((ax.origin[0], -yo, ax.origin[2]), (ax.origin[0], yo, ax.origin[2]), 0.0095, material))
    # the toe plate's hinge lugs on the rails' feet
    pieces += [g.box_between((-r, s * y - r, TRUCK["plate"] + GAP), (r, s * y + r, z_low + 0.04), material)
               for s in (-1, 1)]
    return pieces


def axle(t: Truck) -> Frame:
    return Frame.at((-TRUCK["axle_back"], 0, t.wheel), x=(1, 0, 0), z=(0, 1, 0))


def wheel_y(t: Truck) -> float:
    return t.rail_y + TRUCK["rail"] + GAP + t.tyre / 2 + 0.01


def truck_wheel(t: Truck, side: int, tyre: str, hub: str) -> Assembly:
    """One of the hand truck's wheels on the axle (anchor ``axle``, z along +y); it touches z = 0."""
    o = axle(t).origin
    y, r, w = side * wheel_y(t), t.wheel, t.tyre
    a, b = (o[0], y - w / 2, r), (o[0], y + w / 2, r)
    prof = [(0.55 * r, -w / 2), (0.85 * r, -w / 2), (r, -0.25 * w), (r, 0.25 * w), (0.85 * r, w / 2), (0.55 * r, w / 2)]
    tread = g.revolve(prof, tyre)
    place = Frame.at((o[0], y, r), z=(0, 1, 0), x=(1, 0, 0))
    inner = g.cylinder(a, b, r - WHEEL_INSET, tyre)
    tread = g.Piece(tread.vertices, tread.faces, tyre, []).transformed(place.matrix)
    # a tyre is a rubber shell round a pressed-steel rim (massed as a 6 mm wall): 1.5-2.5 kg a 10 in wheel
    tread = g.Piece(tread.vertices, tread.faces, tyre, [inner.vertices], wall=TRUCK["tyre_wall"])
    hub_pc = g.cylinder((o[0], y - w / 2 + 0.004, r), (o[0], y + w / 2 - 0.004, r), 0.58 * r, hub).replace(convex=())
    return Assembly.single("wheel", [tread, hub_pc], {"axle": Frame.at((o[0], y, r), x=(1, 0, 0), z=(0, 1, 0))},
                           {"axle_a": a, "axle_b": b})


def toe_frame(c: CartSize, t: Truck) -> Frame:
    """The toe plate's hinge: along -y at the rails' front foot; a positive turn folds the plate up."""
    return Frame.at((TRUCK["rail"] + GAP + TRUCK["plate"] / 2, 0, TRUCK["plate"] / 2), x=(1, 0, 0), z=(0, -1, 0))


def toe_plate(c: CartSize, t: Truck, material: str) -> Assembly:
    """The toe plate lying on the floor in front of the rails (anchor ``hinge``)."""
    x0, y = toe_frame(c, t).origin[0], t.rail_y + TRUCK["rail"]
    pieces = [g.box_between((x0 + GAP, -y, 0.0), (x0 + t.toe, y, TRUCK["plate"]), material, bevel=0.002),
              g.cylinder((x0, -0.6 * y, TRUCK["plate"] / 2), (x0, 0.6 * y, TRUCK["plate"] / 2), TRUCK["plate"] / 2,
                         material)]
    return Assembly.single("toe_plate", pieces, {"hinge": toe_frame(c, t)})


# -- serving trolley ------------------------------------------------------------------------------------------------
def serving_frame(c: CartSize, tips: list[Frame], material: str, legs: str) -> list[g.Piece]:
    """A serving trolley: a top board with an apron round a drawer opening in its front, a lower shelf, four
    legs over the caster plates, a push bar at the back; the drawer's runners under the top."""
    b, lw, a = SERVING["board"], SERVING["leg"], SERVING["apron"]
    top = c.height - 0.06 - b
    zd = top - SERVING["drawer"]
    x0, x1, y0, y1 = -c.hx, c.hx, -c.hy, c.hy
    dw = drawer_width(c)
    pieces = [g.box_between((x0, y0, top), (x1, y1, top + b), material, bevel=0.004),
              g.box_between((x0 + 0.02, y0 + 0.02, c.z0 + 0.12), (x1 - 0.02, y1 - 0.02, c.z0 + 0.12 + b), material,
                            bevel=0.003)]
    for sy in (-1, 1):  # side aprons and the front apron's cheeks beside the drawer
        ya, yb = sorted((sy * (c.hy - 0.02), sy * (c.hy - 0.02 - a)))
        pieces.append(g.box_between((x0 + 0.02, ya, zd), (x1 - 0.02, yb, top), material))
        ya, yb = sorted((sy * (dw / 2 + GAP), sy * (c.hy - 0.02)))
        pieces.append(g.box_between((x1 - 0.02 - a, ya, zd), (x1 - 0.02, yb, top), material))
        ya, yb = sorted((sy * (dw / 2 + GAP), sy * (dw / 2 + GAP + SERVING["rails"])))
        pieces.append(g.box_between((x0 + 0.04, ya, zd), (x1 - 0.02 - a, yb, zd + 0.015), material))
    pieces.append(g.box_between((x0 + 0.02, y0 + 0.02, zd), (x0 + 0.02 + a, y1 - 0.02, top), material))
    for t in tips:
        x, y, _ = t.origin
        pieces.append(g.box_between((x - lw, y - lw, c.z0), (x + lw, y + lw, top), legs, bevel=0.003))
    pieces.append(push_handle(c, x0 + 0.02, top + b / 2, 0.05, 0.05, legs))
    return pieces


def drawer_width(c: CartSize) -> float:
    return c.width - 2 * (0.02 + SERVING["apron"] + 0.04)


def drawer(c: CartSize, material: str, handle: str) -> Assembly:
    """The drawer in its opening under the top, its front flush with the front apron (anchor ``slide``: out
    along +x), with a knob or a bar pull on its front."""
    b, a = SERVING["board"], SERVING["apron"]
    top = c.height - 0.06 - b
    h = SERVING["drawer"] - 2 * GAP
    depth = c.length - 0.1 - a
    made = drawer_box(drawer_width(c), h, depth, a, 0.012, material)
    at = Frame.at((c.hx - 0.02, 0, top - GAP - h / 2), x=(0, 0, 1), z=(1, 0, 0))
    made = made.placed(at @ made.anchor("slide").inverse())
    pull = hardware.handle("bar" if c.length > 0.75 else "knob", 0.5 * drawer_width(c), handle)
    pull = pull.attached("mount", to=made.anchor("handle"))
    return made.with_pieces(made.root, pull.pieces)


def _ext_x() -> float:
    return -TRUCK["rail"] - GAP - TRUCK["tube"] - 0.006


def extension_guides(c: CartSize, t: Truck, material: str) -> list[g.Piece]:
    """Two guide collars on the rails' backs that the extension handle's tubes slide in (decoration)."""
    x, r = _ext_x(), TRUCK["tube"] + 0.003
    out = []
    for z in (0.5 * c.height, c.height - 0.2):
        for s in (-1, 1):
            out.append(g.box_between((x - r, s * t.rail_y - r, z), (-TRUCK["rail"], s * t.rail_y + r, z + 0.03),
                                     material).replace(convex=()))
    return out


def extension(c: CartSize, t: Truck, material: str, grip: str) -> Assembly:
    """A telescoping loop handle on two tubes behind the rails, its loop just over the frame's (anchor
    ``slide``: up)."""
    x, y, r = _ext_x(), t.rail_y, TRUCK["tube"]
    z0, z1 = 0.45 * c.height, c.height + 0.02
    path = [(x, -y, z0), (x, -y, z1 - 0.06), (x - 0.02, -y + 0.05, z1), (x - 0.02, y - 0.05, z1), (x, y, z1 - 0.06),
            (x, y, z0)]
    pieces = [g.tube(path, r, material).replace(sheet=0.0015),
              g.cylinder((x - 0.02, -0.11, z1), (x - 0.02, 0.11, z1), 0.017, grip, name="handle")]
    return Assembly.single("handle", pieces, {"slide": Frame.at((x, 0, z1), z=(0, 0, 1), x=(1, 0, 0))})


def leaf(c: CartSize, side: int, width: float, material: str) -> Assembly:
    """A drop leaf hung down the top's side ``side`` (+1: left, +y) from a hinge along x at the top's edge
    (anchor ``hinge``); a positive turn raises it level with the top."""
    b = SERVING["board"]
    top = c.height - 0.06
    y = side * (c.hy + GAP)
    at = Frame.at((0, y, top - b), x=(0, 0, -1), z=(side, 0, 0))
    y0, y1 = sorted((y, y + side * b))
    pieces = [g.box_between((-c.hx + 0.03, y0, top - b - width), (c.hx - 0.03, y1, top - b), material, bevel=0.003)]
    return Assembly.single("leaf", pieces, {"hinge": at})
