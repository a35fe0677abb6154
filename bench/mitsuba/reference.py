"""High-precision references for the rows of compare.py, so every time it prints comes with the
error of the result it times.

Each side is measured against the function it computes, evaluated exactly on the same f32
inputs it reads:

- brdf's D kernels read the cosine m.z only and compute D(cos); Mitsuba's `eval(m)` reads all
  three components (GGX: 1 / (pi a^2 (x^2/a^2 + y^2/a^2 + z^2)^2); Beckmann:
  exp(-(x^2 + y^2) / (a^2 z^2)) / (pi a^2 z^4)). The f32 directions are not exactly unit, so
  the two functions differ by a few f32 roundings; each result is compared with its own.
- The rough conductor: both sides form the half vector h = (v + l) / |v + l| from the f32
  directions (the reference normalizes exactly). Mitsuba: D(h) G1(v) G1(l) F(v.h) / (4 v.z)
  with the separable Smith G1 = 2 / (1 + sqrt(1 + a^2 (x^2 + y^2) / z^2)) of each direction's
  components (its `MicrofacetDistribution::G`); brdf: D(h.z) F(v.h) / (4 v.z (1 + Lambda(v.z)
  + Lambda(l.z))) with the height-correlated Smith G2 and Lambda(c) = (sqrt(1 + a^2 (1 - c^2)
  / c^2) - 1) / 2 (Heitz 2014, eq. 99). F is the exact unpolarized conductor Fresnel of
  eta + i k (Born and Wolf; Mitsuba writes it after Moeller's "Optics", brdf after pbrt-v4:
  the same function).

Two references: `*_f64` over every element in numpy float64, written so that no step cancels
(1 - c^2 as (1 - c)(1 + c), exact for an f32 c), whose own error is ~1e-16 relative, a billionth
of an f32 ULP; and `*_mp` in mpmath at 50 digits, run on a subsample (and on each row's worst
elements) to check the float64 reference itself.
"""

import numpy as np

# ---------------------------------------------------------------------------------------------
# float64 references (vectorized)
# ---------------------------------------------------------------------------------------------


def _sin2(c):
    return (1.0 - c) * (1.0 + c)


def ggx_d_cos_f64(c, a):
    """brdf's `ggx::d(c, a)`: a^2 / (pi ((1 - c^2) + c^2 a^2)^2) for c > 0, else 0."""
    c = np.asarray(c, np.float64)
    den = _sin2(c) + c * c * a * a
    return np.where(c > 0, a * a / (np.pi * den * den), 0.0)


def beckmann_d_cos_f64(c, a):
    """brdf's `beckmann::d(c, a)`: exp(-(1 - c^2) / (c^2 a^2)) / (pi a^2 c^4) for c > 0."""
    c = np.asarray(c, np.float64)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        c2 = c * c
        val = np.exp(-_sin2(c) / (c2 * a * a)) / (np.pi * a * a * c2 * c2)
    return np.where(c > 0, val, 0.0)


def ggx_d_vec_f64(x, y, z, a):
    """Mitsuba's GGX `eval(m)`: 1 / (pi a^2 (x^2/a^2 + y^2/a^2 + z^2)^2), zero where
    result * z <= 1e-20 (its own cut)."""
    x, y, z = (np.asarray(t, np.float64) for t in (x, y, z))
    s = (x * x + y * y) / (a * a) + z * z
    val = 1.0 / (np.pi * a * a * s * s)
    return np.where(val * z > 1e-20, val, 0.0)


def beckmann_d_vec_f64(x, y, z, a):
    """Mitsuba's Beckmann `eval(m)`: exp(-(x^2 + y^2) / (a^2 z^2)) / (pi a^2 z^4), with its cut."""
    x, y, z = (np.asarray(t, np.float64) for t in (x, y, z))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        z2 = z * z
        val = np.exp(-(x * x + y * y) / (a * a * z2)) / (np.pi * a * a * z2 * z2)
    val = np.where(np.isfinite(val), val, 0.0)
    return np.where(val * z > 1e-20, val, 0.0)


def conductor_f64(cos_i, eta, k):
    """Exact unpolarized Fresnel reflectance of a conductor eta + i k from vacuum."""
    c = np.asarray(cos_i, np.complex128)
    n = complex(eta, k)
    s2 = 1.0 - c * c
    cos_t = np.sqrt(1.0 - s2 / (n * n))
    rs = (c - n * cos_t) / (c + n * cos_t)
    rp = (n * c - cos_t) / (n * c + cos_t)
    return 0.5 * (np.abs(rs) ** 2 + np.abs(rp) ** 2)


