//! PNG plots beside the results, for a look without ParaView: the unbalanced-force ratio's history
//! (`history.png`), the ground reaction curve of each excavation (`ground_reaction.png`, staged
//! scenes: support pressure against mean wall closure at each stage's end, from no closure under
//! the whole in-situ pressure, with the liners' reaction curve), the axial force along each installed bolt (`bolts.png`, scenes with
//! bolts) and the liners' forces against their capacity (`liner_capacity.png`, `capacity_plot.rs`).
//!
//! Each is drawn into a buffer and written atomically. A plot that cannot be drawn (no font on
//! the machine: fontconfig is loaded at run time) is a warning of the run, never its failure.

use std::path::Path;

use image::ImageEncoder as _;
use plotters::prelude::*;

use super::StageSummary;
use super::atomic::write_atomic;
use crate::model::Model;
use crate::solve::HistoryRow;

/// Plot size, pixels.
const SIZE: (u32, u32) = (800, 500);

/// Colours of successive curves.
pub(super) const PALETTE: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
];

/// The colour of line `i` of `n`: the palette's while it has enough, else `n` hues around the
/// colour wheel, so that no two lines share one.
fn color_of(i: usize, n: usize) -> RGBAColor {
    if n <= PALETTE.len() {
        PALETTE[i].to_rgba()
    } else {
        HSLColor(i as f64 / n as f64, 0.75, 0.42).to_rgba()
    }
}

/// One line of a plot: its label and points.
struct Line {
    label: String,
    points: Vec<(f64, f64)>,
}

/// Write every plot the run has data for into `dir`; what could not be drawn comes back as
/// warnings.
pub fn write_plots(
    dir: &Path,
    history: &[HistoryRow],
    stages: &[StageSummary],
    excavations: &[String],
    model: &Model,
) -> Vec<String> {
    let mut warnings = Vec::new();
    let ratio = history
        .iter()
        .filter(|r| r.ratio.is_finite() && r.ratio > 0.0)
        .map(|r| (r.cycle as f64, r.ratio))
        .collect();
    let marks: Vec<f64> = if stages.len() > 1 {
        stage_ends(stages).into_iter().map(|c| c as f64).collect()
    } else {
        Vec::new()
    };
    let ratio = [Line {
        label: "ratio".into(),
        points: ratio,
    }];
    let axes = (
        "cycle (implicit: iteration); dashed: a stage's end",
        "ratio",
    );
    let file = ("history.png", "Unbalanced-force ratio", axes, true);
    plot_marked(&mut warnings, dir, file, &ratio, &marks);
    let mut plot = |file: &str, title: &str, axes: (&str, &str), log_y: bool, lines: Vec<Line>| {
        plot_marked(&mut warnings, dir, (file, title, axes, log_y), &lines, &[]);
    };
    // Each excavation's curve starts at no closure under the whole in-situ pressure.
    let curves = excavations
        .iter()
        .map(|name| Line {
            label: name.clone(),
            points: std::iter::once((0.0, 100.0))
                .chain(stages.iter().filter_map(|s| {
                    let c = s.closure.get(name)?;
                    Some((1e3 * c, 100.0 * s.support_fraction))
                }))
                .collect(),
        })
        .filter(|l| l.points.len() > 1)
        .chain(support_reaction_curves(stages, excavations))
        .collect();
    plot(
        "ground_reaction.png",
        "Ground reaction curve, and the liners' reaction",
        ("mean wall closure (mm)", "support pressure (% of in-situ)"),
        false,
        curves,
    );
    plot(
        "bolts.png",
        "Axial force along each bolt, and each group's capacity",
        (
            "distance from the head (m)",
            "axial force per bolt (kN, tension positive)",
        ),
        false,
        bolt_lines(model),
    );
    if !crate::interrupt::requested() {
        warnings.extend(super::capacity_plot::write(dir, &model.supports.liners));
    }
    warnings
}

/// Each excavation's support reaction curve: the pressure its liners put on the wall (% of the
/// in-situ mean stress, `WallMoves::support_pressure_ratio`) against its mean closure, from the
/// closure when they were installed (the stage before the first that carries pressure) on.
fn support_reaction_curves<'a>(
    stages: &'a [StageSummary],
    excavations: &'a [String],
) -> impl Iterator<Item = Line> + 'a {
    excavations.iter().filter_map(move |name| {
        let carried = |s: &StageSummary| {
            s.walls
                .get(name)
                .is_some_and(|w| w.support_pressure_pa > 0.0)
        };
        let first = stages.iter().position(carried)?;
        let installed_at = first
            .checked_sub(1)
            .and_then(|k| stages[k].closure.get(name));
        let points = (installed_at.map(|c| (1e3 * c, 0.0)).into_iter())
            .chain(stages[first..].iter().filter_map(|s| {
                let (c, w) = (s.closure.get(name)?, s.walls.get(name)?);
                Some((1e3 * c, 100.0 * w.support_pressure_ratio))
            }))
            .collect();
        Some(Line {
            label: format!("liners of {name}"),
            points,
        })
    })
}

