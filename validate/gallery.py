"""A static HTML gallery of a folder of objects: cards, filters, a 3D viewer with joint sliders, statistics.

``infmob gallery DIR`` reads every finished object folder under ``DIR`` back (``metadata.json``, the
URDF, its visual OBJ/MTL meshes and textures) and writes a site that opens from ``file://`` with no
server and no internet::

    gallery/index.html                 the page (cards | statistics | viewer)
    gallery/assets/                    three.js (vendored, MIT), gallery.js, gallery.css
    gallery/data/index.js              one row per object (the cards), loaded by a <script> tag
    gallery/data/stats.js              ``infmob stats`` figures + joint-count histograms
    gallery/data/obj/<key>.js          one object: links, joints (URDF + metadata), OBJ text, MTL materials
    gallery/data/tex/<sha>.js          one texture PNG as a data: URI, shared by every object wearing it
    gallery/thumbs/<key>.png           thumbnails rendered for objects that have none

Everything is a ``.js`` file loaded by ``<script>`` tags because Chromium refuses ``fetch()`` and
ES-module imports of local files under ``file://``, and taints WebGL textures read from ``file://``
images (data: URIs are not tainted). Objects' data files load only when a card is opened, so the page
itself reads one row per object. Symlinked copies of one object folder share its data file.

Thumbnails: an object's ``preview.png`` (its rest half) or ``.thumbs/256x256/*.png`` when present;
otherwise one is rendered with :mod:`preview`'s renderer where a Vulkan device works, else the card
shows a placeholder.
"""

from __future__ import annotations

import base64
import contextlib
import hashlib
import http.server
import json
import os
import posixpath
import re
import shutil
import stat
import sys
import time
import urllib.parse
import xml.etree.ElementTree as ET
from collections import Counter
from functools import partial
from pathlib import Path

ASSETS = Path(__file__).with_name("gallery_assets")
ASSET_FILES = ("three.gallery.min.js", "three.LICENSE", "gallery.js", "gallery.css")
THUMB_SIZE = 256
SCENE_SIZE = (640, 480)  # a scene card's picture (width, height)
MOVABLE = ("revolute", "continuous", "prismatic")


class GalleryError(ValueError):
    """Bad input for the gallery: the message names the problem and the fix."""


# Bounds on what one object's files may weigh: ours are kilobytes (URDF, metadata) to tens of
# megabytes (meshes, 4096 px maps); a file far over them is not an object of ours, and reading it
# would take minutes (expat re-scans a huge token once per 64 kB chunk) and gigabytes.
MAX_BYTES = {"metadata": 16 << 20, "URDF": 16 << 20, "mesh": 512 << 20, "MTL": 16 << 20, "texture": 256 << 20}


def _within(real: str, top: str) -> bool:
    return real == top or real.startswith(top.rstrip(os.sep) + os.sep)


def inside(folder: Path, name: str, what: str, base: Path | None = None) -> Path:
    """``base/name`` (``base`` defaults to ``folder``) if it lies inside the object ``folder``, links
    resolved; a file named by an absolute path, or one that climbs out with ``..`` or through a symbolic
    link, raises :class:`ValueError` naming it: a downloaded dataset must not make us read the user's files."""
    if os.path.isabs(name):
        raise ValueError(f"{what} {name!r} is an absolute path: refused (only files inside the object folder"
                         f" are read)")
    path = Path(base if base is not None else folder) / name
    if not _within(os.path.realpath(path), os.path.realpath(folder)):
        raise ValueError(f"{what} {name!r} lies outside the object folder (.. or a symbolic link): refused")
    return path


def read_bounded(path: Path, what: str) -> bytes:
    """The bytes of ``path``, refused with :class:`ValueError` when over ``MAX_BYTES[what]``."""
    limit = MAX_BYTES[what]
    size = path.stat().st_size
    if size > limit:
        raise ValueError(f"{what} {path.name} is {size / 2**20:.0f} MB, over the {limit >> 20} MB an object's"
                         f" {what} may have: refused")
    return path.read_bytes()


# --------------------------------------------------------------------------------------------- finding


def find_object_folders(root: str | Path) -> list[Path]:
    """Every object folder (one with ``metadata.json``) under ``root``, following symlinks, sorted.

    Hidden folders are skipped and an object folder is not searched further. A symlinked copy of
    an object folder is an object of its own; a symlink back to a folder above it is not entered, nor
    one to a folder outside ``root`` (nothing outside ``root`` is read or served).
    """
    return _find_marked(root, "metadata.json")


