"""The office chair category: parts, joints, clearances at every joint state, overrides, seeds."""

from __future__ import annotations

import numpy as np
import pytest

from infmob_usd.blueprint import dof_motion
from infmob_usd.model import build as build_model

from collide import overlap
from helpers import maker, states
from zoo import by_child, movable

SEEDS = range(4)
LABELS = {"base", "caster", "wheel", "lift", "seat", "back", "arm", "armrest", "headrest", "lumbar", "foot_ring",
          "knob"}
PLAIN = dict(has_seat_slider=False, has_tension_knob=False, has_lumbar=False, has_headrest=False, arm_style="arm_4d")
TOL = 1e-7  # m^3, as the validator


make = maker("office_chair")


# -- parts, labels, materials --------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_required_parts_labels_and_materials(seed):
    p, bp = make(seed)
    assert bp.root == "base"
    for name, label in {"base": "base", "lift": "lift", "seat": "seat"}.items():
        assert bp.parts[name].label == label
    assert {part.label for part in bp.parts.values()} <= LABELS
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    assert any(pc.name == "handle" for pc in bp.parts["seat"].pieces)
    links, _ = build_model(bp, {k: 1000.0 for k in bp.materials})
    assert all(link.mass > 0 for link in links)
    assert ("back" in bp.parts) == (p["has_back"] or p["design"] in ("executive", "mesh_chair"))
    assert ("arm_pad_left" in bp.parts) == (p["has_arms"] and p["arm_style"] == "arm_4d")


@pytest.mark.parametrize("seed", SEEDS)
def test_sizes_and_wheels_on_the_floor(seed):
    p, bp = make(seed)
    seat = np.array([pc.bounds for n in ("seat", "seat_pan") if n in bp.parts for pc in bp.parts[n].pieces
                     if pc.material == "seat"])
    assert seat[:, 1, 2].max() == pytest.approx(p["seat_height"], abs=1e-6)
    assert seat[:, 1, 1].max() - seat[:, 0, 1].min() == pytest.approx(p["seat_width"], abs=1e-6)
    assert bp.bounds()[0, 2] == pytest.approx(0.0, abs=1e-9)
    wheels = [n for n, part in bp.parts.items() if part.label == "wheel"]
    for n in wheels:
        assert min(pc.bounds[0, 2] for pc in bp.parts[n].pieces) == pytest.approx(0.0, abs=1e-9)
    for n, part in bp.parts.items():
        if part.label != "wheel":
            assert min(pc.bounds[0, 2] for pc in part.pieces) > 0.01, n


# -- joints ------------------------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_joint_kinds_axes_and_limits(seed):
    p, bp = make(seed)
    n = sum(part.label == "caster" for part in bp.parts.values())
    assert 4 <= n <= 6
    per = 2 if p["caster_style"] == "twin" else 1
    assert sum(part.label == "wheel" for part in bp.parts.values()) == n * per
    for name, part in bp.parts.items():
        if part.label == "caster":
            j = by_child(bp, name)
            assert j.kind == "continuous" and j.parent == "base"
            assert j.dofs[0].axis == pytest.approx((0, 0, 1))
        if part.label == "wheel":
            j = by_child(bp, name)
            assert j.kind == "continuous" and bp.parts[j.parent].label == "caster"
            a, o = np.array(j.dofs[0].axis), np.array(j.dofs[0].origin)
            assert a[2] == pytest.approx(0.0)
            radial = o[:2] / np.linalg.norm(o[:2])
            assert abs(a[:2] @ radial) > 0.9  # axle along the leg
            # centre of mass on the axle: the tyre is a cylinder about it
            tyre = bp.parts[name].pieces[0]
            c = (tyre.bounds[0] + tyre.bounds[1]) / 2
            assert np.linalg.norm(np.cross(c - o, a)) < 1e-6
    lift = by_child(bp, "lift").dofs[0]
    assert by_child(bp, "lift").kind == "prismatic" and lift.axis == pytest.approx((0, 0, 1))
    assert lift.lower == 0.0 and 0.04 < lift.upper <= 0.1
    seat = by_child(bp, "seat")
    assert seat.kind == "continuous" and seat.parent == "lift"
    assert seat.dofs[0].axis == pytest.approx((0, 0, 1))
    assert 11 <= len(movable(bp)) <= 32


