"""Scenes: rooms of generated objects (``infmob scene``), their files, and the scene checks."""

from __future__ import annotations

import hashlib
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import infmob_usd
from infmob_usd.scenes import get_kind, kinds, save_scene, scene
from infmob_usd.scenes.room import boxes_overlap, moved_box
from infmob_usd.supports import support_regions

KITCHEN_LAYOUTS = ("single_wall", "galley", "l_shape", "u_shape", "island", "peninsula")


def _inside(s) -> list[str]:
    """Objects standing outside the room (walls excepted: doors and windows sit in them)."""
    r, out = s.room, []
    for p in s.placed:
        if p.on.startswith("wall:") and p.made.category in ("door", "window"):
            continue
        if np.any(p.lo[:2] < -1e-3) or p.hi[0] > r.depth + 1e-3 or p.hi[1] > r.width + 1e-3 or p.hi[2] > r.height:
            out.append(p.id)
    return out


def _overlapping(s) -> list[tuple[str, str]]:
    """Pairs of objects whose rest boxes overlap, but an item and what it stands on, and a chair pushed in
    under a table whose collision hulls clear the table's."""
    from infmob_usd.scenes.layout import SceneLayout

    out = []
    for i, a in enumerate(s.placed):
        for b in s.placed[i + 1:]:
            if a.on.startswith(b.id + ":") or b.on.startswith(a.id + ":"):
                continue
            if boxes_overlap(a.lo, a.hi, b.lo, b.hi):
                tucked = {a.made.category, b.made.category} == {"dining_table", "folding_chair"}
                if not (tucked and SceneLayout.hulls_clear(a, b, 0.0)):
                    out.append((a.id, b.id))
    return out


@pytest.mark.parametrize("layout", KITCHEN_LAYOUTS)
def test_each_kitchen_layout_has_its_units_in_the_room(layout):
    s = scene("kitchen", 3, texture_size=16, layout=layout)
    cats = [p.made.category for p in s.placed]
    assert s.params["layout"] == layout
    for needed in ("kitchen_cabinet", "oven", "dishwasher", "door"):
        assert needed in cats, (layout, cats)
    assert any(p.made.overrides.get("design") == "sink_base" for p in s.placed), layout
    assert not _inside(s), _inside(s)
    assert not _overlapping(s), _overlapping(s)
    # one kitchen, one set of cabinets: every cabinet is the same seed (the same fronts and worktop)
    assert len({p.made.seed for p in s.placed if p.made.category == "kitchen_cabinet"}) == 1
    # the range's cooktop and the worktops at one height
    tops = {round(float(p.made.obj.params["base_height"]), 6) for p in s.placed if p.made.category == "kitchen_cabinet"
            and p.made.overrides.get("design") != "wall_run"}
    assert tops == {round(s.params["worktop_height"], 6)} or tops == {round(s.params["worktop_height"], 3)}


def test_facing_runs_keep_the_work_aisle():
    s = scene("kitchen", 5, texture_size=16, layout="galley")
    north = [p for p in s.placed if p.wall == "north" and p.on == "floor"]
    south = [p for p in s.placed if p.wall == "south" and p.on == "floor"]
    assert north and south
    aisle = min(p.lo[0] for p in south) - max(p.hi[0] for p in north)
    assert aisle >= 1.07 - 1e-6, aisle  # NKBA's one-cook work aisle


@pytest.mark.parametrize("kind", ["dining_room", "office", "bathroom"])
def test_other_rooms_place_their_furniture(kind):
    need = {"dining_room": "dining_table", "office": "office_chair", "bathroom": "toilet"}[kind]
    for seed in range(3):
        s = scene(kind, seed, texture_size=16)
        assert need in [p.made.category for p in s.placed], (kind, seed)
        assert not _inside(s) and not _overlapping(s), (kind, seed, _inside(s), _overlapping(s))


