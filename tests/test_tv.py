"""The tv category, checked on its blueprint (world space, grounded): parts, joints, clearances."""

from __future__ import annotations

import math

import manifold3d
import numpy as np
import pytest

from infmob_usd.mass import inertial
from infmob_usd.materials import FAMILIES
from infmob_usd.materials.families import split_spec

from helpers import maker, states
from zoo import by_child, movable

SEEDS = range(8)
LABELS = {"screen", "stand", "connector", "button", "frame", "arm", "camera"}
TOL = 1e-7  # m^3, as the validator's contact volume


make = maker("tv")


@pytest.fixture(scope="module", params=SEEDS)
def tv_bp(request):
    return make(request.param)


# -- kinematics and collision helpers ----------------------------------------------------


def posed_hulls(bp, pose):
    out = {}
    for name, part in bp.parts.items():
        hs = []
        for pc in part.pieces:
            for c in pc.convex:
                w = c @ pose[name][:3, :3].T + pose[name][:3, 3]
                hs.append((w, w.min(0), w.max(0)))
        out[name] = hs
    return out


def volume(ha, hb):
    total = 0.0
    for wa, lo_a, hi_a in ha:
        for wb, lo_b, hi_b in hb:
            if np.any(hi_a <= lo_b) or np.any(hi_b <= lo_a):
                continue
            total += (manifold3d.Manifold.hull_points(wa) ^ manifold3d.Manifold.hull_points(wb)).volume()
    return total


def welded_groups(bp):
    group = {n: n for n in bp.parts}

    def find(n):
        while group[n] != n:
            n = group[n]
        return n

    for j in bp.joints:
        if not j.movable:
            group[find(j.child)] = find(j.parent)
    return find


def carried_mass(bp, name):
    names, grew = {name}, True
    while grew:
        grew = False
        for j in bp.joints:
            if j.parent in names and j.child not in names:
                names.add(j.child)
                grew = True
    mass, moment = 0.0, np.zeros(3)
    for n in names:
        dens = ((pc, FAMILIES[split_spec(bp.materials[pc.material])[0]].density) for pc in bp.parts[n].pieces)
        m, com, _ = inertial(dens)
        mass, moment = mass + m, moment + m * com
    return mass, moment / mass


# -- structure -----------------------------------------------------------------------------


def test_parts_labels_and_materials(tv_bp):
    p, bp = tv_bp
    assert {part.label for part in bp.parts.values()} <= LABELS
    assert bp.parts["screen"].label == "screen" and bp.parts["connector"].label == "connector"
    assert by_child(bp, "screen").kind == "fixed" and by_child(bp, "screen").parent == "connector"
    if p["stand_style"] == "wall_mount":
        assert bp.root == "wall_plate"
        assert sorted(n for n in bp.parts if n.startswith("arm_")) == [f"arm_{k}" for k in range(p["arm_links"])]
    else:
        assert bp.root == "stand" and bp.parts["stand"].label == "stand"
    buttons = [n for n, part in bp.parts.items() if part.label == "button"]
    assert len(buttons) == (p["button_count"] if p["has_buttons"] else 0)
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    assert bp.materials["display"] == "screen"  # glossy cover glass
    assert any(pc.material == "display" for pc in bp.parts["screen"].pieces)
    assert all(pc.convex for part in bp.parts.values() for pc in part.pieces)


