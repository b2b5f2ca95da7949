//! The program's messages in the page's language: `cagd: error: NAME: PROBLEM; expected FORM`
//! (and warnings) rendered in Slovenian or Czech through a catalogue of their fixed phrases
//! ([`PHRASES`]), keyed by the English words. The program stays the owner of the wording and
//! of every rule: the catalogue only translates what it was told, phrase by phrase, copying
//! the values (numbers, quoted input, option names) as they are.
//!
//! A message is translated whole or not at all: when a part of its words is not in the
//! catalogue (a rarer error), it is shown in English as the program words it, never half in
//! one language and half in another. The head (`cagd: error:`) follows the body.

use cagd_cli::lang::Lang;
use wasm_bindgen::prelude::wasm_bindgen;

mod phrases;

pub use phrases::PHRASES;

/// A fixed phrase of the messages: the English words, `{0}`, `{1}`, … standing for values
/// copied as they are, and the same in Slovenian and Czech.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Phrase {
    /// English, as the program words it.
    pub en: &'static str,
    /// Slovenian.
    pub sl: &'static str,
    /// Czech.
    pub cs: &'static str,
}

impl Phrase {
    fn get(&self, lang: Lang) -> &'static str {
        match lang {
            Lang::En => self.en,
            Lang::Sl => self.sl,
            Lang::Cs => self.cs,
        }
    }
}

/// The heads of the lines the program prints, in English, Slovenian and Czech.
const HEADS: [[&str; 3]; 3] = [
    ["cagd: error: ", "cagd: napaka: ", "cagd: chyba: "],
    ["cagd: warning: ", "cagd: opozorilo: ", "cagd: varování: "],
    [
        "cagd: internal error: ",
        "cagd: notranja napaka: ",
        "cagd: vnitřní chyba: ",
    ],
];

/// `message` (`cagd: error: NAME: BODY`, a warning, …) in the language of code `lang` (`sl`,
/// `cs`), or as it is when its words are not all in the catalogue, or the language is English
/// or not one of the page's.
///
/// ```
/// let e = "cagd: error: --knots: knot vector: knot 5 (0.5) is below the knot before it (1); \
///     knots must be non-decreasing; expected n + p + 1 non-decreasing knots for n control \
///     points of degree p (n ≥ p + 1), with u_(p+1) < u_(n+1)";
/// assert_eq!(cagd_web::message_in(e, "sl"),
///     "cagd: napaka: --knots: vozliščni vektor: vozel 5 (0.5) je manjši od vozla pred njim (1); \
///     vozli morajo biti nepadajoči; pričakovano: n + p + 1 nepadajočih vozlov za n kontrolnih \
///     točk stopnje p (n ≥ p + 1), pri čemer u_(p+1) < u_(n+1)");
/// assert_eq!(cagd_web::message_in(e, "en"), e);
/// let rare = "cagd: error: --t: spline parameters: t_3 = 2 is not above t_2 = 2; expected increasing values";
/// assert_eq!(cagd_web::message_in(rare, "cs"), rare);
/// ```
#[wasm_bindgen]
pub fn message_in(message: &str, lang: &str) -> String {
    Lang::from_code(lang)
        .and_then(|lang| translate(message, lang))
        .unwrap_or_else(|| message.to_string())
}

/// `message` in `lang`: its head, its NAME as it is and its body from the catalogue; `None`
/// when a part of the body is not in it (or the message has no head the program prints).
pub fn translate(message: &str, lang: Lang) -> Option<String> {
    let column = Lang::ALL.iter().position(|&l| l == lang)?;
    let (head, rest) = HEADS
        .iter()
        .find_map(|h| message.strip_prefix(h[0]).map(|rest| (h[column], rest)))?;
    let (name, body) = rest.split_once(": ")?;
    Some(format!("{head}{name}: {}", body_in(body, lang)?))
}

/// The body of a message (after `NAME: `) in `lang`, phrase by phrase; `None` when a word of
/// it is in no phrase (values, option names, quoted input and symbols are no words).
pub fn body_in(body: &str, lang: Lang) -> Option<String> {
    if lang == Lang::En {
        return Some(body.to_string());
    }
    let (mut out, mut plain, mut at) = (String::new(), String::new(), 0);
    while at < body.len() {
        // The phrase with the longest English words that stands here.
        let found = PHRASES
            .iter()
            .filter_map(|p| matched(body, at, p.en).map(|(end, values)| (p, end, values)))
            .max_by_key(|(p, _, _)| p.en.len());
        if let Some((phrase, end, values)) = found {
            if !neutral(&plain) {
                return None;
            }
            out.push_str(&plain);
            plain.clear();
            out.push_str(&filled(phrase.get(lang), &values, lang));
            at = end;
        } else {
            let c = body[at..].chars().next()?;
            plain.push(c);
            at += c.len_utf8();
        }
    }
    neutral(&plain).then(|| out + &plain)
}

/// A part of a phrase's English words.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Part<'a> {
    Words(&'a str),
    Value(usize),
}