def test_items_stand_on_a_support_region_of_their_host():
    s = scene("kitchen", 1, texture_size=16)
    items = [p for p in s.placed if not p.fixed]
    assert items
    by_id = {p.id: p for p in s.placed}
    for item in items:
        host_id, link = item.on.split(":")
        host = by_id[host_id]
        tops = [host.region_in_room(g)[0][2] for g in host.made.regions if g.link == link]
        assert any(abs(item.lo[2] - z) < 1e-3 for z in tops), (item.id, item.lo[2], tops)


def _into_host(s) -> list[str]:
    """Free items whose rest box cuts into a collision hull of their host (a sink's rim, a tap's base)."""
    by_id = {p.id: p for p in s.placed}
    out = []
    for item in (p for p in s.placed if not p.fixed):
        host = by_id[item.on.split(":")[0]]
        lo, hi = moved_box(item.lo, item.hi, np.linalg.inv(host.pose))  # the item's box in the host's frame
        hulls = [np.asarray(c, float) + link.origin for link in host.made.obj.links for piece in link.pieces
                 for c in piece.convex if len(c) >= 4]
        h_lo, h_hi = np.array([h.min(0) for h in hulls]), np.array([h.max(0) for h in hulls])
        cut = np.all(np.minimum(hi - 1e-6, h_hi) - np.maximum(lo + 1e-6, h_lo) > 0, axis=1)
        if cut.any():
            out.append(item.id)
    return out


@pytest.mark.parametrize(("kind", "seed"), [("bathroom", 0), ("bathroom", 9), ("kitchen", 1)])
def test_items_are_set_down_clear_of_what_rises_from_their_support(kind, seed):
    # a bottle set over the 2 mm sink rim started inside it: pushed out, its cap flew off its seat and it
    # stood tilted, its pump head turning under its own weight
    s = scene(kind, seed, texture_size=16)
    assert not _into_host(s), _into_host(s)


def test_a_bathroom_with_bottles_by_the_sink_rests(tmp_path):
    from infmob_usd.validate.scene import check_scene

    folder = save_scene(scene("bathroom", 9, texture_size=16), tmp_path)
    rest = {r.name: r for r in check_scene(folder, reach=False)}["scene_rest"]
    assert rest.ok, rest.detail


