//! Known-failure texts made from the numbers they explain (issue 26): a case file's `known_failure` is a
//! template whose numbers are all placeholders, `{name}`, filled from the run's [`Outcome::facts`] and
//! from `{computed}`, `{reference}`, `{error}` and `{tolerance}`; a literal number in the template is
//! refused when the case file is read, so a known-failure text cannot quote a number that a later run no
//! longer gives. The printed text opens with the comparison itself, also from the run.
//!
//! [`Outcome::facts`]: super::Outcome::facts

use super::Case;
use super::compare::{Reference, Verdict, error_text, tolerance_text, trim, with_unit};
use super::report::reference_text;

/// The byte offset and text of the first literal number in `template` outside its placeholders: a digit
/// that does not continue or start a word (`2D`, `S093`, `cot^2` are words; `10 deg`, `0.15` are not).
pub fn literal_number(template: &str) -> Option<(usize, String)> {
    let b = template.as_bytes();
    let mut depth = 0usize;
    for (i, &c) in b.iter().enumerate() {
        match c {
            b'{' => depth += 1,
            b'}' => depth = depth.saturating_sub(1),
            _ if depth == 0 && c.is_ascii_digit() => {
                let prev = i.checked_sub(1).map(|j| b[j]);
                if prev.is_some_and(|p| p.is_ascii_alphanumeric() || p == b'_' || p == b'^') {
                    continue;
                }
                let end = (i..b.len())
                    .find(|&j| !(b[j].is_ascii_digit() || b[j] == b'.'))
                    .unwrap_or(b.len());
                if end < b.len() && b[end].is_ascii_alphabetic() {
                    continue;
                }
                return Some((i, template[i..end].trim_end_matches('.').to_string()));
            }
            _ => {}
        }
    }
    None
}

/// `template` with every `{name}` replaced by its value in `facts`; an unknown or unclosed placeholder
/// is an error naming it and the facts there are.
pub fn explain(template: &str, facts: &[(String, String)]) -> Result<String, String> {
    let mut out = String::with_capacity(template.len());
    let mut rest = template;
    while let Some(i) = rest.find('{') {
        out += &rest[..i];
        let after = &rest[i + 1..];
        let Some(j) = after.find('}') else {
            return Err(format!(
                "the known-failure text has an unclosed `{{` at `{}`",
                after.chars().take(20).collect::<String>()
            ));
        };
        let name = after[..j].trim();
        match facts.iter().find(|f| f.0 == name) {
            Some(f) => out += &f.1,
            None => {
                return Err(format!(
                    "the known-failure text quotes {{{name}}}, which this case's computation does not \
                     give (it gives: {})",
                    facts
                        .iter()
                        .map(|f| f.0.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                ));
            }
        }
        rest = &after[j + 1..];
    }
    out += rest;
    Ok(out)
}

/// The known-failure text of a run: the comparison (computed, reference, tolerance, error, all from the
/// run) and the case file's `template` filled with the run's `facts`. A run within the tolerance says
/// only that (the template, still checked, explains a failure this run does not show).
pub fn text(
    template: &str,
    facts: &[(String, String)],
    computed: f64,
    reference: &Reference,
    error: Option<f64>,
    case: &Case,
    verdict: Verdict,
) -> Result<String, String> {
    let unit = case.unit.as_str();
    let mut all = vec![
        ("computed".to_string(), with_unit(&trim(computed), unit)),
        (
            "reference".to_string(),
            reference_text(Some(reference), unit),
        ),
        ("error".to_string(), error_text(error, case.tolerance, unit)),
        (
            "tolerance".to_string(),
            tolerance_text(case.tolerance, unit),
        ),
    ];
    all.extend(facts.iter().cloned());
    let body = explain(template, &all).map_err(|e| format!("{}: {e}", case.path.display()))?;
    let [c, r, e, t] = [0, 1, 2, 3].map(|k| all[k].1.clone());
    Ok(match verdict {
        // The explanation is of a failure this run does not show: not printed as if it did.
        Verdict::UnexpectedPass => format!(
            "computed {c} against {r} (tolerance {t}): within the tolerance in this run, although the \
             case file marks a known failure (seen in other runs or modes); the mark should be revisited"
        ),
        _ => format!(
            "computed {c} against {r} (tolerance {t}, error {e}): outside the tolerance. {body}"
        ),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn literal_numbers_are_found_and_words_with_digits_are_not() {
        assert_eq!(literal_number("a 2D model, S093-{x} and cot^2 beta"), None);
        assert_eq!(
            literal_number("at 10 deg the window"),
            Some((3, "10".into()))
        );
        assert_eq!(
            literal_number("closest is {closest} away, target 0.15."),
            Some((34, "0.15".into()))
        );
        assert_eq!(literal_number("{a} {b:.2} {c}"), None);
    }

    #[test]
    fn placeholders_are_filled_and_unknown_ones_refused() {
        let facts = vec![
            ("computed".to_string(), "1.08 -".to_string()),
            ("first".to_string(), "0.79".to_string()),
        ];
        assert_eq!(
            explain("from {first} to { computed }.", &facts).unwrap(),
            "from 0.79 to 1.08 -."
        );
        let e = explain("the {last} sensor", &facts).unwrap_err();
        assert!(e.contains("{last}") && e.contains("computed, first"), "{e}");
        assert!(explain("open {first", &facts).is_err());
    }
}
