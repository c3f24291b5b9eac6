//! Quiet boundaries (issue 50) against Lysmer & Kuhlemeyer's plane-wave analysis ("Finite dynamic
//! model for infinite media", J. Eng. Mech. Div. ASCE 95(EM4), 1969): a plane P or S wave meeting
//! a boundary of dashpots ρCp (normal) and ρCs (tangential) obliquely is partly reflected, as a
//! wave of its own kind and one converted to the other, the reflected energy fraction depending
//! on the angle and ν alone (not on the frequency: the dashpots have none).
//!
//! The run: a plane Ricker pulse travels straight down a block of elastic rock whose sides are on
//! rollers (free along the wave's particle motion, held across it: exact for a vertical plane
//! wave, so the pulse stays plane however wide the block), its top free, its base quiet and
//! inclined at the angle, so that the pulse meets the base at the angle. The block starts with
//! the pulse's exact field (displacements, the zones' stress from them, velocities half a step
//! earlier) above the base; its energy over the block's width is the energy the pulse brings to
//! each metre of width. Along a span of the base the energy the dashpots absorb
//! (`QuietBoundary::absorbed`) over the energy the pulse brought to the span's width is the
//! absorbed fraction; the rest is reflected. The span lies far enough down the base that what the
//! base's upper corner sends (at Cp at most, from when the pulse reaches it) arrives after the
//! pulse has passed the span: the pulse's trace along the base, C / sin α, outruns Cp.

use std::time::Instant;

use adit::Scene;
use adit::law::{Elastic, ZoneLaw, plane_strain_moduli};
use adit::model::Model;
use adit::scene::WaveKind;
use adit::setup::setup;
use adit::solve::{Quiet, Solver, Status};
use adit::stage::Staging;

use crate::quiet::{ROCK, wave_speed};
use crate::report::CaseReport;

/// Peak particle velocity of the pulse, m/s.
const PEAK: f64 = 1.0;
/// Half the Ricker pulse's duration that holds it (its amplitude below 1e-3 of the peak beyond,
/// its energy below 1e-6), in periods of its peak frequency.
const HALF: f64 = 1.0;
/// Margin on every separation in time, as a fraction.
const MARGIN: f64 = 0.1;
/// The span of the base measured, in the pulse's peak S wavelengths.
const SPAN: f64 = 4.0;

/// The Lamé constants (λ, G) of `ROCK`, Pa (plane strain: λ = α2 = K − 2G/3).
fn lame() -> (f64, f64) {
    let (e, nu, rho) = ROCK;
    let (bulk, shear) = Elastic::from_young(e, nu, rho).moduli();
    (plane_strain_moduli(bulk, shear).1, shear)
}

/// A plane wave's direction of travel d and polarization a (unit vectors) and its speed, m/s.
#[derive(Debug, Clone, Copy)]
struct Plane {
    d: [f64; 2],
    a: [f64; 2],
    c: f64,
}

impl Plane {
    /// A P or S wave at `angle` (rad) from the vertical, travelling down (`up` false) or up, to
    /// the right. An S wave's polarization is d turned clockwise.
    fn new(wave: WaveKind, angle: f64, up: bool) -> Plane {
        let (s, c) = angle.sin_cos();
        let d = [s, if up { c } else { -c }];
        let a = match wave {
            WaveKind::P => d,
            WaveKind::S => [d[1], -d[0]],
        };
        Plane {
            d,
            a,
            c: wave_speed(wave),
        }
    }

