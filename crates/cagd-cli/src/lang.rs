//! The languages of the readable steps (`--lang en|sl|cs`): English, Slovenian (the thesis and
//! the CAD notes) and Czech (the lecture notes).
//!
//! One table for every front end that shows steps to people: the command line labels each item
//! of its text output with it (`% de Casteljaujeva shema …` above `scheme:`), and the web page
//! reads the same table (`cagd_web::step_labels`) for its views. The table is keyed by the
//! names the operation layer gives its items (`scheme`, `rc`, `de_boor`, `insert_1`, …; a
//! numbered item `scheme_2` and a part `de_boor.alpha1` take the label of `scheme` and
//! `de_boor`), so the items themselves — what Octave's format, JSON and CSV write — keep their
//! names in every language. Fixed English phrases inside the readable layouts (the title of a
//! de Casteljau triangle) are translated by [`PHRASES`].
//!
//! The command line's own words — each subcommand's summary, each argument's label and hint —
//! are translated beside them, in [`forms`], for the page's forms.

pub mod forms;

/// A language of the readable output.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash, clap::ValueEnum)]
pub enum Lang {
    /// English.
    #[default]
    En,
    /// Slovenian (slovenščina), the language of the thesis and the CAD notes.
    Sl,
    /// Czech (čeština), the language of the lecture notes.
    Cs,
}

impl Lang {
    /// Every language, in the order of the table's columns.
    pub const ALL: [Lang; 3] = [Lang::En, Lang::Sl, Lang::Cs];

    /// The language's code (`en`, `sl`, `cs`).
    pub fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Sl => "sl",
            Lang::Cs => "cs",
        }
    }

    /// The language of a code such as `sl` or `cs-CZ` (case-insensitive), if it is one of ours.
    ///
    /// ```
    /// use cagd_cli::lang::Lang;
    /// assert_eq!(Lang::from_code("sl-SI"), Some(Lang::Sl));
    /// assert_eq!(Lang::from_code("CS"), Some(Lang::Cs));
    /// assert_eq!(Lang::from_code("de"), None);
    /// ```
    pub fn from_code(code: &str) -> Option<Lang> {
        let primary = code.split(['-', '_']).next()?.to_ascii_lowercase();
        Lang::ALL.into_iter().find(|l| l.code() == primary)
    }
}

/// A label in the three languages.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Words {
    /// English.
    pub en: &'static str,
    /// Slovenian.
    pub sl: &'static str,
    /// Czech.
    pub cs: &'static str,
}

impl Words {
    /// The words in `lang`.
    pub fn get(&self, lang: Lang) -> &'static str {
        match lang {
            Lang::En => self.en,
            Lang::Sl => self.sl,
            Lang::Cs => self.cs,
        }
    }
}

const fn w(en: &'static str, sl: &'static str, cs: &'static str) -> Words {
    Words { en, sl, cs }
}

