"""The tap category, checked on its blueprint (world space, grounded): parts, joints, clearances."""

from __future__ import annotations

import math

import manifold3d
import numpy as np
import pytest

from infmob_usd.categories.parts import taps
from infmob_usd.mass import inertial
from infmob_usd.materials import FAMILIES
from infmob_usd.materials.families import split_spec

from helpers import maker
from helpers import states as shared_states
from zoo import by_child, movable

SEEDS = range(8)
LABELS = {"base", "spout", "lever", "handle", "spray_head", "button", "knob"}
TOL = 1e-7  # m^3, as the validator's contact volume


make = maker("tap")


@pytest.fixture(scope="module", params=SEEDS)
def tap_bp(request):
    return make(request.param)


# -- kinematics and collision helpers ----------------------------------------------------


def at(d, f):
    return f * math.pi if d.type == "continuous" else d.lower + f * (d.upper - d.lower)


def states(bp):
    """The shared sampled states (:func:`helpers.states`) and the spout at eight angles with the rest at upper."""
    js = movable(bp)
    out = shared_states(bp)
    spout = by_child(bp, "spout").dofs[0]
    lo, hi = (-math.pi, math.pi) if spout.type == "continuous" else (spout.lower, spout.upper)
    for a in np.linspace(lo, hi, 8):
        q = {(j.child, i): at(d, 1.0) for j in js for i, d in enumerate(j.dofs)}
        q[("spout", 0)] = a
        out.append(q)
    return out


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


def single_lever(p):
    return p["design"] in ("pull_out", "wall") or (p["design"] == "deck" and p["handles"] == "single_lever")


def own_pipe(p):
    return p["design"] in ("pull_out", "bridge") or (p["design"] == "deck" and p["has_separate_pipe"])


def test_parts_labels_and_materials(tap_bp):
    p, bp = tap_bp
    assert bp.root == "base" and bp.parts["base"].label == "base"
    assert bp.parts["spout"].label == "spout"
    assert {part.label for part in bp.parts.values()} <= LABELS
    if single_lever(p):
        assert bp.parts["lever"].label == "lever" and "handle_0" not in bp.parts
        assert any(pc.name == "handle" for pc in bp.parts["lever"].pieces)
    else:
        assert bp.parts["handle_0"].label == bp.parts["handle_1"].label == "handle" and "lever" not in bp.parts
        assert any(pc.material == "hot" for pc in bp.parts["handle_0"].pieces)
        assert any(pc.material == "cold" for pc in bp.parts["handle_1"].pieces)
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    assert bp.materials["metal"] in ("chrome", "brushed_metal", "enamel:black")
    # every piece collides but the pull-out hose, drawn inside the spout's solid arm hulls
    assert all(pc.convex for part in bp.parts.values() for pc in part.pieces
               if not (part.label == "spray_head" and pc.material == "seal"))


def test_size(tap_bp):
    p, bp = tap_bp
    lo, hi = bp.bounds()
    assert lo[2] == pytest.approx(0.0, abs=1e-9)
    assert hi[2] <= 0.45
    if p["design"] != "wall":  # a wall mixer is as tall as its body and lever
        assert p["height"] - 1e-6 <= hi[2]
    deck = bp.parts["base"].pieces[0].bounds
    assert deck[1, 1] - deck[0, 1] >= min(p["base_width"], 0.12) - 1e-9


def test_spout_swivels_about_its_vertical_axis(tap_bp):
    p, bp = tap_bp
    j = by_child(bp, "spout")
    d = j.dofs[0]
    assert j.parent == "base" and d.axis == pytest.approx((0, 0, 1))
    assert d.origin[:2] == pytest.approx((0.0, 0.0))
    if p["spout_joint"] == "continuous":
        assert j.kind == "continuous"
    else:
        assert j.kind == "revolute" and (d.lower, d.upper) == (-p["spout_swivel"], p["spout_swivel"])
    spout = np.array([pc.bounds for pc in bp.parts["spout"].pieces])
    lo, hi = spout[:, 0].min(0), spout[:, 1].max(0)
    assert hi[0] > 0.05  # it reaches forward
    if own_pipe(p):  # on top of its own pipe: nothing of it behind the axis
        assert lo[0] > -0.0125 and lo[2] > 0.02
    else:  # a collar around the column
        assert lo[0] < -p["body_radius"]


