"""brdf: the Rust crate ``brdf``'s BRDF kernels as numpy functions, in float64 and float32.

Every kernel of the reference CLI's table (``brdf-ref --list``) is a function under the same
dotted path: ``brdf.ggx.d``, ``brdf.fresnel.dielectric``, ``brdf.tonemap.agx_threejs``,
``brdf.material.gltf``, ``brdf.ggx.Ggx.d`` ... Arguments broadcast like numpy ufuncs; the
result has the inputs' float dtype (``help(brdf.ggx.d)`` states the rule, each argument's
domain, the formula and its source). The loops run in Rust on SIMD lanes, without the GIL,
split over threads for large arrays.

Parameter types (``brdf.ggx.Ggx``, ``brdf.diffuse.Eon``, ``brdf.tonemap.HableParams``, ...)
validate at construction (``ValueError`` naming the parameter). ``brdf.integrate`` runs the
crate's hemisphere integrators on a Python callable over arrays of directions.

    >>> import numpy as np, brdf
    >>> brdf.ggx.d(np.linspace(0, 1, 5, dtype=np.float32), 0.3).dtype
    dtype('float32')
"""

from . import _native
from ._kernels import Parameters, build

__version__ = "0.1.0"

#: The kernel table as the Rust side holds it: one dict per kernel (path, summary, args,
#: outputs, constraints, unit_vectors, doc, type_doc), in table order.
KERNELS = _native.kernels()

_modules, _classes = build(__import__(__name__))

from . import integrate  # noqa: E402  (after the generated modules, which it does not need)


def kernel(path):
    """The function of a kernel by its Rust path (``"ggx::Ggx::d"``) or dotted path."""
    import keyword

    parts = path.replace(".", "::").removeprefix("brdf::").split("::")
    path = "::".join(p[:-1] if p.endswith("_") and keyword.iskeyword(p[:-1]) else p for p in parts)
    for info in KERNELS:
        if info["path"] == path:
            parts = path.split("::")
            obj = __import__(__name__)
            for p in parts:
                obj = getattr(obj, p)
            return obj
    raise KeyError(path)


__all__ = sorted({p["path"].split("::")[0] for p in KERNELS}) + [
    "integrate",
    "kernel",
    "Parameters",
    "KERNELS",
]
