//! Generalized Hoek–Brown rock (issue 48): the element test at ten confining pressures and in
//! direct tension, and Carranza-Torres's hole, at three rock masses.

use std::fmt::Write as _;

use adit::scene::SolveMethod;

use crate::axisymmetric::STEPS;
use crate::carranza_torres::{self, POOR_SUPPORT, POOR_UNSUPPORTED, ROCKS, Rock};
use crate::case::{Case, Context, Section, print_row, table, verdict};
use crate::report::CaseReport;
use crate::salencon::Leg;
use crate::triaxial;

/// Zone edge of the element test's specimen, m.
const EDGE: f64 = 0.5;
/// Cycles over which the specimen is driven past its peak.
const DRIVE_CYCLES: u64 = 400_000;
/// Bar of the element test: relative error of σ1.
const ELEMENT_BAR: f64 = 1e-6;
/// Bar of the hole: plastic radius and wall displacement, relative.
const HOLE_BAR: f64 = 0.03;
/// The rock (in `ROCKS`) whose hole, released explicitly on the default zoning, localizes: its
/// plastic zone bands on one side (`wall_spread` ten times the implicit path's) and the wall
/// closes the more the slower the release; reported, not barred, its explicit bar carried by
/// `quasi_static_then_explicit` (the report's section says why).
const LOCALIZES: usize = 1;
/// Ratio of the explicit cycling that follows the quasi-static path: a hundred times the hole's.
const HOLD_RATIO: f64 = 1e-7;

/// The closed form's quasi-static path (implicit load steps), then explicit cycling to
/// `HOLD_RATIO`: whether explicit cycling holds the axisymmetric equilibrium once on it.
fn quasi_static_then_explicit(steps: u64) -> Vec<Leg> {
    vec![
        Leg::new(SolveMethod::Implicit, steps),
        Leg {
            method: SolveMethod::Explicit,
            release: 0,
            ratio: Some(HOLD_RATIO),
        },
    ]
}

/// σ1 = σ3 + σci (mb σ3/σci + s)^a, Pa (compression positive).
fn strength(rock: &Rock, sigma3: f64) -> f64 {
    let (mb, s, a) = adit::law::hoek_brown_constants(rock.gsi, rock.mi, 0.0);
    sigma3 + rock.sigma_ci * (mb * sigma3 / rock.sigma_ci + s).powf(a)
}

/// The apex σt = s σci / mb, Pa: the tension at which the envelope closes.
fn apex(rock: &Rock) -> f64 {
    let (mb, s, _) = adit::law::hoek_brown_constants(rock.gsi, rock.mi, 0.0);
    s * rock.sigma_ci / mb
}

/// Uniaxial tensile strength t on the envelope with σ1 = 0: t = σci (s − mb t/σci)^a, by
/// bisection on [0, apex] (the left side falls from σci s^a to 0 − apex).
fn uniaxial_tension(rock: &Rock) -> f64 {
    let (mut lo, mut hi) = (0.0, apex(rock));
    for _ in 0..200 {
        let t = 0.5 * (lo + hi);
        if strength(rock, -t) > 0.0 {
            lo = t;
        } else {
            hi = t;
        }
    }
    0.5 * (lo + hi)
}

/// The rock as a scene's material object, with a tension cut-off when given (Pa).
fn material(rock: &Rock, tension: Option<f64>) -> serde_json::Value {
    let mut m = serde_json::json!({
        "density": 2600, "young": rock.young, "poisson": rock.poisson, "law": "hoek_brown",
        "sigma_ci": rock.sigma_ci, "gsi": rock.gsi, "mi": rock.mi, "dilation": rock.dilation_deg
    });
    if let Some(t) = tension {
        m["tensile_strength"] = t.into();
    }
    m
}

/// Ten confining pressures, Pa: 0.5 and 0.25 of the apex in tension, none, and up to 0.4 σci.
fn confinements(rock: &Rock) -> [f64; 10] {
    let mut p = [0.0; 10];
    p[0] = -0.5 * apex(rock);
    p[1] = -0.25 * apex(rock);
    for (k, f) in [0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.4].iter().enumerate() {
        p[k + 3] = f * rock.sigma_ci;
    }
    p
}

