"""Door: a single or double hinged leaf or a sliding barn door in a fixed frame, with handles.

Designs (``design``): ``single`` (optionally latched), ``double`` (a French pair), ``sliding`` (a leaf
hung on two wheels from a rail above the opening, sliding along Y), ``dutch`` (a single leaf split into
a bottom and a top half that hinge separately). What follows describes the hinged
leaves.

X is depth, Y is width, Z is up. The frame (the root) stands around x = 0 on the floor: two jambs
and a head as deep as the wall, an optional threshold, stops behind the leaf and architraves on
both faces. The leaf hangs in the opening, its front face flush with the frame's front (+X), and
hinges at one jamb through a pivot on its front face, opening 0..pi/2 toward +X (vertical axis:
neutral under gravity); the lock-side gap allows for its back corner swinging out. Leaf styles:
flat, or 2-6 recessed or raised panels in a stile-and-rail frame, glazed in the top row or
throughout. Handles on both faces: knobs (continuous about X), levers (revolute 0..pi/4; the core
balances them with a counterweight heel) or a fixed bar pull. Parts: ``categories/parts/doors.py``.
"""

from __future__ import annotations

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import furniture
from infmob_usd.params import Choice, Float, Int

from .parts import doors as P
from .parts import hardware

R = P.RANGES  # the parameters' ranges (sourced in doors.Ranges)

GRAMMAR = Grammar("door", {
    "door": Node(label="frame", optional={"threshold": 0.5},
                 one_of={"single": 0.45, "double": 0.22, "sliding": 0.15, "dutch": 0.18}, choice="design"),
    "threshold": Node(label="threshold"),
    "single": Node(required=("leaf",), optional={"latch": 0.55, "letter_plate": 0.45, "viewer": 0.45}),
    "letter_plate": Node(label="flap"),
    "viewer": Node(label="cover"),
    "double": Node(repeat={"leaf": 2}),
    "dutch": Node(required=("leaf", "top_leaf")),
    "top_leaf": Node(label="leaf", optional={"deadbolt": 0.6}),
    "deadbolt": Node(label="knob"),
    "sliding": Node(required=("slider",)),
    "slider": Node(label="leaf", repeat={"roller": 2}, optional={"kick_plate": 0.45, "guide": 0.8}),
    "guide": Node(one_of={"floor_guide": 0.55, "stay_roller": 0.45}, choice="guide_style"),
    "floor_guide": Node(label="guide"),
    "stay_roller": Node(label="wheel"),
    "roller": Node(label="wheel"),
    "leaf": Node(label="leaf", one_of={"knob": 1 / 3, "lever": 1 / 3, "pull": 1 / 3}, choice="handle",
                 optional={"thumb_turn": 0.5, "kick_plate": 0.45}),
    "kick_plate": Node(label="plate"),
    "latch": Node(label="latch"),
    "thumb_turn": Node(label="knob"),
    "knob": Node(repeat={"knob_face": 2}),
    "knob_face": Node(label="knob"),
    "lever": Node(repeat={"lever_face": 2}),
    "lever_face": Node(label="lever"),
    "pull": Node(),
})
"""Designs: a single hinged leaf (with a latch bolt thrown into the jamb's strike: the leaf opens once it
is drawn back), a double (French) pair hinged on both jambs, or a sliding barn-door leaf hung on two
wheels from a rail above the opening, its bottom edge kept off the wall by a floor guide it runs in, or by a
stay roller it rolls against (or neither). Knobs and levers come in pairs, one on each face; a pull is fixed
to the leaf; a thumb-turn sits on the back face above the handle (a key escutcheon on the front). A single
(entrance) leaf may carry a letter plate (its flap pushed in through the leaf) and a door viewer (its privacy
cover swinging aside on the back face). A Dutch (stable) door is a single leaf cut across above its handle
into two solid halves on one hinge line, each opening alone: the bottom half carries the handles (and a kick
plate), the top half a fixed knob and, often, a deadbolt's thumb-turn (Simpson, JELD-WEN Dutch doors: a
lockset in the bottom half, a deadbolt in the top)."""

