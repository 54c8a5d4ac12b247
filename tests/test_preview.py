"""Pictures of generated objects (validate/preview.py): real renders, rest vs opened, sheets, files.

The rendering tests need SAPIEN's renderer on a Vulkan device (headless CPU: Mesa lavapipe >= 25,
see ``preview.INSTALL_HINT``); without one they are skipped with the reason. The joint-pose
tests run everywhere.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import math
import subprocess
import sys

import numpy as np
import pytest

import infmob_usd
from infmob_usd.validate import posing, preview, render_backend, studio

cv2 = pytest.importorskip("cv2")

SIZE = 256


@pytest.fixture(scope="module")
def cabinets(tmp_path_factory):
    """Three kitchen cabinets (seeds 0..2), small textures to keep the test quick."""
    out = tmp_path_factory.mktemp("preview_objects")
    return [infmob_usd.save(infmob_usd.generate("kitchen_cabinet", seed=s, texture_size=128), out) for s in range(3)]


@pytest.fixture(scope="module")
def cabinet(cabinets):
    return cabinets[0]


@pytest.fixture(scope="module")
def renderer():
    """Skip (with what to install) where SAPIEN cannot render here."""
    pytest.importorskip("sapien", reason="the preview renderer needs sapien (pip install sapien==3.0.3)")
    try:
        studio._stage()
    except preview.PreviewUnavailable as exc:
        pytest.skip(f"no renderer for previews: {exc}")
    return preview


# --- joint poses: no renderer needed -----------------------------------------------------------


def test_rest_pose_puts_links_where_metadata_says(cabinet):
    files = posing._read_object(cabinet)
    meta = json.loads((cabinet / "metadata.json").read_text())
    poses = posing._forward_kinematics(files, posing._qpos_for(files, 0.0))
    for link in meta["links"]:
        pose = poses[link["name"]]
        np.testing.assert_allclose(pose[:3, 3], link["origin"], atol=1e-5, err_msg=link["name"])
        np.testing.assert_allclose(pose[:3, :3], np.eye(3), atol=1e-6, err_msg=link["name"])  # world-aligned


def test_joint_fraction_moves_each_joint_along_its_axis(cabinet):
    files = posing._read_object(cabinet)
    meta = {j["name"]: j for j in json.loads((cabinet / "metadata.json").read_text())["joints"]}
    assert files.movable, "a kitchen cabinet has doors or drawers"
    rest = posing._forward_kinematics(files, posing._qpos_for(files, 0.0))
    q = posing._qpos_for(files, posing.OPEN_FRACTION)
    opened = posing._forward_kinematics(files, q)
    for j in files.movable:
        m = meta[j.name]
        if j.type == "continuous":
            assert q[j.name] == pytest.approx(math.pi / 2)
            continue
        gate = any(j.name in gates for gates in posing._gates(files).values())  # a door held fully open
        if m["lower"] == 0:
            assert q[j.name] == pytest.approx((1.0 if gate else 0.7) * m["upper"])
        # 1e-6: a door held fully open for the racks behind it sits at its upper limit as written (9 digits)
        assert m["lower"] - 1e-6 <= q[j.name] <= m["upper"] + 1e-6
        if j.type == "prismatic":
            shift = opened[j.child][:3, 3] - rest[j.child][:3, 3]
            np.testing.assert_allclose(shift, np.asarray(m["axis"]) * q[j.name], atol=1e-6)
        else:  # revolute: the pivot stays put, the link turns about the world axis by q
            rot = opened[j.child][:3, :3] @ rest[j.child][:3, :3].T
            axis = np.asarray(m["axis"], float)
            angle = math.acos(np.clip((np.trace(rot) - 1) / 2, -1, 1))
            assert angle == pytest.approx(abs(q[j.name]), abs=1e-6)
            np.testing.assert_allclose(rot @ axis, axis, atol=1e-6)


def test_pictures_open_a_door_before_its_racks(tmp_path):
    """The opened picture and the sweep hold a door fully open while a rack behind it (``requires_open``)
    is out, and a rack fully out while what rides on it moves, as a robot and ``validate --sim`` open them;
    racks never pass through a half-open door."""
    folder = infmob_usd.save(infmob_usd.generate("dishwasher", seed=3, texture_size=16, rack_count=2,
                                                     design="freestanding"),
                             tmp_path)
    files = posing._read_object(folder)
    gates = posing._gates(files)
    meta = {j["name"]: j for j in json.loads((folder / "metadata.json").read_text())["joints"]}
    racks = [n for n in gates if meta[n]["requires_open"] == "door"]
    assert len(racks) == 2 and all(gates[n] == ["joint_door"] for n in racks)
    door = meta["joint_door"]
    q = posing._qpos_for(files, posing.OPEN_FRACTION)
    assert q["joint_door"] == pytest.approx(door["upper"])
    # a rack is itself the gate of the tines, shelves and baskets riding on it: held fully out, as the door is
    riders = [n for n in gates if meta[n]["requires_open"] not in (None, "door")]
    assert riders and all(gates[n][-1] == "joint_door" and gates[n][0] in racks for n in riders)
    assert all(q[n] == pytest.approx(meta[n]["upper"]) for n in racks)
    assert all(q[n] == pytest.approx(0.7 * meta[n]["upper"]) for n in riders)
    assert posing._qpos_for(files, {"joint_door": 0.5})["joint_door"] == pytest.approx(0.5 * door["upper"])
    assert posing._qpos_for(files, {racks[0]: 0.3})["joint_door"] == pytest.approx(door["upper"])
    for name, qs in preview._sweep_plan(files):
        if name in racks and qs[name] != 0.0:
            assert qs["joint_door"] == pytest.approx(door["upper"]), name
        elif name == "joint_door":
            assert all(qs[n] == 0.0 for n in racks)


def test_render_backend_loads_by_path():
    """``backend_status`` probes in a child process that loads the backend module by its file path
    (a broken Vulkan driver can crash a process): that module must import without its package."""
    spec = importlib.util.spec_from_file_location("_infmob_probe_test", render_backend.__file__)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    assert callable(module._selftest) and "mesa-vulkan-drivers" in module.INSTALL_HINT


def test_backend_status_agrees_with_this_process(monkeypatch, renderer):
    """Where this process renders, the child-process probe says so too (the gallery asks it before
    rendering thumbnails)."""
    monkeypatch.setattr(render_backend, "_STATE", {k: v for k, v in render_backend._STATE.items() if k != "status"})
    ok, why = preview.backend_status()
    assert ok, why


def test_missing_renderer_names_what_to_install(monkeypatch, cabinet):
    monkeypatch.setattr(render_backend, "_STATE", {})
    monkeypatch.setitem(sys.modules, "sapien", None)  # import sapien -> ImportError
    with pytest.raises(preview.PreviewUnavailable) as err:
        preview.render_object(cabinet, size=64)
    assert "mesa-vulkan-drivers" in str(err.value) and "sapien" in str(err.value)


# --- real pictures -------------------------------------------------------------------------------


def _non_background(img: np.ndarray, tol: int = 10) -> np.ndarray:
    return (np.abs(img.astype(int) - studio.BACKGROUND) > tol).any(-1)


def test_render_object_is_a_real_picture(renderer, cabinet):
    img = renderer.render_object(cabinet, size=SIZE)
    assert img.shape == (SIZE, SIZE, 3) and img.dtype == np.uint8
    share = _non_background(img).mean()  # object plus its shadow
    assert 0.10 <= share <= 0.85, share
    with renderer.ObjectRenderer(cabinet) as r:
        frame = r.render(SIZE, supersample=1)
    obj = frame.object_mask
    assert 0.10 <= obj.mean() <= 0.80, obj.mean()
    pixels = frame.rgb[obj].astype(float)
    assert pixels.std(axis=0).mean() > 12, "object pixels are flat: no shading or textures"
    # textures: fine detail inside the object, not just a few flat shaded faces
    gray = cv2.cvtColor(frame.rgb, cv2.COLOR_RGB2GRAY).astype(np.float32)
    lap = np.abs(cv2.Laplacian(gray, cv2.CV_32F))
    inner = cv2.erode(obj.astype(np.uint8), np.ones((5, 5), np.uint8)).astype(bool)
    assert float(np.mean(lap[inner] > 4)) > 0.05, "no texture detail on the object"
    # a shadow or contact darkening on the ground
    assert (frame.shadow[~obj] < 0.8).mean() > 0.01


def test_opened_picture_differs_where_the_doors_and_drawers_are(renderer, cabinet):
    with renderer.ObjectRenderer(cabinet) as r:
        rest_q = posing._qpos_for(r.files, 0.0)
        open_q = posing._qpos_for(r.files, posing.OPEN_FRACTION)
        cam = r.camera_for(rest_q, open_q)
        r.set_qpos(rest_q)
        a = r.render(SIZE, cam)
        r.set_qpos(open_q)
        b = r.render(SIZE, cam)
        moving = {j.child for j in r.files.movable}
    region = np.zeros(a.labels.shape, bool)
    for name in moving:
        region |= a.link_mask(name) | b.link_mask(name)
    assert region.mean() > 0.02, "doors and drawers cover almost nothing"
    diff = np.abs(a.rgb.astype(int) - b.rgb.astype(int)).sum(-1)
    inside, outside = diff[region], diff[~region]
    assert (inside > 30).mean() > 0.3, (inside > 30).mean()
    assert inside.mean() > 3 * max(outside.mean(), 1.0), (inside.mean(), outside.mean())
    # the rest of the cabinet stays where it was
    still = a.object_mask & b.object_mask & ~region
    assert np.array_equal(a.labels[still], b.labels[still])


def test_render_object_joint_fraction_changes_the_picture(renderer, cabinet):
    a = renderer.render_object(cabinet, size=128, joint_fraction=0.0)
    b = renderer.render_object(cabinet, size=128, joint_fraction=1.0)
    assert np.abs(a.astype(int) - b.astype(int)).mean() > 5


def test_contact_sheet_grid(renderer, cabinets, tmp_path):
    out = renderer.contact_sheet(cabinets, tmp_path / "sheet.png", cell=128)
    sheet = cv2.imread(str(out))
    assert sheet.shape == (2 * 128, 2 * 128, 3)  # 3 objects -> 2 columns x 2 rows
    band = preview._caption_height(128)
    for i in range(3):
        y, x = divmod(i, 2)
        cell = sheet[y * 128:(y + 1) * 128, x * 128:(x + 1) * 128]
        caption = cell[-band:]
        assert (caption < 120).any(), f"cell {i} has no caption text"
        assert _non_background(cell[:-band, :, ::-1]).mean() > 0.05, f"cell {i} is empty"
    assert (sheet[128:, 128:] == 255).all(), "the unused cell stays blank"


def test_contact_sheet_rest_and_open_rows(renderer, cabinets, tmp_path):
    """``--open F``: each row of objects at rest is followed by the same objects opened."""
    ap = argparse.ArgumentParser()
    preview.add_arguments(ap)
    root = cabinets[0].parent
    out = tmp_path / "ro.png"
    assert preview.main(ap.parse_args(["--sheet", str(root), "--out", str(out), "--size", "96", "--open", "1"])) == 0
    sheet = cv2.imread(str(out))
    assert sheet.shape == (4 * 96, 2 * 96, 3)  # 3 objects: 2 columns, 2 rows of objects, each rest + open
    band = preview._caption_height(96)
    rest, opened = sheet[:96 - band, :96], sheet[96:2 * 96 - band, :96]
    assert np.abs(rest.astype(int) - opened.astype(int)).mean() > 3, "the open row shows the rest pose"
    assert preview.main(ap.parse_args(["--sheet", str(root), "--out", str(out), "--open", "1.5"])) == 2
    assert preview.main(ap.parse_args([str(cabinets[0]), "--open", "0.5"])) == 2


def test_preview_writes_png_and_sweep(renderer, cabinet, tmp_path):
    from PIL import Image

    written = renderer.preview(cabinet, tmp_path / "pv", size=128)
    assert set(written) == {"preview", "sweep"}
    png = cv2.imread(str(written["preview"]))
    band = preview._caption_height(128)
    assert png.shape[0] == 128 + band and png.shape[1] >= 2 * 128
    left, right = png[:128, :128], png[:128, -128:]
    assert np.abs(left.astype(int) - right.astype(int)).mean() > 3, "opened panel looks like the rest panel"
    gif = Image.open(written["sweep"])
    plan = preview._sweep_plan(posing._read_object(cabinet))
    assert gif.n_frames == len(plan) <= preview.SWEEP_MAX_FRAMES
    assert [q for _, q in plan][0] != [q for _, q in plan][-1]
    assert gif.size == (preview.SWEEP_SIZE, preview.SWEEP_SIZE + preview._caption_height(preview.SWEEP_SIZE))


def test_command_line(renderer, cabinets, tmp_path):
    ap = argparse.ArgumentParser()
    preview.add_arguments(ap)
    root = cabinets[0].parent
    assert preview.main(ap.parse_args(["--sheet", str(root), "--out", str(tmp_path / "s.png"), "--size", "96"])) == 0
    assert cv2.imread(str(tmp_path / "s.png")).shape == (2 * 96, 2 * 96, 3)
    assert preview.main(ap.parse_args([str(cabinets[1]), "--out", str(tmp_path / "p"), "--size", "96"])) == 0
    assert (tmp_path / "p" / cabinets[1].name / "preview.png").is_file()
    assert (tmp_path / "p" / cabinets[1].name / "sweep.gif").is_file()
    assert preview.main(ap.parse_args([])) == 2


def test_glass_is_drawn_see_through_and_the_tint_applied(renderer, tmp_path):
    """The preview shows what the MTL asks: ``d`` < 1 is see-through (blended in the transparency
    pass), ``Kd`` multiplies ``map_Kd`` (the object's tint of its look)."""
    import sapien

    obj = infmob_usd.generate("window", seed=1, texture_size=16)
    folder = infmob_usd.save(obj, tmp_path)
    seen = {}
    with renderer.ObjectRenderer(folder) as r:
        for ent in r._entities.values():
            for shape in ent.find_component_by_type(sapien.render.RenderBodyComponent).render_shapes:
                slot = shape.filename.rsplit("__", 1)[1][: -len(".obj")]
                seen[slot] = shape.parts[0].material
        picture = r.render(SIZE, supersample=1)
    assert picture.object_mask.any()
    glass = seen["glass"]
    d = obj.materials["glass"].opacity
    assert glass.base_color[3] == pytest.approx(d, abs=1e-3)
    texels = glass.base_color_texture.download()
    assert texels.shape[-1] == 4 and np.allclose(texels[..., 3], round(d * 255), atol=1)
    frame = seen["frame"]  # opaque, its map tinted by the wear: a new texture, alpha 1
    assert frame.base_color[3] == 1.0
    tint = np.asarray(obj.materials["frame"].wear.tint)
    if np.abs(tint - 1).max() > 1e-3:
        assert frame.base_color_texture.filename == ""  # made from the tinted map, not the file


def test_preview_and_writer_agree_on_the_simready_thumbnail(tmp_path):
    from infmob_usd.layers.thumbnail import SIZE, thumbnail_path
    from infmob_usd.validate.preview import THUMB_SIZE, simready_thumbnail

    assert THUMB_SIZE == SIZE and simready_thumbnail(tmp_path, "x") == thumbnail_path(tmp_path, "x")


def test_cli_preview_of_a_folder_of_scenes_pictures_each_scene_not_its_objects(tmp_path, renderer):
    """``infmob preview DIR`` finds the scene under DIR and writes its rest and all-open pictures; the
    scene's own object folders are part of the scene, not previews of their own."""
    from infmob_usd.scenes import save_scene, scene

    folder = save_scene(scene("bathroom", 2, texture_size=16), tmp_path / "scenes")
    out = tmp_path / "previews"
    done = subprocess.run([sys.executable, "-m", "infmob_usd", "preview", str(tmp_path / "scenes"), "--size", "256",
                           "--out", str(out)], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    assert sorted(p.relative_to(out).as_posix() for p in out.rglob("*.png")) == [
        f"{folder.name}/preview.png", f"{folder.name}/preview_open.png"]
    rest, opened = (cv2.imread(str(out / folder.name / n)) for n in ("preview.png", "preview_open.png"))
    assert rest.shape == (192, 256, 3) and rest.std() > 10  # a picture, not a blank
    assert np.abs(rest.astype(int) - opened).mean() > 0.5  # doors and drawers open between the two


def test_contact_shadow_follows_a_cable_not_the_hull_of_its_ends():
    """A mouse and its plug joined by a thin cable on the ground: the ground between them, off the cable, is
    not darkened as if under the object (the convex hull of the three read as one grey wedge)."""

    def slab(x0, y0, x1, y1):
        pts = np.array([(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (0.0, 0.002)])
        faces = np.array([(0, 2, 6), (0, 6, 4)])  # the bottom (z = 0) as two triangles
        return pts, faces

    parts = [slab(0.0, -0.03, 0.1, 0.03), slab(0.1, 0.0, 0.2, 0.002), slab(0.2, -0.01, 0.24, 0.01)]
    mouse, cable, plug = parts
    pts = np.vstack([mouse[0], cable[0], plug[0]])
    tris = np.vstack([mouse[1], cable[1] + 8, plug[1] + 16])
    shade = studio._ContactShade(pts, 0.0, tris)
    under, beside_cable, off = shade(np.array([[0.05, 0.0], [0.15, 0.001], [0.15, -0.015]]))  # off: in the hull
    assert under < 0.7 and beside_cable < 0.7
    assert off > 0.8  # 1.5 cm off the cable: its own soft edge only (inside the hull: 0.58)


def test_the_studio_has_no_hard_edges_for_chrome_to_alias_on(tmp_path):
    """A mirror-like thin tube sweeps the whole environment across a few pixels: every hard edge in the map
    (a black card's, the horizon's) draws a painted-on stripe. The cube faces change by a few levels from one
    texel to the next (the cards' soft middle, the cone prefilter), and the cards still darken the studio
    (metal keeps its light and dark bands)."""
    pytest.importorskip("cv2")
    import cv2

    faces = [cv2.imread(p).astype(int) for p in studio._environment_map(tmp_path)]
    steps = max(max(np.abs(np.diff(f, axis=a)).max() for a in (0, 1)) for f in faces)
    assert steps <= 20
    side = np.concatenate([f[:, :, 1].ravel() for f in faces[:2] + faces[4:]])  # the four side faces (green)
    assert side.max() - side.min() > 60
