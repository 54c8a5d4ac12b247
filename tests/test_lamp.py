"""Behaviour of the lamp category, checked on its blueprint (world space, grounded)."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from scipy.spatial import ConvexHull

from infmob_usd.blueprint import descendants, dof_motion
from infmob_usd.categories import lamp
from infmob_usd.categories.parts import lamps as L
from infmob_usd.mass import inertial
from infmob_usd.materials import FAMILIES, split_spec

from collide import overlap
from helpers import maker

SEEDS = range(10)
LABELS = {"base", "pole", "arm", "head", "shade", "bulb", "switch", "screw"}


make = maker("lamp")


def desk_top(p) -> float:
    """Where the lamp's base stands: the floor, or the desk top a clamp lamp is clamped to."""
    return L.DESK_TOP if p["base_shape"] == "clamp" else 0.0


@pytest.fixture(scope="module", params=SEEDS)
def lamp_bp(request):
    return make(request.param)


# -- kinematics and collision helpers ------------------------------------------


def overlaps(bp, names_a, pose_a, names_b, pose_b) -> dict[tuple[str, str], float]:
    """Shared volume (m^3) of the collision hulls of two sets of parts, per pair of parts that touch."""
    out = {(a, b): overlap(bp.parts[a], pose_a[a], bp.parts[b], pose_b[b]) for a in names_a for b in names_b}
    return {pair: v for pair, v in out.items() if v > 0}


def limit_states(joint):
    """Every corner of a joint's DoF box except rest: each DoF at lower, 0 or upper."""
    values = [(d.lower, 0.0, d.upper) for d in joint.dofs]
    for combo in itertools.product(*values):
        if any(v != 0.0 for v in combo):
            yield {(joint.child, i): v for i, v in enumerate(combo)}


def movable(bp):
    return [j for j in bp.joints if j.kind != "fixed"]


def joint_of(bp, child: str):
    return next(j for j in bp.joints if j.child == child)


# -- structure -----------------------------------------------------------------


def test_required_parts_and_labels(lamp_bp):
    p, bp = lamp_bp
    want = {"base": "base", "lower_pole": "pole", "upper_pole": "pole", "head": "head", "shade": "shade"}
    for name, label in want.items():
        assert bp.parts[name].label == label
    assert {part.label for part in bp.parts.values()} <= LABELS
    assert bp.root == "base"
    assert ("bulb" in bp.parts) == p["has_bulb"]
    assert ("switch" in bp.parts) == p["has_switch"]
    arms = sorted(n for n, part in bp.parts.items() if part.label == "arm")
    if p["arm_style"] == "straight":
        assert arms == []
    elif p["arm_style"] == "curved":
        assert arms == ["arm"] and joint_of(bp, "arm").kind == "fixed"
    else:
        assert arms == [f"arm_{k}" for k in range(p["arm_segments"])]
    assert joint_of(bp, "lower_pole").kind == "fixed" and joint_of(bp, "lower_pole").parent == "base"
    assert joint_of(bp, "shade").kind == "fixed" and joint_of(bp, "shade").parent == "head"


def test_height_is_the_sampled_height(lamp_bp):
    p, bp = lamp_bp
    H = p["floor_height"] if p["lamp_type"] == "floor" else p["desk_height"]
    lo, hi = bp.bounds()
    assert lo[2] == pytest.approx(bp.elevation, abs=1e-9)
    assert hi[2] == pytest.approx(desk_top(p) + H, abs=1e-6)


def test_materials_are_declared_and_fit_their_parts(lamp_bp):
    p, bp = lamp_bp
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    assert all(split_spec(spec)[0] in FAMILIES for spec in bp.materials.values())
    family = {slot: split_spec(spec)[0] for slot, spec in bp.materials.items()}  # painted: the furniture palette
    assert family["base"] in {"brushed_metal", "chrome", "enamel", "wood", "ceramic"}
    assert family["pole"] in {"chrome", "brushed_metal", "painted"}
    assert family["shade"] in {"fabric", "painted"}
    assert bp.materials["bulb"] == "glass:frosted"  # warm-white opal bulb glass
    assert all(pc.material == "shade" for pc in bp.parts["shade"].pieces[:1])