def test_controls(tap_bp):
    p, bp = tap_bp
    if single_lever(p):
        j = by_child(bp, "lever")
        assert j.kind == "flip_revolute" and j.parent == "base"
        swivel, lift = j.dofs
        assert swivel.axis == pytest.approx((0, 0, 1))
        assert (swivel.lower, swivel.upper) == pytest.approx((-math.pi / 2, math.pi / 2))
        assert lift.axis == pytest.approx((0, -1, 0)) and (lift.lower, lift.upper) == (0.0, p["lever_tilt"])
        # the load is in front of the lift axis: gravity presses the lever onto its lower stop
        m, com = carried_mass(bp, "lever")
        torque = float(np.cross(com - np.asarray(lift.origin), m * np.array([0, 0, -9.81])) @ np.asarray(lift.axis))
        assert torque < 0
    else:
        for name in ("handle_0", "handle_1"):
            j = by_child(bp, name)
            d = j.dofs[0]
            assert j.kind == "revolute" and d.axis == pytest.approx((0, 0, 1))
            assert (d.lower, d.upper) == pytest.approx((-math.pi / 4, math.pi / 4))
        y0, y1 = (by_child(bp, n).dofs[0].origin[1] for n in ("handle_0", "handle_1"))
        assert y0 == pytest.approx(-y1) and y0 > 0


def test_no_contact_and_nothing_below_ground_in_any_state(tap_bp):
    """Like the validator: non-jointed parts never touch; a child never sinks further into its parent."""
    _, bp = tap_bp
    jointed = {frozenset((j.parent, j.child)) for j in movable(bp)}
    names = list(bp.parts)
    pairs = [(a, b) for i, a in enumerate(names) for b in names[i + 1:] if frozenset((a, b)) not in jointed]
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


@pytest.mark.parametrize("handles", ["single_lever", "two_handles"])
@pytest.mark.parametrize("pipe", [True, False])
def test_forced_handles_and_pipe_build_those_parts_and_stay_clear(handles, pipe):
    """Forced handle styles and a separate pipe give those parts, and the tap stays clear in every state (the
    generic contract: test_category_contract)."""
    p, bp = make(2, design="deck", handles=handles, has_separate_pipe=pipe, spout_shape="gooseneck", height=0.15)
    assert ("lever" in bp.parts) == (handles == "single_lever")
    assert ("handle_1" in bp.parts) == (handles == "two_handles")
    assert p["has_separate_pipe"] == pipe
    test_no_contact_and_nothing_below_ground_in_any_state((p, bp))


@pytest.mark.parametrize("design", ["deck", "bridge", "pull_out", "wall"])
def test_each_design_is_forced_and_moves(design):
    p, bp = make(5, design=design, height=0.3)
    assert p["design"] == design
    kinds = {j.child: j.kind for j in movable(bp)}
    assert kinds["spout"] in ("continuous", "revolute")
    if design == "pull_out":  # the spray head slides out of the spout along its arm and turns
        j = by_child(bp, "spray_head")
        assert j.parent == "spout" and j.kind == "continuous_prismatic"
        assert j.dofs[0].axis == pytest.approx((1, 0, 0)) and j.dofs[0].upper >= 0.1
    if design == "bridge":
        assert {"handle_0", "handle_1"} <= set(kinds)
    if design in ("pull_out", "wall"):
        assert kinds["lever"] == "flip_revolute"
    if design == "wall":  # the spout swings in front of the wall, never into it
        d = by_child(bp, "spout").dofs[0]
        assert kinds["spout"] == "revolute" and d.upper <= taps.WALL_SWIVEL + 1e-9
    test_no_contact_and_nothing_below_ground_in_any_state((p, bp))


def test_lever_never_leaves_its_cartridge():
    """The lever turns about the cartridge pin through its hub: at full lift the hub is where it was
    (a lever turned about a pin elsewhere lifts straight off the body: tap seeds 7004-7006 did)."""
    for seed in range(6):
        p, bp = make(seed, design="deck", handles="single_lever")
        j = by_child(bp, "lever")
        lift = j.dofs[1].upper
        hub = bp.parts["lever"].pieces[0]
        rest = bp.poses()["lever"]
        up = bp.poses({("lever", 1): lift})["lever"]
        for pose in (rest, up):
            c = hub.vertices.mean(0) @ pose[:3, :3].T + pose[:3, 3]
            assert np.linalg.norm(c - np.asarray(j.dofs[1].origin)) < 1e-6


def test_seeds_differ():
    params = [make(s)[0] for s in range(20)]
    for name in ("design", "handles", "has_separate_pipe", "spout_shape", "finish", "spout_joint"):
        assert len({p[name] for p in params}) > 1, name


@pytest.mark.parametrize("seed", range(3))
def test_wall_mixer_diverter_pulls_up(seed):
    p, bp = make(seed, design="wall", has_diverter=True)
    j = by_child(bp, "diverter")
    assert (j.parent, j.kind) == ("base", "prismatic") and j.dofs[0].axis == pytest.approx((0, 0, 1))
    assert bp.parts["diverter"].label == "knob" and j.dofs[0].upper == pytest.approx(0.008)
    test_no_contact_and_nothing_below_ground_in_any_state((p, bp))
