"""Kitchen cabinet: base runs, tall larders, corner carousels, sink bases and hung wall runs.

X is depth (fronts face +X), Y is width, Z is up. Five designs (``design``), each its own tree:

- ``base_run``: a run of base cabinets (0.55-0.62 m deep, 0.85-0.92 m high to the worktop) on
  legs behind a kick board or on visible legs with levellers, under a worktop; every column is
  drawers (2-4, a shallow top drawer over deep pan drawers), doors (with a shelf), a door with
  internal pull-out drawers behind it (they move only once the door is open), a top drawer over
  doors, or an open shelf.
- ``larder``: 2-4 tall cabinets (1.95-2.25 m): a full-height pull-out larder with wire baskets, or
  an upper door (shelves behind it) over a lower door with internal pull-outs.
- ``corner``: a square corner base unit whose door opens on a lazy-susan carousel (a
  continuous joint: pole and trays turn together on a bearing), beside 2-5 base columns.
- ``sink_base``: a sink base with a tilt-out false front (hinged at its bottom edge, a
  sponge tray behind it), two doors below and an inset bowl and tap in the worktop, beside
  1-5 base columns (``column_count``).
- ``wall_run``: hung wall cabinets (0.30-0.35 m deep) on a suspension rail: doors, glazed
  doors, lift-up flaps (hinged at the top edge) or open shelves.
- ``kitchen``: a whole kitchen wall, 2.4-4.8 m: a sink base and base columns under one worktop, a
  splashback and a row of wall cabinets above it (one over each column, 45-60 cm over the worktop),
  sometimes a tall larder at one end (the wall cabinets' tops then line up with it): the large
  assemblies of the category (20-60 moving parts).

Doors hinge about a vertical axis on the front face at the column edge and swing outward;
the core (``limit_to_clearance``) stops a leaf before it meets the neighbour's door or open
drawers. Fronts are slab, shaker, raised-panel or glazed (``front_style``: glass in wall and
upper doors), with 3 mm reveals, concealed hinge cups on the doors' inner faces and real handle
sizes. Parts: ``categories/parts/cabinetry.py``, ``panels``, ``hardware``.
"""

from __future__ import annotations

import math

from infmob_usd.category import Category
from infmob_usd.frames import Frame, cells
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import furniture
from infmob_usd.params import Choice, Flag, Float, Int

from .parts import cabinetry as cab
from .parts.cabinetry import GAP
from .parts.cabinetry import RANGES as R


def run_width(p) -> float:
    """The width the columns share: a kitchen wall's width beside its sink base, else ``width``."""
    return p["kitchen_width"] - p["sink_width"] if p["design"] == "kitchen" else p["width"]


def columns(p, rng) -> int:
    """column_count, or max(1, floor(width / 0.45)); at most floor(width / 0.2) (columns at least 20 cm wide),
    at least ceil(width / 1.0) (at most 1 m wide; a kitchen wall's at most 0.9 m)"""
    w = run_width(p)
    n = min(p["column_count"] or max(1, math.floor(w / cab.COLUMN)), max(1, math.floor(w / cab.COLUMN_MIN)))
    return max(n, math.ceil(w / (cab.KITCHEN_COLUMN_MAX if p["design"] == "kitchen" else cab.COLUMN_MAX)))


def wall_columns(p, rng) -> int:
    """a kitchen wall's wall cabinets: one over each base column and one over the sink"""
    return columns(p, rng) + 1


def leaves(p, rng) -> int:
    """two doors in a column wider than 0.6 m, else one (a column beside a sink or corner unit is
    column_width wide)"""
    width = p["column_width"] if p["design"] in ("sink_base", "corner") else run_width(p) / columns(p, rng)
    return 2 if width > cab.DOUBLE else 1


def sink_columns(p, rng) -> int:
    """a sink base's columns beside its sink: column_count, else 1-5 drawn"""
    return p["column_count"] or int(rng.integers(1, 6))


MOVING = {"drawer", "door", "inner_drawer", "flap", "pullout", "tilt_front", "carousel"}


def moves(tree) -> bool:
    """Something moves: every design has a moving part except a run of only open shelves."""
    return any(n.kind in MOVING for n in tree.walk())


