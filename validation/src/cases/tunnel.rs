//! The README's main job, `models/tunnel.json`, with and without its supports, and its joint realizations.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use std::path::Path;

use adit::Scene;

use crate::plot;
use crate::readme::ModelRow;
use crate::realizations;
use crate::report::CaseReport;

/// Joint realizations of the tunnel model built (issues 14 and 52).
const REALIZATIONS: u64 = 1000;
/// Of those, how many are run through their stages (issue 52: all to equilibrium).
const REALIZATIONS_RUN: u64 = 100;

/// The tunnel's last stage with nothing installed: its mean wall closure (m), whether it reached
/// equilibrium, the block that moved most, with its largest node displacement (m), and what the
/// run's summary says moves at the stage's end (`StageSummary::moving`).
struct Unsupported {
    closure: f64,
    converged: bool,
    block: usize,
    /// The block's centroid at the start (its nodes' mean), m.
    at: [f64; 2],
    moved: f64,
    moving: Option<String>,
}

impl Unsupported {
    fn of(bare: &adit::RunResult) -> Unsupported {
        let last = bare.summary.stages.last();
        let m = &bare.built.model;
        let (node, moved) = (m.nodes.disp.iter().enumerate())
            .map(|(n, u)| (n, u[0].hypot(u[1])))
            .fold((0, 0.0), |best, c| if c.1 > best.1 { c } else { best });
        let block = m.blocks.block_of_node(node as u32);
        let at = m.blocks.node_mean(block, &m.nodes.pos);
        Unsupported {
            closure: last
                .and_then(|s| s.closure.values().next().copied())
                .unwrap_or(f64::NAN),
            converged: last.is_some_and(|s| s.status == "converged"),
            block,
            at,
            moved,
            moving: last.and_then(|s| s.moving.clone()),
        }
    }

    /// The report's sentence on it.
    fn sentence(&self) -> String {
        if self.converged {
            format!(
                "The same sequence with nothing installed closes the wall by {:.2} mm: the supports \
                 hold back the difference.",
                1e3 * self.closure
            )
        } else {
            format!(
                "With nothing installed the last stage stops at its cycle limit: block {} \
                 (centroid ({:.2}, {:.2}) m at the start) has fallen {:.2} m into the tunnel, the \
                 wall's mean closure then {:.0} mm; the run's summary says \"{}\". Installed, the \
                 supports hold it.",
                self.block,
                self.at[0],
                self.at[1],
                self.moved,
                1e3 * self.closure,
                self.moving.as_deref().unwrap_or("nothing moves")
            )
        }
    }

    /// The README's words on it.
    fn readme(&self) -> String {
        if self.converged {
            format!("{:.2} mm with nothing installed", 1e3 * self.closure)
        } else {
            format!(
                "with nothing installed block {} falls into the tunnel",
                self.block
            )
        }
    }
}

