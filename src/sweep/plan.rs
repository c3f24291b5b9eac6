//! A sweep's runs and the scene of each.

use std::collections::BTreeMap;

use adit_meshing::joints::SplitMix;
use serde_json::Value;

use super::SweepSpec;

/// One run of a sweep: its id (`run_NNNN`, also its folder) and the values of its parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct RunInput {
    pub id: String,
    pub params: BTreeMap<String, Value>,
}

/// The runs of `spec`, in order: every combination of the grid's values (the last key varying
/// fastest), each with `draws.count` draws. Draw d takes the same values at every grid point
/// (its stream is SplitMix seeded by `seed` + d), so grid points compare on common draws.
pub fn plan(spec: &SweepSpec) -> Vec<RunInput> {
    let mut points: Vec<BTreeMap<String, Value>> = vec![BTreeMap::new()];
    for (key, values) in &spec.grid {
        points = points
            .into_iter()
            .flat_map(|p| {
                values.iter().map(move |v| {
                    let mut q = p.clone();
                    q.insert(key.clone(), v.clone());
                    q
                })
            })
            .collect();
    }
    if let Some(d) = &spec.draws {
        let draws: Vec<BTreeMap<String, Value>> = (0..d.count)
            .map(|k| {
                let mut rng = SplitMix(d.seed.wrapping_add(k as u64));
                d.uniform
                    .iter()
                    .map(|(key, [lo, hi])| {
                        let u = 0.5 * (rng.symmetric() + 1.0);
                        (key.clone(), Value::from(lo + (hi - lo) * u))
                    })
                    .collect()
            })
            .collect();
        points = points
            .into_iter()
            .flat_map(|p| {
                draws.iter().map(move |d| {
                    let mut q = p.clone();
                    q.extend(d.clone());
                    q
                })
            })
            .collect();
    }
    let width = (points.len().max(1) - 1).to_string().len().max(4);
    points
        .into_iter()
        .enumerate()
        .map(|(i, params)| RunInput {
            id: format!("run_{i:0width$}"),
            params,
        })
        .collect()
}

/// The scene of run `input`: `base` with each parameter set at its dotted path. The path's
/// parent must exist in the base (an object, or an array indexed by number); the last key may
/// be new (the scene's own check then refuses a field it does not know).
pub fn scene_of(base: &Value, input: &RunInput) -> anyhow::Result<Value> {
    let mut scene = base.clone();
    for (path, value) in &input.params {
        set(&mut scene, path, value.clone())
            .map_err(|e| anyhow::anyhow!("{}: parameter {path}: {e}", input.id))?;
    }
    Ok(scene)
}

fn set(scene: &mut Value, path: &str, value: Value) -> anyhow::Result<()> {
    let keys: Vec<&str> = path.split('.').collect();
    let (last, parents) = keys.split_last().expect("split gives one key at least");
    let mut at = scene;
    for (depth, key) in parents.iter().enumerate() {
        let here = keys[..=depth].join(".");
        at = match at {
            Value::Object(map) => map
                .get_mut(*key)
                .ok_or_else(|| anyhow::anyhow!("the base scene has no {here}"))?,
            Value::Array(items) => {
                let len = items.len();
                let i: usize = key
                    .parse()
                    .map_err(|_| anyhow::anyhow!("{here}: an array wants an index"))?;
                items
                    .get_mut(i)
                    .ok_or_else(|| anyhow::anyhow!("{here}: index {i} of {len} items"))?
            }
            _ => anyhow::bail!("{here} is a value, not an object or array"),
        };
    }
    match at {
        Value::Object(map) => {
            map.insert(last.to_string(), value);
        }
        Value::Array(items) => {
            let len = items.len();
            let i: usize = last
                .parse()
                .map_err(|_| anyhow::anyhow!("{path}: an array wants an index"))?;
            *items
                .get_mut(i)
                .ok_or_else(|| anyhow::anyhow!("{path}: index {i} of {len} items"))? = value;
        }
        _ => anyhow::bail!("the parent of {path} is a value, not an object or array"),
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(text: &str) -> SweepSpec {
        SweepSpec::from_json(text, "spec").unwrap()
    }

    #[test]
    fn the_runs_are_the_grid_times_the_draws_in_order() {
        let s = spec(
            r#"{"name": "s", "base": {},
                "grid": {"b": [1, 2], "a": ["x", "y", "z"]},
                "draws": {"count": 2, "seed": 7, "uniform": {"c": [10, 20]}}}"#,
        );
        let runs = plan(&s);
        assert_eq!(runs.len(), 12);
        assert_eq!(runs[0].id, "run_0000");
        assert_eq!(runs[0].params["a"], "x");
        assert_eq!(runs[0].params["b"], 1);
        // a (first key) varies slowest, then b, then the draws.
        assert_eq!(runs[2].params["b"], 2);
        assert_eq!(runs[4].params["a"], "y");
        let c = |r: &RunInput| r.params["c"].as_f64().unwrap();
        assert_eq!(c(&runs[0]), c(&runs[2]), "common draws across the grid");
        assert_ne!(c(&runs[0]), c(&runs[1]));
        assert!(runs.iter().all(|r| (10.0..20.0).contains(&c(r))));
        assert_eq!(plan(&s), runs, "the same spec plans the same runs");
        assert_eq!(plan(&spec(r#"{"name": "s", "base": {}}"#)).len(), 1);
    }

    #[test]
    fn parameters_go_to_their_paths_and_a_missing_parent_is_named() {
        let base: Value = serde_json::from_str(
            r#"{"materials": {"rock": {"young": 1}}, "joint_sets": [{"spacing": 1}, {"spacing": 2}]}"#,
        )
        .unwrap();
        let input = |k: &str, v: Value| RunInput {
            id: "run_0003".into(),
            params: [(k.to_string(), v)].into(),
        };
        let s = scene_of(&base, &input("materials.rock.young", 5.into())).unwrap();
        assert_eq!(s["materials"]["rock"]["young"], 5);
        let s = scene_of(&base, &input("joint_sets.1.spacing", 3.into())).unwrap();
        assert_eq!(s["joint_sets"][1]["spacing"], 3);
        let s = scene_of(&base, &input("realization", 4.into())).unwrap();
        assert_eq!(s["realization"], 4);
        for (path, says) in [
            ("materials.granite.young", "no materials.granite"),
            ("joint_sets.5.spacing", "index 5 of 2"),
            ("joint_sets.x.spacing", "an array wants an index"),
            ("materials.rock.young.value", "a value"),
        ] {
            let e = scene_of(&base, &input(path, 1.into()))
                .unwrap_err()
                .to_string();
            assert!(e.contains(says) && e.contains("run_0003"), "{path}: {e}");
        }
    }
}