# the columns of a base run, per instance
BASE_COLUMN = {"drawers": 0.32, "doors": 0.2, "door_drawers": 0.2, "drawer_door": 0.2, "open": 0.08}
GRAMMAR = Grammar("kitchen_cabinet", {
    "kitchen_cabinet": Node(label="body", one_of={"base_run": 0.2, "kitchen": 0.45, "larder": 0.1, "corner": 0.09,
                                                  "sink_base": 0.08, "wall_run": 0.08}, choice="design"),
    "base_run": Node(required=("stand", "worktop"), repeat={"column": columns}),
    # a kitchen wall: base columns, and a wall cabinet over each (IKEA METOD planning: wall cabinets line
    # up with the base cabinets under them), sometimes a tall unit at the end
    "kitchen": Node(required=("stand", "worktop", "splashback", "sink_unit"),
                    repeat={"column": columns, "wall_column": wall_columns, "tall": (0, 1)}),
    "splashback": Node(),
    "sink_unit": Node(required=("sink", "tilt_front"), repeat={"sink_door": 2}),
    "larder": Node(required=("stand",), repeat={"tall": (2, 4)}),
    "corner": Node(required=("stand", "worktop", "corner_unit"), repeat={"column": (2, 5)}),
    "sink_base": Node(required=("stand", "worktop", "sink", "tilt_front"), repeat={"sink_door": 2,
                                                                                   "column": sink_columns}),
    "wall_run": Node(required=("rail",), repeat={"wall_column": columns}),
    "stand": Node(one_of={"plinth": 0.65, "legs": 0.35}, choice="stand_style"),
    "plinth": Node(), "legs": Node(), "worktop": Node(), "rail": Node(),
    "column": Node(one_of=BASE_COLUMN),
    "drawers": Node(repeat={"drawer": (2, 4)}),
    "drawer": Node(label="drawer"),
    "doors": Node(repeat={"door": leaves}),
    "door": Node(label="door"),
    "door_drawers": Node(required=("door",), repeat={"inner_drawer": (2, 4)}),
    "inner_drawer": Node(label="drawer"),
    "drawer_door": Node(required=("drawer",), repeat={"door": leaves}),
    "open": Node(),
    "tall": Node(one_of={"pullout": 0.4, "tall_doors": 0.6}),
    "pullout": Node(label="pullout", repeat={"basket": (4, 6)}),
    "basket": Node(label="basket"),
    "tall_doors": Node(required=("upper_door", "lower_door")),
    "upper_door": Node(label="door"),
    "lower_door": Node(label="door", repeat={"inner_drawer": (2, 4)}),
    "corner_unit": Node(label="door", required=("carousel",)),
    "carousel": Node(label="carousel", repeat={"tray": (2, 3)}),
    "tray": Node(),
    "sink": Node(label="sink"),
    "tilt_front": Node(label="drawer"),
    "sink_door": Node(label="door"),
    "wall_column": Node(one_of={"wall_doors": 0.55, "flap": 0.33, "wall_open": 0.12}),
    "wall_doors": Node(repeat={"wall_door": leaves}),
    "wall_door": Node(label="door"),
    "flap": Node(label="door"),
    "wall_open": Node(),
}, accept=moves)

