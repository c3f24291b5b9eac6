//! The dynamic stress concentration at a hole under a plane P wave (issue 50) against Pao &
//! Mow's series.

use std::fmt::Write as _;

use plotters::style::RGBColor;

use crate::case::{Case, Context, Section, print_row, table, verdict};
use crate::pao_mow::{Hole, QUASI_STATIC};
use crate::plot::{Curve, curves};

/// Bars (issue 50), on the finest zones: the quasi-static concentration within 2 %, the peak
/// within 5 %.
const QUASI_STATIC_BAR: f64 = 0.02;
const PEAK_BAR: f64 = 0.05;
/// The wall's zone sizes, m, coarsest first.
const WALL_ZONES: [f64; 2] = [0.05, 0.025];
/// The hole's radius, the square's width and the zones away from the hole, m; the Ricker
/// pulse's peak frequency, Hz.
const RADIUS: f64 = 1.0;
const SIZE: f64 = 110.0;
const FAR_ZONE: f64 = 1.0;
const FREQUENCY: f64 = 60.0;

pub struct PaoMow;

impl Case for PaoMow {
    fn name(&self) -> &'static str {
        "pao_mow"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let (mut rows, mut missed, mut finest) = (Vec::new(), Vec::new(), None);
        for wall_zone in WALL_ZONES {
            let hole = Hole {
                radius: RADIUS,
                size: SIZE,
                wall_zone,
                far_zone: FAR_ZONE,
                frequency: FREQUENCY,
            };
            let (row, _) = hole.quasi_static()?;
            print_row(&row);
            rows.push(row);
            let m = hole.run()?;
            print_row(&m.report);
            let within = m.quasi_static <= QUASI_STATIC_BAR && m.peak <= PEAK_BAR;
            if wall_zone == WALL_ZONES[WALL_ZONES.len() - 1] {
                if !within {
                    missed.push(format!("{}: {:?}", m.report.case, m.report.errors));
                }
                finest = Some(m.curve.clone());
            }
            rows.push(m.report);
        }
        let curve = finest.expect("a finest run");
        curves(
            &cx.root.join("docs/img/pao_mow.png"),
            &format!(
                "Hole under a plane P wave: hoop stress at θ = 90°, zones {} m at the wall",
                WALL_ZONES[1]
            ),
            ("αa", "|σθθ| / σ₀"),
            &[
                Curve {
                    label: "run".into(),
                    points: curve.iter().map(|c| (c.0, c.1)).collect(),
                    color: RGBColor(200, 60, 40),
                    dots: true,
                },
                Curve {
                    label: "Pao & Mow".into(),
                    points: curve.iter().map(|c| (c.0, c.2)).collect(),
                    color: RGBColor(40, 40, 40),
                    dots: false,
                },
            ],
        )?;
        let mut md = String::new();
        let _ = writeln!(
            md,
            "\n## A hole under a plane P wave: dynamic stress concentration (issue 50)\n"
        );
        let _ = writeln!(
            md,
            "A hole of radius a = {RADIUS} m at the centre of a {SIZE} m square of elastic rock \
             (E 10 GPa, ν 0.25, ρ 2 500 kg/m³: Cp 2 191 m/s), its base quiet with a Ricker P pulse \
             (peak {FREQUENCY} Hz, peak particle velocity 0.1 m/s) coming in, its sides \
             free-field, its top quiet; zones of the sizes below on the wall, {FAR_ZONE} m away \
             from it (16 or more to the shortest wavelength compared); undamped. The hoop stress \
             at the wall points where the wave's front first runs along it (θ = 90° from its \
             direction), every step, extrapolated from the zones within 0.3 a of each point by a \
             least-squares quadratic in the polar offsets; its Fourier transform over the \
             incident stress's, ρCp V(ω) of the Ricker's velocity, is the measured |σθθ|/σ₀ at \
             αa = ωa/Cp, over the band where the pulse's spectrum is above a tenth of its peak. \
             Against Pao & Mow's series (1973; the scattered potentials with Bessel functions, \
             `validation/src/pao_mow.rs`): `quasi_static` the largest relative error below \
             αa = {QUASI_STATIC}, `peak` that of the largest concentration over the band (2.908 \
             at αa ≈ 0.25), `band` the largest over the whole band. The square is wide enough \
             that what the hole scatters comes back to it from the boundaries only in the \
             window's fall (the window: until the pulse has passed the hole and 10 wall transits \
             of the S wave more, then a half-cosine fall over a period). The gauge itself is read on the static limit (the same hole and \
             zones solved statically under uniaxial strain, Kirsch's 3 − ν/(1 − ν) = 2.667): \
             `static`. Bars (issue 50), on the {} m zones: the quasi-static concentration within \
             {} %, the peak within {} %: {}.\n",
            WALL_ZONES[1],
            100.0 * QUASI_STATIC_BAR,
            100.0 * PEAK_BAR,
            verdict(&missed)
        );
        table(&mut md, &rows);
        let _ = writeln!(
            md,
            "\n![hoop stress concentration against αa](img/pao_mow.png)\n"
        );
        Ok(Section {
            markdown: md,
            rows,
            missed,
            ..Default::default()
        })
    }
}
