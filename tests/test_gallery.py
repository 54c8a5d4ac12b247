"""`infmob gallery`: the files it writes, its errors, and the page in a real headless Chromium.

The browser tests drive Debian's system Chromium (`.ci/sysdeps.sh` installs it) through Playwright
(`pip install -e .[dev]`), WebGL on the CPU (SwiftShader). They open the site from file:// and over
`--serve`, count cards, move a door's slider and compare the canvas pixels where the door is.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys

import pytest

import infmob_usd
from infmob_usd.cli import main as cli_main
from infmob_usd.validate.gallery import build_gallery, find_object_folders, object_data

OBJECTS = [("beverage_fridge", 0), ("kitchen_cabinet", 1), ("lamp", 0)]  # a door + racks behind it; a chain


@pytest.fixture(scope="module")
def dataset(tmp_path_factory):
    root = tmp_path_factory.mktemp("gallery_ds")
    for cat, seed in OBJECTS:
        infmob_usd.save(infmob_usd.generate(cat, seed=seed, texture_size=16), root / cat)
    # a symlinked copy counts as an object of its own but shares the data file
    os.symlink(root / "lamp" / "lamp_000000", root / "lamp_copy")
    return root


@pytest.fixture(scope="module")
def site(dataset):
    return build_gallery(dataset, render=False, log=lambda *a, **k: None)


def _index(site) -> dict:
    text = (site["site"] / "data" / "index.js").read_text()
    return json.loads(re.match(r"INFMOB_GALLERY\.index\((.*)\);\s*$", text, re.S).group(1))


def test_site_files_and_cards(dataset, site):
    assert site["objects"] == 4 and site["distinct"] == 3 and not site["errors"]
    idx = _index(site)
    rows = {r["name"]: r for r in idx["objects"]}
    fridge = rows["beverage_fridge_000000"]
    meta = json.loads((dataset / "beverage_fridge" / "beverage_fridge_000000" / "metadata.json").read_text())
    assert fridge["joints"] == sum(meta["joint_kinds"].values()) >= 3  # a door and racks
    assert fridge["kinds"] == meta["joint_kinds"]
    assert fridge["mass"] == pytest.approx(sum(lk["mass"] for lk in meta["links"]), abs=1e-3)
    lamps = [r for r in idx["objects"] if r["category"] == "lamp"]
    assert len(lamps) == 2 and lamps[0]["key"] == lamps[1]["key"]  # the symlinked copy shares the data
    for r in idx["objects"]:
        assert (site["site"] / "data" / "obj" / f"{r['key']}.js").is_file()
        # render=False: the card shows the SimReady thumbnail the writer put beside the USD
        assert "/.thumbs/256x256/" in r["thumb"] and r["thumb"].endswith(".usda.png"), r["thumb"]
    for name in ("three.gallery.min.js", "three.LICENSE", "gallery.js", "gallery.css"):
        assert (site["site"] / "assets" / name).is_file()
    assert "{{PREFIX}}" not in site["index"].read_text()


def test_object_data_follows_the_urdf(dataset):
    folder = dataset / "lamp" / "lamp_000000"
    textures = {}
    data = object_data(folder, textures)
    meta = json.loads((folder / "metadata.json").read_text())
    movable = [j for j in data["joints"] if j["type"] != "fixed"]
    assert len(movable) == meta["counts"]["movable_joints"]
    # a compound joint is its chain: every DoF of the chain keeps the compound kind and group
    chains = {}
    for j in movable:
        chains.setdefault(j["group"], []).append(j)
    assert any(len(js) == 2 and js[0]["kind"] in ("revolute_prismatic", "continuous_prismatic")
               for js in chains.values())
    assert {t for m in data["materials"].values() for s in m.values() for t in (s.get("map_Kd"),)} <= set(textures)
    assert all(j["lower"] <= j["upper"] for j in data["joints"])


def test_find_follows_symlinks_and_skips_the_gallery(dataset, site):
    found = find_object_folders(dataset)
    assert len(found) == 4
    assert not any("gallery" in f.parts for f in found)


def test_out_html_file(dataset, tmp_path):
    res = build_gallery(dataset, out=tmp_path / "g.html", render=False, log=lambda *a, **k: None)
    assert res["index"] == tmp_path / "g.html"
    assert (tmp_path / "g_files" / "data" / "index.js").is_file()
    assert 'src="g_files/assets/gallery.js"' in (tmp_path / "g.html").read_text()


def test_bad_input_exits_2_and_writes_nothing(tmp_path, capsys):
    assert cli_main(["gallery", str(tmp_path / "missing")]) == 2
    assert "is not a folder" in capsys.readouterr().err
    (tmp_path / "empty").mkdir()
    assert cli_main(["gallery", str(tmp_path / "empty")]) == 2
    assert "no object folders" in capsys.readouterr().err
    assert not (tmp_path / "empty" / "gallery").exists()


# --------------------------------------------------------------------------------------------- browser

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
# SwiftShader WebGL on the CPU; --disable-gpu also puts compositing on the CPU (with a software GL
# compositor a frame took ~1 s here)
CHROMIUM_ARGS = ["--disable-gpu", "--enable-unsafe-swiftshader", "--no-sandbox"]


@pytest.fixture(scope="module")
def browser():
    sync_api = pytest.importorskip("playwright.sync_api", reason="pip install -e .[dev] (playwright)")
    if CHROMIUM is None:
        pytest.skip("no system chromium: run .ci/sysdeps.sh (apt-get install chromium)")
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        yield b
        b.close()


def _page(browser, url):
    page = browser.new_page(viewport={"width": 800, "height": 500})
    page.set_default_timeout(120_000)
    problems = []
    page.on("console", lambda m: problems.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: problems.append(str(e)))
    page.goto(url)
    page.wait_for_function("document.body.dataset.cards === 'ready'", polling=250)
    return page, problems


GRAB = """() => {
  const v = INFMOB_GALLERY.viewer, c = v.renderer.domElement;
  v.renderer.render(v.scene, v.camera);
  const gl = v.renderer.getContext(), px = new Uint8Array(c.width * c.height * 4);
  gl.readPixels(0, 0, c.width, c.height, gl.RGBA, gl.UNSIGNED_BYTE, px);
  window.__grabs = (window.__grabs || []).concat([px]);
  return window.__grabs.length - 1;
}"""
# fraction of pixels inside box [x0, y0, x1, y1] (canvas pixels, y down) that differ between two grabs
DIFF = """([a, b, box]) => {
  const c = INFMOB_GALLERY.viewer.renderer.domElement, A = window.__grabs[a], B = window.__grabs[b];
  let n = 0, changed = 0;
  const [x0, y0, x1, y1] = box.map(Math.round);
  for (let y = y0; y < y1; y++) for (let x = x0; x < x1; x++) {
    const i = ((c.height - 1 - y) * c.width + x) * 4;
    n++;
    if (Math.abs(A[i] - B[i]) + Math.abs(A[i + 1] - B[i + 1]) + Math.abs(A[i + 2] - B[i + 2]) > 30) changed++;
  }
  return n ? changed / n : 0;
}"""


def _open(page, name):
    i = page.evaluate(f"INFMOB_GALLERY.data.objects.findIndex(o => o.name === {name!r})")
    assert i >= 0
    page.evaluate(f"location.hash = 'object={i}'")
    # interval polling: Playwright's default polls once per animation frame, and a frame of a WebGL
    # page composited on the CPU is slow
    page.wait_for_function("document.getElementById('viewer').dataset.state === 'ready'", polling=250)


def _union(a, b):
    return [min(a[0], b[0]), min(a[1], b[1]), max(a[2], b[2]), max(a[3], b[3])]


def test_browser_cards_door_slider_open_all(browser, site):
    page, problems = _page(browser, site["index"].as_uri())
    assert page.locator(".card").count() == 4
    page.select_option("#f-category", "lamp")
    assert page.locator(".card").count() == 2
    page.select_option("#f-category", "")
    page.select_option("#f-kind", "revolute")
    assert page.locator(".card").count() == sum(1 for r in _index(site)["objects"] if r["kinds"].get("revolute"))
    page.select_option("#f-kind", "")

    _open(page, "beverage_fridge_000000")
    sliders = page.locator("#sliders input[type=range]")
    meta = json.loads((site["index"].parents[1] / "beverage_fridge" / "beverage_fridge_000000" / "metadata.json")
                      .read_text())
    assert sliders.count() == meta["counts"]["movable_joints"] >= 3  # one per movable joint
    rack = page.locator("#sliders input[data-joint=joint_rack_0]")
    assert rack.is_disabled()  # requires_open: the rack moves only with the door open
    rest = page.evaluate(GRAB)
    box_rest = page.evaluate("INFMOB_GALLERY.viewer.screenBox('door')")
    door = page.locator("#sliders input[data-joint=joint_door]")
    door.evaluate("(e) => { e.value = e.max * 0.8; e.dispatchEvent(new Event('input')); }")
    moved = page.evaluate(GRAB)
    box = _union(box_rest, page.evaluate("INFMOB_GALLERY.viewer.screenBox('door')"))
    assert page.evaluate(DIFF, [rest, moved, box]) > 0.2, "moving the door's slider did not change the door's pixels"
    assert rack.is_disabled()  # door not fully open yet

    page.click("#btn-open")
    page.wait_for_function("!INFMOB_GALLERY.viewer.anim", polling=250)
    q = page.evaluate("Object.fromEntries(INFMOB_GALLERY.viewer.joints.map(j => [j.name, [j.q, j.upper]]))")
    assert all(v[0] == pytest.approx(v[1]) for v in q.values()), q  # door first, then the racks
    assert rack.is_enabled()
    opened = page.evaluate(GRAB)
    whole = [0, 0, *page.evaluate("((c) => [c.width, c.height])(INFMOB_GALLERY.viewer.renderer.domElement)")]
    assert page.evaluate(DIFF, [rest, opened, whole]) > 0.05, "'open all' looks like the rest state"

    page.click("#btn-reset")
    page.wait_for_function("!INFMOB_GALLERY.viewer.anim", polling=250)
    back = page.evaluate(GRAB)
    assert page.evaluate(DIFF, [rest, back, whole]) < 0.002

    _open(page, "lamp_000000")  # a compound joint: a slider per DoF of its chain
    n = page.evaluate("INFMOB_GALLERY.viewer.joints.length")
    assert page.locator("#sliders input[type=range]").count() == n >= 2

    page.evaluate("location.hash = 'stats'")
    page.wait_for_function("!!document.querySelector('#chart-histograms svg')", polling=250)
    assert page.locator("#chart-histograms figure").count() == 3  # one histogram per category
    assert not problems, problems


def test_browser_over_serve(browser, dataset, site):
    proc = subprocess.Popen([sys.executable, "-m", "infmob_usd.cli", "gallery", str(dataset), "--no-render",
                             "--serve", "--port", "0"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    try:
        url = None
        for line in proc.stdout:
            m = re.search(r"serving (http://127\.0\.0\.1:\d+/\S+)", line)
            if m:
                url = m.group(1)
                break
        assert url, "no 'serving http://127.0.0.1:PORT/...' line"
        page, problems = _page(browser, url)
        assert page.locator(".card").count() == 4
        _open(page, "kitchen_cabinet_000001")
        assert page.locator("#sliders input[type=range]").count() >= 1
        assert not problems, problems
    finally:
        proc.terminate()
        proc.wait(timeout=30)


def test_browser_a_tilt_and_turn_sash_opens_one_mode(browser, tmp_path):
    """The viewer honours ``excludes``: Open all turns a tilt-and-turn sash without tilting it, and
    dragging its tilt slider puts the turn back to rest (one mode at a time, as its handle selects)."""
    ds = tmp_path / "ds"
    infmob_usd.save(infmob_usd.generate("window", seed=1, texture_size=16, style="tilt_turn"), ds)
    site = build_gallery(ds, render=False, log=lambda *a, **k: None)
    page, problems = _page(browser, site["index"].as_uri())
    _open(page, "window_000001")
    page.click("#btn-open")
    page.wait_for_function("!INFMOB_GALLERY.viewer.anim", polling=250)
    grab = "Object.fromEntries(INFMOB_GALLERY.viewer.joints.map(j => [j.name, j.q]))"
    q = page.evaluate(grab)
    assert q["joint_sash_0_0"] > 0.5 and q["joint_sash_0_1"] == 0.0, q
    tilt = page.locator("#sliders input[data-joint=joint_sash_0_1]")
    tilt.evaluate("(e) => { e.value = e.max; e.dispatchEvent(new Event('input')); }")
    q = page.evaluate(grab)
    assert q["joint_sash_0_1"] > 0.1 and q["joint_sash_0_0"] == 0.0, q
    assert not problems, problems


@pytest.fixture(scope="module")
def scene_site(tmp_path_factory):
    from infmob_usd.scenes import save_scene, scene

    root = tmp_path_factory.mktemp("gallery_scenes")
    folder = save_scene(scene("bathroom", 2, texture_size=16), root)
    return folder, build_gallery(root, render=False, log=lambda *a, **k: None)


def test_a_scene_gets_a_card_with_its_own_pictures(scene_site, tmp_path):
    """A scene folder is a scene card (kind, seed, objects, room, rest and all-open pictures when the scene
    has them: ``infmob scene --preview`` writes them); its objects are object cards as well."""
    folder, site = scene_site
    rec = json.loads((folder / "scene.json").read_text())
    idx = _index(site)
    assert site["scenes"] == 1 and not site["errors"]
    (card,) = idx["scenes"]
    assert (card["kind"], card["seed"], card["objects"]) == ("bathroom", 2, len(rec["objects"]))
    assert card["rest"] is None and card["open"] is None  # no pictures and render=False
    assert len(idx["objects"]) == len({o["folder"] for o in rec["objects"]})
    copy = tmp_path / "copy"
    shutil.copytree(folder, copy / folder.name, symlinks=True)
    for name in ("preview.png", "preview_open.png"):  # the pictures `infmob scene --preview` adds
        (copy / folder.name / name).write_bytes(b"\x89PNG\r\n\x1a\n")
    (again,) = _index(build_gallery(copy, render=False, log=lambda *a, **k: None))["scenes"]
    assert again["rest"].endswith(f"{folder.name}/preview.png") and again["open"].endswith("preview_open.png")


def test_browser_scenes_tab(browser, scene_site):
    folder, site = scene_site
    page, problems = _page(browser, site["index"].as_uri())
    assert page.locator("#tab-scenes").is_visible()
    page.click("#tab-scenes")
    page.wait_for_function("document.querySelectorAll('.scene-card').length === 1", polling=250)
    assert folder.name in page.locator(".scene-card .meta").inner_text()
    assert page.locator("#cards").is_hidden()
    assert not problems, problems
