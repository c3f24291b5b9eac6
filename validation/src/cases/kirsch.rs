//! Kirsch's hole: the shipped model, and convergence under refinement with exact and far-field tractions.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::kirsch_case::{KirschResult, OuterLoad, run, scaled};
use crate::plot::{Series, speed_and_convergence};
use crate::readme::ModelRow;
use crate::report::{fitted_order, observed_order};
use adit::Scene;
use plotters::style::RGBColor;

/// Uniform refinement factors of the Kirsch levels (1 = the shipped model's zoning).
const LEVELS: [f64; 4] = [4.0, 2.0, 1.0, 0.6];
/// Unbalanced-force ratio for the convergence levels: tight enough that solver error is far below
/// discretisation error at the finest level.
const STUDY_RATIO: f64 = 1e-8;

fn kirsch_levels(scene: &Scene, load: OuterLoad, tag: &str) -> anyhow::Result<Vec<KirschResult>> {
    let mut base = scene.clone();
    base.solve.ratio = STUDY_RATIO;
    base.solve.max_cycles = 2_000_000;
    LEVELS
        .iter()
        .enumerate()
        .map(|(i, &f)| {
            let r = run(
                &scaled(&base, f),
                &format!("kirsch {tag} L{i} (×{f})"),
                load,
            )?;
            print_row(&r.report());
            Ok(r)
        })
        .collect()
}

fn order_table(md: &mut String, levels: &[KirschResult]) {
    let _ = writeln!(
        md,
        "| levels | h₁ → h₂ (m) | order, stress L2 | order, wall displacement |"
    );
    let _ = writeln!(md, "|---|---|---|---|");
    for w in levels.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        let _ = writeln!(
            md,
            "| {} → {} | {:.3} → {:.3} | {:.2} | {:.2} |",
            a.case.split(' ').nth(2).unwrap_or(""),
            b.case.split(' ').nth(2).unwrap_or(""),
            a.h,
            b.h,
            observed_order(a.h, a.stress_l2, b.h, b.stress_l2),
            observed_order(a.h, a.wall_displacement, b.h, b.wall_displacement)
        );
    }
    let fit = |f: fn(&KirschResult) -> f64| {
        fitted_order(&levels.iter().map(|r| (r.h, f(r))).collect::<Vec<_>>())
    };
    let _ = writeln!(
        md,
        "| least squares, all levels | | {:.2} | {:.2} |",
        fit(|r| r.stress_l2),
        fit(|r| r.wall_displacement)
    );
}

/// The levels' table, then their observed orders under a heading line.
fn convergence_section(md: &mut String, levels: &[KirschResult], heading: &str) {
    table(
        md,
        &levels.iter().map(KirschResult::report).collect::<Vec<_>>(),
    );
    let _ = writeln!(md, "\n{heading}\n");
    order_table(md, levels);
}

pub struct Kirsch;

impl Case for Kirsch {
    fn name(&self) -> &'static str {
        "kirsch"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let root = &cx.root;
        let scene = &cx.kirsch;
        let threads = cx.threads;
        let mut md = String::new();
        let model = run(
            &crate::as_adit_runs(scene)?,
            "kirsch (models/kirsch.json as shipped, solved as adit run does)",
            OuterLoad::Scene,
        )?;
        print_row(&model.report());
        let exact = kirsch_levels(scene, OuterLoad::Exact, "exact-traction")?;
        let far = kirsch_levels(scene, OuterLoad::Scene, "far-field")?;
        let series =
            |levels: &[KirschResult], what: &str, f: fn(&KirschResult) -> f64, color, dashed| {
                Series {
                    label: what.to_string(),
                    points: levels.iter().map(|r| (r.h, r.wall_s, f(r))).collect(),
                    color,
                    dashed,
                }
            };
        let (blue, red) = (RGBColor(31, 119, 180), RGBColor(214, 39, 40));
        let plot_series = [
            series(
                &exact,
                "stress L2, exact tractions",
                |r| r.stress_l2,
                blue,
                false,
            ),
            series(
                &exact,
                "wall displacement, exact tractions",
                |r| r.wall_displacement,
                red,
                false,
            ),
            series(
                &far,
                "stress L2, far field at 20a",
                |r| r.stress_l2,
                blue,
                true,
            ),
            series(
                &far,
                "wall displacement, far field at 20a",
                |r| r.wall_displacement,
                red,
                true,
            ),
        ];
        std::fs::create_dir_all(root.join("docs/img"))?;
        speed_and_convergence(&root.join("docs/img/kirsch_convergence.png"), &plot_series)?;
        let out = root.join("target/validation");
        std::fs::create_dir_all(&out)?;
        std::fs::copy(
            root.join("docs/img/kirsch_convergence.png"),
            out.join("kirsch_convergence.png"),
        )?;