def find_scene_folders(root: str | Path) -> list[Path]:
    """Every scene folder (one with ``scene.json``) under ``root``, found as :func:`find_object_folders`
    finds objects (the scene's own objects are found by that)."""
    return _find_marked(root, "scene.json")


def _find_marked(root: str | Path, marker: str) -> list[Path]:
    """Folders holding a file ``marker`` under ``root``; see :func:`find_object_folders`."""
    root = Path(root)
    if (root / marker).is_file():
        return [root]
    found: list[Path] = []
    top = os.path.realpath(root)
    stack = [(str(root), frozenset([top]))]
    while stack:
        path, above = stack.pop()
        try:
            entries = list(os.scandir(path))
        except OSError:
            continue
        if any(e.name == marker and e.is_file() for e in entries) and path != str(root):
            found.append(Path(path))
            continue
        for e in entries:
            if e.name.startswith(".") or not e.is_dir():
                continue
            real = os.path.realpath(e.path)
            if real not in above and _within(real, top):
                stack.append((e.path, above | {real}))
    return sorted(found)


def _thumbnail_in(folder: Path) -> Path | None:
    """The object's own picture: ``.thumbs/256x256/*.png`` or ``preview.png`` (rest | open)."""
    real = os.path.realpath(folder)
    thumbs = [p for p in sorted((folder / ".thumbs" / "256x256").glob("*.png"))
              if _within(os.path.realpath(p), real)]
    if thumbs:
        return thumbs[0]
    p = folder / "preview.png"
    return p if p.is_file() and _within(os.path.realpath(p), real) else None


def _key(folder: Path) -> str:
    return hashlib.sha1(os.fsencode(os.path.realpath(folder))).hexdigest()[:16]


# --------------------------------------------------------------------------------------------- one object


def _floats(text, default):
    return [float(x) for x in text.split()] if text else list(default)


def _parse_mtl(text: str) -> dict[str, dict]:
    """``newmtl`` blocks of an MTL file: {name: {key: value}} (numbers as lists, maps as file names)."""
    out: dict[str, dict] = {}
    cur: dict | None = None
    for line in text.splitlines():
        parts = line.split()
        if not parts or parts[0].startswith("#"):
            continue
        if parts[0] == "newmtl":
            cur = out.setdefault(" ".join(parts[1:]), {})
        elif cur is not None and len(parts) > 1:
            if parts[0] in ("map_Kd", "map_Pr", "norm", "map_Bump", "bump", "map_Pm"):
                cur[parts[0]] = parts[-1]
            else:
                try:
                    cur[parts[0]] = [float(x) for x in parts[1:]]
                except ValueError:
                    pass
    return out


_MTLLIB = re.compile(r"^mtllib\s+(.+?)\s*$", re.M)


class _Meshes:
    """The OBJ meshes of one object and their MTL files, each read once: ``meshes`` in first-use order
    (``{"obj": text, "mtl": [file keys]}``), ``mtl_files`` by path, their maps named by a hash of the
    texture bytes (``textures`` gains ``{hash: path}``). Only files inside the object folder ``base``
    (:func:`inside`) and within :data:`MAX_BYTES` are read; any other raises :class:`ValueError`."""

    def __init__(self, base: Path, textures: dict[str, Path]):
        self.base, self.textures = base, textures
        self.meshes: list[dict] = []
        self.mesh_index: dict[str, int] = {}
        self.mtl_files: dict[str, dict] = {}
        self.tex_hash: dict[Path, str] = {}

    def texture(self, mtl_dir: Path, name: str) -> str | None:
        path = inside(self.base, name, "texture", mtl_dir).resolve()
        if path not in self.tex_hash:
            if not path.is_file():
                return None
            h = hashlib.sha256(read_bounded(path, "texture")).hexdigest()[:24]
            self.tex_hash[path] = h
            self.textures.setdefault(h, path)
        return self.tex_hash[path]

    def mesh(self, filename: str) -> int:
        if filename.startswith("package://"):
            filename = filename[len("package://"):]
        if filename in self.mesh_index:
            return self.mesh_index[filename]
        path = inside(self.base, filename, "mesh")
        text = read_bounded(path, "mesh").decode()
        libs = []
        for lib in _MTLLIB.findall(text):
            key = os.path.normpath(os.path.join(os.path.dirname(filename), lib))
            if key not in self.mtl_files:
                mpath = inside(self.base, key, "MTL")
                mats = _parse_mtl(read_bounded(mpath, "MTL").decode()) if mpath.is_file() else {}
                for m in mats.values():
                    for k in ("map_Kd", "map_Pr", "norm", "map_Bump", "bump", "map_Pm"):
                        if k in m:
                            m[k] = self.texture(mpath.parent, m[k])
                self.mtl_files[key] = mats
            libs.append(key)
        self.mesh_index[filename] = len(self.meshes)
        self.meshes.append({"obj": text, "mtl": libs})
        return self.mesh_index[filename]