def test_screen_size_follows_width_and_aspect(tv_bp):
    p, bp = tv_bp
    b = np.array([pc.bounds for pc in bp.parts["screen"].pieces if pc.material == "bezel"])
    bezel = np.array([b[:, 0].min(0), b[:, 1].max(0)])
    w, h = bezel[1, 1] - bezel[0, 1], bezel[1, 2] - bezel[0, 2]
    curved = p["panel_shape"] == "curved"
    # a curved panel's chord is a little shorter than its (arc) width; its edges come forward by the sagitta
    assert w == pytest.approx(p["width"], rel=0.02 if curved else 1e-6)
    assert h / w == pytest.approx(9 / 16 if p["aspect"] == "16:9" else 3 / 4, rel=0.03 if curved else 1e-6)
    sag = (p["width"] / 2) ** 2 / (2 * p["curve_radius"]) + 0.01 if curved else 0.0
    assert bezel[1, 0] - bezel[0, 0] <= p["depth"] + sag
    assert bp.elevation == 0.0 or p["stand_style"] == "wall_mount"  # only a wall TV hangs
    assert bp.bounds()[0, 2] == pytest.approx(bp.elevation, abs=1e-9)


# -- joints --------------------------------------------------------------------------------


def test_tilt_connector_rests_on_its_lower_stop(tv_bp):
    p, bp = tv_bp
    j = by_child(bp, "connector")
    if j.kind == "fixed":  # a rigid mount: a stand that does not tilt (never a wall mount)
        assert p["stand_style"] != "wall_mount"
        return
    assert j.kind == "revolute"
    d = j.dofs[0]
    assert d.axis == pytest.approx((0, -1, 0))
    assert d.lower == 0.0 and 0.019 < d.upper <= p["tilt"] + 1e-12 <= math.pi / 8 + 1e-12
    screen_back = min(pc.bounds[0, 0] for pc in bp.parts["screen"].pieces)
    assert d.origin[0] < screen_back  # pivot behind the screen
    # gravity torque of everything the connector carries pushes toward negative q
    m, com = carried_mass(bp, "connector")
    torque = float(np.cross(com - np.asarray(d.origin), m * np.array([0, 0, -9.81])) @ np.asarray(d.axis))
    assert torque < -0.01 * m


def test_stand_joints(tv_bp):
    p, bp = tv_bp
    parent = by_child(bp, "connector").parent
    if p["stand_style"] == "wall_mount":
        for k in range(p["arm_links"]):
            j = by_child(bp, f"arm_{k}")
            assert j.kind == "revolute" and j.dofs[0].axis == pytest.approx((0, 0, 1))
            assert j.dofs[0].lower == -j.dofs[0].upper < 0
        assert parent == f"arm_{p['arm_links'] - 1}"
    elif p["stand_style"] == "single_post" and p["has_height_adjust"]:
        j = by_child(bp, "post")
        assert parent == "post" and j.kind == "revolute_prismatic" and j.parent == "stand"
        slide, turn = j.dofs
        assert slide.axis == pytest.approx((0, 0, 1)) and (slide.lower, slide.upper) == (0.0, p["slide"])
        assert turn.axis == pytest.approx((0, 0, 1)) and (turn.lower, turn.upper) == (-p["swivel"], p["swivel"])
    elif p["stand_style"] == "single_post":  # a swivel pedestal: the neck turns on the base
        j = by_child(bp, "post")
        assert parent == "post" and j.kind == "revolute" and j.parent == "stand"
        assert j.dofs[0].axis == pytest.approx((0, 0, 1))
        assert (j.dofs[0].lower, j.dofs[0].upper) == (-p["swivel"], p["swivel"])
    else:
        assert parent == "stand" and "post" not in bp.parts
    for n, part in bp.parts.items():
        if part.label == "button":
            j = by_child(bp, n)
            d = j.dofs[0]
            assert j.kind == "prismatic" and j.parent == "screen" and d.lower == 0.0 and d.upper > 0
            assert abs(d.axis[2]) < 1e-12  # pressed horizontally
            want = (0, -1, 0) if p["button_place"] == "side" and p["panel_shape"] == "flat" else (-1, 0, 0)
            assert d.axis == pytest.approx(want)