def test_back_reclines_and_gravity_holds_it_upright():
    _, bp = make(0, design="task", has_back=True, has_headrest=True)
    j = by_child(bp, "back")
    d = j.dofs[0]
    assert j.kind == "revolute" and d.axis == pytest.approx((0, -1, 0)) and d.lower == 0.0 and d.upper > 0.2
    # reclining moves the top backwards
    top = np.array([0, 0, bp.parts["back"].pieces[1].bounds[1, 2], 1.0])
    top[:2] = d.origin[:2]
    assert (dof_motion(d, d.upper) @ top)[0] < d.origin[0] - 0.05
    # centre of mass ahead of the hinge: gravity tips it forward, onto its q = 0 stop
    dens = {k: 300.0 for k in bp.materials} | {"frame": 1100.0}
    links, _ = build_model(bp, dens)
    back = next(link for link in links if link.name == "back")
    assert (back.origin + back.com)[0] > d.origin[0] + 0.01


def test_arms_joints():
    p, bp = make(1, has_arms=True, arm_style="arm_4d")
    for side in ("left", "right"):
        post = by_child(bp, f"arm_{side}")
        assert post.kind == "prismatic" and post.parent == "seat"
        assert post.dofs[0].axis == pytest.approx((0, 0, 1)) and post.dofs[0].lower == 0.0
        slide = by_child(bp, f"arm_slider_{side}")
        assert slide.kind == "revolute_prismatic" and slide.parent == f"arm_{side}"
        assert slide.dofs[0].axis == pytest.approx((1, 0, 0))
        assert slide.dofs[1].axis == pytest.approx((0, 0, 1))
        pad = by_child(bp, f"arm_pad_{side}")
        assert pad.kind == "revolute" and pad.dofs[0].axis == pytest.approx((0, 0, 1))
        assert bp.parts[f"arm_pad_{side}"].label == "armrest"


# -- clearances ------------------------------------------------------------------------------


def _box(part, pose):
    pts = np.vstack([c for pc in part.pieces for c in pc.convex])
    w = pts @ pose[:3, :3].T + pose[:3, 3]
    return w.min(0), w.max(0)


def rest_overlaps(bp):
    """Each child's overlap with its parent at rest: the most it may keep in any state."""
    rest = bp.poses()
    return {j.child: overlap(bp.parts[j.child], rest[j.child], bp.parts[j.parent], rest[j.parent])
            for j in bp.joints}


def assert_clear(bp, ps, rest_pc, q):
    """At poses ``ps`` (state ``q``): non-jointed parts never touch; a child never sinks deeper into its
    parent than at rest (``rest_pc``, from :func:`rest_overlaps`)."""
    into = {j.child: j.parent for j in bp.joints}
    names = list(bp.parts)
    parts = bp.parts
    boxes = {n: _box(parts[n], ps[n]) for n in names}
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            (la, ha), (lb, hb) = boxes[a], boxes[b]
            if np.any(ha < lb) or np.any(hb < la):
                continue
            if into.get(a) == b or into.get(b) == a:
                c = a if into.get(a) == b else b
                vol = overlap(parts[c], ps[c], parts[into[c]], ps[into[c]])
                assert vol - rest_pc[c] < TOL, (c, q)
            else:
                assert overlap(parts[a], ps[a], parts[b], ps[b]) < TOL, (a, b, q)


@pytest.mark.parametrize("seed", [0, 5])
def test_no_collisions_at_any_sampled_state(seed):
    """Non-jointed parts never touch; a child never sinks deeper into its parent than at rest."""
    _, bp = make(seed, has_arms=True, has_back=True)
    rest_pc = rest_overlaps(bp)
    for q in states(bp):
        assert_clear(bp, bp.poses(q), rest_pc, q)


@pytest.mark.parametrize("seed", SEEDS)
def test_nothing_below_ground(seed):
    _, bp = make(seed)
    for q in states(bp):
        ps = bp.poses(q)
        for n, part in bp.parts.items():
            pts = np.vstack([c for pc in part.pieces for c in pc.convex])
            z = pts @ ps[n][2, :3] + ps[n][2, 3]
            assert z.min() >= -5e-4, (n, q)


# -- overrides, growth, determinism ----------------------------------------------------