def _joints(root, by_name: dict[str, dict]) -> list[dict]:
    """The viewer's joints: frame, axis and limits from the URDF ``root`` (a revolute joint without limits,
    or a continuous one, turns +-pi), kind, group, role, ``requires_open`` and ``excludes`` from
    ``metadata.json``."""
    joints = []
    for j in root.findall("joint"):
        o, a, lim = j.find("origin"), j.find("axis"), j.find("limit")
        name, jtype = j.get("name"), j.get("type")
        lower = float(lim.get("lower", 0)) if lim is not None else 0.0
        upper = float(lim.get("upper", 0)) if lim is not None else 0.0
        if jtype == "continuous" or (jtype == "revolute" and lower == upper == 0.0):
            lower, upper = -3.141592653589793, 3.141592653589793
        m = by_name.get(name, {})
        joints.append({
            "name": name, "type": jtype, "parent": j.find("parent").get("link"), "child": j.find("child").get("link"),
            "xyz": _floats(o.get("xyz") if o is not None else None, (0, 0, 0)),
            "rpy": _floats(o.get("rpy") if o is not None else None, (0, 0, 0)),
            "axis": _floats(a.get("xyz") if a is not None else None, (1, 0, 0)),
            "lower": min(lower, upper), "upper": max(lower, upper),
            "kind": m.get("kind", jtype), "group": m.get("group", name), "role": m.get("role", ""),
            "requires_open": m.get("requires_open"), "excludes": m.get("excludes", []),
        })
    return joints


def object_data(folder: Path, textures: dict[str, Path]) -> dict:
    """The viewer's data for one object folder: links with visuals, joints, OBJ text, materials.

    Joint frames, axes and limits come from the URDF (what simulators load); kind, group, role,
    ``requires_open`` and ``excludes`` from ``metadata.json``. Texture files are named by a hash of their bytes;
    ``textures`` gains ``{hash: path}`` for each one. Every file is read only if it lies inside
    ``folder`` (:func:`inside`) and within :data:`MAX_BYTES`, else :class:`ValueError` names it.
    """
    meta = json.loads(read_bounded(inside(folder, "metadata.json", "metadata"), "metadata"))
    urdfs = sorted(folder.glob("*.urdf"))
    urdf = folder / f"{meta.get('name', folder.name)}.urdf"
    if not urdf.is_file():
        if not urdfs:
            raise FileNotFoundError(f"no .urdf file in {folder}")
        urdf = urdfs[0]
    root = ET.fromstring(read_bounded(inside(folder, urdf.name, "URDF"), "URDF"))
    table = _Meshes(folder, textures)
    links = []
    for link in root.findall("link"):
        visuals = []
        for vis in link.findall("visual"):
            m = vis.find("geometry/mesh")
            if m is None or not m.get("filename"):
                continue
            o = vis.find("origin")
            visuals.append({"mesh": table.mesh(m.get("filename")),
                            "xyz": _floats(o.get("xyz") if o is not None else None, (0, 0, 0)),
                            "rpy": _floats(o.get("rpy") if o is not None else None, (0, 0, 0)),
                            "scale": _floats(m.get("scale"), (1, 1, 1))})
        links.append({"name": link.get("name"), "visuals": visuals})
    by_name = {j["name"]: j for j in meta.get("joints", [])}
    label = {lk["name"]: lk for lk in meta.get("links", [])}
    for link in links:
        info = label.get(link["name"], {})
        link["label"] = info.get("label", "")
        link["dummy"] = bool(info.get("dummy", False))
    joints = _joints(root, by_name)
    return {"name": meta.get("name", folder.name), "category": meta.get("category", ""), "seed": meta.get("seed"),
            "links": links, "joints": joints, "meshes": table.meshes, "materials": table.mtl_files,
            "textures": sorted(set(table.tex_hash.values()))}


