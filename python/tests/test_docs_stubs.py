"""Docstrings carry the Rust docs; the committed .pyi stubs are the generator's output."""

import pydoc
import tempfile
from pathlib import Path

import brdf
from brdf import _stubs

PACKAGE = Path(__file__).resolve().parents[1] / "py" / "brdf"

# Kernels whose Rust doc the build script cannot reach: methods of types a macro_rules!
# defines (phong), and trait methods whose impl and trait both lack a doc (they fall back
# to the type's doc). The list must not grow: a new kernel should have a doc comment.
NO_OWN_DOC = {
    "ggx::Ggx::d_visible",
    "beckmann::Beckmann::g2_correlated",
    "beckmann::Beckmann::g2_separable",
    "beckmann::Beckmann::d_visible",
    "phong::ClassicPhong::eval",
    "phong::ModifiedPhong::eval",
    "phong::NormalizedPhong::eval",
    "phong::BlinnPhong::eval",
    "phong::NormalizedBlinnPhong::eval",
    "phong::ApproxNormalizedBlinnPhong::eval",
}


def test_help_reads_like_the_rust_docs():
    text = pydoc.render_doc(brdf.ggx.d, renderer=pydoc.plaintext)
    assert "d(n_dot_h, alpha, *, dtype=None" in text
    assert "Walter" in text  # the source the Rust doc cites
    assert "alpha^2" in text or "a^2" in text or "alpha2" in text  # the formula
    assert "Dtypes:" in text and "n_dot_h" in text
    assert brdf.ggx.__doc__.startswith(brdf._native.module_doc("ggx")[:40])


def test_every_kernel_has_its_rust_doc_or_is_listed():
    missing = {k["path"] for k in brdf.KERNELS if not k["doc"]}
    assert missing <= NO_OWN_DOC, sorted(missing - NO_OWN_DOC)
    assert NO_OWN_DOC <= {k["path"] for k in brdf.KERNELS}
    for k in brdf.KERNELS:
        assert k["summary"] in brdf.kernel(k["path"]).__doc__


def test_stubs_are_valid_python_naming_every_kernel():
    import ast

    for path, text in _stubs.generate().items():
        ast.parse(text, filename=path)
    assert brdf.ggx.lambda_ is getattr(brdf.ggx, "lambda")  # a keyword gets a trailing _
    assert "def lambda_(" in _stubs.generate()["ggx.pyi"]


def test_stubs_are_current():
    with tempfile.TemporaryDirectory() as d:
        _stubs.write(d)
        fresh = {p.relative_to(d): p.read_text() for p in Path(d).rglob("*.pyi")}
    committed = {p.relative_to(PACKAGE): p.read_text() for p in PACKAGE.rglob("*.pyi")}
    stale = sorted(str(p) for p in fresh.keys() | committed.keys()
                   if fresh.get(p) != committed.get(p))
    assert not stale, f"regenerate with `python -m brdf._stubs`: {stale}"