def test_no_contact_and_nothing_below_ground_in_any_state(tv_bp):
    """Like the validator: non-jointed parts never touch; a child never sinks further into its parent."""
    _, bp = tv_bp
    find = welded_groups(bp)
    jointed = {frozenset((j.parent, j.child)) for j in movable(bp)}
    names = list(bp.parts)
    pairs = [(a, b) for i, a in enumerate(names) for b in names[i + 1:]
             if frozenset((a, b)) not in jointed and find(a) != find(b)]
    rest = posed_hulls(bp, bp.poses())
    base_pc = {j.child: volume(rest[j.parent], rest[j.child]) for j in movable(bp)}
    for q in states(bp):
        hulls = posed_hulls(bp, bp.poses(q))
        low = min(w[:, 2].min() for hs in hulls.values() for w, _, _ in hs)
        assert low > -1e-6, f"below the ground at {q}"
        for a, b in pairs:
            assert volume(hulls[a], hulls[b]) < TOL, f"{a} touches {b} at {q}"
        for j in movable(bp):
            assert volume(hulls[j.parent], hulls[j.child]) <= base_pc[j.child] + TOL, f"{j.child} at {q}"


# -- overrides, growth, determinism ----------------------------------------------------------


def test_forced_stands_arms_and_buttons_build_those_parts():
    """Forced stand styles, arm links and buttons give those parts and joints (the generic contract:
    test_category_contract)."""
    p, bp = make(1, stand_style="wall_mount", arm_links=2, has_buttons=True, button_count=3, button_place="side")
    assert bp.root == "wall_plate" and {"arm_0", "arm_1"} <= set(bp.parts)
    assert sum(part.label == "button" for part in bp.parts.values()) == 3
    _, bp = make(1, stand_style="single_post", has_height_adjust=True)
    assert by_child(bp, "post").kind == "revolute_prismatic"
    _, bp = make(1, stand_style="single_post", has_height_adjust=False)
    assert by_child(bp, "post").kind == "revolute"
    _, bp = make(1, stand_style="two_legs", has_buttons=False)
    assert bp.root == "stand" and "post" not in bp.parts
    assert not any(part.label == "button" for part in bp.parts.values())
    p, _ = make(1, width=2.0, aspect="4:3")
    assert p["width"] == 2.0 and p["aspect"] == "4:3"


def test_seeds_differ():
    params = [make(s)[0] for s in range(20)]
    for name in ("stand_style", "has_buttons", "aspect", "bezel_finish"):
        assert len({p[name] for p in params}) > 1, name


@pytest.mark.parametrize("shape", ["flat", "curved"])
def test_panel_shape_is_forced_and_a_curved_panel_bends_forward(shape):
    """``--set panel_shape=curved`` bends the panel along an arc: its edges stand forward of its middle by
    the sagitta of ``curve_radius``; the buttons sit in the flat middle of the bottom band."""
    p, bp = make(2, panel_shape=shape, has_buttons=True, button_count=3, width=1.4)
    disp = [pc for pc in bp.parts["screen"].pieces if pc.material == "display"]
    mid = [pc for pc in disp if abs(pc.bounds[:, 1].mean()) < 0.05]
    edge = max(disp, key=lambda pc: pc.bounds[1, 1])
    lift = edge.bounds[1, 0] - mid[0].bounds[1, 0]
    if shape == "curved":
        flat = mid[0].bounds[1, 1]  # the arc starts at the flat middle's edge
        assert len(disp) >= 5 and lift > 0.8 * (0.7 - flat) ** 2 / (2 * p["curve_radius"])
        for n, part in bp.parts.items():
            if part.label == "button":
                assert abs(by_child(bp, n).dofs[0].origin[1]) < 0.1
    else:
        assert len(disp) == 1 and lift == pytest.approx(0.0)
    assert len([n for n, part in bp.parts.items() if part.label == "button"]) == 3