fn rock_name(rock: &Rock) -> String {
    format!(
        "GSI {}, mi {}, σci {} MPa, ψ {}°",
        rock.gsi,
        rock.mi,
        rock.sigma_ci / 1e6,
        rock.dilation_deg
    )
}

/// `rock_name` with the hole's support pressure.
fn hole_name(rock: &Rock) -> String {
    format!("{}, pi {} MPa", rock_name(rock), rock.pi / 1e6)
}

/// Direct tension of the rock's specimen (σ3 = 0, the top pulled) with a cut-off at half its
/// uniaxial tensile strength, by `method`: the relative error of the strength against the
/// cut-off, and the run.
fn direct_tension(rock: &Rock, method: SolveMethod) -> anyhow::Result<(f64, triaxial::Strength)> {
    let e_plane = rock.young / (1.0 - rock.poisson * rock.poisson);
    let cut_off = 0.5 * uniaxial_tension(rock);
    let strain = -(1.5 * cut_off / e_plane + 1e-5);
    let r = triaxial::strength(
        &material(rock, Some(cut_off)),
        0.0,
        EDGE,
        (strain, DRIVE_CYCLES),
        method,
    )?;
    Ok(((-r.sigma1 - cut_off).abs() / cut_off, r))
}

/// The rock's specimen confined by `sigma3` (Pa) and compressed past its peak by `method`: the
/// relative error of its strength against the envelope's, and the run.
fn on_envelope(
    rock: &Rock,
    sigma3: f64,
    method: SolveMethod,
) -> anyhow::Result<(f64, triaxial::Strength)> {
    let e_plane = rock.young / (1.0 - rock.poisson * rock.poisson);
    let exact = strength(rock, sigma3);
    let strain = 1.5 * (exact - sigma3) / e_plane + 1e-4;
    let r = triaxial::strength(
        &material(rock, None),
        sigma3,
        EDGE,
        (strain, DRIVE_CYCLES),
        method,
    )?;
    Ok(((r.sigma1 - exact).abs() / exact, r))
}

/// The element tests of one rock: the envelope at ten confinements (largest relative error of σ1)
/// and direct tension with a cut-off at half the uniaxial tensile strength.
fn element_tests(rock: &Rock, method: SolveMethod) -> anyhow::Result<CaseReport> {
    let mut worst = 0.0f64;
    let (mut zones, mut cycles, mut seconds) = (0, 0, 0.0);
    for sigma3 in confinements(rock) {
        let (error, r) = on_envelope(rock, sigma3, method)?;
        worst = worst.max(error);
        (zones, cycles, seconds) = (r.zones, cycles + r.cycles, seconds + r.seconds);
    }
    let t = uniaxial_tension(rock);
    let (tension, r) = direct_tension(rock, method)?;
    (cycles, seconds) = (cycles + r.cycles, seconds + r.seconds);
    Ok(CaseReport::new(
        format!(
            "Hoek–Brown element test {}: 10 confinements, direct tension at half its uniaxial σt {:.3} MPa (apex {:.3} MPa){}",
            rock_name(rock),
            t / 1e6,
            apex(rock) / 1e6,
            crate::method_suffix(method)
        ),
        zones,
        cycles,
        seconds,
        Some(EDGE),
        &[("envelope", worst), ("tension", tension)],
    ))
}

/// The one-dimensional axisymmetric solve of a rock's hole with adit's own Hoek–Brown law
/// (`crate::axisymmetric`, no assumption on σzz) against Carranza-Torres's closed form (σzz the
/// intermediate stress).
struct Reference {
    rock: Rock,
    /// Wall displacement and plastic radius, relative to the closed form's (signed).
    wall: f64,
    radius: f64,
    out_of_plane: bool,
}

fn reference(rock: &Rock) -> anyhow::Result<Reference> {
    reference_of(rock, None, STEPS)
}

