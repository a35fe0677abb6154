"""Builds the Python functions, classes and submodules from the Rust kernel table.

Every row of ``brdf_ref::KERNELS`` (the reference CLI's table, read through
``brdf._native.kernels()``) becomes one function under its dotted path: ``ggx::d`` is
``brdf.ggx.d``, ``ggx::Ggx::d`` is ``brdf.ggx.Ggx.d``, ``ibl::dfg::lazarov`` is
``brdf.ibl.dfg.lazarov``. Nothing here names a kernel: a row added to the table appears here
at the next build.
"""

from __future__ import annotations

import inspect
import keyword
import math
import sys
import types
from collections import namedtuple

import numpy as np

from . import _native

#: Keyword-only options every kernel function takes (after its arguments).
OPTIONS = ("dtype", "lanes", "threads", "check")

DTYPE_RULE = """\
Dtypes: float64 or float32, the same out as in, never upcast silently.
  - numpy float32 arrays/scalars in, float32 out; float64 in, float64 out;
  - Python floats and ints, and integer or bool arrays, adopt the float inputs' dtype
    (float64 when there are none);
  - float32 and float64 arrays together raise TypeError (cast one, or pass dtype=);
  - dtype=np.float32 or np.float64 forces the type (every input converted to it);
  - other dtypes (float16, longdouble, complex, object) raise TypeError."""

OPTIONS_DOC = """\
Options (keyword only):
  dtype   -- force float32 or float64 (see Dtypes).
  lanes   -- True (default): the kernel's SIMD lane entry (f64x4 / f32x8), bit for bit
             the Rust lane code; False: its scalar f64 / f32 entry, bit for bit the
             reference CLI's output. The two differ only in kernels whose lane path uses
             the lane polynomials of exp, ln, sin, cos, atan, acos, asin (1 to 3 ULP; the
             crate's accuracy table and cli/tests/cli/lanes.rs list them).
  threads -- True (default): arrays above 65536 elements are split over all cores.
  check   -- True: the reference CLI's input checks, raising ValueError naming the
             first argument outside its documented domain (NaN included) or the
             arguments of a broken relation (a direction that is not a unit vector, an
             ordering such as cos_outer <= cos_inner); False (default): the crate's rule,
             a NaN in any input gives NaN out and an invalid parameter gives NaN."""


def _rust_to_dotted(path: str) -> str:
    return ".".join(py_name(p) for p in path.split("::"))


def py_name(name: str) -> str:
    """A Rust name as Python can spell it: a Python keyword gets a trailing underscore
    (`ggx::lambda` is `brdf.ggx.lambda_`, PEP 8's convention); the keyword stays reachable
    through getattr."""
    return name + "_" if keyword.iskeyword(name) else name


def _resolve_dtype(path, names, arrays, values, dtype):
    """The result dtype by the rule in DTYPE_RULE."""
    if dtype is not None:
        dt = np.dtype(dtype)
        if dt not in (np.dtype(np.float32), np.dtype(np.float64)):
            raise TypeError(f"{path}: dtype must be float32 or float64, not {dt}")
        return dt
    strong = set()
    for name, a, v in zip(names, arrays, values):
        kind = a.dtype.kind
        if kind in "biu":
            continue
        if kind != "f" or a.dtype not in (np.dtype(np.float32), np.dtype(np.float64)):
            raise TypeError(
                f"{path}: argument `{name}` has dtype {a.dtype}; pass float32 or float64"
            )
        if isinstance(v, (float, int)) and not isinstance(v, np.generic):
            continue  # a Python number adopts the arrays' dtype
        strong.add(a.dtype)
    if len(strong) > 1:
        raise TypeError(
            f"{path}: float32 and float64 inputs together; cast one of them or pass "
            "dtype=np.float32 / np.float64 (brdf never upcasts silently)"
        )
    return strong.pop() if strong else np.dtype(np.float64)