/// The label of every step the operation layer names, by item name.
pub const STEP_LABELS: &[(&str, Words)] = &[
    ("result", w("the result", "rezultat", "výsledek")),
    ("t", w("the parameters t", "parametri t", "parametry t")),
    ("u", w("the parameters u", "parametri u", "parametry u")),
    ("v", w("the parameters v", "parametri v", "parametry v")),
    (
        "scheme",
        w(
            "the de Casteljau scheme b_i^r(t) = (1 − t) b_i^(r−1) + t b_(i+1)^(r−1)",
            "de Casteljaujeva shema b_i^r(t) = (1 − t) b_i^(r−1) + t b_(i+1)^(r−1)",
            "de Casteljauovo schéma b_i^r(t) = (1 − t) b_i^(r−1) + t b_(i+1)^(r−1)",
        ),
    ),
    (
        "r",
        w(
            "the levels b_i^r of the scheme",
            "nivoji b_i^r sheme",
            "úrovně b_i^r schématu",
        ),
    ),
    (
        "level",
        w(
            "a level of the patch's de Casteljau scheme",
            "nivo de Casteljaujeve sheme ploskve",
            "úroveň de Casteljauova schématu plochy",
        ),
    ),
    (
        "left",
        w(
            "the control points of the part before t",
            "kontrolne točke dela pred t",
            "řídicí body části před t",
        ),
    ),
    (
        "right",
        w(
            "the control points of the part after t",
            "kontrolne točke dela za t",
            "řídicí body části za t",
        ),
    ),
    (
        "control",
        w("the control points", "kontrolne točke", "řídicí body"),
    ),
    ("degree", w("the degree", "stopnja", "stupeň")),
    (
        "rc",
        w(
            "r_c: the surface ruled between the curves c1 and c2",
            "r_c: premonosna ploskev med krivuljama c1 in c2",
            "r_c: přímková plocha mezi křivkami c1 a c2",
        ),
    ),
    (
        "rd",
        w(
            "r_d: the surface ruled between the curves d1 and d2",
            "r_d: premonosna ploskev med krivuljama d1 in d2",
            "r_d: přímková plocha mezi křivkami d1 a d2",
        ),
    ),
    (
        "rcd",
        w(
            "r_cd: the bilinear interpolant of the four corners",
            "r_cd: bilinearna interpolacija štirih oglišč",
            "r_cd: bilineární interpolace čtyř rohů",
        ),
    ),
    (
        "g1",
        w(
            "g1: the Lagrange interpolant of the curves g(u_i, v)",
            "g1: Lagrangeva interpolacija krivulj g(u_i, v)",
            "g1: Lagrangeova interpolace křivek g(u_i, v)",
        ),
    ),
    (
        "g2",
        w(
            "g2: the Lagrange interpolant of the curves g(u, v_j)",
            "g2: Lagrangeva interpolacija krivulj g(u, v_j)",
            "g2: Lagrangeova interpolace křivek g(u, v_j)",
        ),
    ),
    (
        "g12",
        w(
            "g12: the tensor-product interpolant of the intersection points",
            "g12: tenzorska interpolacija presečišč",
            "g12: tenzorová interpolace průsečíků",
        ),
    ),
    (
        "de_boor",
        w(
            "de Boor's algorithm: the points d_i^r and the factors alpha",
            "de Boorov algoritem: točke d_i^r in faktorji alfa",
            "de Boorův algoritmus: body d_i^r a koeficienty alfa",
        ),
    ),
    (
        "basis",
        w(
            "the basis functions N_i,p(t)",
            "bazne funkcije N_i,p(t)",
            "bázové funkce N_i,p(t)",
        ),
    ),
    (
        "triangle",
        w(
            "the Cox–de Boor triangle N_i,j(t), degree j = 0 … p",
            "trikotnik Cox–de Boor N_i,j(t), stopnja j = 0 … p",
            "trojúhelník Cox–de Boor N_i,j(t), stupeň j = 0 … p",
        ),
    ),
    (
        "knots",
        w("the knot vector", "vozliščni vektor", "uzlový vektor"),
    ),
    (
        "knots_before",
        w(
            "the knot vector before the insertion",
            "vozliščni vektor pred vstavljanjem",
            "uzlový vektor před vložením",
        ),
    ),
    (
        "insert",
        w(
            "Boehm's step: one knot u inserted in its span, P'_i = (1 − α_i) P_(i−1) + α_i P_i",
            "Boehmov korak: vozel u vstavljen v svoj interval, P'_i = (1 − α_i) P_(i−1) + α_i P_i",
            "Boehmův krok: uzel u vložen do svého intervalu, P'_i = (1 − α_i) P_(i−1) + α_i P_i",
        ),
    ),
    (
        "span",
        w(
            "the knot span s: u_s ≤ t < u_(s+1), the knots numbered from 1",
            "vozliščni interval s: u_s ≤ t < u_(s+1), vozli oštevilčeni od 1",
            "uzlový interval s: u_s ≤ t < u_(s+1), uzly číslované od 1",
        ),
    ),
    (
        "alpha",
        w(
            "the factors α_i = (u − u_i)/(u_(i+p) − u_i), i = s−p+1 … s, the knots numbered from 1",
            "faktorji α_i = (u − u_i)/(u_(i+p) − u_i), i = s−p+1 … s, vozli oštevilčeni od 1",
            "koeficienty α_i = (u − u_i)/(u_(i+p) − u_i), i = s−p+1 … s, uzly číslované od 1",
        ),
    ),
    ("weights", w("the weights", "uteži", "váhy")),
    (
        "params",
        w(
            "the parameters of the points",
            "parametri točk",
            "parametry bodů",
        ),
    ),
    (
        "system",
        w(
            "the tridiagonal system of the tangents",
            "tridiagonalni sistem za tangente",
            "třídiagonální soustava pro tečné vektory",
        ),
    ),
    (
        "rhs",
        w(
            "the right-hand side of the system",
            "desna stran sistema",
            "pravá strana soustavy",
        ),
    ),
    (
        "tangents",
        w(
            "the tangents at the points",
            "tangente v točkah",
            "tečné vektory v bodech",
        ),
    ),
    (
        "segment",
        w(
            "a segment as Hermite data and as Bézier control points",
            "odsek kot Hermitovi podatki in kot Bézierove kontrolne točke",
            "segment jako Hermiteova data a jako Bézierovy řídicí body",
        ),
    ),
    (
        "hermite_basis",
        w(
            "the Hermite basis H_i(t)",
            "Hermitova baza H_i(t)",
            "Hermiteova báze H_i(t)",
        ),
    ),
    (
        "tangent",
        w(
            "the unit tangent",
            "enotski tangentni vektor",
            "jednotkový tečný vektor",
        ),
    ),
    (
        "normal",
        w("the principal normal", "glavna normala", "hlavní normála"),
    ),
    ("binormal", w("the binormal", "binormala", "binormála")),
    (
        "d1",
        w("the first derivative", "prvi odvod", "první derivace"),
    ),
    (
        "d2",
        w("the second derivative", "drugi odvod", "druhá derivace"),
    ),
    (
        "first",
        w("the first curve", "prva krivulja", "první křivka"),
    ),
    (
        "second",
        w("the second curve", "druga krivulja", "druhá křivka"),
    ),
    (
        "continuity",
        w(
            "the continuity at the joint",
            "zveznost v stiku",
            "spojitost ve spoji",
        ),
    ),
    ("verdict", w("the verdict", "ugotovitev", "závěr")),
    (
        "free_point",
        w(
            "the free control point",
            "prosta kontrolna točka",
            "volný řídicí bod",
        ),
    ),
    ("integral", w("the integral", "integral", "integrál")),
    (
        "antiderivative",
        w(
            "the antiderivative",
            "nedoločeni integral",
            "primitivní funkce",
        ),
    ),
    (
        "basis_integrals",
        w(
            "the integrals of the basis functions",
            "integrali baznih funkcij",
            "integrály bázových funkcí",
        ),
    ),
    (
        "T",
        w("the conversion matrix", "matrika prehoda", "matice převodu"),
    ),
    (
        "coefs",
        w(
            "the coefficients in the new form",
            "koeficienti v novi obliki",
            "koeficienty v novém tvaru",
        ),
    ),
    ("polynomial", w("the polynomial", "polinom", "polynom")),
];

