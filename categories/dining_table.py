"""Dining table: a fixed, extending, draw-leaf or drop-leaf top on an apron, on 4 legs or a pedestal.

X is the long axis (``length``), Y the short axis (``width``), Z is up. The top overhangs an
apron of four boards on 4 legs at its corners (tapered, turned or square) or on one pedestal
(two, trestle style, on a table longer than 1.9 m). The top (``top_style``) is fixed, extends
(two halves split at x = 0 sliding apart along X over a leaf stored in the apron) or has drop
leaves (a narrow fixed centre and a leaf along each long side hanging from a rule-joint hinge,
raised level on a swing-out bracket (loper) that turns out of the apron side under it: a
Pembroke / drop-leaf table). Optional mechanisms: drawers in the long apron boards, pulled out
along Y, or in the end boards, pulled out along X (always so on a drop-leaf table, whose lopers are
in the long boards; one or both ends); levelling feet screwed into the legs (fixed parts); four swivelling
plate casters under the legs (a rolling kitchen table); adjustable legs (inner legs sliding up in square
sleeves under the apron corners, resting on the floor); levelling glides under a pedestal's foot (three
under a round foot, four under trestle feet). An extending top stores one or two leaves, stacked, in the
apron. A draw-leaf top (``draw_leaf``) is fixed over two leaves stored under its ends that pull out along
X. A fixed or draw-leaf top may carry a lazy susan (a turntable on a bearing ring, turning about z). A
table that would grow no moving part gets apron drawers. Parts: ``categories/parts/tables.py``,
``panels.drawer_box``, ``hardware``, ``seating.caster``.
"""

from __future__ import annotations

import math

from infmob_usd import geometry as g
from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import furniture
from infmob_usd.params import Choice, Float, Int

from .parts import seating as S
from .parts import table_mechanisms as M
from .parts import tables as T
from .parts.furniture_sizes import DINING as D
from .parts.furniture_sizes import DINING_RANGES as R
from .parts.furniture_sizes import DINING_SHARES as SH


def per_side(p: dict, count: int) -> int:
    """A long side's drawer count: up to three on a table 1.9 m or longer (farmhouse and refectory tables carry
    2-3 apron drawers a side), else up to two."""
    return min(count, next(n for under, n in D["drawers_per_side"] if p["length"] < under))


def drawer_count(p, rng) -> int:
    """drawer_count in the +Y long side (capped by the length), or one in the +X end"""
    return 1 if p["drawer_sides"] == "ends" else per_side(p, p["drawer_count"])


def back_drawer_count(p, rng) -> int:
    """back_drawer_count in the -Y side when drawer_sides is both (capped), one in the -X end when end_drawers
    is 2, else none"""
    sides = p["drawer_sides"]
    if sides == "ends":
        return 1 if p["end_drawers"] == 2 else 0
    return 0 if sides == "one" else per_side(p, p["back_drawer_count"])


GRAMMAR = Grammar("dining_table", {
    "dining_table": Node(label="body", one_of={"legs": 0.75, "pedestal": 0.25}, choice="support",
                         optional={"drawers": 0.75}, required=("top_style",)),
    "top_style": Node(one_of={"fixed": 0.35, "extension": 0.25, "drop_leaf": 0.2, "draw_leaf": 0.2},
                      choice="top_style"),
    "draw_leaf": Node(repeat={"end_leaf": 2}, optional={"lazy_susan": 0.5}),
    "end_leaf": Node(label="leaf"),
    "fixed": Node(optional={"lazy_susan": 0.5}),
    "lazy_susan": Node(label="turntable"),
    "drop_leaf": Node(repeat={"leaf_side": 2}),
    "leaf_side": Node(label="leaf", optional={"loper": 0.85}),
    "loper": Node(label="bracket"),
    "legs": Node(optional={"adjustable_legs": 0.35, "levellers": 0.6, "casters": 0.35}),
    "casters": Node(repeat={"table_caster": 4}),
    "table_caster": Node(label="caster", one_of={"twin": 0.6, "single": 0.4}, choice="caster_style"),
    "twin": Node(label="wheel"),
    "single": Node(label="wheel"),
    "levellers": Node(repeat={"leveller": 4}),
    "leveller": Node(label="foot"),
    "adjustable_legs": Node(label="leg"),
    "pedestal": Node(optional={"pedestal_levellers": 0.5}),
    "pedestal_levellers": Node(repeat={"leveller": T.pedestal_glide_count}),
    "extension": Node(label="top", repeat={"leaf": "leaf_count"}),
    "leaf": Node(label="leaf"),
    "drawers": Node(repeat={"drawer": drawer_count, "back_drawer": back_drawer_count}),
    "back_drawer": Node(label="drawer"),
    "drawer": Node(label="drawer"),
})

