//! Many blocks: a specimen of Voronoi grains compressed to failure.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::grains;
use crate::plot::{Curve, curves};
use plotters::style::RGBColor;

pub struct Grains;

impl Case for Grains {
    fn name(&self) -> &'static str {
        "grains"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let root = &cx.root;
        let mut md = String::new();
        let loading = |strain_per_cycle: f64, servo: Option<f64>| grains::Loading {
            strain_per_cycle,
            servo,
            residual: 0.8,
            max_strain: 0.02,
        };
        let grain_cases: Vec<grains::GrainsResult> = vec![
            grains::run(10, 0.1, &loading(5e-6, Some(1e-2)))?,
            grains::run(10, 0.1, &loading(2.5e-8, None))?,
            grains::run(10, 0.1, &loading(1e-7, None))?,
            grains::run(10, 0.1, &loading(5e-7, None))?,
            grains::run(71, 1.0 / 71.0, &loading(1e-7, None))?,
        ];
        for r in &grain_cases {
            print_row(&r.report());
        }
        let _ = writeln!(md, "\n## Stability: many blocks (issue 5)\n");
        let _ = writeln!(
            md,
            "A 1 m × 2 m specimen of Voronoi grains (edges under 0.1 grain collapsed) bonded by Coulomb grain \
         boundaries (kn = 1e11 Pa / grain size, 1e12 Pa/m for 0.1 m grains, ks = kn / 2, φ = 30°, c = 4 MPa, \
         T = 2 MPa, lost on failure), rigid except within two grains \
         of the platens (deformable, so the platens drive their nodes), under σ3 = 1 MPa, compressed by a \
         smooth platen to failure, every grain started on the platens' affine velocity field; σ1 is the \
         platen's reaction over the width (no closed form; `validation/src/grains.rs`). In mass-scaled \
         relaxation the platen's speed per cycle matters: the grains' inertial number (with their scaled \
         masses) is at most a few 1e-5, far inside quasi-static flow, yet the peak falls as the platen \
         slows: our reading is that failure spreads from bond to bond over cycles and a fast platen \
         outruns it. The {}-grain specimen peaks at {:.1} MPa servo-controlled and \
         {:.1}, {:.1} and {:.1} MPa at 2.5e-8, 1e-7 and 5e-7 axial strain per cycle. The {}-grain \
         specimen, loaded at 1e-7 per cycle (a rate that puts the coarse peak {:.0} % above its \
         quasi-static value), reaches {:.1} MPa at ε = {:.2e} and ends at {:.1} MPa (ε = {:.2e}){}. That is {:.1} times the coarse \
         specimen's peak at 2.5e-8: a wave takes about {:.1} times more cycles to cross the fine \
         specimen than the coarse one, so the same strain per cycle loads it relatively faster (and its \
         platens' deformable bands are a smaller share of it); its own quasi-static peak is not measured. \
         Loading it at 2.5e-8 would take four times its {} cycles.\n",
            grain_cases[0].grains,
            grain_cases[0].peak / 1e6,
            grain_cases[1].peak / 1e6,
            grain_cases[2].peak / 1e6,
            grain_cases[3].peak / 1e6,
            grain_cases[4].grains,
            100.0 * (grain_cases[2].peak / grain_cases[1].peak - 1.0),
            grain_cases[4].peak / 1e6,
            grain_cases[4].peak_strain,
            grain_cases[4].end / 1e6,
            grain_cases[4].end_strain,
            match &grain_cases[4].stopped {
                None => format!(
                    ", stable throughout: no NaN, runaway, overlap or unstable-step stop while {:.0} % of \
                 its bonds break",
                    100.0 * grain_cases[4].broken
                ),
                Some(reason) => format!(", where a safeguard STOPPED it {reason}"),
            },
            grain_cases[4].peak / grain_cases[1].peak,
            (grain_cases[4].grains as f64 / grain_cases[1].grains as f64).sqrt(),
            grain_cases[4].cycles
        );
        table(
            &mut md,
            &grain_cases
                .iter()
                .map(grains::GrainsResult::report)
                .collect::<Vec<_>>(),
        );
        let grain_curves: Vec<Curve> = grain_cases[1..]
            .iter()
            .zip([
                RGBColor(31, 119, 180),
                RGBColor(44, 160, 44),
                RGBColor(255, 127, 14),
                RGBColor(214, 39, 40),
            ])
            .map(|(r, color)| Curve {
                label: format!(
                    "{} grains, {:.1e} per cycle",
                    r.grains, r.loading.strain_per_cycle
                ),
                points: r.curve.iter().map(|&(e, s)| (100.0 * e, s / 1e6)).collect(),
                color,
                dots: false,
            })
            .collect();
        curves(
            &root.join("docs/img/grains.png"),
            "Voronoi grains, biaxial: axial stress against axial strain",
            ("axial strain (%)", "σ1 (MPa)"),
            &grain_curves,
        )?;
        let _ = writeln!(
            md,
            "\n![axial stress against strain, coarse and 10 000 grains](img/grains.png)\n"
        );
        Ok(Section {
            markdown: md,
            rows: grain_cases
                .iter()
                .map(grains::GrainsResult::report)
                .collect(),

            ..Default::default()
        })
    }
}
