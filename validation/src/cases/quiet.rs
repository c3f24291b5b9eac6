//! Quiet boundaries (issue 50): plane P and S waves through a column's quiet base against the
//! one-dimensional closed form, and a settled column made quiet staying at rest.

use std::fmt::Write as _;

use adit::scene::WaveKind;

use crate::case::{Case, Context, Section, print_row, table};
use crate::quiet::{Column, FREQUENCY, PEAK, at_rest};

/// Bars (issue 50): the top at twice the incident velocity within 2 %, the echo from the base
/// under 2 % of it; at rest, speeds under 1e-6 of the wave's.
const BAR: f64 = 0.02;
const REST_BAR: f64 = 1e-6;

pub struct Quiet;

impl Case for Quiet {
    fn name(&self) -> &'static str {
        "quiet"
    }

    fn run(&self, _cx: &Context) -> anyhow::Result<Section> {
        let (mut rows, mut missed) = (Vec::new(), Vec::new());
        for wave in [WaveKind::P, WaveKind::S] {
            for zone in [1.0, 0.5] {
                let column = Column {
                    wave,
                    width: 2.0,
                    height: 120.0,
                    zone,
                };
                let m = column.run()?;
                print_row(&m.report);
                if m.surface > BAR || m.echo > BAR {
                    missed.push(format!("{}: {:?}", m.report.case, m.report.errors));
                }
                rows.push(m.report);
            }
        }
        let (rest, speed) = at_rest(0.5, 0.2)?;
        print_row(&rest);
        if speed > REST_BAR * PEAK {
            missed.push(format!("{}: {speed:.2e} m/s", rest.case));
        }
        rows.push(rest);
        let mut md = String::new();
        let _ = writeln!(
            md,
            "\n## Quiet boundaries: waves in and out of a column (issue 50)\n"
        );
        let _ = writeln!(
            md,
            "A column 2 m wide and 120 m tall of elastic rock (E 10 GPa, ν 0.25, ρ 2 500 kg/m³: \
             Cp 2 190.9 m/s, Cs 1 264.9 m/s), its sides on rollers (held across the wave's \
             particle velocity), its top free, its base quiet (`boundary[i].quiet`: dashpots ρCp \
             and ρCs per unit length, Lysmer & Kuhlemeyer 1969, integrated centred in time, \
             `docs/theory.md`), through which a plane wave enters (`incident`: a Ricker wavelet of \
             peak particle velocity {PEAK} m/s at {FREQUENCY} Hz, brought in as the stress \
             2ρC v): undamped, one dynamic stage (`solve.duration`) until the base's echo would \
             be back at the top. By the one-dimensional closed form the top moves at 2v₀ when the \
             wavelet arrives, H/C after the base, and nothing comes back: `surface` is |peak \
             velocity at the top / 2v₀ − 1|, `echo` the largest speed at the top around 3H/C \
             (where a wave the base reflected would arrive, doubled) over 2v₀. The last row: a \
             50 m column settled under gravity on a fixed base (implicitly, ratio 1e-8), then a \
             dynamic stage of 0.2 s whose base is quiet with no wave (the fixities' reactions \
             held as constant forces): `speed` is the largest speed at the top and base over \
             the stage, over the wave's v₀. Bars (issue 50): `surface` and `echo` within \
             {} %, `speed` below {REST_BAR:e}: {}.\n",
            100.0 * BAR,
            if missed.is_empty() {
                "met".to_string()
            } else {
                format!("missed by {}", missed.join("; "))
            }
        );
        table(&mut md, &rows);
        Ok(Section {
            markdown: md,
            rows,
            missed,
            ..Default::default()
        })
    }
}
