"""Tests of material families, look sampling and tileable PBR texture synthesis."""

from __future__ import annotations

import dataclasses
import json
import math

import cv2
import numpy as np
import pytest

from infmob_usd.materials import (
    FAMILIES,
    LOOKS_PER_VARIANT,
    TEXTURE_MAPS,
    Family,
    Look,
    encode_png,
    library,
    library_look,
    sample_look,
    synthesize,
    texture_maps,
)
from infmob_usd.materials.families import split_spec, srgb_to_linear
from infmob_usd.materials.synth import height_to_normal, periodic_noise

REQUIRED_FAMILIES = (
    "wood",
    "painted",
    "brushed_metal",
    "plastic",
    "glass",
    "ceramic",
    "rubber",
    "chrome",
    "enamel",
    "fabric",
)
SIZE = 128


def _look(family: str, seed: int = 0) -> Look:
    return sample_look(family, np.random.default_rng(seed))


def _edge_vs_interior(img: np.ndarray, axis: int) -> tuple[float, float]:
    """Mean abs difference across the wrap-around edge, and the largest one between
    neighbouring interior columns (axis=1) or rows (axis=0)."""
    a = np.moveaxis(img.astype(np.float64), axis, 0)
    wrap = float(np.abs(a[0] - a[-1]).mean())
    interior = np.abs(np.diff(a, axis=0)).reshape(a.shape[0] - 1, -1).mean(axis=1)
    return wrap, float(interior.max())


def _assert_seamless(img: np.ndarray, what: str) -> None:
    for axis in (0, 1):
        wrap, interior = _edge_vs_interior(img, axis)
        assert wrap <= 1.25 * interior + 0.5, f"{what}: seam along axis {axis}: {wrap} vs {interior}"


def test_required_families_exist_with_plausible_data():
    assert set(REQUIRED_FAMILIES) <= set(FAMILIES)
    for name, fam in FAMILIES.items():
        assert isinstance(fam, Family) and fam.name == name
        assert 100.0 <= fam.density <= 10000.0
        assert fam.palette and 0.0 <= fam.roughness[0] <= fam.roughness[1] <= 1.0
    assert FAMILIES["brushed_metal"].density == FAMILIES["enamel"].density == 7850.0
    assert FAMILIES["glass"].density == 2500.0
    assert 600.0 <= FAMILIES["wood"].density <= 700.0


@pytest.mark.parametrize("family", REQUIRED_FAMILIES)
def test_sample_look_within_family_ranges(family):
    fam = FAMILIES[family]
    rng = np.random.default_rng(1)
    for _ in range(20):
        look = sample_look(family, rng)
        assert look.family == family
        assert look.variant in {v for v, _ in fam.palette}
        assert len(look.base_color) == 3 and all(0.0 <= c <= 1.0 for c in look.base_color)
        assert fam.roughness[0] <= look.roughness <= fam.roughness[1]
        lo, hi = dict(fam.variant_opacity).get(look.variant, fam.opacity)
        assert lo <= look.opacity <= hi
        assert look.metallic == fam.metallic
        assert isinstance(look.noise_seed, int) and 0 <= look.noise_seed < 2**53


def test_glass_is_translucent_and_others_opaque():
    for family in REQUIRED_FAMILIES:
        opacity = _look(family, 3).opacity
        if family == "glass":
            assert 0.05 <= opacity <= 0.95
        else:
            assert opacity == 1.0
    # window glass is nearly clear, bottle glass tinted and denser, a bulb frosted
    clear = [library_look("glass", "clear", k).opacity for k in range(16)]
    green = [library_look("glass", "bottle_green", k).opacity for k in range(16)]
    frosted = [library_look("glass", "frosted", k).opacity for k in range(16)]
    assert max(clear) < 0.2 < 0.5 < min(green) <= max(green) < min(frosted) < 1.0


def test_look_is_hashable_and_json_roundtrips():
    look = _look("wood", 5)
    assert hash(look) == hash(_look("wood", 5))
    d = json.loads(json.dumps(look.to_dict()))
    assert Look.from_dict(d) == look


