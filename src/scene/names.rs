//! Names in a scene: each a short printable string that is safe in a file name, an XML attribute
//! and a CSV column, and the names a boundary condition can mean (boundary parts, excavations,
//! inclusions) unique among themselves.

use std::collections::HashMap;

use super::Scene;
use super::validate::{SceneError, invalid};

/// Longest name, in characters.
pub const MAX_NAME_CHARS: usize = 64;

/// Characters no name may hold: path separators, and what XML would have to escape.
const FORBIDDEN: [char; 6] = ['/', '\\', '"', '<', '>', '&'];

/// Check one name at `path`: 1 to `MAX_NAME_CHARS` characters, no control characters, none of
/// `FORBIDDEN`, no space at either end, and neither `.` nor `..`.
pub(super) fn check_name(path: &str, name: &str) -> Result<(), SceneError> {
    let chars = name.chars().count();
    let reason = if name.is_empty() {
        "must not be empty".to_string()
    } else if chars > MAX_NAME_CHARS {
        format!("{chars} characters exceed the limit of {MAX_NAME_CHARS}")
    } else if name.chars().any(char::is_control) {
        "must not hold control characters".to_string()
    } else if let Some(c) = name.chars().find(|c| FORBIDDEN.contains(c)) {
        format!("must not hold '{c}' (none of / \\ \" < > &)")
    } else if name.trim() != name {
        "must not start or end with a space".to_string()
    } else if name == "." || name == ".." {
        "must not be '.' or '..'".to_string()
    } else {
        return Ok(());
    };
    Err(invalid(path, format!("'{}': {reason}", shown(name))))
}

/// A name as shown in a message: at most 40 characters, control characters escaped.
fn shown(name: &str) -> String {
    let mut s: String = name
        .chars()
        .take(40)
        .flat_map(char::escape_default)
        .collect();
    if name.chars().count() > 40 {
        s.push('…');
    }
    s
}

impl Scene {
    /// Every name of the scene (`check_name`), and one namespace for `outer`, the region's edge
    /// names, the excavations and the inclusions: a boundary condition's `part` means one thing.
    pub(super) fn validate_names(&self) -> Result<(), SceneError> {
        check_name("name", &self.name)?;
        for name in self.materials.keys() {
            check_name(&format!("materials.{}", shown(name)), name)?;
        }
        for name in self.joint_materials.keys() {
            check_name(&format!("joint_materials.{}", shown(name)), name)?;
        }
        // Each part name and the field that first gave it; region edges may share a name (that
        // groups them into one part), nothing else may.
        let mut parts: HashMap<&str, String> =
            HashMap::from([("outer", "the whole outer boundary".to_string())]);
        let edges = self.region.edge_names.iter().flatten().enumerate();
        let named = edges
            .map(|(i, n)| (format!("region.edge_names[{i}]"), n.as_str()))
            .chain(
                self.excavations
                    .iter()
                    .enumerate()
                    .map(|(i, e)| (format!("excavations[{i}].name"), e.name.as_str())),
            )
            .chain(
                self.inclusions
                    .iter()
                    .enumerate()
                    .map(|(i, e)| (format!("inclusions[{i}].name"), e.name.as_str())),
            );
        for (path, name) in named {
            check_name(&path, name)?;
            let edge = path.starts_with("region.");
            match parts.get(name) {
                Some(first) if !(edge && first.starts_with("region.")) => {
                    return Err(invalid(
                        path,
                        format!(
                            "'{name}' already names {first}: boundary parts, excavations and \
                             inclusions share one namespace"
                        ),
                    ));
                }
                Some(_) => {}
                None => {
                    parts.insert(name, path);
                }
            }
        }
        for (i, st) in self.stages.iter().enumerate() {
            check_name(&format!("stages[{i}].name"), &st.name)?;
        }
        for (i, b) in self.bolts.iter().enumerate() {
            check_name(&format!("bolts[{i}].name"), &b.name)?;
        }
        for (i, h) in self.histories.iter().enumerate() {
            check_name(&format!("histories[{i}].name"), &h.name)?;
        }
        for (i, l) in self.liners.iter().enumerate() {
            check_name(&format!("liners[{i}].name"), &l.name)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_printable_short_and_file_safe() {
        for good in [
            "tunnel",
            "excavate, 25 % support",
            "crown bolts",
            "Ü-Bahn (2)",
        ] {
            assert!(check_name("n", good).is_ok(), "{good}");
        }
        for (bad, why) in [
            ("", "empty"),
            (".", "'.'"),
            ("..", "'.'"),
            ("a/b", "'/'"),
            ("a\"b", "'\"'"),
            ("<x>", "'<'"),
            ("a&b", "'&'"),
            ("a\u{0}b", "control"),
            (" a", "space"),
        ] {
            let msg = check_name("n", bad).unwrap_err().to_string();
            assert!(
                msg.starts_with("n: ") && msg.contains(why),
                "{bad:?}: {msg}"
            );
        }
        let long = "x".repeat(300);
        let msg = check_name("name", &long).unwrap_err().to_string();
        assert!(
            msg.contains("300 characters exceed the limit of 64") && msg.len() < 200,
            "{msg}"
        );
    }
}