def _digests(folder: Path) -> dict[str, str]:
    return {str(p.relative_to(folder)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(folder.rglob("*")) if p.is_file() and ".thumbs" not in p.parts}


def test_same_kind_seed_and_overrides_give_the_same_files(tmp_path):
    a = save_scene(scene("bathroom", 4, texture_size=16), tmp_path / "a")
    b = save_scene(scene("bathroom", 4, texture_size=16), tmp_path / "b")
    assert _digests(a) == _digests(b)
    assert _digests(a) != _digests(save_scene(scene("bathroom", 5, texture_size=16), tmp_path / "c"))


def test_scene_files_reference_each_object_once(tmp_path):
    from pxr import Usd, UsdPhysics

    folder = save_scene(scene("kitchen", 2, texture_size=16), tmp_path)
    rec = json.loads((folder / "scene.json").read_text())
    stage = Usd.Stage.Open(str(folder / "scene.usda"))
    assert len([p for p in stage.Traverse() if p.IsA(UsdPhysics.Scene)]) == 1
    roots = [p for p in stage.Traverse() if p.HasAPI(UsdPhysics.ArticulationRootAPI)]
    assert len(roots) == len(rec["objects"])
    written = sorted(p.parent.name for p in (folder / "objects").glob("*/*/metadata.json"))
    assert len(written) == len({o["folder"] for o in rec["objects"]})
    # a free item's tie to the world is switched off in the scene; a fixed unit's is not
    for o in rec["objects"]:
        prim = stage.GetPrimAtPath(f"/Scene/Objects/{o['id']}")
        joints = [p for p in Usd.PrimRange(prim) if p.IsA(UsdPhysics.FixedJoint)
                  and not UsdPhysics.Joint(p).GetBody0Rel().GetTargets()]
        assert joints, o["id"]
        enabled = [UsdPhysics.Joint(j).GetJointEnabledAttr().Get() for j in joints]
        assert all(enabled) == o["fixed"], (o["id"], enabled)


def test_a_bathroom_loads_rests_and_every_joint_opens_in_the_room(tmp_path):
    from infmob_usd.validate.scene import check_scene

    folder = save_scene(scene("bathroom", 1, texture_size=16), tmp_path)
    results = check_scene(folder, reach=True)
    assert [r.name for r in results] == ["scene_load", "scene_overlap", "scene_rest", "scene_reach"]
    assert all(r.ok for r in results), [(r.name, r.detail) for r in results if not r.ok]


def test_the_overlap_check_finds_a_unit_pushed_into_the_wall(tmp_path):
    """Move a kitchen unit so its back is in the wall: the overlap check names it and the room."""
    folder = save_scene(scene("kitchen", 2, texture_size=16, layout="single_wall"), tmp_path)
    rec = json.loads((folder / "scene.json").read_text())
    unit = next(o for o in rec["objects"] if o["category"] == "kitchen_cabinet")
    unit["position"][0] -= 0.15  # 15 cm back: a sink base is open at the back, its hulls start ~8 cm in
    from infmob_usd.validate.scene import _overlaps, load_sapien_scene

    sim, contexts = load_sapien_scene(folder, rec)
    found = _overlaps(sim, contexts)
    assert any(unit["id"] in f and "room" in f for f in found), found


def test_support_regions_find_worktops_and_shelves():
    cab = infmob_usd.generate("kitchen_cabinet", 5, texture_size=16, design="base_run", base_height=0.9)
    regions = support_regions(cab)
    assert abs(regions[0].z - 0.9) < 0.005 and regions[0].clear is None  # the worktop, open above
    rack = infmob_usd.generate("storage_rack", 3, texture_size=16, design="shelving", shelf_levels=5)
    shelves = {round(g.z, 3) for g in support_regions(rack) if g.clear is not None}
    assert len(shelves) >= 3, shelves


def test_every_kind_documents_its_parameters():
    for name, kind in kinds().items():
        assert kind.schema.names, name
        assert get_kind(name) is kind


def test_cli_scene_writes_a_scene_and_refuses_a_bad_parameter(tmp_path):
    run = [sys.executable, "-m", "infmob_usd", "scene", "bathroom", "--seed", "2", "--texture-size", "16",
           "--out", str(tmp_path)]
    ok = subprocess.run(run, capture_output=True, text=True, timeout=600)
    assert ok.returncode == 0, ok.stderr
    assert (tmp_path / "bathroom_000002" / "scene.usda").is_file()
    bad = subprocess.run(run + ["--set", "width=9"], capture_output=True, text=True, timeout=120)
    assert bad.returncode == 2 and len(bad.stderr.strip().splitlines()) == 1, bad.stderr
    assert "width" in bad.stderr
    unknown = subprocess.run([sys.executable, "-m", "infmob_usd", "scene", "garage"], capture_output=True, text=True)
    assert unknown.returncode == 2 and "kitchen" in unknown.stderr, unknown.stderr


def test_the_recipes_of_docs_scenes_run(tmp_path):
    """docs/scenes.md's three loading recipes (USD, SAPIEN, MuJoCo), each on a real scene."""
    import re

    folder = save_scene(scene("kitchen", 3, texture_size=16), tmp_path)
    text = (Path(__file__).resolve().parents[1] / "docs" / "scenes.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text.split("## Using a scene", 1)[1], re.S)
    assert len(blocks) == 3
    for code in blocks:
        code = code.replace("DIR/kitchen_000003", str(folder))
        exec(compile(code, "docs/scenes.md", "exec"), {})


def _gap(a, b) -> float:
    """Horizontal distance between two placed objects' rest boxes (0 where their footprints overlap)."""
    d = np.maximum(np.maximum(a.lo[:2] - b.hi[:2], b.lo[:2] - a.hi[:2]), 0.0)
    return float(np.hypot(*d))


def test_nothing_stands_in_the_walkway_round_a_dining_table():
    # NKBA: 36 in (0.91 m) from the table's edge to any obstruction behind a seated diner (a floor lamp was 0.34 m
    # from the table's side in seed 0)
    s = scene("dining_room", 0, texture_size=16)
    table = next(p for p in s.placed if p.made.category == "dining_table")
    near = [(p.id, round(_gap(p, table), 2)) for p in s.placed if p is not table and p.on == "floor"
            and p.lo[2] < 1.2 and _gap(p, table) < 0.91 - 1e-3 and p.made.category != "folding_chair"]
    assert not near, near


def test_a_clearance_keeps_other_furniture_out_of_its_floor_space():
    from infmob_usd.scenes.layout import CLEARANCES, Made, Placed, SceneLayout
    from infmob_usd.scenes.room import Room, pose_matrix

    def made(category, size):
        lo, hi = np.array([-size[0] / 2, -size[1] / 2, 0.0]), np.array([size[0] / 2, size[1] / 2, size[2]])
        return Made(category, category, 0, {}, None, lo, hi, [], [], (np.zeros((0, 3)), np.zeros((0, 3))),
                    CLEARANCES.get(category))

    layout = SceneLayout("test", {}, np.random.default_rng(0), np.random.default_rng(0), 16, None)
    layout.room = Room(4.0, 4.0, 2.5, 0.12)
    toilet = layout.keep(Placed("toilet_0", made("toilet", (0.7, 0.4, 0.8)), pose_matrix((0.4, 2.0, 0.0), 0.0),
                                True, "floor"))
    assert toilet is not None
    bin_ = made("trash_can", (0.3, 0.3, 0.4))
    # 0.5 m in front of the toilet (NKBA: 0.76 m clear), beside it within 0.38 m of its centreline: refused
    assert layout.fits(Placed("a", bin_, pose_matrix((0.75 + 0.5, 2.0, 0.0), 0.0), True, "floor")) is False
    assert layout.fits(Placed("b", bin_, pose_matrix((0.4, 2.0 + 0.2 + 0.15 + 0.1, 0.0), 0.0), True, "floor")) is False
    # clear of both: kept
    assert layout.fits(Placed("c", bin_, pose_matrix((0.4, 2.0 + 0.38 + 0.16, 0.0), 0.0), True, "floor")) is True


def test_an_item_set_down_opens_clear_of_its_host():
    # a plate rack set on a shelf inside a base cabinet: its drip tray slid into the closed door (scene_reach
    # of kitchen seed 2, single wall: stopped at 88 %)
    from infmob_usd.scenes.layout import _clear_of_host

    s = scene("kitchen", 2, texture_size=16, layout="single_wall")
    by_id = {p.id: p for p in s.placed}
    blocked = []
    for item in s.placed:
        host = by_id.get(item.on.split(":")[0])
        if host is None:
            continue
        local = np.linalg.inv(host.pose) @ item.pose
        for group, lo, hi in item.made.swept:
            if not _clear_of_host(host.made, *moved_box(lo, hi, local)):
                blocked.append((item.id, group))
    assert not blocked, blocked


def test_a_swivel_seat_sweeps_its_turn_when_placed():
    # a counter stool's swivel seat (continuous) was left out of the swept boxes: its arms hit the island's back
    # at 31 degrees in scene_reach (kitchen seed 2, island and peninsula)
    from infmob_usd.scenes.layout import _measure

    chair = infmob_usd.generate("bar_chair", 0, texture_size=16)
    seat = next(j for j in chair.movable_joints if j.type == "continuous")
    lo, hi, swept, _ = _measure(chair)
    turned = [b for g, *b in swept if g == seat.group]
    assert turned, [g for g, *_ in swept]
    # a seat wider one way than the other reaches further out turned than at rest
    assert np.all(turned[0][0][:2] <= lo[:2] + 1e-9) and np.all(turned[0][1][:2] >= hi[:2] - 1e-9)


UNDER_COUNTER = ("dishwasher", "beverage_fridge")


def _base_runs(s) -> list[list]:
    """Each stretch of a wall's floor units that one worktop covers: base cabinets and the under-counter
    appliances between them, split at a range or a fridge (in order along the wall)."""
    by_wall: dict[str, list] = {}
    for p in s.placed:
        if p.on == "floor" and p.wall is not None:
            by_wall.setdefault(p.wall, []).append(p)
    out = []
    for wall, units in by_wall.items():
        k = int(np.argmax(np.abs(s.room.wall(wall).along[:2])))
        stretch = []
        for p in sorted(units, key=lambda p: float(p.lo[k])) + [None]:
            if p is not None and p.made.category in ("kitchen_cabinet", *UNDER_COUNTER):
                stretch.append(p)
                continue
            if any(q.made.category in UNDER_COUNTER for q in stretch):
                out.append((k, stretch))
            stretch = []
    return out


@pytest.mark.parametrize(("seed", "layout"), [(0, "u_shape"), (3, "peninsula"), (2, "galley")])
def test_a_base_run_carries_one_worktop_over_its_under_counter_appliances(seed, layout):
    # the cabinets' worktops stopped at the dishwasher and the wine cooler: a gap in the counter the width of
    # each appliance (and of each filler strip), where a real worktop is one slab the appliances slide under
    from infmob_usd.categories.rooms.kitchen import _worktop_box

    s = scene("kitchen", seed, texture_size=16, layout=layout)
    runs = _base_runs(s)
    assert runs, [p.id for p in s.placed]
    fixtures = [(f.lo, f.hi) for f in getattr(s.room, "fixtures", [])]
    for k, stretch in runs:
        tops = [_worktop_box(p) for p in stretch if p.made.category == "kitchen_cabinet"] + [
            (lo, hi) for lo, hi in fixtures if lo[k] < stretch[-1].hi[k] and hi[k] > stretch[0].lo[k]]
        z = {round(float(hi[2]), 4) for _, hi in tops}
        assert z == {round(float(tops[0][1][2]), 4)}, z  # one height
        # the worktop's top surface covers the stretch end to end, no gap over 3 mm
        reach, gaps = float(stretch[0].lo[k]), []
        for lo, hi in sorted(tops, key=lambda b: float(b[0][k])):
            if lo[k] - reach > 0.003:
                gaps.append((round(reach, 3), round(float(lo[k]), 3)))
            reach = max(reach, float(hi[k]))
        if stretch[-1].hi[k] - reach > 0.003:
            gaps.append((round(reach, 3), round(float(stretch[-1].hi[k]), 3)))
        assert not gaps, (seed, layout, [p.id for p in stretch], gaps)
        # each appliance slides under it, clear of it
        for p in stretch:
            if p.made.category in UNDER_COUNTER:
                assert p.hi[2] < min(lo[2] for lo, _ in tops) - 0.002, (p.id, p.hi[2])
    for lo, hi in fixtures:  # and no fixture stands in a placed object
        assert not [p.id for p in s.placed if boxes_overlap(lo, hi, p.lo, p.hi)]


def test_a_scene_made_in_a_pool_is_the_same_files(tmp_path):
    # with fewer scenes than workers, one scene's objects are made and written in parallel: the files must
    # not depend on which worker made what, or in what order they finished
    from concurrent.futures import ProcessPoolExecutor

    a = save_scene(scene("kitchen", 2, texture_size=16), tmp_path / "a")
    with ProcessPoolExecutor(2) as pool:
        b = save_scene(scene("kitchen", 2, texture_size=16, pool=pool), tmp_path / "b", pool=pool)
    assert _digests(a) == _digests(b)
    out = tmp_path / "cli"
    cmd = [sys.executable, "-m", "infmob_usd", "scene", "bathroom", "--seed", "4", "--texture-size", "16",
           "--workers", "2", "--out", str(out)]
    assert subprocess.run(cmd, capture_output=True, text=True).returncode == 0
    assert _digests(out / "bathroom_000004") == _digests(save_scene(scene("bathroom", 4, texture_size=16),
                                                                      tmp_path / "one"))


@pytest.mark.parametrize("seed", [1, 3])
def test_chairs_stand_round_a_dining_table_facing_it_pushed_in(seed):
    # NKBA 17: 24 in (0.61 m) of table edge per diner; each chair faces the table, its front at most 0.25 m
    # from the edge (pushed in as far as its hulls, and its folding seat, clear the table's)
    from infmob_usd.scenes.layout import SceneLayout

    s = scene("dining_room", seed, texture_size=16)
    table = next(p for p in s.placed if p.made.category == "dining_table")
    chairs = [p for p in s.placed if p.made.category == "folding_chair"]
    size = table.hi - table.lo
    assert len(chairs) >= 2 * int(max(size[0], size[1]) // 0.61), (seed, len(chairs))
    assert len({c.made.key for c in chairs}) == 1  # one set
    centre = (table.lo + table.hi)[:2] / 2
    sides = set()
    for c in chairs:
        front = c.pose[:2, :2] @ [1.0, 0.0]
        to_table = centre - c.pose[:2, 3]
        axis = int(np.argmax(np.abs(front)))
        assert np.sign(front[axis]) == np.sign(to_table[axis]) and abs(front[axis]) > 0.999, c.id
        tip = c.pose[:2, 3] + front * c.made.hi[0]
        beyond = max(table.lo[0] - tip[0], tip[0] - table.hi[0], table.lo[1] - tip[1], tip[1] - table.hi[1])
        assert -0.07 < beyond <= 0.25 + 1e-6, (c.id, beyond)
        assert SceneLayout.hulls_clear(c, table, 0.0), c.id
        sides.add((axis, np.sign(front[axis])))
    # both long sides; an end only where the table's extension leaves room (seed 3's slides 0.4 m out)
    assert len(sides) >= (3 if seed == 1 else 2), sides
    assert not _overlapping(s), _overlapping(s)


def test_a_dining_table_is_sized_to_the_room():
    # a 3.6 x 3.6 m room cannot keep NKBA's 0.91 m round a 2.4 m table: seed 4 drew one and had no table at all
    s = scene("dining_room", 4, texture_size=16)
    table = next((p for p in s.placed if p.made.category == "dining_table"), None)
    assert table is not None
    assert min(table.lo[0], table.lo[1], s.room.depth - table.hi[0], s.room.width - table.hi[1]) >= 0.91 - 1e-3


def _front(p) -> float:
    """How far ``p``'s pieces but its handles reach from the wall its back is to (at rest)."""
    obj = p.made.obj
    poses = obj.poses({j.name: j.lower for j in obj.movable_joints})
    wall = {"north": (0, 1), "south": (0, -1), "west": (1, 1), "east": (1, -1)}[p.wall]
    reach = []
    for link in obj.links:
        for piece in link.pieces:
            if piece.material != "handle":
                lo, hi = moved_box(*piece.bounds, p.pose @ poses[link.name])
                reach.append(hi[wall[0]] if wall[1] > 0 else -lo[wall[0]])
    return float(max(reach))


@pytest.mark.parametrize("seed", [6, 7, 8])
def test_under_counter_appliances_stand_flush_with_the_cabinet_fronts(seed):
    # an integrated dishwasher's niche is the carcass depth, its decor board a cabinet front (Bosch, Miele
    # installation sheets): drawn 0.52-0.66 m deep, seed 8's stood 75 mm proud of its run, seed 6's 76 mm
    # back, seed 7's wine cooler 52 mm proud
    s = scene("kitchen", seed, texture_size=16)
    under = [p for p in s.placed if p.made.category in ("dishwasher", "beverage_fridge")]
    assert under
    for p in under:
        flush = max(_front(c) for c in s.placed if c.wall == p.wall and c.on == "floor"
                    and c.made.category == "kitchen_cabinet")
        assert abs(_front(p) - flush) <= 0.006, (p.id, _front(p), flush)


@pytest.mark.parametrize("seed", [0, 2])
def test_a_single_wall_kitchen_is_an_aisle_deep_or_eats_in(seed):
    # one run and 0.8-1.6 m of bare floor beyond its aisle looked empty: the room is either only the run and
    # its work aisle deep, or an eat-in kitchen with a table and chairs NKBA's 44 in (1.12 m) from the run
    s = scene("kitchen", seed, texture_size=16, layout="single_wall")
    run = [p for p in s.placed if p.wall == "north" and p.on == "floor"]
    front = max(p.hi[0] for p in run)
    table = next((p for p in s.placed if p.made.category == "dining_table"), None)
    if table is None:
        assert s.room.depth - front <= s.params["aisle"] + 0.4 + 1e-6, (s.room.depth, front)
    else:
        assert table.lo[0] - front >= 1.12 - 0.03, (table.lo[0], front)  # the cabinets' handles stand 25 mm out
        assert sum(p.made.category == "folding_chair" for p in s.placed) >= 4
        assert not _overlapping(s), _overlapping(s)
    assert [p.made.category for p in run][-1] in ("refrigerator", "kitchen_cabinet")


def test_a_carried_worktop_wears_the_cabinets_worktop_material(tmp_path):
    # the slab over a dishwasher was a flat-coloured box, paler than the wood or stone worktops beside it
    from pxr import Sdf, Usd, UsdGeom, UsdShade

    folder = save_scene(scene("kitchen", 0, texture_size=16), tmp_path)
    rec = json.loads((folder / "scene.json").read_text())
    slabs = [b for b in rec["room"]["boxes"] if b["name"].startswith("worktop_")]
    assert slabs
    stage = Usd.Stage.Open(str(folder / "scene.usda"))
    for box in slabs:
        cabinet = next(o for o in rec["objects"] if o["id"] == box["wears"]["object"])
        assert cabinet["category"] == "kitchen_cabinet" and box["wears"]["slot"] == "top"
        prim = stage.GetPrimAtPath(f"/Scene/Room/{box['name']}")
        assert prim.IsA(UsdGeom.Mesh) and UsdGeom.PrimvarsAPI(prim).GetPrimvar("st").HasValue()
        extent = np.array(UsdGeom.Mesh(prim).ComputeLocalBound(0, "default").ComputeAlignedRange().GetSize())
        assert np.allclose(extent, np.subtract(box["max"], box["min"]), atol=1e-4)
        material, _ = UsdShade.MaterialBindingAPI(prim).ComputeBoundMaterial()
        files = {Path(a.Get().resolvedPath) for s in material.GetPrim().GetChildren() for a in s.GetAttributes()
                 if a.GetTypeName() == Sdf.ValueTypeNames.Asset and a.Get() is not None}
        assert folder / cabinet["folder"] / "textures" / "top_basecolor.png" in files, files


@pytest.mark.parametrize("seed", [4])
def test_a_single_wall_run_is_as_long_as_real_ones(seed):
    # one-wall kitchens run 2.4-4.5 m (8-15 ft): the sink base's 1-5 drawn columns beside two plain runs made
    # walls of 7-9 m; the units are sized to a drawn length, and the sink base gets one column
    s = scene("kitchen", seed, texture_size=16, layout="single_wall")
    run = [p for p in s.placed if p.wall == "north" and p.on == "floor"]
    length = max(p.hi[1] for p in run) - min(p.lo[1] for p in run)
    assert 2.4 <= length <= 5.0, length  # 4.5 m of units, a fridge's door clearance and a filler strip
    cats = [p.made.category for p in run]
    for needed in ("kitchen_cabinet", "oven", "dishwasher"):
        assert needed in cats, cats
    sink = next(p for p in run if p.made.overrides.get("design") == "sink_base")
    assert sink.made.obj.params["column_count"] == 1
    # NKBA landing: counter on both sides of the range (seed 4's fridge clearance pushed the base run out)
    order = sorted(run, key=lambda p: float(p.lo[1]))
    k = [p.made.category for p in order].index("oven")
    assert 0 < k < len(order) - 1, cats


@pytest.mark.parametrize("seed", [0, 8])
def test_a_dining_room_has_its_sideboard_with_a_walkway_to_the_table(seed):
    # placed after the table and its chairs, a 0.55-0.62 m deep sideboard found no wall outside the table's
    # 0.91 m walkway and its drawers' travel: no dining room of seeds 0-9 had one. Now placed first, on a wall
    # that leaves the table NKBA's 44 in (1.12 m) to it, where one walks behind the diners
    s = scene("dining_room", seed, texture_size=16, has_sideboard=True)
    board = next((p for p in s.placed if p.made.category == "kitchen_cabinet"), None)
    assert board is not None
    assert board.on == "floor" and board.wall is not None
    table = next(p for p in s.placed if p.made.category == "dining_table")
    assert _gap(board, table) >= 1.12 - 1e-3, _gap(board, table)
    chairs = [p for p in s.placed if p.made.category == "folding_chair"]
    size = table.hi - table.lo
    assert len(chairs) >= 2 * int(max(size[0], size[1]) // 0.61), len(chairs)
    assert not _overlapping(s), _overlapping(s)


def test_every_bathroom_has_its_vanity():
    # the vanity was drawn with the category's 1-5 columns, 12 seeds at one under 1.6 m: seed 4 found none and
    # had no basin at all; it is a sink base with one column (1.2-1.4 m)
    s = scene("bathroom", 4, texture_size=16)
    vanity = [p for p in s.placed if p.made.overrides.get("design") == "sink_base"]
    assert len(vanity) == 1 and vanity[0].on == "floor" and vanity[0].wall is not None
    assert vanity[0].made.obj.params["column_count"] == 1
    assert 1.2 - 1e-3 <= vanity[0].made.size[1] <= 1.45


@pytest.mark.parametrize("seed", [4, 9])
def test_every_dining_room_has_its_door(seed):
    # a table 0.91 m off a wall to the millimetre kept its walkway over the door's casing (seed 4), and the chairs
    # round it left no spot a door's swing cleared (seed 9): two rooms of ten had no door
    from infmob_usd.scenes.layout import SceneLayout

    s = scene("dining_room", seed, texture_size=16)
    doors = [p for p in s.placed if p.made.category == "door"]
    assert len(doors) == 1
    table = next(p for p in s.placed if p.made.category == "dining_table")
    for c in (p for p in s.placed if p.made.category == "folding_chair"):
        assert SceneLayout.hulls_clear(c, table, 0.0), c.id
        assert not any(boxes_overlap(lo, hi, c.lo, c.hi) for _, lo, hi in doors[0].swept_boxes()), c.id
    assert not _overlapping(s), _overlapping(s)


@pytest.mark.parametrize("seed", [0, 2])
def test_moving_parts_keep_a_gap_off_the_walls(seed):
    # a single-wall run without a fridge began with the dishwasher (seed 2) or the wine cooler (seed 0) flush
    # against the side wall: its door dragged on the wall and stopped 0-25 % open in SAPIEN (scene_reach); the
    # first unit gets a filler strip. Checked at rest too: the wine cooler's door swings away from the wall
    from infmob_usd.scenes.layout import WALL_GAP

    s = scene("kitchen", seed, texture_size=16, layout="single_wall")
    r = s.room
    for p in s.placed:
        if p.on.startswith("wall:") and p.made.category in ("door", "window"):
            continue
        for group, lo, hi in p.moving_boxes():
            assert min(lo[0], lo[1], r.depth - hi[0], r.width - hi[1]) >= WALL_GAP - 1e-3, (p.id, group)
        obj = p.made.obj
        rest = obj.poses({j.name: j.lower for j in obj.movable_joints})
        for link in (lk for lk in obj.links if any(j.child == lk.name for j in obj.movable_joints)):
            for piece in link.pieces:
                lo, hi = moved_box(*piece.bounds, p.pose @ rest[link.name])
                assert min(lo[0], lo[1], r.depth - hi[0], r.width - hi[1]) >= WALL_GAP - 1e-3, (p.id, link.name)
