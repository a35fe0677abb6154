"""Broadcasting, the dtype rule, bad input: the NaN rule, ValueError, wrong shapes."""

import importlib

import numpy as np
import pytest

import brdf
from brdf import _native
from conftest import KERNEL_IDS, rows, same_bits


def test_broadcasting_matches_elementwise(dtype):
    c = np.linspace(0, 1, 5, dtype=dtype)[:, None]
    a = np.array([0.01, 0.3, 1.0], dtype=dtype)[None, :]
    got = brdf.ggx.d(c, a)
    assert got.shape == (5, 3) and got.dtype == dtype
    for i in range(5):
        for j in range(3):
            assert same_bits(got[i, j], brdf.ggx.d(c[i, 0], a[0, j]))


def test_multi_output_broadcast_and_named_fields():
    u = np.linspace(0.05, 0.95, 6)
    s = brdf.sampling.ggx_vndf(0.3, 0.3, 0.0, 0.0, 1.0, u[:, None], u[None, :])
    assert s._fields[-1] == "pdf" and s.pdf.shape == (6, 6)
    length = np.sqrt(s[0] ** 2 + s[1] ** 2 + s[2] ** 2)
    assert np.allclose(length, 1, atol=1e-12)


def test_non_contiguous_and_keyword_inputs():
    x = np.linspace(0, 1, 20)[::3]
    assert not x.flags.c_contiguous or x.strides[0] != 8
    want = np.array([brdf.ggx.d(v, 0.2) for v in x])
    assert same_bits(brdf.ggx.d(alpha=0.2, n_dot_h=x), want).all()
    fortran = np.asfortranarray(np.linspace(0, 1, 12).reshape(3, 4))
    assert same_bits(brdf.ggx.d(fortran, 0.2), brdf.ggx.d(np.ascontiguousarray(fortran), 0.2)).all()


def test_scalars_give_numpy_scalars_of_the_dtype():
    assert isinstance(brdf.ggx.d(0.5, 0.3), np.float64)
    assert isinstance(brdf.ggx.d(np.float32(0.5), 0.3), np.float32)
    assert brdf.ggx.d(np.float32(0.5), np.float32(0.3)) == np.float32(brdf.ggx.d(np.float32(0.5), 0.3))


def test_dtype_rule():
    f32 = np.linspace(0, 1, 4, dtype=np.float32)
    f64 = np.linspace(0, 1, 4)
    assert brdf.ggx.d(f32, 0.3).dtype == np.float32  # a Python float adopts float32
    assert brdf.ggx.d(f32, np.array([1, 0, 1, 0])).dtype == np.float32  # int arrays too
    assert brdf.ggx.d(f64, 0.3).dtype == np.float64
    assert brdf.ggx.d(0.5, 1).dtype == np.float64  # no float input: float64
    with pytest.raises(TypeError, match="float32 and float64"):
        brdf.ggx.d(f32, f64)
    with pytest.raises(TypeError, match="float32 and float64"):
        brdf.ggx.d(f32, np.float64(0.3))
    assert brdf.ggx.d(f32, f64, dtype=np.float32).dtype == np.float32
    assert brdf.ggx.d(f32, f64, dtype="float64").dtype == np.float64
    with pytest.raises(TypeError, match="float16"):
        brdf.ggx.d(f32.astype(np.float16), 0.3)
    with pytest.raises(TypeError):
        brdf.ggx.d(f32, 0.3, dtype=np.int32)
    # float32 results are the f32 kernel, not a rounded f64 result.
    x = np.float32(0.7)
    assert brdf.ggx.d(x, np.float32(0.05)) == np.float32(_native.eval_row(
        brdf.ggx.d.index, [float(x), float(np.float32(0.05))], True, True)[0])


def test_wrong_shapes_and_arity():
    with pytest.raises(ValueError, match="do not broadcast.*n_dot_h: \\(3,\\).*alpha: \\(4,\\)"):
        brdf.ggx.d(np.zeros(3), np.zeros(4))
    with pytest.raises(TypeError):
        brdf.ggx.d(0.5)
    with pytest.raises(TypeError):
        brdf.ggx.d(0.5, 0.3, 0.1)
    with pytest.raises(TypeError):
        brdf.ggx.d(0.5, 0.3, bogus=1)
    empty = brdf.ggx.d(np.zeros((0, 3)), 0.3)
    assert empty.shape == (0, 3)


# The crate's own exemptions (tests/kernels/bad_input.rs): V3's component-wise min and max
# follow Real::min / Real::max, which return the other operand for one NaN.
NAN_EXEMPT = {("vec3::V3::min", "o_"), ("vec3::V3::max", "o_")}


@pytest.mark.parametrize("index", range(len(brdf.KERNELS)), ids=KERNEL_IDS)
def test_nan_in_any_argument_gives_nan(index, dtype):
    # The crate's rule (tests/kernels/bad_input.rs): a NaN in any input gives NaN out, on
    # every float type; the binding must carry it through unchanged. A kernel with one
    # output returns NaN; one with several returns NaN in the outputs the argument feeds
    # (an RGB kernel's red input, its red output), so at least one.
    info = brdf.KERNELS[index]
    f = brdf.kernel(info["path"])
    cols = rows(info, 8, dtype, seed=index)
    other = rows(info, 8, dtype, seed=index + 10_000)
    clean = f(*cols)
    clean = [clean] if len(info["outputs"]) == 1 else list(clean)
    for i, arg in enumerate(info["args"]):
        if (info["path"], arg[0][:2]) in NAN_EXEMPT:
            continue
        # An argument the outputs do not depend on here (cos_theta reads w_z alone, a
        # fallback direction serves zero vectors only) owes no NaN.
        moved = list(cols)
        moved[i] = other[i]
        m = f(*moved)
        m = [m] if len(info["outputs"]) == 1 else list(m)
        if all(same_bits(a, b).all() for a, b in zip(m, clean)):
            continue
        bad = [c.copy() for c in cols]
        bad[i][3] = np.nan
        out = f(*bad)
        out = [out] if len(info["outputs"]) == 1 else list(out)
        assert any(np.isnan(o[3]) for o in out), (info["path"], arg[0])
        # The other rows are untouched by their neighbour's NaN (the lanes are independent).
        for o, c in zip(out, clean):
            assert same_bits(np.delete(o, 3), np.delete(c, 3)).all(), info["path"]