    /// The rows of the quiet base's two conditions, σyy − ρCp vy = 0 and σxy − ρCs vx = 0 at
    /// y = 0, per unit displacement amplitude of this wave and per iω: from u = A a e^{i(k·x−ωt)},
    /// k = (ω/c) d, σyy/(iω) = A (λ d·a + 2G d_y a_y)/c, σxy/(iω) = A G (d_x a_y + d_y a_x)/c and
    /// v/(iω) = −A a.
    fn base_rows(&self) -> [f64; 2] {
        let ((lambda, g), rho) = (lame(), ROCK.2);
        let (cp, cs) = (wave_speed(WaveKind::P), wave_speed(WaveKind::S));
        let (d, a) = (self.d, self.a);
        [
            (lambda * (d[0] * a[0] + d[1] * a[1]) + 2.0 * g * d[1] * a[1]) / self.c
                + rho * cp * a[1],
            g * (d[0] * a[1] + d[1] * a[0]) / self.c + rho * cs * a[0],
        ]
    }
}

/// The angle (rad) from the vertical of the wave of kind `to` that a wave of kind `from` at
/// `angle` turns into at a horizontal boundary (Snell: sin α / C alike), `None` past the
/// critical angle.
fn snell(from: WaveKind, to: WaveKind, angle: f64) -> Option<f64> {
    let s = angle.sin() * wave_speed(to) / wave_speed(from);
    (s < 1.0).then(|| s.asin())
}

/// Lysmer & Kuhlemeyer's reflected energy fraction of a plane `wave` meeting a quiet boundary at
/// `angle` (rad from its normal): the reflected P and S amplitudes R_P, R_S solve the boundary's
/// two conditions (`Plane::base_rows`) for the incident wave and the two reflected ones, and each
/// reflected wave carries the energy flux ½ρCω²R² cos α through the boundary, so that the
/// fraction is Σ R² C cos α / (C₀ cos α₀) (1 for the incident wave). `None` past the critical
/// angle.
pub fn reflected_fraction(wave: WaveKind, angle: f64) -> Option<f64> {
    let incident = Plane::new(wave, angle, false);
    let p = Plane::new(WaveKind::P, snell(wave, WaveKind::P, angle)?, true);
    let s = Plane::new(WaveKind::S, snell(wave, WaveKind::S, angle)?, true);
    let (rp, rs, ri) = (p.base_rows(), s.base_rows(), incident.base_rows());
    let det = rp[0] * rs[1] - rs[0] * rp[1];
    let amp_p = (-ri[0] * rs[1] + rs[0] * ri[1]) / det;
    let amp_s = (-rp[0] * ri[1] + ri[0] * rp[1]) / det;
    let flux = |w: &Plane, r: f64| r * r * w.c * w.d[1].abs();
    Some((flux(&p, amp_p) + flux(&s, amp_s)) / flux(&incident, 1.0))
}

/// The Ricker pulse's particle velocity at `tau` s from its peak, m/s:
/// v₀ (1 − 2π²f²τ²) e^(−π²f²τ²), and the displacement it has made, ∫v dτ = v₀ τ e^(−π²f²τ²), m.
fn ricker(frequency: f64, tau: f64) -> (f64, f64) {
    let x = (std::f64::consts::PI * frequency * tau).powi(2);
    (PEAK * (1.0 - 2.0 * x) * (-x).exp(), PEAK * tau * (-x).exp())
}

/// An oblique wave on a quiet base, in a block zoned at `zone` m whose pulse's peak wavelength
/// spans `per_wavelength` zones of the S wave (the shorter of the two the base sends back).
#[derive(Debug, Clone, Copy)]
pub struct Oblique {
    pub wave: WaveKind,
    /// Degrees from the base's normal.
    pub angle: f64,
    pub zone: f64,
    pub per_wavelength: f64,
}

/// The block's layout, from the pulse's arrivals: its base runs `length` m down from the upper
/// corner at the angle; the span measured lies between `span.0` and `span.1` m down it.
struct Layout {
    length: f64,
    /// Horizontal width and the base's rise, m.
    width: f64,
    rise: f64,
    height: f64,
    span: (f64, f64),
    /// Half the pulse's duration with the margin, s.
    half: f64,
}

impl Oblique {
    /// The incident wave's speed, m/s.
    fn speed(&self) -> f64 {
        wave_speed(self.wave)
    }

