#!/usr/bin/env python3
"""Question answered: what does a kernel cost per element from Python, against the same
formula in plain numpy and in Mitsuba 3's scalar and LLVM variants?

Run from the repository root, in the venv where `pip install ./python` put brdf:

    python python/bench.py [--n 1000000] [--threads 1] [--mitsuba-python PATH]

For each formula it times brdf (float64 and float32; lanes, GIL released) on N random inputs
(fixed seed), a plain numpy version of the same formula (written here, as a user would) and,
where a Python with mitsuba is given (or `mitsuba` imports here), Mitsuba 3: the
`llvm_ad_rgb` variant on the whole batch (drjit, JIT compiled, warm) and the `scalar_rgb`
variant in a Python loop over N / 100 elements. Each time is the best of `--rounds` rounds
(the least disturbed by other load on the machine), in ns per element. Mitsuba runs in its own process (its venv), on the same inputs.

Formulas: GGX D(n.h, alpha) (`brdf.ggx.d`, Walter et al. 2007 eq. 33, correctly rounded: in
float64 through double-word arithmetic, its docs give the cost), the same in working precision
(`brdf.ggx.d_fast`, against the same numpy formula); Schlick's Fresnel
(`brdf.fresnel.schlick`); the exact dielectric Fresnel at eta = 1.5 (`brdf.fresnel.dielectric`,
Mitsuba `mi.fresnel`); GGX D of a direction (`brdf.ggx.Ggx.d`, Mitsuba
`MicrofacetDistribution.eval`).

`--threads 1` keeps brdf on one core (its `threads=False`) and drjit on one thread, the fair
comparison; `--threads 0` lets both use every core.
"""

import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np

ALPHA = 0.3
ETA = 1.5
F0 = 0.04


def timed(f, rounds):
    f()  # warm
    ts = []
    for _ in range(rounds):
        t = time.perf_counter()
        f()
        ts.append(time.perf_counter() - t)
    return min(ts)


def inputs(n, dtype):
    rng = np.random.default_rng(7)
    c = rng.random(n).astype(dtype)
    w = rng.normal(size=(3, n))
    w[2] = np.abs(w[2])
    w /= np.linalg.norm(w, axis=0)
    return c, w.astype(dtype)


def numpy_formulas(dtype):
    a = dtype(ALPHA)
    one = dtype(1)

    def ggx_d(c):
        a2 = a * a
        t = c * c * (a2 - one) + one
        return a2 / (dtype(np.pi) * t * t)

    def schlick(c):
        m = one - c
        m2 = m * m
        return dtype(F0) + (one - dtype(F0)) * (m2 * m2 * m)

    def dielectric(c):
        eta = dtype(ETA)
        s2 = (one - c * c) / (eta * eta)
        ct = np.sqrt(np.maximum(one - s2, 0))
        rs = (c - eta * ct) / (c + eta * ct)
        rp = (eta * c - ct) / (eta * c + ct)
        return np.where(s2 >= one, one, dtype(0.5) * (rs * rs + rp * rp))

    def ggx_d_dir(w):
        a2 = a * a
        t = (w[0] * w[0] + w[1] * w[1]) / a2 + w[2] * w[2]
        return np.where(w[2] > 0, one / (dtype(np.pi) * a2 * t * t), 0)

    return {"ggx_d": ggx_d, "ggx_d_fast": ggx_d, "schlick": schlick, "dielectric": dielectric,
            "ggx_d_dir": ggx_d_dir}


def brdf_formulas(threads):
    import brdf

    return {
        "ggx_d": lambda c: brdf.ggx.d(c, ALPHA, threads=threads),
        "ggx_d_fast": lambda c: brdf.ggx.d_fast(c, ALPHA, threads=threads),
        "schlick": lambda c: brdf.fresnel.schlick(c, F0, threads=threads),
        "dielectric": lambda c: brdf.fresnel.dielectric(c, ETA, threads=threads),
        "ggx_d_dir": lambda w: brdf.ggx.Ggx.d(ALPHA, ALPHA, w[0], w[1], w[2], threads=threads),
    }


