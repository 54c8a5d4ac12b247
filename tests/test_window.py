"""The window category: parts, joints, clearances at every joint state, overrides, seeds."""

from __future__ import annotations

import math

import numpy as np
import pytest

from infmob_usd.blueprint import dof_motion
from infmob_usd.categories import window as win
from infmob_usd.categories.parts import windows

from collide import overlap
from helpers import maker, states
from zoo import by_child, movable, object_limits

SEEDS = range(8)
LABELS = {"frame", "sash", "shutter", "curtain", "handle", "vent", "lock"}
VOLUME_TOL = 1e-7  # m^3, as the validator
EYE = np.eye(4)


make = maker("window")


def bounds(part, skip_handle=False):
    b = np.array([pc.bounds for pc in part.pieces if not (skip_handle and pc.name in ("handle", "hinge"))])
    return b[:, 0].min(0), b[:, 1].max(0)


# -- parts, labels, materials --------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_parts_labels_and_materials(seed):
    p, bp = make(seed)
    assert bp.root == "frame" and bp.parts["frame"].label == "frame"
    assert {part.label for part in bp.parts.values()} <= LABELS
    sashes = [part for part in bp.parts.values() if part.label == "sash"]
    assert 1 <= len(sashes) <= 4
    for sash in sashes:
        assert any(pc.material == "glass" for pc in sash.pieces)
        assert any(pc.name == "handle" for pc in sash.pieces)
    assert bp.materials["glass"].startswith("glass")
    assert bp.materials["curtain"] == "fabric"
    assert bp.materials["frame"].split(":")[0] == p["frame_finish"]
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    shutters = sum(part.label == "shutter" for part in bp.parts.values())
    assert shutters == ((4 if p["width"] / 2 > p["shutter_leaf_width"] else 2) if p["has_shutters"] else 0)
    curtains = sum(part.label == "curtain" for part in bp.parts.values())
    assert curtains == ((1 if p["curtain_panels"] == "single" else 2) if p["has_curtains"] else 0)


@pytest.mark.parametrize("seed", SEEDS)
def test_size_and_ground(seed):
    p, bp = make(seed)
    lo, hi = bounds(bp.parts["frame"])
    frame = [pc for pc in bp.parts["frame"].pieces if pc.material == "frame"]
    flo = np.array([pc.bounds[0] for pc in frame]).min(0)
    fhi = np.array([pc.bounds[1] for pc in frame]).max(0)
    if not p["has_sill"]:
        assert fhi[1] - flo[1] == pytest.approx(p["width"])
        assert fhi[2] - flo[2] == pytest.approx(p["height"])
    assert 0.6 <= p["width"] <= 2.5 and 0.6 <= p["height"] <= 2.5
    assert bp.bounds()[0, 2] == pytest.approx(0.0, abs=1e-9)
    # nothing goes below the ground at any sampled state
    for q in states(bp):
        for name, m in bp.poses(q).items():
            pts = np.vstack([pc.vertices for pc in bp.parts[name].pieces])
            assert (pts @ m[:3, :3].T + m[:3, 3])[:, 2].min() >= -1e-9


# -- joints -------------------------------------------------------------------------------------


@pytest.mark.parametrize("seed", range(6))
def test_casement_hinges(seed):
    _, bp = make(seed, style="casement", has_curtains=False)
    for j in movable(bp):
        if bp.parts[j.child].label != "sash":
            continue
        d = j.dofs[0]
        assert j.kind == "revolute" and j.parent == "frame" and j.role == "hinge"
        assert (d.lower, d.upper) == (0.0, pytest.approx(math.pi / 2))
        lo, hi = bounds(bp.parts[j.child], skip_handle=True)
        assert d.origin[0] == pytest.approx(hi[0])  # on the room-side face
        if d.axis == pytest.approx((0, 0, -1)):  # hinged on its left edge, opens toward +X
            assert d.origin[1] == pytest.approx(lo[1])
        else:
            assert d.axis == pytest.approx((0, 0, 1))
            assert d.origin[1] == pytest.approx(hi[1])
        # opening moves the free edge into the room
        m = dof_motion(d, 0.5)
        centre = (lo + hi) / 2
        assert (m[:3, :3] @ centre + m[:3, 3])[0] > centre[0] + 0.05


