//! One output policy for every command.
//!
//! * **Outputs stay inside the output folder.** A name that comes from an input file (the `name` of an
//!   `entry case` file, a sensor or a wave) is turned into a single safe path component by
//!   [`safe_component`] and never joined as a path; a path read back from a results folder (the
//!   `run_folder` of an event in `summary.json`) is accepted only by [`confined`], which refuses absolute
//!   paths, `..` and anything that resolves outside the folder.
//! * **Inputs and foreign files are never overwritten without `--force`.** [`refuse_input_target`]
//!   refuses an output that is one of the command's own inputs (or, for a folder, holds one of them), and
//!   [`check_out_folder`] refuses an existing output folder that holds files the command did not write —
//!   the rule `assess` and `sweep` have applied from the start, now shared by every command.

use std::path::{Component, Path, PathBuf};

use crate::error::{Error, Result};

/// Longest name accepted as a path component, in characters.
pub const MAX_NAME_CHARS: usize = 120;

/// `name` as one path component: letters, digits, `.`, `_`, `-` and `+` are kept, every other
/// character (a `/`, `\`, `:`, a space, a control character) becomes `_`, leading dots are removed (no
/// hidden folders and no `..`) and the length is capped at [`MAX_NAME_CHARS`]. A name with nothing left
/// (empty, only dots) is refused; `what` names where it came from in the message.
pub fn safe_component(name: &str, what: &str) -> Result<String> {
    let mapped: String = name
        .trim()
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || matches!(c, '.' | '_' | '-' | '+') {
                c
            } else {
                '_'
            }
        })
        .take(MAX_NAME_CHARS)
        .collect();
    let kept = mapped.trim_start_matches('.').to_string();
    if kept.is_empty() || kept.chars().all(|c| c == '_') {
        return Err(Error::Invalid(format!(
            "{what} '{}' gives no usable folder name (it must contain a letter or digit); give a name with \
             one, or the output folder with -o DIR",
            escape_control(name)
        )));
    }
    Ok(kept)
}

/// `rel`, a path read from a results folder, joined to `base` only when it stays inside it: relative,
/// made of plain names (no `..`, no root, no drive prefix), and, where it exists, not leading out of
/// `base` through a symbolic link. The error says what is wrong with it.
pub fn confined(base: &Path, rel: &str) -> std::result::Result<PathBuf, String> {
    let p = Path::new(rel);
    if rel.is_empty() {
        return Err("the path is empty".into());
    }
    for c in p.components() {
        match c {
            Component::Normal(_) | Component::CurDir => {}
            Component::ParentDir => {
                return Err(format!(
                    "'{}' climbs out of the results folder with '..'",
                    escape_control(rel)
                ));
            }
            Component::RootDir | Component::Prefix(_) => {
                return Err(format!(
                    "'{}' is an absolute path; paths in a results folder are relative to it",
                    escape_control(rel)
                ));
            }
        }
    }
    let joined = base.join(p);
    if let (Ok(b), Ok(j)) = (base.canonicalize(), joined.canonicalize())
        && !j.starts_with(&b)
    {
        return Err(format!(
            "'{}' leads out of the results folder (to {})",
            escape_control(rel),
            j.display()
        ));
    }
    Ok(joined)
}

/// The canonical form of `p`, or of its nearest existing ancestor joined with the rest (for an output
/// that does not exist yet), so that two spellings of the same place compare equal.
fn resolved(p: &Path) -> PathBuf {
    if let Ok(c) = p.canonicalize() {
        return c;
    }
    let mut rest = Vec::new();
    let mut cur = p.to_path_buf();
    loop {
        match cur.file_name() {
            Some(n) => rest.push(n.to_os_string()),
            None => return p.to_path_buf(),
        }
        if !cur.pop() {
            return p.to_path_buf();
        }
        let base = if cur.as_os_str().is_empty() {
            PathBuf::from(".")
        } else {
            cur.clone()
        };
        if let Ok(c) = base.canonicalize() {
            let mut out = c;
            for n in rest.iter().rev() {
                out.push(n);
            }
            return out;
        }
    }
}

