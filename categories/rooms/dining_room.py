"""Dining room: a dining table with chairs round it, a sideboard, a lamp, a door and windows, things on the table.

The chairs are folding chairs of one seed (a wooden or a padded set; the bar chairs are counter height), one per
0.61 m of the table's edge, each facing the table and pushed in as far as its hulls clear the table's at rest
and over every joint's travel (a drawer, an extension, a leaf); the sideboard is a kitchen_cabinet base run on
legs (a low cabinet with drawers and doors, as a sideboard is), placed first, against a wall that leaves the
table its walkways: NKBA's 44 in (1.12 m) between the table and the sideboard, where one walks behind the
diners to it, and 36 in (0.91 m) on the other sides.
"""

from __future__ import annotations

import numpy as np

from infmob_usd.grammar import Grammar, Node
from infmob_usd.params import Float
from infmob_usd.scenes.kind import SceneKind
from infmob_usd.scenes.layout import RoomLayout

from ._common import CEILING, WALKWAY, WALL, YAWS, chairs_round, door_in, window_in

# a sideboard: 0.8-0.9 m tall, 0.4-0.55 m deep, 1.2-1.8 m wide (IKEA Hemnes / Besta, John Lewis ranges); as a
# kitchen_cabinet it is 0.85-0.9 m tall and its shallowest carcass, 0.55 m
SIDEBOARD_HEIGHT = (0.85, 0.9)
SIDEBOARD_WIDTH = (1.2, 1.8)
SIDEBOARD_DEPTH = 0.55
# NKBA Kitchen Planning Guidelines (2021), 19: 44 in (1.12 m) from a table's edge to an obstruction behind a seated
# diner where one walks behind (to the sideboard, past the diners)
SIDEBOARD_CLEAR = 1.12
# m: a door's casing and handle stand up to 5 cm proud of its wall: the walkway round the table is kept from them
# (a table 0.91 m off a wall, to the millimetre, left no door a spot in that wall)
CASING = 0.05
TABLE = ((1.4, 2.8), (0.9, 1.2))  # m: dining_table's length and width ranges

PARAMS = (
    Float("width", "room width (Y)", "m", 3.2, 4.5),
    Float("depth", "room depth (X)", "m", 3.2, 4.5),
    Float("ceiling", "floor to ceiling", "m", *CEILING),
)

GRAMMAR = Grammar("dining_room", {
    "dining_room": Node(required=("table", "chairs", "door"), optional={"sideboard": 0.8, "lamp": 0.6,
                                                                         "window": 0.85, "tv": 0.2},
                        repeat={"tableware": (1, 5)}),
    **{k: Node() for k in ("table", "chairs", "door", "sideboard", "lamp", "window", "tv", "tableware")},
})


