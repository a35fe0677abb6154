"""The crate's integrators on Python callables: a white furnace of a user's numpy BRDF."""

import numpy as np
import pytest

import brdf
from brdf import integrate


def lambert(albedo):
    return lambda wo, wi: np.full(len(wi), albedo / np.pi, dtype=wi.dtype)


def ggx_d_numpy(alpha):
    """GGX NDF written in plain numpy, as a user would (Walter et al. 2007, eq. 33)."""
    a2 = alpha * alpha

    def d(m):
        c2 = m[:, 2] ** 2
        return a2 / (np.pi * (c2 * (a2 - 1) + 1) ** 2)

    return d


def ggx_g1_numpy(alpha):
    def g1(wo, m):
        c = wo[:, 2]
        t2 = (1 - c * c) / (c * c)
        lam = (np.sqrt(1 + alpha * alpha * t2) - 1) / 2
        return np.where(np.sum(wo * m, axis=1) > 0, 1 / (1 + lam), 0.0)

    return g1


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_white_furnace_of_a_python_lambertian(dtype):
    seen = []

    def f(wo, wi):
        seen.append((wo.dtype, wi.shape))
        return lambert(1.0)(wo, wi)

    e = integrate.directional_albedo(f, wo=(0.6, 0.0, 0.8), dtype=dtype)
    # The integrator's accuracy on smooth integrands (src/integrate.rs: 1e-5 or better).
    assert abs(e.value - 1.0) < 1e-6 and e.error < 1e-5
    assert all(d == dtype for d, _ in seen)
    # Batched: a handful of calls for thousands of evaluations.
    assert e.python_calls == len(seen) and e.python_calls < 20 < e.evaluations


def test_replay_equals_the_rust_integrator_on_the_same_function():
    # The crate's own GGX D through the binding, integrated here and by the Rust integrator
    # in ndf_projected_area's definition: the replayed result is the direction-by-direction
    # one, so the normalization holds to the integrator's error.
    d = lambda m: brdf.ggx.Ggx.d(0.2, 0.2, m[:, 0], m[:, 1], m[:, 2], lanes=False)
    e = integrate.ndf_projected_area(d)
    assert abs(e.value - 1.0) <= max(e.error, 1e-6)
    py = integrate.ndf_projected_area(ggx_d_numpy(0.2))
    assert abs(py.value - 1.0) <= max(py.error, 1e-6)


def test_white_furnace_of_a_numpy_microfacet_brdf():
    # A GGX lobe with F = 1 written in numpy: D G2 / (4 n.l n.v), separable Smith G2. The
    # directional albedo must stay below 1 (energy) and, at alpha = 0.1 from normal
    # incidence, lose only the few percent single scattering loses (Kulla and Conty 2017).
    alpha = 0.1
    d, g1 = ggx_d_numpy(alpha), ggx_g1_numpy(alpha)

    def f(wo, wi):
        h = wo + wi
        h /= np.linalg.norm(h, axis=1, keepdims=True)
        g = g1(wo, h) * g1(wi, h)
        return d(h) * g / (4 * wo[:, 2] * wi[:, 2])

    e = integrate.directional_albedo(f, wo=(0, 0, 1))
    assert 0.95 < e.value <= 1.0 + e.error


def test_smith_weak_furnace_of_numpy_functions():
    wo = np.array([0.6, 0.0, 0.8])
    e = integrate.smith_weak_furnace(ggx_d_numpy(0.3), ggx_g1_numpy(0.3), wo)
    assert abs(e.value - 1.0) < 1e-3


def test_reciprocity_and_hemisphere():
    r = integrate.reciprocity(lambda a, b: a[:, 2] * b[:, 2])
    assert r.max_rel == 0.0 and r.pairs == 64 * 63
    r = integrate.reciprocity(lambda a, b: a[:, 2] + 2 * b[:, 2])
    assert r.max_rel > 0.1
    e = integrate.hemisphere(lambda w: w[:, 2], peaks=[(0, 0, 1)])
    assert abs(e.value - np.pi) < 1e-8


def test_bad_integrands_and_arguments():
    with pytest.raises(ValueError, match="returned shape"):
        integrate.hemisphere(lambda w: np.zeros(3))
    with pytest.raises(ZeroDivisionError):
        integrate.hemisphere(lambda w: 1 / 0)
    with pytest.raises(ValueError, match="`wo`"):
        integrate.directional_albedo(lambert(1), wo=(0, 1))
    # The crate's rule: a NaN direction or tolerance gives NaN, without evaluating.
    assert np.isnan(integrate.directional_albedo(lambert(1), wo=(np.nan, 0, 1)).value)
    assert np.isnan(integrate.hemisphere(lambda w: w[:, 2], abs_tol=np.nan).value)
    # A NaN from the integrand is summed as it is.
    assert np.isnan(integrate.hemisphere(lambda w: np.full(len(w), np.nan)).value)