@pytest.mark.parametrize("seed", range(6))
def test_sliding_sashes_stay_in_the_frame(seed):
    p, bp = make(seed, style="sliding")
    hole_lo = -p["width"] / 2
    for j in movable(bp):
        if bp.parts[j.child].label != "sash":
            continue
        d = j.dofs[0]
        assert j.kind == "prismatic" and abs(d.axis[1]) == pytest.approx(1.0) and d.lower == 0.0
        lo, hi = bounds(bp.parts[j.child])
        shift = d.axis[1] * d.upper
        assert lo[1] + shift > hole_lo and hi[1] + shift < -hole_lo
    tracks = {round(bounds(bp.parts[j.child])[0][0], 4) for j in movable(bp) if j.child.startswith("sash")}
    assert len(tracks) == (1 if len([j for j in movable(bp) if j.child.startswith("sash")]) == 1 else 2)


def test_shutters_and_curtains():
    _, bp = make(4, has_shutters=True, has_curtains=True, curtain_panels="pair", width=2.0, shutter_leaf_width=0.6)
    for k in (0, 1):
        d = by_child(bp, f"shutter_{k}").dofs[0]
        assert abs(d.axis[2]) == pytest.approx(1.0) and 0 < d.upper < math.pi / 2
        lo, hi = bounds(bp.parts[f"shutter_{k}"])
        frame_lo = min(pc.bounds[0, 0] for pc in bp.parts["frame"].pieces if pc.material == "frame"
                       and pc.bounds[1, 2] > 0.2)
        assert hi[0] < frame_lo  # outside the frame
        # the free edge swings away from the window (toward -X)
        m = dof_motion(d, d.upper)
        free = np.array([lo[0], 0.0, (lo[2] + hi[2]) / 2])
        assert (m[:3, :3] @ free + m[:3, 3])[0] < lo[0] - 0.1
        # a wide window's shutters are bifolds: the inner leaf hangs on the outer one
        inner = by_child(bp, f"shutter_{k + 2}")
        assert inner.parent == f"shutter_{k}" and inner.dofs[0].axis == d.axis
        assert inner.dofs[0].upper == pytest.approx(0.8 * math.pi)
        c = by_child(bp, f"curtain_{k}")
        dc = c.dofs[0]
        assert c.kind == "prismatic" and dc.axis[2] == 0.0 and abs(dc.axis[1]) == pytest.approx(1.0)
        clo, chi = bounds(bp.parts[f"curtain_{k}"])
        assert np.sign(dc.axis[1]) == np.sign(clo[1] + chi[1])  # slides outward from the centre


# -- clearances ------------------------------------------------------------------------------------


def _pairs_clear(bp, q):
    ps = bp.poses(q)
    parents = {j.child: j.parent for j in bp.joints}
    names = list(bp.parts)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            v = overlap(bp.parts[a], ps[a], bp.parts[b], ps[b])
            if parents.get(a) == b or parents.get(b) == a:
                rest = overlap(bp.parts[a], EYE, bp.parts[b], EYE)
                assert v <= rest + VOLUME_TOL, f"{a} enters its parent {b} at {q}"
            else:
                assert v < VOLUME_TOL, f"{a} and {b} collide at {q}"