MITSUBA_CHILD = r"""
import json, sys, time
import numpy as np
import drjit as dr, mitsuba as mi
n, rounds, threads, alpha, eta = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
rng = np.random.default_rng(7)
c = rng.random(n).astype(np.float32)
w = rng.normal(size=(3, n)); w[2] = np.abs(w[2]); w /= np.linalg.norm(w, axis=0); w = w.astype(np.float32)
out = {"version": mi.__version__}
def med(f):
    f(); ts = []
    for _ in range(rounds):
        t = time.perf_counter(); f(); ts.append(time.perf_counter() - t)
    return min(ts)
mi.set_variant("llvm_ad_rgb")
if threads:
    dr.set_thread_count(threads)
cf = mi.Float(c); wv = mi.Vector3f(mi.Float(w[0]), mi.Float(w[1]), mi.Float(w[2])); dr.eval(cf, wv)
ggx = mi.MicrofacetDistribution(mi.MicrofacetType.GGX, alpha, False)
def run(expr):
    def f():
        r = expr(); dr.eval(r); dr.sync_thread()
    return f
out["llvm"] = {
    "ggx_d_dir": med(run(lambda: ggx.eval(wv))) / n * 1e9,
    "dielectric": med(run(lambda: mi.fresnel(cf, eta)[0])) / n * 1e9,
}
mi.set_variant("scalar_rgb")
ggx = mi.MicrofacetDistribution(mi.MicrofacetType.GGX, alpha, False)
m = max(n // 100, 1000)
ws = [mi.Vector3f(float(w[0, i]), float(w[1, i]), float(w[2, i])) for i in range(m)]
cs = [float(x) for x in c[:m]]
def loop_d():
    for v in ws: ggx.eval(v)
def loop_f():
    for x in cs: mi.fresnel(x, eta)
out["scalar"] = {"ggx_d_dir": med(loop_d) / m * 1e9, "dielectric": med(loop_f) / m * 1e9}
print(json.dumps(out))
"""


def run_mitsuba(python, n, rounds, threads):
    env = dict(os.environ)
    env.setdefault("DRJIT_LIBLLVM_PATH", "/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1")
    r = subprocess.run(
        [python, "-c", MITSUBA_CHILD, str(n), str(rounds), str(threads), str(ALPHA), str(ETA)],
        capture_output=True, text=True, env=env, check=False,
    )
    if r.returncode != 0:
        print(f"mitsuba run failed:\n{r.stderr[-2000:]}", file=sys.stderr)
        return None
    return json.loads(r.stdout.strip().splitlines()[-1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--rounds", type=int, default=15)
    ap.add_argument("--threads", type=int, default=1, help="1: one core; 0: all cores")
    ap.add_argument("--mitsuba-python", default=None,
                    help="a Python with mitsuba installed (default: this one if it has it)")
    args = ap.parse_args()
    threads = args.threads != 1
    rows = {}
    for dtype in (np.float64, np.float32):
        c, w = inputs(args.n, dtype)
        np_f, br_f = numpy_formulas(dtype), brdf_formulas(threads)
        for name in np_f:
            x = w if name == "ggx_d_dir" else c
            t_np = timed(lambda: np_f[name](x), args.rounds) / args.n * 1e9
            t_br = timed(lambda: br_f[name](x), args.rounds) / args.n * 1e9
            rows.setdefault(name, {})[np.dtype(dtype).name] = (t_br, t_np)
    mi_py = args.mitsuba_python
    if mi_py is None:
        try:
            import mitsuba  # noqa: F401

            mi_py = sys.executable
        except ImportError:
            pass
    mi = run_mitsuba(mi_py, args.n, args.rounds, args.threads) if mi_py else None

    head = "| formula | brdf f64 | numpy f64 | brdf f32 | numpy f32 | Mitsuba LLVM (f32) | Mitsuba scalar (f32) |"
    print(f"ns per element, N = {args.n}, best of {args.rounds} rounds, "
          f"{'one core' if not threads else 'all cores'}"
          + (f", Mitsuba {mi['version']}" if mi else ", Mitsuba not found"))
    print()
    print(head)
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, r in rows.items():
        b64, n64 = r["float64"]
        b32, n32 = r["float32"]
        llvm = f"{mi['llvm'][name]:.2f}" if mi and name in mi["llvm"] else "-"
        scal = f"{mi['scalar'][name]:.0f}" if mi and name in mi["scalar"] else "-"
        print(f"| {name} | {b64:.2f} | {n64:.2f} | {b32:.2f} | {n32:.2f} | {llvm} | {scal} |")


if __name__ == "__main__":
    main()