/// The axial force per bolt (kN) against distance from the head (m, at segment middles) of each
/// installed bolt, named by its group and head, then each installed group's capacity (its yield
/// force, kN) over the longest bolt's length.
fn bolt_lines(model: &Model) -> Vec<Line> {
    let c = &model.supports.cables;
    let mut lines: Vec<Line> = Vec::new();
    let mut capacities: Vec<(usize, f64)> = Vec::new();
    let mut longest = 0.0f64;
    for (group, segments) in c.installed_bolts() {
        let head = c.head(segments.start);
        let mut along = 0.0;
        let mut points = Vec::new();
        for k in segments {
            let length = c.segment_length[k];
            points.push((along + 0.5 * length, 1e-3 * c.bolt_force(k)));
            along += length;
        }
        longest = longest.max(along);
        if !capacities.iter().any(|&(g, _)| g == group) {
            capacities.push((group, 1e-3 * c.capacity(group)));
        }
        lines.push(Line {
            label: format!("{} at ({:.2}, {:.2}) m", c.names[group], head[0], head[1]),
            points,
        });
    }
    lines.extend(capacities.into_iter().map(|(g, capacity)| Line {
        label: format!("capacity of {}: {capacity:.0} kN", c.names[g]),
        points: vec![(0.0, capacity), (longest, capacity)],
    }));
    lines
}

/// The largest size of a value a plot draws: the plotting library's axes loop for ever on an
/// infinite range and lose their ticks far before it.
pub(super) const PLOT_LIMIT: f64 = 1e100;

/// `lines` without their non-finite points (and, on a logarithmic y axis, those not above zero);
/// an error when a value is beyond [`PLOT_LIMIT`] in size or none is left.
fn drawable(lines: &[Line], log_y: bool) -> Result<Vec<Line>, String> {
    let lines: Vec<Line> = lines
        .iter()
        .map(|l| Line {
            label: l.label.clone(),
            points: (l.points.iter())
                .filter(|p| p.0.is_finite() && p.1.is_finite() && (p.1 > 0.0 || !log_y))
                .copied()
                .collect(),
        })
        .collect();
    let mut all = lines.iter().flat_map(|l| &l.points);
    if let Some(p) = all.clone().find(|p| p.0.abs().max(p.1.abs()) > PLOT_LIMIT) {
        return Err(format!(
            "a value ({:e}, {:e}) is beyond the {PLOT_LIMIT:e} a plot draws",
            p.0, p.1
        ));
    }
    if all.next().is_none() {
        return Err("no finite value to draw".into());
    }
    Ok(lines)
}

/// The range (lo, hi) a plot's axis takes for values from `lo` to `hi`: 4 % wider on each side,
/// and never narrower than a millionth of the values' size (a constant curve), so that its ticks
/// are distinct numbers.
fn padded(lo: f64, hi: f64) -> (f64, f64) {
    let pad = (0.04 * (hi - lo))
        .max(1e-6 * lo.abs().max(hi.abs()))
        .max(1e-30);
    (lo - pad, hi + pad)
}

/// Draw `lines` (with a dashed vertical line at each of `marks`) into `dir` as the file of
/// `(file, title, axes, log_y)`, unless they hold no point; what could not be drawn goes to
/// `warnings`.
fn plot_marked(
    warnings: &mut Vec<String>,
    dir: &Path,
    (file, title, axes, log_y): (&str, &str, (&str, &str), bool),
    lines: &[Line],
    marks: &[f64],
) {
    if lines.iter().all(|l| l.points.is_empty()) {
        return;
    }
    // Plots are the last of a run's outputs: an interrupt skips those not yet drawn.
    if crate::interrupt::requested() {
        warnings.push(format!("{file} not written: interrupted"));
        return;
    }
    warnings.extend(write_png(dir, file, || {
        draw_finite(title, axes, log_y, &drawable(lines, log_y)?, marks)
    }));
}

/// The cycle at which each stage ends, counted from the start of the run.
pub fn stage_ends(stages: &[StageSummary]) -> Vec<u64> {
    (stages.iter())
        .scan(0, |done, s| {
            *done += s.cycles;
            Some(*done)
        })
        .collect()
}

