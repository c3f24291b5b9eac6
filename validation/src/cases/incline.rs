//! A block on an incline: sliding and holding near the friction angle, friction-induced flutter, Rayleigh damping.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use adit::scene::{BlockMode, RayleighComponents};

use crate::incline;
use crate::plot::{Curve, curves};
use crate::rayleigh;
use crate::report::CaseReport;
use plotters::style::RGBColor;

/// The incline's flutter sweep (issue 13 defect 3): text, table and a plot of the error against
/// the joint stiffness per block mode.
fn flutter_section(
    md: &mut String,
    rows: &[(f64, CaseReport)],
    root: &std::path::Path,
) -> anyhow::Result<()> {
    let _ = writeln!(
        md,
        "\n### Friction-induced flutter: sliding 1° from holding, against the joint's stiffness\n\n\
         A block that slides with every contact slipping feels a friction force μ kn L δn at each contact, \
         so its normal displacement drives tangential forces and the stiffness of small perturbations is \
         not symmetric. For a deformable or simple block two of its modes can merge into a pair that grows \
         as e^(σt) (mode-coupling flutter: Martins, Oden & Simões 1990; Hoffmann et al. 2002; Adams 1995 \
         for elastic half-spaces); a rigid block's slide feels no tangential stiffness and cannot flutter. \
         `validation/src/flutter.rs` linearizes steady sliding of the block on a rigid base (the simple \
         block with the engine's generalized masses; the deformable block on the engine's own mesh and \
         lumped masses) and takes σ as the largest real part of the eigenvalues. Here each block is \
         released at 0.1 m/s down a 45° slope on φ = 44° (x = v0 t + ½ a t²), so a vibration slower than \
         the slide cannot reverse its slip: where σ = 0 every mode matches the closed form, and at half the \
         step the same; where σ is a few tens per second (e^(σt) stays small in 0.5 s) they match too; from a few \
         hundred per second the deformable and simple blocks depart, more as σ grows; rigid blocks \
         match on every joint. Released from rest instead (the rows above), a block within 1° of its \
         friction angle slides slower than the vibration that the release itself starts, and the same \
         reversal lets a deformable block on the softest joint (σ = 0) slide 6 % too far; that answer is \
         converged (zones of 0.25, 0.125, 0.0625 m: +5.7, +5.9, +6.0 %; half the step: +5.9 %). Rayleigh \
         damping (`solve.rayleigh`, next section) takes the flutter away.\n"
    );
    let reports: Vec<CaseReport> = rows.iter().map(|(_, r)| r.clone()).collect();
    table(md, &reports);
    let colors = [
        RGBColor(31, 119, 180),
        RGBColor(44, 160, 44),
        RGBColor(214, 39, 40),
    ];
    let sweep = incline::SWEEP_STIFFNESS.len() * 3;
    let plotted: Vec<Curve> = [BlockMode::Deformable, BlockMode::Simple, BlockMode::Rigid]
        .into_iter()
        .zip(colors)
        .enumerate()
        .map(|(m, (mode, color))| Curve {
            label: incline::mode_name(mode).to_string(),
            points: rows[..sweep]
                .iter()
                .skip(m)
                .step_by(3)
                .map(|(kn, r)| (kn.log10(), 100.0 * r.errors["displacement"]))
                .collect(),
            color,
            dots: true,
        })
        .collect();
    curves(
        &root.join("docs/img/incline_flutter.png"),
        "block sliding 1° from holding, released at 0.1 m/s",
        ("log10 joint stiffness kn (Pa/m)", "displacement error (%)"),
        &plotted,
    )?;
    let _ = writeln!(md, "\n![incline flutter sweep](img/incline_flutter.png)\n");
    Ok(())
}

