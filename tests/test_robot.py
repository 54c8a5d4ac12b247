"""The robot check (``infmob validate --robot``): a floating Panda gripper in SAPIEN opens annotated joints.

Real simulator on the CPU; the annotations are the ones the build writes (annotations.json)."""

from __future__ import annotations

import json
import math
import shutil
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("sapien")
pytest.importorskip("mani_skill")

import infmob_usd  # noqa: E402
from infmob_usd.cli import main  # noqa: E402
from infmob_usd.validate import robot  # noqa: E402

pytestmark = pytest.mark.sim


@pytest.fixture(scope="module")
def cabinet(tmp_path_factory) -> Path:
    """A kitchen cabinet (seed 1: bar handles) annotated for one drawer and one door."""
    folder = Path(infmob_usd.save(infmob_usd.generate("kitchen_cabinet", 1, texture_size=16),
                                  tmp_path_factory.mktemp("robot")))
    targets = json.loads((folder / "annotations.json").read_text())["targets"]
    keep = [next(t for t in targets if t["part_class"] == c) for c in ("slider_drawer", "hinge_door")]
    _write(folder, keep)
    return folder


def _write(folder: Path, targets: list[dict]) -> None:
    doc = json.loads((folder / "annotations.json").read_text())
    doc["targets"] = targets
    (folder / "annotations.json").write_text(json.dumps(doc))


def _copy(folder: Path, tmp_path: Path, edit) -> Path:
    out = tmp_path / folder.name
    shutil.copytree(folder, out)
    targets = json.loads((out / "annotations.json").read_text())["targets"]
    _write(out, edit(targets))
    return out


def test_the_gripper_opens_a_drawer_and_a_door(cabinet):
    results = robot.check_robot(cabinet)
    assert [r.name for r in results] == ["robot", "robot"]
    assert all(r.ok for r in results), [r.detail for r in results]
    assert "(slider_drawer): opened" in results[0].detail and "(hinge_door): opened" in results[1].detail


def test_the_gripper_presses_a_button_and_turns_a_dial(tmp_path):
    folder = Path(infmob_usd.save(infmob_usd.generate("toaster", 0, texture_size=16), tmp_path))
    targets = json.loads((folder / "annotations.json").read_text())["targets"]
    keep = [next(t for t in targets if t["action"] == a and t["joint"].startswith(j))
            for a, j in (("press", "joint_button"), ("turn", "joint_dial"))]
    _write(folder, keep)
    results = robot.check_robot(folder)
    assert all(r.ok for r in results), [r.detail for r in results]
    assert "(slider_button): opened" in results[0].detail and "(hinge_knob): opened" in results[1].detail
    # the fingers pressed on the body beside the button: the button stays out, and the report says why
    g = keep[0]["grasps"][0]
    g["position"] = (np.asarray(g["position"]) + 0.05 * np.asarray(g["closing"])).tolist()
    _write(folder, keep[:1])
    [r] = robot.check_robot(folder)
    assert not r.ok and "blocked by" in r.detail, r.detail


def test_a_grasp_beside_the_handle_misses(cabinet, tmp_path):
    def beside(targets):
        t = targets[0]
        g = t["grasps"][0]
        g["position"] = (np.asarray(g["position"]) + 0.3 * np.asarray(g["closing"])).tolist()
        return [t]

    [r] = robot.check_robot(_copy(cabinet, tmp_path, beside))
    assert not r.ok and "missed handle" in r.detail, r.detail


def test_a_path_into_the_cabinet_fails_at_the_joint_limit(cabinet, tmp_path):
    def inwards(targets):
        t = targets[0]
        p = np.asarray(t["path"])
        t["path"] = (2 * p[0] - p).tolist()  # the drawer's path mirrored: pushing it in
        return [t]

    [r] = robot.check_robot(_copy(cabinet, tmp_path, inwards))
    assert not r.ok and "joint limit" in r.detail, r.detail


