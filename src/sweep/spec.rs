//! The sweep spec (a JSON file, or the same as a dict in Python):
//!
//! ```json
//! { "name": "tunnel_sweep",
//!   "base": "tunnel.json",
//!   "grid": { "materials.rock.young": [10e9, 20e9], "realization": [1, 2, 3, 4] },
//!   "draws": { "count": 8, "seed": 1, "uniform": { "materials.rock.cohesion": [1e6, 3e6] } },
//!   "out": "out/tunnel_sweep" }
//! ```
//!
//! `base` is a scene file (relative to the spec's folder) or a scene object. Parameters are
//! addressed by dotted paths into the scene (`joint_sets.0.spacing`: an array's element by its
//! index). The runs are every combination of the `grid`'s values (keys in name order), each with
//! `draws.count` draws of the `uniform` ranges (by `seed`, the same on every machine); without a
//! grid, the draws alone; without either, the base once. `realization` is the scene's joint
//! realization (docs/scene-format.md).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::Deserialize;
use serde_json::Value;

/// Most runs one sweep may plan (a spec asking for more is refused before any run).
pub const MOST_RUNS: usize = 100_000;

/// A sweep, as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepSpec {
    pub name: String,
    /// The base scene: a path (relative to the spec's folder) or the scene itself.
    pub base: Value,
    /// Values of each parameter; the runs take every combination.
    #[serde(default)]
    pub grid: BTreeMap<String, Vec<Value>>,
    #[serde(default)]
    pub draws: Option<Draws>,
    /// Output folder (default `out/<name>`), relative to the working folder.
    #[serde(default)]
    pub out: Option<PathBuf>,
}

/// Random draws of parameters, uniform within their ranges.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Draws {
    /// Draws per grid point (≥ 1).
    pub count: usize,
    /// Seed of the draws (same seed, same values).
    #[serde(default = "one")]
    pub seed: u64,
    /// [low, high] of each parameter.
    pub uniform: BTreeMap<String, [f64; 2]>,
}

fn one() -> u64 {
    1
}

impl SweepSpec {
    /// The spec in `text` (from `source`, named in errors), checked: an error names the field.
    pub fn from_json(text: &str, source: &str) -> anyhow::Result<SweepSpec> {
        let spec: SweepSpec = serde_json::from_str(text)
            .map_err(|e| anyhow::anyhow!("{source}: not a sweep spec: {e}"))?;
        spec.check()?;
        Ok(spec)
    }

    /// The spec in the file at `path`.
    pub fn load(path: &Path) -> anyhow::Result<SweepSpec> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
        SweepSpec::from_json(&text, &path.display().to_string())
    }

    fn check(&self) -> anyhow::Result<()> {
        anyhow::ensure!(
            !self.name.is_empty()
                && self
                    .name
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c)),
            "name: {:?} must be letters, digits, '-', '_' or '.' (it names the output folder)",
            self.name
        );
        anyhow::ensure!(
            self.base.is_string() || self.base.is_object(),
            "base: a scene file's path or a scene object"
        );
        let mut runs: usize = 1;
        for (key, values) in &self.grid {
            anyhow::ensure!(!values.is_empty(), "grid.{key}: no values");
            runs = runs.saturating_mul(values.len());
        }
        if let Some(d) = &self.draws {
            anyhow::ensure!(d.count >= 1, "draws.count: at least 1");
            anyhow::ensure!(!d.uniform.is_empty(), "draws.uniform: no parameter to draw");
            for (key, [lo, hi]) in &d.uniform {
                anyhow::ensure!(
                    lo.is_finite() && hi.is_finite() && lo <= hi,
                    "draws.uniform.{key}: [{lo}, {hi}] is not a range (low ≤ high, finite)"
                );
                anyhow::ensure!(
                    !self.grid.contains_key(key),
                    "draws.uniform.{key}: also in grid"
                );
            }
            runs = runs.saturating_mul(d.count);
        }
        anyhow::ensure!(
            runs <= MOST_RUNS,
            "grid and draws: {runs} runs, more than {MOST_RUNS}"
        );
        Ok(())
    }

    /// The base scene as JSON, its file read relative to `dir` (the spec's folder).
    pub fn base_scene(&self, dir: &Path) -> anyhow::Result<Value> {
        match &self.base {
            Value::String(path) => {
                let path = dir.join(path);
                let text = std::fs::read_to_string(&path)
                    .map_err(|e| anyhow::anyhow!("base: {}: {e}", path.display()))?;
                let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
                serde_json::from_str(text)
                    .map_err(|e| anyhow::anyhow!("base: {}: {e}", path.display()))
            }
            scene => Ok(scene.clone()),
        }
    }

    /// The output folder: `out`, else `out/<name>`.
    pub fn out_dir(&self) -> PathBuf {
        self.out
            .clone()
            .unwrap_or_else(|| Path::new("out").join(&self.name))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bad_spec_is_refused_naming_its_field() {
        let cases = [
            (r#"{"name": "a b", "base": {}}"#, "name"),
            (r#"{"name": "s", "base": 3}"#, "base"),
            (r#"{"name": "s", "base": {}, "grid": {"x": []}}"#, "grid.x"),
            (
                r#"{"name": "s", "base": {}, "draws": {"count": 0, "uniform": {"x": [0, 1]}}}"#,
                "draws.count",
            ),
            (
                r#"{"name": "s", "base": {}, "draws": {"count": 2, "uniform": {"x": [2, 1]}}}"#,
                "draws.uniform.x",
            ),
            (r#"{"name": "s", "base": {}, "grids": {}}"#, "grids"),
            (
                r#"{"name": "s", "base": {}, "grid": {"a": [1,2,3,4,5,6,7,8,9,10], "b": [1,2,3,4,5,6,7,8,9,10], "c": [1,2,3,4,5,6,7,8,9,10], "d": [1,2,3,4,5,6,7,8,9,10], "e": [1,2,3,4,5,6,7,8,9,10], "f": [1, 2]}}"#,
                "more than",
            ),
        ];
        for (text, field) in cases {
            let e = SweepSpec::from_json(text, "spec").unwrap_err().to_string();
            assert!(e.contains(field), "{text}: {e}");
        }
    }
}
