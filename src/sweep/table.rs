//! The sweep's table (`sweep.csv`) and the plot of its spread (`sweep.png`).

use std::collections::BTreeSet;
use std::path::Path;

use serde_json::Value;

use super::Row;
use crate::output::atomic::write_atomic;
use crate::output::csv_field;

/// Write `sweep.csv` into `out`: one row per run, in the runs' order, with its parameters, status,
/// error, seconds, cycles, the closure of each excavation (m), yielded zones, the largest bolt
/// force and liner thrust (N/m); empty where a run has no such figure. Then `sweep.png`, each
/// figure's values over the runs that converged; a plot that cannot be drawn comes back as a
/// warning.
pub fn write_table(out: &Path, rows: &[Row]) -> anyhow::Result<Vec<String>> {
    let params: BTreeSet<&String> = rows.iter().flat_map(|r| r.params.keys()).collect();
    let excavations: BTreeSet<&String> = rows.iter().flat_map(|r| r.closure_m.keys()).collect();
    std::fs::create_dir_all(out).map_err(|e| anyhow::anyhow!("{}: {e}", out.display()))?;
    write_atomic(&out.join("sweep.csv"), |w| {
        let mut head: Vec<String> = vec!["id".into()];
        head.extend(params.iter().map(|p| p.to_string()));
        head.extend(["status", "error", "wall_seconds", "cycles"].map(String::from));
        head.extend(excavations.iter().map(|e| format!("closure_{e}_m")));
        head.extend(
            [
                "yielded_zones",
                "max_bolt_force_n_per_m",
                "max_liner_thrust_n_per_m",
            ]
            .map(String::from),
        );
        writeln!(w, "{}", csv_line(&head))?;
        for r in rows {
            let mut line = vec![r.id.clone()];
            line.extend(
                params
                    .iter()
                    .map(|p| r.params.get(*p).map_or(String::new(), cell)),
            );
            line.push(r.status.clone());
            line.push(r.error.clone().unwrap_or_default());
            line.push(format!("{:.3}", r.wall_seconds));
            line.push(r.cycles.to_string());
            line.extend(excavations.iter().map(|e| {
                r.closure_m
                    .get(*e)
                    .map_or(String::new(), |c| format!("{c:e}"))
            }));
            line.push(r.yielded_zones.to_string());
            for f in [r.max_bolt_force_n_per_m, r.max_liner_thrust_n_per_m] {
                line.push(f.map_or(String::new(), |v| format!("{v:e}")));
            }
            writeln!(w, "{}", csv_line(&line))?;
        }
        Ok(())
    })?;
    let ok: Vec<&Row> = rows
        .iter()
        .filter(|r| matches!(r.status.as_str(), "converged" | "completed" | "cycle_limit"))
        .collect();
    let mut figures: Vec<(String, Vec<f64>)> = excavations
        .iter()
        .map(|e| {
            let v = ok
                .iter()
                .filter_map(|r| r.closure_m.get(*e))
                .map(|c| 1e3 * c);
            (format!("closure of {e} (mm)"), v.collect())
        })
        .collect();
    figures.push((
        "yielded zones".into(),
        ok.iter().map(|r| r.yielded_zones as f64).collect(),
    ));
    figures.push((
        "largest bolt force (kN/m)".into(),
        ok.iter()
            .filter_map(|r| r.max_bolt_force_n_per_m)
            .map(|f| 1e-3 * f)
            .collect(),
    ));
    figures.push((
        "largest liner thrust (kN/m)".into(),
        ok.iter()
            .filter_map(|r| r.max_liner_thrust_n_per_m)
            .map(|f| 1e-3 * f)
            .collect(),
    ));
    figures.retain(|(_, v)| !v.is_empty());
    Ok(crate::output::plots::write_spread(
        out,
        "sweep.png",
        &figures,
    ))
}

/// The table's files in `out`: what a sweep removes when it starts, so that a table that exists is
/// of a sweep that finished.
pub const TABLE_FILES: [&str; 3] = ["sweep.csv", "sweep.png", "sweep.parquet"];

/// Remove the table an earlier sweep left in `out`.
pub fn remove_table(out: &Path) -> std::io::Result<()> {
    for file in TABLE_FILES {
        match std::fs::remove_file(out.join(file)) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => return Err(e),
            _ => {}
        }
    }
    Ok(())
}

/// A parameter's value as a CSV cell: numbers and strings as they are, anything else as JSON.
fn cell(v: &Value) -> String {
    match v {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// One CSV line.
fn csv_line(fields: &[String]) -> String {
    let cells: Vec<_> = fields.iter().map(|f| csv_field(f)).collect();
    cells.join(",")
}