def test_every_piece_collides_except_the_hidden_base_weight(lamp_bp):
    _, bp = lamp_bp
    for name, part in bp.parts.items():
        for pc in part.pieces:
            assert pc.convex or (name == "base" and pc.material == "weight")


# -- joints --------------------------------------------------------------------


def test_upper_pole_rests_collapsed_pulls_up_and_turns(lamp_bp):
    p, bp = lamp_bp
    # a two-stage floor pole: the middle tube turns and slides in the lower one, the upper pole slides in it
    first = "middle_pole" if "middle_pole" in bp.parts else "upper_pole"
    assert (first == "middle_pole") == (p["lamp_type"] == "floor" and p["pole_stages"] == 2)
    j = joint_of(bp, first)
    assert j.kind == "revolute_prismatic" and j.parent == "lower_pole"
    slide, turn = j.dofs
    # at rest it sits on its stop (slide 0) and extends upward: gravity holds it collapsed
    assert slide.type == "prismatic" and np.allclose(slide.axis, (0, 0, 1))
    assert turn.type == "revolute" and np.allclose(turn.axis, (0, 0, 1))
    assert (turn.lower, turn.upper) == pytest.approx((-math.pi, math.pi))
    assert np.allclose(turn.origin[:2], 0) and np.allclose(slide.origin, turn.origin)
    # L = the stage's length above the tube top (the joint origin)
    stage = bp.parts[first].pieces[:2 if first == "middle_pole" else 1]  # tube (and collar); not an arm's hub
    L = max(pc.bounds[1, 2] for pc in stage) - slide.origin[2]
    assert slide.lower == 0 and slide.upper == pytest.approx(0.25 * L, rel=1e-6)
    # the stage sits inside the tube: its radius is below the tube's inner radius
    tube = bp.parts["lower_pole"].pieces[0].vertices
    pole = stage[0].vertices  # (a middle tube's collar stays above the lower tube)
    r_in = np.hypot(tube[:, 0], tube[:, 1]).min()
    assert np.hypot(pole[:, 0], pole[:, 1]).max() + 0.002 <= r_in
    # collapsed, its end stays above the base; fully extended, it is still well inside the tube
    z_end = pole[:, 2].min()
    assert z_end > tube[:, 2].min() + 0.002
    assert z_end + slide.upper < slide.origin[2] - 0.005
    if first == "middle_pole":
        up = joint_of(bp, "upper_pole")
        (d,) = up.dofs
        assert up.kind == "prismatic" and up.parent == "middle_pole"
        assert np.allclose(d.axis, (0, 0, 1)) and d.lower == 0 < d.upper
        mid = bp.parts["middle_pole"].pieces[0].vertices
        rod = bp.parts["upper_pole"].pieces[0].vertices
        assert np.hypot(rod[:, 0], rod[:, 1]).max() + 0.002 <= np.hypot(mid[:, 0], mid[:, 1]).min()
        assert rod[:, 2].min() > mid[:, 2].min() + 0.002  # collapsed, above the middle tube's end
        assert rod[:, 2].min() + d.upper < d.origin[2] - 0.005  # extended, still inside it


def test_socket_knob_turns_on_an_upright_head():
    p, bp = make(0, arm_style="straight", has_switch=True, switch_kind="socket_switch")
    j = joint_of(bp, "switch")
    (d,) = j.dofs
    assert j.kind == "continuous" and j.parent == "head"
    assert abs(d.axis[2]) < 1e-9  # about its own horizontal, radial axis: balanced, gravity leaves it
    knob = np.vstack([pc.vertices for pc in bp.parts["switch"].pieces])
    r = np.hypot(knob[:, 0], knob[:, 1])
    assert r.min() > 0.005 and r.max() < 0.05  # it stands out of the socket, inside the shade
    # a hanging head has no turn-knob socket: another lamp draws a push switch on its base
    p, bp = make(0, arm_style="chain", has_switch=True, switch_kind="socket_switch")
    assert p["switch_kind"] == "push_switch" and joint_of(bp, "switch").parent == "base"


