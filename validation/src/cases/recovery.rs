//! The recovered nodal stress and the zones' error indicator on Kirsch's hole (issue 19).

use std::fmt::Write as _;

use plotters::style::RGBColor;

use crate::case::{Case, Context, Section};
use crate::kirsch_case::scaled;
use crate::plot::{Curve, curves};
use crate::recovery::{RecoveryResult, kirsch, salencon, untuned};
use crate::report::CaseReport;

/// Zonings (×: the shipped zone size), coarse to fine.
const LEVELS: [f64; 4] = [2.0, 1.0, 0.6, 0.4];

pub struct Recovery;

/// One result on the console.
fn say(r: &RecoveryResult) {
    println!(
        "{}: zones {:.3e}, recovered {:.3e}, effectivity {:.3}, correlation {:.3}",
        r.case, r.zone_l2, r.recovered_l2, r.effectivity, r.correlation
    );
}

impl Case for Recovery {
    fn name(&self) -> &'static str {
        "recovery"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let mut results: Vec<RecoveryResult> = Vec::new();
        for (tag, scene) in [
            ("shipped stresses", cx.kirsch.clone()),
            ("Sxx = −30, Syy = −5 MPa, ν = 0.35", untuned(&cx.kirsch)),
        ] {
            for f in LEVELS {
                let r = kirsch(&scaled(&scene, f), &format!("Kirsch ×{f}, {tag}"))?;
                say(&r);
                results.push(r);
            }
        }
        for f in [2.0, 1.0, 0.6] {
            let r = salencon(
                &cx.kirsch,
                f,
                &format!("Salençon ×{f}, shipped rock, r ≤ 2 Rp"),
            )?;
            say(&r);
            results.push(r);
        }
        let mut md = String::new();
        let _ = writeln!(
            md,
            "\n## Recovered nodal stress and error indicator (issue 19)\n"
        );
        let _ = writeln!(
            md,
            "The zone files carry a recovered nodal stress σ* (`stress_nodal`, `sigma1_nodal`, \
             `sigma3_nodal`: superconvergent patch recovery, block by block, `docs/theory.md`) \
             and each zone's indicator ηₑ (`recovery_error`, the root mean square of σ* − σₕ over \
             the zone). Measured on Kirsch's hole with the exact traction on the outer boundary \
             (so only the zoning's error remains; solved implicitly), over the zones with \
             centroid r ≤ 5a, in the in-plane norm |σ|² = σxx² + σyy² + 2σxy² integrated by a \
             three-point rule on each zone: the zones' error ‖σₕ − σ‖/‖σ‖ against the recovered \
             field's ‖σ* − σ‖/‖σ‖ (σ* linear between each zone's corners); the indicator's \
             effectivity ‖η‖/‖σₕ − σ‖ (1: it sizes the zoning's error exactly) and the \
             correlation of ηₑ with each zone's true error eₑ (root mean square of σₕ − σ over \
             the zone). The second set of rows is a stress state and Poisson's ratio nothing \
             was tuned to; the third, Salençon's hole in the shipped Mohr–Coulomb rock \
             (unsupported, solved at once), measured within r ≤ 2 Rp, where the stress has a \
             kink at the plastic radius that no plane fits. Recovery seconds: σ* and η once, as each output step computes them \
             ({} threads).\n",
            cx.threads
        );
        let _ = writeln!(
            md,
            "| case | zones | h (m) | zones' error | recovered error | ratio | effectivity | correlation | recovery s | solve s |"
        );
        let _ = writeln!(md, "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
        for r in &results {
            let _ = writeln!(
                md,
                "| {} | {} | {:.3} | {:.3} % | {:.3} % | {:.2} | {:.3} | {:.3} | {:.4} | {:.3} |",
                r.case,
                r.zones,
                r.h,
                100.0 * r.zone_l2,
                100.0 * r.recovered_l2,
                r.recovered_l2 / r.zone_l2,
                r.effectivity,
                r.correlation,
                r.recovery_s,
                r.wall_s
            );
        }
        let shipped = &results[1];
        let img = cx.root.join("docs/img/recovery_indicator.png");
        let top = shipped
            .pairs
            .iter()
            .fold(0.0f64, |m, p| m.max(p.0).max(p.1));
        curves(
            &img,
            &format!(
                "Kirsch ×1: indicator against true error, {} zones",
                shipped.pairs.len()
            ),
            ("true error eₑ (Pa)", "indicator ηₑ (Pa)"),
            &[
                Curve {
                    label: "zones".into(),
                    points: shipped.pairs.iter().map(|&(eta, e)| (e, eta)).collect(),
                    color: RGBColor(200, 60, 40),
                    dots: true,
                },
                Curve {
                    label: "ηₑ = eₑ".into(),
                    points: vec![(0.0, 0.0), (top, top)],
                    color: RGBColor(40, 40, 40),
                    dots: false,
                },
            ],
        )?;
        let _ = writeln!(
            md,
            "\n![indicator against true error](img/recovery_indicator.png)\n"
        );
        let mut missed = Vec::new();
        for r in &results {
            if r.recovered_l2 >= r.zone_l2 {
                missed.push(format!(
                    "{}: the recovered stress ({:.3e}) is not nearer the closed form than the zones' ({:.3e})",
                    r.case, r.recovered_l2, r.zone_l2
                ));
            }
        }
        let rows = results
            .iter()
            .map(|r| {
                CaseReport::new(
                    format!("recovery: {}", r.case),
                    r.zones,
                    1,
                    r.wall_s,
                    Some(r.h),
                    &[
                        ("zone_l2", r.zone_l2),
                        ("recovered_l2", r.recovered_l2),
                        ("effectivity_gap", (r.effectivity - 1.0).abs()),
                    ],
                )
            })
            .collect();
        Ok(Section {
            markdown: md,
            rows,
            missed,
            ..Default::default()
        })
    }
}
