"""Synthesis of seamlessly tiling PBR texture maps for a sampled :class:`Look`.

All maps cover one UV unit and tile with wrap = repeat.  Tiling is exact by
construction: every random field is built in the Fourier domain at integer
frequencies (cycles per UV unit) and transformed with an inverse real FFT, and
every spatial filter (Sobel) runs on a wrap-padded copy.  U runs along image
columns (left to right) and V along image rows (bottom to top, i.e. row 0 is
V = 1), the usual texture convention.

Randomness comes only from ``numpy.random.Generator`` objects seeded with
``(look.noise_seed, field name, octave)``.  A field's Fourier coefficient at a
given integer frequency does not depend on the output size, so the maps of one
look at 256 and at 1024 px show the same pattern (the smaller one simply lacks
the finest detail).

Output conventions (see :func:`synthesize`): basecolor is sRGB-encoded RGB,
roughness is a linear grey, normal is an OpenGL (+Y up)
tangent-space normal map.
"""

from __future__ import annotations

import math
import zlib
from collections.abc import Callable, Sequence

import cv2
import numpy as np

from .families import FAMILIES, WOOD_SPECIES, Look

__all__ = ["TEXTURE_MAPS", "TILE_METRES", "encode_png", "height_to_normal", "periodic_noise", "synthesize"]

TEXTURE_MAPS = ("basecolor", "roughness", "normal")
"""The maps of a look.  Metallic is constant per family, so it is a material constant
(``Pm`` in the MTL, the ``metallic`` input in USD) rather than a texture."""

MIN_SIZE = 16
MAX_SIZE = 4096

TILE_METRES = 0.5
"""Metres of surface one texture repeat covers, for every family (one texel density:
512 px maps give ~1 mm texels).  Family scales are per metre and are converted with it;
the geometry kernel lays UVs at the same density (``infmob_usd.shading.UV_TILE``)."""

Component = tuple[float, float, float]
"""``(weight, sigma_u, sigma_v)``: one anisotropic Gaussian of a noise amplitude
spectrum, with standard deviations in cycles per UV unit along U and V."""

# zlib level 1 with run-length matching: half the time of level 3 and, on these noise
# textures, smaller files (measured on 15 maps of 5 families at 512 px: 222 vs 454 ms, 2.37 vs 2.52 MB)
_PNG_PARAMS = [cv2.IMWRITE_PNG_COMPRESSION, 1, cv2.IMWRITE_PNG_STRATEGY, cv2.IMWRITE_PNG_STRATEGY_RLE]


def _srgb_encode_lut(n: int) -> np.ndarray:
    """Lookup table mapping ``round(linear * (n - 1))`` to 8-bit sRGB, shape (n,)."""
    c = np.linspace(0.0, 1.0, n)
    srgb = np.where(c <= 0.0031308, 12.92 * c, 1.055 * c ** (1.0 / 2.4) - 0.055)
    return np.rint(srgb * 255.0).astype(np.uint8)


_SRGB_LUT = _srgb_encode_lut(1 << 16)


# --------------------------------------------------------------------------- noise


def _gauss_sum(a: float, b: float, k_max: int) -> float:
    """``sum_{|k| <= k_max} exp(-k^2 / (2 a^2)) * exp(-k^2 / (2 b^2))``."""
    k = np.arange(-k_max, k_max + 1, dtype=np.float64)
    return float(np.exp(-0.5 * k * k * (1.0 / (a * a) + 1.0 / (b * b))).sum())