def card(meta: dict) -> dict:
    """The figures a card shows, from ``metadata.json``."""
    kinds = {k: int(v) for k, v in sorted(meta.get("joint_kinds", {}).items())}
    return {
        "name": meta.get("name", ""),
        "category": meta.get("category", "?"),
        "seed": meta.get("seed"),
        "joints": sum(kinds.values()),
        "links": int(meta.get("counts", {}).get("links", 0)),
        "kinds": kinds,
        "mass": round(sum(float(lk.get("mass") or 0.0) for lk in meta.get("links", [])), 3),
    }


# --------------------------------------------------------------------------------------------- statistics


def gallery_stats(metas: list[dict], max_pairs: int = 2000) -> dict:
    """``infmob stats`` figures (validate/stats.py) plus a movable-joint-count histogram per category."""
    from .stats import REFERENCE, Group, reference_count, tree_from_metadata

    groups: dict[str, Group] = {}
    overall = Group("overall")
    hist: dict[str, Counter] = {}
    for meta in metas:
        kinds = meta.get("joint_kinds", {})
        n = sum(kinds.values())
        tree = tree_from_metadata(meta)
        cat = meta.get("category", "?")
        ref = reference_count(meta) if "joints" in meta else None
        for g in (groups.setdefault(cat, Group(cat)), overall):
            g.joints.append(n)
            if ref is not None:
                g.ref_joints.append(ref)
            g.kinds.update(kinds)
            g.trees.append(tree)
        hist.setdefault(cat, Counter())[n] += 1
    return {
        "categories": {name: g.summary(max_pairs) for name, g in sorted(groups.items())},
        "overall": overall.summary(max_pairs),
        "reference": REFERENCE,
        "histogram": {cat: {str(k): v for k, v in sorted(c.items())} for cat, c in sorted(hist.items())},
        "max_pairs": max_pairs,
    }


# --------------------------------------------------------------------------------------------- thumbnails


class _Thumbnailer:
    """Renders missing thumbnails with preview.py's renderer, or says once why it cannot."""

    def __init__(self, enabled: bool, log):
        self.enabled, self.log = enabled, log
        self.ok: bool | None = None
        self.seconds: list[float] = []
        self.failed = 0

    def _ready(self) -> bool:
        if self.ok is None:
            from .preview import backend_status

            self.ok, why = backend_status()
            if not self.ok:
                self.log(f"gallery: cannot render thumbnails ({why.splitlines()[0]}); cards show placeholders")
        return self.ok

    def __call__(self, folder: Path, out_png: Path) -> bool:
        if not self.enabled or not self._ready():
            return False
        from .preview import render_object

        t0 = time.perf_counter()
        try:
            rgb = render_object(folder, size=THUMB_SIZE)
        except Exception as exc:  # one bad object must not stop the gallery
            self.failed += 1
            self.log(f"gallery: thumbnail of {folder} failed: {exc}")
            return False
        return self._encode(rgb, out_png, t0)

    def scene(self, folder: Path, out_png: Path, fraction: float) -> bool:
        """Render the scene ``folder`` with every joint at ``fraction`` of its range into ``out_png``."""
        if not self.enabled or not self._ready():
            return False
        from .scene_preview import render_scene

        t0 = time.perf_counter()
        try:
            rgb = render_scene(folder, SCENE_SIZE[0], SCENE_SIZE[1], fraction=fraction)
        except Exception as exc:  # one bad scene must not stop the gallery
            self.failed += 1
            self.log(f"gallery: picture of scene {folder} failed: {exc}")
            return False
        return self._encode(rgb, out_png, t0)

    def _encode(self, rgb, out_png: Path, t0: float) -> bool:
        import cv2

        ok, png = cv2.imencode(".png", rgb[..., ::-1])
        if not ok:
            self.failed += 1
            return False
        _write(out_png, png.tobytes())
        self.seconds.append(time.perf_counter() - t0)
        return True


# --------------------------------------------------------------------------------------------- the site


def _write(path: Path, data: bytes) -> None:
    """Write ``path`` through a temporary file beside it: never half-written (a kill, a full disk), and
    a symbolic link at ``path`` is replaced, never written through."""
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_TRUNC | os.O_NOFOLLOW | os.O_CLOEXEC, 0o644)
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        try:
            if stat.S_ISREG(os.lstat(tmp).st_mode):
                os.unlink(tmp)
        except OSError:
            pass
        raise


def _write_js(path: Path, call: str, *args) -> None:
    body = ",".join(json.dumps(a, separators=(",", ":")).replace("</", "<\\/") for a in args)
    _write(path, f"{call}({body});\n".encode())


