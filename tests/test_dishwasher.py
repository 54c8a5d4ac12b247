"""The dishwasher category: parts, joints, clearances at joint states, door at rest, overrides, seeds."""

from __future__ import annotations

import math

import numpy as np
import pytest

from infmob_usd.materials.families import FAMILIES, split_spec
from infmob_usd.model import build as build_model

from collide import contacts, overlap
from helpers import maker
from zoo import by_child, movable

SEEDS = range(5)
VOL = 1e-7  # m^3: the validators' contact volume


# a built-in door model (``integrated`` on odd seeds, ``freestanding`` on even ones) unless ``design`` says
# otherwise: the tests below check its door and racks; the other designs have their own tests
make = maker("dishwasher", design=lambda seed: ("freestanding", "integrated")[seed % 2])


def at(j, f):
    """Value of a (one-DoF) joint at fraction ``f``; states are ``Blueprint.poses`` keys ``(child, 0)``."""
    return j.dofs[0].lower + f * (j.dofs[0].upper - j.dofs[0].lower)


def opened(bp, q):
    """``q`` with the door fully open when a rack behind it moves (as the validator does)."""
    out = dict(q)
    for j in bp.joints:
        if j.requires_open and q.get((j.child, 0), 0.0) != 0.0:
            out[(j.requires_open, 0)] = by_child(bp, j.requires_open).dofs[0].upper
    return out


# -- parts, labels, materials -------------------------------------------------------

LABELS = {"body", "door", "rack", "basket", "control_panel", "button", "tines", "shelf"}


@pytest.mark.parametrize("seed", SEEDS)
def test_parts_labels_and_materials(seed):
    p, bp = make(seed)
    assert bp.root == "body"
    assert bp.parts["body"].label == "body" and bp.parts["door"].label == "door"
    assert {part.label for part in bp.parts.values()} <= LABELS
    racks = [n for n, part in bp.parts.items() if part.label == "rack"]
    assert len(racks) == p["rack_count"]
    assert ("control_panel" in bp.parts) == p["has_control_panel"]
    assert any(pc.name == "handle" for pc in bp.parts["door"].pieces) == p["has_handle"]
    baskets = [n for n, part in bp.parts.items() if part.label == "basket"]
    for n in baskets:  # a cutlery basket lifts straight up out of the lowest rack
        j = by_child(bp, n)
        assert j.kind == "prismatic" and j.parent == "rack_0" and j.dofs[0].axis == pytest.approx((0, 0, 1))
        assert 0.01 < j.dofs[0].upper <= p["basket_lift"]
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    links, _ = build_model(bp, {k: 1000.0 for k in bp.materials})
    assert all(link.mass > 0 for link in links)


@pytest.mark.parametrize("seed", SEEDS)
def test_size_and_hollow_tub(seed):
    p, bp = make(seed)
    lo, hi = bp.bounds()
    assert lo[2] == pytest.approx(0.0, abs=1e-9)
    assert hi[2] == pytest.approx(p["height"], abs=1e-6)
    assert hi[1] - lo[1] == pytest.approx(p["width"], abs=1e-6)
    liner = np.array([pc.bounds for pc in bp.parts["body"].pieces if pc.material == "tub"])
    centre = (liner[:, 0].min(0) + liner[:, 1].max(0)) / 2
    for pc in bp.parts["body"].pieces:
        for c in pc.convex:
            assert not ((c.min(0) < centre) & (centre < c.max(0))).all()


