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
roughness and metallic are linear greys, normal is an OpenGL (+Y up)
tangent-space normal map.
"""

from __future__ import annotations

import math
import zlib
from collections.abc import Callable, Sequence

import cv2
import numpy as np

from .families import FAMILIES, Look

__all__ = ["TEXTURE_MAPS", "encode_png", "height_to_normal", "periodic_noise", "synthesize"]

TEXTURE_MAPS = ("basecolor", "roughness", "metallic", "normal")

MIN_SIZE = 16
MAX_SIZE = 4096

Component = tuple[float, float, float]
"""``(weight, sigma_u, sigma_v)``: one anisotropic Gaussian of a noise amplitude
spectrum, with standard deviations in cycles per UV unit along U and V."""

_PNG_COMPRESSION = 3


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
    Frequencies above ``4 * max(sigma)`` are dropped, as is everything at or
    above the Nyquist frequency of ``size``.

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
    k_ref = math.ceil(4.0 * max(max(su, sv) for _, su, sv in components))
    k_cap = min(k_ref, size // 2 - 1)
    cols = k_cap + 1
    tag = zlib.crc32(name.encode("utf-8"))
    spec = np.zeros((size, cols), dtype=np.complex64)
    # Octave o holds the frequencies with 2**o <= max(|ku|, |kv|) < 2**(o + 1) (octave 0
    # also holds DC), drawn from its own generator as one full block (|kv|, ku < 2**(o + 1))
    # so that coefficients do not depend on size.  Writing high octaves first lets the
    # lower ones overwrite the inner part of each block.
    for octave in reversed(range(k_cap.bit_length())):
        hi = 2 << octave
        rng = np.random.default_rng(np.random.SeedSequence((seed, tag, octave)))
        draw = rng.standard_normal((2 * hi, hi, 2), dtype=np.float32).view(np.complex64)
        spec[np.arange(-hi, hi) % size, : min(hi, cols)] = draw[:, :cols, 0]
    spec[k_cap + 1 : size - k_cap] = 0.0
    spec[0, 0] = 0.0
    # irfft keeps only the real part of the ku = 0 column: restore its variance.
    spec[:, 0] *= np.float32(math.sqrt(2.0))

    ku = np.arange(cols, dtype=np.float32)
    kv = (np.fft.fftfreq(size) * size).astype(np.float32)
    amp = np.zeros(spec.shape, dtype=np.float32)
    variance = 0.0
    for w, su, sv in components:
        amp += np.float32(w) * np.outer(np.exp(-0.5 * (kv / sv) ** 2), np.exp(-0.5 * (ku / su) ** 2))
        for w2, su2, sv2 in components:
            variance += w * w2 * _gauss_sum(su, su2, k_ref) * _gauss_sum(sv, sv2, k_ref)
    variance -= sum(w for w, _, _ in components) ** 2  # the excluded DC term
    # Inverse transform over V, then a real inverse transform over U (zero-padding ku).
    rows = np.fft.ifft(spec * amp, axis=0, norm="forward")
    field = np.fft.irfft(rows, n=size, axis=1, norm="forward")
    return (field / np.float32(math.sqrt(2.0 * max(variance, 1e-12)))).astype(np.float32)


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
    inv_len = 1.0 / np.sqrt(du * du + dv * dv + 1.0)
    n = np.stack((-du * inv_len, -dv * inv_len, inv_len), axis=-1)
    return np.rint(n * 127.5 + 127.5).astype(np.uint8)


# --------------------------------------------------------------------------- styles
#
# A style maps (look, size) to three float32 fields of shape (size, size):
#   tint      - positive colour field, (size, size) grey or (size, size, 3); it is
#               rescaled per channel so that its mean equals look.base_color;
#   roughness - roughly unit-std variation, scaled by look.roughness_variation;
#   height    - height field for the normal map (rescaled to look.bump).

Fields = tuple[np.ndarray, np.ndarray, np.ndarray]


def _wood(look: Look, size: int) -> Fields:
    """Growth rings across V, wiggled by low-frequency warp, plus grain and pores along U."""
    seed, aniso = look.noise_seed, look.anisotropy
    rings = max(1, round(look.scale))
    warp = periodic_noise(seed, "wood.warp", size, [(1.0, 1.0, 1.2)])
    figure = periodic_noise(seed, "wood.figure", size, [(1.0, 2.0, 3.0)])
    grain = periodic_noise(seed, "wood.grain", size, [(1.0, 70.0 / aniso, 70.0)])
    pores = periodic_noise(seed, "wood.pores", size, [(1.0, 200.0 / aniso, 200.0)])

    v = (np.arange(size, dtype=np.float32) + 0.5) / size
    phase = rings * v[:, None] + 0.5 * warp + 0.02 * grain
    t = phase - np.floor(phase)
    # Earlywood lightens gradually into dark latewood, then the next ring starts sharply.
    latewood = (t * t * t - 0.25) / 0.284 * (1.0 + 0.3 * figure)
    dark = 0.8 * latewood + 0.45 * grain + 0.25 * pores

    ln_base = np.log(np.maximum(np.asarray(look.base_color, dtype=np.float32), 1e-3))
    # Darker wood is also more saturated: channels darken in proportion to -ln(base).
    tint = np.exp(-look.color_variation * dark[..., None] * (0.5 - ln_base))
    roughness = 0.8 * pores + 0.5 * latewood
    height = 0.6 * grain + 0.5 * pores - 0.3 * latewood
    return tint, roughness, height


def _brushed(look: Look, size: int) -> Fields:
    """Fine and coarse streaks along U, shared by colour, roughness and normal."""
    seed, s = look.noise_seed, look.scale
    su = s / look.anisotropy
    streaks = periodic_noise(
        seed, "brushed.streaks", size, [(1.0, su, s), (0.8, 0.5 * su, 0.15 * s)]
    )
    low = periodic_noise(seed, "brushed.low", size, [(1.0, 2.0, 2.0)])
    tint = 1.0 + look.color_variation * (streaks + 0.4 * low)
    return tint, streaks, streaks


def _coating(look: Look, size: int) -> Fields:
    """Smooth coating: faint low-frequency mottling plus band-pass orange peel."""
    seed, s = look.noise_seed, look.scale
    su = s / look.anisotropy
    low = periodic_noise(seed, "coating.low", size, [(1.0, 2.5, 2.5)])
    peel = periodic_noise(seed, "coating.peel", size, [(1.0, su, s), (-1.0, 0.5 * su, 0.5 * s)])
    tint = 1.0 + look.color_variation * (low + 0.3 * peel)
    return tint, 0.7 * (low + peel), peel


def _speckle(look: Look, size: int) -> Fields:
    """Fine isotropic speckle over a faint low-frequency variation."""
    seed, s = look.noise_seed, look.scale
    speck = periodic_noise(seed, "speckle.fine", size, [(1.0, s / look.anisotropy, s)])
    low = periodic_noise(seed, "speckle.low", size, [(1.0, 3.0, 3.0)])
    detail = 0.8 * speck + 0.6 * low
    return 1.0 + look.color_variation * detail, detail, speck


def _woven(look: Look, size: int) -> Fields:
    """Plain weave: warp threads along V, weft threads along U, with fibre noise."""
    seed = look.noise_seed
    n = 2 * max(2, round(look.scale / 2.0))  # threads per UV unit; even, so it tiles
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


_STYLES: dict[str, Callable[[Look, int], Fields]] = {
    "wood": _wood,
    "brushed": _brushed,
    "coating": _coating,
    "speckle": _speckle,
    "woven": _woven,
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
    linear = tint * (base / tint.mean(axis=(0, 1)))
    index = np.rint(np.clip(linear, 0.0, 1.0) * 65535.0).astype(np.uint16)
    return _SRGB_LUT[index]


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
        - ``"metallic"``: (size, size) linear, constant ``look.metallic``;
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
        "metallic": np.full((size, size), round(look.metallic * 255.0), dtype=np.uint8),
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
    ok, buf = cv2.imencode(".png", bgr, [cv2.IMWRITE_PNG_COMPRESSION, _PNG_COMPRESSION])
    if not ok:
        raise RuntimeError("cv2.imencode failed to encode a PNG")
    return buf.tobytes()