@pytest.mark.parametrize("place", ["side", "bottom"])
def test_a_full_key_row_fits_the_smallest_screen(place):
    """--set button_count=7 (power, input, menu, volume +/-, channel +/-) on a 0.6 m screen: seven keys, each
    pressing in, inside the screen's outline and clear of each other."""
    p, bp = make(3, width=0.6, has_buttons=True, button_count=7, button_place=place, panel_shape="flat")
    keys = [j for j in movable(bp) if bp.parts[j.child].label == "button"]
    assert len(keys) == 7 and all(j.kind == "prismatic" and j.parent == "screen" for j in keys)
    b = np.array([pc.bounds for pc in bp.parts["screen"].pieces if pc.material == "bezel"])
    lo, hi = b[:, 0].min(0), b[:, 1].max(0)
    boxes = [np.array([pc.bounds for pc in bp.parts[j.child].pieces]) for j in keys]
    boxes = [(x[:, 0].min(0), x[:, 1].max(0)) for x in boxes]
    dims = [2] if place == "side" else [1, 2]  # side keys stand proud of the right rim, in its height
    for a, c in boxes:
        assert (a[dims] >= lo[dims] - 1e-9).all() and (c[dims] <= hi[dims] + 1e-9).all()
    for i in range(7):
        for k in range(i + 1, 7):
            (a0, a1), (b0, b1) = boxes[i], boxes[k]
            assert (a1 < b0).any() or (b1 < a0).any()


def test_a_tilting_wall_mount_and_a_three_link_arm():
    """arm_links=0: the fork on a bracket off the wall plate, the screen's full tilt clear of the wall;
    arm_links=3: three swivels about Z, then the tilt."""
    p, bp = make(2, stand_style="wall_mount", arm_links=0, tilt=math.pi / 10, has_camera=True)
    assert bp.root == "wall_plate" and not any(n.startswith("arm_") for n in bp.parts)
    j = by_child(bp, "connector")
    assert j.parent == "wall_plate" and j.kind == "revolute"
    assert j.dofs[0].upper == pytest.approx(math.pi / 10, abs=2e-3)
    wall = max(pc.bounds[1, 0] for pc in bp.parts["wall_plate"].pieces if pc.bounds[1, 1] - pc.bounds[0, 1] >= 0.2)
    for name in ("screen", "camera"):
        pose = bp.poses({("connector", 0): j.dofs[0].upper})[name]
        pts = np.vstack([c for pc in bp.parts[name].pieces for c in pc.convex]) @ pose[:3, :3].T + pose[:3, 3]
        assert pts[:, 0].min() > wall + 0.009
    _, bp = make(2, stand_style="wall_mount", arm_links=3)
    chain = [by_child(bp, f"arm_{k}") for k in range(3)]
    assert [j.parent for j in chain] == ["wall_plate", "arm_0", "arm_1"] and by_child(bp, "connector").parent == "arm_2"
    assert all(j.kind == "revolute" and j.dofs[0].axis == pytest.approx((0, 0, 1)) for j in chain)


def test_a_pop_up_camera_rises_out_of_its_pocket():
    """has_camera: a module behind the top edge, flush at rest, sliding up 35 mm clear of its pocket."""
    p, bp = make(3, has_camera=True, stand_style="single_post")
    j = by_child(bp, "camera")
    assert j.parent == "screen" and j.kind == "prismatic" and bp.parts["camera"].label == "camera"
    d = j.dofs[0]
    assert d.axis == pytest.approx((0, 0, 1)) and (d.lower, d.upper) == (0.0, pytest.approx(0.035))
    top = max(pc.bounds[1, 2] for pc in bp.parts["screen"].pieces)
    cam = np.array([pc.bounds for pc in bp.parts["camera"].pieces])
    assert cam[:, 1, 2].max() < top and cam[:, 0, 2].min() + d.upper > top - 0.02  # rises clear of the frame
    _, bp = make(3, has_camera=False)
    assert "camera" not in bp.parts


def test_every_tree_moves():
    """Feet without tilt, keys or camera would not move: the grammar draws the mount again."""
    for seed in range(12):
        _, bp = make(seed, stand_style="two_legs", has_buttons=False, has_camera=False)
        assert by_child(bp, "connector").kind == "revolute"