def test_forced_casters_arms_and_back_build_those_parts():
    """Forced caster counts and styles, arms and backs give those parts; the biggest task chair has the reference
    method's joint count (the generic contract: test_category_contract)."""
    _, bp = make(3, leg_count=5, caster_style="twin", has_arms=True, design="task", **PLAIN)
    assert sum(part.label == "caster" for part in bp.parts.values()) == 5
    assert len(movable(bp)) == 5 * 3 + 3 + 6  # the reference method's biggest chairs
    _, bp = make(3, leg_count=6, caster_style="single", has_arms=False, has_back=False, design="drafting", **PLAIN)
    assert sum(part.label == "wheel" for part in bp.parts.values()) == 6
    assert "back" not in bp.parts and not any(n.startswith("arm") for n in bp.parts)
    assert len(movable(bp)) == 12 + 2 + 1  # and the foot ring
    _, bp = make(3, design="task", has_back=True, back_style="mesh")
    assert any(pc.material == "mesh" for pc in bp.parts["back"].pieces)
    p, _ = make(3, seat_height=0.45, base_finish="chrome")
    assert p["seat_height"] == 0.45 and p["base_finish"] == "chrome"


def test_seeds_differ_in_ways_a_person_sees():
    made = [make(s) for s in range(12)]
    for name in ("caster_style", "base_finish", "has_arms", "leg_style"):
        assert len({p[name] for p, _ in made}) > 1, name
    legs = {sum(part.label == "caster" for part in bp.parts.values()) for _, bp in made}
    assert 5 in legs and legs <= {4, 5, 6}


def test_star_bases_have_five_legs_rarely_four_or_six():
    from infmob_usd.categories.parts.seating import legs

    rng = np.random.default_rng(0)
    drawn = [legs({"leg_count": None}, rng) for _ in range(400)]
    assert set(drawn) <= {4, 5, 6} and drawn.count(5) / len(drawn) > 0.8
    assert legs({"leg_count": 4}, rng) == 4


# -- designs: the parts each one adds --------------------------------------------------------


DESIGN_PARTS = {"task": {"back"}, "executive": {"back", "headrest"}, "mesh_chair": {"back", "lumbar"},
                "drafting": {"foot_ring"}}


@pytest.mark.parametrize("design", sorted(DESIGN_PARTS))
def test_each_design_grows_its_parts_and_moves_them(design):
    p, bp = make(2, design=design, has_back=False, has_arms=True)
    assert p["design"] == design
    assert DESIGN_PARTS[design] <= set(bp.parts)
    if design == "executive":
        j = by_child(bp, "headrest")
        assert j.kind == "prismatic" and j.parent == "back"
        assert j.dofs[0].axis == pytest.approx((0, 0, 1)) and j.dofs[0].upper > 0.05  # slides up
        back = np.array([pc.bounds for pc in bp.parts["back"].pieces if pc.material == "seat"])
        assert back[:, 1, 2].max() - back[:, 0, 2].min() >= 0.62  # a high back
    if design == "mesh_chair":
        j = by_child(bp, "lumbar")
        assert j.kind == "prismatic" and j.dofs[0].axis == pytest.approx((0, 0, 1)) and j.dofs[0].upper > 0.04
        assert any(pc.material == "mesh" for pc in bp.parts["back"].pieces)
    if design == "drafting":
        j = by_child(bp, "foot_ring")
        assert j.kind == "prismatic" and j.parent == "base" and j.dofs[0].upper > 0.05
        assert 0.62 <= p["seat_height"] <= 0.78 and "back" not in bp.parts
    rest_pc = rest_overlaps(bp)
    for q in states(bp):
        assert_clear(bp, bp.poses(q), rest_pc, q)


@pytest.mark.parametrize("style", ["arm_4d", "arm_height", "arm_fixed", "arm_flip"])
def test_arm_styles(style):
    _, bp = make(4, design="task", has_back=True, has_arms=True, arm_style=style)
    kinds = {"arm_4d": "prismatic", "arm_height": "prismatic", "arm_fixed": "fixed", "arm_flip": "revolute"}
    for side in ("left", "right"):
        assert by_child(bp, f"arm_{side}").kind == kinds[style]
        assert (f"arm_pad_{side}" in bp.parts) == (style == "arm_4d")
    if style == "arm_flip":
        d = by_child(bp, "arm_left").dofs[0]
        assert d.axis == pytest.approx((0, -1, 0)) and d.upper > 1.2
    rest_pc = rest_overlaps(bp)
    for q in states(bp):
        assert_clear(bp, bp.poses(q), rest_pc, q)


def test_seat_slider_moves_pan_and_cushion_forward():
    _, bp = make(5, has_seat_slider=True, has_tension_knob=True)
    knob = by_child(bp, "tension_knob")
    assert knob.kind == "continuous" and knob.parent == "seat" and knob.dofs[0].axis == pytest.approx((1, 0, 0))
    rest_pc = rest_overlaps(bp)
    for q in states(bp):
        assert_clear(bp, bp.poses(q), rest_pc, q)
    j = by_child(bp, "seat_pan")
    assert j.kind == "prismatic" and j.parent == "seat" and j.dofs[0].axis == pytest.approx((1, 0, 0))
    assert {pc.material for pc in bp.parts["seat_pan"].pieces} == {"seat", "pan"}
    assert any(pc.name == "handle" for pc in bp.parts["seat"].pieces)