@pytest.mark.parametrize("family", REQUIRED_FAMILIES)
def test_synthesize_shapes_and_dtypes(family):
    maps = synthesize(_look(family), SIZE)
    assert tuple(maps) == TEXTURE_MAPS
    assert maps["basecolor"].shape == (SIZE, SIZE, 3)
    assert maps["roughness"].shape == (SIZE, SIZE)
    assert maps["normal"].shape == (SIZE, SIZE, 3)
    assert all(m.dtype == np.uint8 for m in maps.values())


@pytest.mark.parametrize("family", REQUIRED_FAMILIES)
def test_smallest_size_works(family):
    maps = synthesize(_look(family), 16)
    assert maps["normal"].shape == (16, 16, 3)
    assert (maps["normal"][..., 2] > 128).all()


@pytest.mark.parametrize("family", REQUIRED_FAMILIES)
def test_maps_tile_seamlessly(family):
    for seed in range(2):
        maps = synthesize(_look(family, seed), 256)
        for key, img in maps.items():
            _assert_seamless(img, f"{family}/{key}")


def test_seam_check_detects_a_seam():
    ramp = np.tile(np.linspace(0, 255, 64), (64, 1))
    noise = cv2.GaussianBlur(np.random.default_rng(0).random((64, 64)) * 255, (0, 0), 3)
    for img in (ramp, noise):
        wrap, interior = _edge_vs_interior(img, 1)
        assert wrap > 1.25 * interior + 0.5


def test_periodic_noise_is_periodic_unit_std_and_size_consistent():
    comps = [(1.0, 8.0, 8.0)]
    big = periodic_noise(42, "test", 512, comps)
    small = periodic_noise(42, "test", 128, comps)
    # The pattern does not depend on the resolution it is sampled at.
    np.testing.assert_allclose(big[::4, ::4], small, atol=1e-5)
    assert big.dtype == np.float32 and big.shape == (512, 512)
    assert abs(float(big.mean())) < 1e-4
    assert 0.8 < float(big.std()) < 1.2
    _assert_seamless(big, "noise")
    assert not np.allclose(big, periodic_noise(42, "other", 512, comps))


@pytest.mark.parametrize("family", REQUIRED_FAMILIES)
def test_deterministic_png_bytes(family):
    a = synthesize(sample_look(family, np.random.default_rng(123)), SIZE)
    b = synthesize(sample_look(family, np.random.default_rng(123)), SIZE)
    c = synthesize(sample_look(family, np.random.default_rng(124)), SIZE)
    for key in TEXTURE_MAPS:
        assert encode_png(a[key]) == encode_png(b[key])
    assert encode_png(a["basecolor"]) != encode_png(c["basecolor"])
    assert encode_png(a["normal"]) != encode_png(c["normal"])


@pytest.mark.parametrize("family", REQUIRED_FAMILIES)
def test_basecolor_and_roughness_means_match_look(family):
    for seed in range(3):
        look = _look(family, seed)
        maps = synthesize(look, 256)
        linear = srgb_to_linear(maps["basecolor"] / 255.0)
        mean = linear.reshape(-1, 3).mean(axis=0)
        np.testing.assert_allclose(mean, look.base_color, atol=0.01, rtol=0.03)
        assert abs(maps["roughness"].mean() / 255.0 - look.roughness) < 0.02


@pytest.mark.parametrize("family", REQUIRED_FAMILIES)
def test_maps_vary_around_the_mean(family):
    maps = synthesize(_look(family, 9), 256)
    assert maps["basecolor"].astype(float).std(axis=(0, 1)).max() > 0.0
    assert maps["normal"].std() > 0.0


def test_wood_varies_more_than_paint():
    wood = synthesize(_look("wood", 2), 256)["basecolor"].astype(float)
    paint = synthesize(_look("painted", 2), 256)["basecolor"].astype(float)
    assert wood.std(axis=(0, 1)).mean() > 4.0 * paint.std(axis=(0, 1)).mean()


@pytest.mark.parametrize("family", REQUIRED_FAMILIES)
def test_normal_map_is_mostly_flat_and_upward(family):
    normal = synthesize(_look(family, 4), 256)["normal"]
    mean = normal.reshape(-1, 3).mean(axis=0)
    assert abs(mean[0] - 127.5) < 3.0 and abs(mean[1] - 127.5) < 3.0
    assert mean[2] > 235.0
    assert (normal[..., 2] > 128).all()
    # Decoded normals are unit length up to 8-bit quantisation.
    n = normal.astype(np.float64) / 127.5 - 1.0
    np.testing.assert_allclose(np.linalg.norm(n, axis=-1), 1.0, atol=0.02)


