"""Interaction annotations (annotations.json, metadata "interaction", grasp Xforms in the USD): every operated
joint has a grasp a Panda hand can take, on the part's surface, and a path that follows the joint."""

from __future__ import annotations

import functools
import json

import numpy as np
import pytest

from infmob_usd import api
from infmob_usd.annotations import AnnotationError, load
from infmob_usd.grasps import MAX_WIDTH
from infmob_usd.interaction import PALM, _carried, _mesh, operated

from helpers import surface_distance

SEEDS = (0, 1, 2)


@functools.lru_cache(maxsize=8)
def _made(category: str, seed: int):
    return api.generate(category, seed, texture_size=16)


@pytest.mark.parametrize("category", api.list_categories())
def test_every_operated_joint_has_a_panda_grasp_on_the_surface(category):
    """Seeds 0-2: every movable joint a person operates (not a wheel, caster swivel or coupled follower) is a
    target with a grasp of width <= 80 mm lying on its link's mesh (within 2 mm)."""
    for seed in SEEDS:
        obj = _made(category, seed)
        want = {j.name for j in obj.joints if operated(j, obj.joints)}
        targets = {t["joint"]: t for t in obj.interaction}
        assert set(targets) == want, f"{category} {seed}"
        for name, t in targets.items():
            assert any(g["width"] <= MAX_WIDTH for g in t["grasps"]), f"{category} {seed} {name}: no grasp"
            v, f, _, _ = _carried(obj, obj.link(t["link"]))
            for g in t["grasps"]:
                d = surface_distance(v, f, g["position"])
                assert d <= 0.002, f"{category} {seed} {name}: grasp {d * 1000:.1f} mm off the surface"
                assert abs(np.dot(g["approach"], g["closing"])) < 1e-6
                # a link named in the hand's way is really there: within the fingers' 6 cm of the grasp, or
                # the hand's body's farthest corner behind it
                reach = max(0.06, float(np.linalg.norm([PALM[3], PALM[0] / 2, PALM[1] / 2])) + 0.005)
                for name in g["blocked_by"]:
                    other = obj.link(name)
                    ov, of = _mesh(other.pieces)
                    near = surface_distance(ov + other.origin - obj.link(t["link"]).origin, of, g["position"])
                    assert near < reach, f"{category} {seed} {name} blocks {t['joint']} from {near:.3f} m"


def test_passive_joints_are_not_targets():
    obj = _made("office_chair", 0)
    targets = {t["joint"] for t in obj.interaction}
    wheels = [j for j in obj.joints if j.role == "wheel"]
    casters = [j for j in obj.joints if any(w.parent == j.child for w in wheels)]
    assert wheels and casters and not targets & {j.name for j in wheels + casters}


@pytest.mark.parametrize("design", ["pump_bottle", "sauce_pump"])
def test_a_plunger_is_pressed_down_its_stroke_like_a_button(design):
    """A pump head (role ``plunger``) is pushed down along its axis by the fingertips, as a button is: action
    ``press``, GAPartNet ``slider_button``, the hand's grasps approaching along the stroke; not a drawer pulled."""
    obj = api.generate("dispenser", 1, texture_size=16, design=design)
    pumps = [j for j in obj.joints if j.role == "plunger" and operated(j, obj.joints)]
    assert pumps, design
    targets = {t["joint"]: t for t in obj.interaction}
    for j in pumps:
        t = targets[j.name]
        assert t["action"] == "press" and t["part_class"] == "slider_button", (design, t["action"], t["part_class"])
        assert np.allclose(t["direction"], [0.0, 0.0, -1.0]), t["direction"]
        assert any(np.dot(g["approach"], t["direction"]) > 0.9 for g in t["grasps"]), "no grasp along the stroke"


def test_a_handle_part_brings_its_grasp():
    """A bar pull's grasp rides on its bar through placement: on the bar, across it, its diameter wide."""
    from infmob_usd.categories.parts import hardware
    from infmob_usd.frames import Frame

    at = Frame.at((0.3, 0.1, 0.5), z=(1, 0, 0), x=(0, 0, 1))  # on a +X face, bar vertical
    placed = hardware.bar_handle(0.16, "handle").attached("mount", to=at)
    grasps = [g for p in placed.pieces for g in p.grasps]
    assert len(grasps) == 1
    g = grasps[0]
    assert g.handle_class == "line_fixed_handle"
    np.testing.assert_allclose(g.approach, (-1, 0, 0), atol=1e-12)
    np.testing.assert_allclose(np.abs(g.closing), (0, 1, 0), atol=1e-12)
    assert g.width == pytest.approx(2 * hardware.BAR.bar_radius)
    bar = next(p for p in placed.pieces if p.grasps)
    assert surface_distance(bar.vertices, bar.faces, g.position) < 1e-3


def test_a_hold_whose_hand_meets_a_neighbour_is_named_and_a_free_one_offered():
    """The hand's body counts, not only its fingers: a fridge rack under another is not taken from above (the
    hand's body meets the rack over it) but by its front wire from the front, fingers closing vertically; and
    a screw cap whose own side pinch reaches onto the bottle's shoulder also offers a free hold (across it
    from above, for the lift and the turn alike)."""
    fridge = {t["joint"]: t for t in _made("beverage_fridge", 4).interaction}
    for name in ("joint_rack_0", "joint_rack_1"):
        g = fridge[name]["grasps"][0]
        assert g["approach"][0] < -0.9 and abs(g["closing"][2]) > 0.9, (name, g)
        assert set(g["blocked_by"]) <= {"door"}  # only the door, shut at rest, which the rack requires open
    caps = [t for t in _made("bottle", 4).interaction if t["link"] == "cap"]
    assert len(caps) == 2
    for t in caps:
        assert t["grasps"][0]["blocked_by"] == ["body"]  # the cap's declared edge pinch, listed first
        free = [g for g in t["grasps"] if not g["blocked_by"]]
        assert free and free[0]["approach"][2] < -0.9, t["joint"]