/// Refuse an output `out` (a file or a folder) that is one of `inputs` (under any spelling of its
/// path), unless `force`. `option` names the option in the message (`-o`).
pub fn refuse_input_target(out: &Path, inputs: &[&Path], option: &str, force: bool) -> Result<()> {
    if force {
        return Ok(());
    }
    let o = resolved(out);
    for input in inputs {
        let i = resolved(input);
        if i == o {
            return Err(Error::Invalid(format!(
                "{option} {} is the input {}: writing there would overwrite it; give another {option} \
                 (or --force to overwrite it anyway)",
                out.display(),
                input.display()
            )));
        }
    }
    Ok(())
}

/// Refuse an existing output folder that holds a file or folder the command did not write (`known`
/// decides, hidden entries are always allowed), unless `force`; `what` names the command's results
/// ("an assessment", "a sweep"). A file where the folder should be is refused as such.
pub fn check_out_folder(
    dir: &Path,
    known: &dyn Fn(&str) -> bool,
    what: &str,
    force: bool,
) -> Result<()> {
    if dir.exists() && !dir.is_dir() {
        return Err(Error::Invalid(format!(
            "the output folder {} is a file, not a folder; give another -o DIR",
            dir.display()
        )));
    }
    if let Some(f) = file_in_the_way(dir) {
        return Err(Error::Invalid(format!(
            "the output folder {} cannot be made: {} is a file, not a folder; give another -o DIR",
            dir.display(),
            f.display()
        )));
    }
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Ok(());
    };
    let other = entries
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .find(|n| !known(n) && !n.starts_with('.'));
    match other {
        Some(n) if !force => Err(Error::Invalid(format!(
            "the output folder {} holds '{}', which {what} did not write; give another -o DIR or --force \
             to write there anyway",
            dir.display(),
            escape_control(&n)
        ))),
        _ => Ok(()),
    }
}

/// The nearest ancestor of `p` (not `p` itself) that exists as a file rather than a folder, if any: the
/// reason a folder cannot be created under it.
pub fn file_in_the_way(p: &Path) -> Option<PathBuf> {
    p.ancestors()
        .skip(1)
        .filter(|a| !a.as_os_str().is_empty())
        .find(|a| std::fs::metadata(a).is_ok_and(|m| !m.is_dir()))
        .map(Path::to_path_buf)
}

/// `text` with every control character written as an escape (`\n`, `\u{1b}`), so that a name from a
/// file never moves the cursor, rings the bell or recolours the terminal.
pub fn escape_control(text: &str) -> String {
    if !text.chars().any(char::is_control) {
        return text.to_string();
    }
    text.chars()
        .map(|c| {
            if c.is_control() {
                c.escape_default().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_become_one_component() {
        assert_eq!(safe_component("../../escaped", "n").unwrap(), "_.._escaped");
        assert_eq!(safe_component("/abs/dir", "n").unwrap(), "_abs_dir");
        assert_eq!(safe_component("wedge 30", "n").unwrap(), "wedge_30");
        assert!(safe_component("", "n").is_err());
        assert!(safe_component("..", "n").is_err());
        assert!(safe_component("/", "n").is_err());
        assert_eq!(
            safe_component(&"a".repeat(500), "n").unwrap().len(),
            MAX_NAME_CHARS
        );
    }

    #[test]
    fn results_paths_are_confined() {
        let d = tempfile::tempdir().unwrap();
        assert!(confined(d.path(), "runs/a").is_ok());
        assert!(confined(d.path(), "../x").is_err());
        assert!(confined(d.path(), "runs/../../x").is_err());
        assert!(confined(d.path(), "/etc").is_err());
        assert!(confined(d.path(), "").is_err());
    }

    #[test]
    fn an_input_is_not_a_target() {
        let d = tempfile::tempdir().unwrap();
        let f = d.path().join("h.toml");
        std::fs::write(&f, "x").unwrap();
        let same = d.path().join(".").join("h.toml");
        assert!(refuse_input_target(&same, &[&f], "-o", false).is_err());
        assert!(refuse_input_target(&same, &[&f], "-o", true).is_ok());
        assert!(refuse_input_target(&d.path().join("new.svg"), &[&f], "-o", false).is_ok());
    }

    #[test]
    fn control_characters_are_escaped() {
        assert_eq!(escape_control("a\u{1b}[31mb\n"), "a\\u{1b}[31mb\\n");
        assert_eq!(escape_control("plain"), "plain");
    }
}