def _real_folder(path: Path, what: str) -> Path:
    """Create ``path`` (a folder of the site) unless it is a symbolic link or a file: writes never leave
    the site through a link placed in it."""
    if os.path.islink(path):
        raise GalleryError(f"{what} {path} is a symbolic link; the gallery never writes through a link: remove it"
                           f" or give another --out")
    if path.exists() and not path.is_dir():
        raise GalleryError(f"{what} {path} is a file: give a folder for the site or an .html file")
    path.mkdir(parents=True, exist_ok=True)
    return path


def _url(relpath: str) -> str:
    """A relative file path as a relative URL (``#``, ``?``, spaces ... escaped)."""
    return urllib.parse.quote(relpath.replace(os.sep, "/"), errors="surrogateescape")  # a non-UTF-8 name: its bytes


def site_paths(out: str | Path | None, root: Path) -> tuple[Path, Path]:
    """(index.html, folder of assets and data) for ``--out``: a folder, or an ``.html`` file."""
    if out is None:
        site = root / "gallery"
        return site / "index.html", site
    out = Path(out)
    if out.suffix.lower() in (".html", ".htm"):
        return out, out.with_name(out.stem + "_files")
    return out / "index.html", out


def _site_for(out, root: Path) -> tuple[Path, Path]:
    """``(index.html, site folder)`` for ``--out`` (:func:`site_paths`), refused where a folder stands in
    the page's place or a file in the site's."""
    index_html, site = site_paths(out, root)
    if index_html.exists() and index_html.is_dir():
        raise GalleryError(f"--out {index_html} is a folder: give a folder for the site or a new .html file")
    if site.exists() and not site.is_dir():
        raise GalleryError(f"--out {site} is a file: give a folder for the site or an .html file")
    for p in (site, index_html):
        if os.path.islink(p):
            raise GalleryError(f"--out {p} is a symbolic link; the gallery never writes through a link:"
                               f" give the real folder or another --out")
    return index_html, site


def _make_writable(site: Path) -> None:
    """Create the site folder and prove it writable before any work, else a :class:`GalleryError`."""
    try:
        site.mkdir(parents=True, exist_ok=True)
        probe = site / f".write_probe.{os.getpid()}"
        probe.write_text("")
        probe.unlink()
    except OSError as exc:
        raise GalleryError(f"cannot write the gallery to {site} ({exc.strerror}): give a writable --out") from None


def _card_thumbnail(folder: Path, png: Path, rel, thumbnailer) -> tuple[str | None, bool]:
    """``(url, half)`` of a card's picture: the object's own thumbnail (``half``: a rest | opened
    ``preview.png``, the card shows its left half), else ``png`` if fresh or rendered now, else None."""
    own = _thumbnail_in(folder)
    if own is not None:
        return _url(rel(own)), own.name == "preview.png"
    fresh = png.is_file() and png.stat().st_mtime >= (folder / "metadata.json").stat().st_mtime
    if fresh or thumbnailer(folder, png):
        return _url(rel(png)), False
    return None, False


def _scene_picture(folder: Path, name: str, png: Path, fraction: float, rel, thumbnailer) -> str | None:
    """The URL of a scene's picture: the scene's own ``name`` (``infmob scene --preview``), else ``png`` if
    fresh or rendered now, else None."""
    own = folder / name
    if own.is_file() and _within(os.path.realpath(own), os.path.realpath(folder)):
        return _url(rel(own))
    fresh = png.is_file() and png.stat().st_mtime >= (folder / "scene.json").stat().st_mtime
    if fresh or thumbnailer.scene(folder, png, fraction):
        return _url(rel(png))
    return None


def scene_cards(root: Path, site: Path, thumbdir: Path, rel, thumbnailer, errors: list[str]) -> list[dict]:
    """One card per scene folder under ``root`` (kind, seed, room, object count, rest and all-open
    pictures); an unreadable ``scene.json`` is an entry in ``errors``, not a stop."""
    cards = []
    for folder in find_scene_folders(root):
        if _within(os.path.realpath(folder), os.path.realpath(site)):
            continue
        try:
            rec = json.loads(read_bounded(inside(folder, "scene.json", "scene"), "metadata"))
            room, objects = rec["room"], rec["objects"]
            row = {"name": str(rec["name"]), "kind": str(rec["kind"]), "seed": int(rec["seed"]),
                   "objects": len(objects), "fixed": sum(1 for o in objects if o.get("fixed")),
                   "room": [float(room["depth"]), float(room["width"]), float(room["height"])],
                   "layout": str((rec.get("overrides") or {}).get("layout") or rec.get("layout") or "")}
        except (OSError, ValueError, KeyError, TypeError, AttributeError) as exc:
            errors.append(f"{folder}: unreadable scene.json ({exc})")
            continue
        key = _key(folder)
        row.update(path=rel(folder),
                   rest=_scene_picture(folder, "preview.png", thumbdir / f"{key}_rest.png", 0.0, rel, thumbnailer),
                   open=_scene_picture(folder, "preview_open.png", thumbdir / f"{key}_open.png", 1.0, rel,
                                       thumbnailer))
        cards.append(row)
    return cards