PARAMS = (  # ranges and their sources: cabinetry.RANGES
    Float("width", "run width (Y) of a base or wall run", "m", *R["width"]),
    Int("column_count", "columns of a base or wall run (auto = max(1, floor(width / 0.45)); kept 0.2-1 m wide),"
        " or beside a sink base's sink (column_width each; auto = 1-5 drawn)",
        "", 1, 10, auto=True),
    Float("base_depth", "base and tall carcass depth (X), front excluded", "m", *R["base_depth"]),
    Float("base_height", "floor to worktop top", "m", *R["base_height"]),
    Float("tall_height", "tall (larder) cabinet height", "m", *R["tall_height"]),
    Float("wall_depth", "wall cabinet depth (X)", "m", *R["wall_depth"]),
    Float("wall_height", "wall cabinet height", "m", *R["wall_height"]),
    Float("column_width", "width of a tall cabinet or of a column beside a corner or sink unit", "m",
          *R["column_width"]),
    Float("corner_size", "corner unit width and depth", "m", *R["corner_size"]),
    Float("sink_width", "sink base width", "m", *R["sink_width"]),
    Float("kitchen_width", "kitchen wall: width of the base columns under the worktop", "m", *R["kitchen_width"]),
    Float("wall_gap", "kitchen wall: worktop to the bottom of the wall cabinets", "m", *R["wall_gap"]),
    Float("board", "carcass board thickness", "m", *R["board"]),
    Float("front_thickness", "door and drawer-front thickness", "m", *R["front_thickness"]),
    Float("worktop_thickness", "worktop thickness (laminate 28-40 mm, stone 20-30 mm)", "m", *R["worktop_thickness"]),
    Float("plinth_height", "leg / kick-board height", "m", *R["plinth_height"]),
    Choice("front_style", "fronts: slab, shaker, raised panel, or glazed (glass in wall and upper doors)",
           choices=cab.FRONT_STYLES, weights=(0.35, 0.3, 0.15, 0.2)),
    Flag("has_handles", "fronts have handles (else push-to-open)", p=0.9),
    Choice("handle_style", "handle shape", choices=("bar", "knob", "recessed"), weights=(0.5, 0.3, 0.2)),
    Choice("body_finish", "carcass and front material", choices=("painted", "wood")),
    Choice("handle_finish", "handle material", choices=("brushed_metal", "chrome", "plastic")),
    Float("drawer_travel", "drawer opening as a fraction of its depth (full extension runners: 0.9)", "",
          *R["drawer_travel"]),
    Float("door_angle", "hinge opening angle (a door beside another column may stop earlier)", "rad",
          *R["door_angle"]),
)

MATERIALS = {"body": "body_finish", "front": "body_finish", "handle": "handle_finish",
             "plinth": "plastic:black|dark_grey", "top": "wood", "glass": "glass:clear|clear_blue",
             "hinge": "brushed_metal", "leg": "brushed_metal", "foot": "plastic:black|dark_grey",
             "sink": "brushed_metal", "tap": "chrome", "wire": "chrome", "tray": "plastic:white|light_grey"}