PARAMS = (
    Float("length", "top length (X, the long axis) with the extension closed", "m", *R["length"]),
    Float("width", "top width (Y)", "m", *R["width"]),
    Float("height", "overall height", "m", *R["height"]),
    Choice("top_shape", "shape of the top", choices=("rectangular", "oval"), weights=SH["top_shape"]),
    Float("top_thickness", "thickness of the top", "m", *R["top_thickness"]),
    Float("end_overhang", "overhang of a rectangular top beyond the apron at each end (X)", "m",
          *R["end_overhang"]),
    Float("side_overhang", "overhang of a rectangular top beyond the apron at each side (Y)", "m",
          *R["side_overhang"]),
    Float("apron_height", "apron height (raised to fit a leaf and drawers)", "m", *R["apron_height"]),
    Choice("leg_style", "leg shape", choices=("tapered", "turned", "square"), weights=SH["leg_style"]),
    Float("leg_width", "leg side (square and tapered) or diameter (turned) at the top", "m", *R["leg_width"]),
    Float("leaf_fraction", "a drop leaf's width as a fraction of the table width (leaves of 20-34 cm)", "",
          *R["leaf_fraction"]),
    Int("lopers_per_leaf", "swing brackets under each drop leaf: one in the middle, or two on an apron 1.3 m or "
        "longer", "", *R["lopers_per_leaf"]),
    Float("extension_fraction", "how far each half slides out, as a fraction of the apron's half length",
          "", *R["extension_fraction"]),
    Int("drawer_count", "drawers in the +Y long side (at most two under 1.9 m long)", "", *R["drawer_count"]),
    Int("back_drawer_count", "drawers in the -Y long side when drawer_sides is both (capped as the +Y side)", "",
        *R["back_drawer_count"]),
    Choice("drawer_sides", "drawers in one long side (+Y), both long sides, or the ends (X)",
           choices=("one", "both", "ends"), weights=SH["drawer_sides"]),
    # a Pembroke table has one drawer in one end (often a false front at the other); refectory tables one in each
    Int("end_drawers", "drawers in the ends when drawer_sides is ends: one (+X) or both", "", *R["end_drawers"]),
    # self-storing extension leaves: one or two stacked in the apron (e.g. Bassett, Ethan Allen, Pottery Barn
    # extension tables ship with one or two leaves), each half the opening wide
    Int("leaf_count", "extension leaves stored in the apron, stacked", "", *R["leaf_count"]),
    # lazy susans on dining tables: 50-70 cm turntables on a ball-bearing ring (round banquet tables, family tables)
    Float("lazy_susan_radius", "turntable radius as a fraction of the table width (fixed top)", "",
          *R["lazy_susan_radius"]),
    Choice("handle_style", "drawer handle", choices=("knob", "bar", "bow"), weights=SH["handle_style"]),
    Float("leg_travel", "how far an adjustable inner leg slides up", "m", *R["leg_travel"]),
    # rolling kitchen / farmhouse tables on four locking plate casters (e.g. John Boos work tables, industrial
    # rolling dining tables): 50-75 mm wheels, twin-wheel or single-wheel
    Float("wheel_radius", "caster wheel radius", "m", *R["wheel_radius"]),
    Float("pedestal_radius", "pedestal column radius", "m", *R["pedestal_radius"]),
    Choice("top_finish", "material of the top and the leaf", choices=("wood", "painted"), weights=SH["top_finish"]),
    Choice("frame_finish", "legs, apron, pedestal", choices=("wood", "painted", "brushed_metal"),
           weights=SH["frame_finish"]),
    Choice("handle_finish", "drawer handle material", choices=("brushed_metal", "chrome", "wood")),
    Choice("wheel_finish", "caster tyres", choices=("plastic", "rubber"), weights=SH["wheel_finish"]),
)

MATERIALS = {"top": "top_finish", "frame": "frame_finish", "handle": "handle_finish", "metal": "brushed_metal",
             "foot": "rubber", "caster": S.BLACK, "wheel": ("wheel_finish", {"plastic": S.BLACK})}


