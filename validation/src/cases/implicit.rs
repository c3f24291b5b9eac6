//! The implicit static path against the explicit one (issue 17): each case solved both ways, to
//! the same unbalanced-force ratio, with the cost of each side by side.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::kirsch_case::{KirschResult, OuterLoad, run, scaled};
use crate::peer;
use crate::plot::{Series, speed_and_convergence};
use crate::report::CaseReport;
use crate::salencon::{self, Rock, WEAK_ROCK};
use crate::{
    bundled, direct_shear, glued, gravity, incompressible, lined, modes, pullout, softening,
};
use adit::scene::{BlockMode, SolveMethod};

pub struct Implicit;

/// A dilatant rock for the third Salençon set (c = 2 MPa, φ = 35°, ψ = 10°, ν = 0.25,
/// p0 = 20 MPa, E = 10 GPa).
const DILATANT_ROCK: Rock = Rock {
    cohesion: 2e6,
    friction_deg: 35.0,
    dilation_deg: 10.0,
    young: 10e9,
    poisson: 0.25,
    p0: 20e6,
    mixed: false,
};

/// A dilatant rock in mixed zones (c = 1 MPa, φ = 25°, ψ = 10°, ν = 0.4, p0 = 15 MPa,
/// E = 10 GPa; β = 0.43 of a zone's own volumetric strain kept): its patches average the plastic
/// change of mean stress, which the implicit trial lags into its next predictor (`cycle::mixed`).
/// Its slow path is slower explicitly ([`DILATANT_MIXED_RAMP`]).
const DILATANT_MIXED: Rock = Rock {
    cohesion: 1e6,
    friction_deg: 25.0,
    dilation_deg: 10.0,
    young: 10e9,
    poisson: 0.4,
    p0: 15e6,
    mixed: true,
};

/// Cycles over which [`DILATANT_MIXED`]'s hole is released explicitly on its slow path: over the
/// other rocks' 16 000 (`bundled::QUASI_STATIC_RAMP`) the wall closed 6.6 % less than the closed
/// form, over 64 000 8.4 % less, as the implicit solve in 16 load steps (8.5 %) and in 64 (8.6 %)
/// does: 16 000 cycles were not yet quasi-static for it.
const DILATANT_MIXED_RAMP: u64 = 64_000;

/// Kirsch's zonings, × the shipped zone size.
const KIRSCH_LEVELS: [f64; 4] = [2.0, 1.0, 0.6, 0.4];

/// Bytes per stored non-zero of the Cholesky factor (its f64 value).
const FACTOR_VALUE_BYTES: f64 = 8.0;

