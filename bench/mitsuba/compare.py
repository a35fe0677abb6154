#!/usr/bin/env python3
"""Question answered: how long do brdf's f32x8 kernels take against Mitsuba 3's LLVM JIT on
the same batch of directions, on one core, in the same run?

Run (setup in README.md, beside this file): `python3 bench/mitsuba/compare.py` from the
repository root. It

1. writes N (default 10^7) random view and light directions, uniform on the upper hemisphere
   (numpy, fixed seed), as six f32 structure-of-arrays slices to a raw file (vx, vy, vz,
   lx, ly, lz);
2. builds brdf's throughput benchmark with `-C target-cpu=native` (its timing mode reads that
   file; benches/throughput.rs documents it);
3. times, round after round (interleaved: one Mitsuba evaluation of each kernel, then one
   timed brdf run of each), the kernels below, each warm (compiled and cached before the
   first timed round), and prints the median of the rounds:
   - GGX D of the view direction taken as the microfacet normal m:
     Mitsuba `MicrofacetDistribution(GGX, alpha).eval(m)`, brdf `ggx::d(m.z, alpha)`;
   - Beckmann D, the same with `MicrofacetType.Beckmann` and `beckmann::d`;
   - the rough conductor, one channel, f cos(theta_l) as a BSDF evaluation returns it:
     Mitsuba D(h) G(v, l, h) F_conductor(v.h, eta + i k) / (4 cos(theta_v)) with its
     distribution's `eval` and `G` and `mi.fresnel_conductor` (the arithmetic of its
     `roughconductor` plugin's `eval`), brdf `cook_torrance::ggx_conductor_local` (D V F from
     the two directions, D from the half vector's components) times n.l;
   - beside each, brdf's working-precision variant against the same Mitsuba time:
     `ggx::d_fast`, `beckmann::d_fast`, `cook_torrance::ggx_conductor_local_fast` (their
     error against the exact forms is in their docs), and for the rough conductor the
     dot-product route too (`half_vector`, then `cook_torrance::ggx` with `fresnel::conductor`,
     or `half_cosines` with `ggx::d_fast` and `fresnel::conductor_fast`), whose D reads n.h
     alone;
   - the copy floor: brdf's `copy_from_slice` of one input slice into the output slice;
   - a yardstick row: GGX D in plain working precision (defined in benches/throughput.rs,
     not a brdf kernel), to show what brdf's correctly rounded `ggx::d` costs.

The whole process (Python, drjit's worker and the brdf binary) is pinned to one core with
`taskset -c 0` and drjit runs one thread. Each side is timed by its CPU clock (`--clock cpu`,
the default: Python's `process_time`, which counts drjit's worker thread and the tracing,
and the brdf thread's own), which leaves out the time spent waiting for the core on a shared
machine; `--clock wall` times elapsed time, as `--parallel` always does. Absolute times move
from run to run (and on a shared machine by much more); the ratio column, from one
interleaved run, is the figure to quote. `--sizes` prints instead ns per element for batches
of 10^3 up to `--n` elements on both sides.

Differences the ratio carries: Mitsuba's `eval(m)` reads the three components of m (12 bytes
per element), brdf's D the cosine only (4 bytes); Mitsuba's G is the separable Smith
G1(v) G1(l), brdf's V the height-correlated form (the values differ by design: the script
prints the median ratio of the two results). Mitsuba's times include tracing the expression in
Python (a fraction of a millisecond per kernel).
"""

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import reference as ref

ALPHA = 0.3
ETA, K = 0.2, 3.0
KERNELS = ["ggx_d", "beckmann_d", "rough_conductor"]
# brdf's working-precision variants, each timed against the same Mitsuba kernel as its exact form.
FAST = {"ggx_d_fast": "ggx_d", "beckmann_d_fast": "beckmann_d",
        "rough_conductor_fast": "rough_conductor"}
# The dot-product route of the rough conductor (D from n.h alone), kept for comparison.
COSINES = {"rough_conductor_cosines": "rough_conductor",
           "rough_conductor_cosines_fast": "rough_conductor"}
