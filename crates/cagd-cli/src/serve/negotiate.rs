//! What a client accepts: its content codings (`Accept-Encoding`) and the tags it already
//! holds (`If-None-Match`).

use std::collections::HashMap;

/// The content codings a client accepts (its `Accept-Encoding`), of those the server sends.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(super) struct Accepts {
    pub gzip: bool,
    pub brotli: bool,
}

impl Accepts {
    /// Parses `Accept-Encoding`: a coding is accepted when it is listed with a quality above
    /// 0, or when `*` is and the coding is not listed with `q=0`.
    pub fn parse(header: Option<&str>) -> Accepts {
        let mut listed: HashMap<String, bool> = HashMap::new();
        for item in header.unwrap_or("").split(',') {
            let mut parts = item.split(';');
            let name = parts.next().unwrap_or("").trim().to_ascii_lowercase();
            let q = parts
                .filter_map(|p| p.trim().strip_prefix("q="))
                .filter_map(|q| q.trim().parse::<f32>().ok())
                .next()
                .unwrap_or(1.0);
            let name = if name == "x-gzip" {
                "gzip".into()
            } else {
                name
            };
            if !name.is_empty() {
                listed.insert(name, q > 0.0);
            }
        }
        let star = listed.get("*").copied().unwrap_or(false);
        let accepted = |name: &str| listed.get(name).copied().unwrap_or(star);
        Accepts {
            gzip: accepted("gzip"),
            brotli: accepted("br"),
        }
    }
}

/// Whether an `If-None-Match` header names `tag` (or is `*`); weak tags compare by their
/// opaque part, as RFC 9110 asks for this header.
pub(super) fn none_match(header: &str, tag: &str) -> bool {
    header.split(',').map(str::trim).any(|t| {
        t == "*" || t.strip_prefix("W/").unwrap_or(t) == tag.strip_prefix("W/").unwrap_or(tag)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn accept_encoding_follows_the_qualities() {
        let a = |h: &str| Accepts::parse(Some(h));
        assert_eq!(
            a("gzip, deflate, br, zstd"),
            Accepts {
                gzip: true,
                brotli: true
            }
        );
        assert!(!a("gzip;q=0, br").gzip);
        assert!(a("*;q=0.5").gzip);
        assert!(!a("*, gzip;q=0").gzip);
        assert_eq!(a("identity"), Accepts::default());
        assert_eq!(Accepts::parse(None), Accepts::default());
        assert!(a("x-gzip").gzip);
    }

    #[test]
    fn if_none_match_compares_opaque_tags() {
        assert!(none_match("\"a\", \"b\"", "\"b\""));
        assert!(none_match("W/\"b\"", "\"b\""));
        assert!(none_match("*", "\"b\""));
        assert!(!none_match("\"a\"", "\"b\""));
    }
}