def test_pole_extended_makes_the_lamp_taller(lamp_bp):
    p, bp = lamp_bp
    H = p["floor_height"] if p["lamp_type"] == "floor" else p["desk_height"]
    slide = joint_of(bp, "upper_pole").dofs[0]
    up = bp.poses({("upper_pole", 0): slide.upper})
    top = max((pc.vertices @ up[n][:3, :3].T + up[n][:3, 3])[:, 2].max()
              for n, part in bp.parts.items() for pc in part.pieces)
    assert top == pytest.approx(desk_top(p) + H + slide.upper, abs=1e-6)


def test_head_turns_or_tilts(lamp_bp):
    p, bp = lamp_bp
    j = joint_of(bp, "head")
    (d,) = j.dofs
    if p["arm_style"] == "straight" or (p["arm_style"] == "curved" and p["lamp_type"] == "floor"):
        assert j.kind == "continuous" and np.allclose(np.abs(d.axis), (0, 0, 1))
    else:
        assert j.kind == "revolute" and np.allclose(np.abs(d.axis), (0, 1, 0))
        assert (d.lower, d.upper) == pytest.approx((-p["head_tilt"], p["head_tilt"]))


def test_chain_segments_pitch_or_swing(lamp_bp):
    p, bp = lamp_bp
    if p["arm_style"] != "chain":
        return
    for k in range(p["arm_segments"]):
        j = joint_of(bp, f"arm_{k}")
        (d,) = j.dofs
        assert j.kind == "revolute"
        if np.allclose(np.abs(d.axis), (0, 1, 0)):  # pitch, declared both ways (the core picks a side)
            assert d.upper == pytest.approx(math.pi / 6)  # +q turns the arm up and back, by pi/6
            assert -math.pi / 6 - 1e-9 <= d.lower <= -math.pi / 12 + 1e-9  # forward, less near the ground
        else:  # swing arm on a vertical pin
            assert k > 0 and np.allclose(np.abs(d.axis), (0, 0, 1))
            assert (d.lower, d.upper) == pytest.approx((-math.pi / 2, math.pi / 2))
    assert np.allclose(np.abs(joint_of(bp, "arm_0").dofs[0].axis), (0, 1, 0))


@pytest.mark.parametrize("seed", [1, 4, 6])
def test_chain_pitch_joints_rest_on_their_stop_in_the_object(seed):
    """The core keeps the side of a pitch hinge that lifts its load: it rests on lower = 0."""
    from infmob_usd.api import generate

    obj = generate("lamp", seed, 16)
    pitch = [j for j in obj.movable_joints if j.child.startswith("arm_") and np.allclose(np.abs(j.axis), (0, 1, 0))]
    for j in pitch:
        assert j.lower == 0 and 0 < j.upper <= math.pi / 6 + 1e-9


def test_bulb_screws_out_of_its_socket(lamp_bp):
    """A standing bulb turns and slides up out of its socket; a hanging one only turns."""
    p, bp = lamp_bp
    if not p["has_bulb"]:
        return
    j = joint_of(bp, "bulb")
    assert j.parent == "head"
    if p["arm_style"] != "straight":
        (turn,) = j.dofs
        assert j.kind == "continuous" and np.allclose(np.abs(turn.axis), (0, 0, 1))
        return
    assert j.kind == "continuous_prismatic"
    slide, turn = j.dofs
    assert np.allclose(slide.axis, (0, 0, 1))
    assert np.allclose(slide.axis, turn.axis) and np.allclose(np.abs(slide.axis), (0, 0, 1))
    assert slide.lower == 0 and 0 < slide.upper <= 0.02
    # unscrewing moves the bulb away from the socket's closed end (toward the glass tip)
    glass = np.vstack([pc.vertices for pc in bp.parts["bulb"].pieces if pc.material == "bulb"])
    tip_dir = (glass.mean(0) - np.asarray(slide.origin)) @ np.asarray(slide.axis)
    assert tip_dir > 0


