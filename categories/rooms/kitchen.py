"""Kitchen: cabinet runs with a sink, a dishwasher and a range, wall units, a door and a window, things on the worktops.

Six layouts (NKBA and scene_synthesizer's set): a single wall, a galley (two facing runs), an L, a U, a run with
an island and a run with a peninsula (counter stools at the island's and the peninsula's back). Every cabinet
of one kitchen is the same kitchen_cabinet seed (so the same fronts, worktop and handles) with its own design
and width; the range's cooktop and the worktops are at one height; the dishwasher and a wine cooler fit under
the worktop. Objects of categories that exist join in: a refrigerator, and an electric kettle, a toaster and a
coffee machine on the worktop.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd.categories.parts.dishwashers import DW
from infmob_usd.grammar import Grammar, Node
from infmob_usd.params import Float
from infmob_usd.scenes.kind import SceneKind
from infmob_usd.scenes.layout import RUN_GAP, RoomLayout
from infmob_usd.scenes.room import Fixture, boxes_overlap, moved_box

from ._common import chairs_round

# NKBA Kitchen Planning Guidelines (2021): work aisle >= 42 in (1.07 m) for one cook, 48 in (1.22 m) for two;
# 36 in (0.91 m) behind a seated diner where no one passes, 44 in (1.12 m) where one walks behind.
AISLE = (1.07, 1.3)
SEATING_CLEAR = 0.91
SEATING_WALK = 1.12  # NKBA 44 in behind a seated diner where one walks behind: between an eat-in table and a run
# one-wall kitchens are 8-15 ft (2.4-4.5 m) long; the one run holds every unit, each sized in its real range to fill a
# drawn length, never shorter than its units at their least (3.45 m without a fridge, 4.05 m with one: a dishwasher
# and NKBA's landing either side of the range are kept)
SINGLE_WALL_RUN = (2.4, 4.5)
SINGLE_WALL_UNITS = {  # m: the width range the composer sizes each unit of a one-wall run in
    "refrigerator": (0.6, 0.91),  # 60 cm (EU) to 36 in (US) full-size fridges
    "beverage_fridge": (0.45, 0.6),  # 15 in / 60 cm under-counter wine coolers
    "dishwasher": (0.45, 0.6),  # slimline 45 cm, standard 60 cm / 24 in (Bosch, Miele)
    "sink": (0.8, 1.0),  # kitchen_cabinet's sink_width: sink bases 80 / 90 / 100 cm (IKEA METOD)
    "column": (0.4, 0.6),  # the sink base's one column beside its sink (IKEA METOD 40 / 60 cm)
    "oven": (0.6, 0.76),  # freestanding ranges 60 cm (EN) / 30 in (US)
    # a plain base run on the range's other side: kitchen_cabinet's shortest base run (1.2 m) gives NKBA 12
    # and 15's landing (0.38 m beside a cooktop) and 0.91 m of preparation counter
    "base": (1.2, 1.4),
}
# a sink base in a fitted run: its sink and 1-2 base cabinets beside it (the category draws 1-5, up to 4 m wide)
SINK_COLUMNS = (1, 2)
EAT_IN = 0.6  # a single-wall kitchen with a table in it (else the room is only the run and its aisle deep)
# residential ceilings: 8-9 ft (2.44-2.74 m; 2.4 m the UK/EU minimum of most building codes)
CEILING = (2.4, 2.7)
WALL = 0.12  # m: a 100 mm stud partition with 12.5 mm plasterboard each side
# counter stools for a 36 in counter: seat 24-26 in (0.61-0.66 m) (BIFMA / retailers' counter-height stools)
STOOL_SEAT = (0.61, 0.66)
DOOR_ANGLE = math.pi / 2  # cabinet hinges in a fitted run: 90-110 degrees; 90 keeps a door clear of its neighbour
SILL = (0.95, 1.1)  # m: a kitchen window's sill above the floor, over worktop height
# built in under the worktop, between base cabinets: the run's worktop is carried over them
UNDER_COUNTER = ("dishwasher", "beverage_fridge")

PARAMS = (
    Float("worktop_height", "floor to worktop top (and to the range's cooktop)", "m", 0.86, 0.92),
    Float("aisle", "work aisle between facing runs, and in front of a run (NKBA: >= 1.07 m)", "m", *AISLE),
    Float("ceiling", "floor to ceiling", "m", *CEILING),
    Float("run_width", "width of a plain cabinet run (between appliances)", "m", 1.2, 1.8),
)

GRAMMAR = Grammar("kitchen", {
    "kitchen": Node(required=("runs", "door"), optional={"window": 0.7, "wall_units": 0.85, "microwave": 0.8,
                                                          "plate_rack": 0.4, "wine_cooler": 0.35,
                                                          "refrigerator": 0.85, "kettle": 0.5, "toaster": 0.4,
                                                          "coffee_machine": 0.3},
                    repeat={"bottle": (0, 4), "jar": (0, 3), "cookware": (1, 2)}),
    "runs": Node(one_of={"single_wall": 0.2, "galley": 0.15, "l_shape": 0.2, "u_shape": 0.15, "island": 0.15,
                         "peninsula": 0.15}, choice="layout"),
    **{k: Node() for k in ("single_wall", "galley", "l_shape", "u_shape", "island", "peninsula", "door", "window",
                           "wall_units", "microwave", "plate_rack", "wine_cooler", "refrigerator", "bottle", "jar",
                           "cookware", "kettle", "toaster", "coffee_machine")},
})


def fill_widths(spans: dict[str, tuple[float, float]], total: float, rng: np.random.Generator) -> dict[str, float]:
    """A width for each unit inside its span ``(least, most)``, together ``total`` where the spans allow (else
    each at its nearer end): what the least widths leave is shared by drawn weights, a unit's share past its
    most passed on to the others. Rounded to the millimetre."""
    out = {k: lo for k, (lo, _) in spans.items()}
    weight = dict(zip(spans, rng.dirichlet(np.ones(len(spans)))))
    left, growing = total - sum(out.values()), [k for k, (lo, hi) in spans.items() if hi > lo]
    while left > 1e-9 and growing:
        share = left / sum(weight[k] for k in growing)
        for k in list(growing):
            give = min(share * weight[k], spans[k][1] - out[k])
            out[k] += give
            left -= give
            if out[k] >= spans[k][1] - 1e-9:
                growing.remove(k)
    return {k: round(v, 3) for k, v in out.items()}


def _worktop_box(placed) -> tuple[np.ndarray, np.ndarray]:
    """Room-frame box of a placed cabinet's worktop (its ``top`` pieces at rest)."""
    obj = placed.made.obj
    poses = obj.poses({j.name: j.lower for j in obj.movable_joints})
    boxes = [moved_box(*p.bounds, placed.pose @ poses[link.name]) for link in obj.links for p in link.pieces
             if p.material == "top"]
    return np.min([b[0] for b in boxes], 0), np.max([b[1] for b in boxes], 0)