def periodic_noise(
    seed: int, name: str, size: int, components: Sequence[Component]
) -> np.ndarray:
    """Seamlessly tiling Gaussian noise with a sum-of-Gaussians amplitude spectrum.

    The amplitude at integer frequency ``(ku, kv)`` (cycles per UV unit) is
    ``sum(w * exp(-ku**2 / (2 su**2) - kv**2 / (2 sv**2)) for w, su, sv in components)``;
    negative weights give band-pass (difference of Gaussians) spectra.
    Frequencies beyond four times the largest sigma of their axis are dropped,
    as is everything at or above the Nyquist frequency of ``size``.

    Parameters
    ----------
    seed : int
        Noise seed (``Look.noise_seed``).
    name : str
        Field name; different names give independent fields.
    size : int
        Output side length in pixels (even).
    components : sequence of (float, float, float)
        ``(weight, sigma_u, sigma_v)`` spectrum components.

    Returns
    -------
    numpy.ndarray
        float32, shape (size, size), zero mean; its expected standard deviation
        is 1 when ``size`` resolves the whole spectrum and smaller otherwise.
    """
    # The spectrum is kept on the rectangle |ku| <= ku_ref, |kv| <= kv_ref (4 sigma).
    ku_ref = math.ceil(4.0 * max(su for _, su, _ in components))
    kv_ref = math.ceil(4.0 * max(sv for _, _, sv in components))
    half = size // 2
    ku_cap, kv_cap = min(ku_ref, half - 1), min(kv_ref, half - 1)
    cols = ku_cap + 1
    tag = zlib.crc32(name.encode("utf-8"))
    # Octave o holds the frequencies with 2**o <= max(|ku|, |kv|) < 2**(o + 1) (octave 0
    # also holds DC), drawn from its own generator as one block whose shape depends on
    # the octave and the spectrum only, so coefficients do not depend on size.  Writing
    # high octaves first lets the lower ones overwrite the inner part of each block.
    # The row length half + 1 (not a power of two) keeps the column FFTs cache-friendly.
    spec = np.zeros((size, half + 1), dtype=np.complex64)
    for octave in reversed(range(max(ku_cap, kv_cap).bit_length())):
        hi = 2 << octave
        hu, hv = min(hi, ku_ref + 1), min(hi, kv_ref + 1)
        rng = np.random.default_rng(np.random.SeedSequence((seed, tag, octave)))
        draw = rng.standard_normal((2 * hv, hu, 2), dtype=np.float32).view(np.complex64)
        spec[np.arange(-hv, hv) % size, : min(hu, cols)] = draw[:, :cols, 0]
    spec[kv_cap + 1 : size - kv_cap] = 0.0
    spec[0, 0] = 0.0
    # irfft keeps only the real part of the ku = 0 column: restore its variance.
    spec[:, 0] *= np.float32(math.sqrt(2.0))

    ku = np.arange(cols, dtype=np.float32)
    kv = (np.fft.fftfreq(size) * size).astype(np.float32)
    amp = np.zeros((size, cols), dtype=np.float32)
    variance = 0.0
    for w, su, sv in components:
        amp += np.float32(w) * np.outer(np.exp(-0.5 * (kv / sv) ** 2), np.exp(-0.5 * (ku / su) ** 2))
        for w2, su2, sv2 in components:
            variance += w * w2 * _gauss_sum(su, su2, ku_ref) * _gauss_sum(sv, sv2, kv_ref)
    variance -= sum(w for w, _, _ in components) ** 2  # the excluded DC term
    # Inverse transform over V (non-zero columns only), then a real one over U.  Both
    # divide by size (numpy's default norm, much faster here than norm="forward").
    spec[:, :cols] = np.fft.ifft(spec[:, :cols] * amp, axis=0)
    field = np.fft.irfft(spec, n=size, axis=1)
    field *= np.float32(size * size / math.sqrt(2.0 * max(variance, 1e-12)))
    return field


# --------------------------------------------------------------------------- normals


