//! The README's figures for the bundled models come from the report's own runs: the report binary
//! rewrites the block between `BEGIN` and `END` in README.md, so no figure there is typed by hand.

/// Marks the start of the generated block (an HTML comment: invisible when rendered).
pub const BEGIN: &str =
    "<!-- models table: written by `cargo run -p adit-validation --release` -->";
/// Marks its end.
pub const END: &str = "<!-- end of models table -->";

/// One bundled model's run.
#[derive(Debug, Clone)]
pub struct ModelRow {
    /// The scene file, e.g. `models/tunnel.json`.
    pub file: String,
    pub zones: usize,
    pub blocks: usize,
    pub cycles: u64,
    /// Wall-clock seconds of the run (build and solve).
    pub seconds: f64,
    /// What the run gives, in words with its figures.
    pub result: String,
}

/// The generated block: a table of the bundled models with the threads they ran on.
pub fn models_table(rows: &[ModelRow], threads: usize) -> String {
    let mut s = format!(
        "{BEGIN}\n| model | zones | blocks | cycles or iterations | seconds ({threads} threads) | result |\n|---|---|---|---|---|---|\n"
    );
    for r in rows {
        s.push_str(&format!(
            "| `{}` | {} | {} | {} | {:.1} | {} |\n",
            r.file, r.zones, r.blocks, r.cycles, r.seconds, r.result
        ));
    }
    s.push_str(END);
    s
}

/// `text` with the block from `BEGIN` to `END` (markers included) replaced by `block`; an error if
/// the markers are missing or out of order, so a README that lost them is not silently left stale.
pub fn replace_block(text: &str, block: &str) -> anyhow::Result<String> {
    let start = text
        .find(BEGIN)
        .ok_or_else(|| anyhow::anyhow!("README.md has no line `{BEGIN}`"))?;
    let end = text[start..]
        .find(END)
        .map(|e| start + e + END.len())
        .ok_or_else(|| anyhow::anyhow!("README.md has no line `{END}` after `{BEGIN}`"))?;
    Ok(format!("{}{}{}", &text[..start], block, &text[end..]))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row() -> ModelRow {
        ModelRow {
            file: "models/tunnel.json".into(),
            zones: 4149,
            blocks: 258,
            cycles: 17020,
            seconds: 7.25,
            result: "closure 11.3 mm".into(),
        }
    }

    #[test]
    fn the_block_is_replaced_and_the_rest_kept() {
        let text = format!("intro\n{BEGIN}\nold figures\n{END}\noutro\n");
        let out = replace_block(&text, &models_table(&[row()], 2)).unwrap();
        assert!(
            out.starts_with("intro\n") && out.ends_with("\noutro\n"),
            "{out}"
        );
        assert!(!out.contains("old figures"));
        assert!(
            out.contains("| `models/tunnel.json` | 4149 | 258 | 17020 | 7.2 | closure 11.3 mm |")
        );
        // Idempotent: a second pass finds its own markers.
        let again = replace_block(&out, &models_table(&[row()], 2)).unwrap();
        assert_eq!(again, out);
    }

    #[test]
    fn a_readme_without_markers_is_an_error() {
        assert!(replace_block("no markers here", "x").is_err());
        assert!(replace_block(&format!("{END} then {BEGIN}"), "x").is_err());
    }

    /// The shipped README carries the markers the report rewrites.
    #[test]
    fn the_readme_has_the_generated_block() {
        let text = std::fs::read_to_string(crate::repository_root().join("README.md")).unwrap();
        replace_block(&text, "x").unwrap();
    }
}