    /// The pulse's peak frequency, Hz.
    fn frequency(&self) -> f64 {
        wave_speed(WaveKind::S) / (self.per_wavelength * self.zone)
    }

    /// The span starts where the pulse, reaching a point s m down the base at s sin α / C after
    /// the upper corner, has passed it (2 × half later) before anything from the corner arrives
    /// (s / Cp): s ≥ 2 half / (1/Cp − sin α / C). The base goes on below the span until what its
    /// lower corner sends (from when the pulse reaches it) would come back after the pulse has
    /// passed the span.
    fn layout(&self) -> anyhow::Result<Layout> {
        let cp = wave_speed(WaveKind::P);
        let (c, (sin, cos)) = (self.speed(), self.angle.to_radians().sin_cos());
        let half = HALF / self.frequency() * (1.0 + MARGIN);
        let outrun = 1.0 / cp - sin / c;
        anyhow::ensure!(
            outrun > 0.0,
            "{}: the pulse's trace along the base is slower than Cp",
            self.name()
        );
        let span_length = SPAN * self.per_wavelength * self.zone;
        let first = 2.0 * half * (1.0 + MARGIN) / outrun;
        let tail = 2.0 * half * (1.0 + MARGIN) / (sin / c + 1.0 / cp) + span_length;
        let round = |x: f64| (x / self.zone).ceil() * self.zone;
        let length = round(first + span_length + tail);
        let (width, rise) = (length * cos, length * sin);
        let last = first + span_length;
        Ok(Layout {
            length,
            width,
            rise,
            height: round(rise + 3.0 * c * half),
            span: (first, last),
            half,
        })
    }

    fn name(&self) -> String {
        format!(
            "{} wave at {}° on a quiet base, peak S wavelength {} zones",
            match self.wave {
                WaveKind::P => "P",
                WaveKind::S => "S",
            },
            self.angle,
            self.per_wavelength
        )
    }

    /// The block: the base from (0, 0) up to (width, rise), the sides on rollers (held across
    /// the wave's particle motion), the top free.
    fn scene(&self, layout: &Layout) -> Scene {
        let (e, nu, rho) = ROCK;
        let (w, r, h) = (layout.width, layout.rise, layout.height);
        let across = match self.wave {
            WaveKind::P => "x",
            WaveKind::S => "y",
        };
        let text = serde_json::json!({
            "name": "oblique",
            "materials": { "rock": { "density": rho, "young": e, "poisson": nu } },
            "region": { "polygon": [[0, 0], [w, r], [w, h], [0, h]],
                        "edge_names": ["base", "right", "top", "left"], "material": "rock" },
            "zoning": { "edge_at_excavation": self.zone, "edge_far": self.zone },
            "boundary": [{ "part": "base", "quiet": true },
                         { "part": "left", "fix": across }, { "part": "right", "fix": across }],
            "solve": { "mode": "dynamic", "damping": 0, "max_cycles": 1, "monitor_every": 1 }
        });
        Scene::from_json(&text.to_string(), "oblique").expect("a valid oblique block")
    }