def _write_textures(textures: dict[str, Path], texdir: Path) -> None:
    """One ``<hash>.js`` per texture (a base64 data URI), skipping those already written."""
    for h, path in textures.items():
        dest = texdir / f"{h}.js"
        if not dest.is_file():
            uri = "data:image/png;base64," + base64.b64encode(read_bounded(path, "texture")).decode()
            _write_js(dest, "INFMOB_GALLERY.texture", h, uri)


def build_gallery(root: str | Path, out: str | Path | None = None, render: bool = True,
                  max_pairs: int = 2000, log=print) -> dict:
    """Write the gallery of every object under ``root``; returns timings and counts.

    ``out``: the site folder (default ``root/gallery``), or an ``.html`` file whose assets and
    data go to ``<stem>_files/`` beside it. ``render``: render missing thumbnails (else placeholders).
    """
    root = Path(root)
    if not root.is_dir():
        raise GalleryError(f"{root} is not a folder: give a folder of objects written by `infmob generate`")
    index_html, site = _site_for(out, root)
    t0 = time.perf_counter()
    folders = [f for f in find_object_folders(root) if os.path.realpath(f) != os.path.realpath(site)]
    if not folders:
        raise GalleryError(f"no object folders (with metadata.json) under {root}: run `infmob generate` first")
    before, had_index = _site_entries(site), os.path.lexists(index_html)
    _make_writable(site)
    try:
        return _build(root, folders, index_html, site, render, max_pairs, log, t0)
    except BaseException:  # SIGTERM, Ctrl-C, a full disk: no half-built site is left
        _remove_new(site, before)
        if not had_index and os.path.lexists(index_html) and not os.path.isdir(index_html):
            index_html.unlink(missing_ok=True)
        raise


def _site_entries(site: Path) -> set[str] | None:
    """The paths under ``site`` before a build; None when the site does not exist yet."""
    if not os.path.lexists(site):
        return None
    found: set[str] = set()
    for top, dirs, files in os.walk(site):  # links are not followed
        found.update(os.path.join(top, n) for n in dirs + files)
    return found


def _remove_new(site: Path, before: set[str] | None) -> None:
    """Remove what an interrupted build added under ``site``: the whole site if it created it, else only the
    new entries (the user's files and an older site's files stay)."""
    if before is None:
        shutil.rmtree(site, ignore_errors=True)
        return
    for top, dirs, files in os.walk(site, topdown=False):
        for n in files + dirs:
            p = os.path.join(top, n)
            if p in before:
                continue
            if os.path.isdir(p) and not os.path.islink(p):
                shutil.rmtree(p, ignore_errors=True)
            else:
                with contextlib.suppress(OSError):
                    os.unlink(p)