def test_cli_prints_the_robot_table(cabinet, capsys):
    assert main(["validate", "--robot", "--no-mass", "--workers", "1", str(cabinet)]) == 0
    out = capsys.readouterr().out
    assert "robot: joints opened" in out
    row = next(line for line in out.splitlines() if line.startswith("all joints"))
    assert row.split()[2:] == ["2/2", "2/2"], row


def test_no_annotations_is_a_skip_and_a_wrong_format_an_error(tmp_path):
    assert [(r.ok, r.detail) for r in robot.check_robot(tmp_path)] == [
        (True, "skipped: no annotations.json in this folder")]
    (tmp_path / "annotations.json").write_text(json.dumps({"format": "other/2", "targets": []}))
    with pytest.raises(robot.AnnotationError, match="infmob-annotations/1"):
        robot.read_annotations(tmp_path)


def test_hand_frame_and_euler_round_trip():
    r = robot.hand_rotation([-1, 0, 0], [0, 1, 0])
    assert np.allclose(r[:, 2], [-1, 0, 0]) and np.allclose(r[:, 1], [0, 1, 0])
    assert np.allclose(np.linalg.det(r), 1.0)
    a, b, c = 0.3, -0.7, 2.0
    rx = np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]])
    ry = np.array([[math.cos(b), 0, math.sin(b)], [0, 1, 0], [-math.sin(b), 0, math.cos(b)]])
    rz = np.array([[math.cos(c), -math.sin(c), 0], [math.sin(c), math.cos(c), 0], [0, 0, 1]])
    assert np.allclose(robot.euler_xyz(rx @ ry @ rz), [a, b, c])
    turn = robot.rotation_between([1, 0, 0], [0, 1, 0])
    assert np.allclose(turn @ [1, 0, 0], [0, 1, 0]) and np.allclose(turn @ [0, 0, 1], [0, 0, 1])


def test_a_key_over_a_stand_is_pressed_with_the_hand_turned_flat(tmp_path):
    """A TV's key in its bezel's bottom band, 7 cm over the stand's foot: the annotated way in (the fingers'
    closing axis vertical) puts the hand's 0.2 m body into the foot; turned a quarter about the approach,
    the shut fingers press the key."""
    folder = Path(infmob_usd.save(infmob_usd.generate("tv", 4, texture_size=16), tmp_path))
    targets = json.loads((folder / "annotations.json").read_text())["targets"]
    key = next(t for t in targets if t["action"] == "press")
    _write(folder, [key])
    [r] = robot.check_robot(folder)
    assert r.ok and "(slider_button): opened" in r.detail, r.detail
    assert len(robot.grasp_candidates(key)) > 2 * len(key["grasps"])  # turned and tilted ways in


def test_an_oven_knob_under_the_grate_is_turned_with_the_wrist_wound_back(tmp_path):
    """An oven's knobs on its backguard, 0.1 m over the hob's grate: turned a quarter in one hold from the
    annotated grip (the hand's 0.2 m across the fingers level), the hand's body swings down into the grate.
    Held wound back by half the turn (and let go and taken again past :data:`robot.REGRIP`), it opens."""
    folder = Path(infmob_usd.save(infmob_usd.generate("oven", 3, texture_size=16), tmp_path))
    targets = json.loads((folder / "annotations.json").read_text())["targets"]
    knob = next(t for t in targets if t["joint"] == "joint_knob_0")
    _write(folder, [knob])
    [r] = robot.check_robot(folder)
    assert r.ok and "(hinge_knob): opened" in r.detail, r.detail
    back = robot.wound_back(knob, knob["grasps"][0])
    assert back is not None and back in robot.grasp_candidates(knob)
    angle = math.acos(float(np.dot(back["closing"], knob["grasps"][0]["closing"])))
    assert math.isclose(angle, min(knob["open"], robot.REGRIP) / 2, abs_tol=1e-6)
    # turned away from the way the knob turns: the hand then sweeps either side of the annotated grip
    assert float(np.dot(back["closing"], knob["direction"])) < 0