class CabinetLayout(Layout):
    # -- the designs --------------------------------------------------------------------------------
    def kitchen_cabinet(self, node):
        """The design's main carcass box (the part every front hangs on), then the design."""
        design = node.one(node.choice)
        p = self.p
        kind = design.kind
        if kind == "wall_run":
            D, z0, z1, W = p["wall_depth"], 0.0, p["wall_height"], p["width"]
        else:
            D, z0, z1 = self._base_dims(tall=kind == "larder")
            W = {"base_run": p["width"], "larder": len(design.of("tall")) * p["column_width"],
                 "kitchen": p["kitchen_width"] + len(design.of("tall")) * p["column_width"],
                 "corner": p["corner_size"] + len(design.of("column")) * p["column_width"],
                 "sink_base": p["sink_width"] + len(design.of("column")) * p["column_width"]}[kind]
        first = {"corner": p["corner_size"], "sink_base": p["sink_width"], "kitchen": p["sink_width"]}.get(kind, W)
        xs = cab.front_part(cab.centred(D), p["corner_size"]) if kind == "corner" else cab.centred(D)
        ys, _ = cab.split(cab.centred(W), first)
        self.add("carcass", "body", cab.carcass(xs, ys, (z0, z1), p["board"], "body",
                                                top=kind not in ("sink_base", "kitchen")))
        self.grow(design, W=W, D=D, zs=(z0, z1))

    def _base_dims(self, tall: bool = False):
        p = self.p
        z0 = p["plinth_height"]
        z1 = p["tall_height"] if tall else p["base_height"] - p["worktop_thickness"]
        return p["base_depth"], z0, z1

    def _box(self, ys, xs, zs, top=True):
        self.extend("carcass", cab.carcass(xs, ys, zs, self.p["board"], "body", top=top))

    def _run(self, cols, ys, xs, zs, box=True, first=0, side=None):
        """Grow ``cols`` as equal columns of one carcass over ``ys`` (dividers between them), named from
        column ``first`` on. A single leaf hinges on ``side``, or towards the nearer end of the run
        (beside a corner unit every leaf hinges on its right, away from the corner door: both open 90
        degrees to the same divider)."""
        t = self.p["board"]
        W0, W1 = ys
        if box:
            self._box(ys, xs, zs)
        spans = cells(W0 + t, W1 - t, len(cols), gap=t)
        for c, (col, (ya, yb)) in enumerate(zip(cols, spans)):
            if c < len(cols) - 1:  # divider to the right of this column
                self.extend("carcass", [cab.divider(xs, yb, zs, t)])
            fy = cab.front_span(c, len(cols), (ya, yb), ys, t)
            hand = side or ("left" if c < len(cols) / 2 and self.p["design"] != "corner" else "right")
            self.grow(col, c=first + c, side=hand, ys=(ya, yb), fys=fy, zs=cab.inset(zs, t), fzs=cab.inset(zs, GAP),
                      xs=xs)

    def _stand_and_top(self, node, ys, D, z0, top_hole=None):
        self.grow(node.one("stand"), ys=ys, xs=cab.centred(D), z0=z0)
        if node.one("worktop"):
            self.grow(node.one("worktop"), ys=ys, xs=cab.centred(D), hole=top_hole)

    def base_run(self, node, W, D, zs):
        self._run(node.of("column"), cab.centred(W), cab.centred(D), zs, box=False)
        self._stand_and_top(node, cab.centred(W), D, zs[0])

    def larder(self, node, W, D, zs):
        self._run(node.of("tall"), cab.centred(W), cab.centred(D), zs, box=False)
        self._stand_and_top(node, cab.centred(W), D, zs[0])

    def corner(self, node, W, D, zs):
        p = self.p
        C = p["corner_size"]
        cols = node.of("column")
        ys, xs = cab.centred(W), cab.centred(D)
        corner_ys, run_ys = cab.split(ys, C)
        corner_xs = cab.front_part(xs, C)
        # the corner box (the root's) reaches further back than the run beside it; all fronts are flush
        self._run(cols, run_ys, xs, zs)
        self.grow(node.one("corner_unit"), ys=corner_ys, xs=corner_xs, zs=zs)
        self.grow(node.one("stand"), ys=ys, xs=xs, z0=zs[0])
        self.extend("carcass", cab.corner_legs(corner_xs[0], corner_ys, zs[0]))
        self.grow(node.one("worktop"), ys=ys, xs=xs, hole=None, corner=(run_ys[0], corner_xs[0]))

    def sink_base(self, node, W, D, zs):
        cols = node.of("column")
        ys, run_ys = cab.split(cab.centred(W), self.p["sink_width"])
        if cols:
            self._run(cols, run_ys, cab.centred(D), zs)
        hole = self.sink_unit(node, ys, D, zs, beside=bool(cols))
        self._stand_and_top(node, cab.centred(W), D, zs[0], top_hole=hole)

    def sink_unit(self, node, ys, D, zs, beside):
        """The sink, its tilt-out false front and two doors in the box over ``ys`` (a run of columns
        ``beside`` it on its right); returns the worktop's cut-out."""
        p = self.p
        xs = cab.centred(D)
        hole = cab.sink_hole(xs, ys)
        self.grow(node.one("sink"), hole=hole, z_top=p["base_height"])
        fy, tilt_zs, door_zs = cab.sink_fronts(ys, zs, p["board"], beside)
        self.grow(node.one("tilt_front"), fys=fy, fzs=tilt_zs, xs=xs)
        doors = node.of("sink_door")
        for k, (kid, leaf) in enumerate(zip(doors, cab.leaf_pair(fy))):
            self.grow(kid, name=f"door_sink_{k}", leaf=leaf, fzs=door_zs, x1=xs[1])
        return hole

    def wall_run(self, node, W, D, zs):
        H = zs[1]
        self._run(node.of("wall_column"), cab.centred(W), cab.centred(D), (0.0, H), box=False)
        self.grow(node.one("rail"), ys=cab.centred(W), xs=cab.centred(D), z=H - cab.RAIL_BELOW)

    def kitchen(self, node, W, D, zs):
        """Base columns under a worktop, a splashback, a wall cabinet over each base column, and maybe
        a tall unit at the +Y end (the wall cabinets' tops then line up with its top)."""
        p = self.p
        xs = cab.centred(D)
        counter, tall_ys = cab.split(cab.centred(W), p["kitchen_width"])
        base, wall, talls = node.of("column"), node.of("wall_column"), node.of("tall")
        ys, base_ys = cab.split(counter, p["sink_width"])  # the sink base at the -Y end (the root's box)
        self._run(base, base_ys, xs, zs)
        hole = self.grow(node.one("sink_unit"), ys=ys, D=D, zs=zs, beside=True)
        if talls:
            self._run(talls, tall_ys, xs, (zs[0], p["tall_height"]), first=len(base), side="right")
        bottom = p["base_height"] + p["wall_gap"]
        top = p["tall_height"] if talls else bottom + p["wall_height"]
        top = max(top, bottom + cab.WALL_MIN)
        wall_xs, _ = cab.split(xs, p["wall_depth"])
        self._run(wall, counter, wall_xs, (bottom, top), first=len(base) + len(talls))
        self.grow(node.one("splashback"), ys=counter, x=xs[0], zs=(p["base_height"], bottom))
        self.grow(node.one("stand"), ys=cab.centred(W), xs=xs, z0=zs[0])
        # the worktop overhangs 5 mm at a free end; it butts against a tall unit's side
        y0, yk = counter
        self.grow(node.one("worktop"), ys=(y0, yk - cab.TOP_END if talls else yk), xs=xs, hole=hole)

    def splashback(self, node, ys, x, zs):
        """A panel on the wall between the worktop and the wall cabinets: it carries them."""
        self.extend("carcass", [cab.splashback(x, ys, zs)])

    # -- stands, worktops, rails ---------------------------------------------------------------------
    def stand(self, node, **where):
        self.grow(node.one(node.choice), **where)

    def plinth(self, node, ys, xs, z0):
        """Legs behind a kick board clipped on, set back 50 mm (IKEA METOD plinth)."""
        self.extend("carcass", cab.plinth(xs, ys, z0))

    def legs(self, node, ys, xs, z0):
        """Visible legs with levellers, one pair per ~60 cm of run."""
        self.extend("carcass", cab.leg_run(xs, ys, z0))

    def worktop(self, node, ys, xs, hole=None, corner=None):
        p = self.p
        z1 = p["base_height"]
        z0 = z1 - p["worktop_thickness"]
        self.extend("carcass", cab.kitchen_worktop(xs, ys, z0, z1, hole, corner))

    def rail(self, node, ys, xs, z):
        self.extend("carcass", cab.wall_rail(xs, ys, z, "hinge"))

    def sink(self, node, hole, z_top):
        name = self.add("sink", "sink", cab.sink(hole, z_top, cab.SINK_DEPTH, "sink", "tap"))
        self.fix("carcass", name)

    # -- columns -------------------------------------------------------------------------------------
    def column(self, node, **where):
        self.grow(node.one(node.choice), **where)

    wall_column = tall = column

    def open(self, node, c, side, ys, fys, zs, fzs, xs):
        self.extend("carcass", cab.open_shelves(xs, ys, zs, self.p["board"], self.rng))

    wall_open = open

    def _handles(self):
        """The handle style, or None on a handle-less (push-to-open) front."""
        return self.p["handle_style"] if self.p["has_handles"] else None

    def _drawer_pieces(self, xs, ys, fys, fz, bz, style=True):
        """Front (styled) and box of a drawer; ``bz`` the box's z range."""
        p = self.p
        return cab.drawer(xs, ys, fys, fz, bz, p["board"], p["front_thickness"], p["front_style"] if style else "slab",
                          self._handles())

    def drawers(self, node, c, side, ys, fys, zs, fzs, xs):
        kids = node.of("drawer")
        splits = cab.SPLITS[len(kids)]
        self._drawer_stack(kids, splits, c, ys, fys, zs, fzs, xs)

    def _drawer_stack(self, kids, splits, c, ys, fys, zs, fzs, xs, r0=0):
        for r, (kid, (fz, bz)) in enumerate(zip(kids, cab.drawer_stack(splits, zs, fzs))):
            self.grow(kid, name=f"drawer_{c}_{r + r0}", xs=xs, ys=ys, fys=fys, fz=fz, bz=bz)

    def drawer(self, node, name, xs, ys, fys, fz, bz):
        pieces, box = self._drawer_pieces(xs, ys, fys, fz, bz)
        self.add(name, "drawer", pieces)
        travel = self.p["drawer_travel"] * (box[1] - box[0])
        self.slide("carcass", name, cab.pull_frame(xs[1], fys, fz[0]), upper=travel)

    def doors(self, node, c, side, ys, fys, zs, fzs, xs, shelf=True):
        t = self.p["board"]
        if shelf:
            self.extend("carcass", [cab.mid_shelf(xs, ys, zs, t)])
        kids = node.of("door") or node.of("wall_door")
        if len(kids) == 2:  # double doors, hinged at both outer edges
            spec = cab.leaf_pair(fys)
        else:  # one leaf, hinged on the side facing the nearer end of the run
            spec = [(fys[0], fys[1], side)]
        for k, (kid, leaf) in enumerate(zip(kids, spec, strict=True)):
            self.grow(kid, name=f"door_{c}_{k}", leaf=leaf, fzs=fzs, x1=xs[1])

    wall_doors = doors

    def _door(self, name, leaf, fzs, x1, glazed=False, handle_at=None, gate=False):
        """A hinged door. A ``gate`` (a door with pull-outs or a carousel behind it) opens to 90 degrees:
        two gates hinged on one divider then never meet (the core scales no gate's limit), and its
        pull-outs pass the open leaf."""
        p = self.p
        pieces, hinge = cab.door(x1, leaf, fzs, p["front_thickness"], p["front_style"], self._handles(), glazed,
                                 handle_at)
        self.add(name, "door", pieces)
        self.hinge("carcass", name, hinge, upper=cab.GATE if gate else p["door_angle"])
        return name

    def door(self, node, name, leaf, fzs, x1, gate=False, wall=False):
        """A base or tall door; a wall cabinet's door is glazed, its handle near the bottom edge."""
        self._door(name, leaf, fzs, x1, glazed=wall,
                   handle_at=fzs[0] + cab.WALL_HANDLE * (fzs[1] - fzs[0]) if wall else None, gate=gate)

    sink_door = door

    def wall_door(self, node, name, leaf, fzs, x1):
        self.door(node, name, leaf, fzs, x1, wall=True)

    def door_drawers(self, node, c, side, ys, fys, zs, fzs, xs):
        """One door with pull-out drawers behind it: they move once the door is open."""
        self.grow(node.one("door"), name=f"door_{c}_0", leaf=(fys[0], fys[1], side), fzs=fzs, x1=xs[1],
                  gate=True)
        self._inner_drawers(node.of("inner_drawer"), f"door_{c}_0", c, ys, zs, xs)

    def _inner_drawers(self, kids, gate, c, ys, zs, xs):
        for r, (kid, z) in enumerate(zip(kids, cab.inner_drawer_rows(len(kids), zs))):
            self.grow(kid, name=f"inner_{c}_{r}", gate=gate, xs=xs, ys=ys, zs=z)

    def inner_drawer(self, node, name, gate, xs, ys, zs):
        """An internal pull-out: a low-fronted box set back behind the door, narrowed to pass the hinges
        (Blum / IKEA METOD inner drawers: ~25 mm each side)."""
        p = self.p
        pieces, x0, x1 = cab.inner_drawer(xs, ys, zs, p["board"])
        self.add(name, "drawer", pieces)
        self.slide("carcass", name, cab.pull_frame(x1, ys, zs[0]), upper=p["drawer_travel"] * (x1 - x0),
                   requires_open=gate)

    def drawer_door(self, node, c, side, ys, fys, zs, fzs, xs):
        board, top_i, top_f, door_zs, door_fzs = cab.drawer_over_doors(xs, ys, zs, fzs, self.p["board"])
        self.extend("carcass", [board])
        self._drawer_stack(node.of("drawer"), (1.0,), c, ys, fys, top_i, top_f, xs)
        self.doors(node, c, side, ys, fys, door_zs, door_fzs, xs, shelf=False)

    # -- tall cabinets -------------------------------------------------------------------------------
    def pullout(self, node, c, side, ys, fys, zs, fzs, xs):
        """A full-height pull-out larder: the front on full-extension runners carries a frame
        of wire baskets (Kesseböhmer Dispensa: 4-6 baskets, 90 % extension)."""
        p = self.p
        kids = node.of("basket")
        pieces, travel, rows = cab.pullout(xs, ys, fys, fzs, zs, p["board"], p["front_thickness"], p["front_style"],
                                           self._handles(), len(kids))
        name = self.add(f"pullout_{c}", "pullout", pieces)
        self.slide("carcass", name, cab.pull_frame(xs[1], fys, fzs[0]), upper=travel)
        for k, (kid, (bxs, bys, z)) in enumerate(zip(kids, rows)):
            self.grow(kid, parent=name, xs=bxs, ys=bys, z=z, k=k)

    def basket(self, node, parent, xs, ys, z, k):
        name = self.add(f"{parent}_basket_{k}", "basket", cab.basket(xs, ys, z, "wire"))
        self.fix(parent, name)

    def tall_doors(self, node, c, side, ys, fys, zs, fzs, xs):
        """An upper door with shelves behind it over a lower door with pull-outs behind it."""
        boards, upper_fzs, lower_fzs, lower_zs = cab.tall_split(xs, ys, zs, fzs, self.p["board"])
        self.extend("carcass", boards)
        leaf = (*fys, side)
        self.grow(node.one("upper_door"), name=f"door_{c}_1", leaf=leaf, fzs=upper_fzs, x1=xs[1])
        self.grow(node.one("lower_door"), name=f"door_{c}_0", leaf=leaf, fzs=lower_fzs, x1=xs[1], c=c, ys=ys,
                  zs=lower_zs, xs=xs)

    def upper_door(self, node, name, leaf, fzs, x1):
        self._door(name, leaf, fzs, x1, glazed=True, handle_at=fzs[0] + cab.TALL_HANDLE)

    def lower_door(self, node, name, leaf, fzs, x1, c, ys, zs, xs):
        self._door(name, leaf, fzs, x1, handle_at=fzs[1] - cab.TALL_HANDLE, gate=True)
        self._inner_drawers(node.of("inner_drawer"), name, c, ys, zs, xs)

    # -- corner, sink, wall --------------------------------------------------------------------------
    def corner_unit(self, node, ys, xs, zs):
        """The corner box's front: a blind panel and a door hinged at the run's side, opening on
        the carousel."""
        p = self.p
        blind, leaf, fz, carousel = cab.corner_front(xs, ys, zs, p["board"], p["front_thickness"], p["front_style"])
        self.extend("carcass", blind)  # the blind part of the front: a fixed panel in the carcass
        name = self._door("door_corner", leaf, fz, xs[1], handle_at=None, gate=True)
        self.grow(node.one("carousel"), gate=name, **carousel)

    def carousel(self, node, gate, centre, radius, zs):
        """A lazy susan: a pole with 2-3 trays turning on a bearing (continuous)."""
        cx, cy = centre
        trays = node.of("tray")
        plates, pole, z0, tray_zs = cab.carousel(cx, cy, zs, len(trays), "hinge")
        self.extend("carcass", plates)
        name = self.add("carousel", "carousel", [pole])
        for kid, z in zip(trays, tray_zs):
            self.grow(kid, centre=centre, radius=radius, z=z)
        self.spin("carcass", name, Frame.at((cx, cy, z0)), role="turntable", requires_open=gate)

    def tray(self, node, centre, radius, z):
        self.extend("carousel", [cab.carousel_tray(*centre, z, radius, "tray")])

    def tilt_front(self, node, fys, fzs, xs):
        """The sink base's false front: it tips out about its bottom edge, a tray behind it."""
        p = self.p
        pieces, hinge = cab.tilt_front(xs, fys, fzs, p["front_thickness"], p["front_style"], self._handles())
        name = self.add("tilt_front", "drawer", pieces)
        self.hinge("carcass", name, hinge, upper=cab.TILT)

    def flap(self, node, c, side, ys, fys, zs, fzs, xs):
        """A lift-up flap hinged at its top edge (Blum AVENTOS HK): the bottom swings out and up."""
        p = self.p
        pieces, hinge = cab.flap(xs, fys, fzs, p["front_thickness"], p["front_style"], self._handles())
        self.extend("carcass", [cab.mid_shelf(xs, ys, zs, p["board"])])
        name = self.add(f"flap_{c}", "door", pieces)
        self.hinge("carcass", name, hinge, upper=cab.FLAP)

CATEGORY = Category("kitchen_cabinet", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, CabinetLayout, MATERIALS,
                    palette=furniture)
