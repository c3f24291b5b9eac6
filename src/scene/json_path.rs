//! Where a parse error is, as a scene's author names it: the JSON path (`materials.rock.young`,
//! `stages[2].install[0]`) of the value at a line and column, and serde's wording made plain.
//!
//! serde_json reports a line and column; a scene given as a Python dict was never written as
//! text by its author, so its messages name the path instead, and a file's name both.

/// One open container on the way to a position: an object with the key being read or last read,
/// or an array with the index of its current element.
enum Level {
    Object(Option<String>),
    Array(usize),
}

/// The JSON path of the value at 1-based `line` and `column` of `text` (the position serde_json
/// reports: the last character it read), e.g. `stages[1].solve.method`; empty at the top level.
pub fn path_at(text: &str, line: usize, column: usize) -> String {
    let mut stack: Vec<Level> = Vec::new();
    let mut chars = text.chars();
    let (mut l, mut c) = (1usize, 0usize);
    // Whether the string being read is an object's key (else a value).
    let mut expecting_key = false;
    let at_end = |l: usize, c: usize| l > line || (l == line && c >= column);
    let mut last = ' ';
    while let Some(ch) = chars.next() {
        last = ch;
        if ch == '\n' {
            (l, c) = (l + 1, 0);
        } else {
            c += 1;
        }
        match ch {
            '{' => {
                stack.push(Level::Object(None));
                expecting_key = true;
            }
            '[' => {
                stack.push(Level::Array(0));
                expecting_key = false;
            }
            '}' | ']' => {
                stack.pop();
            }
            ',' => match stack.last_mut() {
                Some(Level::Array(i)) => *i += 1,
                Some(Level::Object(_)) => expecting_key = true,
                None => {}
            },
            ':' => expecting_key = false,
            '"' => {
                let s = read_string(&mut chars, &mut l, &mut c);
                if expecting_key && let Some(Level::Object(key)) = stack.last_mut() {
                    *key = Some(s);
                }
            }
            _ => {}
        }
        if at_end(l, c) {
            break;
        }
    }
    // serde stops on an array's opening bracket when the array itself is of the wrong type.
    if last == '[' {
        stack.pop();
    }
    render(&stack)
}

/// Read a JSON string's rest after its opening quote, counting lines and columns.
fn read_string(chars: &mut std::str::Chars, l: &mut usize, c: &mut usize) -> String {
    let mut s = String::new();
    while let Some(ch) = chars.next() {
        *c += 1;
        match ch {
            '"' => break,
            '\\' => {
                if let Some(e) = chars.next() {
                    *c += 1;
                    s.push(e);
                }
            }
            '\n' => {
                (*l, *c) = (*l + 1, 0);
            }
            _ => s.push(ch),
        }
    }
    s
}

fn render(stack: &[Level]) -> String {
    let mut path = String::new();
    for level in stack {
        match level {
            Level::Object(Some(key)) => {
                if !path.is_empty() {
                    path.push('.');
                }
                path.push_str(key);
            }
            Level::Object(None) => {}
            Level::Array(i) => path.push_str(&format!("[{i}]")),
        }
    }
    path
}

/// serde_json's message made plain: its own " at line L column C" dropped (the error says where),
/// and Rust's type names said as a scene's author reads them (`f64` is "a number").
pub fn plain_message(message: &str) -> String {
    let text = match message.rfind(" at line ") {
        Some(i) => &message[..i],
        None => message,
    };
    [
        ("expected f64", "expected a number"),
        ("expected f32", "expected a number"),
        ("expected u32", "expected a whole number, 0 or more"),
        ("expected u64", "expected a whole number, 0 or more"),
        ("expected usize", "expected a whole number, 0 or more"),
        ("expected i64", "expected a whole number"),
        ("expected i32", "expected a whole number"),
        ("invalid type: floating point", "invalid type: number"),
        ("expected a borrowed string", "expected a string"),
    ]
    .iter()
    .fold(text.to_string(), |t, (from, to)| t.replace(from, to))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The position serde_json reports for `text` parsed as some value, and the path there.
    fn path_of_error<T: serde::de::DeserializeOwned + std::fmt::Debug>(text: &str) -> String {
        let e = serde_json::from_str::<T>(text).unwrap_err();
        path_at(text, e.line(), e.column())
    }

    #[derive(Debug, serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Rock {
        young: f64,
        #[serde(default)]
        list: Vec<[f64; 2]>,
    }

    #[derive(Debug, serde::Deserialize)]
    #[allow(dead_code)]
    struct Top {
        name: String,
        materials: std::collections::BTreeMap<String, Rock>,
        #[serde(default)]
        stages: Vec<Rock>,
    }

    #[test]
    fn a_wrong_type_is_found_at_its_key_on_one_line_or_many() {
        let one = r#"{"name": "a", "materials": {"granite": {"young": "x"}}}"#;
        assert_eq!(path_of_error::<Top>(one), "materials.granite.young");
        let many = "{\n \"name\": \"a\",\n \"materials\": {\n  \"granite\": {\n   \"young\": true\n  }\n }\n}";
        assert_eq!(path_of_error::<Top>(many), "materials.granite.young");
    }

    #[test]
    fn array_elements_and_unknown_fields_are_found() {
        let text = r#"{"name": "a", "materials": {}, "stages": [{"young": 1}, {"young": 2, "list": [[0, 1], [2, "3"]]}]}"#;
        assert_eq!(path_of_error::<Top>(text), "stages[1].list[1][1]");
        let unknown = r#"{"name": "a", "materials": {"r": {"young": 1, "yung": 2}}}"#;
        assert_eq!(path_of_error::<Top>(unknown), "materials.r.yung");
    }

    #[test]
    fn keys_with_escapes_and_commas_in_strings_do_not_confuse_it() {
        let text = r#"{"name": "a, \"b\" [", "materials": {"r,\"1\"": {"young": []}}}"#;
        assert_eq!(path_of_error::<Top>(text), "materials.r,\"1\".young");
    }

    #[test]
    fn serde_type_names_read_as_words() {
        let e = serde_json::from_str::<Rock>(r#"{"young": "x"}"#).unwrap_err();
        assert_eq!(
            plain_message(&e.to_string()),
            "invalid type: string \"x\", expected a number"
        );
    }
}