def _build(root: Path, folders: list[Path], index_html: Path, site: Path, render: bool, max_pairs: int, log,
           t0: float) -> dict:
    """:func:`build_gallery` once the site folder is known writable."""
    t_find = time.perf_counter() - t0
    data, objdir, texdir, thumbdir, assets = (site / "data", site / "data" / "obj", site / "data" / "tex",
                                              site / "thumbs", site / "assets")
    for d in (assets, data, objdir, texdir, thumbdir):
        _real_folder(d, "site folder")
    for name in ASSET_FILES:
        _write(assets / name, (ASSETS / name).read_bytes())
    base = index_html.parent
    rel = partial(os.path.relpath, start=base)
    thumbnailer = _Thumbnailer(render, log)
    textures: dict[str, Path] = {}
    rows, metas, done, errors, shown = [], [], {}, [], []
    t_read = t_thumb = 0.0
    for folder in folders:
        key = _key(folder)
        try:
            meta = json.loads(read_bounded(inside(folder, "metadata.json", "metadata"), "metadata"))
            if not isinstance(meta, dict):
                raise ValueError("not a JSON object")
        except (OSError, ValueError) as exc:
            errors.append(f"{folder}: unreadable metadata.json ({exc})")
            continue
        if key not in done:
            t1 = time.perf_counter()
            try:
                payload = object_data(folder, textures)
            except (OSError, ValueError, ET.ParseError) as exc:
                errors.append(f"{folder}: {exc}")
                continue
            path = objdir / f"{key}.js"
            _write_js(path, "INFMOB_GALLERY.object", key, payload)
            t2 = time.perf_counter()
            t_read += t2 - t1
            done[key] = _card_thumbnail(folder, thumbdir / f"{key}.png", rel, thumbnailer)
            t_thumb += time.perf_counter() - t2
        thumb, half = done[key]
        row = card(meta)
        row.update(key=key, path=rel(folder), thumb=thumb, half=half)
        rows.append(row)
        metas.append(meta)
        shown.append(folder)
    if not rows:
        raise GalleryError(f"no readable object folders under {root}: " + "; ".join(errors[:3]))
    t3 = time.perf_counter()
    _write_textures(textures, texdir)
    t_tex = time.perf_counter() - t3
    t4 = time.perf_counter()
    stats = gallery_stats(metas, max_pairs=max_pairs)
    t_stats = time.perf_counter() - t4
    prefix = _url(os.path.relpath(site, base))
    prefix = "" if prefix == "." else prefix + "/"
    t5 = time.perf_counter()
    scenes = scene_cards(root, site, thumbdir, rel, thumbnailer, errors)
    t_thumb += time.perf_counter() - t5
    index = {"root": str(root), "objects": rows, "scenes": scenes, "generated": time.strftime("%Y-%m-%d %H:%M:%S"),
             "data": prefix + "data"}
    _write_js(data / "index.js", "INFMOB_GALLERY.index", index)
    _write_js(data / "stats.js", "INFMOB_GALLERY.stats", stats)
    html = (ASSETS / "index.html").read_text().replace("{{PREFIX}}", prefix)
    index_html.parent.mkdir(parents=True, exist_ok=True)
    _write(index_html, html.encode())
    total = time.perf_counter() - t0
    return {"index": index_html, "site": site, "folders": shown, "objects": len(rows), "distinct": len(done),
            "scenes": len(scenes),
            "errors": errors,
            "textures": len(textures), "rendered": len(thumbnailer.seconds), "render_seconds": thumbnailer.seconds,
            "seconds": {"find": t_find, "read": t_read, "thumbnails": t_thumb, "textures": t_tex,
                        "stats": t_stats, "total": total}}


# --------------------------------------------------------------------------------------------- serving


LOOPBACK_NAMES = ("127.0.0.1", "localhost")


def make_server(index_html: Path, site: Path, folders: list[Path], port: int = 8000):
    """``(server, url)``: an HTTP server on 127.0.0.1 (this machine only) serving exactly the page, the
    site folder and the object ``folders`` it shows (thumbnails are linked from them), nothing else.

    URLs are paths below the common parent of those, but a request is answered only when the file
    it names, every link resolved, lies inside one of them: no directory listings, no link out of
    an object folder, and only ``Host: 127.0.0.1|localhost[:PORT]`` (a DNS-rebinding page elsewhere
    names its own host and is refused).
    """
    index_html, site = Path(os.path.abspath(index_html)), Path(os.path.abspath(site))
    top = Path(os.path.commonpath([str(index_html.parent), str(site)] + [os.path.abspath(f) for f in folders]))
    handler = partial(_GalleryHandler, directory=str(top))
    try:
        httpd = _GalleryServer(("127.0.0.1", port), handler)
    except OSError as exc:
        raise GalleryError(f"cannot listen on 127.0.0.1:{port} ({exc.strerror}): pick another --port") from None
    httpd.files = {os.path.realpath(index_html)}
    httpd.trees = {os.path.realpath(site)} | {os.path.realpath(f) for f in folders}
    url_path = _url(os.path.relpath(index_html, top))
    return httpd, f"http://127.0.0.1:{httpd.server_address[1]}/{url_path}"


def serve(index_html: Path, site: Path, folders: list[Path], port: int = 8000, log=print) -> None:
    """Serve the site (:func:`make_server`) until Ctrl-C or SIGTERM."""
    httpd, url = make_server(index_html, site, folders, port)
    log(f"serving {url}  (127.0.0.1 only: this machine; Ctrl-C stops)", flush=True)
    try:
        httpd.serve_forever()
    except KeyboardInterrupt:
        pass
    finally:
        httpd.server_close()