PARAMS = (
    Float("leaf_width", "leaf width (Y)", "m", *R.leaf_width),
    Float("leaf_height", "leaf height (Z)", "m", *R.leaf_height),
    Float("leaf_thickness", "leaf thickness (X)", "m", *R.leaf_thickness),
    Float("frame_depth", "jamb depth (X), about the wall thickness", "m", *R.frame_depth),
    Float("jamb_width", "jamb and head board thickness", "m", *R.jamb_width),
    Float("casing_width", "architrave width", "m", *R.casing_width),
    Choice("hinge_side", "jamb the leaf hangs on, seen from the front (+X)", choices=("left", "right")),
    Choice("leaf_style", "leaf face", choices=("flat", "recessed", "raised"), weights=(0.3, 0.35, 0.35)),
    Int("panel_count", "panels of a panelled leaf (2, 3, 5: one column; 4, 6: two)", "", *R.panel_count),
    Choice("glazing", "glass lites", choices=("none", "top", "full"), weights=(0.55, 0.3, 0.15)),
    Float("stile_width", "width of the leaf's stiles and top rail", "m", *R.stile_width),
    Float("handle_height", "handle axis above the floor", "m", *R.handle_height),
    Float("lever_length", "lever grip length", "m", *R.lever_length),
    Float("knob_radius", "knob radius", "m", *R.knob_radius),
    Float("pull_length", "bar pull length", "m", *R.pull_length),
    Float("pair_fraction", "each leaf of a double door as a fraction of leaf_width (0.6-0.75 m leaves)", "",
          *R.pair_fraction),
    Float("wheel_radius", "barn-door hanger wheel radius", "m", *R.wheel_radius),
    Choice("leaf_finish", "leaf material", choices=("wood", "painted")),
    Choice("frame_finish", "frame material: the leaf's or painted white", choices=("match", "white"),
           weights=(0.6, 0.4)),
    Choice("handle_finish", "handle material", choices=("chrome", "brushed_metal")),
)

PAINTS = "painted:white|off_white|light_grey|grey|sage|navy|charcoal"
MATERIALS = {"leaf": ("leaf_finish", {"painted": PAINTS}), "frame": "frame_family",
             "glass": "glass:clear|clear_blue", "handle": "handle_finish", "hinge": "handle_finish"}


def frame_family(p: dict) -> dict:
    """A frame matching the leaf wears the leaf's family; otherwise it is painted white. A fully glazed leaf
    takes no letter plate (its opening would cross a lite), a glazed one no viewer (its glass is the view)."""
    leaf = "wood" if p["leaf_finish"] == "wood" else PAINTS
    p = {**p, "has_letter_plate": p["has_letter_plate"] and p["glazing"] != "full",
         "has_viewer": p["has_viewer"] and p["glazing"] == "none",
         "has_thumb_turn": p["has_thumb_turn"] and p["design"] != "dutch"}  # a Dutch door's lock is its top's
    return {**p, "frame_family": leaf if p["frame_finish"] == "match" else "painted:white|off_white"}


def _crosses(piece, box) -> bool:
    """Whether a piece's bounds overlap the box ``(lo, hi)``."""
    lo, hi = piece.bounds
    return bool(np.all(lo < np.asarray(box[1])) and np.all(hi > np.asarray(box[0])))