def _half(v, l):
    s = [np.asarray(a, np.float64) + np.asarray(b, np.float64) for a, b in zip(v, l)]
    n = np.sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2])
    return [t / n for t in s]


def _lambda_ggx(c, a):
    t2 = _sin2(c) / (c * c)
    return 0.5 * (np.sqrt(1.0 + a * a * t2) - 1.0)


def rough_conductor_brdf_f64(v, l, a, eta, k):
    """brdf's row: D(h.z) F(v.h) / (4 v.z (1 + Lambda(v.z) + Lambda(l.z))), 0 below a horizon."""
    v = [np.asarray(t, np.float64) for t in v]
    l = [np.asarray(t, np.float64) for t in l]
    h = _half(v, l)
    vh = v[0] * h[0] + v[1] * h[1] + v[2] * h[2]
    with np.errstate(divide="ignore", invalid="ignore"):
        g2 = 1.0 / (1.0 + _lambda_ggx(v[2], a) + _lambda_ggx(l[2], a))
        val = ggx_d_cos_f64(h[2], a) * g2 * conductor_f64(vh, eta, k) / (4.0 * v[2])
    return np.where((v[2] > 0) & (l[2] > 0), val, 0.0)


def _g1_mitsuba(w, h, a):
    xy = a * a * (w[0] * w[0] + w[1] * w[1])
    with np.errstate(divide="ignore", invalid="ignore"):
        g = 2.0 / (1.0 + np.sqrt(1.0 + xy / (w[2] * w[2])))
    g = np.where(xy == 0.0, 1.0, g)
    wh = w[0] * h[0] + w[1] * h[1] + w[2] * h[2]
    return np.where(wh * w[2] <= 0.0, 0.0, g)


def rough_conductor_mitsuba_f64(v, l, a, eta, k):
    """Mitsuba's row: D(h) G1(v) G1(l) F(v.h) / (4 v.z), 0 below a horizon."""
    v = [np.asarray(t, np.float64) for t in v]
    l = [np.asarray(t, np.float64) for t in l]
    h = _half(v, l)
    vh = v[0] * h[0] + v[1] * h[1] + v[2] * h[2]
    d = ggx_d_vec_f64(h[0], h[1], h[2], a)
    g = _g1_mitsuba(v, h, a) * _g1_mitsuba(l, h, a)
    with np.errstate(divide="ignore", invalid="ignore"):
        val = d * g * conductor_f64(vh, eta, k) / (4.0 * v[2])
    return np.where((v[2] > 0) & (l[2] > 0), val, 0.0)


# ---------------------------------------------------------------------------------------------
# mpmath references (one element at a time), the check on the float64 ones
# ---------------------------------------------------------------------------------------------


def _mp():
    import mpmath

    mpmath.mp.dps = 50
    return mpmath


def ggx_d_cos_mp(c, a):
    mp = _mp()
    c, a = mp.mpf(float(c)), mp.mpf(float(a))
    if c <= 0:
        return mp.mpf(0)
    den = 1 - c * c + c * c * a * a
    return a * a / (mp.pi * den * den)


def beckmann_d_cos_mp(c, a):
    mp = _mp()
    c, a = mp.mpf(float(c)), mp.mpf(float(a))
    if c <= 0:
        return mp.mpf(0)
    return mp.exp(-(1 - c * c) / (c * c * a * a)) / (mp.pi * a * a * c**4)


def ggx_d_vec_mp(x, y, z, a):
    mp = _mp()
    x, y, z, a = (mp.mpf(float(t)) for t in (x, y, z, a))
    s = (x * x + y * y) / (a * a) + z * z
    val = 1 / (mp.pi * a * a * s * s)
    return val if val * z > mp.mpf(1e-20) else mp.mpf(0)


def beckmann_d_vec_mp(x, y, z, a):
    mp = _mp()
    x, y, z, a = (mp.mpf(float(t)) for t in (x, y, z, a))
    if z == 0:
        return mp.mpf(0)
    val = mp.exp(-(x * x + y * y) / (a * a * z * z)) / (mp.pi * a * a * z**4)
    return val if val * z > mp.mpf(1e-20) else mp.mpf(0)