@pytest.mark.parametrize("over", [
    dict(style="casement", sash_count=4, meeting="french", has_shutters=True, has_curtains=True, width=2.0,
         shutter_leaf_width=0.8),
    dict(style="casement", sash_count=3, width=1.2, meeting="mullion", has_transom=True, height=2.0),
    dict(style="sliding", sash_count=4, has_shutters=True, has_curtains=True, glazing="bars", width=2.4,
         shutter_leaf_width=0.6, shutter_style="boarded"),
    dict(style="sliding", sash_count=3, width=2.0, shutter_style="louvred", has_shutters=True),
    dict(style="sliding", sash_count=1, width=0.7, has_curtains=True),
])
def test_no_collision_at_any_sampled_state(over):
    """With the limits of the generated object (the core stops casements before the curtains)."""
    _, bp = make(11, **over)
    bp = object_limits("window", 11, bp, **over)
    for q in states(bp):
        _pairs_clear(bp, q)


@pytest.mark.parametrize("seed", (1, 4))
def test_moving_parts_keep_a_gap_at_rest(seed):
    """Shifted 1 mm in any axis direction, no moving part touches anything."""
    _, bp = make(seed, has_shutters=True, has_curtains=True)
    for j in movable(bp):
        for axis in range(3):
            for s in (-1, 1):
                m = np.eye(4)
                m[axis, 3] = s * 0.001
                for other in bp.parts:
                    if other != j.child:
                        assert overlap(bp.parts[j.child], m, bp.parts[other], EYE) < 1e-9, (j.child, other)


# -- overrides, growth, determinism ------------------------------------------------------------------


@pytest.mark.parametrize("style", ["tilt_turn", "awning", "double_hung"])
def test_each_design_is_forced_moves_and_stays_clear(style):
    # (object_limits reads back one-DoF joints only: a tilt-and-turn chain keeps its declared turn, which
    # the core stops short of curtains)
    over = dict(style=style, has_shutters=False, has_curtains=style != "tilt_turn")
    p, bp = make(12, **over)
    assert p["style"] == style
    kinds = {j.child: j.kind for j in movable(bp) if j.child.startswith("sash")}
    if style == "tilt_turn":  # turn on the side hinge, then tilt about the bottom rail (top inward)
        assert set(kinds.values()) == {"flip_revolute"}
        j = by_child(bp, "sash_0")
        turn, tilt = j.dofs
        assert abs(turn.axis[2]) == pytest.approx(1.0) and tilt.axis == pytest.approx((0, 1, 0))
        top = np.array([bounds(bp.parts["sash_0"], True)[1][0], tilt.origin[1], 1.0, 1.0])
        assert (dof_motion(tilt, tilt.upper) @ top)[0] > top[0] + 0.05
    elif style == "awning":  # top-hung, the bottom swings out (-X)
        assert set(kinds.values()) == {"revolute"}
        d = by_child(bp, "sash_0").dofs[0]
        lo, hi = bounds(bp.parts["sash_0"], True)
        bottom = np.array([lo[0], d.origin[1], lo[2], 1.0])
        assert d.origin[2] >= hi[2] - 1e-6 and (dof_motion(d, 0.3) @ bottom)[0] < bottom[0] - 0.05  # float32 vertices
        assert p["height"] <= 1.0
    else:  # the lower sash slides up, the upper one tilts in
        assert kinds == {"sash_0": "prismatic", "sash_1": "revolute"}
        assert by_child(bp, "sash_0").dofs[0].axis == pytest.approx((0, 0, 1))
        assert p["width"] <= 1.2
    bp = object_limits("window", 12, bp, **over)
    for q in states(bp):
        _pairs_clear(bp, q)


def test_forced_sashes_shutters_and_curtains_build_those_parts():
    """Forced sash counts and styles, shutters and curtains give those parts and joints; curtains alone limit
    a casement (the generic contract: test_category_contract)."""
    _, bp = make(3, sash_count=3, style="casement", has_shutters=False, has_curtains=False, has_trickle_vents=False)
    assert sorted(n for n, part in bp.parts.items() if part.label == "sash") == ["sash_0", "sash_1", "sash_2"]
    assert {j.kind for j in movable(bp)} == {"revolute"}
    _, bp = make(3, sash_count=2, style="sliding", has_shutters=True, width=1.0)
    assert {j.kind for j in movable(bp) if j.child.startswith("sash")} == {"prismatic"}
    assert {n for n, part in bp.parts.items() if part.label == "shutter"} == {"shutter_0", "shutter_1"}
    _, bp = make(3, width=2.4, has_shutters=True, shutter_leaf_width=0.7)
    assert sum(part.label == "shutter" for part in bp.parts.values()) == 4
    p, _ = make(3, width=1.5, frame_finish="wood")
    assert p["width"] == 1.5 and p["frame_finish"] == "wood"
    # the casement angle is limited only by curtains
    _, bp = make(3, style="casement", has_curtains=True)
    assert all(0.3 < by_child(bp, n).dofs[0].upper <= math.pi / 2 for n in bp.parts if n.startswith("sash"))


