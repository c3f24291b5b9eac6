//! `liner_capacity.png`: each installed liner with strengths as RS2's support capacity plots
//! draw it: its elements' thrust against their moment, and against their shear (both ends of
//! every element, per set), inside the section's envelopes of factor of safety 1, 1.5 and 2
//! (`support::liner_capacity`).

use std::path::Path;

use plotters::prelude::*;

use super::plots::{PALETTE, PLOT_LIMIT, png, write_png};
use crate::support::Liners;
use crate::support::liner_capacity::Section;

/// The envelopes drawn: factors of safety.
const FACTORS: [f64; 3] = [1.0, 1.5, 2.0];

/// One panel's curves and points: x in kN·m or kN, y in MN.
struct Panel {
    x_label: &'static str,
    envelopes: Vec<Vec<(f64, f64)>>,
    points: Vec<(f64, f64)>,
}

/// One liner's two panels and its name.
struct Figure {
    liner: String,
    panels: [Panel; 2],
}

/// Write `liner_capacity.png` into `dir` when an installed liner has strengths; what could not be
/// drawn comes back as a warning.
pub fn write(dir: &Path, liners: &Liners) -> Vec<String> {
    let figures = figures(liners);
    if figures.is_empty() {
        return Vec::new();
    }
    write_png(dir, "liner_capacity.png", || draw(&figures))
        .into_iter()
        .collect()
}

/// The figures of every installed liner with a section.
fn figures(liners: &Liners) -> Vec<Figure> {
    (0..liners.names.len())
        .filter(|&g| liners.active[g])
        .filter_map(|g| {
            let section: Section = liners.props[g].section?;
            let elements =
                (0..liners.element.len()).filter(|&e| liners.element_group[e] as usize == g);
            let forces: Vec<_> = elements.flat_map(|e| liners.section_forces(e)).collect();
            let moment = Panel {
                x_label: "bending moment per set (kN·m)",
                envelopes: (FACTORS.iter())
                    .map(|&f| scaled(&section.moment_envelope(f)))
                    .collect(),
                points: scaled(
                    &forces
                        .iter()
                        .map(|f| (f.moment, f.thrust))
                        .collect::<Vec<_>>(),
                ),
            };
            let shear = Panel {
                x_label: "shear force per set (kN)",
                envelopes: (FACTORS.iter())
                    .map(|&f| scaled(&section.shear_envelope(f, 60)))
                    .collect(),
                points: scaled(
                    &forces
                        .iter()
                        .map(|f| (f.shear, f.thrust))
                        .collect::<Vec<_>>(),
                ),
            };
            Some(Figure {
                liner: liners.names[g].clone(),
                panels: [moment, shear],
            })
        })
        .collect()
}

/// (N·m or N, N) as (kN·m or kN, MN).
fn scaled(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    points.iter().map(|&(x, y)| (1e-3 * x, 1e-6 * y)).collect()
}

fn draw(figures: &[Figure]) -> Result<Vec<u8>, String> {
    let all = || {
        (figures.iter().flat_map(|f| &f.panels))
            .flat_map(|p| p.points.iter().chain(p.envelopes.iter().flatten()))
    };
    if let Some(p) = all()
        .find(|p| !p.0.is_finite() || !p.1.is_finite() || p.0.abs().max(p.1.abs()) > PLOT_LIMIT)
    {
        return Err(format!("a force ({:e}, {:e}) cannot be drawn", p.0, p.1));
    }
    let size = (1100, 460 * figures.len() as u32);
    let mut rgb = vec![255u8; (size.0 * size.1 * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, size).into_drawing_area();
        let cells = root.split_evenly((figures.len(), 2));
        let err = |e: &dyn std::fmt::Display| e.to_string();
        let grays = [BLACK, RGBColor(214, 39, 40), RGBColor(44, 160, 44)];
        for (k, (figure, panel)) in figures
            .iter()
            .flat_map(|f| f.panels.iter().map(move |p| (f, p)))
            .enumerate()
        {
            let area = &cells[k];
            let bounds = |f: fn(&(f64, f64)) -> f64| {
                let values = panel.points.iter().chain(panel.envelopes.iter().flatten());
                let (lo, hi) = values
                    .map(f)
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                        (a.min(v), b.max(v))
                    });
                let pad = 0.06 * (hi - lo).max(1e-12);
                (lo - pad)..(hi + pad)
            };
            let mut chart = ChartBuilder::on(area)
                .caption(
                    format!(
                        "Liner '{}': thrust against {}",
                        figure.liner,
                        if k % 2 == 0 { "moment" } else { "shear" }
                    ),
                    ("sans-serif", 17),
                )
                .margin(12)
                .x_label_area_size(40)
                .y_label_area_size(60)
                .build_cartesian_2d(bounds(|p| p.0), bounds(|p| p.1))
                .map_err(|e| err(&e))?;
            chart
                .configure_mesh()
                .x_desc(panel.x_label)
                .y_desc("thrust per set (MN, compression positive)")
                .draw()
                .map_err(|e| err(&e))?;
            for ((envelope, &fs), color) in panel.envelopes.iter().zip(&FACTORS).zip(grays) {
                chart
                    .draw_series(LineSeries::new(envelope.clone(), color.stroke_width(2)))
                    .map_err(|e| err(&e))?
                    .label(format!("factor of safety {fs}"))
                    .legend(move |(x, y)| {
                        PathElement::new([(x, y), (x + 16, y)], color.stroke_width(2))
                    });
            }
            let color = PALETTE[0];
            chart
                .draw_series(
                    panel
                        .points
                        .iter()
                        .map(|&p| Circle::new(p, 3, color.filled())),
                )
                .map_err(|e| err(&e))?
                .label("elements (both ends)")
                .legend(move |(x, y)| Circle::new((x + 8, y), 3, color.filled()));
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .draw()
                .map_err(|e| err(&e))?;
        }
        root.present().map_err(|e| err(&e))?;
    }
    png(&rgb, size)
}