def call(index, info, values, dtype=None, lanes=True, threads=True, check=False, result=None):
    """Evaluates kernel `index` on `values` (one per argument) with numpy broadcasting."""
    path = info["path"]
    names = [a[0] for a in info["args"]]
    arrays = [np.asarray(v) for v in values]
    dt = _resolve_dtype(_rust_to_dotted(path), names, arrays, values, dtype)
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrays))
    except ValueError:
        shapes = ", ".join(f"{n}: {a.shape}" for n, a in zip(names, arrays))
        raise ValueError(
            f"{_rust_to_dotted(path)}: argument shapes do not broadcast ({shapes})"
        ) from None
    flat = []
    for a in arrays:
        a = a.astype(dt, copy=False)
        if a.size == 1:
            flat.append(a.reshape(1))
        elif a.shape == shape:
            flat.append(np.ascontiguousarray(a).reshape(-1))
        else:
            flat.append(np.ascontiguousarray(np.broadcast_to(a, shape)).reshape(-1))
    if check:
        # The reference CLI's own checks (each argument's domain as the float type rounds
        # its ends, then the relations: unit vectors, orderings), on the values as given.
        _native.check_rows(index, [f.astype(np.float64) for f in flat], dt == np.float32)
    evaluate = _native.eval_f32 if dt == np.float32 else _native.eval_f64
    n = math.prod(shape)
    outs = [np.empty(n, dt) for _ in info["outputs"]]
    if n:
        evaluate(index, flat, outs, lanes=lanes, threads=threads)
    outs = [o.reshape(shape) if shape else o[0] for o in outs]
    if result is None:
        return outs[0]
    return result(*outs)


def _docstring(info, dotted, signature):
    args = "\n".join(f"  {a[0]:<22} {a[1]}" for a in info["args"])
    outs = "\n".join(f"  {o[0]:<22} {o[1]}" for o in info["outputs"])
    parts = [f"{dotted}{signature}", "", info["summary"] + ".", ""]
    parts += ["Arguments (array-like, broadcast together) and their domains:", args, ""]
    if info["constraints"]:
        parts += ["Constraints:"] + [f"  {c}" for c in info["constraints"]] + [""]
    kind = "one array" if len(info["outputs"]) == 1 else "a named tuple of arrays"
    parts += [f"Returns {kind} (a numpy scalar for scalar inputs):", outs, ""]
    doc = info["doc"] or info["type_doc"]
    if doc:
        heading = "Rust documentation" if info["doc"] else "Rust documentation of the type"
        parts += [f"{heading} (brdf::{info['path']}):", "", doc, ""]
    parts += [DTYPE_RULE, "", OPTIONS_DOC]
    return "\n".join(parts)


def _signature(names, leading=()):
    P = inspect.Parameter
    params = [P(n, P.POSITIONAL_OR_KEYWORD) for n in names]
    params += [
        P("dtype", P.KEYWORD_ONLY, default=None),
        P("lanes", P.KEYWORD_ONLY, default=True),
        P("threads", P.KEYWORD_ONLY, default=True),
        P("check", P.KEYWORD_ONLY, default=False),
    ]
    return inspect.Signature([P(n, P.POSITIONAL_ONLY) for n in leading] + params)


def make_function(index, info):
    """The Python function of table row `index`."""
    path = info["path"]
    leaf = path.rsplit("::", 1)[-1]
    dotted = "brdf." + _rust_to_dotted(path)
    names = [a[0] for a in info["args"]]
    out_names = [o[0] for o in info["outputs"]]
    result = None
    if len(out_names) > 1:
        result = namedtuple(_rust_to_dotted(path).replace(".", "_") + "_result", out_names)
        result.__module__ = "brdf"
    sig = _signature(names)

    def kernel(*args, **kwargs):
        bound = sig.bind(*args, **kwargs)
        bound.apply_defaults()
        a = bound.arguments
        return call(
            index,
            info,
            [a[n] for n in names],
            a["dtype"],
            a["lanes"],
            a["threads"],
            a["check"],
            result,
        )

    kernel.__name__ = py_name(leaf)
    kernel.__qualname__ = _rust_to_dotted(path.split("::", 1)[1]) if "::" in path else leaf
    kernel.__signature__ = sig
    kernel.__doc__ = _docstring(info, dotted, str(sig))
    kernel.path = path
    kernel.index = index
    kernel.arg_names = tuple(names)
    kernel.output_names = tuple(out_names)
    kernel.result_type = result
    return kernel


class Parameters:
    """Base of the parameter types (``brdf.ggx.Ggx``, ``brdf.diffuse.Eon``, ...).

    Construction runs the crate's own constructor on the values (rounded to ``dtype``):
    a value outside its domain raises ``ValueError`` naming the parameter. Methods of an
    instance are the type's kernels with the constructor's arguments filled in; on the class
    they are the flat kernels, taking every argument.
    """

    _path = ""
    _args: tuple = ()

    def __init__(self, *args, dtype=np.float64, **kwargs):
        sig = inspect.Signature(
            [inspect.Parameter(n, inspect.Parameter.POSITIONAL_OR_KEYWORD) for n in self._args]
        )
        bound = sig.bind(*args, **kwargs)
        dt = np.dtype(dtype)
        if dt not in (np.dtype(np.float32), np.dtype(np.float64)):
            raise TypeError(f"dtype must be float32 or float64, not {dt}")
        values = []
        for n in self._args:
            v = bound.arguments[n]
            if np.ndim(v) != 0:
                raise ValueError(f"parameter `{n}` must be a scalar (one value per type)")
            values.append(float(v))
        _native.validate(self._path, values, dt == np.float32)
        self.dtype = dt
        self.values = tuple(float(dt.type(v)) for v in values)

    def __repr__(self):
        inner = ", ".join(f"{n}={v!r}" for n, v in zip(self._args, self.values))
        return f"{type(self).__name__}({inner})"

    def __eq__(self, other):
        return type(self) is type(other) and self.values == other.values

    def __hash__(self):
        return hash((type(self), self.values))