def test_switch_is_pressed_horizontally_toward_the_pole(lamp_bp):
    p, bp = lamp_bp
    if not p["has_switch"] or p["switch_kind"] != "push_switch":
        return
    j = joint_of(bp, "switch")
    (d,) = j.dofs
    assert j.kind == "prismatic" and j.parent == "base"
    assert abs(d.axis[2]) < 1e-9 and d.lower == 0 and 0 < d.upper <= 0.01
    assert np.dot(d.axis[:2], d.origin[:2]) < 0  # pressing moves it toward the pole
    # it stands on the base, inside its outline
    button = bp.parts["switch"].pieces[0].vertices
    base = bp.parts["base"].pieces[0].vertices
    assert np.all(np.abs(button[:, :2]).max(0) <= np.abs(base[:, :2]).max(0))


def test_limits_contain_rest_and_pivots_sit_in_the_hinge(lamp_bp):
    _, bp = lamp_bp
    for j in movable(bp):
        planes = [ConvexHull(c).equations for n in (j.child, j.parent)
                  for pc in bp.parts[n].pieces for c in pc.convex]
        for d in j.dofs:
            assert d.lower <= 0 <= d.upper and d.lower < d.upper
            if d.type != "prismatic":
                # the pivot is inside (within 5 mm of) a collision piece of the turning part or its
                # parent: the axis runs through the hinge, not through empty space
                x = np.asarray(d.origin)
                if j.child == "middle_pole":  # a tube turning in a tube: the pivot is on their common axis
                    z = np.vstack([pc.vertices for pc in bp.parts["middle_pole"].pieces])[:, 2]
                    assert np.allclose(x[:2], 0) and z.min() < x[2] < z.max()
                    continue
                depth = min(float((eq[:, :3] @ x + eq[:, 3]).max()) for eq in planes)
                assert depth < 0.005, f"{j.child}: pivot {x} is {depth * 1000:.1f} mm off its hinge"


# -- physical plausibility ------------------------------------------------------


def test_moving_parts_clear_their_parents_at_rest(lamp_bp):
    _, bp = lamp_bp
    rest = bp.poses()
    for j in movable(bp):
        v = overlaps(bp, [j.child], rest, [j.parent], rest)
        assert sum(v.values()) < 1e-9, f"{j.child} is embedded in {j.parent} at rest"


def test_every_joint_limit_stays_above_ground_and_enters_nothing(lamp_bp):
    """Each joint alone at every corner of its range, moving its whole subtree."""
    _, bp = lamp_bp
    rest = bp.poses()
    for j in movable(bp):
        moved = descendants(bp.joints, j.child)
        still = [n for n in bp.parts if n not in moved]
        before = overlaps(bp, moved, rest, still, rest)
        for q in limit_states(j):
            now = bp.poses(q)
            z = min((c @ now[n][2, :3] + now[n][2, 3]).min() for n in moved for pc in bp.parts[n].pieces
                    for c in pc.convex)
            assert z > -1e-3, f"{j.child} at {q} goes {-z * 1000:.1f} mm below the ground"
            for pair, v in overlaps(bp, moved, now, still, rest).items():
                assert v <= before.get(pair, 0.0) + 1e-8, f"{pair} overlap {v * 1e6:.2f} cm^3 at {q}"


def carried_mass(bp, name: str) -> tuple[float, np.ndarray]:
    """Mass and centre of mass at rest of a part and everything it carries."""
    mass, moment = 0.0, np.zeros(3)
    for n in descendants(bp.joints, name):
        part = bp.parts[n]
        m, com, _ = inertial((pc, FAMILIES[split_spec(bp.materials[pc.material])[0]].density) for pc in part.pieces)
        mass, moment = mass + m, moment + m * com
    return mass, moment / mass


