//! Slopes by strength reduction of Hoek–Brown rock (issue 49): the generalized method of Hammah
//! et al. (2005) against Bishop's simplified method with the envelope's instantaneous strength.

use std::fmt::Write as _;

use adit::scene::SolveMethod;
use adit::strength_reduction::FactorOfSafety;

use crate::case::{Case, Context, Section, print_row, table, verdict};
use crate::slope::{self, hoek_brown_slope};

/// Bar: within 5 % of Bishop's on the 0.5 m zones (as the Coulomb slope's on its finest),
/// explicit and implicit within 1 % of each other on the 1 m zones.
const SLOPE_BAR: f64 = 0.05;
const APART_BAR: f64 = 0.01;

/// The zone sizes, m: the last carries the bar. (On 0.25 m zones, 44 271 of them, the implicit
/// path does not settle the gravity stage itself: its ratio stalls where the surface rock sits
/// at the envelope's apex, and the search finds F < 1; measured once, left for the implicit
/// path's apex handling.)
const ZONES: [f64; 2] = [1.0, 0.5];

/// `max_cycles` of the explicit search, on the 1 m zones. (On the 0.5 m zones, 150 000 cycles a
/// trial found 1.8281 against the implicit 1.8203 in 1 361 s, measured on `3731ada`'s code: the
/// report's second costliest row, so the paths are compared on the coarser zones.)
const EXPLICIT_CYCLES: u64 = 100_000;

/// `max_cycles` of the Hoek–Brown tunnel's explicit search (its stages and trials).
const TUNNEL_CYCLES: u64 = 100_000;

pub struct SlopeHoekBrown;

/// The zones the trial at a search's factor of safety turned inside out and its largest node
/// displacement, m (none and 0 when no trial was stable).
fn at_factor(fos: &FactorOfSafety) -> (usize, f64) {
    fos.at_factor()
        .map_or((0, 0.0), |t| (t.inverted, t.displacement_m))
}