/// The words and the value places (`{0}`) of `en`, in order.
fn parts(en: &str) -> Vec<Part<'_>> {
    let (mut parts, mut start, mut i) = (Vec::new(), 0, 0);
    while i < en.len() {
        let place = en[i..]
            .strip_prefix('{')
            .and_then(|r| r.split_once('}'))
            .and_then(|(n, _)| Some((n.parse::<usize>().ok()?, n.len() + 2)));
        match place {
            Some((n, len)) => {
                if start < i {
                    parts.push(Part::Words(&en[start..i]));
                }
                parts.push(Part::Value(n));
                i += len;
                start = i;
            }
            None => i += en[i..].chars().next().map_or(1, char::len_utf8),
        }
    }
    if start < en.len() {
        parts.push(Part::Words(&en[start..]));
    }
    parts
}

fn is_word(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// Whether phrase `en` stands at byte `at` of `text`: its end and its values.
///
/// A phrase starts and ends at word boundaries. A value is the shortest text up to the words
/// that follow it, never across a clause (`; `); a value at the end of the phrase reaches to
/// the next `; `, ` (`, `)`, `: ` or `, `; one at its start is one token. A value holds no
/// words (see [`neutral`]) unless it is quoted input or words of the catalogue.
fn matched(text: &str, at: usize, en: &str) -> Option<(usize, Vec<Taken>)> {
    let before = text[..at].chars().next_back();
    let parts = parts(en);
    let starts_with_value = matches!(parts.first(), Some(Part::Value(_)));
    let starts_word = en.chars().next().is_some_and(is_word) || starts_with_value;
    if starts_word
        && before.is_some_and(|c| is_word(c) || (starts_with_value && !c.is_whitespace()))
    {
        return None;
    }
    let mut values = vec![Taken::default(); parts.len()];
    let mut pos = at;
    for (k, part) in parts.iter().enumerate() {
        match *part {
            Part::Words(w) => {
                pos += text[pos..].starts_with(w).then_some(w.len())?;
            }
            Part::Value(n) => {
                let rest = &text[pos..];
                let len = match parts.get(k + 1) {
                    Some(Part::Words(next)) => rest.find(next)?,
                    _ => ["; ", " (", ")", ": ", ", "]
                        .iter()
                        .filter_map(|end| rest.find(end))
                        .min()
                        .unwrap_or(rest.len()),
                };
                let value = &rest[..len];
                let one_token = k > 0 || !value.contains(char::is_whitespace);
                // A value between quotes is input, copied whatever it says; any other is a
                // number or a symbol, or words of the catalogue (translated in their turn).
                let quoted =
                    k > 0 && matches!(parts[k - 1], Part::Words(w) if w.ends_with(['`', '"']));
                let known = quoted || neutral(value) || body_in(value, Lang::Sl).is_some();
                if value.is_empty() || value.contains("; ") || !one_token || !known {
                    return None;
                }
                *values.get_mut(n)? = Taken {
                    text: value.to_string(),
                    quoted,
                };
                pos += len;
            }
        }
    }
    let ends_word = en.chars().next_back().is_some_and(is_word);
    if ends_word && text[pos..].chars().next().is_some_and(is_word) {
        return None;
    }
    Some((pos, values))
}

/// A value taken from a message: its text, and whether it stood between quotes (input).
#[derive(Debug, Clone, Default)]
struct Taken {
    text: String,
    quoted: bool,
}

/// `words` with each `{n}` replaced by value `n`: input and numbers as they are, words of the
/// catalogue ("end of input", "relative tolerance 1e-10") in `lang`.
fn filled(words: &str, values: &[Taken], lang: Lang) -> String {
    parts(words)
        .into_iter()
        .map(|part| match part {
            Part::Words(w) => w.to_string(),
            Part::Value(n) => {
                let Some(value) = values.get(n) else {
                    return String::new();
                };
                if value.quoted || neutral(&value.text) {
                    value.text.clone()
                } else {
                    body_in(&value.text, lang).unwrap_or_else(|| value.text.clone())
                }
            }
        })
        .collect()
}

/// Whether `text` (between phrases) holds no word of any language: only values (numbers,
/// symbols such as `u_(p+1)`, `x(1,0)`, single letters), option names (`--rows`), names in
/// capitals (`CONTROL`, `CAGD_MAX_DEGREE`), quoted input (`` `NaN` ``, `"[0 1]"`) and
/// punctuation.
fn neutral(text: &str) -> bool {
    let mut unquoted = String::new();
    let mut quote = None;
    for c in text.chars() {
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if c == '`' || c == '"' => quote = Some(c),
            None => unquoted.push(c),
        }
    }
    unquoted.split_whitespace().all(|token| {
        let t = token.trim_matches(|c: char| !c.is_alphanumeric());
        t.chars().count() <= 1
            || token.starts_with('-')
            || t.contains(|c: char| c.is_ascii_digit() || c == '_')
            || !t.contains(char::is_lowercase)
    })
}

#[cfg(test)]
mod tests;