def test_seeds_differ_in_ways_a_person_sees():
    made = [make(s) for s in range(16)]
    for name in ("style", "frame_finish", "glazing", "has_curtains", "has_sill"):
        assert len({p[name] for p, _ in made}) > 1, name
    assert len({sum(part.label == "sash" for part in bp.parts.values()) for _, bp in made}) >= 3
    counts = [len(movable(bp)) for _, bp in made]
    assert min(counts) < max(counts)


@pytest.mark.parametrize("style", ["casement", "tilt_turn"])
def test_lever_handles_turn_toward_the_hinge(style):
    """A casement or tilt-and-turn sash's lever is its own part: hanging under its spindle, it turns a quarter
    turn about the sash normal toward the hinge side, clear of its sash; knob handles stay fixed."""
    _, bp = make(2, style=style, sash_count=2, handle_style="lever", has_curtains=False, has_shutters=False)
    levers = [n for n, part in bp.parts.items() if part.label == "handle"]
    assert len(levers) == 2
    for name in levers:
        j = by_child(bp, name)
        d = j.dofs[0]
        sash = j.parent
        assert j.kind == "revolute" and abs(d.axis[0]) == pytest.approx(1.0) and d.upper == pytest.approx(math.pi / 2)
        hinge_y = by_child(bp, sash).dofs[0].origin[1]
        grip = max(bp.parts[name].pieces, key=lambda pc: np.ptp(pc.bounds[:, 2]))
        tip = np.array([grip.bounds[:, 0].mean(), d.origin[1], grip.bounds[0, 2], 1.0])
        moved = dof_motion(d, d.upper) @ tip
        assert abs(moved[1] - hinge_y) < abs(d.origin[1] - hinge_y)  # it swung toward the hinge side
        for q in (0.0, d.upper):
            assert overlap(bp.parts[name], dof_motion(d, q), bp.parts[sash], np.eye(4)) < VOLUME_TOL
    _, bp = make(2, style="casement", sash_count=2, handle_style="knob")
    assert not any(part.label == "handle" for part in bp.parts.values())


@pytest.mark.parametrize("style", ["casement", "sliding", "double_hung", "awning"])
def test_trickle_vents_slide_in_the_head(style):
    """Trickle vents: one per sash (one over a double-hung pair) on the head's room face; each shutter
    slides along y in its housing without leaving it or touching the frame."""
    p, bp = make(4, style=style, has_trickle_vents=True, has_curtains=False, has_shutters=False, sash_count=2)
    vents = sorted(n for n, part in bp.parts.items() if part.label == "vent")
    sashes = [n for n, part in bp.parts.items() if part.label == "sash"]
    assert len(vents) == (1 if style == "double_hung" else len(sashes))
    frame_hi = bounds(bp.parts["frame"])[1]
    for name in vents:
        j = by_child(bp, name)
        d = j.dofs[0]
        assert j.parent == "frame" and j.kind == "prismatic" and abs(d.axis[1]) == pytest.approx(1.0)
        assert 0.02 < d.upper <= 0.035
        lo, hi = bounds(bp.parts[name])
        assert lo[2] > max(bounds(bp.parts[s])[1][2] for s in sashes)  # above every sash
        assert hi[2] < frame_hi[2]
        for q in (0.0, d.upper):
            assert overlap(bp.parts[name], dof_motion(d, q), bp.parts["frame"], np.eye(4)) < VOLUME_TOL