LABELS = {
    "ggx_d": "GGX D",
    "beckmann_d": "Beckmann D",
    "rough_conductor": "rough conductor: D, G, complex Fresnel, times cos (1 channel), "
                       "`cook_torrance::ggx_conductor_local`",
    "ggx_d_fast": "GGX D, `ggx::d_fast` (working precision)",
    "beckmann_d_fast": "Beckmann D, `beckmann::d_fast` (working precision)",
    "rough_conductor_fast": "rough conductor, `ggx_conductor_local_fast` (working precision)",
    "rough_conductor_cosines": "rough conductor by the cosines: `half_vector`, `cook_torrance::ggx`, "
                               "`fresnel::conductor` (D from n.h alone)",
    "rough_conductor_cosines_fast": "the same with `d_fast`, `conductor_fast`, `half_cosines`",
}


def pin_to_one_core(args):
    """Re-runs this script under `taskset -c 0` unless already on one core."""
    if args.no_pin or len(os.sched_getaffinity(0)) == 1:
        return
    if shutil.which("taskset") is None:
        print("taskset not found: running unpinned", file=sys.stderr)
        return
    os.execvp("taskset", ["taskset", "-c", "0", sys.executable, *sys.argv])


def write_directions(path, n, seed):
    """n view and n light directions uniform on the upper hemisphere, six f32 SoA slices."""
    rng = np.random.default_rng(seed)
    arrays = []
    for _ in range(2):
        z = rng.random(n)
        phi = 2.0 * np.pi * rng.random(n)
        s = np.sqrt((1.0 - z) * (1.0 + z))
        arrays += [s * np.cos(phi), s * np.sin(phi), z]
    soa = np.stack(arrays).astype("<f4")
    soa.tofile(path)
    return soa


def build_brdf(repo, target_dir):
    """Builds benches/throughput.rs with -C target-cpu=native and returns its executable."""
    env = dict(os.environ)
    env["RUSTFLAGS"] = (env.get("RUSTFLAGS", "") + " -C target-cpu=native").strip()
    env["CARGO_TARGET_DIR"] = target_dir
    cmd = ["cargo", "bench", "-p", "brdf-bench", "--bench", "throughput", "--no-run", "--message-format=json"]
    out = subprocess.run(cmd, cwd=repo, env=env, check=True, capture_output=True, text=True)
    for line in out.stdout.splitlines():
        msg = json.loads(line)
        if msg.get("reason") == "compiler-artifact" and msg["target"]["name"] == "throughput":
            if msg.get("executable"):
                return msg["executable"]
    raise RuntimeError("cargo did not report the throughput executable")


CLOCK = {"clock": "cpu"}


def run_brdf(exe, raw, runs, out_dir=None, parallel=False, only=None):
    """One brdf timing run: {kernel: [ms, ...]}; over all cores (`batch::par_run_f32`) when
    `parallel`; only the kernels in `only` when given."""
    env = dict(os.environ, BRDF_THROUGHPUT_INPUT=raw, BRDF_THROUGHPUT_RUNS=str(runs),
               BRDF_THROUGHPUT_PARALLEL="1" if parallel else "0",
               BRDF_THROUGHPUT_CLOCK=CLOCK["clock"])
    if only:
        env["BRDF_THROUGHPUT_ONLY"] = ",".join(only)
    if out_dir:
        env["BRDF_THROUGHPUT_OUTPUT"] = out_dir
    out = subprocess.run([exe], env=env, check=True, capture_output=True, text=True)
    times = {}
    for line in out.stdout.splitlines():
        tag, name, ms = line.split()
        if tag == "time":
            times.setdefault(name, []).append(float(ms))
    return times