def test_lumbar_pad_clear_of_a_cushion_back():
    """The sliding lumbar pad stands in front of the cushion (seed 4 of the sweep had it 165 cm^3 inside)."""
    _, bp = make(4, design="task", back_style="cushion", has_lumbar=True)
    assert overlap(bp.parts["lumbar"], np.eye(4), bp.parts["back"], np.eye(4)) < TOL


def test_gas_lift_is_steel_whatever_its_finish():
    """A black gas lift is a coated steel cylinder, not a plastic tube: it weighs what the chrome one
    does (a real class 3/4 lift: 1-2 kg with its rod), so light chairs stay over the table's 8 kg."""
    import infmob_usd

    masses = {}
    for finish in ("chrome", "black"):
        obj = infmob_usd.generate("office_chair", seed=7031, texture_size=16, lift_finish=finish)
        masses[finish] = obj.link("lift").mass
        assert obj.materials["lift"].family == ("chrome" if finish == "chrome" else "enamel")
    assert masses["black"] == pytest.approx(masses["chrome"], rel=1e-9)
    assert 0.3 < masses["black"] < 2.0


def flip_arm_stays_over_the_seat(bp):
    """Through its whole range a flip-up arm's pad stays above the seat's top and no part of the arm goes
    behind the back's panel (the mechanism turns the cap up on its post, it does not swing the arm down behind
    the chair)."""
    rest = bp.poses({})
    seat_top = max(pc.bounds[1, 2] for n, part in bp.parts.items() if n.startswith("seat") for pc in part.pieces
                   if pc.material == "seat")
    back_rear = min(pc.bounds[0, 0] for pc in bp.parts["back"].pieces if pc.material in ("seat", "mesh"))
    for side in ("left", "right"):
        name = f"arm_{side}"
        d = by_child(bp, name).dofs[0]
        for f in np.linspace(0.0, 1.0, 7):
            m = bp.poses({(name, 0): d.lower + f * (d.upper - d.lower)})[name] @ np.linalg.inv(rest[name])
            pads = np.vstack([pc.vertices for pc in bp.parts[name].pieces if pc.material == "pad"])
            every = np.vstack([pc.vertices for pc in bp.parts[name].pieces])
            assert (pads @ m[:3, :3].T + m[:3, 3])[:, 2].min() > seat_top, (name, f)
            assert (every @ m[:3, :3].T + m[:3, 3])[:, 0].min() > back_rear, (name, f)


@pytest.mark.parametrize("seed", [4, 7301])
def test_flip_up_arms_turn_up_beside_the_back(seed):
    _, bp = make(seed, design="task", has_back=True, has_arms=True, arm_style="arm_flip")
    flip_arm_stays_over_the_seat(bp)


@pytest.mark.parametrize("name", ["office_chair", "bar_chair"])
def test_ranges_and_shares_come_from_the_sourced_table(name):
    """Both chairs draw what parts/seating_sizes.py lists: every numeric range and choice share of PARAMS."""
    import importlib

    from infmob_usd.categories.parts import seating_sizes as SS

    mod = importlib.import_module(f"infmob_usd.categories.{name}")
    ranges = {p.name: (p.low, p.high) for p in mod.PARAMS if hasattr(p, "low")}
    shares = {p.name: tuple(p.weights) for p in mod.PARAMS if getattr(p, "weights", None)}
    assert ranges == getattr(SS, f"{name.upper()}_RANGES")
    assert shares == getattr(SS, f"{name.upper()}_SHARES")


@pytest.mark.parametrize("seed", range(3))
def test_drafting_foot_ring_slides_only_along_its_sleeve(seed):
    """A drafting chair's foot ring rests above the hub and tops out 30 mm short of its column sleeve's top."""
    from infmob_usd.categories.parts import seating as S

    _, bp = make(seed, design="drafting")
    ring = bp.parts["foot_ring"]
    z_lo = min(float(pc.bounds[0, 2]) for pc in ring.pieces)
    column_top = max(float(pc.bounds[1, 2]) for pc in bp.parts["base"].pieces)
    (dof,) = by_child(bp, "foot_ring").dofs
    assert z_lo >= S.RING_MIN - 0.02
    assert 0 < dof.upper and z_lo + dof.upper < column_top