@pytest.mark.parametrize("width,aspect,bottom", [(2.1, "4:3", 0.3), (1.0, "16:9", 1.07 - 0.5625 / 2)])
def test_a_wall_mounted_tv_hangs_with_its_centre_at_eye_height(width, aspect, bottom):
    """Hung, not standing on the floor: the screen's centre 1.07 m up, its bottom at least 0.3 m up."""
    _, bp = make(3, stand_style="wall_mount", width=width, aspect=aspect)
    screen = np.vstack([c for pc in bp.parts["screen"].pieces for c in pc.convex])
    assert bp.bounds()[0, 2] == pytest.approx(bottom, abs=1e-6)
    assert screen[:, 2].min() == pytest.approx(bottom, abs=0.01)
    _, standing = make(3, stand_style="two_legs")
    assert standing.bounds()[0, 2] == pytest.approx(0.0, abs=1e-9)


@pytest.mark.sim
def test_a_large_tv_on_a_wall_arm_swings_freely_in_sapien(tmp_path):
    """A 2.1 m 4:3 screen on a two-link arm must hang clear of the floor: standing on it, it dragged (the arm
    stopped at 77-81 % of its swing in SAPIEN); hung, every joint reaches both ends."""
    pytest.importorskip("sapien")
    import infmob_usd
    from infmob_usd.validate.sim import check_sapien

    obj = infmob_usd.generate("tv", 597338, texture_size=16, width=2.1, aspect="4:3", depth=0.02,
                              stand_style="wall_mount", arm_links=2, has_buttons=True, button_place="bottom")
    reach = {c.name: c for c in check_sapien(infmob_usd.save(obj, tmp_path), checks=["reach"])}["reach"]
    assert reach.ok, reach.detail


def _com_margins(obj):
    """(back, front, needed) of the whole set's centre of mass over its floor contact along x, upright and with
    each screen tilt at its upper limit; ``needed``: its height x tan(10 degrees)."""
    from infmob_usd.blueprint import descendants

    links = {link.name: link for link in obj.links}
    pts = np.vstack([pc.vertices + link.origin for link in obj.links for pc in link.pieces])
    foot = pts[pts[:, 2] < pts[:, 2].min() + 0.002]
    lo, hi = foot[:, 0].min(), foot[:, 0].max()
    mass = sum(link.mass for link in links.values())
    out = []
    for j in [None] + [j for j in obj.joints if j.type == "revolute" and abs(j.axis[1]) > 0.9]:
        com = {n: np.asarray(link.origin) + np.asarray(link.com) for n, link in links.items()}
        if j is not None:  # turned about the tilt axis by its upper limit (Rodrigues)
            a, t = np.asarray(j.axis, float), j.upper
            k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
            r = np.eye(3) + math.sin(t) * k + (1 - math.cos(t)) * k @ k
            for n in descendants(obj.joints, j.child):
                com[n] = np.asarray(j.origin) + r @ (com[n] - np.asarray(j.origin))
        c = sum(links[n].mass * com[n] for n in links) / mass
        out.append((c[0] - lo, hi - c[0], c[2] * math.tan(math.radians(10))))
    return out


@pytest.mark.parametrize("seed", [1, 3, 4, 7301])
def test_a_set_on_its_stand_does_not_overturn_tilted_ten_degrees(seed):
    """IEC 62368-1 8.6.2.2: the centre of mass stays inside the stand's floor contact by its height x tan 10
    degrees, upright and with the screen tilted back (a 2 m set on feet tipped back before: seed 7301)."""
    from infmob_usd.api import generate

    obj = generate("tv", seed=seed, texture_size=16)
    assert obj.params["stand_style"] != "wall_mount"
    for back, front, needed in _com_margins(obj):
        assert back >= needed and front >= needed, (back, front, needed)