class DiningRoomLayout(RoomLayout):
    def dining_room(self, node):
        p = self.p
        self.room_of(p["width"], p["depth"], p["ceiling"], WALL)
        for kind in ("sideboard", "table", "chairs", "tv", "lamp", "door", "window"):
            if node.one(kind) is not None:
                self.grow(node.one(kind))
        for child in node.of("tableware"):
            self.grow(child)

    def table_space(self, sideboard=None) -> tuple[np.ndarray, np.ndarray]:
        """The floor (x, y lo and hi) a table's box may take: the walkway off every wall, and
        :data:`SIDEBOARD_CLEAR` off the front of ``sideboard`` (a placed one, or ``(wall name, depth)``)."""
        r = self.room
        extent = np.array([r.depth, r.width])
        lo, hi = np.full(2, WALKWAY + CASING), extent - WALKWAY - CASING
        if sideboard is not None:
            wall = r.wall(sideboard.wall if hasattr(sideboard, "wall") else sideboard[0])
            k = int(np.argmax(np.abs(wall.inward[:2])))
            inward = wall.inward[k] > 0
            if hasattr(sideboard, "wall"):
                front = float(sideboard.hi[k] if inward else sideboard.lo[k])
            else:
                front = sideboard[1] if inward else extent[k] - sideboard[1]
            if inward:
                lo[k] = max(lo[k], front + SIDEBOARD_CLEAR)
            else:
                hi[k] = min(hi[k], front - SIDEBOARD_CLEAR)
        return lo, hi

    def table(self, node):
        # a table the room keeps the walkways round (the category's 1.4-2.8 x 0.9-1.2 m, as much as fits), its
        # long axis along the longer side of the floor it has
        lo, hi = self.table_space(getattr(self, "sideboard_at", None))
        span = hi - lo - 0.05
        long_cap, short_cap = float(span.max()), float(span.min())
        (l0, l1), (w0, w1) = TABLE
        table = self.make("dining_table", length=round(float(self.rng.uniform(l0, max(l0, min(l1, long_cap)))), 3),
                          width=round(float(self.rng.uniform(w0, max(w0, min(w1, short_cap)))), 3))
        longer = YAWS[1] if span[1] > span[0] else 0.0
        # either way round where the floor is near square and the table fits across it too (a table turned across
        # the short side stood 1.07 m from a sideboard, seed 8)
        either = abs(span[1] - span[0]) < 0.3 and float(table.size[0]) <= short_cap + 0.05
        yaw = YAWS[int(self.rng.integers(2))] if either else longer
        centre = (lo + hi) / 2
        # a dining table keeps a walkway round it (NKBA 36 in behind a seated diner)
        self.table_at = self.at(table, centre, yaw) or self.on_floor(table, self.rng, YAWS, margin=WALKWAY)

    def chairs(self, node):
        table = getattr(self, "table_at", None)
        if table is not None:
            chairs_round(self, table)

    def sideboard(self, node):
        """Against a wall, centred on it where it fits, that leaves a table of the least size its walkways
        (:meth:`table_space`); a wall the table would face the long side of first. None where none does."""
        unit = self.make("kitchen_cabinet", design="base_run",
                         width=round(float(self.rng.uniform(*SIDEBOARD_WIDTH)), 3),
                         base_height=round(float(self.rng.uniform(*SIDEBOARD_HEIGHT)), 3), base_depth=SIDEBOARD_DEPTH,
                         stand_style="legs", door_angle=1.5708)
        depth = float(unit.size[0]) + 0.005
        fits = []
        for name in self.rng.permutation(["north", "east", "west", "south"]):
            lo, hi = self.table_space((str(name), depth))
            span = hi - lo - 0.05
            wall = self.room.wall(str(name))
            if span.max() >= TABLE[0][0] and span.min() >= TABLE[1][0] and wall.length >= unit.size[1] + 0.1:
                along = int(np.argmax(np.abs(wall.along[:2])))
                fits.append((span[along] < span[1 - along], str(name)))  # facing the table's long side first
        for _, name in sorted(fits, key=lambda f: f[0]):
            wall = self.room.wall(name)
            centre = (wall.length - float(unit.size[1])) / 2
            for s in (centre, *self.rng.uniform(0.05, wall.length - float(unit.size[1]) - 0.05, 6)):
                got = self.against(unit, wall, float(s))
                if got is not None:
                    self.sideboard_at = got
                    return got
        return None

    def tv(self, node):
        host = getattr(self, "sideboard_at", None)
        if host is not None:
            tv = self.make("tv", stand_style=str(self.rng.choice(["single_post", "two_legs"])))  # it stands
            self.set_on(tv, host, self.rng, prefer=lambda g: -g.z)

    def lamp(self, node):
        lamp = self.make("lamp", lamp_type="floor")
        self.on_floor(lamp, self.rng, YAWS, margin=0.25)

    def door(self, node):
        if door_in(self) is not None:
            return
        # a room has its door: where the chairs round the table leave no wall a swing clears (seed 9), the door
        # goes where the table alone lets it, and only the chairs that still fit with it stay
        chairs = [p for p in self.placed if p.made.category == "folding_chair"]
        self.placed = [p for p in self.placed if p.made.category != "folding_chair"]
        door_in(self)
        table = getattr(self, "table_at", None)
        for c in chairs:
            if self.fits(c, ignore=() if table is None else (table.id,)):
                self.placed.append(c)

    def window(self, node):
        window_in(self)

    def tableware(self, node):
        hosts = [h for h in (getattr(self, "table_at", None), getattr(self, "sideboard_at", None)) if h is not None]
        made = self.make(str(self.rng.choice(["bottle", "jar", "vase", "pot"])))
        self.scatter(made, hosts[:1] if self.rng.uniform() < 0.7 else hosts, self.rng, prefer=lambda g: -g.z)


KIND = SceneKind("dining_room", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, DiningRoomLayout)