/// `reference` of `rock` softening to the constants of `residual`'s GSI (the rock's mi, D = 0)
/// over its plastic shear strain, if given, unloaded in `steps` steps.
fn reference_of(
    rock: &Rock,
    residual: Option<(f64, f64)>,
    steps: usize,
) -> anyhow::Result<Reference> {
    let constants = adit::law::hoek_brown_constants(rock.gsi, rock.mi, 0.0);
    let mut law = adit::law::HoekBrown::new(
        adit::law::Elastic::from_young(rock.young, rock.poisson, 1.0),
        rock.sigma_ci,
        constants,
        rock.dilation_deg,
        f64::INFINITY,
    );
    let mut closed = carranza_torres::CarranzaTorres::new(
        1.0,
        (rock.p0, rock.pi),
        rock.sigma_ci,
        constants,
        rock.dilation_deg.to_radians(),
        rock.young / (2.0 * (1.0 + rock.poisson)),
        rock.poisson,
    );
    if let Some((gsi, strain)) = residual {
        let (mb, s, a) = adit::law::hoek_brown_constants(gsi, rock.mi, 0.0);
        law = law.with_residual(adit::law::Residual { mb, s, a, strain });
        closed = closed.with_residual((mb, s, a));
    }
    let one_d = crate::axisymmetric::solve_law(&law, 1.0, (rock.p0, rock.pi), 1e-8, steps)?;
    Ok(Reference {
        rock: *rock,
        wall: one_d.wall_displacement / closed.wall_displacement() - 1.0,
        radius: one_d.plastic_radius / closed.plastic_radius() - 1.0,
        out_of_plane: one_d.out_of_plane_yield,
    })
}

fn write_references(md: &mut String, references: &[Reference]) {
    let _ = writeln!(
        md,
        "\nThe closed form itself, checked by the one-dimensional axisymmetric solve of each hole \
         with adit's own Hoek–Brown law (`validation/src/axisymmetric.rs`: 1 200 elements, 60 \
         unloading steps; σzz free to become the major or minor stress, which the closed form \
         assumes it never does):\n"
    );
    let _ = writeln!(
        md,
        "| rock | 1D wall displacement vs closed form | 1D plastic radius vs closed form | yields out of plane |"
    );
    let _ = writeln!(md, "|---|---:|---:|---|");
    for r in references {
        let _ = writeln!(
            md,
            "| {} | {:+.2} % | {:+.2} % | {} |",
            hole_name(&r.rock),
            100.0 * r.wall,
            100.0 * r.radius,
            if r.out_of_plane { "yes" } else { "no" }
        );
    }
}

pub struct HoekBrown;