impl Case for Implicit {
    fn name(&self) -> &'static str {
        "implicit"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let mut md = String::new();
        let mut pairs: Vec<(CaseReport, CaseReport)> = Vec::new();
        let mut both = |solve: &dyn Fn(SolveMethod) -> anyhow::Result<CaseReport>| {
            let e = solve(SolveMethod::Explicit)?;
            let i = solve(SolveMethod::Implicit)?;
            print_row(&e);
            print_row(&i);
            pairs.push((e, i));
            anyhow::Ok(())
        };
        let kirsch = |factor: f64, method: SolveMethod| {
            let mut s = scaled(&cx.kirsch, factor);
            s.solve.method = method;
            let case = format!("kirsch ×{factor} exact traction, {}", method.name());
            run(&s, &case, OuterLoad::Exact)
        };
        let mut levels: Vec<(f64, KirschResult, KirschResult)> = Vec::new();
        for factor in KIRSCH_LEVELS {
            let (e, i) = (
                kirsch(factor, SolveMethod::Explicit)?,
                kirsch(factor, SolveMethod::Implicit)?,
            );
            both(&|method| {
                Ok(match method {
                    SolveMethod::Explicit => e.report(),
                    _ => i.report(),
                })
            })?;
            levels.push((factor, e, i));
        }
        both(&|method| incompressible::run_by(0.45, false, 0.06, method))?;
        for nu in [0.45, 0.499] {
            both(&|method| incompressible::run_by(nu, true, 0.06, method))?;
        }
        both(&|method| gravity::self_weight_by(0.5, method))?;
        let weak_mixed = Rock {
            mixed: true,
            ..WEAK_ROCK
        };
        for rock in [
            Rock::SHIPPED,
            WEAK_ROCK,
            weak_mixed,
            DILATANT_ROCK,
            DILATANT_MIXED,
        ] {
            both(&|method| salencon::run_rock_by(&cx.kirsch, 1.0, 0.0, &rock, method))?;
            both(&|method| {
                let release = match method {
                    SolveMethod::Explicit if rock == DILATANT_MIXED => DILATANT_MIXED_RAMP,
                    _ => bundled::quasi_static(method),
                };
                salencon::run_rock_released_by(&cx.kirsch, 1.0, &rock, method, release)
            })?;
        }
        for thickness in [0.15, 0.05] {
            both(&|method| lined::run_by(&cx.kirsch, 1.0, thickness, method))?;
        }
        for fraction in [0.25, 0.6] {
            both(&|method| Ok(pullout::run_by(fraction, 0.1, method)?.0))?;
        }
        let fractions = [0.8, 0.6, 0.5, 0.4, 0.3, 0.2, 0.1, 0.05, 0.0];
        for slowly in [false, true] {
            both(&|method| {
                let release = if slowly {
                    bundled::quasi_static(method)
                } else {
                    0
                };
                let grc =
                    salencon::ground_reaction_by(&cx.kirsch, 1.0, &fractions, method, release);
                Ok(grc?.1)
            })?;
        }
        both(&|method| Ok(softening::run_by(0.1, 0.004, 2e-7, method)?.report()))?;
        both(&|method| direct_shear::run_by(0.0625, method))?;
        for k in [1e11, 1e12] {
            both(&|method| Ok(glued::run_glued_by(&cx.kirsch, k, method)?.report()))?;
        }
        both(&|method| Ok(glued::run_coulomb_by(&cx.kirsch, 1e11, 30.0, method)?.report()))?;
        let dir = cx.root.join("target/validation/bundled");
        let mut tunnel_paths = None;
        for file in [
            "models/tunnel.json",
            "models/jointed_tunnel.json",
            "models/jointed_tunnel_mixed.json",
        ] {
            let run = |method, release, sub: &str| {
                bundled::run(&cx.root, file, method, release, &dir.join(sub))
            };
            let e = run(SolveMethod::Explicit, 0, "e")?;
            let i = run(SolveMethod::Implicit, 0, "i")?;
            let slow_e = run(SolveMethod::Explicit, bundled::QUASI_STATIC_RAMP, "se")?;
            let slow_i = run(SolveMethod::Implicit, bundled::QUASI_STATIC_STEPS, "si")?;
            for (path, e, i) in [("at once", &e, &i), ("slowly", &slow_e, &slow_i)] {
                let (re, ri) = bundled::reports(file, path, e, i);
                both(&|method| {
                    Ok(match method {
                        SolveMethod::Explicit => re.clone(),
                        _ => ri.clone(),
                    })
                })?;
            }
            if tunnel_paths.is_none() {
                tunnel_paths = Some((e, i, slow_e, slow_i));
            }
        }
        let jointed = adit::Scene::load(&cx.root.join("models/jointed_tunnel.json"))?;
        for mode in [BlockMode::Rigid, BlockMode::Simple] {
            for (path, slowly) in [("at once", false), ("slowly", true)] {
                let by = |method| modes::run_by(&jointed, mode, method, slowly);
                let (e, i) = (by(SolveMethod::Explicit)?, by(SolveMethod::Implicit)?);
                let (re, ri) = modes::method_reports(&e, &i, path);
                both(&|method| {
                    Ok(match method {
                        SolveMethod::Explicit => re.clone(),
                        _ => ri.clone(),
                    })
                })?;
            }
        }
        let peer_md = peer_section(cx, &levels)?;
        let _ = writeln!(md, "\n## Implicit static solve (issue 17)\n");
        let _ = writeln!(
            md,
            "`solve.method: implicit` (`src/implicit/`, `docs/theory.md`): the stiffness of the zones \
             (and of the contacts, with their joints' elastic stiffness) factorized by faer's sparse \
             Cholesky, each iteration solving K Δu = R for the out-of-balance force of the explicit \
             force stages and moving the model through the same laws, to the same unbalanced-force \
             ratio; yielding zones and slipping joints converge by the initial-stiffness method \
             accelerated by Anderson mixing of the last {depth} iterates. The zones' and the joints' \
             laws and the bolts' grout slip and yield are evaluated from the load step's start and \
             the whole increment since (trial and commit: a zone's Mohr–Coulomb stress returns to \
             its yield surface, at its edges and corners too, a joint's shear stress to its \
             Coulomb limit, its residual one where it fails within the step, from the last \
             commit; contacts detected anew within a step commit \
             their joints where they are), so a step's answer does not depend on the iterations \
             that reach it. A plastic answer depends on the loading path, explicitly \
             too: released at once, the explicit solve overshoots dynamically and yields further. \
             So the plastic cases are solved along two paths, at once and slowly (the quasi-static \
             path: explicit over {ramp} cycles a stage, `solve.ramp`; implicit in {steps} load \
             steps, `solve.load_steps`); the last column of the second table shows by how much \
             the answers differ. Each case of the report below solved both ways: Kirsch's hole with the exact traction on its outer boundary at \
             four zonings (×2 coarser to ×0.4 finer than shipped), Lamé's cylinder (ν = 0.45 in plain triangles; ν = 0.45 and 0.499 in mixed zones, \
             `zoning.mixed`, whose matrix is the plain triangles' while the residual is the mixed \
             zone stage's), \
             the self-weight column (h = 0.5 m), Salençon's hole at the shipped rock, the weak \
             rock of issue 13 in plain and in mixed zones, a dilatant rock (c = 2 MPa, φ = 35°, \
             ψ = 10°, p0 = 20 MPa) and a dilatant rock in mixed zones (c = 1 MPa, φ = 25°, \
             ψ = 10°, ν = 0.4, p0 = 15 MPa: a yielding zone's plastic change of mean stress is \
             averaged over its patches, which the implicit trial lags into its next predictor; \
             released slowly over 64000 explicit cycles, as over 16000 it was not yet \
             quasi-static: 6.6 % from the closed form at the wall, against 8.4 % over 64000 \
             and 8.5 % in the implicit's 16 load steps), each at once and slowly, the \
             lined hole of Einstein–Schwartz (liners: beam elements and their wall links in the \
             matrix) and the grouted bolt's pull-out, elastic and with the grout slipping (bolts: \
             segments and grout springs in the matrix, the slip converging by the iterations), and \
             the bundled `models/tunnel.json` (Mohr–Coulomb rock, non-persistent joints, bolts, \
             shotcrete, three stages) and `models/jointed_tunnel.json` (372 deformable blocks) and \
             `models/jointed_tunnel_mixed.json` (deformable near the tunnel, simple beyond), whose \
             implicit rows give the relative change of the median wall closure and of the count of \
             yielded zones from the explicit run along the same path (issue 17's bar: 1 %; the \
             paths are below the table), and the jointed tunnel in \
             rigid and in simple blocks (their generalised displacements as the unknowns), whose \
             implicit rows give the change of the median wall closure, at once and slowly (their \
             slip depends on its path more than the deformable blocks': explicit over {block_ramp} \
             cycles, implicit in {block_steps} load steps, `modes::QUASI_STATIC_RAMP`; the largest \
             closures, in the case names, differ by design: released at once, a loose rigid or \
             simple wedge keeps drifting explicitly at the speed it had, as in UDEC, while the \
             static solve leaves it where it lost its clamping, as the deformable wedges stop); \
             further, Salençon's \
             ground reaction curve (staged support pressures 100 % to 0 %, each stage at once and \
             slowly), the strain-softening specimen of issue 5 (zones of 0.1 m; its platen \
             driven by 4e-5 m between samples, explicitly over 200 cycles, implicitly as one \
             static solve under displacement control, `implicit::solve_driven`; its error is the \
             peak's, the branch after it localizing along a path of its own; with zones of \
             0.05 m the first implicit solve past the peak, at ε = 1.06e-3, does not converge \
             within 500 iterations, nor 2 000: a localizing band can snap back, which has no \
             static path under platen control, and the explicit solve passes it dynamically), \
             the direct shear of \
             a Coulomb joint (zones of 0.0625 m; the box driven by 1e-5 m between samples; the \
             continuously yielding joint is refused by the implicit path, which would give that \
             law, hardening along the path of its shear, a load step's whole increment at once), \
             the Kirsch model cut \
             by glued joints (kn = 1e11 and 1e12 Pa/m) and by the same joints with Coulomb \
             friction 30° (slipping near the hole). \
             Cycles are the explicit cycles or the implicit iterations; the seconds include meshing \
             and setting up.\n",
            ramp = bundled::QUASI_STATIC_RAMP,
            steps = bundled::QUASI_STATIC_STEPS,
            depth = adit::implicit::ANDERSON_DEPTH,
            block_ramp = modes::QUASI_STATIC_RAMP,
            block_steps = modes::QUASI_STATIC_STEPS,
        );
        let rows: Vec<CaseReport> = pairs
            .iter()
            .flat_map(|(e, i)| [e.clone(), i.clone()])
            .collect();
        table(&mut md, &rows);
        let _ = writeln!(
            md,
            "\nSide by side. Factor MB: the Cholesky factor's non-zeros × {FACTOR_VALUE_BYTES} bytes \
             (its values; the largest allocation of the solve). Speed-up: explicit over implicit \
             wall seconds, meshing included; solve only: both less the implicit run's seconds \
             outside its solve (meshing and setting up, the same code either way). Largest change: the largest \
             difference of any of the case's relative errors, implicit − explicit, in percentage \
             points (issue 17's bar for the nonlinear cases: within 0.5, or better against the \
             closed form; an elastic row's change is the explicit path's own convergence error, as \
             the implicit solve is exact to round-off).\n"
        );
        let _ = writeln!(
            md,
            "| case | zones | explicit cycles | explicit s | implicit iterations | factorizations | factor MB | implicit s | speed-up | speed-up, solve only | largest change, pp |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
        );
        for (e, i) in &pairs {
            let cost = i.implicit.unwrap_or_default();
            let change = e
                .errors
                .iter()
                .map(|(k, ve)| i.errors.get(k).map_or(f64::NAN, |vi| vi - ve))
                .fold(0.0f64, |a, d| if d.abs() > a.abs() { d } else { a });
            // Meshing and setting up are the same code either way: what the implicit run spent
            // outside its solve is taken off both to compare the solves alone.
            let solve_s = cost.seconds();
            let setup_s = i.wall_s - solve_s;
            let _ = writeln!(
                md,
                "| {} | {} | {} | {:.2} | {} | {} | {:.1} | {:.2} | {:.1}× | {:.1}× | {:+.3} |",
                e.case.trim_end_matches(", explicit"),
                e.zones,
                e.cycles,
                e.wall_s,
                i.cycles,
                cost.factorizations,
                cost.factor_nonzeros as f64 * FACTOR_VALUE_BYTES / 1e6,
                i.wall_s,
                e.wall_s / i.wall_s,
                (e.wall_s - setup_s) / solve_s,
                100.0 * change
            );
        }
        if let Some((e, i, se, si)) = &tunnel_paths {
            let _ = writeln!(
                md,
                "\nEach bundled model is solved along the same two paths: its stages' loads \
                 released at once (explicit: the dynamic overshoot of a sudden excavation, damped \
                 out), and slowly (explicit: over {} cycles per stage; implicit: in {} load \
                 steps). The tunnel's median wall closure: explicit {:.2} mm with {} \
                 zones yielded at once ({} cycles, {:.2} s), {:.2} mm with {} zones slowly ({} \
                 cycles, {:.2} s); implicit {:.2} mm with {} zones at once ({} iterations, {:.2} s), \
                 {:.2} mm with {} zones slowly ({} iterations, {:.2} s). Issue 17's bar of 1 % \
                 {} between the two quasi-static answers; released at once the explicit \
                 solve overshoots by {:.1} % of closure.\n",
                bundled::QUASI_STATIC_RAMP,
                bundled::QUASI_STATIC_STEPS,
                1e3 * e.closure,
                e.yielded,
                e.cycles,
                e.wall_s,
                1e3 * se.closure,
                se.yielded,
                se.cycles,
                se.wall_s,
                1e3 * i.closure,
                i.yielded,
                i.cycles,
                i.wall_s,
                1e3 * si.closure,
                si.yielded,
                si.cycles,
                si.wall_s,
                match bundled::differences(se, si) {
                    (closure, yielded) if closure < bundled::BAR && yielded < bundled::BAR => {
                        "holds"
                    }
                    _ => "does not hold",
                },
                100.0 * (e.closure - se.closure) / se.closure,
            );
        }
        md.push_str(&peer_md);
        Ok(Section {
            markdown: md,
            rows,
            ..Default::default()
        })
    }
}

