//! The part of a scene that sets its state at the end of a stage, and where two scenes' parts
//! first differ: what lets a run go on from a checkpoint of another scene whose earlier stages
//! are the same (UDEC's save and restore, branched: the same excavation, another bolt pattern).
//!
//! The part is the scene as parsed (its pretty `Debug` text: one field a line, whatever the
//! file's layout) without its name, its output folder, the stages after the checkpoint's and the
//! bolt groups and liners only those later stages install.

use std::collections::BTreeSet;

use crate::Scene;

/// The text of the part of `scene` that sets its state after its first `stages_done` stages.
pub fn prefix(scene: &Scene, stages_done: usize) -> String {
    let mut s = scene.clone();
    s.name.clear();
    s.output.folder = None;
    if !s.stages.is_empty() {
        s.stages.truncate(stages_done);
        let installed: BTreeSet<String> = (s.stages.iter())
            .flat_map(|st| st.install.iter().cloned())
            .collect();
        s.bolts.retain(|b| installed.contains(&b.name));
        s.liners.retain(|l| installed.contains(&l.name));
    }
    format!("{s:#?}")
}

/// Where `theirs` (a checkpoint's prefix) and `ours` (the scene's) first differ: the field's path
/// (`stages[1].support_fraction`) and each side's line there; `None` when they are the same.
pub fn first_difference(theirs: &str, ours: &str) -> Option<(String, String, String)> {
    let (a, b): (Vec<&str>, Vec<&str>) = (theirs.lines().collect(), ours.lines().collect());
    let at = (0..a.len().max(b.len())).find(|&i| a.get(i) != b.get(i))?;
    // The lines before `at` are the same in both: the path is read from either.
    let path = path_of_line(&b[..at.min(b.len())], b.get(at).or(a.get(at)).copied());
    let side = |l: &[&str]| {
        l.get(at).map_or("(nothing)".to_string(), |t| {
            t.trim().trim_end_matches(',').to_string()
        })
    };
    Some((path, side(&a), side(&b)))
}

/// One open level of a pretty `Debug` text: its name in the path, whether it is a list, and the
/// index its next element takes.
struct Level {
    label: String,
    list: bool,
    next: usize,
}

/// The path of `line`, which follows `before`, in a pretty `Debug` text (four spaces a level,
/// the root `Scene {` at level 0).
fn path_of_line(before: &[&str], line: Option<&str>) -> String {
    let mut stack: Vec<Level> = Vec::new();
    for text in before {
        visit(text, &mut stack);
    }
    let Some(line) = line else {
        return String::new();
    };
    let (depth, own) = visit(line, &mut stack);
    let mut path = String::new();
    for level in stack.iter().take(depth).skip(1) {
        join(&mut path, &level.label);
    }
    join(&mut path, &own);
    path
}

/// Read one line into the open levels: its level and its label (a key, a list index, or empty
/// for a closing bracket or an unnamed value).
fn visit(text: &str, stack: &mut Vec<Level>) -> (usize, String) {
    let trimmed = text.trim_start();
    let depth = (text.len() - trimmed.len()) / 4;
    stack.truncate(depth);
    if trimmed.starts_with(['}', ']', ')']) {
        return (depth, String::new());
    }
    let label = match stack.last_mut() {
        Some(parent) if parent.list => {
            parent.next += 1;
            format!("[{}]", parent.next - 1)
        }
        _ => key_of(trimmed).unwrap_or_default(),
    };
    if trimmed.ends_with(['{', '[', '(']) {
        stack.push(Level {
            label: label.clone(),
            list: trimmed.ends_with('['),
            next: 0,
        });
    }
    (depth, label)
}

fn join(path: &mut String, label: &str) {
    if label.is_empty() {
        return;
    }
    if !path.is_empty() && !label.starts_with('[') {
        path.push('.');
    }
    path.push_str(label);
}

/// The key of a `key: value` or `"key": value` line.
fn key_of(line: &str) -> Option<String> {
    if let Some(rest) = line.strip_prefix('"') {
        let end = rest.find('"')?;
        return rest[end + 1..]
            .starts_with(": ")
            .then(|| rest[..end].to_string());
    }
    let end = line.find(": ")?;
    let key = &line[..end];
    key.chars()
        .all(|c| c.is_ascii_alphanumeric() || c == '_')
        .then(|| key.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    const SCENE: &str = r#"{
        "name": "t",
        "materials": { "rock": { "density": 2500, "young": 1e9, "poisson": 0.2 } },
        "region": { "polygon": [[-10, -10], [10, -10], [10, 10], [-10, 10]], "material": "rock" },
        "excavations": [{ "name": "hole", "circle": { "center": [0, 0], "radius": 1 } }],
        "zoning": { "edge_at_excavation": 0.5, "edge_far": 2 },
        "in_situ": { "sxx": -1e6, "syy": -1e6 },
        "boundary": [{ "part": "outer", "in_situ_traction": true }],
        "bolts": [{ "name": "b", "young": 200e9, "area": 5e-4, "yield_force": 2e5,
                    "grout_stiffness": 1e9, "bond_strength": 2e5,
                    "pattern": { "excavation": "hole", "count": 3, "length": 2, "spacing": 1 } }],
        "stages": [
            { "name": "dig", "excavate": ["hole"], "support_fraction": 0.3 },
            { "name": "bolt", "install": ["b"] }
        ]
    }"#;

    fn scene(edit: impl Fn(&mut serde_json::Value)) -> Scene {
        let mut v: serde_json::Value = serde_json::from_str(SCENE).unwrap();
        edit(&mut v);
        Scene::from_json(&v.to_string(), "t").unwrap()
    }

    #[test]
    fn later_stages_their_supports_the_name_and_the_folder_are_not_part_of_it() {
        let base = scene(|_| {});
        let other = scene(|v| {
            v["name"] = "other".into();
            v["output"] = serde_json::json!({ "folder": "elsewhere" });
            v["bolts"][0]["pattern"]["spacing"] = 0.5.into();
            v["stages"][1]["name"] = "bolt closer".into();
        });
        assert_eq!(prefix(&base, 1), prefix(&other, 1));
        assert_ne!(prefix(&base, 2), prefix(&other, 2));
    }

    #[test]
    fn the_first_difference_is_named_by_its_path() {
        let base = scene(|_| {});
        let other = scene(|v| v["stages"][0]["support_fraction"] = 0.4.into());
        let (path, theirs, ours) = first_difference(&prefix(&base, 1), &prefix(&other, 1)).unwrap();
        assert_eq!(path, "stages[0].support_fraction");
        assert_eq!(
            (theirs.as_str(), ours.as_str()),
            ("support_fraction: 0.3", "support_fraction: 0.4")
        );
        let other = scene(|v| v["materials"]["rock"]["young"] = 2e9.into());
        let (path, ..) = first_difference(&prefix(&base, 1), &prefix(&other, 1)).unwrap();
        assert!(path.starts_with("materials.rock."), "{path}");
        let other = scene(|v| v["region"]["polygon"][2][1] = 12.into());
        let (path, ..) = first_difference(&prefix(&base, 1), &prefix(&other, 1)).unwrap();
        assert_eq!(path, "region.polygon[2][1]");
    }
}