    /// Run it: the reflected fraction measured and by the closed form, with the report.
    pub fn run(&self) -> anyhow::Result<(CaseReport, f64, f64)> {
        let start = Instant::now();
        let exact = reflected_fraction(self.wave, self.angle.to_radians())
            .ok_or_else(|| anyhow::anyhow!("{} is past the critical angle", self.name()))?;
        let layout = self.layout()?;
        let scene = self.scene(&layout);
        let mut b = setup(&scene)?;
        Staging::new(&b.plan).apply(&b.plan.stages[0], &mut b.model, &b.plan);
        let model = &mut b.model;
        let mut solver = Solver::new(model, &scene.solve, 0);
        let dt = solver.params.dt;
        let brought =
            self.launch(model, layout.rise + self.speed() * layout.half, dt) / layout.width;
        let mut span = Span::of(model, &layout, self.speed())?;
        let mut cycles = 0u64;
        while (cycles as f64) * dt < span.end() {
            let sol = solver.solve(model, &mut Quiet);
            anyhow::ensure!(
                !matches!(sol.status, Status::Failed(_)),
                "{}: {:?}",
                self.name(),
                sol.status
            );
            cycles += sol.cycles.max(1);
            span.record(model, cycles as f64 * dt);
        }
        let measured = 1.0 - span.fraction(brought);
        let report = CaseReport::new(
            format!(
                "{}: reflected {measured:.4} (Lysmer & Kuhlemeyer {exact:.4}), base {} m",
                self.name(),
                layout.length
            ),
            model.zones.len(),
            cycles,
            start.elapsed().as_secs_f64(),
            Some(self.zone),
            &[("reflected", (measured - exact).abs())],
        );
        Ok((report, measured, exact))
    }

    /// Give the model the pulse's exact field at time 0, travelling down with its peak at
    /// height `peak` m (particle motion down for a P wave, along x for an S wave):
    /// displacements, the zones' stress from them (by the zones' own law), the velocities at
    /// −Δt/2 (the central difference's). Returns the field's energy, kinetic and strain, J/m.
    fn launch(&self, model: &mut Model, peak: f64, dt: f64) -> f64 {
        let (c, f) = (self.speed(), self.frequency());
        let a = match self.wave {
            WaveKind::P => [0.0, -1.0],
            WaveKind::S => [1.0, 0.0],
        };
        let (nodes, laws) = (&mut model.nodes, &model.materials.zone);
        let mut energy = 0.0;
        for n in 0..nodes.len() {
            // Travelling down: the peak passes height y at (peak − y)/C.
            let tau = (nodes.pos[n][1] - peak) / c;
            let (_, u) = ricker(f, tau);
            let (v, _) = ricker(f, tau - 0.5 * dt);
            nodes.disp[n] = [a[0] * u, a[1] * u];
            nodes.vel[n] = [a[0] * v, a[1] * v];
            energy += 0.5 * nodes.mass[n] * v * v;
        }
        let zones = &mut model.zones;
        for z in 0..zones.len() {
            let (gr, t) = (zones.grad[z], zones.nodes[z]);
            let u = t.map(|n| nodes.disp[n as usize]);
            let exx: f64 = (0..3).map(|i| gr[i] * u[i][0]).sum();
            let eyy: f64 = (0..3).map(|i| gr[3 + i] * u[i][1]).sum();
            let gxy: f64 = (0..3).map(|i| gr[3 + i] * u[i][0] + gr[i] * u[i][1]).sum();
            let mut s = [0.0; 4];
            let law = &laws[zones.material[z].0 as usize];
            law.update(&mut s, &mut 0, &mut 0.0, &[exx, eyy, gxy]);
            energy += 0.5 * zones.area[z] * (s[0] * exx + s[1] * eyy + s[3] * gxy);
            zones.stress[z] = s;
        }
        energy
    }
}

/// The quiet base's nodes along the layout's span: each with its share of the base (half the base
/// between its neighbours, m), the time the pulse has passed it (s), and the energy its dashpots
/// had absorbed then (J/m), once that time has come.
struct Span {
    nodes: Vec<SpanNode>,
    /// cos α: the base's horizontal width per metre along it.
    cos: f64,
}

struct SpanNode {
    /// Index in the quiet boundary's nodes.
    quiet: usize,
    share: f64,
    passed: f64,
    absorbed: Option<f64>,
}