@pytest.mark.parametrize("seed", range(6))
def test_gravity_holds_every_joint_at_rest(seed):
    """Each DoF of the generated lamp is neutral under gravity, balanced, or pressed into the
    lower limit it rests on (the core's ``rest_on_stops`` picks the side of two-sided hinges).

    Neutral: a rotation about a vertical axis, or a horizontal slide. A slide along
    gravity rests at lower = 0 with gravity pushing toward negative q. A hinge about a
    horizontal axis either carries its centre of mass straight below the axis
    (balanced, stable) or rests at lower = 0 with the gravity torque of everything
    it carries pushing toward negative q.
    """
    from infmob_usd.api import generate
    from infmob_usd.physical import gravity_torque

    obj = generate("lamp", seed, 16)
    for j in obj.movable_joints:
        torque, m, com = gravity_torque(obj.links, obj.joints, j)
        a, o = np.asarray(j.axis), np.asarray(j.origin)
        if j.type == "prismatic":
            if abs(a[2]) < 1e-9:
                continue
            assert j.lower == 0 and -9.81 * m * a[2] < 0, f"{j.child}: gravity pulls the slide into its range"
            continue
        if abs(a[2]) > 1 - 1e-9 or j.type == "continuous":
            continue
        assert abs(a[2]) < 1e-9, f"{j.child}: tilted hinge axis {a}"
        arm = abs(torque) / (9.81 * m)  # horizontal offset of the load from the axis
        if arm < 2e-4:
            assert com[2] < o[2], f"{j.child}: balanced upside down"
            continue
        assert j.lower == 0 and torque < 0, (
            f"{j.child}: gravity torque {torque:.3f} N m does not press it onto its lower stop"
            f" [{j.lower:.3f}, {j.upper:.3f}]")


def test_stands_on_its_base(lamp_bp):
    """Only the base touches the ground, and the centre of mass lies over it; a clamp lamp's clamp holds it on the
    desk top, which nothing else reaches below."""
    p, bp = lamp_bp
    for name, part in bp.parts.items():
        if name not in ("base", "screw"):
            assert min(pc.bounds[0, 2] for pc in part.pieces) > desk_top(p) + 1e-3, name
    if p["base_shape"] == "clamp":
        return
    mass, moment = 0.0, np.zeros(3)
    for part in bp.parts.values():
        m, com, _ = inertial((pc, FAMILIES[split_spec(bp.materials[pc.material])[0]].density) for pc in part.pieces)
        mass, moment = mass + m, moment + m * com
    base = np.vstack([pc.vertices for pc in bp.parts["base"].pieces])
    half = np.abs(base[:, :2]).max(0)
    assert np.all(np.abs(moment[:2] / mass) < 0.8 * half)


# -- parameters -------------------------------------------------------------------


def test_schema_has_the_growth_flags_and_arm_choice():
    names = lamp.CATEGORY.schema.names
    assert {"has_bulb", "has_switch", "lamp_type", "arm_style", "arm_segments"} <= set(names)
    assert lamp.CATEGORY.schema["arm_style"].choices == tuple(lamp.GRAMMAR.nodes["arm"].one_of)
    assert lamp.CATEGORY.schema["lamp_type"].weights == (0.55, 0.45)
    assert "lamp: builds base; requires pole, arm; may grow bulb (0.6), switch (0.8)" in lamp.CATEGORY.rules()


@pytest.mark.parametrize("seed", [0, 3])
def test_lamp_type_override_sets_the_height_range(seed):
    p, bp = make(seed, lamp_type="floor")
    assert 1.0 <= bp.bounds()[1, 2] <= 1.5
    p, bp = make(seed, lamp_type="desk", desk_height=0.42)
    assert bp.bounds()[1, 2] == pytest.approx(0.42)


def test_style_overrides_shape_the_arm():
    _, bp = make(5, arm_style="chain", arm_segments=3)
    assert {f"arm_{k}" for k in range(3)} <= set(bp.parts)
    _, bp = make(5, arm_style="curved", lamp_type="floor")
    assert joint_of(bp, "head").kind == "continuous"
    _, bp = make(5, arm_style="straight", has_bulb=False, has_switch=False)
    assert not {"bulb", "switch", "arm"} & set(bp.parts)


