"""The crate's hemisphere integrators (``brdf::integrate``) on a Python callable.

The integrand takes arrays of directions, each of shape (n, 3) (unit vectors in the local
shading frame, normal = +z, pointing away from the surface) and returns n values. It is
called a few to a few dozen times with many directions at once: the adaptive integration is
replayed in Rust until every direction it needs has a value, so the result is exactly the
Rust integrator's with the integrand called one direction at a time. The integrand must be
a function of the directions alone (same direction, same value).

``dtype=np.float32`` hands the integrand float32 directions and rounds its values to
float32, the integration itself staying in float64 (the crate's ``_f32`` forms).

    >>> import numpy as np
    >>> from brdf import integrate
    >>> lambert = lambda wo, wi: np.full(len(wi), 0.8 / np.pi)
    >>> round(integrate.directional_albedo(lambert, wo=(0, 0, 1)).value, 6)
    0.8
"""

from __future__ import annotations

from collections import namedtuple

import numpy as np

from . import _native

__all__ = [
    "Estimate",
    "Reciprocity",
    "hemisphere",
    "directional_albedo",
    "ndf_projected_area",
    "smith_weak_furnace",
    "reciprocity",
]

#: An integral's estimate: value, estimated absolute error, integrand evaluations the Rust
#: integrator spent, and Python calls made to the integrand.
Estimate = namedtuple("Estimate", ["value", "error", "evaluations", "python_calls"])
#: Largest relative asymmetry max |f(a, b) - f(b, a)| / max(|f(a, b)|, |f(b, a)|), the pair
#: where it occurs, the pairs tested and the Python calls made.
Reciprocity = namedtuple("Reciprocity", ["max_rel", "worst_a", "worst_b", "pairs", "python_calls"])


def _is_f32(dtype):
    dt = np.dtype(dtype)
    if dt not in (np.dtype(np.float32), np.dtype(np.float64)):
        raise TypeError(f"dtype must be float32 or float64, not {dt}")
    return dt == np.float32


def _dir(name, w):
    w = np.asarray(w, dtype=np.float64)
    if w.shape != (3,):
        raise ValueError(f"`{name}` must be one direction of 3 components, not shape {w.shape}")
    return [float(x) for x in w]


def hemisphere(f, peaks=(), abs_tol=1e-10, rel_tol=1e-7, max_evals=2_000_000, dtype=np.float64):
    """Integral of f(w) dw over the upper hemisphere (brdf::integrate::hemisphere).

    f(w): w of shape (n, 3) -> n values. `peaks`: up to 4 directions where f may be sharply
    peaked (they shape the initial partition). Stops when error <= abs_tol or
    <= rel_tol |value|, or after max_evals evaluations. A NaN or negative tolerance, or a
    non-finite peak, gives NaN (the crate's rule). Returns an Estimate.
    """
    p = [_dir("peaks[i]", w) for w in peaks]
    r = _native.integrate(
        "hemisphere", f, peaks=p, abs_tol=abs_tol, rel_tol=rel_tol, max_evals=max_evals,
        f32=_is_f32(dtype),
    )
    return Estimate(*r)


def directional_albedo(f, wo=(0.0, 0.0, 1.0), abs_tol=1e-10, rel_tol=1e-7, max_evals=2_000_000,
                       dtype=np.float64):
    """Directional albedo rho(wo) = integral of f(wo, wi) cos(theta_i) dwi.

    brdf::integrate::directional_albedo_with. f(wo, wi): both of shape (n, 3) (wo repeated)
    -> n values. A physical BRDF has rho <= 1 for every wo (white furnace); a Lambertian of
    albedo a gives a. Returns an Estimate.
    """
    r = _native.integrate(
        "directional_albedo", f, wo=_dir("wo", wo), abs_tol=abs_tol, rel_tol=rel_tol,
        max_evals=max_evals, f32=_is_f32(dtype),
    )
    return Estimate(*r)


def ndf_projected_area(d, dtype=np.float64):
    """Integral of D(m) cos(theta_m) dm: 1 for a normalized NDF (Walter et al. 2007, eq. 4).

    d(m): m of shape (n, 3) -> n values. Returns an Estimate.
    """
    return Estimate(*_native.integrate("ndf_projected_area", d, f32=_is_f32(dtype)))


def smith_weak_furnace(d, g1, wo, dtype=np.float64):
    """Integral of G1(wo, m) D(m) max(0, wo.m) dm / cos(theta_o): 1 for a Smith G1 that
    matches D (Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based
    BRDFs", eq. 18 and section 5).

    d(m) -> n values; g1(wo, m) -> n values (wo repeated). wo.z must be > 0 (else NaN).
    The error estimate carries the crate's KINK_SAFETY factor. Returns an Estimate.
    """
    return Estimate(*_native.integrate(
        "smith_weak_furnace", d, g1=g1, wo=_dir("wo", wo), f32=_is_f32(dtype)
    ))


def reciprocity(f, dtype=np.float64):
    """Largest relative asymmetry of f(a, b) against f(b, a) over the crate's 64 test
    directions (brdf::integrate::reciprocity): 0 for a reciprocal BRDF. Returns a
    Reciprocity.
    """
    return Reciprocity(*_native.integrate("reciprocity", f, f32=_is_f32(dtype)))
