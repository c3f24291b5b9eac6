//! Fuzzing the scene loader and builder (issue 15): the bundled models mutated 520 ways from a
//! fixed seed (fields deleted, wrong types, extreme numbers, bad names, truncation, garbage), each
//! checked by `adit check` in a child process under a time and memory limit. Every case ends with
//! exit 0, or exit 1 and one `error:` line; never a panic (101), an abort (134), a kill or a hang.

mod common;

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
fn check(text: &str, tag: usize) -> (Option<i32>, String) {
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
    // Two children at a time.
    let outcomes: Vec<(Option<i32>, String)> = std::thread::scope(|s| {
        let halves: Vec<_> = [0, 1]
            .map(|h| {
                let cases = &cases;
                s.spawn(move || {
                    (h..cases.len())
                        .step_by(2)
                        .map(|i| (i, check(&cases[i], i)))
                        .collect::<Vec<_>>()
                })
            })
            .into_iter()
            .collect();
        let mut all: Vec<_> = halves.into_iter().flat_map(|h| h.join().unwrap()).collect();
        all.sort_by_key(|(i, _)| *i);
        all.into_iter().map(|(_, o)| o).collect()
    });
    let mut bad = Vec::new();
    let (mut built, mut refused) = (0, 0);
    for (i, ((code, err), text)) in outcomes.iter().zip(&cases).enumerate() {
        let clear = err.starts_with("error: ") && err.lines().count() == 1;
        match code {
            Some(0) => built += 1,
            Some(1) if clear => refused += 1,
            _ => bad.push(format!(
                "case {i}: exit {code:?}: {}\n  scene: {}",
                err.lines().next().unwrap_or(""),
                text.chars().take(300).collect::<String>()
            )),
        }
    }
    eprintln!("{CASES} mutations: {built} build, {refused} refused with one error line");
    assert!(
        bad.is_empty(),
        "{} bad outcomes:\n{}",
        bad.len(),
        bad.join("\n")
    );
}