class _GalleryServer(http.server.ThreadingHTTPServer):
    daemon_threads = True
    files: set[str] = set()
    trees: set[str] = set()

    def allows(self, real: str) -> bool:
        if real in self.files:
            return True
        p = real
        while True:  # the real path or a folder above it is a tree we serve
            if p in self.trees:
                return True
            parent = os.path.dirname(p)
            if parent == p:
                return False
            p = parent


class _GalleryHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, fmt, *args):  # one line per request is noise for a gallery
        pass

    def _host_ok(self) -> bool:
        host = (self.headers.get("Host") or "").strip().lower()
        name, _, port = host.rpartition(":") if host.count(":") == 1 else (host, "", "")
        return name in LOOPBACK_NAMES and port in ("", str(self.server.server_address[1]))

    def translate_path(self, path):
        """As http.server's, but %XX escapes decode to the file name's own bytes (a non-UTF-8 name too)."""
        path = path.split("?", 1)[0].split("#", 1)[0]
        trailing = path.rstrip().endswith("/")
        words = [w for w in posixpath.normpath(urllib.parse.unquote(path, errors="surrogateescape")).split("/")
                 if w and w not in (os.curdir, os.pardir)]
        return os.path.join(self.directory, *words) + ("/" if trailing else "")

    def send_head(self):
        if not self._host_ok():
            self.send_error(421, "Misdirected Request: this gallery answers only to 127.0.0.1 and localhost")
            return None
        path = self.translate_path(self.path)
        target = os.path.join(path, "index.html") if os.path.isdir(path) else path
        if not os.path.isfile(target) or not self.server.allows(os.path.realpath(target)):
            self.send_error(404, "File not found")
            return None
        return super().send_head()

    def list_directory(self, path):  # never: a folder without index.html is not part of the site
        self.send_error(404, "File not found")
        return None


# --------------------------------------------------------------------------------------------- command line


def add_arguments(parser) -> None:
    parser.add_argument("folder", metavar="DIR", help="a folder of objects (searched recursively, symlinks followed)")
    parser.add_argument("--out", default=None, metavar="FILE|DIR",
                        help="the site: a folder (index.html inside) or an .html file (its data in <stem>_files/"
                             " beside it); default DIR/gallery")
    parser.add_argument("--serve", action="store_true",
                        help="then serve it over HTTP on 127.0.0.1 only (this machine; no other address is bound):"
                             " the site and the object folders it shows, nothing else (Ctrl-C stops)")
    parser.add_argument("--port", type=int, default=8000, help="with --serve: the port; default 8000 (0: any free)")
    parser.add_argument("--no-render", action="store_true",
                        help="do not render missing thumbnails (cards show a placeholder instead)")
    parser.add_argument("--max-pairs", type=int, default=2000,
                        help="statistics: at most this many sampled object pairs per group for mean TED; default 2000")


def main(args) -> int:
    """Run ``infmob gallery`` with the namespace of :func:`add_arguments`; returns the exit code."""
    if not 0 <= args.port <= 65535:
        print(f"infmob: error: --port must be 0..65535, got {args.port}", file=sys.stderr)
        return 2
    try:
        res = build_gallery(args.folder, args.out, render=not args.no_render, max_pairs=args.max_pairs,
                            log=partial(print, file=sys.stderr))
    except GalleryError as exc:
        print(f"infmob: error: {exc}", file=sys.stderr)
        return 2
    for e in res["errors"]:
        print(f"gallery: skipped {e}", file=sys.stderr)
    s = res["seconds"]
    n, d = res["objects"], res["distinct"]
    line = (f"{res['index']}  ({n} objects, {d} distinct folders, {res['textures']} textures; "
            f"{s['total']:.1f} s: find {s['find']:.1f}, read+write {s['read']:.1f} ({s['read'] / max(d, 1) * 1000:.1f}"
            f" ms per object), textures {s['textures']:.1f}, stats {s['stats']:.1f}")
    if res["rendered"]:
        import statistics

        line += (f", {res['rendered']} thumbnails rendered in {s['thumbnails']:.1f} s"
                 f" (median {statistics.median(res['render_seconds']):.2f} s each)")
    print(line + ")")
    if args.serve:
        try:
            serve(Path(res["index"]), Path(res["site"]), res["folders"], args.port)
        except GalleryError as exc:
            print(f"infmob: error: {exc}", file=sys.stderr)
            return 2
    return 1 if res["errors"] else 0
