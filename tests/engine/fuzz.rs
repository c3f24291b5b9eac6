//! Fuzzing the scene loader and builder (issue 15): the bundled models mutated 520 ways from a
//! fixed seed (fields deleted, wrong types, extreme numbers, bad names, truncation, garbage), each
//! checked by `adit check` in a child process under a time and memory limit. Every case ends with
//! exit 0, or exit 1 and one `error:` line; never a panic (101), an abort (134), a kill or a hang.

use crate::common;

use std::process::{Command, Stdio};
use std::time::Duration;

use serde_json::{Value, json};

const CASES: usize = 520;
const SECONDS: u64 = 30;
/// Address-space limit of each child, KiB (`ulimit -v`).
const MEMORY_KIB: u64 = 4 << 20;

/// SplitMix64, for a reproducible draw of mutations.
struct Draw(u64);

impl Draw {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

/// JSON pointers of every value in `v` below the root.
fn pointers(v: &Value, at: String, out: &mut Vec<String>) {
    match v {
        Value::Object(m) => {
            for (k, x) in m {
                let p = format!("{at}/{}", k.replace('~', "~0").replace('/', "~1"));
                out.push(p.clone());
                pointers(x, p, out);
            }
        }
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                let p = format!("{at}/{i}");
                out.push(p.clone());
                pointers(x, p, out);
            }
        }
        _ => {}
    }
}

/// The replacement values a mutation draws from.
fn oddities() -> Vec<Value> {
    vec![
        json!(0),
        json!(-0.0),
        json!(1e-300),
        json!(1e300),
        json!(-1e300),
        json!(u64::MAX),
        json!(-1),
        json!(1e-9),
        json!(9e15),
        json!("NaN"),
        json!(""),
        json!(".."),
        json!("a/b"),
        json!("<&\"x"),
        json!("x".repeat(300)),
        json!("outer"),
        json!(null),
        json!(true),
        json!([]),
        json!({}),
        json!([1e300, -1e300]),
    ]
}

/// Mutation `i` of `model`, as the text of a scene file.
fn mutate(model: &Value, draw: &mut Draw) -> String {
    let mut v = model.clone();
    let mut all = Vec::new();
    pointers(&v, String::new(), &mut all);
    let target = all[draw.below(all.len())].clone();
    match draw.below(10) {
        // Delete the field or element.
        0 | 1 => {
            let (parent, key) = target.rsplit_once('/').unwrap();
            match v.pointer_mut(parent).unwrap() {
                Value::Object(m) => {
                    m.remove(key);
                }
                Value::Array(a) => {
                    a.remove(key.parse::<usize>().unwrap());
                }
                _ => unreachable!(),
            }
            v.to_string()
        }
        // Truncate the text.
        2 => {
            let text = v.to_string();
            let cut = draw.below(text.len());
            text.chars().take(cut).collect()
        }
        // Garbage: control bytes and a stray brace somewhere.
        3 => {
            let text = v.to_string();
            let at = text
                .char_indices()
                .nth(draw.below(text.chars().count()))
                .map_or(0, |(i, _)| i);
            format!("{}\u{1}}}\u{7f}{}", &text[..at], &text[at..])
        }
        // An odd value in place of the field.
        _ => {
            let odd = oddities();
            *v.pointer_mut(&target).unwrap() = odd[draw.below(odd.len())].clone();
            v.to_string()
        }
    }
}

/// Run `adit check` on `text` in a child with the limits; (exit code or None if killed, stderr).
fn check(text: &str, tag: &str) -> (Option<i32>, String) {
    let path = std::env::temp_dir().join(format!("adit-fuzz-{}-{tag}.json", std::process::id()));
    std::fs::write(&path, text).unwrap();
    let child = Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {MEMORY_KIB}; exec \"$0\" check \"$1\""))
        .arg(env!("CARGO_BIN_EXE_adit"))
        .arg(&path)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let (code, err) = common::wait_at_most(child, Duration::from_secs(SECONDS));
    std::fs::remove_file(&path).unwrap();
    (code, err)
}

/// Check every case of `cases` (scene texts) two children at a time, their files named after
/// `test` and the case; the outcomes in order.
fn check_all(cases: &[String], test: &str) -> Vec<(Option<i32>, String)> {
    std::thread::scope(|s| {
        let halves: Vec<_> = [0, 1]
            .map(|h| {
                s.spawn(move || {
                    (h..cases.len())
                        .step_by(2)
                        .map(|i| (i, check(&cases[i], &format!("{test}-{i}"))))
                        .collect::<Vec<_>>()
                })
            })
            .into_iter()
            .collect();
        let mut all: Vec<_> = halves.into_iter().flat_map(|h| h.join().unwrap()).collect();
        all.sort_by_key(|(i, _)| *i);
        all.into_iter().map(|(_, o)| o).collect()
    })
}

