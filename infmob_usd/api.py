"""The public API: ``generate``, ``save``, ``list_categories``, ``get_category``."""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

from . import physical
from .effort import assign_drives
from .errors import ArgumentTypeError, ModelError, ParameterError, UnknownCategoryError
from .interaction import annotate
from .layers import write_object
from .model import ArticulatedObject, build
from .seeding import streams

TEXTURE_SIZES = tuple(2**k for k in range(4, 13))


def list_categories() -> list[str]:
    """Every category id, sorted."""
    from .categories import CATEGORIES

    return list(CATEGORIES)


def get_category(category: str):
    """The :class:`~infmob_usd.category.Category` of an id; unknown ids raise a message listing the valid ones."""
    from .categories import CATEGORIES

    if not isinstance(category, str) or category not in CATEGORIES:
        raise UnknownCategoryError(
            f"unknown category {category!r}; valid categories: {', '.join(CATEGORIES)}"
        )
    return CATEGORIES[category]


def check_texture_size(size: Any) -> int:
    if isinstance(size, bool) or not isinstance(size, int) or size not in TEXTURE_SIZES:
        raise ParameterError(
            f"texture size must be a power of two from {TEXTURE_SIZES[0]} to {TEXTURE_SIZES[-1]},"
            f" got {size!r}"
        )
    return size


def check_share(share: Any) -> float:
    if isinstance(share, bool) or not isinstance(share, (int, float)):
        raise ArgumentTypeError(f"parts share must be a number in [0, 1], got {share!r}")
    if not 0.0 <= float(share) <= 1.0:
        raise ParameterError(f"parts share must be a number in [0, 1], got {share!r}")
    return float(share)


def _check_path(value: Any, what: str) -> None:
    import os

    if not isinstance(value, (str, os.PathLike)):
        raise ArgumentTypeError(f"{what} must be a folder path (str or pathlib.Path), got {type(value).__name__}"
                                f" {value!r:.60}")


def generate(category: str, seed: int = 0, texture_size: int = 512, parts=None, parts_share: float = 0.5,
             **overrides: Any) -> ArticulatedObject:
    """Generate one object: a pure function of ``(category, seed, overrides)``.

    Parameters
    ----------
    category : str
        One of :func:`list_categories`.
    seed : int
        Non-negative; the same seed gives the same object, byte for byte.
    texture_size : int
        Edge of every texture map in pixels (power of two, 16..4096).
    parts : path or :class:`~infmob_usd.partlib.Library`, optional
        A part library: where a part's label is in it, with probability ``parts_share`` the part is
        a library mesh placed by its support points (:mod:`infmob_usd.retrieval`).
    parts_share : float
        Probability in [0, 1] that a retrievable part is retrieved (with ``parts``); default 0.5.
        Checked always; without ``parts`` there is nothing to retrieve and it has no effect.
    **overrides
        Parameter values (see ``infmob params CATEGORY``); validated against the
        category schema.
    """
    cat = get_category(category)
    check_texture_size(texture_size)
    share = check_share(parts_share)
    retriever = None
    if parts is not None:
        from .partlib import Library, load_library
        from .retrieval import Retriever

        if not isinstance(parts, Library):
            _check_path(parts, "parts")
        retriever = Retriever(load_library(parts), share, category, seed)
    t0 = time.perf_counter()
    rng = streams(category, seed)
    params = cat.schema.sample(rng["params"], overrides)
    t1 = time.perf_counter()
    if retriever is None:
        bp = cat.build(params, rng["structure"], rng["geometry"])
    else:
        from .retrieval import ACTIVE

        token = ACTIVE.set(retriever)
        try:
            bp = cat.build(params, rng["structure"], rng["geometry"])
        finally:
            ACTIVE.reset(token)
    t2 = time.perf_counter()
    obj = assemble(bp, seed, rng["materials"], texture_size, params, cat.schema.validate(overrides))
    if retriever is not None:
        obj.retrieved = list(retriever.records)
        # share 0 keeps the procedural object byte for byte, metadata included
        obj.retrieval = retriever.summary() if share > 0 else None
    obj.timings = {"sampling": t1 - t0, "geometry": t2 - t1 + obj.timings["geometry"],
                   "textures": obj.timings["textures"]}
    return obj