impl Span {
    /// The span's nodes of `model`'s quiet base; the pulse, at speed `c` m/s, passes a point s m
    /// down the base from its upper corner at s sin α / C + 2 × half.
    fn of(model: &Model, layout: &Layout, c: f64) -> anyhow::Result<Span> {
        let quiet = (model.quiet.as_ref())
            .ok_or_else(|| anyhow::anyhow!("the oblique block has no quiet base"))?;
        let corner = [layout.width, layout.rise];
        let mut along: Vec<(f64, usize)> = (quiet.nodes.iter().enumerate())
            .map(|(i, &n)| {
                let p = model.nodes.pos[n as usize];
                ((p[0] - corner[0]).hypot(p[1] - corner[1]), i)
            })
            .collect();
        along.sort_by(|a, b| a.0.total_cmp(&b.0));
        let sin = layout.rise / layout.length;
        let nodes: Vec<SpanNode> = (1..along.len().saturating_sub(1))
            .filter(|&k| (layout.span.0..=layout.span.1).contains(&along[k].0))
            .map(|k| SpanNode {
                quiet: along[k].1,
                share: 0.5 * (along[k + 1].0 - along[k - 1].0),
                passed: along[k].0 * sin / c + 2.0 * layout.half,
                absorbed: None,
            })
            .collect();
        anyhow::ensure!(!nodes.is_empty(), "no quiet node on the span");
        Ok(Span {
            nodes,
            cos: layout.width / layout.length,
        })
    }

    /// The time by which the pulse has passed every node, s.
    fn end(&self) -> f64 {
        self.nodes.iter().map(|n| n.passed).fold(0.0, f64::max)
    }

    /// At time `t` s: keep what each node passed by then has absorbed.
    fn record(&mut self, model: &Model, t: f64) {
        let Some(quiet) = model.quiet.as_ref() else {
            return;
        };
        for n in self
            .nodes
            .iter_mut()
            .filter(|n| n.absorbed.is_none() && n.passed <= t)
        {
            n.absorbed = Some(quiet.absorbed[n.quiet]);
        }
    }

    /// The energy the span absorbed, J/m, over what a pulse bringing `brought` J per metre of
    /// width brought it.
    fn fraction(&self, brought: f64) -> f64 {
        let absorbed: f64 = self.nodes.iter().filter_map(|n| n.absorbed).sum();
        let width: f64 = self.nodes.iter().map(|n| n.share).sum::<f64>() * self.cos;
        absorbed / (brought * width)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Lysmer & Kuhlemeyer's figures for ν = 0.25 (issue 50): P at 45° ≈ 0.004, at 60° ≈ 0.036;
    /// S at 30° ≈ 0.036; nothing reflected at normal incidence.
    #[test]
    fn the_closed_form_gives_lysmer_and_kuhlemeyers_figures() {
        let f = |w, a: f64| reflected_fraction(w, a.to_radians()).unwrap();
        assert!(f(WaveKind::P, 0.0) < 1e-20 && f(WaveKind::S, 0.0) < 1e-20);
        assert!((f(WaveKind::P, 45.0) - 0.0039).abs() < 1e-4);
        assert!((f(WaveKind::P, 60.0) - 0.0359).abs() < 1e-4);
        assert!((f(WaveKind::S, 30.0) - 0.0359).abs() < 1e-4);
        assert!(reflected_fraction(WaveKind::S, 40f64.to_radians()).is_none());
    }

    /// The coarse twin of the report's rows: the reflected fraction within ±0.02 of the closed
    /// form for P at 60° and S at 30° (the report's coarser pulse, and coarser still for P), and
    /// nothing reflected at normal incidence.
    #[test]
    fn an_oblique_wave_reflects_off_a_quiet_base_as_lysmer_and_kuhlemeyer_found() {
        for (wave, angle, per_wavelength) in [
            (WaveKind::P, 0.0, 10.0),
            (WaveKind::P, 60.0, 10.0),
            (WaveKind::S, 30.0, 12.0),
        ] {
            let case = Oblique {
                wave,
                angle,
                zone: 1.0,
                per_wavelength,
            };
            let (r, measured, exact) = case.run().unwrap();
            assert!((measured - exact).abs() < 0.02, "{r:?}");
        }
    }
}