def test_double_hung_sash_locks():
    """Cam locks on the lower sash's meeting rail, one on a narrow unit and two on one wider than 0.9 m; each
    lever turns a quarter turn about the vertical (no gravity torque) and stays clear of the upper sash."""
    for width, n in ((0.7, 1), (1.1, 2)):
        over = dict(style="double_hung", has_sash_locks=True, width=width, has_curtains=False, has_shutters=False)
        _, bp = make(5, **over)
        locks = [name for name, part in bp.parts.items() if part.label == "lock"]
        assert len(locks) == n
        top = bounds(bp.parts["sash_0"], True)[1][2]
        for name in locks:
            j = by_child(bp, name)
            d = j.dofs[0]
            assert j.parent == "sash_0" and j.kind == "revolute" and abs(d.axis[2]) == pytest.approx(1.0)
            assert d.origin[2] > top and d.upper == pytest.approx(math.pi / 2)
        bp = object_limits("window", 5, bp, **over)
        for q in states(bp):
            _pairs_clear(bp, q)


def test_single_curtain_panel_draws_to_one_side():
    """One curtain panel across the rod, sliding to one side; the rod reaches past it fully drawn."""
    _, bp = make(6, has_curtains=True, curtain_panels="single", style="sliding")
    assert [n for n, part in bp.parts.items() if part.label == "curtain"] == ["curtain_0"]
    d = by_child(bp, "curtain_0").dofs[0]
    lo, hi = bounds(bp.parts["curtain_0"])
    assert lo[1] < -0.3 and hi[1] > 0.3  # across the window
    m = dof_motion(d, d.upper)
    end = (m @ [0, hi[1] if d.axis[1] > 0 else lo[1], 0, 1])[1]
    rod = max((pc for pc in bp.parts["frame"].pieces if pc.material == "rod"), key=lambda pc: np.ptp(pc.bounds[:, 1]))
    assert rod.bounds[0, 1] < end < rod.bounds[1, 1]


@pytest.mark.parametrize("style", ["casement", "tilt_turn", "sliding"])
@pytest.mark.parametrize("width", [0.6, 1.0, 1.6])
def test_a_sash_count_too_many_for_the_frame_is_lowered(style, width):
    """Fuzz draw 51: sash_count 4 in a 0.6 m tilt-and-turn frame gave 6 cm sashes, narrower than their two stiles,
    whose turns jammed at 0.8 rad. The count is lowered to the most sashes of at least MIN_SASH."""
    p, bp = make(5, style=style, width=width, sash_count=4, has_shutters=False, has_curtains=False)
    sashes = [part for part in bp.parts.values() if part.label == "sash"]
    assert len(sashes) == p["sash_count"] == min(4, win.max_sashes(p)) >= 1
    for part in sashes:
        b = np.array([pc.bounds for pc in part.pieces if pc.material != "handle"])
        assert b[:, 1, 1].max() - b[:, 0, 1].min() > windows.MIN_SASH - 0.02  # sliding sashes overlap a little


@pytest.mark.sim
def test_fuzz_draw_51_turns_its_sash_open_in_sapien(tmp_path):
    pytest.importorskip("sapien")
    import infmob_usd
    from infmob_usd.validate.sim import check_sapien

    draw = dict(width=0.6, sash_count=4, frame_depth=0.14, frame_width=0.09, frame_finish="painted",
                handle_style="lever", handle_finish="plastic", shutter_leaf_width=0.8,
                curtain_offset=0.10134250746539765, curtain_overhang=0.25, curtain_panels="single", curtain_open=0.45,
                rod_finish="chrome", style="tilt_turn", has_curtains=False, has_transom=True)
    obj = infmob_usd.generate("window", seed=784298, texture_size=16, **draw)
    res = {c.name: c for c in check_sapien(infmob_usd.save(obj, tmp_path), checks=["reach"])}
    assert res["reach"].ok, res["reach"].detail


