//! A circular inclusion 1000× softer or stiffer than the rock against Goodier's solution.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::inclusion;
use adit::scene::SolveMethod;

pub struct Inclusion;

impl Case for Inclusion {
    fn name(&self) -> &'static str {
        "inclusion"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let scene = &cx.kirsch;
        let mut md = String::new();
        let mut inclusion_cases: Vec<inclusion::InclusionResult> = Vec::new();
        for contrast in [1e-3, 1e3] {
            for method in [SolveMethod::Explicit, SolveMethod::Implicit] {
                let mut s = inclusion::scene(scene, contrast);
                s.solve.method = method;
                let case = format!(
                    "circular inclusion {contrast} × as stiff as the rock, Kirsch mesh, {}",
                    method.name()
                );
                inclusion_cases.push(inclusion::run(&s, &case)?);
            }
        }
        for r in &inclusion_cases {
            print_row(&r.report());
        }
        let (stiff_explicit, stiff_implicit) = (&inclusion_cases[2], &inclusion_cases[3]);
        let _ = writeln!(md, "\n## Stability: stiffness contrast (issue 5)\n");
        let _ = writeln!(
            md,
            "The shipped Kirsch model with its hole replaced by a circular inclusion (`inclusions`: a region of \
         another material cut from the rock and glued to it, kn = max E/h) 1000× softer or 1000× stiffer \
         than the rock (same ν), loaded from zero stress by the far field (σxx, σyy) = (−10, −20) MPa with \
         the exact traction on the outer boundary, against the closed form of a bonded circular inclusion \
         (Goodier 1933, Muskhelishvili §56: uniform stress inside, derived and checked for continuity in \
         `validation/src/inclusion.rs`). `stress_l2` as for Kirsch (r ≤ 5a, both materials); \
         `inside_mean`: the inclusion's mean stress against its uniform exact value ({}); `interface`: the \
         largest zone error within a zone of the interface over the largest exact stress there. Each \
         contrast is solved by explicit relaxation and by the implicit solve (`solve.method`; cycles are \
         its iterations). The stiff inclusion's scaled masses are 1000× heavier, so its rigid-body-like \
         modes against the soft rock take explicit relaxation {} cycles ({}), where the implicit solve \
         takes {} iterations ({:.2} s against {:.2} s).\n",
            inclusion_cases
                .iter()
                .map(|r| format!(
                    "{:.3} / {:.3} MPa for ×{}",
                    r.inside_exact[0] / 1e6,
                    r.inside_exact[1] / 1e6,
                    r.contrast
                ))
                .fold(Vec::<String>::new(), |mut seen, v| {
                    // Each contrast is run twice (explicit, implicit): its value once.
                    if seen.last() != Some(&v) {
                        seen.push(v);
                    }
                    seen
                })
                .join(", "),
            stiff_explicit.cycles,
            stiff_explicit.status,
            stiff_implicit.cycles,
            stiff_implicit.wall_s,
            stiff_explicit.wall_s,
        );
        table(
            &mut md,
            &inclusion_cases
                .iter()
                .map(inclusion::InclusionResult::report)
                .collect::<Vec<_>>(),
        );
        Ok(Section {
            markdown: md,
            rows: inclusion_cases
                .iter()
                .map(inclusion::InclusionResult::report)
                .collect(),

            ..Default::default()
        })
    }
}