def height_to_normal(height: np.ndarray, bump: float) -> np.ndarray:
    """Encode a tiling height field as an OpenGL tangent-space normal map.

    Parameters
    ----------
    height : numpy.ndarray
        Height field, shape (h, w), any scale (it is rescaled).
    bump : float
        Target RMS slope (tangent of the typical tilt) of the surface.

    Returns
    -------
    numpy.ndarray
        uint8, shape (h, w, 3), RGB = ``round(127.5 * n + 127.5)`` with
        ``n = normalize(-dh/du, -dh/dv, 1)``; +V points up the image (OpenGL),
        a flat surface is (128, 128, 255).
    """
    padded = np.pad(height.astype(np.float32), 1, mode="wrap")
    du = cv2.Sobel(padded, cv2.CV_32F, 1, 0, ksize=3)[1:-1, 1:-1]
    dv = -cv2.Sobel(padded, cv2.CV_32F, 0, 1, ksize=3)[1:-1, 1:-1]  # rows run down, V up
    rms = float(np.sqrt(np.mean(du * du + dv * dv)))
    gain = np.float32(bump / rms if rms > 1e-12 else 0.0)
    du *= gain
    dv *= gain
    half_inv_len = np.float32(127.5) / np.sqrt(du * du + dv * dv + np.float32(1.0))
    # 127.5 * n + 127.5, rounded half up by adding 0.5 and truncating.
    normal = np.empty(height.shape + (3,), dtype=np.uint8)
    normal[..., 0] = 128.0 - du * half_inv_len
    normal[..., 1] = 128.0 - dv * half_inv_len
    normal[..., 2] = 128.0 + half_inv_len
    return normal


# --------------------------------------------------------------------------- styles
#
# A style maps (look, size) to three float32 fields of shape (size, size):
#   tint      - positive colour field, (size, size) grey or (size, size, 3); it is
#               rescaled per channel so that its mean equals look.base_color;
#   roughness - roughly unit-std variation, scaled by look.roughness_variation;
#   height    - height field for the normal map (rescaled to look.bump).

Fields = tuple[np.ndarray, np.ndarray, np.ndarray]


def _smoothstep(lo: float, hi: float, x: np.ndarray) -> np.ndarray:
    x = np.clip((x - lo) / (hi - lo), 0.0, 1.0)
    return x * x * (3.0 - 2.0 * x)


def _ring_profile(t: np.ndarray) -> np.ndarray:
    """Latewood density over one growth ring, ``t`` in [0, 1): light earlywood darkening
    into a narrow latewood band that falls off quickly into the next ring."""
    return _smoothstep(0.45, 0.9, t) - _smoothstep(0.92, 1.0, t)


_RING_GRID = _ring_profile(np.linspace(0.0, 1.0, 4096, endpoint=False))
_RING_MEAN, _RING_STD = float(_RING_GRID.mean()), float(_RING_GRID.std())


