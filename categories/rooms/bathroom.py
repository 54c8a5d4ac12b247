"""Bathroom: a toilet, a vanity unit with its basin and tap, a shelf, a door and a window, bottles on the shelf.

The vanity is a kitchen_cabinet sink base at vanity height (0.85-0.9 m, "comfort height"; BS 6465-2 / NKBA bath
guidelines give
0.76-0.86 m); the toilet keeps its clear floor space in front (NKBA bath guideline: 30 x 48 in, 0.76 x 1.22 m).
"""

from __future__ import annotations

from infmob_usd.grammar import Grammar, Node
from infmob_usd.params import Float
from infmob_usd.scenes.kind import SceneKind
from infmob_usd.scenes.layout import RoomLayout

from ._common import CEILING, WALL, door_in, window_in

VANITY_HEIGHT = (0.85, 0.9)
VANITY_WIDTH = 1.6  # m: the widest vanity unit a bathroom of 2.2-3.2 m takes (retail double vanities: 1.2-1.5 m)
TOILET_CLEAR = 0.76  # m free in front of a toilet (NKBA bath guideline 30 in by 48 in)

PARAMS = (
    Float("width", "room width (Y)", "m", 2.2, 3.2),
    Float("depth", "room depth (X)", "m", 2.2, 3.2),
    Float("ceiling", "floor to ceiling", "m", *CEILING),
)

GRAMMAR = Grammar("bathroom", {
    "bathroom": Node(required=("toilet", "vanity", "door"), optional={"shelf": 0.3, "window": 0.7},
                     repeat={"toiletry": (1, 5)}),
    **{k: Node() for k in ("toilet", "vanity", "door", "shelf", "window", "toiletry")},
})


class BathroomLayout(RoomLayout):
    def bathroom(self, node):
        p = self.p
        self.room_of(p["width"], p["depth"], p["ceiling"], WALL)
        self.hosts = []
        for kind in ("vanity", "toilet", "shelf", "door", "window"):  # the largest unit first
            if node.one(kind) is not None:
                self.grow(node.one(kind))
        for child in node.of("toiletry"):
            self.grow(child)

    def toilet(self, node):
        toilet = self.make("toilet")
        self.on_wall(toilet, self.rng.permutation(["north", "east", "west"]), self.rng)

    def vanity(self, node):
        # a sink base grows 1-5 columns beside its sink: the fitter picks a unit that fits the room
        height = round(float(self.rng.uniform(*VANITY_HEIGHT)), 3)
        for _ in range(12):
            vanity = self.make("kitchen_cabinet", design="sink_base", base_height=height, sink_width=0.8,
                               stand_style="plinth", door_angle=1.5708)
            if vanity.size[1] <= VANITY_WIDTH:
                got = self.on_wall(vanity, self.rng.permutation(["north", "east", "west", "south"]), self.rng)
                if got is not None:
                    self.hosts.append(got)
                    return

    def shelf(self, node):
        rack = self.make("storage_rack", design="shelving", width=1.5, shelf_levels=4,
                         has_goods=False,
                         shelf_spacing=round(float(self.rng.uniform(0.3, 0.4)), 3))
        got = self.on_wall(rack, self.rng.permutation(["north", "east", "south", "west"]), self.rng)
        if got is not None:
            self.hosts.append(got)

    def door(self, node):
        door_in(self)

    def window(self, node):
        window_in(self, sill=(1.2, 1.5))  # a bathroom window sits high (privacy)

    def toiletry(self, node):
        if self.hosts:
            self.scatter(self.make(str(self.rng.choice(["bottle", "jar"]))), self.hosts, self.rng)


KIND = SceneKind("bathroom", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, BathroomLayout)