/// The damped incline sweep and the Rayleigh damping column (issue 13 defect 3), with the bars
/// read from the rows.
fn damped_section(md: &mut String, damped: &[CaseReport], column: &[CaseReport]) {
    let sliding: Vec<&CaseReport> = damped
        .iter()
        .filter(|r| r.errors.contains_key("final"))
        .collect();
    let worst_slide = sliding
        .iter()
        .map(|r| r.errors["displacement"])
        .fold(0.0, f64::max);
    let holding = damped
        .iter()
        .filter(|r| !r.errors.contains_key("final"))
        .map(|r| r.errors["displacement"])
        .fold(0.0, f64::max);
    let step_change = incline::DAMPED_STEP_PAIRS
        .iter()
        .map(|&(a, b)| (damped[a].errors["final"] - damped[b].errors["final"]).abs())
        .fold(0.0, f64::max);
    let verdict = |ok: bool| if ok { "met" } else { "NOT met" };
    let _ = writeln!(
        md,
        "\n### Damped sliding: Rayleigh damping takes the flutter away\n\n\
         The shipped joint (kn = 1e11 Pa/m) from rest, as in the first table, with stiffness-proportional \
         Rayleigh damping (`solve.rayleigh`, `components: stiffness`: a slide is a rigid-body motion and is \
         not resisted). Its viscous stresses are β_R times the rate of the zones' and contacts' stresses, \
         friction included, so the linearization above holds with the damping matrix C = β_R K: each row \
         names σ without and with the damping. β_R is the smallest of 1e-4 · 2^k s that makes the \
         block's slide on φ = 44° stable (1e-4 s, 5 % at 159 Hz, deformable, where zones of 0.25 m need it; \
         5e-5 s, 5 % at 318 Hz, simple; the rigid block needs none and takes 2e-4 s to show it changes \
         nothing), over 0.5 s. `final` is \
         the signed error at the end. Largest sliding error {:.2} % (bar 2 %: **{}**); holding block {:.1e} \
         of a frictionless slide; halving the step changes the deformable block's final slide by {:.2} % \
         (bar 1 %: **{}**; the simple block's, 20 million cycles at half the step, by nothing to three \
         figures, 2.97e-3 at both, in the complete run on `ccb6213`'s code: left out of the report's run \
         for its 852 s). What remains from rest is a velocity the deformable block gains in its first \
         milliseconds, while the slide is still slower than the vibration the release starts (released at \
         0.1 m/s, the row after the holding one, the same block follows the closed form). The \
         damping costs steps: Δt falls by √(1 + ξ_max²) − ξ_max with ξ_max = β_R / Δt_crit (compare \
         the cycles with the undamped rows above; more on finer zones, whose fastest modes are damped \
         hardest).\n",
        100.0 * worst_slide,
        verdict(worst_slide <= 0.02),
        holding,
        100.0 * step_change,
        verdict(step_change <= 0.01),
    );
    table(md, damped);
    let _ = writeln!(
        md,
        "\n## Dynamics: Rayleigh damping\n\n\
         A 2 m × 10 m column (E = 10 GPa, ν = 0.25, ρ = 2 500 kg/m³) on a fixed base between rollers, \
         released unstressed under gravity, vibrates about its static settlement in the fixed–free bar's \
         modes ω_n = (2n − 1)πc/(2H), each decaying at ξ_n = ½(α_R/ω_n + β_R ω_n) \
         (`validation/src/rayleigh.rs`: the modal series of the top's displacement, 200 modes). \
         ξ = 5 % at the fundamental ({:.1} Hz) in each form, over six of its periods. `response`: the \
         largest error of the top's displacement over the run relative to the static settlement; `decay`: \
         the damping read from the logarithmic decrement of the top's peaks against ξ_1.\n",
        rayleigh::mode_frequency(1) / std::f64::consts::TAU
    );
    table(md, column);
}

/// What the holding rows show: that every block holds, or which walk down the slope (more than
/// `incline::WALKS` of a frictionless slide in the run), read from the rows: a walking block whose settled
/// base has a growing mode (σ > 0 in its name) flutters; one without is a defect.
fn holding_verdict(rows: &[CaseReport]) -> String {
    let walking: Vec<&CaseReport> = rows
        .iter()
        .filter(|r| r.case.contains(": holds") && r.errors["displacement"] > incline::WALKS)
        .collect();
    if walking.is_empty() {
        return "holding blocks hold in every mode".to_string();
    }
    let says = |r: &CaseReport| match incline::named_growth_rate(&r.case) {
        Some(sigma) if sigma > 0.0 => format!(
            "\"{}\" walks {:.2} of a frictionless slide: its settled base is at the friction \
             limit at the contacts named, the state of steady sliding at rest, and with those \
             contacts slipping it grows at σ = {sigma:.0} 1/s, so a round-off that sets them \
             slipping grows into the flutter of the sliding rows (whether it does is chance: \
             next table)",
            r.case, r.errors["displacement"]
        ),
        _ => format!(
            "\"{}\" walks {:.2} of a frictionless slide (a defect: its settled base has no \
             growing mode)",
            r.case, r.errors["displacement"]
        ),
    };
    let said: Vec<String> = walking.iter().map(|r| says(r)).collect();
    format!(
        "holding blocks hold **but {} of them**: {}",
        walking.len(),
        said.join("; ")
    )
}

/// The holding block settled to other ratios and implicitly: the same static state, walking or
/// holding by its round-off.
fn holding_section(md: &mut String, rows: &[CaseReport]) {
    let walks = rows
        .iter()
        .filter(|r| r.errors["displacement"] > incline::WALKS)
        .count();
    let _ = writeln!(
        md,
        "\n### Holding at the friction limit: the settle's round-off decides\n\n\
         The deformable block holding at 43° on φ = 44° on zones of 0.125 m, undamped, settled \
         explicitly to unbalanced-force ratios {} and then implicitly (`solve.method: implicit`). \
         Each settle reaches the same static state, every contact of its base at the friction \
         limit but the toe's (each row names how many). That is steady sliding \
         at rest, and its linearization with those contacts slipping and the toe stuck grows at the \
         σ each row names (`flutter::partly_slipping_growth_rate`). What differs is the \
         out-of-balance force the settle leaves: where it slips the contacts at the limit, the \
         flutter grows from round-off and the block walks; where it does not, it holds. {walks} \
         of {} walk. The block is statically stable; released without damping it is dynamically \
         unstable, as the sliding block is, and Rayleigh damping holds it (the damped holding row \
         below).\n",
        incline::HOLDING_SETTLE_RATIOS
            .map(|r| format!("{r:.0e}"))
            .join(", "),
        rows.len(),
    );
    table(md, rows);
}