class KitchenLayout(RoomLayout):
    def kitchen(self, node):
        p = self.p
        self.cabinet_seed = self.seed()
        self.h = p["worktop_height"]
        self.worktops, self.runs = [], {}
        wine = node.one("wine_cooler") is not None
        # a full-size fridge at the end of the sink run, where the category exists
        self.fridge = node.one("refrigerator") is not None and "refrigerator" in self.categories()
        layout = node.one("runs").children[0].kind
        self._built.append(node.one("runs").path)
        self.grow(node.one("runs").children[0], wine=wine)
        for kind in ("wine_cooler", "refrigerator"):
            if node.one(kind) is not None:
                self._built.append(node.one(kind).path)
        for kind in ("wall_units", "door", "window", "microwave", "plate_rack", "coffee_machine", "toaster", "kettle"):
            if node.one(kind) is not None:
                self.grow(node.one(kind))
        for kind in ("cookware", "bottle", "jar"):
            for child in node.of(kind):
                self.grow(child)
        self.layout_name = layout

    # -- units -------------------------------------------------------------------------------------------------
    def cabinet(self, design: str, **kw):
        return self.make("kitchen_cabinet", self.cabinet_seed, design=design, base_height=self.h,
                         stand_style="plinth", door_angle=DOOR_ANGLE, **kw)

    def base(self, width: float | None = None):
        return self.cabinet("base_run", width=round(width or float(self.rng.uniform(1.2, self.p["run_width"])), 3))

    def cabinet_params(self) -> dict:
        """The parameters every cabinet of this kitchen shares (one seed: worktop, wall gap, fronts), read off
        one made already, never a unit made only to be read."""
        return next(m for m in self._made.values() if m.category == "kitchen_cabinet").obj.params

    def under_counter(self, category: str, **kw):
        """An appliance built in under the worktop: 4 mm under it, its door flush with the cabinets' fronts
        (an integrated dishwasher's niche is the carcass depth, its door panel a cabinet front: Bosch, Miele
        installation sheets); a deeper one stood up to 47 mm proud of the run."""
        p = self.cabinet_params()
        depth = p["base_depth"] + p["front_thickness"]  # to the cabinets' door fronts
        if kw.get("design") == "integrated":  # the decor board on its door is the cabinet front
            depth -= DW["front"]["board"]
        return self.make(category, height=round(self.h - p["worktop_thickness"] - 0.004, 4), depth=round(depth, 4),
                         **kw)

    def sink_side(self, wine: bool) -> list:
        columns = int(self.rng.integers(SINK_COLUMNS[0], SINK_COLUMNS[1] + 1))
        units = [self.cabinet("sink_base", column_count=columns), self.under_counter("dishwasher", design="integrated")]
        if wine:
            units.append(self.under_counter("beverage_fridge"))
        if self.fridge:
            units.append(self.make("refrigerator"))
        return units

    def cook_side(self) -> list:
        return [self.base(), self.make("oven", height=self.h), self.base()]

    def _depth(self, modules) -> float:
        return max(m.size[0] for m in modules) + 0.005

    def _room(self, width: float, depth: float):
        from infmob_usd.scenes.room import Room

        self.room = Room(round(width, 4), round(depth, 4), self.p["ceiling"], WALL)

    def _runs(self, placed):
        for pl, _ in placed:
            if pl.made.category == "kitchen_cabinet" or pl.made.category == "oven":
                self.worktops.append(pl)
        self.carry_worktop([pl for pl, _ in placed])
        return placed

    def carry_worktop(self, run: list) -> None:
        """One worktop over each stretch of ``run`` between its tall or freestanding units (a range, a fridge):
        where the cabinets' own worktops leave off (over a dishwasher, a wine cooler, a filler) a slab at their
        height and depth joins them, a static fixture of the room; the appliances slide under it, their tops
        4 mm below it (:meth:`under_counter`). A piece that would meet a placed object or its swing is left out."""
        if not run:
            return
        k = int(np.argmax(np.abs(self.room.wall(run[0].wall).along[:2])))  # the axis the run lies along
        stretch: list = []
        for pl in sorted(run, key=lambda pl: float(pl.lo[k])) + [None]:
            if pl is not None and pl.made.category in ("kitchen_cabinet", *UNDER_COUNTER):
                stretch.append(pl)
                continue
            cabinets = [c for c in stretch if c.made.category == "kitchen_cabinet"]
            if cabinets and len(stretch) > 1:
                self._bridge(stretch, cabinets, k)
            stretch = []

    def _bridge(self, stretch: list, cabinets: list, k: int) -> None:
        top = {c.id: _worktop_box(c) for c in cabinets}
        lo, hi = top[cabinets[0].id]
        look = cabinets[0].made.obj.materials["top"]
        covered = sorted((float(a[k]), float(b[k])) for a, b in top.values())
        s, end = float(min(pl.lo[k] for pl in stretch)), float(max(pl.hi[k] for pl in stretch))
        gaps = []
        for a, b in covered + [(end, end)]:
            if a - s > 1e-4:
                gaps.append((s, a))
            s = max(s, b)
        for s0, s1 in gaps:
            g_lo, g_hi = lo.copy(), hi.copy()
            g_lo[k], g_hi[k] = s0, s1
            clear = all(not boxes_overlap(g_lo, g_hi, o.lo, o.hi) and not any(
                boxes_overlap(g_lo, g_hi, a, b) for _, a, b in o.moving_boxes()) for o in self.placed)
            if clear:
                name = f"worktop_{len(self.room.fixtures)}"
                worn = np.asarray(look.base_color[:3], float) * np.asarray(look.wear.tint, float)
                self.room.fixtures.append(Fixture(name, g_lo, g_hi, tuple(float(c) for c in worn),
                                                  wears=(cabinets[0].id, "top"), grain=k))

    # -- layouts -----------------------------------------------------------------------------------------------
    def single_wall(self, node, wine):
        """One run on the north wall, and in front of it either an eat-in table with chairs (the room as
        deep as NKBA's clearances round it ask) or nothing (the room only the run and its aisle deep, as a
        kitchen of one wall is in a flat): never a bare floor too small for a table and too big for an aisle.

        The run, from the west end: the fridge, a wine cooler, the dishwasher beside the sink (NKBA 25: within
        36 in of it), the sink base with its one column between the sink and the range (preparation and
        landing counter), the range, a plain base run (its other landing). Each unit is sized in its real
        range so that the run is a drawn one-wall length (:data:`SINGLE_WALL_RUN`)."""
        names = [*(["refrigerator"] if self.fridge else []), *(["beverage_fridge"] if wine else []),
                 "dishwasher", "sink", "column", "oven", "base"]
        spans = {n: SINGLE_WALL_UNITS[n] for n in names}
        least = sum(lo for lo, _ in spans.values()) + RUN_GAP * (len(names) - 2)
        run = float(self.rng.uniform(max(SINGLE_WALL_RUN[0], least), max(SINGLE_WALL_RUN[1], least)))
        w = fill_widths(spans, run - RUN_GAP * (len(names) - 2), self.rng)
        # the sink base first: the under-counter units are sized to the cabinets' worktop and fronts
        sink = self.cabinet("sink_base", column_count=1, sink_width=w["sink"], column_width=w["column"])
        a = [self.make("refrigerator", width=w["refrigerator"])] if self.fridge else []
        if wine:
            a.append(self.under_counter("beverage_fridge", width=w["beverage_fridge"]))
        a += [self.under_counter("dishwasher", design="integrated", width=w["dishwasher"]), sink,
              self.make("oven", height=self.h, width=w["oven"]), self.base(w["base"])]
        beyond = 0.5 + float(self.rng.uniform(0, 0.8))  # floor beyond the run's end
        da, width = self._depth(a), self.run_length(a) + beyond
        eat_in = self.rng.uniform() < EAT_IN
        table = None
        if eat_in:
            spare = 2 * SEATING_CLEAR + 0.05
            length = float(self.rng.uniform(1.4, max(1.4, min(2.2, width - spare))))
            breadth = float(self.rng.uniform(0.9, 1.0))
            table = self.make("dining_table", length=round(length, 3), width=round(breadth, 3))
            depth = da + SEATING_WALK + table.size[1] + SEATING_CLEAR + float(self.rng.uniform(0.0, 0.3))
        else:
            depth = da + self.p["aisle"] + float(self.rng.uniform(0.1, 0.4))
        # laid out in a room with space for every filler (a fridge's door clearance: up to 0.45 m), then the room
        # as wide as the run came out and its spare: a fridge's clearance had pushed the last base run out
        self._room(width + 0.6 * len(a), depth)
        self.runs["north"] = self._runs(self.run_along(a, self.room.wall("north")))
        self.room.width = round(max(float(pl.hi[1]) for pl, _ in self.runs["north"]) + beyond, 4)
        if table is not None:
            # its long side to the run, SEATING_WALK from the run's front (a cook passes behind the diners)
            x = da + SEATING_WALK + table.size[1] / 2
            got = self.at(table, (x, self.room.width / 2), math.pi / 2)
            if got is not None:
                chairs_round(self, got)

    def galley(self, node, wine):
        a, b = self.cook_side(), self.sink_side(wine) + [self.base()]
        self._room(max(self.run_length(a), self.run_length(b)) + 0.5 + float(self.rng.uniform(0.3, 1.2)),
                   self._depth(a) + self.p["aisle"] + self._depth(b))
        self.runs["north"] = self._runs(self.run_along(a, self.room.wall("north")))
        self.runs["south"] = self._runs(self.run_along(b, self.room.wall("south"), start=0.25))

    def l_shape(self, node, wine):
        a, b = [self.base()] + self.sink_side(wine) + [self.base()], self.cook_side()
        da = self._depth(a)
        self._room(self.run_length(a) + 0.3 + float(self.rng.uniform(0.3, 1.0)),
                   da + 0.05 + self.run_length(b) + 0.3 + float(self.rng.uniform(0.6, 1.4)))
        self.runs["north"] = self._runs(self.run_along(a, self.room.wall("north")))
        west = self.room.wall("west")
        self.runs["west"] = self._runs(self.run_back(b[::-1], west, end=west.length - da - 0.05))

    def u_shape(self, node, wine):
        a, b, c = [self.base()] + self.sink_side(wine) + [self.base()], self.cook_side(), [self.base()]
        da, db, dc = self._depth(a), self._depth(b), self._depth(c)
        width = max(self.run_length(a) + 0.3, db + dc + self.p["aisle"] + 0.1)
        side = max(self.run_length(b), self.run_length(c)) + 0.3
        self._room(width, da + 0.05 + side + float(self.rng.uniform(0.5, 1.2)))
        north = self.room.wall("north")
        self.runs["north"] = self._runs(self.run_along(a, north, start=(width - self.run_length(a)) / 2))
        west, east = self.room.wall("west"), self.room.wall("east")
        self.runs["west"] = self._runs(self.run_back(b[::-1], west, end=west.length - da - 0.05))
        self.runs["east"] = self._runs(self.run_along(c, east, start=da + 0.05))

    def island(self, node, wine):
        a, isle = self.cook_side() + self.sink_side(wine), self.base()
        da, di = self._depth(a), isle.size[0]
        self._room(self.run_length(a) + 0.5 + float(self.rng.uniform(0.2, 0.8)),
                   da + self.p["aisle"] + di + SEATING_CLEAR + 0.4)
        self.runs["north"] = self._runs(self.run_along(a, self.room.wall("north")))
        x = da + self.p["aisle"] - isle.lo[0] * 0 + isle.hi[0]  # the island's front faces the run (yaw 180)
        y = self.room.width / 2
        got = self.at(isle, (x, y), math.pi)
        if got is not None:
            self.worktops.append(got)
            self.stools(got, along=(0.0, 1.0), facing=math.pi)

    def peninsula(self, node, wine):
        a, pen = self.cook_side() + self.sink_side(wine), self.base()
        da, dp = self._depth(a), pen.size[0]
        self._room(self.run_length(a) + 2.0 + dp + SEATING_CLEAR, da + 0.05 + pen.size[1] + self.p["aisle"] + 0.3)
        self.runs["north"] = self._runs(self.run_along(a, self.room.wall("north")))
        end = max((pl.hi[1] for pl, _ in self.runs["north"]), default=0.0)
        y_back = end + 0.05 + dp
        self.room.width = round(y_back + SEATING_CLEAR + 0.5, 4)
        # its back to the seating side (+Y), its front into the kitchen (-Y): yaw -90 degrees
        x, y = da + 0.05 - pen.lo[1], y_back + pen.lo[0]
        got = self.at(pen, (x, y), -math.pi / 2)
        if got is not None:
            self.worktops.append(got)
            self.stools(got, along=(1.0, 0.0), facing=-math.pi / 2)

    def stools(self, counter, along, facing):
        """Counter stools along the back of ``counter``, facing it, one per 0.6 m (NKBA: 24 in per seat)."""
        stool = self.make("bar_chair", seat_height=round(float(self.rng.uniform(*STOOL_SEAT)), 3))
        n = int((counter.hi - counter.lo)[0 if along[0] else 1] // 0.6)
        back = counter.pose[:3, :3] @ [-1.0, 0.0, 0.0]  # the counter's back direction
        centre = (counter.lo + counter.hi) / 2
        reach = (counter.hi - counter.lo)[1 if along[0] else 0] / 2 + stool.size[0] / 2 + 0.05
        for k in range(n):
            off = (k + 0.5 - n / 2) * 0.6
            for extra in (0.0, 0.05, 0.1, 0.15, 0.2):  # as close as its swivelling seat and back let it
                xy = centre[:2] + back[:2] * (reach + extra) + [along[0] * off, along[1] * off]
                if self.at(stool, xy, facing) is not None:
                    break

    # -- everything else -----------------------------------------------------------------------------------------
    def wall_units(self, node):
        gap = self.cabinet_params()["wall_gap"]
        for wall, run in self.runs.items():
            for placed, s in run:
                if placed.made.category == "kitchen_cabinet" and placed.made.size[1] >= 1.25:
                    width = round(float(placed.made.size[1]) - 0.05, 3)
                    # as tall as the ceiling lets its doors (a lift-up flap swings above it) open: else shorter
                    for height in (None, 0.75, 0.6):
                        unit = self.cabinet("wall_run", width=width, **({} if height is None else
                                                                        {"wall_height": height}))
                        if self.against(unit, self.room.wall(wall), s + 0.025, z=float(placed.hi[2]) + gap):
                            break

    def door(self, node):
        for wall in ("south", "east", "west", "north"):
            if self.embed(self.make("door"), self.room.wall(wall), rng=self.rng) is not None:
                return

    def window(self, node):
        window = self.make("window", height=round(float(self.rng.uniform(0.9, 1.2)), 3))
        z = float(self.rng.uniform(*SILL))
        for wall in self.rng.permutation(["east", "south", "west", "north"]):
            if self.embed(window, self.room.wall(str(wall)), z=z, rng=self.rng) is not None:
                return

    def _on_worktop(self, made, fixed: bool = False, open_top: bool = False):
        """``made`` on a worktop (the highest region first), or with ``open_top`` only on one with nothing of its
        cabinet above it (an appliance or a drainer stands on the worktop, not on a shelf inside a unit)."""
        return self.scatter(made, [w for w in self.worktops if w.made.category == "kitchen_cabinet"], self.rng,
                            prefer=lambda g: -g.z, fixed=fixed, where=(lambda g: g.clear is None) if open_top else None)

    def microwave(self, node):
        self._on_worktop(self.make("microwave"), open_top=True)

    def plate_rack(self, node):
        # fixed where it stands: its plates lean in their slots held by joint friction, which PhysX's
        # coefficient model gives only a fixed base (on a free rack they tip 1.4 degrees at rest)
        self._on_worktop(self.make("plate_rack"), fixed=True, open_top=True)

    def kettle(self, node):
        self._on_worktop(self.make("kettle", design="electric"), open_top=True)  # a stovetop one: on the range

    def toaster(self, node):
        self._on_worktop(self.make("toaster"), open_top=True)

    def coffee_machine(self, node):
        self._on_worktop(self.make("coffee_machine"), open_top=True)

    def bottle(self, node):
        self._on_worktop(self.make("bottle"))

    def jar(self, node):
        self._on_worktop(self.make("jar"))

    def cookware(self, node):
        """A pot or a pan on the range's cooktop where it has a steady one (an electric top), else beside it on
        the worktop (gas grates lift off: a loaded grate is not what the range's checks found)."""
        made = self.make(str(self.rng.choice(["pot", "pan"])))
        ranges = [w for w in self.worktops if w.made.category == "oven"]
        if not (ranges and self.scatter(made, ranges, self.rng, prefer=lambda g: -g.z)):
            self._on_worktop(made)


KIND = SceneKind("kitchen", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, KitchenLayout)