impl Case for HoekBrown {
    fn name(&self) -> &'static str {
        "hoek_brown"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let mut md = String::new();
        let mut missed = Vec::new();
        let mut elements = Vec::new();
        for rock in &ROCKS {
            for method in [SolveMethod::Explicit, SolveMethod::Implicit] {
                elements.push(element_tests(rock, method)?);
            }
        }
        for r in &elements {
            print_row(r);
            if r.errors.values().any(|&e| e > ELEMENT_BAR) {
                missed.push(format!("{}: {:?} beyond {ELEMENT_BAR:e}", r.case, r.errors));
            }
        }
        let ramp = crate::bundled::quasi_static(SolveMethod::Explicit);
        let steps = crate::bundled::quasi_static(SolveMethod::Implicit);
        let (mut holes, mut unsolved) = (Vec::new(), Vec::new());
        for (k, rock) in ROCKS.iter().enumerate() {
            // The explicit release over as many periods of the mesh's slowest mode: its cycles
            // grow as the zones across the model.
            let runs = [
                (1.0, vec![Leg::new(SolveMethod::Explicit, 0)]),
                (1.0, vec![Leg::new(SolveMethod::Explicit, ramp)]),
                (0.5, vec![Leg::new(SolveMethod::Explicit, 2 * ramp)]),
                (1.0, vec![Leg::new(SolveMethod::Implicit, steps)]),
                (0.5, vec![Leg::new(SolveMethod::Implicit, steps)]),
                (1.0, quasi_static_then_explicit(steps)),
            ];
            for (factor, path) in runs {
                let barred = factor == 1.0
                    && path[0].release > 0
                    && !(k == LOCALIZES && path == [Leg::new(SolveMethod::Explicit, ramp)]);
                let r = match hole_or_why(cx, factor, rock, &path) {
                    Ok(r) => r,
                    Err(what) => {
                        if barred {
                            missed.push(format!("not solved: {what}"));
                        }
                        unsolved.push(what);
                        continue;
                    }
                };
                if barred && !r.hole_within(HOLE_BAR) {
                    missed.push(format!("{}: {:?} beyond {HOLE_BAR}", r.case, r.errors));
                }
                holes.push(r);
            }
        }
        let unsupported = unsupported_holes(cx, ramp, steps);
        let references: Vec<Reference> = (ROCKS.iter().chain([&POOR_UNSUPPORTED]))
            .map(reference)
            .collect::<anyhow::Result<_>>()?;
        let mohr_coulomb = crate::salencon::run(&cx.kirsch, 1.0, 0.0)?;
        print_row(&mohr_coulomb);
        let hoek_brown_at_once = holes
            .iter()
            .find(|r| r.case.starts_with("Hoek–Brown hole GSI 50") && r.case.ends_with("(×1)"))
            .ok_or_else(|| anyhow::anyhow!("the fair rock's hole released at once"))?;
        write_section(
            &mut md,
            &elements,
            &holes,
            (&mohr_coulomb, hoek_brown_at_once),
        );
        for what in &unsolved {
            let _ = writeln!(md, "\nNot solved: {what}.");
        }
        write_unsupported(&mut md, &unsupported);
        write_references(&mut md, &references);
        let _ = writeln!(
            md,
            "\nBars (issue 48): the element test within {ELEMENT_BAR:e} of the envelope and of the \
             tensile strength, explicit and implicit; the hole released slowly on the shipped \
             zoning (×1) within {} % in plastic radius and wall displacement, explicit and \
             implicit, the fair rock's explicit release excepted (it localizes, above: its \
             explicit bar is the quasi-static path then explicit cycling to a ratio of \
             {HOLD_RATIO:e}): {}.\n",
            100.0 * HOLE_BAR,
            verdict(&missed)
        );
        let mut rows = elements;
        rows.extend(holes);
        rows.extend(unsupported.into_iter().filter_map(Result::ok));
        rows.push(mohr_coulomb);
        Ok(Section {
            markdown: md,
            rows,
            missed,
            ..Default::default()
        })
    }
}

/// The poor rock unsupported (not a bar, see `carranza_torres::POOR_SUPPORT`): released slowly
/// on the zonings ×1 and ×0.5, explicitly and implicitly; each run or why it was not solved.
fn unsupported_holes(cx: &Context, ramp: u64, steps: u64) -> Vec<Result<CaseReport, String>> {
    let runs = [
        (1.0, SolveMethod::Explicit, ramp),
        (0.5, SolveMethod::Explicit, 2 * ramp),
        (1.0, SolveMethod::Implicit, steps),
    ];
    (runs.into_iter())
        .map(|(factor, method, release)| {
            hole_or_why(cx, factor, &POOR_UNSUPPORTED, &[Leg::new(method, release)])
        })
        .collect()
}

/// Carranza-Torres's hole in `rock` on the zoning ×`factor` solved along `path`
/// (`carranza_torres::run_along`), its row printed; or why it was not solved (the rock, zoning,
/// method and error), printed too.
fn hole_or_why(cx: &Context, factor: f64, rock: &Rock, path: &[Leg]) -> Result<CaseReport, String> {
    match carranza_torres::run_along(&cx.kirsch, factor, rock, path) {
        Ok(r) => {
            print_row(&r);
            Ok(r)
        }
        Err(e) => {
            let what = format!(
                "{} on the zoning ×{factor}, {}: {e}",
                hole_name(rock),
                path[0].method.name()
            );
            println!("{what}");
            Err(what)
        }
    }
}