/// The joint realizations' section (issue 14): how many build, in what time, with what zones, and
/// the spread of the tunnel's closure over those run, as a histogram.
fn realizations_section(
    md: &mut String,
    built: &[realizations::Built],
    ran: &[realizations::Ran],
    shipped: &adit::RunResult,
    root: &Path,
) -> anyhow::Result<()> {
    use realizations::quantile;
    let ok: Vec<&realizations::Built> = built.iter().filter(|b| b.error.is_none()).collect();
    let seconds: Vec<f64> = built.iter().map(|b| b.seconds).collect();
    let angles: Vec<f64> = ok.iter().map(|b| b.min_angle).collect();
    let zones: Vec<f64> = ok.iter().map(|b| b.zones as f64).collect();
    let blocks: Vec<f64> = ok.iter().map(|b| b.blocks as f64).collect();
    let closures: Vec<f64> = ran
        .iter()
        .filter_map(|r| r.closure.as_ref().ok().map(|c| 1e3 * c))
        .collect();
    let run_failures: Vec<String> = ran
        .iter()
        .filter_map(|r| match &r.closure {
            Err(e) => Some(format!("realization {}: {e}", r.n)),
            Ok(_) if !r.converged => Some(format!(
                "realization {}: a stage stopped short of equilibrium ({} cycles in all)",
                r.n, r.cycles
            )),
            Ok(_) => None,
        })
        .collect();
    let median_s = quantile(&seconds, 0.5);
    let worst_s = quantile(&seconds, 1.0);
    let shipped_closure = shipped
        .summary
        .stages
        .last()
        .and_then(|s| s.closure.values().next().copied())
        .map_or(f64::NAN, |c| 1e3 * c);
    let run_seconds: Vec<f64> = ran.iter().map(|r| r.seconds).collect();
    let converged = ran.iter().filter(|r| r.converged).count();
    let _ = writeln!(
        md,
        "\n## Joint realizations of the tunnel model (issues 14 and 52)\n"
    );
    let _ = writeln!(
        md,
        "`models/tunnel.json` with each joint set given the scatter of `validation/src/realizations.rs` \
         (`joint_sets[i].scatter`: origins moved by up to ± the set's spacing (2.5 and 3 m) in x and in y, \
         dips by ±15°, spacings and traces scaled by U(0.6, 1.4)) and the scene's `realization` \
         N = 1…{n}: each draw is a different joint geometry. Built (cut, meshed, blocks and contacts): \
         **{b} of {n}** ({pct:.1} %; bar: all). Build time \
         median {median_s:.3} s, worst {worst_s:.3} s ({ratio:.1}× the median; bar 10×: **{verdict}**). \
         Zones median {zm:.0} (from {z0:.0} to {z1:.0}), blocks {bm:.0} (from {b0:.0} to {b1:.0}); smallest \
         zone angle per realization: worst {a0:.1}°, 5th percentile {a5:.1}°, median {a50:.1}° \
         (`zoning.min_angle` 30° is what refinement asks for; `zoning.accept_angle`, 1°, what a mesh must \
         have). The first {r} run through the tunnel's three stages (**{converged} of {r} reach \
         equilibrium** in every stage, bar: all; {rok} report a closure; median run {rs:.1} s): the \
         wall's closure at the end spreads from {c0:.2} to {c1:.2} mm, median {c50:.2} mm, \
         against {shipped_closure:.2} mm for the shipped joints. That spread is the joints' share of the \
         answer's uncertainty.\n",
        n = built.len(),
        b = ok.len(),
        pct = 100.0 * ok.len() as f64 / built.len().max(1) as f64,
        ratio = worst_s / median_s,
        verdict = if worst_s <= 10.0 * median_s {
            "met"
        } else {
            "NOT met"
        },
        zm = quantile(&zones, 0.5),
        z0 = quantile(&zones, 0.0),
        z1 = quantile(&zones, 1.0),
        bm = quantile(&blocks, 0.5),
        b0 = quantile(&blocks, 0.0),
        b1 = quantile(&blocks, 1.0),
        a0 = quantile(&angles, 0.0),
        a5 = quantile(&angles, 0.05),
        a50 = quantile(&angles, 0.5),
        r = ran.len(),
        rok = closures.len(),
        rs = quantile(&run_seconds, 0.5),
        c0 = quantile(&closures, 0.0),
        c1 = quantile(&closures, 1.0),
        c50 = quantile(&closures, 0.5),
    );
    let failures: Vec<String> = built
        .iter()
        .filter_map(|b| {
            b.error
                .as_ref()
                .map(|e| format!("realization {}: {e}", b.n))
        })
        .chain(run_failures)
        .collect();
    if !failures.is_empty() {
        let _ = writeln!(md, "Failures:\n");
        for f in failures.iter().take(10) {
            let _ = writeln!(md, "- {f}");
        }
        let _ = writeln!(md);
    }
    if !closures.is_empty() {
        plot::histogram(
            &root.join("docs/img/realizations_closure.png"),
            &format!("tunnel closure over {} joint realizations", closures.len()),
            "wall closure at the end (mm)",
            &closures,
            12,
        )?;
        let _ = writeln!(
            md,
            "![closure over joint realizations](img/realizations_closure.png)\n"
        );
    }
    Ok(())
}

