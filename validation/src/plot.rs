//! Plots of the report (plotters, PNG): error against run time and against zone size, and
//! computed against closed-form curves.

use std::path::Path;

use plotters::prelude::*;

/// One convergence series: label, and (zone size m, wall s, error) per level.
pub struct Series {
    pub label: String,
    pub points: Vec<(f64, f64, f64)>,
    pub color: RGBColor,
    pub dashed: bool,
}

fn log_range(values: impl Iterator<Item = f64> + Clone) -> std::ops::Range<f64> {
    let lo = values.clone().fold(f64::INFINITY, f64::min);
    let hi = values.fold(0.0, f64::max);
    (lo / 1.5)..(hi * 1.5)
}

/// Two panels: error against wall seconds (speed versus error) and error against zone size.
pub fn speed_and_convergence(path: &Path, series: &[Series]) -> anyhow::Result<()> {
    let root = BitMapBackend::new(path, (1100, 460)).into_drawing_area();
    root.fill(&WHITE)?;
    let (left, right) = root.split_horizontally(550);
    let errors = log_range(
        series
            .iter()
            .flat_map(|s| s.points.iter().map(|p| p.2))
            .collect::<Vec<_>>()
            .into_iter(),
    );
    let panels = [
        (
            left,
            "error vs run time",
            "wall seconds",
            1usize,
            SeriesLabelPosition::LowerLeft,
        ),
        (
            right,
            "error vs zone size",
            "zone size h near the hole (m)",
            0usize,
            SeriesLabelPosition::LowerRight,
        ),
    ];
    for (area, title, xlabel, axis, legend) in panels {
        let xs: Vec<f64> = series
            .iter()
            .flat_map(|s| s.points.iter().map(|p| if axis == 1 { p.1 } else { p.0 }))
            .collect();
        let mut chart = ChartBuilder::on(&area)
            .caption(title, ("sans-serif", 20))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(
                log_range(xs.into_iter()).log_scale(),
                errors.clone().log_scale(),
            )?;
        chart
            .configure_mesh()
            .x_desc(xlabel)
            .y_desc("relative error")
            .x_label_formatter(&|v| format!("{v:.2}"))
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .draw()?;
        for s in series {
            let pts: Vec<(f64, f64)> = s
                .points
                .iter()
                .map(|p| (if axis == 1 { p.1 } else { p.0 }, p.2))
                .collect();
            let style = ShapeStyle::from(&s.color).stroke_width(2);
            if s.dashed {
                chart.draw_series(DashedLineSeries::new(pts.clone(), 6, 4, style))?;
            } else {
                chart.draw_series(LineSeries::new(pts.clone(), style))?;
            }
            let color = s.color;
            chart
                .draw_series(pts.iter().map(|&p| Circle::new(p, 4, color.filled())))?
                .label(s.label.clone())
                .legend(move |(x, y)| Circle::new((x + 8, y), 4, color.filled()));
        }
        chart
            .configure_series_labels()
            .position(legend)
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()?;
    }
    root.present()?;
    Ok(())
}

/// One curve of a linear plot: closed forms as lines, computed values as dots.
pub struct Curve {
    pub label: String,
    pub points: Vec<(f64, f64)>,
    pub color: RGBColor,
    pub dots: bool,
}

/// A linear x–y plot of `curves` (PNG).
pub fn curves(
    path: &Path,
    title: &str,
    (xlabel, ylabel): (&str, &str),
    curves: &[Curve],
) -> anyhow::Result<()> {
    let root = BitMapBackend::new(path, (640, 420)).into_drawing_area();
    root.fill(&WHITE)?;
    let all = || curves.iter().flat_map(|c| c.points.iter().copied());
    let (x0, x1) = all().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
        (a.min(p.0), b.max(p.0))
    });
    let (y0, y1) = all().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
        (a.min(p.1), b.max(p.1))
    });
    let pad = 0.05 * (y1 - y0).max(1e-30);
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, (y0 - pad)..(y1 + pad))?;
    chart
        .configure_mesh()
        .x_desc(xlabel)
        .y_desc(ylabel)
        .x_label_formatter(&|v| {
            // Large or small ranges in powers of ten, others as they are.
            if x1.abs().max(x0.abs()) >= 1e4 || x1.abs().max(x0.abs()) < 1e-2 {
                format!("{v:.1e}")
            } else {
                format!("{v}")
            }
        })
        .y_label_formatter(&|v| format!("{v:.3e}"))
        .draw()?;
    for c in curves {
        let color = c.color;
        if c.dots {
            chart
                .draw_series(c.points.iter().map(|&p| Circle::new(p, 3, color.filled())))?
                .label(c.label.clone())
                .legend(move |(x, y)| Circle::new((x + 8, y), 3, color.filled()));
        } else {
            chart
                .draw_series(LineSeries::new(c.points.clone(), color.stroke_width(2)))?
                .label(c.label.clone())
                .legend(move |(x, y)| {
                    PathElement::new([(x, y), (x + 16, y)], color.stroke_width(2))
                });
        }
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}

/// A histogram of `values` in `bins` equal bins over their range (PNG).
pub fn histogram(
    path: &Path,
    title: &str,
    xlabel: &str,
    values: &[f64],
    bins: usize,
) -> anyhow::Result<()> {
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let width = ((hi - lo) / bins as f64).max(1e-12 * hi.abs().max(1.0));
    let mut counts = vec![0u32; bins];
    for &v in values {
        counts[(((v - lo) / width) as usize).min(bins - 1)] += 1;
    }
    let top = counts.iter().copied().max().unwrap_or(1);
    let root = BitMapBackend::new(path, (640, 420)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(50)
        .build_cartesian_2d(lo..(lo + width * bins as f64), 0u32..(top + 1))?;
    chart
        .configure_mesh()
        .x_desc(xlabel)
        .y_desc("realizations")
        .draw()?;
    chart.draw_series(counts.iter().enumerate().map(|(i, &c)| {
        let x0 = lo + i as f64 * width;
        Rectangle::new([(x0, 0), (x0 + width, c)], RGBColor(31, 119, 180).filled())
    }))?;
    root.present()?;
    Ok(())
}