def mitsuba_kernels(soa, variant, threads):
    """Mitsuba's kernels as functions returning an unevaluated drjit array."""
    import drjit as dr
    import mitsuba as mi

    mi.set_variant(variant)
    dr.set_thread_count(threads)
    vx, vy, vz, lx, ly, lz = (mi.Float(a) for a in soa)
    v, l = mi.Vector3f(vx, vy, vz), mi.Vector3f(lx, ly, lz)
    dr.eval(v, l)
    ggx = mi.MicrofacetDistribution(mi.MicrofacetType.GGX, ALPHA, False)
    beckmann = mi.MicrofacetDistribution(mi.MicrofacetType.Beckmann, ALPHA, False)
    eta = mi.Complex2f(ETA, K)

    def rough_conductor():
        h = dr.normalize(v + l)
        d = ggx.eval(h)
        g = ggx.G(v, l, h)
        f = mi.fresnel_conductor(dr.dot(v, h), eta)
        value = d * g * f / (4.0 * v.z)
        return dr.select((v.z > 0) & (l.z > 0), value, 0.0)

    kernels = {
        "ggx_d": lambda: ggx.eval(v),
        "beckmann_d": lambda: beckmann.eval(v),
        "rough_conductor": rough_conductor,
    }
    versions = {"mitsuba": mi.__version__, "drjit": dr.__version__, "variant": variant,
                "threads": dr.thread_count()}
    return kernels, versions


def measure_accuracy(soa, mi_values, brdf_values, n_check, seed):
    """{(side, row): (max ULP, median ULP, max relative error, worst element)} of each side's
    f32 results against its float64 reference over every element; then mpmath checks the
    float64 references on n_check random elements and each row's ten worst, and prints the
    largest disagreement (in f32 ULP; it must be far below the errors reported)."""
    vx, vy, vz, lx, ly, lz = (a.astype(np.float64) for a in soa)
    v, l = (vx, vy, vz), (lx, ly, lz)
    a = np.float32(ALPHA).astype(np.float64)
    eta, k = float(np.float32(ETA)), float(np.float32(K))
    refs64 = {
        "ggx_d": (lambda: ref.ggx_d_vec_f64(vx, vy, vz, a),
                  lambda: ref.ggx_d_cos_f64(vz, a)),
        "beckmann_d": (lambda: ref.beckmann_d_vec_f64(vx, vy, vz, a),
                       lambda: ref.beckmann_d_cos_f64(vz, a)),
        "rough_conductor": (lambda: ref.rough_conductor_mitsuba_f64(v, l, a, eta, k),
                            lambda: ref.rough_conductor_brdf_f64(v, l, a, eta, k)),
    }
    refs_mp = {
        "ggx_d": (lambda i: ref.ggx_d_vec_mp(vx[i], vy[i], vz[i], a),
                  lambda i: ref.ggx_d_cos_mp(vz[i], a)),
        "beckmann_d": (lambda i: ref.beckmann_d_vec_mp(vx[i], vy[i], vz[i], a),
                       lambda i: ref.beckmann_d_cos_mp(vz[i], a)),
        "rough_conductor": (
            lambda i: ref.rough_conductor_mitsuba_mp([t[i] for t in v], [t[i] for t in l],
                                                     a, eta, k),
            lambda i: ref.rough_conductor_brdf_mp([t[i] for t in v], [t[i] for t in l],
                                                  a, eta, k)),
    }
    out, worst_of = {}, {}
    for name in KERNELS:
        r_mi, r_brdf = refs64[name][0](), refs64[name][1]()
        rows = [("mitsuba", name, np.asarray(mi_values[name], np.float32), r_mi, 0)]
        extra = {"ggx_d": ("ggx_d_plain",), "rough_conductor": tuple(COSINES)}.get(name, ())
        for row in (name, name + "_fast") + extra:
            if row in brdf_values:
                rows.append(("brdf", row, brdf_values[row], r_brdf, 1))
        for side, row, x, r, which in rows:
            ulp, rel, sub = ref.errors(x, r)
            abs_sub = float(np.abs(x[sub].astype(np.float64) - r[sub]).max()) if sub.any() else 0.0
            ulp, rel = np.where(sub, 0.0, ulp), np.where(sub, 0.0, rel)
            order = np.argsort(ulp)[::-1]
            out[(side, row)] = (float(ulp.max()), float(np.median(ulp[~sub])), float(rel.max()),
                                int(order[0]), int(sub.sum()), abs_sub)
            worst_of.setdefault((name, which), set()).update(int(i) for i in order[:10])
    rng = np.random.default_rng(seed + 1)
    sample = set(int(i) for i in rng.choice(len(vz), size=min(n_check, len(vz)), replace=False))
    for name in KERNELS:
        for which, side in ((0, "Mitsuba's"), (1, "brdf's")):
            r64 = refs64[name][which]()
            idx = sorted(sample | worst_of.get((name, which), set()))
            dev = 0.0
            for i in idx:
                rm = refs_mp[name][which](i)
                if rm != 0:
                    dev = max(dev, float(abs(r64[i] - rm)) / float(ref.ulp_f32(float(rm))))
            print(f"# reference check: float64 against mpmath, {side} {name}: "
                  f"max {dev:.2g} f32 ULP over {len(idx)} elements")
    return out


