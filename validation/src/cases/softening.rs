//! Strain softening: a Mohr–Coulomb specimen whose cohesion falls with plastic strain.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::plot::{Curve, curves};
use crate::softening;
use plotters::style::RGBColor;

pub struct Softening;

impl Case for Softening {
    fn name(&self) -> &'static str {
        "softening"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let root = &cx.root;
        let mut md = String::new();
        let softening_cases: Vec<softening::SofteningResult> = [0.05, 0.025]
            .iter()
            .map(|&edge| softening::run(edge, 0.004, 2e-7))
            .collect::<anyhow::Result<_>>()?;
        for r in &softening_cases {
            print_row(&r.report());
        }
        let _ = writeln!(md, "\n## Stability: strain softening (issue 5)\n");
        let _ = writeln!(
            md,
            "A 1 m × 2 m Mohr–Coulomb specimen (E = 5 GPa, ν = 0.25, φ = 30°, ψ = 0) whose cohesion falls \
         from 1 MPa to 0.1 MPa over a plastic shear strain of 0.005, under σ3 = 1 MPa, compressed between \
         smooth platens at 2e-7 m per cycle to 0.4 % axial strain, at two zone sizes. Before the peak the \
         stress is uniform: `peak` is the error against σ3 Nφ + 2c√Nφ = {:.2} MPa. After it the \
         unstructured mesh's imperfections localise the plastic strain into a band (half of it in the \
         few % of the area the label gives) and the load falls towards the band's residual strength \
         ({:.2} MPa with c = 0.1 MPa); the softening branch depends on the zone size, as it must \
         without a regularising length. The run never blows up.\n",
            softening::strength(1e6) / 1e6,
            softening::strength(0.1e6) / 1e6
        );
        table(
            &mut md,
            &softening_cases
                .iter()
                .map(softening::SofteningResult::report)
                .collect::<Vec<_>>(),
        );
        let soft_curves: Vec<Curve> = softening_cases
            .iter()
            .zip([RGBColor(31, 119, 180), RGBColor(214, 39, 40)])
            .map(|(r, color)| Curve {
                label: format!("zones of {} m", r.edge),
                points: r.curve.iter().map(|&(e, s)| (100.0 * e, s / 1e6)).collect(),
                color,
                dots: false,
            })
            .collect();
        curves(
            &root.join("docs/img/softening.png"),
            "strain-softening specimen: axial stress against axial strain",
            ("axial strain (%)", "σ1 (MPa)"),
            &soft_curves,
        )?;
        let _ = writeln!(
            md,
            "\n![axial stress against strain at two zone sizes](img/softening.png)\n"
        );
        Ok(Section {
            markdown: md,
            rows: softening_cases
                .iter()
                .map(softening::SofteningResult::report)
                .collect(),

            ..Default::default()
        })
    }
}