def _wood(look: Look, size: int) -> Fields:
    """Flat-sawn boards glued edge to edge, grain along U, at real scale.

    The tile is cut into 3-5 boards across V (seams between them).  Each board is a flat
    slice through a log: at a point ``x`` along the board and ``y`` across it, the growth
    ring crossed is ``sqrt((y - pith)**2 + depth(x)**2) / ring width``, where the slice's
    depth below the pith wanders slowly along the board, which draws the cathedral arches
    of flat-sawn figure and straight lines near the edges.  Pores are short dark streaks
    along the grain, gathered in the earlywood band of ring-porous species; oak adds ray
    flecks (:data:`~infmob_usd.materials.families.WOOD_SPECIES`).  Colour carries only
    albedo (ring, pore, board and fibre differences), never shading.
    """
    seed = look.noise_seed
    species = WOOD_SPECIES.get(look.variant, WOOD_SPECIES["maple"])
    rng = np.random.default_rng(np.random.SeedSequence((seed, zlib.crc32(b"wood.boards"))))
    boards = max(1, round(TILE_METRES / rng.uniform(0.1, 0.17)))
    width = TILE_METRES / boards
    # pith offset across each board, m: mostly towards an edge, so the rings draw open arches
    pith = rng.choice([-1.0, 1.0], boards) * rng.uniform(0.2, 0.75, boards) * width
    depth0 = rng.uniform(0.05, 0.14, boards)  # slice depth below the pith, m
    amp = rng.uniform(0.3, 1.0, (boards, 2)) * np.array([0.012, 0.004])  # its wander along the board
    turn = rng.uniform(0.0, 1.0, (boards, 2))
    spacing = 1.0 / (look.scale * rng.uniform(0.85, 1.2, boards))  # ring width, m
    shift = rng.normal(0.0, 0.45, boards)  # board-to-board colour difference
    ring0 = rng.uniform(0.0, 1.0, boards)

    u = (np.arange(size, dtype=np.float32) + 0.5) / size
    v = (np.arange(size, dtype=np.float32) + 0.5) / size
    b = np.minimum((v * boards).astype(np.int64), boards - 1)  # board of each row
    y = ((v * boards - b - 0.5) * width - pith[b]).astype(np.float32)  # m from the pith line, per row
    wander = (amp[b, 0:1] * np.sin(2 * np.pi * (u[None, :] + turn[b, 0:1]))
              + amp[b, 1:2] * np.sin(2 * np.pi * (2 * u[None, :] + turn[b, 1:2])))
    depth = (depth0[b, None] + wander).astype(np.float32)
    warp = periodic_noise(seed, "wood.warp", size, [(1.0, 3.0, 10.0)])
    radius = np.sqrt(y[:, None] ** 2 + depth * depth) + np.float32(0.001) * warp
    phase = radius / spacing[b, None].astype(np.float32) + ring0[b, None].astype(np.float32)
    t = phase - np.floor(phase)
    latewood = (_ring_profile(t) - _RING_MEAN) / _RING_STD
    earlywood = 1.0 - _smoothstep(0.05, 0.3, t)  # the band where ring-porous woods carry big pores

    k = TILE_METRES  # cycles per metre -> per tile
    fibre = periodic_noise(seed, "wood.fibre", size, [(1.0, 10.0 * k, 180.0 * k)])
    pore_noise = periodic_noise(seed, "wood.pores", size, [(1.0, 60.0 * k, 600.0 * k)])
    pores = np.maximum(pore_noise - 1.0, 0.0) * (
        1.0 - species["ring_porous"] + 3.0 * species["ring_porous"] * earlywood)
    pores *= species["pores"]
    rays = 0.0
    if species["rays"] > 0:
        ray_noise = periodic_noise(seed, "wood.rays", size, [(1.0, 25.0 * k, 500.0 * k)])
        rays = species["rays"] * np.maximum(ray_noise - 2.0, 0.0)
    # seams: a thin line where two boards meet (about 0.6 mm, at least a texel)
    edge = np.abs(v * boards - np.rint(v * boards)) * width  # m to the nearest board edge, per row
    seam = np.exp(-((edge / max(0.0006, 0.6 * TILE_METRES / size)) ** 2)).astype(np.float32)[:, None]

    figure = periodic_noise(seed, "wood.figure", size, [(1.0, 2.0, 12.0)])  # mineral streaks, colour runs
    dark = (species["rings"] * 0.6 * latewood + shift[b, None].astype(np.float32) + 0.45 * fibre
            + 0.3 * figure + 1.2 * pores + 1.0 * rays + 3.0 * seam)
    ln_base = np.log(np.maximum(np.asarray(look.base_color, dtype=np.float32), 1e-3))
    # Darker wood is also more saturated: channels darken in proportion to -ln(base).
    tint = np.exp(-look.color_variation * dark[..., None] * (0.5 - ln_base))
    roughness = 0.9 * pores + 1.5 * seam - 0.3 * latewood + 0.3 * fibre
    height = 0.35 * fibre - 0.9 * pores - 2.5 * seam + 0.15 * latewood
    return tint, roughness, height


def _brushed(look: Look, size: int) -> Fields:
    """Fine abrasive lines along U, shared by colour, roughness and normal.

    Only line-scale detail (and a faint hint of coarser lines, a third of the line frequency):
    bands a centimetre wide, as coarse streaks give, read as wood grain on a steel panel."""
    seed, s = look.noise_seed, look.scale * TILE_METRES
    su = s / look.anisotropy
    streaks = periodic_noise(
        seed, "brushed.streaks", size, [(1.0, su, s), (0.25, 0.5 * su, 0.33 * s)]
    )
    low = periodic_noise(seed, "brushed.low", size, [(1.0, 2.0, 2.0)])
    tint = 1.0 + look.color_variation * (streaks + 0.4 * low)
    return tint, streaks, streaks