def test_annotations_are_deterministic():
    a = api.generate("kitchen_cabinet", 4, texture_size=16).interaction
    b = api.generate("kitchen_cabinet", 4, texture_size=16).interaction
    assert json.dumps(a) == json.dumps(b)
    assert json.dumps(a) != json.dumps(api.generate("kitchen_cabinet", 5, texture_size=16).interaction)


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    out = tmp_path_factory.mktemp("annot")
    return [api.save(_made(c, 0), out) for c in ("microwave", "dishwasher", "window")]


def test_path_follows_the_joint_in_the_written_urdf(written):
    """Each path point is the first grasp moved by the URDF's forward kinematics, the joint at its fraction."""
    from infmob_usd.validate.files import parse_urdf

    for folder in written:
        urdf = parse_urdf(folder / f"{folder.name}.urdf")
        for t in load(folder)["targets"]:
            p = np.append(t["grasps"][0]["position"], 1.0)
            for i, point in enumerate(t["path"]):
                q = t["rest"] + (t["open"] - t["rest"]) * i / 10
                pose = urdf.poses({t["joint"]: q})[t["link"]]
                np.testing.assert_allclose(point, (pose @ p)[:3], atol=1e-6)
            if t["joint_type"] != "continuous":
                joint = urdf.joints[t["joint"]]
                assert t["open"] in (pytest.approx(joint.upper), pytest.approx(joint.lower))


def test_files_agree(written):
    """annotations.json == metadata.json "interaction"; blocked_by names links; one USD grasp Xform per grasp,
    at its position."""
    from pxr import Usd

    from infmob_usd.validate.files import parse_urdf

    for folder in written:
        doc = load(folder)
        meta = json.loads((folder / "metadata.json").read_text())
        assert meta["interaction"] == doc["targets"] and meta["files"]["annotations"] == "./annotations.json"
        links = set(parse_urdf(folder / f"{folder.name}.urdf").links)
        assert {n for t in doc["targets"] for g in t["grasps"] for n in g["blocked_by"]} <= links
        stage = Usd.Stage.Open(str(folder / f"{folder.name}.usda"))
        root = stage.GetDefaultPrim().GetPath()
        for t in doc["targets"]:
            for i, g in enumerate(t["grasps"]):
                prim = stage.GetPrimAtPath(root.AppendChild(t["link"]).AppendChild(f"grasp_{t['joint']}_{i}"))
                assert prim.IsValid() and prim.GetTypeName() == "Xform"
                assert prim.GetAttribute("infmob:joint").Get() == t["joint"]
                assert prim.GetAttribute("infmob:width").Get() == pytest.approx(g["width"], rel=1e-6)
                np.testing.assert_allclose(prim.GetAttribute("xformOp:translate").Get(), g["position"], atol=1e-9)


def _broken(folder, tmp_path, edit):
    doc = json.loads((folder / "annotations.json").read_text())
    bad = tmp_path / "bad"
    bad.mkdir(exist_ok=True)
    text = edit(doc)
    (bad / "annotations.json").write_text(text if isinstance(text, str) else json.dumps(text))
    return bad


def _set(path, value):
    def edit(doc):
        node = doc
        for k in path[:-1]:
            node = node[k]
        node[path[-1]] = value
        return doc
    return edit


@pytest.mark.parametrize("edit, words", [
    (lambda d: "{not json", "not valid UTF-8 JSON"),
    (lambda d: json.dumps(d).replace('"width": 0', '"width": NaN', 1), "not a number"),
    (_set(["format"], "infmob-annotations/9"), "format"),
    (_set(["targets", 0, "grasps", 0, "approach"], [1, 1, 0]), "unit vector"),
    (_set(["targets", 0, "grasps", 0, "width"], "wide"), "width"),
    (_set(["targets", 0, "grasps", 0, "blocked_by"], [3]), "blocked_by"),
    (_set(["targets", 0, "part_class"], "teapot"), "part_class"),
    (_set(["targets", 0, "path"], [[0, 0, 0]]), "path"),
    (lambda d: {**d, "targets": d["targets"][:1] * 2}, "annotated twice"),
    (_set(["targets"], {}), "targets"),
])
def test_load_rejects_hostile_files_in_one_line(written, tmp_path, edit, words):
    bad = _broken(written[0], tmp_path, edit)
    with pytest.raises(AnnotationError) as e:
        load(bad)
    msg = str(e.value)
    assert words in msg and "\n" not in msg and "annotations.json" in msg


def test_load_refuses_missing_files_and_links(written, tmp_path):
    with pytest.raises(AnnotationError, match="missing"):
        load(tmp_path)
    (tmp_path / "annotations.json").symlink_to(written[0] / "annotations.json")
    with pytest.raises(AnnotationError, match="symbolic link"):
        load(tmp_path)
    with pytest.raises(AnnotationError, match="folder path"):
        load(42)