fn write_unsupported(md: &mut String, runs: &[Result<CaseReport, String>]) {
    let _ = writeln!(
        md,
        "\n**The poor rock unsupported** (reported, not a bar). The poor rock's bar is its hole \
         under a support pressure of {} MPa (3 % of p0). Unsupported, the closed form's wall lies \
         at σ3 = 0, where the criterion's slope dσ1/dσ3 is 15.5 and its apex 17.5 kPa away in \
         tension: the constant stress of a triangle near the wall strays past the apex by more than \
         that (σθ changes by about 7 MPa per metre there), those zones fail in tension (a ring \
         about 0.4 m deep on the ×1 zoning), carry less hoop stress, and the plastic zone grows \
         and the wall closes too much. Neither a slower release (19.4 % over 16 000 cycles, 20.0 % \
         over 64 000) nor mixed zones (19.8 %) nor a tension cut-off at 0 instead of the apex \
         (15.4 %) removes it, and finer zones make it worse (explicitly, released slowly: −7.0 % \
         on zones twice the shipped size, +11.4 % on the shipped zoning as written, +19.7 % on \
         zones half the size, +19.4 % on the default zoning): it diverges where a \
         discretization error would converge. 0.3 MPa of support removes it (1.7 %, no zone in \
         tension; 0.1 MPa: 9.3 %). Itasca's \
         verification of this hole in FLAC supports it too (p_i = p0/6). The one-dimensional \
         solve below meets the closed form unsupported: the closed form holds, the \
         triangles do not resolve its wall.\n",
        POOR_SUPPORT / 1e6
    );
    let rows: Vec<CaseReport> = runs
        .iter()
        .filter_map(|r| r.as_ref().ok().cloned())
        .collect();
    table(md, &rows);
    for what in runs.iter().filter_map(|r| r.as_ref().err()) {
        let _ = writeln!(md, "\nNot solved: {what}.");
    }
}