def _coating(look: Look, size: int) -> Fields:
    """Smooth coating: faint low-frequency mottling plus band-pass orange peel."""
    seed, s = look.noise_seed, look.scale * TILE_METRES
    su = s / look.anisotropy
    low = periodic_noise(seed, "coating.low", size, [(1.0, 2.5, 2.5)])
    peel = periodic_noise(seed, "coating.peel", size, [(1.0, su, s), (-1.0, 0.5 * su, 0.5 * s)])
    tint = 1.0 + look.color_variation * (low + 0.3 * peel)
    return tint, 0.7 * (low + peel), peel


def _speckle(look: Look, size: int) -> Fields:
    """Fine isotropic speckle over a faint low-frequency variation."""
    seed, s = look.noise_seed, look.scale * TILE_METRES
    speck = periodic_noise(seed, "speckle.fine", size, [(1.0, s / look.anisotropy, s)])
    low = periodic_noise(seed, "speckle.low", size, [(1.0, 3.0, 3.0)])
    detail = 0.9 * speck + 0.3 * low
    return 1.0 + look.color_variation * detail, detail, speck


def _woven(look: Look, size: int) -> Fields:
    """Plain weave: warp threads along V, weft threads along U, with fibre noise."""
    seed = look.noise_seed
    n = 2 * max(2, round(look.scale * TILE_METRES / 2.0))  # threads per UV unit; even, so it tiles
    across, along = 2.0 * n, 2.0 * n / look.anisotropy
    fib_warp = periodic_noise(seed, "woven.warp", size, [(1.0, across, along)])
    fib_weft = periodic_noise(seed, "woven.weft", size, [(1.0, along, across)])

    c = (np.arange(size, dtype=np.float32) + 0.5) * (n / size)
    cell = np.floor(c)
    frac = c - cell
    profile = np.sqrt(np.sin(np.pi * frac))  # round thread cross-section
    parity = np.pi * cell
    # Warp (column i) is on top in cells with even i + j, the weft in the others.
    over_warp = 0.5 + 0.5 * np.cos(np.pi * (c[:, None] - 0.5) + parity[None, :])
    over_weft = 0.5 - 0.5 * np.cos(np.pi * (c[None, :] - 0.5) + parity[:, None])
    h_warp = profile[None, :] * (0.35 + 0.65 * over_warp)
    h_weft = profile[:, None] * (0.35 + 0.65 * over_weft)
    is_warp = h_warp >= h_weft
    weave = np.maximum(h_warp, h_weft)
    fibres = np.where(is_warp, fib_warp, fib_weft)

    # Fade the weave out where threads get narrower than ~4 px (avoids moire).
    gain = float(np.clip(size / (2.0 * n) - 1.0, 0.0, 1.0))
    shade = 1.0 + gain * (0.35 * (weave - 0.6) + np.where(is_warp, 0.03, -0.03))
    tint = shade * (1.0 + look.color_variation * fibres)
    roughness = 0.6 * fibres - gain * (weave - 0.6)
    height = gain * weave + 0.1 * fibres
    return tint, roughness, height


def _polished(look: Look, size: int) -> Fields:
    """A mirror-like finish (chrome plating, glass, a screen's cover glass): no bands or
    rings, only a faint fine haze in colour and roughness and an almost flat normal."""
    seed, s = look.noise_seed, look.scale * TILE_METRES
    haze = periodic_noise(seed, "polished.haze", size, [(1.0, s, s)])
    return 1.0 + look.color_variation * haze, haze, haze


def _corrugated(look: Look, size: int) -> Fields:
    """Corrugated board: a paper liner's fibre mottling over the flutes glued under it, which show through
    as faint parallel ridges (``look.scale`` flutes a metre) along U."""
    seed, s = look.noise_seed, look.scale * TILE_METRES
    n = max(1, round(s))  # whole flutes per tile, so it tiles
    v = (np.arange(size, dtype=np.float32) + 0.5) / size
    flutes = np.cos(2 * np.pi * n * v)[:, None] * np.ones((1, size), np.float32)
    fibre = periodic_noise(seed, "corrugated.fibre", size, [(1.0, 400.0 * TILE_METRES, 250.0 * TILE_METRES)])
    low = periodic_noise(seed, "corrugated.low", size, [(1.0, 4.0, 4.0)])
    # the liner is lighter over each flute's crest (it rubs and sun-fades first) and mottled throughout
    tint = 1.0 + look.color_variation * (0.6 * fibre + 0.4 * low + 0.25 * flutes)
    height = flutes + 0.35 * fibre
    return tint, fibre + 0.3 * low, height