def test_a_long_turn_is_made_in_holds_of_at_most_regrip(tmp_path, monkeypatch):
    """A rotary dimmer between two others turns 300 degrees; in one hold the fingers slip off it. Taken
    again and turned in holds of at most :data:`robot.REGRIP` (let go, turned back, taken again), it opens."""
    folder = Path(infmob_usd.save(infmob_usd.generate("switch", 3, texture_size=16), tmp_path))
    targets = json.loads((folder / "annotations.json").read_text())["targets"]
    dial = next(t for t in targets if t["joint"] == "joint_dimmer_0_1")
    assert dial["open"] > 3 * robot.REGRIP
    _write(folder, [dial])
    regrips = []
    real = robot.TurnMotion.regrip

    def counted(self, run):
        regrips.append(self.angle)
        return real(self, run)

    monkeypatch.setattr(robot.TurnMotion, "regrip", counted)
    [r] = robot.check_robot(folder)
    assert r.ok, r.detail
    assert len(regrips) >= 3 and all(a < robot.REGRIP + robot.TURN_LEAD for a in regrips), regrips


def test_a_pot_lid_is_lifted_by_its_loop(tmp_path):
    """A pot lid with a loop handle sits on the rim with its edge over the pot's wall (the fingers cannot get
    under it): the loop declares its grasp (from above, across the bar), which comes first and lifts it."""
    folder = Path(infmob_usd.save(infmob_usd.generate("pot", 3, texture_size=16), tmp_path))
    targets = json.loads((folder / "annotations.json").read_text())["targets"]
    lid = next(t for t in targets if t["joint"] == "joint_lid_0")
    assert lid["handle_class"] == "line_fixed_handle" and lid["grasps"][0]["approach"] == [0.0, 0.0, -1.0]
    _write(folder, [lid])
    [r] = robot.check_robot(folder)
    assert r.ok and "(slider_lid): opened" in r.detail, r.detail


def test_progress_is_the_grasp_points_place_on_the_path_riding_on_the_parent():
    """The hand goes up to ``INSET`` past the annotated grasp point: its place on the path is read with that
    offset taken off (else a drawer pulled 0.1 m reads 0.09 m and the target runs ahead of the part). The
    path rides on the operated joint's parent: moved 0.2 m (a rack pulled out, a tote slid on its shelf), the
    hand's target moves with it and its progress is read there."""
    grasp = np.eye(4)
    grasp[:3, 3] = [-0.01, 0.0, 0.0]  # 10 mm inset along a -x approach into a drawer front pulled along +x
    parent = np.eye(4)
    motion = robot.PathMotion(robot.Path3([[0, 0, 0], [0.3, 0, 0]]), grasp, lambda: parent)
    moved = grasp.copy()
    moved[0, 3] += 0.1
    assert motion.progress(grasp) == pytest.approx(0.0) and motion.progress(moved) == pytest.approx(0.1)
    parent[1, 3] = 0.2  # the parent gives way sideways under the pull
    moved[1, 3] += 0.2
    assert motion.progress(moved) == pytest.approx(0.1)
    assert np.allclose(motion.pose(0.1, 0.15)[:3, 3], [0.14, 0.2, 0.0])


def test_a_tote_lid_is_lifted_through_its_arc(tmp_path):
    """A tote's lid on the top level of a storage rack, lifted by its front tab (the hand 10 mm in past the
    tab's edge) through 109 degrees: the hand's place on the arc read without that inset ran the target
    ahead, the hand dragged the tote 13 cm off its shelf and lost the tab at half the range."""
    folder = Path(infmob_usd.save(infmob_usd.generate("storage_rack", 5, texture_size=16), tmp_path))
    targets = json.loads((folder / "annotations.json").read_text())["targets"]
    _write(folder, [next(t for t in targets if t["joint"] == "joint_level_0_3_tote_0_lid")])
    [r] = robot.check_robot(folder)
    assert r.ok and "(hinge_lid): opened" in r.detail, r.detail