/// Draw `lines` with a dashed vertical line at each of `marks` (x).
fn draw_finite(
    title: &str,
    (x_label, y_label): (&str, &str),
    log_y: bool,
    lines: &[Line],
    marks: &[f64],
) -> Result<Vec<u8>, String> {
    let mut rgb = vec![255u8; (SIZE.0 * SIZE.1 * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, SIZE).into_drawing_area();
        let all = || lines.iter().flat_map(|l| l.points.iter().copied());
        let span = |f: fn((f64, f64)) -> f64| {
            let (lo, hi) = all().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(f(p)), b.max(f(p)))
            });
            padded(lo, hi)
        };
        let (x0, x1) = span(|p| p.0);
        let err = |e: &dyn std::fmt::Display| e.to_string();
        let mut chart = ChartBuilder::on(&root);
        chart
            .caption(title, ("sans-serif", 20))
            .margin(14)
            .x_label_area_size(44)
            .y_label_area_size(80);
        let legend = lines.len() > 1 && lines.len() <= 12;
        if log_y {
            let (lo, hi) = all().fold((f64::INFINITY, 0.0f64), |(a, b), p| {
                (a.min(p.1), b.max(p.1))
            });
            let mut chart = chart
                .build_cartesian_2d(x0..x1, (lo * 0.5..hi * 2.0).log_scale())
                .map_err(|e| err(&e))?;
            chart
                .configure_mesh()
                .x_desc(x_label)
                .y_desc(y_label)
                .y_label_formatter(&|v| format!("{v:.0e}"))
                .draw()
                .map_err(|e| err(&e))?;
            for &x in marks.iter().filter(|&&x| x > x0 && x < x1) {
                chart
                    .draw_series(DashedLineSeries::new(
                        [(x, lo * 0.5), (x, hi * 2.0)],
                        4,
                        4,
                        BLACK.mix(0.5).stroke_width(1),
                    ))
                    .map_err(|e| err(&e))?;
            }
            for (i, l) in lines.iter().enumerate() {
                let color = color_of(i, lines.len());
                chart
                    .draw_series(LineSeries::new(l.points.clone(), color.stroke_width(2)))
                    .map_err(|e| err(&e))?;
            }
        } else {
            let (y0, y1) = span(|p| p.1);
            let mut chart = chart
                .build_cartesian_2d(x0..x1, y0..y1)
                .map_err(|e| err(&e))?;
            chart
                .configure_mesh()
                .x_desc(x_label)
                .y_desc(y_label)
                .draw()
                .map_err(|e| err(&e))?;
            for (i, l) in lines.iter().enumerate() {
                let color = color_of(i, lines.len());
                chart
                    .draw_series(LineSeries::new(l.points.clone(), color.stroke_width(2)))
                    .map_err(|e| err(&e))?
                    .label(l.label.clone())
                    .legend(move |(x, y)| {
                        PathElement::new([(x, y), (x + 16, y)], color.stroke_width(2))
                    });
                chart
                    .draw_series(l.points.iter().map(|&p| Circle::new(p, 3, color.filled())))
                    .map_err(|e| err(&e))?;
            }
            if legend {
                chart
                    .configure_series_labels()
                    .position(SeriesLabelPosition::UpperRight)
                    .background_style(WHITE.mix(0.8))
                    .border_style(BLACK)
                    .draw()
                    .map_err(|e| err(&e))?;
            }
        }
        root.present().map_err(|e| err(&e))?;
    }
    png(&rgb, SIZE)
}

/// An RGB buffer of `size` pixels as PNG bytes.
pub(super) fn png(rgb: &[u8], size: (u32, u32)) -> Result<Vec<u8>, String> {
    let mut png = Vec::new();
    image::codecs::png::PngEncoder::new(&mut png)
        .write_image(rgb, size.0, size.1, image::ColorType::Rgb8)
        .map_err(|e| e.to_string())?;
    Ok(png)
}

/// Write the PNG `draw` makes as `file` in `dir`, atomically; a warning when it could not be
/// drawn or written (a panic of the plotting library included).
pub(super) fn write_png(
    dir: &Path,
    file: &str,
    draw: impl FnOnce() -> Result<Vec<u8>, String> + std::panic::UnwindSafe,
) -> Option<String> {
    let written = match std::panic::catch_unwind(draw) {
        Ok(Ok(png)) => {
            write_atomic(&dir.join(file), |w| w.write_all(&png)).map_err(|e| e.to_string())
        }
        Ok(Err(e)) => Err(e),
        Err(_) => Err("the plotting library panicked (no usable font?)".to_string()),
    };
    written.err().map(|e| format!("{file} not written: {e}"))
}

/// Write `file` into `dir`: one panel per figure, its values sorted against the fraction of
/// runs at or below them (the spread as an empirical distribution). A plot that cannot be drawn
/// comes back as a warning.
pub fn write_spread(dir: &Path, file: &str, figures: &[(String, Vec<f64>)]) -> Vec<String> {
    if figures.is_empty() {
        return Vec::new();
    }
    write_png(dir, file, || spread(figures))
        .into_iter()
        .collect()
}