# -- joints ------------------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_joint_kinds_axes_limits(seed):
    p, bp = make(seed)
    door = by_child(bp, "door")
    d = door.dofs[0]
    assert door.kind == "revolute" and door.parent == "body"
    assert d.axis == pytest.approx((0, 1, 0))
    assert (d.lower, d.upper) == (0.0, pytest.approx(math.pi / 2))
    leaf = np.array([pc.bounds for pc in bp.parts["door"].pieces if pc.name != "handle"
                     and pc.material != "front"])  # the machine door; a cabinet front hangs on it
    assert d.origin[0] == pytest.approx(leaf[:, 1, 0].max())  # front face ...
    assert d.origin[2] == pytest.approx(leaf[:, 0, 2].min())  # ... bottom edge
    assert d.origin[2] >= p["kick_height"]  # above the plinth
    for j in movable(bp):
        r = j.dofs[0]
        # racks are behind the door: they slide once it is open; nothing else waits for it
        label = bp.parts[j.child].label
        assert j.requires_open == ("door" if label == "rack" else None), j.child
        if label in ("tines", "shelf"):  # fold-down tines and cup shelves turn a quarter turn about X in a rack
            assert j.kind == "revolute" and bp.parts[j.parent].label == "rack"
            assert abs(r.axis[0]) == pytest.approx(1.0) and (r.lower, r.upper) == (0.0, pytest.approx(math.pi / 2))
        elif label == "rack":
            assert j.kind == "prismatic" and j.parent == "body"
            assert r.axis == pytest.approx((1, 0, 0)) and r.lower == 0.0 and r.upper > 0.2
        elif j.child.startswith("button_"):
            assert j.kind == "prismatic" and j.parent == "control_panel"
            assert r.axis == pytest.approx((-1, 0, 0)) and 0 < r.upper < 0.004
    assert by_child(bp, "control_panel").kind == "fixed" if "control_panel" in bp.parts else True


def test_door_falls_forward_and_rests_shut():
    _, bp = make(0)
    pose = bp.poses({("door", 0): math.pi / 2})["door"]
    pts = np.vstack([pc.vertices for pc in bp.parts["door"].pieces if pc.name != "handle"])
    moved = pts @ pose[:3, :3].T + pose[:3, 3]
    assert np.ptp(moved[:, 2]) < 0.1 and moved[:, 0].max() > pts[:, 0].max() + 0.5  # flat, in front
    # centre of mass of the door subtree behind the hinge line: gravity presses it shut
    densities = {k: FAMILIES[split_spec(v)[0]].density for k, v in bp.materials.items()}
    links, _ = build_model(bp, densities)
    hinge_x = by_child(bp, "door").dofs[0].origin[0]
    sub = {"door", "control_panel", *(n for n in bp.parts if n.startswith("button_"))}
    masses = [(lk.mass, lk.origin + lk.com) for lk in links if lk.name in sub]
    com = sum(m * c for m, c in masses) / sum(m for m, _ in masses)
    assert com[0] < hinge_x - 0.005


# -- clearances ----------------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_no_contacts_at_sampled_states(seed):
    _, bp = make(seed)
    js = movable(bp)
    states = [{}]
    states += [{(j.child, 0): at(j, f) for j in js} for f in (0.5, 1.0)]
    states += [{(j.child, 0): at(j, f)} for j in js if not j.child.startswith("button") for f in (0.5, 1.0)]
    for q in states:
        assert not contacts(bp, opened(bp, q)), q


@pytest.mark.parametrize("seed", SEEDS)
def test_the_door_is_solid(seed):
    """Front skin, core and inner skin all collide, each over the whole leaf: a rack pulled out
    through the shut door meets the door (open it first), and nothing else."""
    p, bp = make(seed)
    leaf = [pc for pc in bp.parts["door"].pieces if pc.name != "handle" and pc.material != "front"]
    assert all(pc.convex for pc in leaf)
    lo = np.min([pc.bounds[0] for pc in leaf], axis=0)
    hi = np.max([pc.bounds[1] for pc in leaf], axis=0)
    hulls = [(c.min(0), c.max(0)) for pc in leaf for c in pc.convex]
    # a skin at the front, one at the back, and the core between: each spans the leaf's face
    back = hi[0] - p["door_thickness"]  # the inner skin's back face (the dispenser stands proud)
    for x in (hi[0] - 0.0005, hi[0] - p["door_thickness"] / 2, back + 0.0005):
        spans = [(a, b) for a, b in hulls if a[0] <= x <= b[0]]
        assert any(a[1] <= lo[1] + 0.011 and b[1] >= hi[1] - 0.011 and a[2] <= lo[2] + 0.011
                   and b[2] >= hi[2] - 0.011 for a, b in spans), x
    for j in movable(bp):
        if bp.parts[j.child].label == "rack":
            hit = {frozenset((a, b)) for a, b, _ in contacts(bp, {(j.child, 0): at(j, 1.0)})}
            assert hit and all("door" in pair for pair in hit), hit
            assert not contacts(bp, opened(bp, {(j.child, 0): at(j, 1.0)}))