def test_normal_map_follows_opengl_convention():
    size = 64
    x = np.arange(size) / size
    flat = height_to_normal(np.zeros((size, size)), 0.1)
    assert (flat == (128, 128, 255)).all()
    # Height rising towards +U (to the right) tilts the normal towards -U: red < 128.
    ramp_u = np.tile(np.sin(2 * np.pi * x), (size, 1))
    n = height_to_normal(ramp_u, 0.3)
    assert n[:, 0, 0].max() < 128 and n[:, size // 2, 0].min() > 128
    # Height rising towards +V (up the image, decreasing row) tilts it towards -V: green < 128.
    ramp_v = np.tile(np.sin(2 * np.pi * x)[::-1, None], (1, size))
    n = height_to_normal(ramp_v, 0.3)
    assert n[size - 1, :, 1].max() < 128 and n[size // 2, :, 1].min() > 128


def test_metallic_by_family_is_a_constant_not_a_map():
    assert "metallic" not in TEXTURE_MAPS
    for family in ("brushed_metal", "chrome"):
        assert _look(family).metallic == 1.0
    for family in ("wood", "plastic", "painted", "enamel", "fabric"):
        assert _look(family).metallic == 0.0


def test_roughness_ordering_between_families():
    chrome = synthesize(_look("chrome"), SIZE)["roughness"].mean()
    rubber = synthesize(_look("rubber"), SIZE)["roughness"].mean()
    assert chrome < 0.2 * 255 < 0.75 * 255 < rubber


def test_unknown_family_raises_with_valid_names():
    with pytest.raises(ValueError, match="unknown material family 'marble'.*wood"):
        sample_look("marble", np.random.default_rng(0))
    look = dataclasses.replace(_look("wood"), family="marble")
    with pytest.raises(ValueError, match="valid families"):
        synthesize(look, SIZE)


def test_sample_look_requires_a_generator():
    with pytest.raises(TypeError, match="Generator"):
        sample_look("wood", 0)


@pytest.mark.parametrize("size", [0, 8, 15, 100, 8192, 512.0, True, "512"])
def test_bad_size_raises(size):
    with pytest.raises(ValueError, match=r"power of two in \[16, 4096\]"):
        synthesize(_look("plastic"), size)


def test_encode_png_roundtrip_rgb_and_grey():
    rng = np.random.default_rng(0)
    rgb = rng.integers(0, 256, (20, 30, 3), dtype=np.uint8)
    grey = rng.integers(0, 256, (20, 30), dtype=np.uint8)
    decoded = cv2.imdecode(np.frombuffer(encode_png(rgb), np.uint8), cv2.IMREAD_UNCHANGED)
    np.testing.assert_array_equal(decoded[..., ::-1], rgb)  # stored as RGB, not BGR
    decoded = cv2.imdecode(np.frombuffer(encode_png(grey), np.uint8), cv2.IMREAD_UNCHANGED)
    np.testing.assert_array_equal(decoded, grey)
    assert encode_png(rgb).startswith(b"\x89PNG")


def test_encode_png_rejects_bad_images():
    with pytest.raises(ValueError, match="uint8"):
        encode_png(np.zeros((4, 4, 3), dtype=np.float32))
    with pytest.raises(ValueError, match="uint8"):
        encode_png(np.zeros((4, 4, 4), dtype=np.uint8))


def test_variant_restricted_family_spec():
    rng = np.random.default_rng(0)
    variants = {sample_look("plastic:black|dark_grey", rng).variant for _ in range(20)}
    assert variants == {"black", "dark_grey"}
    with pytest.raises(ValueError, match="no variant"):
        sample_look("plastic:mauve", rng)


# --------------------------------------------------------------------------- look library and cache


def test_looks_come_from_a_finite_library():
    assert len(library()) == LOOKS_PER_VARIANT * sum(len(f.palette) for f in FAMILIES.values())
    assert len(set(library())) == len(library())  # every look distinct
    rng = np.random.default_rng(7)
    drawn = {sample_look("plastic:black|white", rng) for _ in range(400)}
    assert drawn <= set(library("plastic:black|white"))
    assert len(drawn) > LOOKS_PER_VARIANT  # both variants, many indices
    look = library_look("wood", "oak", 3)
    assert look == library_look("wood", "oak", 3) and look.index == 3 and look.variant == "oak"
    assert look != library_look("wood", "oak", 4)


@pytest.mark.parametrize("args, match", [
    (("wood", "pine", 0), "no variant 'pine'.*oak"),
    (("wood", "oak", LOOKS_PER_VARIANT), "look index"),
    (("wood", "oak", -1), "look index"),
    (("marble", "oak", 0), "unknown material family"),
])
def test_library_look_rejects_bad_keys(args, match):
    with pytest.raises(ValueError, match=match):
        library_look(*args)


def test_texture_cache_serves_the_same_bytes_and_survives_corruption(tmp_path, monkeypatch):
    from infmob_usd.materials import cache as lib

    monkeypatch.setenv("INFMOB_USD_CACHE", str(tmp_path))
    monkeypatch.setattr(lib, "_memory", type(lib._memory)())
    look = library_look("fabric", "teal", 5)
    fresh = lib.make_maps(look, 32)
    first = texture_maps(look, 32)
    assert first == fresh and tuple(first) == TEXTURE_MAPS
    files = sorted((tmp_path / "textures").rglob("*.png"))
    assert len(list((tmp_path / "textures").rglob("*.sha256.json"))) == 1
    assert len(files) == len(TEXTURE_MAPS) and all(f.read_bytes() in fresh.values() for f in files)
    lib._memory.clear()
    files[0].write_bytes(files[0].read_bytes()[:100])  # a torn file: regenerated, not served
    assert texture_maps(look, 32) == fresh
    assert all(lib._whole_png(f.read_bytes()) for f in files)
    lib._memory.clear()
    data = bytearray(files[1].read_bytes())  # 16 flipped bytes inside: header and end intact
    data[60:76] = bytes(b ^ 0xFF for b in data[60:76])
    files[1].write_bytes(bytes(data))
    assert lib._whole_png(files[1].read_bytes())
    assert texture_maps(look, 32) == fresh  # the hash check refuses it: made again, and the entry rebuilt
    assert files[1].read_bytes() in fresh.values()
    lib._memory.clear()
    monkeypatch.setenv("INFMOB_USD_CACHE", "off")
    assert lib.cache_dir() is None and texture_maps(look, 32) == fresh


def test_texture_memory_cache_is_bounded(tmp_path, monkeypatch):
    from infmob_usd.materials import cache as lib

    monkeypatch.setenv("INFMOB_USD_CACHE", "off")
    monkeypatch.setattr(lib, "_memory", type(lib._memory)())
    monkeypatch.setattr(lib, "_memory_bytes", 0)
    monkeypatch.setattr(lib, "MEMORY_BUDGET", 40_000)
    for k in range(8):
        texture_maps(library_look("wood", "oak", k), 64)
    assert lib._memory_bytes <= 40_000 or len(lib._memory) == 1
    assert 0 < len(lib._memory) < 8


def test_editing_an_objects_maps_never_edits_the_cache(monkeypatch):
    from infmob_usd.materials import cache as lib

    monkeypatch.setenv("INFMOB_USD_CACHE", "off")
    look = library_look("ceramic", "white", 1)
    first = texture_maps(look, 16)
    first["basecolor"] = b"edited"
    del first["normal"]
    again = texture_maps(look, 16)
    assert again == lib.make_maps(look, 16)


def test_build_fills_the_cache_once(tmp_path, monkeypatch):
    from infmob_usd.materials import cache as lib

    monkeypatch.setenv("INFMOB_USD_CACHE", str(tmp_path))
    first = lib.build(16, "rubber:black", workers=1)
    assert first["looks"] == first["made"] == LOOKS_PER_VARIANT and first["megabytes"] > 0
    again = lib.build(16, "rubber:black", workers=2)
    assert again["made"] == 0 and again["cache"] == first["cache"]
    look = library_look("rubber", "black", 3)
    assert lib._disk_maps(look, 16) == (lib.make_maps(look, 16), False)


def test_every_family_has_contact_properties():
    """Every material family can be bound as a physics material (a new family without them broke the USD writer)."""
    from infmob_usd.materials import FAMILIES
    from infmob_usd.materials.families import CONTACT

    assert set(FAMILIES) == set(CONTACT)


def test_cold_bench_makes_every_object_its_maps_from_an_empty_cache(tmp_path, monkeypatch):
    """`infmob bench --cold`: each timed object starts with nothing cached (disk or memory), so each
    makes every map it uses into its own fresh folder, and the report prints without throughput runs."""
    from infmob_usd.api import generate
    from infmob_usd.materials import cache as lib
    from infmob_usd.validate.bench import _stage_times, format_bench, run_bench

    monkeypatch.setenv("INFMOB_USD_CACHE", str(tmp_path / "warm"))
    used = [len(generate("door", seed=seed, texture_size=16).textures) for seed in range(2)]
    _stage_times(["door"], 2, 16, tmp_path, cold=True)  # leaves the variable at the last cold folder
    for seed in range(2):
        made = list((tmp_path / "cold" / f"door_{seed}").rglob("*.png"))
        assert len(made) == used[seed] * len(lib.TEXTURE_MAPS)
    res = run_bench(["door"], 1, 16, 1, cold=True)
    assert res["texture_library"] is None and res["objects_per_s_1_worker"] is None
    assert "cold cache" in format_bench(res)


def _lab(hex_colour: str) -> np.ndarray:
    rgb = np.array([[[int(hex_colour[i:i + 2], 16) for i in (1, 3, 5)]]], np.float32) / 255.0
    return cv2.cvtColor(rgb, cv2.COLOR_RGB2Lab)[0, 0]


def test_metals_match_measured_reflectance():
    # F0 from complex IOR (physicallybased.info): stainless 0.669/0.639/0.598, chromium 0.654/0.685/0.701
    for family, f0 in (("brushed_metal", (0.669, 0.639, 0.598)), ("chrome", (0.654, 0.685, 0.701))):
        for variant, _ in FAMILIES[family].palette:
            look = library_look(family, variant, 0)
            assert np.abs(np.asarray(look.base_color) - f0).max() < 0.09, (family, variant, look.base_color)


def test_wood_is_not_saturated():
    # finished hardwoods stay below C* ~30; more reads as orange paint
    for variant, hex_colour in FAMILIES["wood"].palette:
        _, a, b = _lab(hex_colour)
        assert math.hypot(a, b) < 30.0, variant


def test_brushed_steel_has_no_wood_like_bands():
    # brushing lines are sub-millimetre and barely tint the steel: bands 1-17 cm wide across the lines
    # (the 0.5 m tile's rows averaged along them) stay under 0.3 % of the brightness (coarse streaks,
    # which read as wood grain on a fridge door, were 0.4-0.8 %)
    for variant, _ in FAMILIES["brushed_metal"].palette:
        for index in (0, 5, 10):
            grey = synthesize(library_look("brushed_metal", variant, index), 512)["basecolor"].mean(axis=2)
            spec = np.fft.rfft(grey.mean(axis=1))
            spec[:3] = 0.0
            spec[50:] = 0.0
            assert np.fft.irfft(spec, grey.shape[0]).std() / grey.mean() < 0.003, (variant, index)


def test_oven_cavity_enamel_is_dark():
    from categories.oven import MATERIALS

    _, variants = split_spec(MATERIALS["interior"])
    for variant in variants:
        lightness, a, b = _lab(dict(FAMILIES["enamel"].palette)[variant])
        assert lightness < 35.0 and math.hypot(a, b) < 15.0, variant


@pytest.mark.parametrize("size", [256, 512])
def test_moulded_plastic_is_one_even_colour_not_blotchy(size):
    """An injection-moulded shell (a mouse, a remote, a phone) is one colour with a sub-millimetre grain:
    neither its colour nor its normal map may show the centimetre blotches that read as dough."""
    for variant in ("white", "light_grey", "blue"):
        for index in range(0, LOOKS_PER_VARIANT, 5):
            maps = synthesize(library_look("plastic", variant, index), size)
            lum = srgb_to_linear(maps["basecolor"].astype(np.float64) / 255.0).mean(axis=2)
            assert lum.std() / lum.mean() < 0.02, (variant, index)
            n = maps["normal"].astype(np.float64) / 127.5 - 1.0
            tilt = np.hypot(n[..., 0], n[..., 1]) / np.maximum(n[..., 2], 1e-6)
            assert np.sqrt((tilt**2).mean()) < 0.012, (variant, index)