_STYLES: dict[str, Callable[[Look, int], Fields]] = {
    "corrugated": _corrugated,
    "wood": _wood,
    "brushed": _brushed,
    "coating": _coating,
    "speckle": _speckle,
    "woven": _woven,
    "polished": _polished,
}


# --------------------------------------------------------------------------- public


def _check_size(size: int) -> None:
    ok = (
        isinstance(size, int | np.integer)
        and not isinstance(size, bool)
        and MIN_SIZE <= size <= MAX_SIZE
        and size & (size - 1) == 0
    )
    if not ok:
        raise ValueError(
            f"texture size must be a power of two in [{MIN_SIZE}, {MAX_SIZE}], got {size!r}"
        )


def _basecolor(tint: np.ndarray, base_color: tuple[float, float, float]) -> np.ndarray:
    """Scale ``tint`` to mean ``base_color`` (linear) and encode as 8-bit sRGB (h, w, 3)."""
    if tint.ndim == 2:
        tint = tint[..., None]
    base = np.asarray(base_color, dtype=np.float32)
    mean = np.asarray(cv2.mean(tint)[: tint.shape[2]], dtype=np.float32)  # fast per-channel mean
    scale = base / mean * np.float32(len(_SRGB_LUT) - 1)
    index = tint * scale
    np.clip(index, 0.0, len(_SRGB_LUT) - 1, out=index)
    index += 0.5  # round half up when truncating to integers
    return _SRGB_LUT[index.astype(np.uint16)]


def synthesize(look: Look, size: int = 512) -> dict[str, np.ndarray]:
    """Synthesize the tiling PBR maps of ``look`` (one UV unit, wrap = repeat).

    Parameters
    ----------
    look : Look
        Appearance from :func:`~infmob_usd.materials.sample_look`.
    size : int, optional
        Side length in pixels: a power of two in [16, 4096].

    Returns
    -------
    dict of str to numpy.ndarray
        Keys exactly :data:`TEXTURE_MAPS`, all uint8:

        - ``"basecolor"``: (size, size, 3) sRGB, RGB order, mean ``look.base_color``;
        - ``"roughness"``: (size, size) linear, around ``look.roughness``;
        - ``"normal"``: (size, size, 3) OpenGL tangent-space normal, flat = (128, 128, 255).

        Deterministic given ``(look, size)``.

    Raises
    ------
    ValueError
        If ``size`` is not an allowed size or ``look.family`` is unknown.
    """
    _check_size(size)
    size = int(size)
    family = FAMILIES.get(look.family)
    if family is None:
        raise ValueError(
            f"unknown material family {look.family!r}; valid families: {', '.join(sorted(FAMILIES))}"
        )
    tint, roughness, height = _STYLES[family.style](look, size)
    rough = np.clip(look.roughness + look.roughness_variation * roughness, 0.0, 1.0)
    return {
        "basecolor": _basecolor(tint, look.base_color),
        "roughness": np.rint(rough * 255.0).astype(np.uint8),
        "normal": height_to_normal(height, look.bump),
    }


def encode_png(img: np.ndarray) -> bytes:
    """Encode an RGB (h, w, 3) or grey (h, w) uint8 image as deterministic PNG bytes.

    Raises
    ------
    ValueError
        If ``img`` is not a uint8 array of one of those shapes.
    """
    img = np.asarray(img)
    if img.dtype != np.uint8 or not (img.ndim == 2 or (img.ndim == 3 and img.shape[2] == 3)):
        raise ValueError(
            f"expected a uint8 (h, w) or (h, w, 3) image, got {img.dtype} {img.shape}"
        )
    bgr = np.ascontiguousarray(img[..., ::-1]) if img.ndim == 3 else img
    ok, buf = cv2.imencode(".png", bgr, _PNG_PARAMS)
    if not ok:
        raise RuntimeError("cv2.imencode failed to encode a PNG")
    return buf.tobytes()
