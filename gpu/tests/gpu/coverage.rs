//! Twin coverage: every kernel of the reference table has a WGSL twin or a reason in
//! `NO_TWIN`, and each module a shader calls (`brdf_gpu::shaders::TWINNED_MODULES`) has
//! twins; no reason is left standing for a kernel that has a twin (or no longer exists).

use brdf_gpu::shaders::{NO_TWIN, TWINNED_MODULES, families, module_of, no_twin_reason, twins};

#[test]
fn every_kernel_a_shader_calls_has_a_twin_or_a_stated_reason() {
    let fams = families();
    let (with, without) = twins(&fams);
    println!(
        "{} kernels have a WGSL twin; {} do not:",
        with.len(),
        without.len()
    );
    let mut missing = Vec::new();
    for p in &without {
        match no_twin_reason(p) {
            Some(why) => println!("  {p}: {why}"),
            None => {
                println!("  {p}: NO REASON");
                missing.push(*p);
            }
        }
    }
    // Every kernel of the table, not only those of TWINNED_MODULES: a kernel of any other
    // module needs its reason as well.
    assert!(
        TWINNED_MODULES
            .iter()
            .all(|m| with.iter().any(|t| module_of(t.kernel.path) == *m)),
        "a module of TWINNED_MODULES without any twin"
    );
    assert!(
        missing.is_empty(),
        "kernels without a WGSL twin or a reason in \
         brdf_gpu::shaders::NO_TWIN: {missing:?}"
    );
}

#[test]
fn no_reason_is_left_for_a_kernel_with_a_twin() {
    // An exact entry of NO_TWIN names a kernel without a twin; a module entry (ending in `::`)
    // covers at least one such kernel (its module may have some twins, as `sampling` does).
    let fams = families();
    let (with, without) = twins(&fams);
    let mut stale = Vec::new();
    for (entry, _) in NO_TWIN {
        let covers = |p: &&str| {
            if entry.ends_with("::") {
                p.starts_with(entry)
            } else {
                p == entry
            }
        };
        let twinned = !entry.ends_with("::") && with.iter().any(|t| covers(&t.kernel.path));
        if twinned || !without.iter().any(covers) {
            stale.push(*entry);
        }
    }
    assert!(
        stale.is_empty(),
        "NO_TWIN entries that name no kernel without a twin (it has one now, or the kernel \
         is gone): {stale:?}"
    );
}

#[test]
fn the_check_catches_a_kernel_without_twin_or_reason() {
    // A family list without the Beckmann twins (and the families whose modules include
    // them): their kernels have no twin and no reason.
    let mut fams = families();
    fams.retain(|f| {
        ![
            "beckmann",
            "cook_torrance",
            "material",
            "sampling",
            "rough_dielectric",
            "transmission",
            "layered",
        ]
        .contains(&f.name)
    });
    let (_, without) = twins(&fams);
    assert!(
        without
            .iter()
            .any(|p| p.starts_with("beckmann::") && no_twin_reason(p).is_none()),
        "dropping beckmann.wgsl leaves its kernels uncovered"
    );
}