def test_check_names_the_argument_outside_its_domain():
    with pytest.raises(ValueError, match="`alpha` = -0.5 \\(element 1\\) lies outside its domain"):
        brdf.ggx.d(0.5, [0.1, -0.5], check=True)
    with pytest.raises(ValueError, match="`n_dot_h`"):
        brdf.ggx.d(np.nan, 0.3, check=True)
    with pytest.raises(ValueError, match="m_x, m_y, m_z .*length"):
        brdf.ggx.Ggx.d(0.3, 0.3, 0.8, 0.0, 0.8, check=True)
    # An ordering between arguments, the table's own relation.
    spot = brdf.lights.spot_cone
    names = spot.arg_names
    assert "cos_outer" in names and "cos_inner" in names
    ok = dict(cos_angle=0.9, cos_outer=0.8, cos_inner=0.95)
    spot(*[ok[n] for n in names], check=True)
    bad = dict(ok, cos_outer=0.99)
    with pytest.raises(ValueError, match="cos_outer"):
        spot(*[bad[n] for n in names], check=True)
    assert np.isnan(spot(*[bad[n] for n in names]))  # unchecked: the crate's rule, NaN
    with pytest.raises(ValueError, match="`model`"):
        brdf.sampling.d_cos_pdf(0.5, 0.3, 0.3, 0.0, 0.0, 1.0, check=True)
    assert np.isfinite(brdf.ggx.d(0.5, 0.3, check=True))


def test_unchecked_invalid_parameter_gives_nan():
    assert np.isnan(brdf.ggx.Ggx.d(-1.0, 0.3, 0.0, 0.0, 1.0))


@pytest.mark.parametrize("threads", [False, True])
def test_an_invalid_element_leaves_its_lane_neighbours_alone(dtype, threads):
    # `Ggx::new` on lanes is NaN in every lane when one lane's alpha is invalid; the array
    # loop evaluates such lanes again alone, so only the invalid element is NaN.
    n = 70_001 if threads else 19  # above the threading threshold, or a few lane groups
    alpha_x = np.full(n, 0.3, dtype)
    bad = [2, 9, n - 1]
    alpha_x[bad] = -1.0
    got = brdf.ggx.Ggx.d(alpha_x, 0.5, 0.0, 0.6, 0.8, threads=threads)
    assert np.isnan(got[bad]).all()
    ok = np.ones(n, bool)
    ok[bad] = False
    want = brdf.ggx.Ggx.d(dtype(0.3), 0.5, 0.0, 0.6, 0.8)
    assert same_bits(got[ok], np.full(n - len(bad), want, dtype)).all()


PARAM_TYPES = dict(_native.param_types())


@pytest.mark.parametrize("type_path", sorted(PARAM_TYPES))
def test_parameter_types_validate_and_name_the_parameter(type_path):
    names = PARAM_TYPES[type_path]
    mod, _, name = type_path.rpartition("::")
    cls = getattr(importlib.import_module("brdf." + mod.replace("::", ".")), name)
    good = {
        "tonemap::HableParams": [0.15, 0.5, 0.1, 0.2, 0.02, 0.3, 11.2, 2.0],
        "tonemap::LottesParams": [1.6, 0.977, 8.0, 0.18, 0.267],
        "lights::SpotCone": [0.3, 0.6],
    }.get(type_path, [0.5] * len(names))
    p = cls(*good)
    assert p.values == tuple(good)
    for i, n in enumerate(names):
        bad = list(good)
        bad[i] = np.nan
        rust_name = "base_color" if n.startswith("base_color") else n
        with pytest.raises(ValueError, match=f"invalid parameter `{rust_name}`"):
            cls(*bad)


def test_bound_methods_equal_the_flat_kernels():
    g = brdf.ggx.Ggx(0.2, 0.4)
    m = np.array([[0.0, 0.0, 1.0], [0.6, 0.0, 0.8]])
    assert same_bits(g.d(m[:, 0], m[:, 1], m[:, 2]), brdf.ggx.Ggx.d(0.2, 0.4, m[:, 0], m[:, 1], m[:, 2])).all()
    e = brdf.diffuse.Eon(0.8, 0.5)
    assert e.eval(0, 0, 1, 0, 0, 1) == brdf.diffuse.Eon.eval(0.8, 0.5, 0, 0, 1, 0, 0, 1)
    with pytest.raises(ValueError, match="`sigma`"):
        brdf.diffuse.Eon(0.8, 2.0)
    with pytest.raises(ValueError, match="scalar"):
        brdf.ggx.Ggx([0.1, 0.2], 0.3)
    # float32 validation: a width finite in f64 but not in f32.
    brdf.ggx.Ggx(1e39, 0.3)
    with pytest.raises(ValueError, match="alpha_x"):
        brdf.ggx.Ggx(1e39, 0.3, dtype=np.float32)
