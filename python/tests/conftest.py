"""Shared helpers: in-domain rows of a kernel, bitwise comparison."""

import numpy as np
import pytest

import brdf


def same_bits(a, b):
    """Equal bits, or both NaN (lane and scalar code may differ in a NaN's payload)."""
    a = np.asarray(a)
    b = np.asarray(b, dtype=a.dtype)
    ints = np.uint32 if a.dtype == np.float32 else np.uint64
    return (a.view(ints) == b.view(ints)) | (np.isnan(a) & np.isnan(b))


def sample_arg(rng, arg, n, dtype):
    """n values in an argument's documented domain: its finite ends, then a spread inside."""
    name, text, lo, hi, lo_open, hi_open, integer = arg
    if integer:
        return rng.integers(int(lo), int(hi) + 1, n).astype(dtype)
    big = float(np.finfo(dtype).max)
    a = max(lo, -1e6) if np.isfinite(lo) else -1e6
    b = min(hi, 1e6) if np.isfinite(hi) else 1e6
    if a > b:
        a, b = b, a
    v = rng.uniform(a, b, n)
    # Small and large magnitudes where the domain reaches them.
    extra = [lo, hi, 0.0, 1.0, 1e-3, 0.5, 10.0, big, 1e-30, -1.0]
    for i, x in enumerate(extra[: n // 4]):
        v[i] = x
    v = v.astype(dtype)
    lo_t, hi_t = dtype(lo), dtype(hi)
    with np.errstate(invalid="ignore"):
        ok = (v > lo_t) if lo_open else (v >= lo_t)
        ok &= (v < hi_t) if hi_open else (v <= hi_t)
        ok &= np.isfinite(v) | (v == lo_t) | (v == hi_t)
    mid = dtype((a + b) / 2) if np.isfinite(a + b) else dtype(0.5)
    return np.where(ok, v, mid).astype(dtype)


def rows(info, n, dtype, seed=0):
    """n rows (one array per argument) in the kernel's domains, unit vectors normalized."""
    rng = np.random.default_rng(seed)
    cols = [sample_arg(rng, a, n, dtype) for a in info["args"]]
    for i, j, k in info["unit_vectors"]:
        w = rng.normal(size=(3, n))
        w[2] = np.abs(w[2]) * np.where(rng.random(n) < 0.8, 1, -1)
        w /= np.linalg.norm(w, axis=0)
        w[:, 0] = (0, 0, 1)  # the normal itself
        for m, c in zip((i, j, k), w):
            cols[m] = c.astype(dtype)
    return cols


@pytest.fixture(params=[np.float64, np.float32], ids=["f64", "f32"])
def dtype(request):
    return request.param


KERNEL_IDS = [k["path"] for k in brdf.KERNELS]