/// The outcomes that are neither a build (exit 0) nor one `error:` line (exit 1), described.
fn bad_outcomes(
    outcomes: &[(Option<i32>, String)],
    cases: &[String],
    what: &[String],
) -> Vec<String> {
    let mut bad = Vec::new();
    for (i, (code, err)) in outcomes.iter().enumerate() {
        let clear = err.starts_with("error: ") && err.lines().count() == 1;
        if !(*code == Some(0) || (*code == Some(1) && clear)) {
            bad.push(format!(
                "case {i} ({}): exit {code:?}: {}\n  scene: {}",
                what[i],
                err.lines().next().unwrap_or(""),
                cases[i].chars().take(300).collect::<String>()
            ));
        }
    }
    bad
}

/// The extreme values a numeric field takes in `numeric_fields_at_extremes_build_or_are_named`:
/// huge and tiny of both signs, zero, a subnormal, the smallest normal, the bounds' edges, and
/// strings that other tools write for non-finite numbers.
fn extremes() -> Vec<Value> {
    vec![
        json!(1e300),
        json!(-1e300),
        json!(1e-300),
        json!(-1e-300),
        json!(0),
        json!(-0.0),
        json!(5e-324),
        json!(2.2250738585072014e-308),
        json!(1e30),
        json!(1e-30),
        json!(1.8e19),
        json!(-9e15),
        json!("NaN"),
        json!("inf"),
        json!("-Infinity"),
    ]
}

/// Every numeric field of the bundled models (each number of an array too) set to each extreme
/// value in turn (3 465 scenes): `adit check` builds the scene or refuses it with one error
/// line, within 30 s and 4 GiB each (issue 52: extreme in-situ stresses and gravity had aborted
/// on a 6 GB allocation).
#[test]
fn numeric_fields_at_extremes_build_or_are_named() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/models");
    let extremes = extremes();
    let (mut cases, mut what) = (Vec::new(), Vec::new());
    for name in [
        "kirsch",
        "tunnel",
        "jointed_tunnel",
        "jointed_tunnel_mixed",
        "shallow_tunnel_bem",
    ] {
        let text = std::fs::read_to_string(format!("{dir}/{name}.json")).unwrap();
        let model: Value = serde_json::from_str(&text).unwrap();
        let mut all = Vec::new();
        pointers(&model, String::new(), &mut all);
        for p in all.iter().filter(|p| model.pointer(p).unwrap().is_number()) {
            for x in &extremes {
                let mut v = model.clone();
                *v.pointer_mut(p).unwrap() = x.clone();
                what.push(format!("{name}{p} = {x}"));
                cases.push(v.to_string());
            }
        }
    }
    let outcomes = check_all(&cases, "extremes");
    let bad = bad_outcomes(&outcomes, &cases, &what);
    let built = outcomes.iter().filter(|o| o.0 == Some(0)).count();
    eprintln!(
        "{} numeric fields at extremes: {built} build, {} refused with one error line",
        cases.len(),
        cases.len() - built - bad.len()
    );
    assert!(
        bad.is_empty(),
        "{} bad outcomes:\n{}",
        bad.len(),
        bad.join("\n")
    );
}

#[test]
fn mutated_models_give_a_clear_error_or_build() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/models");
    let models: Vec<Value> = ["kirsch", "tunnel", "jointed_tunnel", "jointed_tunnel_mixed"]
        .iter()
        .map(|m| {
            serde_json::from_str(&std::fs::read_to_string(format!("{dir}/{m}.json")).unwrap())
                .unwrap()
        })
        .collect();
    let mut draw = Draw(15);
    let cases: Vec<String> = (0..CASES)
        .map(|i| mutate(&models[i % models.len()], &mut draw))
        .collect();
    let outcomes = check_all(&cases, "mutations");
    let what: Vec<String> = (0..CASES).map(|i| format!("mutation {i}")).collect();
    let bad = bad_outcomes(&outcomes, &cases, &what);
    let built = outcomes.iter().filter(|o| o.0 == Some(0)).count();
    let refused = CASES - built - bad.len();
    eprintln!("{CASES} mutations: {built} build, {refused} refused with one error line");
    assert!(
        bad.is_empty(),
        "{} bad outcomes:\n{}",
        bad.len(),
        bad.join("\n")
    );
}