pub struct Incline;

impl Case for Incline {
    fn name(&self) -> &'static str {
        "incline"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let root = &cx.root;
        let mut md = String::new();
        let incline_cases = vec![
            incline::run(30.0, 20.0, 0.5, 0.125, BlockMode::Deformable)?,
            incline::run(30.0, 40.0, 0.5, 0.125, BlockMode::Deformable)?,
            incline::run(30.0, 20.0, 0.5, 0.125, BlockMode::Simple)?,
            incline::run(30.0, 40.0, 0.5, 0.125, BlockMode::Simple)?,
            incline::run(30.0, 20.0, 0.5, 0.125, BlockMode::Rigid)?,
            incline::run(30.0, 40.0, 0.5, 0.125, BlockMode::Rigid)?,
        ]
        .into_iter()
        .chain(
            // Within 1° of the friction angle on both sides, at a low and a high friction (issue 13).
            [(20.0, 21.0), (21.0, 20.0), (43.0, 44.0), (45.0, 44.0)]
                .into_iter()
                .flat_map(|(alpha, phi)| {
                    [BlockMode::Deformable, BlockMode::Simple, BlockMode::Rigid]
                        .map(|mode| incline::run(alpha, phi, 0.5, 0.125, mode))
                })
                .collect::<anyhow::Result<Vec<_>>>()?,
        )
        .collect::<Vec<_>>();
        for r in &incline_cases {
            print_row(r);
        }
        let holding_cases = incline::holding_sweep(0.125)?;
        for r in &holding_cases {
            print_row(r);
        }
        let flutter_cases = incline::flutter_sweep(0.125)?;
        for (_, r) in &flutter_cases {
            print_row(r);
        }
        let damped_cases = incline::damped_sweep(0.125)?;
        for r in &damped_cases {
            print_row(r);
        }
        let column_cases = [1.0, 0.5]
            .into_iter()
            .flat_map(|h| {
                [
                    RayleighComponents::Both,
                    RayleighComponents::Stiffness,
                    RayleighComponents::Mass,
                ]
                .map(|components| rayleigh::Column {
                    h,
                    fraction: 0.05,
                    components,
                })
            })
            .chain([rayleigh::Column {
                h: 0.5,
                fraction: 0.0,
                components: RayleighComponents::Both,
            }])
            .map(|c| c.run())
            .collect::<anyhow::Result<Vec<_>>>()?;
        for r in &column_cases {
            print_row(r);
        }
        let _ = writeln!(md, "## Jointed rock: block on an incline\n");
        let _ = writeln!(
            md,
            "A 1 m × {height} m block (deformable, simple or rigid) on a fixed deformable base, joined by a Coulomb joint \
         (kn = ks = 1e11 Pa/m); gravity is tilted by α. Sliding at 45° on φ = 44°, the resultant of the normal \
         forces on its base lies μ h / 2 = {e:.2} m ahead of its middle, within the kern (1/6 m), so its whole base \
         stays closed; a block 0.5 m high lifts its heel, and then even a rigid block flutters (its bounce and \
         rocking couple through the friction's moment; `flutter::heel`). The block settles statically: on its own joint when \
         it holds (φ ≥ α), on a joint that cannot slip when it slides, which then takes its friction φ; the \
         run continues in real time without damping. Sliding: the block's mean displacement against \
         ½ g (sin α − cos α tan φ) t² over 0.5 s (`displacement`: largest error over 20 samples relative to \
         the final exact value). Holding: its displacement relative to a frictionless slide. The rows within \
         1° of the friction angle are issue 13's: {holding}; rigid blocks slide as \
         the closed form; deformable and simple ones slide too far where σ > 0, more so at high friction. Each sliding \
         row names the growth rate σ of friction-induced flutter (`validation/src/flutter.rs`, below): on \
         this stiff joint steady sliding of a deformable or simple block is unstable, its vibration grows \
         until contacts open and, where the slide is slower than the vibration, slip backwards, and the \
         friction averages out. That is the modelled system's own dynamics; the sweep below shows it.\n",
            height = incline::BLOCK_HEIGHT,
            e = 0.5 * adit::joint::tan_deg(44.0) * incline::BLOCK_HEIGHT,
            holding = holding_verdict(&incline_cases),
        );
        table(&mut md, &incline_cases);
        holding_section(&mut md, &holding_cases);
        flutter_section(&mut md, &flutter_cases, root)?;
        damped_section(&mut md, &damped_cases, &column_cases);
        let mut rows = incline_cases;
        rows.extend(holding_cases);
        rows.extend(flutter_cases.iter().map(|(_, r)| r.clone()));
        rows.extend(damped_cases);
        rows.extend(column_cases);
        Ok(Section {
            markdown: md,
            rows,

            ..Default::default()
        })
    }
}