/// Fixed English phrases of the readable step layouts, translated.
pub const PHRASES: &[Words] = &[
    w(
        "L: control points of the part before t (the diagonal b_0^r), R: of the part after t (the last row b_(n-r)^r)",
        "L: kontrolne točke dela pred t (diagonala b_0^r), R: dela za t (zadnja vrstica b_(n-r)^r)",
        "L: řídicí body části před t (diagonála b_0^r), R: části za t (poslední řádek b_(n-r)^r)",
    ),
    w(
        "de Casteljau scheme, degree",
        "de Casteljaujeva shema, stopnja",
        "de Casteljauovo schéma, stupeň",
    ),
];

/// The label of item `name` in `lang`: the name itself, else without a part (`de_boor.alpha1`)
/// or a trailing number (`scheme_2`, `insert_1`, `level_0`).
///
/// ```
/// use cagd_cli::lang::{label, Lang};
/// assert_eq!(label("rcd", Lang::Sl), Some("r_cd: bilinearna interpolacija štirih oglišč"));
/// assert_eq!(label("scheme_2", Lang::Cs), label("scheme", Lang::Cs));
/// assert_eq!(label("de_boor.alpha1", Lang::En), label("de_boor", Lang::En));
/// assert_eq!(label("frobnicate", Lang::En), None);
/// ```
pub fn label(name: &str, lang: Lang) -> Option<&'static str> {
    let find = |n: &str| {
        STEP_LABELS
            .iter()
            .find(|(key, _)| *key == n)
            .map(|(_, words)| words.get(lang))
    };
    let whole = name.split('.').next().unwrap_or(name);
    find(whole).or_else(|| {
        let base = whole.trim_end_matches(|c: char| c.is_ascii_digit());
        let base = base.strip_suffix('_').unwrap_or(base);
        find(base)
    })
}

/// `text` with the fixed English phrases of [`PHRASES`] in `lang`.
///
/// ```
/// use cagd_cli::lang::{phrases, Lang};
/// assert_eq!(
///     phrases("de Casteljau scheme, degree 3, t = 1/2", Lang::Sl),
///     "de Casteljaujeva shema, stopnja 3, t = 1/2"
/// );
/// ```
pub fn phrases(text: &str, lang: Lang) -> String {
    PHRASES.iter().fold(text.to_string(), |out, words| {
        out.replace(words.en, words.get(lang))
    })
}

/// The tables as JSON for the web page: `{"labels": {name: {en, sl, cs}}, "phrases": [{en, sl,
/// cs}]}`.
pub fn tables_json() -> serde_json::Value {
    let words = |w: &Words| serde_json::json!({ "en": w.en, "sl": w.sl, "cs": w.cs });
    let labels: serde_json::Map<String, serde_json::Value> = STEP_LABELS
        .iter()
        .map(|(name, w)| ((*name).to_string(), words(w)))
        .collect();
    serde_json::json!({
        "labels": labels,
        "phrases": PHRASES.iter().map(words).collect::<Vec<_>>(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_label_has_three_languages_and_distinct_names() {
        let mut names: Vec<&str> = STEP_LABELS.iter().map(|(n, _)| *n).collect();
        names.sort_unstable();
        let before = names.len();
        names.dedup();
        assert_eq!(names.len(), before, "a name twice in STEP_LABELS");
        for (name, w) in STEP_LABELS.iter() {
            assert!(
                !w.en.is_empty() && !w.sl.is_empty() && !w.cs.is_empty(),
                "{name}"
            );
        }
    }

    #[test]
    fn numbered_items_and_parts_take_their_base_label() {
        assert_eq!(label("insert_12", Lang::Sl), label("insert", Lang::Sl));
        assert_eq!(label("level_0", Lang::En), label("level", Lang::En));
        assert_eq!(label("triangle.p3", Lang::Cs), label("triangle", Lang::Cs));
        assert_eq!(label("g12", Lang::En).map(|s| &s[..4]), Some("g12:"));
    }
}