def test_painted_joinery_weighs_as_softwood():
    """A painted frame is painted softwood (windows.SOFTWOOD), not the MDF the painted family weighs:
    the same frame in the wood family (650 kg/m^3) weighs 150 kg/m^3 more of its solid volume."""
    import infmob_usd

    links = {f: infmob_usd.generate("window", seed=7049, texture_size=16, frame_finish=f).link("frame")
             for f in ("painted", "wood")}
    volume = sum(pc.volume() for pc in links["painted"].pieces if pc.material == "frame")
    assert volume > 0.01
    assert links["wood"].mass - links["painted"].mass == pytest.approx((650.0 - windows.SOFTWOOD) * volume, rel=1e-6)


def test_tilt_and_turn_modes_exclude_each_other(tmp_path):
    """A tilt-and-turn handle selects one mode: the metadata names the two joints as excluding each other,
    the opened picture, the validators' all-open states and the clearance pass open the turn only, and the
    tilt is swept from the all-open state with the turn at rest (so neither is cut short by the other)."""
    import json

    import infmob_usd
    from infmob_usd.physical.clearance import _clearance
    from infmob_usd.validate import gallery, physics, posing

    obj = infmob_usd.generate("window", seed=1, texture_size=16, style="tilt_turn")
    folder = infmob_usd.save(obj, tmp_path)
    meta = {j["name"]: j for j in json.loads((folder / "metadata.json").read_text())["joints"]}
    turn, tilt = "joint_sash_0_0", "joint_sash_0_1"
    assert meta[turn]["excludes"] == [tilt] and meta[tilt]["excludes"] == [turn]
    assert all(not m.get("excludes") for m in meta.values() if m["kind"] != "flip_revolute")
    files = posing._read_object(folder)
    q = posing._qpos_for(files, posing.OPEN_FRACTION)
    sashes = sorted({m["group"] for m in meta.values() if m.get("excludes")})
    assert len(sashes) >= 1
    for s in sashes:
        modes = [q[f"joint_{s}_0"], q[f"joint_{s}_1"]]
        assert sum(v != 0.0 for v in modes) == 1 and modes[0] > 0, (s, modes)
    assert posing._qpos_for(files, {tilt: 1.0})[tilt] == pytest.approx(meta[tilt]["upper"])
    viewer = {j["name"]: j for j in gallery.object_data(folder, {})["joints"]}  # the gallery's Open all reads it
    assert viewer[turn]["excludes"] == [tilt] and viewer[tilt]["excludes"] == [turn]
    model = physics.load_model(folder)
    for state in physics.sampled_states(model)[1:3]:  # all@50 %, all@100 %
        assert all(state.q[f"joint_{s}_1"] == 0.0 for s in sashes), state.label
    c = _clearance(obj)
    assert c.open_state(c.by_joint[tilt])[tilt] > 0 and turn not in c.open_state(c.by_joint[tilt])
    assert c.open_state(c.by_joint["joint_sash_1_0"]).get("joint_sash_1_1", 0.0) == 0.0
    # the declared tilt (12 degrees) is kept whole: it is never swept with a turned sash beside it
    assert meta[tilt]["upper"] == pytest.approx(windows.TILT)


def test_only_a_compound_joint_has_exclusive_modes():
    from infmob_usd import joints as J
    from infmob_usd.errors import ModelError

    with pytest.raises(ModelError, match="one DoF"):
        J.JointSpec("revolute", "a", "b", (J.Dof("revolute", (0, 0, 0), (0, 0, 1), 0.0, 1.0),), exclusive=True)
    assert J.one_mode({"t": 1.0, "u": 0.5, "v": 0.2}, ["t", "u", "v"], {"t": ["u"], "u": ["t"]}) == \
        {"t": 1.0, "u": 0.0, "v": 0.2}
    assert J.one_mode({"t": 0.0, "u": 0.5}, ["t", "u"], {"t": ["u"], "u": ["t"]}) == {"t": 0.0, "u": 0.5}