/// The peer comparison (scikit-fem P1 on adit's own Kirsch meshes) with its plot, or the note
/// saying why it was skipped.
fn peer_section(
    cx: &Context,
    levels: &[(f64, KirschResult, KirschResult)],
) -> anyhow::Result<String> {
    let mut md = String::new();
    let _ = writeln!(md, "\n### Against an implicit finite-element peer\n");
    if let Err(note) = peer::available() {
        let _ = writeln!(md, "Skipped: {note}.\n");
        return Ok(md);
    }
    let dir = cx.root.join("target/validation/peer");
    let mut peers = Vec::new();
    for (factor, _, _) in levels {
        let p = peer::solve(&cx.kirsch, *factor, &dir)?;
        println!(
            "scikit-fem P1 peer, kirsch ×{factor}: {} unknowns, {:.3} s, stress_l2 {:.3e}, difference from adit {:.1e}",
            p.unknowns, p.seconds, p.stress_l2, p.difference
        );
        peers.push(p);
    }
    let _ = writeln!(
        md,
        "scikit-fem (`validation/peer/kirsch_skfem.py`: linear triangles, SciPy's sparse direct \
         solver) solves the exact-traction Kirsch problem of the table above on adit's own mesh, \
         with the same fixities and the same nodal force, so the two solve one discrete problem: \
         their zone stresses differ by round-off (last column, over the largest exact stress) and \
         the comparison is of speed. The peer's seconds are its assembly, solve and stresses; adit's \
         solve seconds are the implicit solve's assembly, factorization and iterations, and its \
         total adds meshing and setting up (which the peer, reading adit's mesh, does not do).\n"
    );
    let _ = writeln!(
        md,
        "| zoning | zones | unknowns | explicit s | adit implicit total s | adit implicit solve s | scikit-fem s | solve speed-up over scikit-fem | stress L2 | difference |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    );
    for ((factor, e, i), p) in levels.iter().zip(&peers) {
        let cost = i.implicit.unwrap_or_default();
        let solve_s = cost.seconds();
        let _ = writeln!(
            md,
            "| ×{factor} | {} | {} | {:.2} | {:.3} | {:.3} | {:.3} | {:.1}× | {:.3e} | {:.1e} |",
            i.zones,
            cost.unknowns,
            e.wall_s,
            i.wall_s,
            solve_s,
            p.seconds,
            p.seconds / solve_s,
            p.stress_l2,
            p.difference
        );
    }
    let series = |label: &str, points: Vec<(f64, f64, f64)>, color, dashed| Series {
        label: label.to_string(),
        points,
        color,
        dashed,
    };
    let (blue, green, grey) = (
        plotters::style::RGBColor(31, 119, 180),
        plotters::style::RGBColor(44, 160, 44),
        plotters::style::RGBColor(127, 127, 127),
    );
    let implicit_solve = |i: &KirschResult| i.implicit.unwrap_or_default().seconds();
    let plot = [
        series(
            "adit implicit, total",
            levels
                .iter()
                .map(|(_, _, i)| (i.h, i.wall_s, i.stress_l2))
                .collect(),
            blue,
            false,
        ),
        series(
            "adit implicit, solve",
            levels
                .iter()
                .map(|(_, _, i)| (i.h, implicit_solve(i), i.stress_l2))
                .collect(),
            blue,
            true,
        ),
        series(
            "scikit-fem P1, assemble + solve",
            levels
                .iter()
                .zip(&peers)
                .map(|((_, _, i), p)| (i.h, p.seconds, p.stress_l2))
                .collect(),
            green,
            false,
        ),
        series(
            "adit explicit, total",
            levels
                .iter()
                .map(|(_, e, _)| (e.h, e.wall_s, e.stress_l2))
                .collect(),
            grey,
            false,
        ),
    ];
    let image = cx.root.join("docs/img/implicit_peer.png");
    speed_and_convergence(&image, &plot)?;
    let _ = writeln!(
        md,
        "\n![stress error against seconds and zone size: adit implicit and explicit, scikit-fem](img/implicit_peer.png)\n"
    );
    Ok(md)
}