def blueprint(category: str, seed: int = 0, **overrides: Any):
    """The world-space :class:`~infmob_usd.blueprint.Blueprint` of one object: its grown parts and
    declared joints, what :func:`generate` builds before the core's passes (ground, gaps, limits,
    masses) and before any texture or file. Cheap (milliseconds); used for statistics of the grammar
    (``infmob stats --grammar``). Same seed and overrides, same blueprint as ``generate`` starts from."""
    cat = get_category(category)
    rng = streams(category, seed)
    params = cat.schema.sample(rng["params"], overrides)
    return cat.build(params, rng["structure"], rng["geometry"])


def save(obj: ArticulatedObject, folder: str | Path, formats: str | list[str] | tuple[str, ...] | None = None
         ) -> Path:
    """Write ``obj`` into ``folder/<name>/`` (atomically: written under a temporary name, then
    renamed) and return that path.

    ``formats``: names from :data:`infmob_usd.layers.FORMATS` (``usd``, ``urdf``, ``mjcf``, ``glb``; ``isaac``: the USD
    in Isaac Sim's layout, instead of ``usd``)
    as a list or a comma string; default ``usd,urdf,mjcf``. Arguments of the wrong type raise
    :class:`~infmob_usd.errors.ArgumentTypeError`; a ``folder`` that is a symbolic link or not UTF-8,
    :class:`~infmob_usd.errors.OutputError`.
    """
    if not isinstance(obj, ArticulatedObject):
        raise ArgumentTypeError(f"save() needs an object made by generate(), got {type(obj).__name__} {obj!r:.60}")
    _check_path(folder, "folder")
    if formats is not None and not (isinstance(formats, str) or (
            isinstance(formats, (list, tuple)) and all(isinstance(f, str) for f in formats))):
        raise ArgumentTypeError(f"formats must be a comma string or a list of names (usd, urdf, mjcf, glb),"
                                f" got {formats!r:.60}")
    return write_object(obj, Path(folder), formats)


def assemble(bp, seed: int, materials_rng, texture_size: int = 512, params: dict | None = None,
             overrides: dict | None = None) -> ArticulatedObject:
    """Turn a world-space blueprint into an object: ground it, frame it, dress it.

    ``materials_rng`` draws one look per declared material slot (in declaration
    order, used or not, so optional parts never reshuffle the others).
    """
    from .materials import FAMILIES, sample_look, split_spec, texture_maps

    check_texture_size(texture_size)
    t0 = time.perf_counter()
    bp = physical.rest_on_ground(bp)
    looks = {slot: sample_look(family, materials_rng) for slot, family in bp.materials.items()}
    used = sorted({p.material for part in bp.parts.values() for p in part.pieces})
    missing = [slot for slot in used if slot not in bp.materials]
    if missing:
        raise ModelError(f"material slots {missing} are used by pieces but have no family in the blueprint")
    families = {slot: FAMILIES[split_spec(bp.materials[slot])[0]] for slot in used}
    densities = {slot: bp.densities.get(slot, f.density) for slot, f in families.items()}
    walls = {slot: f.wall for slot, f in families.items()}
    links, joints = build(bp, densities, walls)
    links, joints = physical.rest_on_stops(links, joints, densities, walls)
    links = physical.clear_bores(physical.ensure_gaps(links, joints), joints)
    links = physical.thicken_hulls(physical.square_rims(links, joints))
    joints = physical.limit_to_ground(links, joints)
    looks = {slot: looks[slot] for slot in used}
    t1 = time.perf_counter()
    textures = {slot: texture_maps(look, texture_size) for slot, look in looks.items()}
    t2 = time.perf_counter()
    obj = ArticulatedObject(
        category=bp.category,
        seed=int(seed),
        params=params or {},
        overrides=overrides or {},
        links=links,
        joints=joints,
        materials=looks,
        textures=textures,
        texture_size=texture_size,
        timings={"geometry": t1 - t0, "textures": t2 - t1},
    )
    obj = physical.keep_meeting_gaps(obj)  # before the clearance pass, which sweeps the final hulls
    obj = physical.limit_to_clearance(obj)
    obj = assign_drives(obj)  # after every limit is final: the stop budget depends on the range
    obj.interaction = annotate(obj)  # after the limits: the open state and the path read them
    obj.densities = densities  # slot -> kg/m^3 of its substrate (a painted slot on steel or on wood)
    obj.timings["geometry"] += time.perf_counter() - t2
    return obj