def test_racks_clear_the_open_door_everywhere():
    """Four racks at full travel over the flat door, with a bar handle and a control panel."""
    _, bp = make(1, rack_count=4, has_handle=True, handle_style="bar", has_control_panel=True,
                 has_buttons=True, has_baskets=True, rack_travel=0.8)
    js = movable(bp)
    assert not contacts(bp, {(j.child, 0): at(j, 1.0) for j in js})
    door = bp.poses({("door", 0): math.pi / 2})["door"]
    top = max((np.vstack([pc.vertices for pc in bp.parts["door"].pieces]) @ door[:3, :3].T
               + door[:3, 3])[:, 2])
    low = min(pc.bounds[0, 2] for n, part in bp.parts.items() if part.label in ("rack", "basket")
              for pc in part.pieces)
    assert low > top


@pytest.mark.parametrize("seed", [*SEEDS, 19])  # 19: a cutlery tray under the ceiling nozzle
def test_moving_parts_do_not_enter_their_parent(seed):
    _, bp = make(seed)
    for j in movable(bp):
        parent = bp.parts[j.parent]
        for f in (0.0, 0.25, 0.5, 0.75, 1.0):
            pose = bp.poses({(j.child, 0): at(j, f)})
            assert overlap(bp.parts[j.child], pose[j.child], parent, pose[j.parent]) < VOL, (j.child, f)
        assert overlap(bp.parts[j.child], np.eye(4), parent, np.eye(4), pad=0.001) < VOL


@pytest.mark.parametrize("seed", SEEDS)
def test_nothing_below_ground(seed):
    _, bp = make(seed)
    js = movable(bp)
    for q in [{(j.child, 0): at(j, 1.0) for j in js}, *({(j.child, 0): at(j, 1.0)} for j in js)]:
        pose = bp.poses(opened(bp, q))
        for name, part in bp.parts.items():
            pts = np.vstack([pc.vertices for pc in part.pieces])
            assert (pts @ pose[name][:3, :3].T + pose[name][:3, 3])[:, 2].min() >= -1e-6


# -- overrides, growth, determinism ------------------------------------------------------


def test_forced_racks_baskets_and_buttons_build_those_parts():
    """Forced rack, basket and button counts build exactly those parts; without panel and handle only doors,
    racks, tines, shelves and baskets move (the generic contract: test_category_contract)."""
    def racks(bp):
        return [n for n, part in bp.parts.items() if part.label == "rack"]

    _, bp = make(2, rack_count=1, has_baskets=True, basket_count=3)
    assert racks(bp) == ["rack_0"]
    assert sorted(n for n in bp.parts if n.startswith("basket_")) == ["basket_0", "basket_1", "basket_2"]
    _, bp = make(2, rack_count=4, has_baskets=False)
    assert len(racks(bp)) == 4 and not any(n.startswith("basket") for n in bp.parts)
    _, bp = make(2, has_control_panel=True, has_buttons=True, button_count=5)
    assert sum(n.startswith("button_") for n in bp.parts) == 5
    _, bp = make(2, has_control_panel=False, has_handle=False)
    moving = [bp.parts[j.child].label for j in movable(bp)]
    assert set(moving) <= {"door", "rack", "tines", "shelf", "basket"} and moving.count("rack") == len(racks(bp))
    assert not any(pc.name == "handle" for pc in bp.parts["door"].pieces)