        let finest = exact.last().expect("levels");
        let _ = writeln!(md, "## Kirsch: circular hole under far-field stress\n");
        let _ = writeln!(
            md,
            "Hole radius a = 1 m, square domain of half-width 20 m, E = 10 GPa, ν = 0.25, Sxx = −10 MPa, \
         Syy = −20 MPa, plane strain, compared with the closed form of Jaeger, Cook & Zimmerman (§8.4). \
         `stress_l2`: area-weighted L2 error of zone stress over zones with centroid r ≤ 5a, relative to the \
         exact stress norm there. `wall_displacement`: largest error of the excavation-induced displacement \
         over the hole-wall nodes, relative to the largest exact wall displacement.\n"
        );
        let _ = writeln!(md, "### The shipped model (`models/kirsch.json`)\n");
        table(&mut md, &[model.report()]);
        let pass = model.stress_l2 <= 0.03 && model.wall_displacement <= 0.01;
        let _ = writeln!(
            md,
            "\nBar: stress L2 ≤ 3 % and wall displacement ≤ 1 %: **{}** ({:.2} % and {:.2} %).\n",
            if pass { "met" } else { "NOT met" },
            100.0 * model.stress_l2,
            100.0 * model.wall_displacement
        );
        let _ = writeln!(md, "### Convergence under uniform refinement\n");
        let _ = writeln!(
            md,
            "Each level scales every zoning length (and the grading) of the shipped model by the factor shown; the \
         hole polygon gets one segment per wall zone. Solved to an unbalanced-force ratio of {STUDY_RATIO:e}.\n\n\
         *Exact tractions*: the outer boundary carries the exact Kirsch traction σ(x)·n, so the discrete \
         problem's exact solution is the Kirsch field and only discretisation error is left. *Far field*: the \
         outer boundary carries the far-field stress as in the shipped model; the finite domain adds a \
         truncation error of order (a/R)² that no refinement removes.\n"
        );
        convergence_section(
            &mut md,
            &exact,
            "Observed order of convergence with exact tractions (expected: 1 for CST stresses, 2 for displacements):",
        );
        let _ = writeln!(md);
        convergence_section(
            &mut md,
            &far,
            "Observed order with far-field tractions (the displacement error levels off at the truncation error):",
        );
        let _ = writeln!(
            md,
            "\nSpeed on the finest level: **{:.2e} zone-cycles per second** ({} zones, {} cycles, {threads} threads).\n",
            finest.zone_cycles_per_s, finest.zones, finest.cycles
        );
        let _ = writeln!(
            md,
            "![error against run time and zone size](img/kirsch_convergence.png)\n"
        );
        let mut rows = vec![model.report()];
        rows.extend(exact.iter().map(KirschResult::report));
        rows.extend(far.iter().map(KirschResult::report));
        let models = vec![ModelRow {
            file: "models/kirsch.json".into(),
            zones: model.zones,
            blocks: 1,
            cycles: model.cycles,
            seconds: model.wall_s,
            result: format!(
                "zone stress within {:.2} % of Kirsch (L2)",
                100.0 * model.stress_l2
            ),
        }];
        let missed = if pass {
            vec![]
        } else {
            vec!["the shipped Kirsch model misses its accuracy bar".to_string()]
        };
        Ok(Section {
            markdown: md,
            rows,
            models,
            missed,
            ..Default::default()
        })
    }
}
