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