def test_fold_down_tines_cup_shelves_and_lift_out_baskets_are_forced():
    """--set forces 2-4 fold-down tine rows in the lower rack, 0-2 in an upper rack, 1-2 flip-down cup
    shelves on an upper rack (none on the cutlery tray), and baskets that lift out of the lower rack."""
    over = dict(rack_count=3, tine_rows=4, upper_tine_rows=2, has_cup_shelves=True, cup_shelf_count=2,
                has_baskets=True, basket_count=2)
    p, bp = make(3, **over)
    kids = {}
    for j in movable(bp):
        kids.setdefault(j.parent, []).append(bp.parts[j.child].label)
    assert sorted(kids["rack_0"]) == ["basket"] * 2 + ["tines"] * 4
    assert sorted(kids["rack_1"]) == ["shelf"] * 2 + ["tines"] * 2
    assert "rack_2" not in kids  # the cutlery tray
    for j in movable(bp):  # each folds a quarter turn and lands clear of everything but its rack
        if bp.parts[j.child].label in ("tines", "shelf", "basket"):
            q = opened(bp, {(j.child, 0): at(j, 1.0), (j.parent, 0): by_child(bp, j.parent).dofs[0].upper})
            assert not contacts(bp, q), j.child
    _, bp = make(3, **{**over, "tine_rows": 2, "upper_tine_rows": 0, "has_cup_shelves": False})
    labels = [bp.parts[j.child].label for j in movable(bp)]
    assert labels.count("tines") == 2 and "shelf" not in labels
    _, bp = make(3, design="dish_drawer", tine_rows=3)  # each drawer's rack has its own rows
    for d in ("drawer_0", "drawer_1"):
        rack = f"{d}_rack"
        assert sum(j.parent == rack and bp.parts[j.child].label == "tines" for j in movable(bp)) == 3


def test_seeds_differ():
    params = [make(s)[0] for s in range(20)]
    for name in ("rack_count", "has_handle", "has_control_panel", "has_baskets", "body_finish"):
        assert len({p[name] for p in params}) > 1, name


# -- designs -------------------------------------------------------------------------------------


@pytest.mark.parametrize("design", ["freestanding", "integrated", "compact", "dish_drawer"])
def test_each_design_is_forced_and_has_its_mechanism(design):
    """``--set design=...`` forces a design; each has its own structure, moving parts and real sizes."""
    p, bp = make(6, design=design, has_handle=True, rack_count=3)
    assert p["design"] == design
    lo, hi = bp.bounds()
    labels = [part.label for part in bp.parts.values()]
    racks = [n for n, part in bp.parts.items() if part.label == "rack"]
    if design == "dish_drawer":  # two drawers, each a tub with a rack fixed in it; no door
        assert "door" not in labels and sorted(n for n in bp.parts if bp.parts[n].label == "drawer") == [
            "drawer_0", "drawer_1"]
        for k in range(2):
            j = by_child(bp, f"drawer_{k}")
            assert j.kind == "prismatic" and j.dofs[0].axis == pytest.approx((1, 0, 0)) and j.dofs[0].upper > 0.3
            assert by_child(bp, f"drawer_{k}_rack").parent == f"drawer_{k}"
        assert 0.79 <= hi[2] - lo[2] <= 0.87
        return
    door = by_child(bp, "door")
    assert door.kind == "revolute" and door.dofs[0].axis == pytest.approx((0, 1, 0))
    assert all(by_child(bp, n).requires_open == "door" for n in racks)
    if design == "compact":  # a counter-top model: one rack, 0.42-0.47 m high
        assert len(racks) == 1 and 0.42 <= hi[2] - lo[2] <= 0.48 and hi[1] - lo[1] <= 0.61
    else:
        assert len(racks) == 3
    if design == "integrated":  # a cabinet front panel on the door, the handle on it
        assert any(pc.material == "front" for pc in bp.parts["door"].pieces)
        assert bp.materials["front"].split(":")[0] in ("wood", "painted")
    if design == "freestanding":
        assert any(pc.material == "worktop" for pc in bp.parts["body"].pieces)