def has_a_moving_part(p: dict) -> dict:
    """A table whose draw grows no moving part (extension, drop leaves, drawers, adjustable legs, lazy susan) gets
    apron drawers; adjustable legs have no levellers; a drop-leaf table's drawers are in its ends (its lopers
    turn out of the long apron boards)."""
    if p["has_adjustable_legs"]:  # inner legs stand on their own rubber feet
        p = {**p, "has_levellers": False, "has_casters": False}
    if p["has_casters"]:  # legs on casters have no levelling feet
        p = {**p, "has_levellers": False}
    if p["top_style"] == "draw_leaf" and p["top_shape"] != "rectangular":  # draw leaves are square-ended
        p = {**p, "top_shape": "rectangular"}
    if p["top_style"] == "drop_leaf" and p["drawer_sides"] != "ends":
        p = {**p, "drawer_sides": "ends"}
    if p["top_style"] == "fixed" and not (p["has_drawers"] or p["has_lazy_susan"]
                                          or (p["support"] == "legs" and p["has_adjustable_legs"])):
        p = {**p, "has_drawers": True}
    return p


class TableLayout(Layout):
    def dining_table(self, node):
        p = self.p
        L, W, H, tt = p["length"], p["width"], p["height"], p["top_thickness"]
        support, drawers = node.one(node.choice), node.one("drawers")
        style = node.one("top_style")
        ext = style.one("extension")
        leaves = style.one("drop_leaf")
        draw = style.one("draw_leaf")
        fr = T.DiningFrame.of(p, D, len(ext.of("leaf")) if ext else None, bool(leaves), bool(draw), bool(drawers))
        La, Wa, wc, za0, za1, board = fr.La, fr.Wa, fr.wc, fr.za0, fr.za1, D["board"]
        holes = {}
        if drawers:
            holes[1] = self._holes(fr.span, za0, fr.z_top, len(drawers.of("drawer")))
            if drawers.of("back_drawer"):
                holes[-1] = self._holes(fr.span, za0, fr.z_top, len(drawers.of("back_drawer")))
        sides = tuple(holes)
        rails = M.apron_rails_ends if p["drawer_sides"] == "ends" else T.apron_rails
        body = rails(La, Wa, fr.lw, za0, za1, board, "frame", holes)
        whole, centre = D["top_bevel"]
        if leaves:
            xy = T.outline(L, W, p["top_shape"], D["outline"])
            body.append(T.slab(M.clip_outline(xy, -wc / 2, wc / 2), H - tt, H, centre * tt, "top"))
        elif not ext:
            body.append(T.top(L, W, p["top_shape"], H - tt, H, whole * tt, "top"))
        if draw:  # the top rests on a bearer frame (two side rails, a cross rail) between the stored leaves
            xb, yb = L / 2 - self._draw_leaf_length() - D["leaf_gap"], Wa / 2 - board
            body += M.bearer_frame(xb, yb, za1, H - tt, D["bearer"], "frame")
        self.add("body", "body", body)
        self.grow(support, La=La, Wa=Wa, lw=fr.lw, za0=za0, za1=za1)
        self.grow(style, x_in=fr.x_in, La=La, Wa=Wa, leaf=fr.leaf, wc=wc, za0=za0, za1=za1, fr=fr)
        if drawers:
            self.grow(drawers, slots=[(s, h) for s in sides for h in holes[s]], Wa=Wa, La=La, sides=len(sides))

    def _holes(self, x_in, z0, z1, n):
        """``n`` drawer openings spread evenly along a board with ``x_in`` free each side of its centre."""
        return M.dining_openings(x_in, z0, z1, n, self.p["drawer_sides"] == "ends", D)

    def legs(self, node, La, Wa, lw, za0, za1):
        p = self.p
        corners = T.corner_frames(La, Wa, lw / 2)
        adj = node.one("adjustable_legs")
        if adj is None:
            lev, cas = node.one("levellers"), node.one("casters")
            c = S.caster(p["caster_style"], p["wheel_radius"]) if cas else None
            plate, wider = D["caster_plate"]
            # levelling feet or casters under the legs
            z0 = D["leveller"] if lev else c.stem_top + plate if cas else 0.0
            self.extend("body", [pc for f in corners for pc in
                                 T.leg_part(p["leg_style"], lw / 2, za1 - z0, "frame", kind="dining").mounted(
                                     f.moved(dz=z0)).pieces])
            if lev:
                self.grow(lev, corners=corners, lw=lw)
            if cas:
                # the casters' top plates under the legs
                self.extend("body", [g.box((lw + wider, lw + wider, plate), f.point((0, 0, z0 - plate / 2)), "metal")
                                     for f in corners])
                self.grow(cas, corners=corners, c=c)
            return
        zs0 = D["sleeve_from"] * p["height"]
        self.extend("body", [pc.transformed(f.matrix) for f in corners
                             for pc in T.square_sleeve(lw, zs0, za1, D["sleeve_wall"], "frame")])
        self.grow(adj, corners=corners, lw=lw, zs0=zs0, za1=za1)

    def levellers(self, node, corners, lw):
        for k, (n, f) in enumerate(zip(node.of("leveller"), corners)):
            self.grow(n, k=k, at=f, lw=lw)

    def leveller(self, node, k, at, lw):
        """A levelling foot: a glide disc on a threaded stem screwed into the leg. Fixed: a foot under load
        turns only with the table lifted (the sweep's reach could not spin two of four feet carrying a
        table: ground friction), so it is a part, not a joint."""
        self.add(f"leveller_{k}", "foot", M.leveller(at, lw, D["leveller"], D))
        self.fix("body", f"leveller_{k}")

    def casters(self, node, corners, c):
        for k, (n, f) in enumerate(zip(node.of("table_caster"), corners, strict=True)):
            self.grow(n, k=k, at=f, c=c)

    def table_caster(self, node, k, at, c):
        """A swivelling plate caster under leg ``k`` (its fork turns about z under the leg)."""
        fork = self.place(S.fork(c).placed(at), f"caster_{k}")
        self.spin("body", fork.root, fork.anchor("swivel"), role="swivel")
        self.grow(node.one(node.choice), fork=fork, wheels=[w.mounted(at) for w in S.wheels(c)], k=k)

    def twin(self, node, fork, wheels, k):
        for j, w in enumerate(wheels):
            wheel = self.place(w, f"wheel_{k}" if len(wheels) == 1 else f"wheel_{k}_{j}")
            self.spin(fork.root, wheel.root, wheel.anchor("axle"), role="wheel")

    single = twin

    def adjustable_legs(self, node, corners, lw, zs0, za1):
        zi1 = zs0 + D["inner_at_rest"]
        travel = min(self.p["leg_travel"], za1 - D["inner_top"] - zi1)
        wi = lw - 2 * (D["sleeve_wall"] + D["clear"])
        for k, f in enumerate(corners):
            pieces = [pc.transformed(f.matrix) for pc in T.inner_leg(wi, zi1, "metal", "foot")]
            leg = self.add(f"leg_{k}", "leg", pieces)
            self.slide("body", leg, f.moved(dz=zi1), upper=travel, role="telescope")

    def pedestal(self, node, La, Wa, lw, za0, za1):
        p = self.p
        lev = node.one("pedestal_levellers")
        z0 = D["leveller"] if lev else 0.0  # the foot stands on levelling glides
        up = Frame.at((0, 0, z0)).matrix
        self.extend("body", [pc.transformed(up) for pc in T.pedestals(p["length"], La, Wa, p["width"],
                                                                      p["pedestal_radius"], za0 - 0.002 - z0,
                                                                      "frame")])
        if lev:
            self.grow(lev, feet=T.pedestal_glides(p["length"], La, p["width"]))

    def pedestal_levellers(self, node, feet):
        """Levelling glides under the pedestal foot: four under a round foot, two under each trestle foot."""
        for k, (n, f) in enumerate(zip(node.of("leveller"), feet, strict=True)):
            self.grow(n, k=k, at=f, lw=D["pedestal_glide_leg"])

    def top_style(self, node, **slot):
        self.grow(node.one(node.choice), **slot)

    def fixed(self, node, **slot):
        self.extend("body", [])  # the top is the body's (built with it)
        if node.one("lazy_susan"):
            self.grow(node.one("lazy_susan"))

    def lazy_susan(self, node):
        """A turntable in the middle of the top on a ball-bearing ring (the ring is the body's)."""
        p = self.p
        ring, table, z0 = M.lazy_susan(p["lazy_susan_radius"] * p["width"], p["height"], D["bearing"], D["susan_t"],
                                       "metal", "top")
        self.extend("body", [ring])
        self.add("lazy_susan", "turntable", [table])
        self.spin("body", "lazy_susan", Frame.at((0, 0, z0)), role="turntable")

    def _draw_leaf_length(self):
        """A draw leaf's length: 40-50 cm on a long table (each adds that much), never past a third of the top."""
        return min(D["draw_leaf"], self.p["length"] / D["draw_leaf_share"])

    def draw_leaf(self, node, za1, **slot):
        for side, n in zip((1, -1), node.of("end_leaf"), strict=True):
            self.grow(n, side=side, za1=za1)
        if node.one("lazy_susan"):
            self.grow(node.one("lazy_susan"))

    def end_leaf(self, node, side, za1):
        """A draw leaf: stored under one end of the top on runners over the apron, pulled out along X
        (a draw-leaf / refectory table, e.g. IKEA BJURSTA, Ercol draw-leaf tables; on the real table the leaf
        then rises level with the top on its tapered runners, here it stays on them)."""
        ll = self._draw_leaf_length()
        leaf = self.place(M.draw_leaf(self.p["length"], self.p["width"], ll, side, za1 + D["leaf_gap"], D),
                          "leaf_front" if side > 0 else "leaf_back")
        self.slide("body", leaf.root, leaf.anchor("slide"), upper=ll - D["draw_leaf_keep"])

    def drop_leaf(self, node, fr, **slot):
        for side, n in zip((1, -1), node.of("leaf_side")):
            self.grow(n, side=side, fr=fr)

    def leaf_side(self, node, side, fr):
        p = self.p
        L, W, H, tt = p["length"], p["width"], p["height"], p["top_thickness"]
        name = "leaf_left" if side > 0 else "leaf_right"
        piece, hinge = M.drop_leaf(T.outline(L, W, p["top_shape"], D["outline"]), side, fr.wc / 2 + D["leaf_gap_y"],
                                   H - tt, H, "top")
        self.add(name, "leaf", [piece])
        self.hinge("body", name, hinge, upper=math.pi / 2)
        if node.one("loper"):
            self.grow(node.one("loper"), side=side, leaf=name, fr=fr)

    def loper(self, node, side, leaf, fr):
        """One swing-out bracket under the middle of the leaf, or two (at a quarter of the apron from each end)
        under a leaf whose apron is ``D["two_lopers"]`` long or longer when ``lopers_per_leaf`` is 2."""
        count = self.p["lopers_per_leaf"] if fr.La >= D["two_lopers"] else 1
        lopers = M.apron_lopers(fr.La, side * fr.Wa / 2, side, fr.za0, fr.za1, fr.loper_length(self.p["width"], D),
                                count, "frame")
        for k, bracket in enumerate(lopers):
            loper = self.place(bracket, f"loper_{'left' if side > 0 else 'right'}" + (f"_{k + 1}" if k else ""))
            self.hinge("body", loper.root, loper.anchor("hinge"), upper=math.pi / 2, requires_open=leaf)

    def extension(self, node, x_in, La, Wa, leaf, **slot):
        p = self.p
        L, W, H, tt = p["length"], p["width"], p["height"], p["top_thickness"]
        travel = p["extension_fraction"] * La / 2
        for name, s in (("top_front", 1), ("top_back", -1)):
            half = self.place(M.split_half(L, W, p["top_shape"], H - tt, H, D["split"], s, "top"), name)
            self.slide("body", half.root, half.anchor("slide"), upper=travel)
        leaves = node.of("leaf")
        made = M.stored_leaves(len(leaves), min(travel, x_in - D["leaf_store"]), Wa, leaf[1], D, "top")
        for k, (n, stored) in enumerate(zip(leaves, made, strict=True)):
            self.grow(n, k=k, leaf=stored)

    def leaf(self, node, k, leaf):
        """A leaf stored on the runners in the apron, under the split (it is taken out by hand)."""
        self.fix("body", self.place(leaf, "leaf" if k == 0 else f"leaf_{k + 1}").root)

    def drawers(self, node, slots, Wa, La, sides):
        ends = self.p["drawer_sides"] == "ends"
        both, one = D["drawer_reach"]
        if ends:
            depth = min(D["drawer_depth"], (La - 2 * D["board"]) * both)
        else:
            depth = min(D["drawer_depth"], (Wa - 2 * D["board"]) * (both if sides == 2 else one))
        for k, (d, (s, hole)) in enumerate(zip(node.of("drawer") + node.of("back_drawer"), slots, strict=True)):
            self.grow(d, k=k, side=s, hole=hole, at=s * (La if ends else Wa) / 2, depth=depth, ends=ends)

    def drawer(self, node, k, side, hole, at, depth, ends):
        metal = self.p["frame_finish"] == "brushed_metal"
        drawer = self.place(M.opening_drawer(hole, at, side, ends, depth, self.p["handle_style"], D,
                                             D["metal_drawer_sheet"] if metal else None), f"drawer_{k}")
        self.slide("body", drawer.root, drawer.anchor("slide"), upper=D["pull"] * depth)

    back_drawer = drawer


CATEGORY = Category("dining_table", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, TableLayout, MATERIALS,
                    derive=has_a_moving_part, palette=furniture)