def test_a_front_loaders_door_and_detergent_drawer_are_pulled_by_their_grips(tmp_path):
    """A front loader's porthole door and detergent drawer sit flush in the front: pinched across their edges
    the back finger meets the cabinet. Each has a grip (a bar on the door's free edge, a lip along the
    drawer front's bottom) that declares its hold; taken by it, both open."""
    folder = Path(infmob_usd.save(infmob_usd.generate("washing_machine", 5, texture_size=16), tmp_path))
    targets = json.loads((folder / "annotations.json").read_text())["targets"]
    keep = [next(t for t in targets if t["joint"] == j) for j in ("joint_door", "joint_drawer")]
    assert all(t["handle_class"] == "line_fixed_handle" and t["grasp_source"] == "part" for t in keep)
    _write(folder, keep)
    results = robot.check_robot(folder)
    assert all(r.ok for r in results), [r.detail for r in results]


def test_progress_on_an_arc_takes_off_the_inset_turned_with_the_part():
    """A knob held 10 mm in from its rim on an 18 mm arc: the hand is sent to the path's point with the inset
    turned as far as the part has come, and its place is read back the same way (the inset taken off
    unturned, a quarter turn read 2-3 mm off: the target ran ahead of the knob or lagged it)."""
    r, inset = 0.018, 0.01
    angles = np.linspace(0, math.pi / 2, 11)
    arc = robot.Path3([[r * math.cos(a), r * math.sin(a), 0.0] for a in angles])
    grasp = np.eye(4)
    grasp[:3, 3] = [r - inset, 0.0, 0.0]
    motion = robot.PathMotion(arc, grasp)
    for s in np.linspace(0, arc.length, 21)[1:]:
        assert motion.progress(motion.pose(s, s)) == pytest.approx(s, abs=2e-4), s


def test_an_office_chairs_arm_is_taken_where_its_own_pad_leaves_the_fingers_room(tmp_path):
    """An office chair's flip-up arm (seed 5), pinched at its pad's front: the grasp search let the fingers
    overlap the arm's own pad in front of the pinched stretch (only the hand's body was checked against the
    part itself), the fingers pushed the pad on the way in, the seat swivelled away and they closed on
    nothing. With the fingers kept clear of the part's own mesh the hold is taken and the arm flips up."""
    folder = Path(infmob_usd.save(infmob_usd.generate("office_chair", 5, texture_size=16), tmp_path))
    targets = json.loads((folder / "annotations.json").read_text())["targets"]
    arm = next(t for t in targets if t["joint"] == "joint_arm_left")
    assert arm["grasps"][0]["blocked_by"] == [], arm["grasps"]
    _write(folder, [arm])
    [r] = robot.check_robot(folder)
    assert r.ok and "(hinge_lid): opened" in r.detail, r.detail


def test_a_toasters_crumb_tray_is_pulled_by_its_tab(tmp_path):
    """A toaster's crumb tray sits flush in the casing's front with 2 mm round it: pinched across its front
    plate's edge, the lower finger met the casing (seed 5: "approach blocked by body"). Its front carries a
    pull tab that declares its hold; taken by it, the tray slides out."""
    folder = Path(infmob_usd.save(infmob_usd.generate("toaster", 5, texture_size=16), tmp_path))
    targets = json.loads((folder / "annotations.json").read_text())["targets"]
    tray = next(t for t in targets if t["joint"] == "joint_tray")
    assert tray["handle_class"] == "line_fixed_handle" and tray["grasp_source"] == "part", tray
    assert tray["grasps"][0]["blocked_by"] == []
    _write(folder, [tray])
    [r] = robot.check_robot(folder)
    assert r.ok and "(slider_drawer): opened" in r.detail, r.detail