fn write_section(
    md: &mut String,
    elements: &[CaseReport],
    holes: &[CaseReport],
    (mohr_coulomb, hoek_brown): (&CaseReport, &CaseReport),
) {
    let support = POOR_SUPPORT / 1e6;
    let _ = writeln!(
        md,
        "\n## Hoek–Brown rock: element tests and Carranza-Torres's hole (issue 48)\n"
    );
    let _ = writeln!(
        md,
        "Three rock masses (mb, s, a from GSI and mi with D = 0; E, ν and p0 of the hole below): \
         good (GSI 75, mi 25, σci 150 MPa, E 40 GPa, ν 0.2, p0 100 MPa, ψ 0), fair (GSI 50, mi 12, \
         σci 80 MPa, E 10 GPa, ν 0.25, p0 30 MPa, ψ 5°) and poor (GSI 25, mi 8, σci 40 MPa, \
         E 2 GPa, ν 0.3, p0 10 MPa, ψ 0; its hole's wall supported by {support} MPa, see below).\n\n\
         **Element test** (`validation/src/triaxial.rs`): a 1 m × 2 m plane-strain specimen in \
         zones of {EDGE} m, confined by σ3 on its sides, compressed between smooth platens to 1.5 \
         times its peak strain over {DRIVE_CYCLES} cycles, brought to rest and relaxed to a ratio \
         of 1e-10; the platen stress against σ1 = σ3 + σci (mb σ3/σci + s)^a at ten confinements \
         (0.5 and 0.25 of the apex σt = s σci/mb in tension, 0, and 0.01 to 0.4 σci): `envelope` \
         is the largest relative error. Direct tension (σ3 = 0, the top pulled) with a cut-off at \
         half the uniaxial tensile strength t = σci (s − mb t/σci)^a fails at the cut-off: \
         `tension`. (Pulled with the default cut-off at the apex, the specimen peaks at t to \
         2e-4 while driven, but t lies within 1e-3 of the apex, where the envelope's slope is \
         infinite: relaxed, zones slide along it to the apex and the specimen ends 6–9 % below \
         t, so that test is not a measure of the law; likewise confined by 0.9 of the apex in \
         tension, where the envelope's slope dσ1/dσ3 reaches 65 in the good rock, the driven \
         peak is within 1.3e-4 but with ψ = 0 the relaxed specimen localizes and unloads by \
         40 %: the strongly non-associated flow's instability, not the return.) \
         Implicitly the specimen is driven in 40 static steps.\n"
    );
    table(md, elements);
    let _ = writeln!(
        md,
        "\n**Carranza-Torres's hole** (2004): the Kirsch geometry (a = 1 m, 40 m square; ×1: the \
         zoning a user gets by default, the shipped graded zoning with its plastic zone refined, \
         `zoning.plastic_depth: \"auto\"`; ×0.5: the shipped zoning halved everywhere, not \
         refined further) under hydrostatic p0 (the poor rock's wall under its support \
         pressure pi), to a ratio of 1e-5 (the bundled models'; \
         implicitly the fair rock's first load step stalls between 2e-6 and 1e-5 on the refined \
         zoning and does not reach 1e-6), the hole excavated at once (zones start \
         at −p0, the wall free), solved explicitly released at once and slowly (the out-of-balance \
         force over {} cycles on ×1, twice as many on ×0.5, or implicitly in {} load steps: the \
         closed form's quasi-static path), against the closed form \
         integrated numerically (`validation/src/carranza_torres.rs`: pcr from 2(p0 − pcr) = \
         q(pcr), ln(Rp/a) = ∫ dσ/q(σ) from 0 to pcr, σr by RK4 in ln r, the wall displacement \
         from the flow rule's compatibility with the elastic strains). Measures as for Salençon: \
         `plastic_radius` (the hole's area plus the yielded zones' as a circle), `stress_l2` \
         (σr, σθ over r ≤ 3Rp), `wall_displacement` (mean radial displacement of the wall), \
         `wall_spread` (a measure: the wall's largest minus smallest radial displacement over the \
         mean). The rows \"then explicit\" continue the implicit path's answer by explicit \
         cycling to a ratio of {HOLD_RATIO:e}.\n",
        crate::bundled::QUASI_STATIC_RAMP,
        crate::bundled::QUASI_STATIC_STEPS
    );
    table(md, holes);
    write_localization(md);
    let _ = writeln!(
        md,
        "\n**Speed**: the fair rock's hole released at once runs at {:.2e} zone-cycles per second, \
         Salençon's Mohr–Coulomb hole on the same zoning at {:.2e} (ratio {:.2}), in this run.\n",
        hoek_brown.zone_cycles_per_s,
        mohr_coulomb.zone_cycles_per_s,
        hoek_brown.zone_cycles_per_s / mohr_coulomb.zone_cycles_per_s
    );
}

/// Why the fair rock's explicit release is not barred, and what is instead (`LOCALIZES`).
fn write_localization(md: &mut String) {
    let _ = writeln!(
        md,
        "\n**The fair rock released explicitly localizes** (reported, not a bar). `wall_spread` is \
         the wall's largest minus smallest radial displacement over the mean: for the fair rock \
         about 1 % along the implicit path and after it, about 10 % released explicitly on the \
         default zoning, whose plastic zone forms shear bands on one side. Its flow is strongly \
         non-associated (ψ 5° against the envelope's friction angle, 63° at the wall falling to \
         30° at the plastic radius), and a perfectly plastic solid with non-associated flow can localize (its critical \
         hardening modulus is positive: Rudnicki & Rice 1975): the axisymmetric closed form is \
         one answer of a problem that has others, and the dynamic release picks another. It is \
         a bifurcation, not a discretization error: the slower the release, the worse (3.6 % \
         closure over 16 000 cycles, 7.4 % over 32 000; the hole excavated in eight stages of \
         support pressure, the convergence–confinement method, each settled explicitly: \
         +11.7 %, implicitly +0.6 %; on zones half the size 2.3 % over 32 000 cycles, 3.1 % over \
         64 000), and both answers are equilibria of the same zoning: explicit cycling from the \
         quasi-static path's answer to a ratio of {HOLD_RATIO:e}, a hundred times tighter, stays \
         on it (the rows \"then explicit\"). That row is the fair rock's explicit bar; the other \
         rocks' explicit releases keep theirs. A user whose rock flows this non-associatively \
         should solve its excavation implicitly (`solve.method` `implicit`, `load_steps`) or \
         check the plastic zone's symmetry where the geometry has one."
    );
}