def test_deterministic():
    for seed in (1, 2):
        (p1, a), (p2, b) = make(seed), make(seed)
        assert p1 == p2 and list(a.parts) == list(b.parts) and a.joints == b.joints
        for name in a.parts:
            for x, y in zip(a.parts[name].pieces, b.parts[name].pieces):
                assert np.array_equal(x.vertices, y.vertices)


@pytest.mark.parametrize("style,kind", [("straight", "desk"), ("chain", "floor"), ("curved", "floor")])
def test_tripod_base_stands_on_three_feet(style, kind):
    p, bp = make(3, base_shape="tripod", arm_style=style, lamp_type=kind, has_switch=True,
                 switch_kind="push_switch")
    assert p["base_shape"] == "tripod" and not p["has_switch"] and "switch" not in bp.parts
    base = bp.parts["base"].pieces
    feet = [pc for pc in base if pc.material == "fitting"]
    assert len(feet) == 3 and all(pc.bounds[0, 2] == pytest.approx(0.0, abs=1e-9) for pc in feet)
    centres = np.array([pc.bounds.mean(0)[:2] for pc in feet])
    assert np.linalg.norm(centres, axis=1).min() > 0.1  # splayed well out from the pole
    # real pole and arm thicknesses: 15-25 mm poles
    pole = np.array([pc.bounds for pc in bp.parts["upper_pole"].pieces])
    assert pole[:, 1, 0].max() - pole[:, 0, 0].min() >= 0.015


@pytest.mark.parametrize("style", ["curved", "chain"])
def test_a_desk_lamp_with_a_hanging_head_is_not_on_a_tripod(style):
    """A tripod's 16 cm hub leaves a desk lamp no room for a head hanging from an arm: without this rule it
    grew a 7-17 mm shade whose rim held the bulb fast. Such a lamp stands on a round base, its shade full size."""
    p, bp = make(35, base_shape="tripod", arm_style=style, lamp_type="desk", has_bulb=True)
    assert p["base_shape"] == "round"
    shade = np.array([pc.bounds for pc in bp.parts["shade"].pieces])
    assert (shade[:, 1, 1].max() - shade[:, 0, 1].min()) / 2 >= 0.75 * 0.5 * p["desk_shade_radius"]


@pytest.mark.parametrize("shape", ["round", "square", "domed"])
def test_rotary_dimmer_turns_on_the_base(shape):
    """A rotary switch is a dimmer knob on the base's top: it turns about z (neutral under gravity) through
    about 300 degrees, above its boss, inside the base's outline, clear of everything at any angle."""
    p, bp = make(2, base_shape=shape, has_switch=True, switch_kind="rotary_switch")
    j = joint_of(bp, "switch")
    (d,) = j.dofs
    assert j.kind == "revolute" and j.parent == "base" and d.axis == pytest.approx((0, 0, 1))
    assert d.lower == 0 and 5.0 < d.upper < 5.5
    knob = np.vstack([pc.vertices for pc in bp.parts["switch"].pieces])
    base = np.vstack([pc.vertices for pc in bp.parts["base"].pieces if pc.material == "base"])
    assert np.hypot(*knob[:, :2].T).max() < np.hypot(*base[:, :2].T).max()
    assert knob[:, 2].min() > d.origin[2] - 1e-9
    for q in (0.0, 0.5 * d.upper, d.upper):
        m = dof_motion(d, q)
        for other in bp.parts:
            if other != "switch":
                assert overlap(bp.parts["switch"], m, bp.parts[other], np.eye(4)) < 1e-9, (other, q)


