//! A picture of a solved tunnel model (plotters, PNG): left, the most compressive principal
//! stress σ1 of each zone; right, the zones' yield state, the joints (those that slip or open
//! dotted blue), the bolts and the liner — what a user looks at in ParaView, for the docs.

use std::path::Path;

use adit::law::{SHEAR_NOW, SHEAR_PAST, TENSION_NOW, TENSION_PAST};
use adit::model::Model;
use adit::output::vtu::principal;
use plotters::prelude::*;

/// Colour of t in [0, 1] on a blue–white–red scale (compressive blue).
fn diverging(t: f64) -> RGBColor {
    let t = t.clamp(0.0, 1.0);
    let lerp = |a: u8, b: u8, s: f64| (a as f64 + (b as f64 - a as f64) * s).round() as u8;
    let (lo, mid, hi) = ((33, 102, 172), (247, 247, 247), (178, 24, 43));
    if t < 0.5 {
        let s = 2.0 * t;
        RGBColor(
            lerp(lo.0, mid.0, s),
            lerp(lo.1, mid.1, s),
            lerp(lo.2, mid.2, s),
        )
    } else {
        let s = 2.0 * t - 1.0;
        RGBColor(
            lerp(mid.0, hi.0, s),
            lerp(mid.1, hi.1, s),
            lerp(mid.2, hi.2, s),
        )
    }
}

/// Yield-state colour: shear now, tension now, yielded in the past, elastic.
fn state_colour(state: u8) -> RGBColor {
    if state & SHEAR_NOW != 0 {
        RGBColor(214, 39, 40)
    } else if state & TENSION_NOW != 0 {
        RGBColor(148, 103, 189)
    } else if state & (SHEAR_PAST | TENSION_PAST) != 0 {
        RGBColor(255, 187, 120)
    } else {
        RGBColor(225, 225, 225)
    }
}

/// Render `model` within the square of half-width `half` (m) about `centre` into `path`.
pub fn tunnel_png(path: &Path, model: &Model, centre: [f64; 2], half: f64) -> anyhow::Result<()> {
    let root = BitMapBackend::new(path, (1200, 640)).into_drawing_area();
    root.fill(&WHITE)?;
    let (left, right) = root.split_horizontally(600);
    let (x0, x1) = (centre[0] - half, centre[0] + half);
    let (y0, y1) = (centre[1] - half, centre[1] + half);
    let pos = &model.nodes.pos;
    let z = &model.zones;
    let inside = |i: usize| {
        let c = z.centroid(i, pos);
        (x0..x1).contains(&c[0]) && (y0..y1).contains(&c[1])
    };
    let excavated = |i: usize| model.blocks.is_removed(z.block[i] as usize);
    let sigma1: Vec<f64> = (0..z.len()).map(|i| principal(&z.stress[i]).0).collect();
    let shown: Vec<usize> = (0..z.len())
        .filter(|&i| inside(i) && !excavated(i))
        .collect();
    let lo = shown
        .iter()
        .map(|&i| sigma1[i])
        .fold(f64::INFINITY, f64::min);
    let hi = shown
        .iter()
        .map(|&i| sigma1[i])
        .fold(f64::NEG_INFINITY, f64::max);
    let panels: [(_, String, &dyn Fn(usize) -> RGBColor); 2] = [
        (
            left,
            format!(
                "sigma1 (most compressive), {:.1} to {:.1} MPa",
                lo / 1e6,
                hi / 1e6
            ),
            &|i| diverging((sigma1[i] - lo) / (hi - lo).max(1.0) * 0.5),
        ),
        (
            right,
            "yield: shear now (red), tension now (purple), past (orange); joints slipping or open (blue)"
                .to_string(),
            &|i| state_colour(z.state[i]),
        ),
    ];
    for (k, (area, title, colour)) in panels.into_iter().enumerate() {
        let mut chart = ChartBuilder::on(&area)
            .caption(title, ("sans-serif", 16))
            .margin(10)
            .x_label_area_size(30)
            .y_label_area_size(40)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart.configure_mesh().disable_mesh().draw()?;
        chart.draw_series(shown.iter().map(|&i| {
            let pts: Vec<(f64, f64)> = z.nodes[i]
                .iter()
                .map(|&n| (pos[n as usize][0], pos[n as usize][1]))
                .collect();
            Polygon::new(pts, colour(i).filled())
        }))?;
        if k == 0 {
            continue;
        }
        // Block boundaries (the joints), then the joints that slip or are open at their contacts.
        let visible = |p: [f64; 2]| (x0..x1).contains(&p[0]) && (y0..y1).contains(&p[1]);
        chart.draw_series(model.blocks.edges.iter().filter_map(|e| {
            let [a, b] = e.map(|n| pos[n as usize]);
            (visible(a) && visible(b)).then(|| {
                PathElement::new(
                    [(a[0], a[1]), (b[0], b[1])],
                    RGBColor(90, 90, 90).stroke_width(1),
                )
            })
        }))?;
        let c = &model.contacts;
        chart.draw_series((0..c.len()).filter_map(|k| {
            let s = &c.state[k];
            let moving = s.flags & (adit::joint::SLIPPING | adit::joint::OPEN) != 0;
            let p = pos[c.node[k] as usize];
            (moving && visible(p)).then(|| Circle::new((p[0], p[1]), 3, BLUE.filled()))
        }))?;
        let cab = &model.supports.cables;
        chart.draw_series(cab.segment.iter().map(|s| {
            let [a, b] = s.map(|n| cab.pos[n as usize]);
            PathElement::new([(a[0], a[1]), (b[0], b[1])], BLACK.stroke_width(2))
        }))?;
        let lin = &model.supports.liners;
        chart.draw_series(lin.element.iter().map(|e| {
            let [a, b] = e.map(|n| lin.pos[n as usize]);
            PathElement::new(
                [(a[0], a[1]), (b[0], b[1])],
                RGBColor(0, 128, 0).stroke_width(4),
            )
        }))?;
    }
    root.present()?;
    Ok(())
}