def time_mitsuba(kernel):
    """(ms, result) of one evaluation: by this process's CPU clock (all its threads: Python's
    tracing and drjit's worker) under `--clock cpu`, else by the wall clock."""
    import drjit as dr

    clock = time.process_time if CLOCK["clock"] == "cpu" else time.perf_counter
    t = clock()
    r = kernel()
    dr.eval(r)
    dr.sync_thread()
    return (clock() - t) * 1e3, r


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--n", type=int, default=10_000_000, help="batch size")
    p.add_argument("--rounds", type=int, default=7, help="interleaved rounds (median)")
    p.add_argument("--seed", type=int, default=13)
    p.add_argument("--variant", default="llvm_ad_rgb", help="Mitsuba variant (an llvm_* one)")
    p.add_argument("--threads", type=int, default=1, help="drjit worker threads")
    p.add_argument("--brdf-exe", help="a built throughput bench binary (skips the build)")
    p.add_argument("--target-dir", default="target/native", help="CARGO_TARGET_DIR of the build")
    p.add_argument("--no-pin", action="store_true", help="do not pin to core 0")
    p.add_argument("--parallel", action="store_true",
                   help="all cores, unpinned: drjit with one worker per core, brdf through "
                        "batch::par_run_f32 (rayon), and brdf on one thread beside it")
    p.add_argument("--check", type=int, default=1000,
                   help="elements on which mpmath checks the float64 reference")
    p.add_argument("--clock", choices=["cpu", "wall"], default="cpu",
                   help="cpu (default): each side's CPU time, which leaves out the time it "
                        "waited for a core on a shared machine; wall: elapsed time (always "
                        "with --parallel)")
    p.add_argument("--sizes", action="store_true",
                   help="instead of the main table: ns per element for batches of 10^3 to "
                        "--n elements, both sides, one core")
    args = p.parse_args()
    CLOCK["clock"] = args.clock
    if args.parallel:
        args.no_pin = True
        args.threads = len(os.sched_getaffinity(0))
        CLOCK["clock"] = "wall"
    pin_to_one_core(args)
    repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    exe = args.brdf_exe or build_brdf(repo, os.path.join(repo, args.target_dir))
    if args.sizes:
        return batch_sizes(exe, args)

    with tempfile.TemporaryDirectory() as tmp:
        raw = os.path.join(tmp, "directions.f32")
        soa = write_directions(raw, args.n, args.seed)
        kernels, versions = mitsuba_kernels(soa, args.variant, args.threads)
        print(f"# {versions}, n = {args.n}, rounds = {args.rounds}, "
              f"cpus = {sorted(os.sched_getaffinity(0))}, clock = {CLOCK['clock']}, "
              f"load average = {os.getloadavg()}")

        # Warm: Mitsuba compiles and caches each kernel; brdf writes its values once.
        mi_values = {name: np.asarray(time_mitsuba(k)[1]) for name, k in kernels.items()}
        run_brdf(exe, raw, 1, out_dir=tmp)
        brdf_values = {}
        for name in KERNELS + list(FAST) + ["ggx_d_plain"] + list(COSINES):
            path = os.path.join(tmp, f"{name}.f32")
            if os.path.exists(path):
                brdf_values[name] = np.fromfile(path, dtype="<f4")
        for name, ours in brdf_values.items():
            theirs = mi_values[{**FAST, **COSINES, "ggx_d_plain": "ggx_d"}.get(name, name)]
            theirs = theirs.astype(np.float64)
            ok = theirs > 0
            ratio = ours[ok] / theirs[ok]
            print(f"# values {name}: brdf / Mitsuba median {np.median(ratio):.6f}, "
                  f"range [{ratio.min():.4g}, {ratio.max():.4g}] over {ok.sum()} elements")
        # The errors do not depend on the thread count: --parallel skips them (at 10^7
        # elements they take minutes).
        accuracy = ({} if args.parallel else
                    measure_accuracy(soa, mi_values, brdf_values, args.check, args.seed))
        material_err = {}
        path = os.path.join(tmp, "material_gltf.f32")
        if os.path.exists(path):
            exact = np.fromfile(path, dtype="<f4").astype(np.float64)
            for row in ("material_textbook_scalar", "material_textbook_inlined", "material_gltf",
                        "material_gltf_fast"):
                p2 = os.path.join(tmp, f"{row}.f32")
                if os.path.exists(p2):
                    ulp, _, sub = ref.errors(np.fromfile(p2, dtype="<f4"), exact)
                    ulp = ulp[~sub]
                    material_err[row] = (float(ulp.max()), float(np.median(ulp)))

        mi_ms = {name: [] for name in KERNELS}
        brdf_ms = {name: [] for name in KERNELS + list(FAST) + ["ggx_d_plain", "copy"]}
        brdf1_ms = {}
        for _ in range(args.rounds):
            for name in KERNELS:
                mi_ms[name].append(time_mitsuba(kernels[name])[0])
            for name, ms in run_brdf(exe, raw, 1, parallel=args.parallel).items():
                # Rows the table does not show (a borrowing-closure variant) are kept for the
                # per-round listing.
                brdf_ms.setdefault(name, []).extend(ms)
            if args.parallel:
                for name, ms in run_brdf(exe, raw, 1).items():
                    brdf1_ms.setdefault(name, []).extend(ms)

    med = {k: statistics.median(v) for k, v in brdf_ms.items() if v}
    copy = med["copy"]
    print(f"\n| kernel ({args.n:.0e} elements) | Mitsuba 3 | brdf f32x8 | brdf / Mitsuba "
          f"| brdf / copy |")
    print("|---|---|---|---|---|")

    def cell(ms, acc):
        if acc is None:
            return f"{ms:.2f} ms"
        return f"{ms:.2f} ms at {acc[0]:.3g} ULP (median {acc[1]:.2g})"

    for name in KERNELS:
        m, b = statistics.median(mi_ms[name]), med[name]
        mi_acc = accuracy.get(("mitsuba", name))
        rows = [(LABELS[name], name)]
        if med.get(name + "_fast") is not None:
            rows.append((LABELS[name + "_fast"], name + "_fast"))
        if name == "ggx_d" and "ggx_d_plain" in med:
            rows.append(("GGX D in working precision (bench-local yardstick, not a brdf kernel)",
                         "ggx_d_plain"))
        if name == "rough_conductor":
            rows += [(LABELS[r], r) for r in COSINES if r in med and ("brdf", r) in accuracy]
        for label, row in rows:
            b = med[row]
            print(f"| {label} | {cell(m, mi_acc)} | {cell(b, accuracy.get(('brdf', row)))} "
                  f"| {b / m:.2f} | {b / copy:.2f} |")
    print(f"| copy (floor) | | {copy:.2f} ms | | 1.00 |")

    if "material_textbook_scalar" in med and "material_gltf" in med:
        t = med["material_textbook_scalar"]
        print(f"\n| glTF material ({args.n:.0e} elements, RGB, from the directions) | time "
              f"| ns per element | textbook scalar f32 (one call per element) / this "
              f"| textbook inlined / this | against the exact tier (red) |")
        print("|---|---|---|---|---|---|")
        ti = med.get("material_textbook_inlined", float("nan"))
        for row, label in (("material_textbook_scalar",
                            "textbook scalar f32 (Filament's surface_brdf.fs forms), one call "
                            "per element"),
                           ("material_textbook_inlined",
                            "the same textbook f32, inlined in the loop (LLVM may vectorize it)"),
                           ("material_gltf", "`material::gltf`, f32x8 (exact tier)"),
                           ("material_gltf_fast", "`material::gltf_fast`, f32x8 (working precision)")):
            if row not in med:
                continue
            b = med[row]
            mx, md = material_err.get(row, (0.0, 0.0))
            print(f"| {label} | {b:.2f} ms | {b * 1e6 / args.n:.2f} | {t / b:.2f} | {ti / b:.2f} "
                  f"| max {mx:.3g} ULP, median {md:.2g} |")
    if args.parallel:
        print(f"\n| kernel, all {args.threads} cores ({args.n:.0e} elements) | Mitsuba 3, "
              f"{args.threads} threads | brdf, batch::par_run_f32 | brdf, one thread "
              f"| brdf speed-up | brdf / Mitsuba |")
        print("|---|---|---|---|---|---|")
        for name in KERNELS + list(FAST):
            if name not in med or name not in brdf1_ms:
                continue
            m = statistics.median(mi_ms[FAST.get(name, name)])
            b, b1 = med[name], statistics.median(brdf1_ms[name])
            print(f"| {LABELS[name]} | {m:.2f} ms | {b:.2f} ms | {b1:.2f} ms | {b1 / b:.2f} "
                  f"| {b / m:.2f} |")
    print("\nULP: each result against the function it computes, evaluated exactly on the same "
          "f32 inputs (bench/mitsuba/reference.py): max and median over all "
          f"{args.n} elements whose exact value is 0 or a normal f32; max relative error; "
          "elements whose exact value is subnormal (below 1.2e-38), and the largest absolute "
          "error there:")
    for (side, name), (mx, md, rel, worst, n_sub, abs_sub) in accuracy.items():
        print(f"#   {side:7s} {name:22s} max {mx:10.4g} ULP  median {md:8.3g}  "
              f"max rel {rel:.3g}  (worst element {worst}); subnormal: {n_sub}, "
              f"max abs error {abs_sub:.3g}")
    print("\n# every round (ms):")
    for name in KERNELS:
        print(f"#   mitsuba {name}: {' '.join(f'{x:.2f}' for x in mi_ms[name])}")
    for name, v in brdf_ms.items():
        print(f"#   brdf {name}: {' '.join(f'{x:.2f}' for x in v)}")