/// Bar of the elastic–brittle–plastic hole: plastic radius and wall displacement, relative.
const BRITTLE_BAR: f64 = 0.05;

/// The brittle rock: the fair rock's peak dropping to GSI 30's constants over this plastic shear
/// strain (at once: the drop's own elastic strain is ten times more).
const BRITTLE: (f64, f64) = (30.0, 1e-4);

/// Load steps of the brittle hole's implicit path, the bar's; the report also gives 16 and 64.
pub const BRITTLE_STEPS: u64 = 256;

/// Unloading steps of the one-dimensional reference of the brittle hole.
const BRITTLE_REFERENCE_STEPS: [usize; 3] = [60, 240, 960];

/// The brittle hole on the shipped zoning (×`factor`), by `method` over `release` (explicit ramp
/// cycles or implicit load steps).
fn brittle_hole(
    kirsch: &adit::Scene,
    factor: f64,
    (method, release): (SolveMethod, u64),
) -> anyhow::Result<CaseReport> {
    carranza_torres::run_brittle(kirsch, factor, &ROCKS[1], BRITTLE, (method, release))
}

/// The elastic–brittle–plastic hole: the fair rock softening to GSI 30's constants at once.
pub struct HoekBrownBrittle;

impl Case for HoekBrownBrittle {
    fn name(&self) -> &'static str {
        "hoek_brown_brittle"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let ramp = crate::bundled::quasi_static(SolveMethod::Explicit);
        let runs = [
            (1.0, SolveMethod::Explicit, ramp),
            (1.0, SolveMethod::Explicit, 4 * ramp),
            (0.5, SolveMethod::Explicit, 2 * ramp),
            (1.0, SolveMethod::Implicit, 16),
            (1.0, SolveMethod::Implicit, 64),
            (1.0, SolveMethod::Implicit, BRITTLE_STEPS),
        ];
        let (mut rows, mut missed) = (Vec::new(), Vec::new());
        for (factor, method, release) in runs {
            let r = brittle_hole(&cx.kirsch, factor, (method, release))?;
            print_row(&r);
            // The bar is the quasi-static path's: the implicit one's (see the section's text for
            // why the explicit path is reported, not barred).
            let barred =
                factor == 1.0 && method != SolveMethod::Explicit && release == BRITTLE_STEPS;
            if barred && !r.hole_within(BRITTLE_BAR) {
                missed.push(format!("{}: {:?} beyond {BRITTLE_BAR}", r.case, r.errors));
            }
            rows.push(r);
        }
        let references: Vec<(usize, Reference)> = (BRITTLE_REFERENCE_STEPS.iter())
            .map(|&n| Ok((n, reference_of(&ROCKS[1], Some(BRITTLE), n)?)))
            .collect::<anyhow::Result<_>>()?;
        let mut md = String::new();
        let _ = writeln!(
            md,
            "\n## Hoek–Brown rock: the elastic–brittle–plastic hole (issue 48)\n\n\
             The fair rock of the section above (GSI 50, mi 12, σci 80 MPa, E 10 GPa, ν 0.25, \
             ψ 5°, p0 30 MPa) softening to the constants of GSI {} over a plastic shear strain of \
             {:e} (`residual`: the strength drops at once), released slowly (explicitly over \
             {ramp} cycles, and {} and, on zones half the size, {} cycles; implicitly in 16, 64 \
             and {BRITTLE_STEPS} load steps), against Carranza-Torres's (2004) elastic–brittle–plastic solution (pcr \
             from the peak constants, the plastic zone on the residual ones, σθ dropping at Rp; \
             `CarranzaTorres::with_residual`), to a ratio of 1e-5, on the shipped zoning as \
             written (`zoning.plastic_depth` 0: refined through its plastic zone, the default, \
             the implicit path's {BRITTLE_STEPS} load steps do not converge within their cuts). \
             Bar: plastic radius and wall displacement within {} % on the shipped zoning, \
             along the quasi-static path (implicitly in {BRITTLE_STEPS} steps); the explicit \
             path is reported, not barred (below).\n",
            BRITTLE.0,
            BRITTLE.1,
            4 * ramp,
            2 * ramp,
            100.0 * BRITTLE_BAR
        );
        table(&mut md, &rows);
        let _ = writeln!(
            md,
            "\nThe closed form is the quasi-static path's: the one-dimensional axisymmetric solve \
             with adit's own law (`validation/src/axisymmetric.rs`, no assumption on σzz) \
             converges to it as its unloading steps shrink, each step returning the whole step's \
             strain from its start (a zone whose strength drops within a step sheds its load \
             only at the step's end):\n\n\
             | unloading steps | 1D wall displacement vs closed form | 1D plastic radius vs closed form |\n\
             |---:|---:|---:|"
        );
        for (n, r) in &references {
            let _ = writeln!(
                md,
                "| {n} | {:+.2} % | {:+.2} % |",
                100.0 * r.wall,
                100.0 * r.radius
            );
        }
        let _ = writeln!(
            md,
            "\nSo does the implicit path in the Kirsch geometry (16, 64, {BRITTLE_STEPS} load \
             steps above). The explicit path cannot follow it, however slowly it releases: the \
             drop's own elastic strain is ten times its plastic strain (a snap-back), so a zone \
             that fails sheds its load in a few cycles whatever the ramp, and the energy it \
             releases moves its neighbours dynamically; and a strength that drops with a plastic \
             strain localizes in a band one zone wide, so its answer depends on the zone size \
             (Bažant's local softening continuum). Measured: a ramp four times longer moves the \
             error little, zones half the size double it (the rows above). The quasi-static \
             closed form is the implicit path's bar; the explicit rows show what a dynamic \
             release of brittle rock does, not a discretization error. {}\n",
            if missed.is_empty() {
                "Bar met.".to_string()
            } else {
                format!("Bar missed by {}.", missed.join("; "))
            }
        );
        Ok(Section {
            markdown: md,
            rows,
            missed,
            ..Default::default()
        })
    }
}