class _Method:
    """A kernel on a type: the flat function on the class, bound to the values on an instance."""

    def __init__(self, func, nbound):
        self.func = func
        self.nbound = nbound
        self.__doc__ = func.__doc__

    def __set_name__(self, owner, name):
        self.name = name

    def __get__(self, obj, owner=None):
        if obj is None or self.nbound == 0:
            return self.func
        func, values, n = self.func, obj.values, self.nbound
        names = func.arg_names[n:]
        sig = _signature(names)

        def method(*args, **kwargs):
            return func(*values, *args, **kwargs)

        method.__name__ = func.__name__
        method.__signature__ = sig
        method.__doc__ = func.__doc__
        return method


def build(package):
    """Creates the submodules of `package` (the `brdf` module) from the table."""
    table = _native.kernels()
    params = dict(_native.param_types())
    modules = {}

    def module(rust_path):
        if rust_path in modules:
            return modules[rust_path]
        dotted = f"{package.__name__}.{_rust_to_dotted(rust_path)}"
        m = types.ModuleType(dotted)
        m.__doc__ = _native.module_doc(rust_path) or f"brdf::{rust_path}"
        m.__all__ = []
        modules[rust_path] = m
        sys.modules[dotted] = m
        parent, _, leaf = rust_path.rpartition("::")
        owner = module(parent) if parent else package
        setattr(owner, leaf, m)
        if parent:
            owner.__all__.append(leaf)
        return m

    classes = {}
    methods = {}
    for index, info in enumerate(table):
        func = make_function(index, info)
        parts = info["path"].split("::")
        type_at = next((i for i, p in enumerate(parts) if p[:1].isupper()), None)
        if type_at is None:
            m = module("::".join(parts[:-1]))
            func.__module__ = m.__name__
            setattr(m, parts[-1], func)
            setattr(m, py_name(parts[-1]), func)
            m.__all__.append(py_name(parts[-1]))
        else:
            type_path = "::".join(parts[: type_at + 1])
            methods.setdefault(type_path, []).append((parts[-1], func))
    for type_path, funcs in methods.items():
        mod_path, _, name = type_path.rpartition("::")
        m = module(mod_path)
        ctor = tuple(params.get(type_path, ()))
        base = (Parameters,) if ctor else (object,)
        doc = next((f for _, f in funcs), None)
        ns = {"__module__": m.__name__, "_path": type_path, "_args": ctor}
        for leaf, func in funcs:
            nbound = len(ctor) if func.arg_names[: len(ctor)] == ctor else 0
            ns[leaf] = ns[py_name(leaf)] = _Method(func, nbound)
        cls = type(name, base, ns)
        cls.__doc__ = _class_doc(type_path, ctor, doc, table)
        classes[type_path] = cls
        setattr(m, name, cls)
        m.__all__.append(name)
    # Validated types without kernels of their own (tonemap's curve parameters).
    for type_path, ctor in params.items():
        if type_path in classes:
            continue
        mod_path, _, name = type_path.rpartition("::")
        m = module(mod_path)
        cls = type(
            name,
            (Parameters,),
            {"__module__": m.__name__, "_path": type_path, "_args": tuple(ctor)},
        )
        cls.__doc__ = _class_doc(type_path, tuple(ctor), None, table)
        classes[type_path] = cls
        setattr(m, name, cls)
        m.__all__.append(name)
    return modules, classes


def _class_doc(type_path, ctor, _func, table):
    type_doc = next(
        (
            t["type_doc"]
            for t in table
            if t["path"].startswith(type_path + "::") and t["type_doc"]
        ),
        None,
    )
    lines = [f"brdf::{type_path}"]
    if ctor:
        lines += [
            "",
            f"{type_path.rsplit('::', 1)[-1]}({', '.join(ctor)}, *, dtype=np.float64): the",
            "crate's constructor validates the values (rounded to dtype); ValueError names",
            "the parameter outside its domain. Instance methods take the remaining arguments.",
        ]
    else:
        lines += ["", "A namespace: its methods are the flat kernels, taking every argument."]
    if type_doc:
        lines += ["", type_doc]
    return "\n".join(lines)
