"""Reading a folder of generated objects that may come from elsewhere: every path is checked.

A source object folder is what ``infmob generate`` writes (``metadata.json``, ``NAME.urdf``,
``semantics.txt``, ``meshes/``, ``textures/``). The folder is treated as hostile input: files are
opened only when they are regular files inside the object folder, reached without a symbolic
link; mesh, material and texture references that point anywhere else are refused; sizes are
bounded. Every refusal is an :class:`ExportError` whose message names the object and the problem.
"""

from __future__ import annotations

import json
import os
import re
import stat
from dataclasses import dataclass
from pathlib import Path

from infmob_usd.errors import InfmobError
from infmob_usd.validate.files import UrdfModel, read_urdf

MAX_TEXT = 64 << 20  # bytes of one metadata/URDF/OBJ/MTL file we agree to read
MAX_DEPTH = 4  # SRC/CATEGORY/OBJECT is depth 2; deeper trees are searched a little further
SAFE_NAME = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9_.\-]*$")
LABEL = re.compile(r"^[A-Za-z0-9_\-]+$")


class ExportError(InfmobError, ValueError):
    """A source folder that cannot be exported (malformed, unsafe, or missing files)."""


def _inside(root: Path, rel: str, what: str) -> Path:
    """``root/rel`` when ``rel`` is a plain relative path with no ``..``, no link on the way and a
    regular file at the end; else :class:`ExportError`."""
    parts = rel.replace("\\", "/").split("/")
    if rel.startswith("/") or ".." in parts or not parts[-1]:
        raise ExportError(f"{root}: {what} {rel!r} points outside the object folder; only files inside it are read")
    path = root
    for p in (p for p in parts if p not in ("", ".")):
        path = path / p
        try:
            st = os.lstat(path)
        except OSError:
            raise ExportError(f"{root}: {what} {rel!r} is missing; regenerate the object (infmob generate)") from None
        if stat.S_ISLNK(st.st_mode):
            raise ExportError(f"{root}: {what} {rel!r} is a symbolic link; export never follows links")
    if not stat.S_ISREG(st.st_mode):
        raise ExportError(f"{root}: {what} {rel!r} is not a regular file")
    if st.st_size > MAX_TEXT:
        raise ExportError(f"{root}: {what} {rel!r} is {st.st_size} bytes (over {MAX_TEXT}); not an infmob object")
    return path


def read_text(root: Path, rel: str, what: str) -> str:
    """The UTF-8 text of ``root/rel`` (checked by :func:`_inside`)."""
    path = _inside(root, rel, what)
    try:
        return path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise ExportError(f"{root}: {what} {rel!r} is not UTF-8 text") from None


def read_bytes(root: Path, rel: str, what: str) -> bytes:
    return _inside(root, rel, what).read_bytes()


@dataclass
class Source:
    """One source object: its folder, ``metadata.json``, URDF model and ``semantics.txt`` labels."""

    folder: Path
    meta: dict
    model: UrdfModel
    urdf_dir: str  # folder of the URDF, relative to ``folder`` ("" for top level)
    semantics: dict[str, tuple[str, str]]  # link -> (PartNet-Mobility joint type, label)
    dummies: set[str]

    @property
    def category(self) -> str:
        return self.meta["category"]

    @property
    def seed(self) -> int:
        return self.meta["seed"]


def _check_meta(folder: Path, meta) -> dict:
    if not isinstance(meta, dict):
        raise ExportError(f"{folder}: metadata.json is not a JSON object; not an infmob object folder")
    ok = (isinstance(meta.get("category"), str) and LABEL.match(meta["category"])
          and isinstance(meta.get("seed"), int) and not isinstance(meta.get("seed"), bool)
          and isinstance(meta.get("links"), list) and isinstance(meta.get("joints"), list)
          and isinstance(meta.get("files"), dict) and isinstance(meta["files"].get("urdf"), str))
    if not ok:
        raise ExportError(f"{folder}: metadata.json lacks category/seed/links/joints/files.urdf;"
                          f" export reads folders written by `infmob generate --formats urdf,...`")
    return meta


def _semantics(folder: Path, text: str, model: UrdfModel) -> dict[str, tuple[str, str]]:
    out = {}
    for n, line in enumerate(text.splitlines(), 1):
        words = line.split()
        if not words:
            continue
        if len(words) != 3 or not all(LABEL.match(w) for w in words) or words[0] not in model.links:
            raise ExportError(f"{folder}: semantics.txt line {n} is not `LINK JOINT_TYPE LABEL` of a URDF link")
        out[words[0]] = (words[1], words[2])
    return out


def read_source(folder: str | Path) -> Source:
    """Read and check one object folder (see the module docstring).

    Raises
    ------
    ExportError
        Anything missing, malformed, unsafe or inconsistent; the message names the folder.
    """
    folder = Path(folder)
    try:
        meta = _check_meta(folder, json.loads(read_text(folder, "metadata.json", "metadata")))
    except json.JSONDecodeError as e:
        raise ExportError(f"{folder}: metadata.json is not valid JSON ({e.msg}, line {e.lineno})") from None
    rel = meta["files"]["urdf"]
    try:
        model = read_urdf(read_text(folder, rel, "URDF"))
        model.ordered()
    except ValueError as e:
        if isinstance(e, ExportError):
            raise
        raise ExportError(f"{folder}: {rel}: {e}") from None
    urdf_dir = os.path.dirname(os.path.normpath(rel.removeprefix("./")))
    for link in model.links.values():
        for m in (*link.visuals, *link.collisions):
            _inside(folder, os.path.join(urdf_dir, m.filename), f"link {link.name} mesh")
    semantics = _semantics(folder, read_text(folder, "semantics.txt", "semantics"), model)
    dummies = {str(link.get("name")) for link in meta["links"] if isinstance(link, dict) and link.get("dummy")}
    real = [n for n in model.links if n not in dummies]
    missing = [n for n in real if n not in semantics]
    if missing:
        raise ExportError(f"{folder}: semantics.txt has no label for links {missing[:3]}; regenerate the object")
    for name in model.links:
        if not LABEL.match(name):
            raise ExportError(f"{folder}: link name {name!r} has characters other than letters, digits, _ and -")
    return Source(folder, meta, model, urdf_dir, semantics, dummies)


def find_sources(src: str | Path) -> list[str]:
    """Object folders under ``src`` (those holding a regular ``metadata.json``), as paths relative
    to ``src`` in sorted order; links and hidden names are never entered.

    Raises
    ------
    ExportError
        ``src`` is missing, not a folder, or a symbolic link.
    """
    src = Path(src)
    if os.path.islink(src):
        raise ExportError(f"SRC {str(src)!r} is a symbolic link; give the real folder (export never follows links)")
    if not src.is_dir():
        raise ExportError(f"SRC {str(src)!r} is not a folder; give a folder of generated objects (infmob generate)")
    found: list[str] = []

    def walk(rel: str, depth: int) -> None:
        here = src / rel if rel else src
        try:
            entries = sorted(os.scandir(here), key=lambda e: e.name)
        except OSError:
            return
        if any(e.name == "metadata.json" and e.is_file(follow_symlinks=False) for e in entries):
            found.append(rel)
            return
        if depth >= MAX_DEPTH:
            return
        for e in entries:
            if not e.name.startswith(".") and e.is_dir(follow_symlinks=False):
                walk(f"{rel}/{e.name}" if rel else e.name, depth + 1)

    walk("", 0)
    return found