def conductor_mp(cos_i, eta, k):
    mp = _mp()
    c = mp.mpf(cos_i)
    n = mp.mpc(eta, k)
    cos_t = mp.sqrt(1 - (1 - c * c) / (n * n))
    rs = (c - n * cos_t) / (c + n * cos_t)
    rp = (n * c - cos_t) / (n * c + cos_t)
    return (abs(rs) ** 2 + abs(rp) ** 2) / 2


def _half_mp(v, l):
    mp = _mp()
    s = [mp.mpf(float(a)) + mp.mpf(float(b)) for a, b in zip(v, l)]
    n = mp.sqrt(s[0] ** 2 + s[1] ** 2 + s[2] ** 2)
    return [t / n for t in s]


def rough_conductor_brdf_mp(v, l, a, eta, k):
    mp = _mp()
    v = [mp.mpf(float(t)) for t in v]
    l = [mp.mpf(float(t)) for t in l]
    if v[2] <= 0 or l[2] <= 0:
        return mp.mpf(0)
    a = mp.mpf(float(a))
    h = _half_mp(v, l)
    vh = v[0] * h[0] + v[1] * h[1] + v[2] * h[2]

    def lam(c):
        return (mp.sqrt(1 + a * a * (1 - c * c) / (c * c)) - 1) / 2

    den = 1 - h[2] ** 2 + h[2] ** 2 * a * a
    d = a * a / (mp.pi * den * den)
    g2 = 1 / (1 + lam(v[2]) + lam(l[2]))
    return d * g2 * conductor_mp(vh, eta, k) / (4 * v[2])


def rough_conductor_mitsuba_mp(v, l, a, eta, k):
    mp = _mp()
    v = [mp.mpf(float(t)) for t in v]
    l = [mp.mpf(float(t)) for t in l]
    if v[2] <= 0 or l[2] <= 0:
        return mp.mpf(0)
    a = mp.mpf(float(a))
    h = _half_mp(v, l)
    vh = v[0] * h[0] + v[1] * h[1] + v[2] * h[2]

    def g1(w):
        xy = a * a * (w[0] ** 2 + w[1] ** 2)
        g = 1 if xy == 0 else 2 / (1 + mp.sqrt(1 + xy / (w[2] ** 2)))
        wh = w[0] * h[0] + w[1] * h[1] + w[2] * h[2]
        return 0 if wh * w[2] <= 0 else g

    d = ggx_d_vec_mp(h[0], h[1], h[2], a)
    return d * g1(v) * g1(l) * conductor_mp(vh, eta, k) / (4 * v[2])


# ---------------------------------------------------------------------------------------------
# Error measures
# ---------------------------------------------------------------------------------------------


def ulp_f32(r):
    """The spacing of f32 at |r| (the smallest subnormal's spacing below f32's smallest normal)."""
    r = np.abs(np.asarray(r, np.float64))
    e = np.floor(np.log2(np.where(r > 0, r, 1.0)))
    return np.exp2(np.maximum(e, -126.0) - 23.0)


def errors(x, ref):
    """(ulp, rel, subnormal) arrays of the f32 results x against the reference ref.

    Where the reference is 0, a result of 0 counts as 0 ULP and anything else as inf; NaN
    anywhere counts as inf. `subnormal` marks the elements whose reference lies below f32's
    smallest normal number (2^-126 = 1.2e-38), where shader languages and flush-to-zero
    builds promise nothing and the fast kernels document a flush to 0: compare.py reports
    them apart, by their absolute error, and leaves them out of the ULP statistics."""
    x = np.asarray(x, np.float64)
    ref = np.asarray(ref, np.float64)
    diff = np.abs(x - ref)
    with np.errstate(divide="ignore", invalid="ignore"):
        ulp = np.where(ref != 0, diff / ulp_f32(ref), np.where(x == 0, 0.0, np.inf))
        rel = np.where(ref != 0, diff / np.abs(ref), np.where(x == 0, 0.0, np.inf))
    bad = ~np.isfinite(x) | ~np.isfinite(ref)
    subnormal = (ref != 0) & (np.abs(ref) < 2.0**-126) & ~bad
    return np.where(bad, np.inf, ulp), np.where(bad, np.inf, rel), subnormal