fn spread(figures: &[(String, Vec<f64>)]) -> Result<Vec<u8>, String> {
    let columns = figures.len().min(3) as u32;
    let rows = (figures.len() as u32).div_ceil(columns);
    let size = (420 * columns, 320 * rows);
    let mut rgb = vec![255u8; (size.0 * size.1 * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, size).into_drawing_area();
        let panels = root.split_evenly((rows as usize, columns as usize));
        let err = |e: &dyn std::fmt::Display| e.to_string();
        for ((title, values), panel) in figures.iter().zip(&panels) {
            let mut v = values.clone();
            v.sort_by(f64::total_cmp);
            let n = v.len() as f64;
            let points: Vec<(f64, f64)> = v
                .iter()
                .enumerate()
                .map(|(i, &y)| ((i as f64 + 1.0) / n, y))
                .collect();
            let (lo, hi) = (v[0], v[v.len() - 1]);
            let pad = if hi > lo {
                0.08 * (hi - lo)
            } else {
                0.5 * lo.abs().max(1.0)
            };
            let mut chart = ChartBuilder::on(panel)
                .caption(format!("{title}, {} runs", v.len()), ("sans-serif", 15))
                .margin(10)
                .x_label_area_size(32)
                .y_label_area_size(60)
                .build_cartesian_2d(0.0..1.02, (lo - pad)..(hi + pad))
                .map_err(|e| err(&e))?;
            chart
                .configure_mesh()
                .x_desc("fraction of runs at or below")
                .draw()
                .map_err(|e| err(&e))?;
            let color = PALETTE[0];
            chart
                .draw_series(points.iter().map(|&p| Circle::new(p, 3, color.filled())))
                .map_err(|e| err(&e))?;
        }
        root.present().map_err(|e| err(&e))?;
    }
    png(&rgb, size)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A plot comes out as a PNG of the plot's size.
    #[test]
    fn the_ratio_plot_marks_the_stages_ends() {
        let lines = [Line {
            label: "ratio".into(),
            points: vec![(0.0, 1.0), (60.0, 1e-2), (100.0, 1e-5)],
        }];
        let axes = ("cycle", "ratio");
        let plain = draw_finite("r", axes, true, &lines, &[]).unwrap();
        let marked = draw_finite("r", axes, true, &lines, &[60.0]).unwrap();
        assert_ne!(plain, marked, "the stage's end is drawn");
    }

    /// Draw `lines` as a PNG image (their finite points: [`drawable`]).
    fn draw(
        title: &str,
        axes: (&str, &str),
        log_y: bool,
        lines: &[Line],
    ) -> Result<Vec<u8>, String> {
        draw_finite(title, axes, log_y, &drawable(lines, log_y)?, &[])
    }

    /// Issue 49: colours do not repeat among the bolts (the tunnel has 11, a pattern may have
    /// dozens).
    #[test]
    fn no_two_lines_share_a_colour() {
        for n in [1, 6, 7, 11, 40] {
            let colors: Vec<_> = (0..n).map(|i| color_of(i, n).rgb()).collect();
            for i in 0..n {
                assert!(!colors[..i].contains(&colors[i]), "{n} lines: {i} repeats");
            }
        }
    }

    #[test]
    fn a_plot_is_a_png_image() {
        let line = Line {
            label: "a".into(),
            points: vec![(0.0, 1.0), (1.0, 3.0), (2.0, 2.0)],
        };
        let png = draw("t", ("x", "y"), false, &[line]).unwrap();
        assert_eq!(&png[1..4], b"PNG");
        let image = image::load_from_memory(&png).unwrap();
        assert_eq!((image.width(), image.height()), SIZE);
    }

    /// A plot of extreme or non-finite values ends, drawn from its finite points or refused
    /// with a reason (an infinite range had looped in the plotting library for ever).
    #[test]
    fn extreme_values_are_drawn_or_refused_at_once() {
        let cases = [
            ([1e305, 2e305], false),
            ([f64::INFINITY, 1.0], true),
            ([1e20, 1e20], true),
            ([1e-300, 2e-300], true),
            ([f64::NAN, 1.0], true),
            ([-1e308, 1e308], false),
            ([f64::NAN, f64::INFINITY], false),
            ([-3.0, 2.0], true),
        ];
        for (ys, drawn) in cases {
            for log_y in [false, true] {
                let line = Line {
                    label: "a".into(),
                    points: vec![(0.0, ys[0]), (1.0, ys[1])],
                };
                let png = draw("t", ("x", "y"), log_y, &[line]);
                assert_eq!(png.is_ok(), drawn, "{ys:?}, log {log_y}: {png:?}");
            }
        }
    }
}
