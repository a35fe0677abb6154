"""Every kernel of the table, called from Python on arrays, equals the Rust call on each row
through the table's own entries (the route the reference CLI takes) bit for bit, in float64
and float32, on the lane path and on the scalar path."""

import numpy as np
import pytest

import brdf
from brdf import _native
from conftest import KERNEL_IDS, rows, same_bits

N = 37  # not a multiple of 8 or 4: the lanes' tail is exercised


@pytest.mark.parametrize("index", range(len(brdf.KERNELS)), ids=KERNEL_IDS)
@pytest.mark.parametrize("lanes", [True, False], ids=["lanes", "scalar"])
def test_kernel_equals_rust_row_by_row(index, lanes, dtype):
    info = brdf.KERNELS[index]
    f = brdf.kernel(info["path"])
    cols = rows(info, N, dtype, seed=index)
    got = f(*cols, lanes=lanes)
    got = [got] if len(info["outputs"]) == 1 else list(got)
    assert all(g.dtype == dtype and g.shape == (N,) for g in got)
    f32 = dtype == np.float32
    for r in range(N):
        want = _native.eval_row(index, [float(c[r]) for c in cols], f32, lanes)
        for name, g, w in zip(f.output_names, got, want):
            assert same_bits(g[r], w), (info["path"], name, r, [c[r] for c in cols], g[r], w)


def test_every_table_kernel_is_reachable_by_its_dotted_path():
    for info in brdf.KERNELS:
        obj = brdf
        for part in info["path"].split("::"):
            obj = getattr(obj, part)
        assert obj.path == info["path"]
        assert callable(obj)
    assert len(brdf.KERNELS) > 200


def test_lanes_and_scalars_agree_on_most_kernels():
    # The crate's promise: lanes equal scalars bit for bit except the kernels using the lane
    # polynomials (cli/tests/cli/lanes.rs lists about 50). A binding that mixed up the entries
    # or the lane order would break this on nearly every kernel.
    differ = []
    for index, info in enumerate(brdf.KERNELS):
        f = brdf.kernel(info["path"])
        cols = rows(info, 64, np.float64, seed=1000 + index)
        a, b = f(*cols, lanes=True), f(*cols, lanes=False)
        a = [a] if len(info["outputs"]) == 1 else list(a)
        b = [b] if len(info["outputs"]) == 1 else list(b)
        if not all(same_bits(x, y).all() for x, y in zip(a, b)):
            differ.append(info["path"])
    assert len(differ) < 80, differ


def test_threads_split_gives_the_same_bits(dtype):
    n = 200_003  # above the threading threshold, not a multiple of the chunk
    rng = np.random.default_rng(5)
    c = rng.random(n).astype(dtype)
    alpha = rng.random(n).astype(dtype)
    a = brdf.ggx.d(c, alpha, threads=True)
    b = brdf.ggx.d(c, alpha, threads=False)
    assert same_bits(a, b).all()
    # The broadcast-scalar path over threads.
    assert same_bits(brdf.ggx.d(c, 0.3, threads=True), brdf.ggx.d(c, 0.3, threads=False)).all()
