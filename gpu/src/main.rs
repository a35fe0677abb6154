//! `brdf-gpu-equiv [--out DIR] [--only PREFIX]`: every WGSL twin (or those whose kernel path
//! starts with PREFIX) on the adapter wgpu finds, against the CPU;
//! prints the adapter and the per-kernel table, writes `gpu-equivalence.md` and
//! `gpu-equivalence.csv` into DIR (default `out/gpu`). Exit status 1 when a value leaves its
//! bound, 2 when no adapter exists. Needs at run time only a Vulkan loader
//! (`libvulkan.so.1`, found through `LD_LIBRARY_PATH`) and a driver's ICD.

use brdf_gpu::device::Gpu;
use brdf_gpu::equiv::{csv, markdown, rows, run_kernel};
use brdf_gpu::shaders::{families, twins};
use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    let mut out = PathBuf::from("out/gpu");
    let mut only = String::new();
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out" => match args.next() {
                Some(d) => out = PathBuf::from(d),
                None => {
                    eprintln!("--out needs a folder");
                    return ExitCode::from(2);
                }
            },
            "--only" => match args.next() {
                Some(p) => only = p,
                None => {
                    eprintln!("--only needs a kernel path prefix");
                    return ExitCode::from(2);
                }
            },
            "-h" | "--help" => {
                println!(
                    "brdf-gpu-equiv [--out DIR] [--only PREFIX]: the WGSL twins on this machine's GPU"
                );
                return ExitCode::SUCCESS;
            }
            other => {
                eprintln!("unknown argument {other}");
                return ExitCode::from(2);
            }
        }
    }
    let Some(gpu) = Gpu::new() else {
        eprintln!(
            "no adapter: wgpu found no Vulkan device (is libvulkan.so.1 on LD_LIBRARY_PATH?)"
        );
        return ExitCode::from(2);
    };
    let adapter = gpu.describe();
    println!("adapter: {adapter}");
    let fams = families();
    let (with, without) = twins(&fams);
    let mut figs = Vec::new();
    for t in with.iter().filter(|t| t.kernel.path.starts_with(&only)) {
        let f = run_kernel(&gpu, t, &fams, &rows(t.kernel));
        println!(
            "{:40} max {:>6} ULP ({:>6} on normal numbers)  identical {:>6.2}%  max/bound {:.3}  \
             excluded {:>5}  outside {}",
            f.path,
            f.max_ulp,
            f.max_ulp_normal,
            100.0 * f.identical as f64 / f.compared.max(1) as f64,
            f.max_ratio,
            f.excluded_total(),
            f.outside + f.twin_differs
        );
        for line in &f.failures {
            println!("    {line}");
        }
        figs.push(f);
    }
    let forms = brdf_gpu::contrast::run(&gpu);
    for f in &forms {
        println!(
            "GGX D near n.h = 1, {:18} identical {:>6.2}%  max {} ULP at (n.h, alpha) = {:?}",
            f.name,
            100.0 * f.identical as f64 / f.compared as f64,
            f.max_ulp,
            f.worst
        );
    }
    let md = markdown(&adapter, &figs, &without) + &brdf_gpu::contrast::markdown(&forms);
    if let Err(e) = std::fs::create_dir_all(&out)
        .and_then(|()| std::fs::write(out.join("gpu-equivalence.md"), &md))
        .and_then(|()| std::fs::write(out.join("gpu-equivalence.csv"), csv(&figs)))
    {
        eprintln!("cannot write {}: {e}", out.display());
        return ExitCode::from(2);
    }
    println!("wrote {}", out.join("gpu-equivalence.md").display());
    if figs.iter().any(|f| f.outside + f.twin_differs > 0) {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}
