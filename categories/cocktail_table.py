"""Cocktail (coffee) table: lift-top storage, telescopic legs, pedestal, drawer table or a nest of tables.

X is depth (the front faces +X), Y is width, Z is up. The top is a bevelled slab, round or
square, ``width`` across. Designs (``support``):
- ``legs``: on legs (3 or 4; a square top has 4) under an apron, with an optional lower shelf,
  either a lift-top (the legs and a deep apron form a storage well; the top rises along +Z, or
  tilted toward the front, on two visible two-stage lift struts joined by a cross bar: body ->
  lift frame -> top), or telescopic legs (metal sleeves on the floor with posts sliding up in them,
  carrying the top and the apron);
- ``pedestal``: a column carrying the top slides up out of a tube on a base disc and turns in it
  (revolute_prismatic);
- ``drawers``: a square storage table, drawers in the front (and maybe the back) of a deep apron
  between four legs, an optional lower shelf, maybe four swivel casters, and maybe one or two drop
  leaves on its sides hanging from the top's edges (a Pembroke / drop-leaf coffee table), each maybe
  held up by a swing-out bracket (loper) under it;
- ``nesting``: a square table on slim legs with one or two smaller tables under it that slide out
  to the front and back, each maybe with a third nested inside it (a nest of tables).
Every slide rests at its bottom or closed. Parts: ``categories/parts/tables.py`` and
``table_mechanisms.py``.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import furniture
from infmob_usd.params import Choice, Flag, Float, Int

from .parts import seating as S
from .parts import table_mechanisms as M
from .parts import tables as T
from .parts.furniture_sizes import COCKTAIL as C
from .parts.furniture_sizes import COCKTAIL_RANGES as R
from .parts.furniture_sizes import COCKTAIL_SHARES as SH
from .parts.furniture_sizes import NEST


def per_side(p: dict, count: int) -> int:
    """A side's drawer count, capped by the table's width: one under 0.7 m, two under 0.9 m, else up to three
    (the cap keeps every drawer front at least ~0.25 m wide, as on IKEA HEMNES / LIATORP storage tables)."""
    return min(count, next(n for under, n in C["drawers_per_side"] if p["width"] < under))


def drawer_count(p, rng) -> int:
    """drawer_count in the front, capped by the width"""
    return per_side(p, p["drawer_count"])


def back_drawer_count(p, rng) -> int:
    """back_drawer_count in the back when drawer_sides is both, capped by the width"""
    return per_side(p, p["back_drawer_count"]) if p["drawer_sides"] == "both" else 0


GRAMMAR = Grammar("cocktail_table", {
    "cocktail_table": Node(required=("top",), one_of={"legs": 0.14, "pedestal": 0.06, "drawers": 0.6,
                                                      "nesting": 0.2}, choice="support"),
    "top": Node(label=("top", "lid")),  # a lift-top is the lid of a storage box
    "legs": Node(label="body", optional={"shelf": 0.4, "lift_top": 0.55}),
    "lift_top": Node(label="lift"),
    "shelf": Node(),
    "pedestal": Node(label="stand"),
    "drawers": Node(label="body", repeat={"drawer": drawer_count, "back_drawer": back_drawer_count},
                    optional={"shelf": 0.4, "casters": 0.45, "drop_leaves": 0.55}),
    "drop_leaves": Node(repeat={"leaf_side": (1, 2)}),
    "leaf_side": Node(label="leaf", optional={"loper": 0.5}),
    "loper": Node(label="bracket"),
    "back_drawer": Node(label="drawer"),
    "casters": Node(repeat={"table_caster": 4}),
    "table_caster": Node(label="caster", one_of={"twin": 0.4, "single": 0.6}, choice="caster_style"),
    "twin": Node(label="wheel"),
    "single": Node(label="wheel"),
    "drawer": Node(label="drawer"),
    "nesting": Node(label="body", repeat={"nested": (1, 2)}),
    "nested": Node(label="table", optional={"inner": 0.5}),
    "inner": Node(label="table"),
})
"""``shelf`` and ``lift_top`` grow on a legged table; without a lift-top its legs are telescopic.
A storage table has 1-3 drawers in the front and maybe 1-3 in the back (fewer on a narrow table), maybe stands on
four swivel casters (a cart-style coffee table) and maybe has one or two drop leaves on its sides (drop-leaf / Pembroke
coffee tables: a leaf on each side, or one on a table kept against a sofa's arm), each maybe on a loper; a nest has one
or two tables under the top (front, back), each maybe with a smaller one inside it."""

PARAMS = (
    Float("width", "top diameter (round) or side (square)", "m", *R["width"]),
    Float("height", "overall height at rest", "m", *R["height"]),
    Choice("top_shape", "shape of the top", choices=("round", "square")),
    Float("top_thickness", "thickness of the top", "m", *R["top_thickness"]),
    Float("bevel", "bevel of the top's edges, as a fraction of its thickness", "", *R["bevel"]),
    Int("leg_count", "legs under a round top (a square top has 4); auto = drawn 3 or 4", "",
        *R["leg_count"], auto=True),
    Choice("leg_style", "shape of fixed legs (hairpin and tube legs are steel, in metal_finish)",
           choices=("turned", "tapered", "square", "hairpin", "tube"), weights=SH["leg_style"]),
    Float("leg_radius", "leg radius (half side of a square leg) at its top", "m", *R["leg_radius"]),
    Float("leg_inset", "distance of the leg centres in from the top's edge", "m", *R["leg_inset"]),
    Float("apron_height", "height of the apron under the top", "m", *R["apron_height"]),
    Float("shelf_height", "lower shelf height as a fraction of the height", "", *R["shelf_height"]),
    Float("lift_travel", "how far a lift-top rises", "m", *R["lift_travel"]),
    Flag("has_lift_forward", "a lift-top rises toward the front (scissor mechanism)", p=0.5),
    Float("lift_forward_ratio", "forward (+X) over upward motion of a forward lift-top", "", *R["lift_forward_ratio"]),
    Float("box_depth", "storage well (lift-top) or drawer apron depth (13-20 cm on lift-top tables)", "m",
          *R["box_depth"]),
    Int("drawer_count", "drawers in the front (one under 0.7 m wide, at most two under 0.9 m)", "", *R["drawer_count"]),
    Int("back_drawer_count", "drawers in the back when drawer_sides is both (capped as the front)", "",
        *R["back_drawer_count"]),
    Choice("drawer_sides", "drawers in the front only or front and back", choices=("front", "both")),
    Float("leaf_width", "a drop leaf's width (drop-leaf coffee tables: 18-30 cm leaves; less on a low table)", "m",
          *R["leaf_width"]),
    Float("caster_radius", "wheel radius of a storage table's casters (50-75 mm furniture casters)", "m",
          *R["caster_radius"]),
    Float("stand_travel", "how far telescopic legs or a pedestal column extend", "m", *R["stand_travel"]),
    Float("stand_turn", "turn limit (+-) of a pedestal top", "rad", math.pi / 2, math.pi),
    Float("base_radius", "pedestal base radius as a fraction of the width", "", *R["base_radius"]),
    Float("column_radius", "pedestal inner column radius", "m", *R["column_radius"]),
    Choice("top_finish", "material of the top", choices=("wood", "painted", "glass"), weights=SH["top_finish"]),
    Choice("frame_finish", "material of the legs and apron", choices=("wood", "painted", "brushed_metal"),
           weights=SH["frame_finish"]),
    Choice("metal_finish", "sleeves, column and pedestal base", choices=("brushed_metal", "chrome", "painted")),
)

MATERIALS = {"top": "top_finish", "frame": "frame_finish", "metal": "metal_finish", "foot": "rubber",
             "handle": "metal_finish", "strut": "brushed_metal", "caster": "plastic:black|dark_grey",
             "wheel": "rubber"}


def nest_size(p: dict) -> dict:
    """A nest of tables is side-table sized (``NEST["size"]``); a lift-top is at most ``C["lift_top_t"]`` thick; a
    storage table with drawers is at least ``C["drawers_w"]`` wide (:mod:`.parts.furniture_sizes`)."""
    if p["support"] == "drawers":
        return {**p, "width": max(p["width"], C["drawers_w"])}
    if p["support"] == "legs" and p["has_lift_top"]:
        return {**p, "top_thickness": min(p["top_thickness"], C["lift_top_t"])}
    if p["support"] != "nesting":
        return p
    return {**p, "width": min(p["width"], NEST["size"][0]), "height": min(p["height"], NEST["size"][1])}


class TableLayout(Layout):
    def cocktail_table(self, node):
        p = self.p
        # a thick painted top is a lightweight board; a nest's small tables keep solid MDF tops
        if p["top_finish"] == "painted" and p["top_thickness"] > C["hollow_top_from"] and p["support"] != "nesting":
            self.bp.densities["top"] = C["hollow_top_density"]
        carried = self.grow(node.one(node.choice))
        self.grow(node.one("top"), **carried)

    def top(self, node, pieces, joint, label="top", shape=None):
        p = self.p
        W, H, tt = p["width"], p["height"], p["top_thickness"]
        slab = T.top(W, W, shape or p["top_shape"], H - tt, H, p["bevel"] * tt, "top")
        self.add("top", label, [slab, *pieces])
        self.join(joint)

    def legs(self, node):
        p = self.p
        W, shape = p["width"], p["top_shape"]
        few, most = C["leg_counts"]
        n = most if shape == "square" else (p["leg_count"] or int(self.rng.integers(few, most + 1)))
        lift = node.one("lift_top")
        fr = T.LegFrame.of(p, C, bool(lift))
        inset, za0, za1, rl = fr.inset, fr.za0, fr.za1, p["leg_radius"]
        frames = T.leg_frames(W, shape, inset, n)
        apron = T.apron(W, shape, inset, rl, za0, za1, "frame")
        if lift:
            body = apron + [pc for f in frames for pc in self._leg(p["leg_style"], rl, za1).mounted(f).pieces]
            self.add("body", "body", body)
            if node.one("shelf"):
                self.grow(node.one("shelf"), inset=inset, r_leg=C["shelf_leg"] * rl, z=fr.shelf_z)
            fwd = p["lift_forward_ratio"] if p["has_lift_forward"] else 0.0
            return self.grow(lift, inset=inset, z=za0, fwd=fwd)
        # telescopic: sleeves stay, the top lifts with its apron and posts
        ro = fr.sleeve_r
        self.add("body", "body", [pc.transformed(f.matrix) for f in frames
                                  for pc in T.round_sleeve(ro, fr.sleeve_top, "metal", "foot")])
        if node.one("shelf"):
            self.grow(node.one("shelf"), inset=inset, r_leg=ro, z=fr.shelf_z)
        else:
            self.extend("body", T.stretchers(frames, C["stretcher_z"], ro, "metal", square=shape == "square"))
        posts = [g.cylinder(f.point((0, 0, fr.post_bottom)), f.point((0, 0, za1)), fr.post_r, "metal", 32)
                 for f in frames]
        at = Frame.at((0, 0, fr.sleeve_top))
        return {"pieces": apron + posts,
                "joint": J.prismatic("body", "top", at.origin, at.z, 0.0, fr.travel, role="telescope")}

    def lift_top(self, node, inset, z, fwd):
        """The storage well's floor and the lift: two two-stage struts on the floor, their middle
        stages joined by a cross bar (the ``lift`` part), their rods under the top."""
        p = self.p
        W, H, tt = p["width"], p["height"], p["top_thickness"]
        self.extend("body", [T.apron_bottom(W, p["top_shape"], inset, p["leg_radius"], z, "frame")])
        (sleeves, middle, rods, t1, t2), at = M.well_struts(W, p["top_shape"], inset, z + C["well_floor"], H - tt, fwd,
                                                            p["lift_travel"], C)
        self.extend("body", sleeves)
        self.add("lift_frame", "lift", middle)
        self.join(J.prismatic("body", "lift_frame", at.origin, at.z, 0.0, t1, role="slide"))
        return {"pieces": rods, "label": "lid",
                "joint": J.prismatic("lift_frame", "top", at.origin, at.z, 0.0, t2, role="slide")}

    def shelf(self, node, inset, r_leg, z, shape=None):
        self.extend("body", [T.shelf(self.p["width"], shape or self.p["top_shape"], inset, r_leg, z, "top")])

    def pedestal(self, node):
        p = self.p
        W, H, tt = p["width"], p["height"], p["top_thickness"]
        rc = p["column_radius"]
        ro = rc + T.CLEAR + T.WALL
        base, zb = T.pedestal_base(p["base_radius"] * W, ro, "metal")
        zt1 = C["tube_top"] * (H - tt)
        room, foot, below = C["pedestal_tube"]
        travel = min(p["stand_travel"], zt1 - zb - room)
        self.add("body", "stand", base + T.column_tube(ro, zb - foot, zt1, "metal"))
        share, most = C["plate"]
        column = T.column_and_plate(rc, zt1 - travel - below, H - tt, min(share * W, most), "metal")
        at = Frame.at((0, 0, zt1))
        return {"pieces": column, "joint": J.revolute_prismatic(
            "body", "top", at.origin, at.z, (-p["stand_turn"], p["stand_turn"]), at.z, (0.0, travel),
            role="telescope")}

    @staticmethod
    def _leg(style, radius, height):
        """One fixed leg (a part a library may replace): wooden or painted in the frame's finish, or a steel
        hairpin or tube leg in the metal finish."""
        steel = style in ("hairpin", "tube")
        return T.leg_part(style, radius, height, "metal" if steel else "frame", foot="foot")

    # -- storage table with drawers --------------------------------------------------------------
    def drawers(self, node):
        p = self.p
        leaves = node.one("drop_leaves")
        front, back = node.of("drawer"), node.of("back_drawer")
        box = T.StorageFrame.of(p, C, bool(leaves), bool(back))
        lw, half, za0, za1, span = box.lw, box.half, box.za0, box.za1, box.span

        def openings(per):  # one bay per drawer, the drawer centred in it
            return M.drawer_openings(span, per, za0, za1, C["drawer_margin"], C["drawer_stile"], C["drawer_wide"])

        holes = {1: openings(len(front))}
        if back:
            holes[-1] = openings(len(back))
        frames = box.corners()
        casters = node.one("casters")
        c = S.caster(p["caster_style"], p["caster_radius"]) if casters else None
        over, plate, _ = C["caster_plate"]
        z_leg = c.stem_top + over + plate if c else 0.0  # legs on a caster's top plate
        style = "square" if p["leg_style"] == "turned" or c else p["leg_style"]
        legs = [pc for f in frames for pc in self._leg(style, lw / 2, za1 - z_leg).mounted(f.moved(dz=z_leg)).pieces]
        if c:
            legs += M.caster_plates(frames, lw, c.stem_top, z_leg, C)
        self.add("body", "body", M.drawer_apron(half, lw, za0, za1, T.BOARD, "frame", holes) + legs)
        if node.one("shelf"):
            self.grow(node.one("shelf"), **box.shelf(p, z_leg, C), shape="square")
        if casters:
            self.grow(casters, frames=frames, caster=c)
        slots = [(1, h) for h in holes[1]] + [(-1, h) for h in holes.get(-1, [])]
        for k, (d, (side, hole)) in enumerate(zip(front + back, slots, strict=True)):
            self.grow(d, k=k, side=side, hole=hole, x=side * half, depth=box.depth)
        if leaves:
            self.grow(leaves, half=half, za0=za0, za1=za1, z_low=z_leg)
        return {"pieces": [], "joint": J.fixed("body", "top"), "shape": "square"}

    def drawer(self, node, k, side, hole, x, depth):
        metal = self.p["frame_finish"] == "brushed_metal"
        drawer = self.place(M.opening_drawer(hole, x, side, True, depth, None, C,
                                             C["metal_drawer_sheet"] if metal else None), f"drawer_{k}")
        self.slide("body", drawer.root, drawer.anchor("slide"), upper=C["drawer_pull"] * depth)

    back_drawer = drawer

    def drop_leaves(self, node, half, za0, za1, z_low):
        """A leaf on the +y side, and maybe one on the -y side, hanging from the top's edges at rest."""
        for side, n in zip((1, -1), node.of("leaf_side")):
            self.grow(n, side=side, half=half, za0=za0, za1=za1, z_low=z_low)

    def leaf_side(self, node, side, half, za0, za1, z_low):
        """One drop leaf, hinged along the top's edge (a positive turn raises it level); it hangs clear of
        the floor and the casters, and a loper swung out under it ends under its middle."""
        p = self.p
        W, H, tt = p["width"], p["height"], p["top_thickness"]
        leaf_w = min(p["leaf_width"], H - tt - z_low - C["leaf_floor"])
        y_h = W / 2 + C["leaf_gap_y"]
        xy = T.outline(W, 2 * (y_h + leaf_w), "square", C["outline"])
        piece, hinge = M.drop_leaf(xy, side, y_h, H - tt, H, "top")
        name = "leaf_left" if side > 0 else "leaf_right"
        self.add(name, "leaf", [piece])
        self.hinge("body", name, hinge, upper=math.pi / 2)
        if node.one("loper"):
            self.grow(node.one("loper"), leaf=name, side=side, half=half, za0=za0, za1=za1,
                      length=min(C["loper"], C["loper_reach"][0] * half, y_h + C["loper_reach"][1] * leaf_w - half))

    def loper(self, node, leaf, side, half, za0, za1, length):
        """A swing-out bracket lying along the side board under ``leaf``; swung out (once the leaf is up)
        it holds the leaf level (as the dining table's)."""
        pieces, at = M.apron_loper(-length / 2, side * half, side, za0, za1, length, "frame")
        name = f"loper_{leaf[5:]}"
        self.add(name, "bracket", pieces)
        self.hinge("body", name, at, upper=math.pi / 2, requires_open=leaf)

    def casters(self, node, frames, caster):
        for i, (n, f) in enumerate(zip(node.of("table_caster"), frames)):
            out = f.origin / max(float(np.linalg.norm(f.origin)), 1e-9)
            self.grow(n, tip=Frame.at(f.origin, x=(out[0], out[1], 0.0)), caster=caster, i=i)

    def table_caster(self, node, tip, caster, i):
        """A swivel caster under a leg: the fork turns about z, its wheels about their axle."""
        f = self.place(S.fork(caster).placed(tip), f"caster_{i}")
        self.spin("body", f.root, f.anchor("swivel"), role="swivel")
        self.grow(node.one(node.choice), fork=f, wheels=[w.mounted(tip) for w in S.wheels(caster)], i=i)

    def twin(self, node, fork, wheels, i):
        for k, w in enumerate(wheels):
            wheel = self.place(w, f"wheel_{i}" if len(wheels) == 1 else f"wheel_{i}_{k}")
            self.spin(fork.root, wheel.root, wheel.anchor("axle"), role="wheel")

    single = twin

    # -- a nest of tables ---------------------------------------------------------------------------
    def nesting(self, node):
        p = self.p
        W, H, tt = p["width"], p["height"], p["top_thickness"]
        frame, span = M.nest_frame(W, H - tt, NEST, "frame")
        self.add("body", "body", frame)
        kids = node.of("nested")
        top_t = NEST["top"].get(p["top_finish"], NEST["top_board"])
        size = M.NestedSize.first(span, W, H - tt, len(kids), top_t, NEST)
        for k, n in enumerate(kids):
            self.grow(n, name=f"nested_{k}", parent="body", side=1 if k == 0 else -1, size=size)
        return {"pieces": [], "joint": J.fixed("body", "top"), "shape": "square"}

    def nested(self, node, name, parent, side, size):
        """One table of the nest, sliding out along ``side`` * x; its own nested table inside it."""
        made, inner = M.nested_table(size, side, NEST)
        table = self.place(made, name)
        self.slide(parent, table.root, table.anchor("slide"), upper=NEST["travel"] * size.depth, role="slide")
        if node.one("inner"):
            self.grow(node.one("inner"), name=f"{name}_inner", parent=name, side=side, size=inner)

    inner = nested


CATEGORY = Category("cocktail_table", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, TableLayout, MATERIALS,
                    derive=nest_size, palette=furniture)