#[cfg(test)]
mod coarse {
    use super::*;

    /// The brittle hole's coarse twin: implicitly in the bar's load steps, within the bar of
    /// Carranza-Torres's elastic–brittle–plastic solution (in 16 steps it is not: 12 % and 26 %).
    #[test]
    fn the_brittle_hole_meets_its_closed_form_in_small_steps() {
        let kirsch = crate::shipped_kirsch().unwrap();
        let r = brittle_hole(&kirsch, 1.0, (SolveMethod::Implicit, BRITTLE_STEPS)).unwrap();
        for what in ["plastic_radius", "wall_displacement"] {
            assert!(r.errors[what] < BRITTLE_BAR, "{what}: {r:?}");
        }
    }

    /// The fair rock's element test: its envelope at three confinements (one near the apex),
    /// explicit and implicit, and direct tension at a cut-off below its uniaxial strength, each
    /// within 1e-6.
    #[test]
    fn a_hoek_brown_specimen_ends_on_its_envelope() {
        let rock = &ROCKS[1];
        for method in [SolveMethod::Explicit, SolveMethod::Implicit] {
            for sigma3 in [-0.5 * apex(rock), 0.0, 0.2 * rock.sigma_ci] {
                let (error, r) = on_envelope(rock, sigma3, method).unwrap();
                assert!(
                    error < ELEMENT_BAR,
                    "{method:?} σ3 {sigma3}: {} against {}",
                    r.sigma1,
                    strength(rock, sigma3)
                );
            }
        }
        let t = uniaxial_tension(rock);
        assert!(t > 0.0 && t < apex(rock));
        for method in [SolveMethod::Explicit, SolveMethod::Implicit] {
            let (error, r) = direct_tension(rock, method).unwrap();
            assert!(
                error < ELEMENT_BAR,
                "{method:?}: {} against {}",
                -r.sigma1,
                0.5 * t
            );
        }
    }
}
