//! `histories.png`: one panel per monitoring point (`histories`), its quantity against the
//! cycle, with the end of each stage marked by a dashed line.

use std::path::Path;

use plotters::prelude::*;

use super::histories::Samples;
use super::plots::{PALETTE, PLOT_LIMIT, png, write_png};

/// Write `histories.png` into `dir` for the points named `columns` (their `histories.csv`
/// columns) sampled in `samples`, stages ending at the cycles `stage_ends`; what could not be
/// drawn comes back as a warning.
pub fn write(dir: &Path, columns: &[String], samples: &Samples, stage_ends: &[u64]) -> Vec<String> {
    if columns.is_empty() || samples.is_empty() {
        return Vec::new();
    }
    write_png(dir, "histories.png", || draw(columns, samples, stage_ends))
        .into_iter()
        .collect()
}

fn draw(columns: &[String], samples: &Samples, stage_ends: &[u64]) -> Result<Vec<u8>, String> {
    let n = columns.len();
    let per_row = n.min(2);
    let rows = n.div_ceil(per_row);
    let size = (560 * per_row as u32, 340 * rows as u32);
    let mut rgb = vec![255u8; (size.0 * size.1 * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, size).into_drawing_area();
        let panels = root.split_evenly((rows, per_row));
        let err = |e: &dyn std::fmt::Display| e.to_string();
        let x1 = *samples.cycle.last().expect("samples") as f64;
        for (k, (column, panel)) in columns.iter().zip(&panels).enumerate() {
            let points: Vec<(f64, f64)> = (0..samples.len())
                .map(|i| (samples.cycle[i] as f64, samples.values[i][k]))
                .filter(|p| p.1.is_finite() && p.1.abs() <= PLOT_LIMIT)
                .collect();
            if points.is_empty() {
                return Err(format!("{column}: no finite value to draw"));
            }
            let (lo, hi) = points
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                    (a.min(p.1), b.max(p.1))
                });
            let pad = (0.06 * (hi - lo))
                .max(1e-6 * lo.abs().max(hi.abs()))
                .max(1e-30);
            let (y0, y1) = (lo - pad, hi + pad);
            let mut chart = ChartBuilder::on(panel)
                .caption(column, ("sans-serif", 15))
                .margin(10)
                .x_label_area_size(32)
                .y_label_area_size(70)
                .build_cartesian_2d(0.0..x1.max(1.0), y0..y1)
                .map_err(|e| err(&e))?;
            chart
                .configure_mesh()
                .x_desc("cycle (implicit: iteration)")
                .y_label_formatter(&|v| format!("{v:.3e}"))
                .draw()
                .map_err(|e| err(&e))?;
            for &end in stage_ends {
                let x = end as f64;
                chart
                    .draw_series(DashedLineSeries::new(
                        [(x, y0), (x, y1)],
                        4,
                        4,
                        BLACK.mix(0.5).stroke_width(1),
                    ))
                    .map_err(|e| err(&e))?;
            }
            chart
                .draw_series(LineSeries::new(points, PALETTE[0].stroke_width(2)))
                .map_err(|e| err(&e))?;
        }
        root.present().map_err(|e| err(&e))?;
    }
    png(&rgb, size)
}