@pytest.mark.parametrize("style", ["straight", "curved", "chain"])
def test_clamp_lamp_hangs_on_a_desk_edge(style):
    """A desk clamp (architect lamps): the upper jaw lies on the desk top, DESK_TOP up; the spindle turns and
    rises until its pad is a gap under the upper jaw, its T-bar then still clear of the lower jaw; no base
    switch (no base plate); a floor lamp drawing a clamp stands on a round base."""
    p, bp = make(5, base_shape="clamp", lamp_type="desk", arm_style=style, has_switch=True,
                 switch_kind="rotary_switch")
    assert p["base_shape"] == "clamp" and p["has_screw"] and "switch" not in bp.parts
    base = np.array([pc.bounds for pc in bp.parts["base"].pieces])
    jaw = bp.parts["base"].pieces[0].bounds
    assert jaw[0, 2] == pytest.approx(L.DESK_TOP, abs=1e-9)  # the upper jaw's underside on the desk top
    assert base[:, 0, 2].min() < L.DESK_TOP - L.CLAMP["throat"]
    j = next(j for j in bp.joints if j.child == "screw")
    assert j.kind == "continuous_prismatic" and j.parent == "base"
    slide = j.dofs[0]
    assert slide.lower == 0 and slide.upper > 0.8 * L.CLAMP["throat"]
    rest = bp.poses()
    assert not overlaps(bp, ["screw"], rest, ["base"], rest)
    for q in ({("screw", 0): slide.upper}, {("screw", 0): slide.upper, ("screw", 1): 1.3}):
        now = bp.poses(q)
        assert not overlaps(bp, ["screw"], now, ["base"], rest), q
        pad_top = max((pc.vertices @ now["screw"][:3, :3].T + now["screw"][:3, 3])[:, 2].max()
                      for pc in bp.parts["screw"].pieces)
        assert L.DESK_TOP - 0.004 < pad_top < L.DESK_TOP  # the pad meets the desk's underside
    p, bp = make(5, base_shape="clamp", lamp_type="floor", arm_style=style)
    assert p["base_shape"] == "round" and "screw" not in bp.parts and bp.elevation == 0


@pytest.mark.sim
def test_clamp_lamp_screw_and_arm_reach_in_sapien(tmp_path):
    pytest.importorskip("sapien")
    import infmob_usd
    from infmob_usd.validate.sim import check_sapien

    obj = infmob_usd.generate("lamp", seed=5, texture_size=16, base_shape="clamp", lamp_type="desk",
                              arm_style="chain")
    res = {c.name: c for c in check_sapien(infmob_usd.save(obj, tmp_path), checks=["reach", "rest"])}
    assert res["reach"].ok, res["reach"].detail
    assert res["rest"].ok, res["rest"].detail


@pytest.mark.parametrize("seed,over", [
    (598892, dict(desk_shade_radius=0.13, lamp_type="desk", desk_height=0.352, base_shape="tripod",
                  arm_style="straight", switch_kind="socket_switch", has_bulb=False)),
    (938943, dict(desk_height=0.35, pole_radius=0.0125, base_shape="tripod", arm_style="straight", has_bulb=False)),
    (590166, dict(desk_height=0.35, lamp_type="desk", base_shape="tripod", arm_style="straight", pole_radius=0.0075,
                  lower_pole_fraction=0.55, desk_shade_radius=0.13)),
])
def test_a_short_desk_lamp_on_a_tripod_keeps_a_pole_under_its_head(seed, over):
    """A 0.35 m desk lamp on a 0.16 m tripod hub under a 13 cm shade would keep
    29-43 mm of pole, its head's collar in the lower pole's. The shade shrinks until MIN_POLE is left."""
    p, bp = make(seed, **over)
    assert p["base_shape"] == "tripod" and p["arm_style"] == "straight"
    lo = min(pc.bounds[0, 2] for pc in bp.parts["lower_pole"].pieces)
    hi = max(pc.bounds[1, 2] for pc in bp.parts["upper_pole"].pieces)
    assert hi - lo >= L.MIN_POLE - 1e-9
    rest = bp.poses()
    assert not overlaps(bp, ["head"], rest, ["lower_pole", "base"], rest)