class DoorLayout(Layout):
    def door(self, node):
        p = self.p
        design = node.choice
        left = p["hinge_side"] == "left"
        op = P.opening(design, p["leaf_width"], p["leaf_height"], p["leaf_thickness"], p["frame_depth"], left,
                       bool(node.one("threshold")), p["pair_fraction"], p["casing_width"])
        frame = P.frame(op.x_front, p["frame_depth"], op.opening, op.head, p["jamb_width"], p["casing_width"], 0.0,
                        op.stop_x)
        latch = None
        if design == "single" and node.one("single").one("latch"):
            latch = P.latch_bolt(op.xs, op.lock_y, op.lock_out, p["handle_height"])
            k = 1 if left else 0  # the lock-side jamb
            frame[k] = P.mortise(frame[k], *latch[2])
            frame.append(P.strike_plate(op.strike_x, op.jamb_face, op.lock_out, p["handle_height"]))
        self.add("frame", "frame", frame)
        if node.one("threshold"):
            self.grow(node.one("threshold"), ys=op.opening)
        if design == "single":
            self.grow(node.one("single"), xs=op.xs, ys=op.ys, zs=op.zs, latch=latch)
        elif design == "dutch":
            self.grow(node.one("dutch"), xs=op.xs, ys=op.ys, zs=op.zs)
        elif design == "double":
            self.grow(node.one("double"), xs=op.xs, leaves=op.leaves, zs=op.zs)
        else:
            self.grow(node.one("sliding"), xs=op.xs, ys=op.ys, zs=op.zs, travel=op.travel)

    def threshold(self, node, ys):
        """The threshold (a separate sill strip screwed to the floor between the jambs)."""
        Dj = self.p["frame_depth"]
        self.add("threshold", "threshold",
                 [g.box_between([-Dj / 2, ys[0], 0.0], [Dj / 2, ys[1], P.THRESHOLD], "frame", bevel=0.004)])
        self.fix("frame", "threshold")

    def single(self, node, xs, ys, zs, latch):
        side = self.p["hinge_side"]
        line = self.grow(node.one("leaf"), xs=xs, ys=ys, zs=zs, side=side, name="leaf", latch=latch)
        if latch:  # the bolt's joint first: the leaf's hinge requires it drawn back
            self.grow(node.one("latch"), bolt=latch[0], out=1.0 if side == "left" else -1.0)
            self.hinge("frame", "leaf", line, upper=P.OPENS, requires_open="latch")
        for kind in ("letter_plate", "viewer"):
            if node.one(kind):
                self.grow(node.one(kind), xs=xs, ys=ys, leaf="leaf")

    def letter_plate(self, node, xs, ys, leaf):
        """A letter plate below the handle (BS EN 13724: the opening 0.7-1.7 m above the floor), centred on the
        leaf: its opening is cut through every leaf piece it crosses; the flap turns in about +y."""
        z = max(P.LETTER_LOW, self.p["handle_height"] - P.LETTER_BELOW)
        cut, fixed, flap, (o, a) = P.letter_plate(xs, (ys[0] + ys[1]) / 2, z)
        part = self.bp.parts[leaf]
        part.pieces[:] = [P.mortise(pc, *cut) if _crosses(pc, cut) else pc for pc in part.pieces]
        self.extend(leaf, fixed)
        self.add("letter_flap", "flap", flap)
        self.hinge(leaf, "letter_flap", Frame.at(o, z=a), upper=P.LETTER_FLAP_OPENS)

    def viewer(self, node, xs, ys, leaf):
        """A door viewer at eye height on the leaf's centre line; its cover swings aside on the back face."""
        fixed, cover, (o, a) = P.viewer(xs, (ys[0] + ys[1]) / 2, P.VIEWER_HEIGHT)
        self.extend(leaf, fixed)
        self.add("viewer_cover", "cover", cover)
        self.hinge(leaf, "viewer_cover", Frame.at(o, z=a), upper=P.VIEWER_SWING)

    def double(self, node, xs, leaves, zs):
        for kid, (ys, side), name in zip(node.of("leaf"), leaves, ("leaf", "leaf_2"), strict=True):
            self.grow(kid, xs=xs, ys=ys, zs=zs, side=side, name=name, latch=None)

    def dutch(self, node, xs, ys, zs):
        """The bottom half up to the cut above its handle (at least P.DUTCH_CUT above the floor), the top half
        above it; both solid-core (Dutch doors are exterior doors), one panel or lite each."""
        p = self.p
        post, over = P.DUTCH_CLEAR
        above = P.ROSE[0] if p["handle"] != "pull" else p["pull_length"] / 2 + post
        cut = max(P.DUTCH_CUT, p["handle_height"] + above + over)
        self.grow(node.one("leaf"), xs=xs, ys=ys, zs=(zs[0], cut - P.GAP / 2), side=p["hinge_side"], name="leaf",
                  latch=None, dutch=True)
        self.grow(node.one("top_leaf"), xs=xs, ys=ys, zs=(cut + P.GAP / 2, zs[1]))

    def top_leaf(self, node, xs, ys, zs):
        """A Dutch door's top half: a fixed knob on each face by its lock edge, a deadbolt's thumb-turn above."""
        p = self.p
        edge = P.edges(xs, ys, zs, p["hinge_side"] == "left")
        y = edge.handle_y
        zk = zs[0] + P.DUTCH_KNOB
        pieces = P.leaf(xs, ys, zs, zs[0], p["leaf_style"], p["glazing"], p["stile_width"], 1, wall=P.EXTERIOR_WALL)
        for n, face in ((1.0, xs[1]), (-1.0, xs[0])):
            knob = hardware.knob_handle(p["knob_radius"], P.DUTCH_KNOB_DEPTH, "handle")
            pieces += [P.rose(face, n, y, zk)] + list(knob.placed(Frame.at((face + n * P.ROSE[1], y, zk),
                                                                           z=(n, 0, 0))).pieces)
        self.add("leaf_2", "leaf", pieces + P.knuckles(xs[1], edge.hinge_y, *zs))
        self.hinge("frame", "leaf_2", edge.hinge, upper=P.OPENS)
        if node.one("deadbolt"):
            self.grow(node.one("deadbolt"), xs=xs, y=y, z=zk + P.THUMB["above"])

    def deadbolt(self, node, xs, y, z):
        self._thumb_turn("leaf_2", "deadbolt", xs, y, z)

    def _thumb_turn(self, leaf, name, xs, y, z):
        """A thumb turn on the leaf's back face, turning a quarter turn, its roses on both faces."""
        made = P.thumb_turn_set(xs, y, z)
        self.extend(leaf, made.roses)
        placed = self.place(made.turn, name)
        self.hinge(leaf, placed.root, placed.anchor("axis"), upper=P.THUMB_TURNS, role="knob")

    def leaf(self, node, xs, ys, zs, side, name, latch, dutch=False):
        p = self.p
        edge = P.edges(xs, ys, zs, side == "left")
        zk = p["handle_height"]
        if dutch:  # a Dutch door's bottom half: solid-core, one unglazed panel
            pieces = P.leaf(xs, ys, zs, zk, p["leaf_style"], "none", p["stile_width"], 1, wall=P.EXTERIOR_WALL)
        else:
            pieces = P.leaf(xs, ys, zs, zk, p["leaf_style"], p["glazing"], p["stile_width"], p["panel_count"])
        if latch:
            pieces[0] = P.mortise(pieces[0], *latch[1])
        self.add(name, "leaf", pieces + P.knuckles(xs[1], edge.hinge_y, *zs))
        line = edge.hinge
        if not latch:
            self.hinge("frame", name, line, upper=P.OPENS)
        where = dict(xs=xs, y=edge.handle_y, z=zk, inward=edge.inward, leaf=name)
        self.grow(node.one(node.choice), **where)
        if node.one("thumb_turn"):
            self.grow(node.one("thumb_turn"), **where)
        if node.one("kick_plate"):
            self.grow(node.one("kick_plate"), xs=xs, ys=ys, zs=zs, leaf=name)
        return line

    def kick_plate(self, node, xs, ys, zs, leaf):
        """A stainless kick plate screwed across the bottom of the leaf's front face (a separate part)."""
        name = self.add(f"kick_plate{leaf[4:]}", "plate", P.kick_plate(xs, ys, zs))
        self.fix(leaf, name)

    def latch(self, node, bolt, out):
        self.add("latch", "latch", bolt)
        # drawn back into its mortise by the handle (a 13 mm throw), horizontal: still under gravity
        y, z = bolt[0].bounds.mean(0)[1:]
        x = bolt[0].bounds.mean(0)[0]
        self.slide("leaf", "latch", Frame.at((x, y, z), z=(0, -out, 0)), upper=P.BOLT["throw"] + P.BOLT["slack"],
                   role="slide")

    def thumb_turn(self, node, xs, y, z, inward, leaf):
        zt = z + P.THUMB["above"]
        if self.p["handle"] == "pull":  # above the bar pull's top post
            zt = z + max(P.THUMB["above"], self.p["pull_length"] / 2 + P.THUMB["rose"] + P.THUMB["over_pull"])
        self._thumb_turn(leaf, f"thumb_turn{leaf[4:]}", xs, y, zt)

    def sliding(self, node, xs, ys, zs, travel):
        self.grow(node.one("slider"), xs=xs, ys=ys, zs=zs, travel=travel)

    def slider(self, node, xs, ys, zs, travel):
        p = self.p
        # it slides toward the hinge side's wall
        hang = P.hanging(xs, ys, zs, travel, p["wheel_radius"], p["hinge_side"] == "left")
        self.extend("frame", P.barn_track(hang.x_wall, *hang.track, hang.z_rail))
        pieces = P.leaf(xs, ys, zs, p["handle_height"], p["leaf_style"], p["glazing"], p["stile_width"],
                        p["panel_count"])
        for y in hang.straps:
            pieces += P.hanger_strap(xs[1], hang.x_wheel, y, zs[1] - P.BARN["strap_below"], hang.z_axle)
        # a bar pull on the front face near the trailing edge, a flush pull on the back
        at = Frame.at((xs[1], hang.y_pull, p["handle_height"]), z=(1, 0, 0), x=(0, 0, 1))
        pieces += hardware.bar_handle(p["pull_length"], "handle", P.PULL).attached("mount", to=at).pieces
        pieces.append(P.flush_pull(xs[0], hang.y_pull, p["handle_height"]))
        self.add("leaf", "leaf", pieces)
        self.slide("frame", "leaf", hang.slide, upper=travel, role="slide")
        for k, (kid, y) in enumerate(zip(node.of("roller"), hang.straps, strict=True)):
            self.grow(kid, k=k, at=(hang.x_wheel, y, hang.z_axle), r=p["wheel_radius"])
        if node.one("kick_plate"):
            self.grow(node.one("kick_plate"), xs=xs, ys=ys, zs=zs, leaf="leaf")
        if node.one("guide"):
            self.grow(node.one("guide"), xs=xs, x_wall=hang.x_wall, ys=ys, d=hang.d)

    def guide(self, node, xs, x_wall, ys, d):
        """What keeps the leaf's bottom edge off the wall: a floor guide it runs in, at the opening's edge on the
        side it slides to (always under it), or a stay roller on the architrave it slides over."""
        if node.choice == "floor_guide":
            self.grow(node.one("floor_guide"), xs=xs, y=(ys[0] + P.GUIDE_IN) if d < 0 else (ys[1] - P.GUIDE_IN))
        else:
            y = ys[0] + P.BARN["stay_in"] + self.p["casing_width"] / 2
            self.grow(node.one("stay_roller"), xs=xs, x_wall=x_wall, y=y if d < 0 else -y)

    def stay_roller(self, node, xs, x_wall, y):
        """A barn door's stay roller: a bracket screwed to the architrave's face and the floor, reaching under
        the leaf's bottom edge, with a roller on a vertical pin that the leaf's front face runs against
        (National Hardware N187-165, Rustica stay rollers: a 30-40 mm roller on an L bracket)."""
        bracket, roller, centre = P.stay_roller(xs, x_wall, y)
        self.extend("frame", bracket)
        self.add("stay_roller", "wheel", [roller])
        self.spin("frame", "stay_roller", Frame.at(centre, z=(0, 0, 1)), role="wheel")

    def floor_guide(self, node, xs, y):
        """A barn door's floor guide: a U channel screwed to the floor that the leaf's bottom edge runs in
        (National Hardware / Rustica stay rollers and floor guides: 40-60 mm long, 20-40 mm high)."""
        pieces = P.floor_guide(xs, y)
        self.add("floor_guide", "guide", pieces)
        self.fix("frame", "floor_guide")

    def roller(self, node, k, at, r):
        name = self.add(f"wheel_{k}", "wheel", P.wheel(*at, r))
        self.spin("leaf", name, Frame.at(at, z=(1, 0, 0)), role="wheel")

    def pull(self, node, xs, y, z, inward, leaf):
        for n, face in ((1.0, xs[1]), (-1.0, xs[0])):
            at = Frame.at((face, y, z), z=(n, 0, 0), x=(0, 0, 1))
            bar = hardware.bar_handle(self.p["pull_length"], "handle", P.PULL).attached("mount", to=at)
            self.extend(leaf, bar.parts[bar.root].pieces)

    def _faces(self, node, kind, xs, y, z, inward, leaf):
        for kid, (side, n, face) in zip(node.of(kind), (("front", 1.0, xs[1]), ("back", -1.0, xs[0])), strict=True):
            self.extend(leaf, [P.rose(face, n, y, z)])
            self.grow(kid, side=side + leaf[4:], n=n, start=face + n * (P.ROSE[1] + P.GAP), y=y, z=z, inward=inward,
                      leaf=leaf)

    def knob(self, node, **where):
        self._faces(node, "knob_face", **where)

    def lever(self, node, **where):
        self._faces(node, "lever_face", **where)

    def knob_face(self, node, side, n, start, y, z, inward, leaf):
        at = Frame.at((start, y, z), z=(n, 0, 0))
        knob = self.place(P.knob_part(self.p["knob_radius"]).attached("mount", to=at), f"knob_{side}")
        self.spin(leaf, knob.root, at, role="knob")

    def lever_face(self, node, side, n, start, y, z, inward, leaf):
        grip = -inward  # the grip points back toward the hinge
        name = self.add(f"lever_{side}", "lever", P.lever(start, n, y, z, grip, self.p["lever_length"]))
        # about (grip direction) x (-Z) = (-grip, 0, 0): a positive angle turns the grip down
        self.hinge(leaf, name, Frame.at((start, y, z), z=(-grip, 0, 0)), upper=P.LEVER_TURN, role="knob")


CATEGORY = Category("door", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, DoorLayout, MATERIALS,
                    derive=frame_family, palette=furniture)