/// The tunnel model's section: its cost, its stages and what its supports carry.
fn tunnel_section(
    md: &mut String,
    run: &adit::RunResult,
    row: &CaseReport,
    unsupported: &Unsupported,
) {
    let _ = writeln!(md, "\n## The tunnel model (`models/tunnel.json`)\n");
    let _ = writeln!(
        md,
        "A 6 m × 5.5 m horseshoe at 800 m depth (σv = 21.2 MPa at the axis with its gradient and gravity, \
         K0 = 1.5), Mohr–Coulomb rock cut by two sets of non-persistent joints; the in-situ state is solved, the \
         tunnel excavated with 25 % of the in-situ traction left on its wall (partial relaxation), then 11 \
         grouted, pretensioned 4 m bolts over the crown and a 0.15 m shotcrete liner are installed and the \
         support pressure removed. Not a closed-form case: its figures are what the README's main job shows.\n"
    );
    table(md, std::slice::from_ref(row));
    let _ = writeln!(md, "\n| stage | cycles | status | wall closure (mm) |");
    let _ = writeln!(md, "|---|---:|---|---:|");
    for s in &run.summary.stages {
        let closure = s
            .closure
            .values()
            .next()
            .map_or("–".to_string(), |c| format!("{:.2}", 1e3 * c));
        let _ = writeln!(
            md,
            "| {} | {} | {} | {closure} |",
            s.name, s.cycles, s.status
        );
    }
    let _ = writeln!(md, "\n{}", unsupported.sentence());
    let m = &run.built.model;
    let sup = &m.supports;
    let yielded = m.zones.state.iter().filter(|&&s| s != 0).count();
    let moving = m
        .contacts
        .state
        .iter()
        .filter(|s| s.flags & (adit::joint::SLIPPING | adit::joint::OPEN) != 0)
        .count();
    let loads = sup.loads();
    let _ = writeln!(
        md,
        "\nAt the end: {yielded} of {} zones have yielded, {moving} of {} contacts slip or are open; the largest \
         bolt force is {:.0} kN/m ({} of {} segments at yield), the largest liner thrust {:.2} MN/m and \
         moment {:.0} kN·m/m.\n\n![sigma1 and yield state around the tunnel, bolts (black) and liner (green)](img/tunnel.png)\n",
        m.zones.len(),
        m.contacts.len(),
        loads.bolt_force / 1e3,
        loads.bolts_yielded,
        sup.cables.segment.len(),
        loads.liner_thrust / 1e6,
        loads.liner_moment / 1e3
    );
}

pub struct Tunnel;

impl Case for Tunnel {
    fn name(&self) -> &'static str {
        "tunnel"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let root = &cx.root;
        let mut md = String::new();
        let tunnel_scene = Scene::load(&root.join("models/tunnel.json"))?;
        let tunnel = adit::run_scene(
            &tunnel_scene,
            &root.join("target/validation/tunnel"),
            &mut adit::solve::Quiet,
        )?;
        let tunnel_report = CaseReport::new(
            "models/tunnel.json (README main job): staged, bolted and lined horseshoe",
            tunnel.summary.zones,
            tunnel.summary.cycles,
            tunnel.summary.wall_seconds,
            None,
            &[],
        );
        print_row(&tunnel_report);
        // The same sequence with nothing installed: what the supports hold back.
        let mut bare_scene = tunnel_scene.clone();
        bare_scene.stages.iter_mut().for_each(|s| s.install.clear());
        bare_scene.bolts.clear();
        bare_scene.liners.clear();
        // Its monitoring points of supports have nothing to read (a run refuses them).
        bare_scene.histories.retain(|h| {
            use adit::scene::HistoryQuantity::{BoltForce, LinerMoment, LinerThrust};
            !matches!(h.quantity, BoltForce | LinerThrust | LinerMoment)
        });
        let bare = adit::run_scene(
            &bare_scene,
            &root.join("target/validation/tunnel_unsupported"),
            &mut adit::solve::Quiet,
        )?;
        let unsupported = Unsupported::of(&bare);
        let realizations_built = realizations::build_all(REALIZATIONS)?;
        let realizations_ran = realizations::run_all(
            REALIZATIONS_RUN,
            &root.join("target/validation/realization"),
        )?;
        println!(
            "realizations: {} of {} built, {} of {} ran to equilibrium",
            realizations_built
                .iter()
                .filter(|b| b.error.is_none())
                .count(),
            REALIZATIONS,
            realizations_ran.iter().filter(|r| r.converged).count(),
            REALIZATIONS_RUN
        );
        crate::render::tunnel_png(
            &root.join("docs/img/tunnel.png"),
            &tunnel.built.model,
            [0.0, -0.5],
            9.0,
        )?;
        tunnel_section(&mut md, &tunnel, &tunnel_report, &unsupported);
        realizations_section(
            &mut md,
            &realizations_built,
            &realizations_ran,
            &tunnel,
            root,
        )?;
        let closure = tunnel
            .summary
            .stages
            .last()
            .and_then(|s| s.closure.values().next().copied())
            .unwrap_or(f64::NAN);
        let models = vec![ModelRow {
            file: "models/tunnel.json".into(),
            zones: tunnel.summary.zones,
            blocks: tunnel.summary.blocks,
            cycles: tunnel.summary.cycles,
            seconds: tunnel.summary.wall_seconds,
            result: format!(
                "mean wall closure {:.2} mm supported ({})",
                1e3 * closure,
                unsupported.readme()
            ),
        }];
        Ok(Section {
            markdown: md,
            rows: vec![tunnel_report],
            models,
            ..Default::default()
        })
    }
}