def batch_sizes(exe, args):
    """ns per element of each kernel (exact and fast rows, and the copy) for batches of 10^3 up
    to args.n elements, both sides, interleaved round by round, medians: where per-call costs
    (Mitsuba's tracing and kernel launch, brdf's none) give way to arithmetic, and that to the
    memory floor."""
    sizes = []
    n = 1000
    while n <= args.n:
        sizes.append(n)
        n *= 10
    names = KERNELS + list(FAST)
    print(f"\n| kernel: ns per element (Mitsuba 3 / brdf f32x8) | "
          + " | ".join(f"{s:.0e}" for s in sizes) + " |")
    print("|---|" + "---|" * len(sizes))
    cells = {name: [] for name in names + ["copy"]}
    for size in sizes:
        with tempfile.TemporaryDirectory() as tmp:
            raw = os.path.join(tmp, "directions.f32")
            soa = write_directions(raw, size, args.seed)
            kernels, _ = mitsuba_kernels(soa, args.variant, args.threads)
            for k in kernels.values():
                time_mitsuba(k)
            # Small batches take microseconds: many repetitions per round.
            reps = max(1, min(200, 10_000_000 // (size * 10)))
            mi = {name: [] for name in KERNELS}
            br = {}
            for _ in range(args.rounds):
                for name in KERNELS:
                    mi[name].append(min(time_mitsuba(kernels[name])[0] for _ in range(reps)))
                for name, ms in run_brdf(exe, raw, reps, only=names + ["copy"]).items():
                    br.setdefault(name, []).append(min(ms))
            for name in names + ["copy"]:
                b = statistics.median(br[name]) * 1e6 / size
                if name == "copy":
                    cells[name].append(f"- / {b:.2f}")
                    continue
                m = statistics.median(mi[FAST.get(name, name)]) * 1e6 / size
                cells[name].append(f"{m:.2f} / {b:.2f}")
    for name in names + ["copy"]:
        print(f"| {LABELS.get(name, 'copy (floor)')} | " + " | ".join(cells[name]) + " |")
    print("\n(each cell: the median over the rounds of the fastest of several repetitions "
          f"per round; clock = {CLOCK['clock']})")


if __name__ == "__main__":
    main()
