"""Scenes: rooms composed of generated articulated objects, written as one USD stage.

>>> import infmob_usd
>>> s = infmob_usd.scene("kitchen", seed=3)             # a Scene: room, placed objects
>>> folder = infmob_usd.save_scene(s, "out")            # out/kitchen_000003/scene.usda, scene.json, scene.xml
>>> sim_scene, articulations = infmob_usd.scene.load_sapien(folder)

A scene kind (``categories/rooms/``) is a parameter schema, a growth grammar and a layout, as a category is;
``infmob scene KIND --seed S`` makes one. Same kind, seed and overrides: the same files, byte for byte.
"""

from __future__ import annotations

import zlib
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ParameterError
from .kind import SceneKind
from .layout import Made, Placed, SceneLayout
from .room import Room


@dataclass
class Scene:
    kind: str
    seed: int
    params: dict[str, Any]
    overrides: dict[str, Any]
    room: Room
    placed: list[Placed]
    texture_size: int

    @property
    def name(self) -> str:
        return f"{self.kind}_{self.seed:06d}"

    @property
    def objects(self) -> list[Made]:
        """Each distinct object once, in the order first placed."""
        seen: dict[str, Made] = {}
        for p in self.placed:
            seen.setdefault(p.made.key, p.made)
        return list(seen.values())


def kinds() -> dict[str, SceneKind]:
    from ..categories.rooms import KINDS

    return KINDS


def get_kind(kind: str) -> SceneKind:
    found = kinds()
    if not isinstance(kind, str) or kind not in found:
        raise ParameterError(f"unknown scene kind {kind!r}; choose one of: {', '.join(found)}")
    return found[kind]


def scene_streams(kind: str, seed: int) -> dict[str, np.random.Generator]:
    from ..seeding import MAX_SEED

    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or not 0 <= seed <= MAX_SEED:
        raise ParameterError(f"seed must be an integer in 0..{MAX_SEED}, got {seed!r}")
    root = np.random.SeedSequence((int(seed), zlib.crc32(f"scene:{kind}".encode())))
    names = ("params", "structure", "placement", "objects")
    return {n: np.random.default_rng(s) for n, s in zip(names, root.spawn(len(names)))}


def scene(kind: str, seed: int = 0, texture_size: int = 256, pool=None, **overrides: Any) -> Scene:
    """Compose one scene: a pure function of ``(kind, seed, overrides)``.

    ``texture_size``: edge of every object's texture maps (power of two, 16..4096; a room holds dozens
    of objects, so the default is smaller than an object's). ``pool``: a ``concurrent.futures`` process
    pool that makes the scene's objects in parallel (the same scene, byte for byte, as without one).
    ``overrides``: the kind's parameters (``infmob scene KIND --params``)."""
    from ..api import check_texture_size, generate, list_categories

    k = get_kind(kind)
    check_texture_size(texture_size)
    rng = scene_streams(kind, seed)
    params = k.schema.sample(rng["params"], overrides)
    tree = k.grammar.grow(params, rng["structure"])
    layout: SceneLayout = k.layout(kind, k.grammar.resolve(params), rng["placement"], rng["objects"], texture_size,
                                   generate, tuple(list_categories()), pool=pool)
    layout.run(tree)
    return Scene(kind, int(seed), params, k.schema.validate(overrides), layout.room, layout.placed, texture_size)


def save_scene(s: Scene, folder, pool=None) -> Any:
    """Write ``s`` into ``folder/<kind>_<seed>/`` (atomically) and return that path: every distinct
    object once under ``objects/``, ``scene.usda`` (each object a reference to its own stage),
    ``scene.json`` and ``scene.xml`` (MuJoCo). ``pool``: as in :func:`scene`, writes the object folders."""
    from ..layers.scene import write_scene

    return write_scene(s, folder, pool=pool)


def load_sapien(folder, scene_json=None, **kw):
    """The scene in SAPIEN: ``(sapien.Scene, {placed id: articulation})`` (see :mod:`infmob_usd.validate.scene`)."""
    from ..validate.scene import load_sapien_scene

    return load_sapien_scene(folder, scene_json, **kw)


__all__ = ["Made", "Placed", "Room", "Scene", "SceneKind", "SceneLayout", "get_kind", "kinds", "load_sapien",
           "save_scene", "scene"]