impl Case for SlopeHoekBrown {
    fn name(&self) -> &'static str {
        "slope_hb"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let (mut rows, mut missed) = (Vec::new(), Vec::new());
        let mut implicit = Vec::new();
        let mut bishop = 0.0;
        for zone in ZONES {
            let (r, f, b) = slope::hoek_brown(SolveMethod::Implicit, zone, 40_000)?;
            print_row(&r);
            bishop = b;
            implicit.push(f);
            rows.push(r);
        }
        let at_bar = &rows[ZONES.len() - 1];
        if !(at_bar.errors["bishop"] <= SLOPE_BAR) {
            missed.push(format!(
                "{}: {:?} beyond {SLOPE_BAR}",
                at_bar.case, at_bar.errors
            ));
        }
        let (r, explicit, _) = slope::hoek_brown(SolveMethod::Explicit, ZONES[0], EXPLICIT_CYCLES)?;
        print_row(&r);
        rows.push(r);
        let apart = (explicit - implicit[0]).abs() / implicit[0];
        if apart > APART_BAR {
            missed.push(format!(
                "1 m zones: explicit {explicit:.4}, implicit {:.4} ({:.2} % apart)",
                implicit[0],
                100.0 * apart
            ));
        }
        let (tunnel_row, tunnel_fos, _) =
            slope::bundled(&cx.root, "models/tunnel_hb.json", None, true)?;
        print_row(&tunnel_row);
        rows.push(tunnel_row);
        let explicitly = Some((SolveMethod::Explicit, TUNNEL_CYCLES));
        let (row, tunnel_explicit, _) =
            slope::bundled(&cx.root, "models/tunnel_hb.json", explicitly, true)?;
        print_row(&row);
        rows.push(row);
        let (f_auto, f_explicit) = (tunnel_fos.factor, tunnel_explicit.factor);
        let tunnel_apart = (f_explicit - f_auto).abs() / f_auto;
        let [auto_at, explicit_at] = [&tunnel_fos, &tunnel_explicit].map(at_factor);
        let whole = auto_at.0 == 0 && explicit_at.0 == 0;
        if whole && tunnel_apart > APART_BAR {
            missed.push(format!(
                "models/tunnel_hb.json: explicit {f_explicit:.4}, auto {f_auto:.4} ({:.2} % apart)",
                100.0 * tunnel_apart
            ));
        }
        let tunnel_verdict = if whole {
            "both factors' trials leave the rock whole, so the bar holds"
        } else {
            "a factor's trial turned zones inside out, so the bar is not posed: reported"
        };
        let rock = hoek_brown_slope().hoek_brown.expect("a Hoek–Brown slope");
        let mut md = String::new();
        let _ = writeln!(
            md,
            "\n## Factor of safety by strength reduction: Hoek–Brown rock (issue 49)\n"
        );
        let _ = writeln!(
            md,
            "A Hoek–Brown rock has no single c and φ: at each normal stress its envelope's tangent \
             has its own (instantaneous) cᵢ and φᵢ, and dividing those by F divides the shear \
             strength by F at every σn. The reduced envelope is fitted with a generalized \
             Hoek–Brown one (σci kept, mb, s, a fitted; Hammah, Yacoub, Corkum & Curran 2005, as \
             RS2 does; `src/law/hoek_brown_reduction.rs`, formulas in `docs/theory.md`). \
             **Slope**: a 2:1 slope 20 m high with a 24 m crest plateau, its base (fixed) at the \
             toe's level, rollers behind, γ 25 kN/m³, GSI 30, mi 10, D 0, σci 1 MPa (mb \
             {:.4}, s {:.3e}, a {:.4}), ψ 0, E 500 MPa, ν 0.3; settled under gravity and \
             searched (tolerance 0.005). Reference: Bishop's simplified method searched over \
             circles with each slice's base taking the envelope's instantaneous cᵢ, tan φᵢ at \
             its normal stress (iterated with the slice's vertical equilibrium; \
             `validation/src/slope.rs`, written apart from the engine's reduction): F = \
             {bishop:.4}. `bishop`: |F − F_Bishop| / F_Bishop. Implicitly on 1 and 0.5 m zones: \
             {}; explicitly on the 1 m zones ({EXPLICIT_CYCLES} cycles): {explicit:.4} (on the \
             0.5 m zones, 150 000 cycles a trial, 1.8281 in 1 361 s, measured on `3731ada`'s \
             code: the paths are compared on the coarser zones). On \
             0.25 m zones (44 271) the implicit path does not settle the gravity stage itself \
             (its ratio stalls where the surface rock sits at the envelope's apex) and the search \
             returns F < 1: left for the implicit path's apex handling. Bars: within {} % of \
             Bishop's on the 0.5 m zones, explicit and implicit within {} % of each other on the \
             1 m zones. **The Hoek–Brown tunnel** \
             (`models/tunnel_hb.json`) with its last stage searched (tolerance 0.01): F = {:.3} \
             in {} trials with `auto`, {f_explicit:.3} explicitly ({TUNNEL_CYCLES} cycles), \
             {:.2} % apart. Its mechanism is the rock mass squeezing into the tunnel, not a \
             falling block: below the factor of safety the plastic rock comes to rest after a \
             displacement that depends on the solve's path (at F = 3 on 0.5 m zones, 1.95 m \
             explicitly and 0.68 m implicitly, both converged), so a trial is judged by \
             convergence and by no block leaving the rock around it (`displacement_limit`, \
             `docs/theory.md`). At the factors found the rock has flowed into the opening further \
             than its 3 m radius: the trials at them moved nodes {:.2} m (`auto`) and {:.2} m \
             (explicitly) from the stage's equilibrium and turned {} and {} zones inside out \
             (their deformed area reversed: the rock passed through itself, which small strain \
             does not see; `adit run` warns of it); the largest factors tried whose trials \
             turned none: {:.3} and {:.3}. There the factor is where a flow of metres that small \
             strain cannot describe stops, on each path its own: `auto`'s implicit iterations \
             stop on a node pressed through its neighbouring block (interpenetration: the trials' \
             `reason`) where explicit cycling settles after tens of thousands of cycles. Not the \
             region's extent: on 1 m zones a ±80 m region finds 3.719 with `auto` against the \
             shipped ±40 m region's 3.750 (measured with `adit run`). So the {} % bar between the \
             paths is judged where both factors' trials leave the rock whole, as on the slopes \
             above; here {tunnel_verdict}.\n",
            rock.mb,
            rock.s,
            rock.a,
            implicit
                .iter()
                .map(|f| format!("{f:.4}"))
                .collect::<Vec<_>>()
                .join(", "),
            100.0 * SLOPE_BAR,
            100.0 * APART_BAR,
            tunnel_fos.factor,
            tunnel_fos.trials.len(),
            100.0 * tunnel_apart,
            auto_at.1,
            explicit_at.1,
            auto_at.0,
            explicit_at.0,
            tunnel_fos.largest_whole(),
            tunnel_explicit.largest_whole(),
            100.0 * APART_BAR,
        );
        let _ = writeln!(md, "Bars: {}.\n", verdict(&missed));
        table(&mut md, &rows);
        Ok(Section {
            markdown: md,
            rows,
            missed,
            ..Default::default()
        })
    }
}
