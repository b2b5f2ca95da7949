//! The catalogue: the fixed phrases of the messages the page shows, by their English words,
//! in Slovenian and Czech. The wording is the program's (the core's errors, the operation
//! layer's checks and forms, the literal reader's, the command line's notes); a form the
//! operation layer or the command line exports as a constant is named by it, so the English
//! key is the owner's own text. Counts are written as "number of …: N" so that no Slovenian
//! or Czech ending depends on N.

use super::Phrase;
use cagd_ops::ops;

const fn p(en: &'static str, sl: &'static str, cs: &'static str) -> Phrase {
    Phrase { en, sl, cs }
}

/// Every phrase, in no particular order (the longest English match wins).
pub static PHRASES: &[Phrase] = &[
    // The clauses joined by the messages.
    p("; expected ", "; pričakovano: ", "; očekává se: "),
    // What the core's and the operation layer's words are about.
    p("knot vector", "vozliščni vektor", "uzlový vektor"),
    p(
        "knot vector along u",
        "vozliščni vektor v smeri u",
        "uzlový vektor ve směru u",
    ),
    p(
        "knot vector along v",
        "vozliščni vektor v smeri v",
        "uzlový vektor ve směru v",
    ),
    p("control points", "kontrolne točke", "řídicí body"),
    p(
        "control points along u",
        "kontrolne točke v smeri u",
        "řídicí body ve směru u",
    ),
    p(
        "control points along v",
        "kontrolne točke v smeri v",
        "řídicí body ve směru v",
    ),
    p(
        "knot domain [u_(p+1), u_(n+1)]",
        "definicijsko območje vozlov [u_(p+1), u_(n+1)]",
        "definiční obor uzlů [u_(p+1), u_(n+1)]",
    ),
    p("B-spline", "B-zlepek", "B-spline křivka"),
    p("NURBS curve", "krivulja NURBS", "křivka NURBS"),
    p("Bézier curve", "Bézierova krivulja", "Bézierova křivka"),
    p(
        "B-spline basis",
        "bazne funkcije B-zlepka",
        "bázové funkce B-spline",
    ),
    p("NURBS weights", "uteži NURBS", "váhy NURBS"),
    p(
        "NURBS surface weights",
        "uteži ploskve NURBS",
        "váhy plochy NURBS",
    ),
    p("degree", "stopnja", "stupeň"),
    p("samples N", "vzorci N", "vzorky N"),
    p("inserted knot", "vstavljeni vozel", "vkládaný uzel"),
    p("Lagrange nodes", "Lagrangeevi vozli", "Lagrangeovy uzly"),
    p(
        "Lagrange values",
        "vrednosti Lagrangeeve interpolacije",
        "hodnoty Lagrangeovy interpolace",
    ),
    p("column {0}", "stolpec {0}", "sloupec {0}"),
    p(
        "expected {0} columns (one per node), found {1} columns",
        "pričakovano število stolpcev je {0} (en na vozel), najdeno: {1}",
        "očekávaný počet sloupců je {0} (jeden na uzel), nalezeno: {1}",
    ),
    p("end of input", "konec vnosa", "konec vstupu"),
    // The core's errors (cagd::Error), after their "WHAT: ".
    p(
        "knot {0} ({1}) is below the knot before it ({2}); knots must be non-decreasing",
        "vozel {0} ({1}) je manjši od vozla pred njim ({2}); vozli morajo biti nepadajoči",
        "uzel {0} ({1}) je menší než uzel před ním ({2}); uzly musí být neklesající",
    ),
    p(
        "expected {0} knots (control points + degree + 1), got {1}",
        "pričakovano število vozlov je {0} (kontrolne točke + stopnja + 1), podano: {1}",
        "očekávaný počet uzlů je {0} (řídicí body + stupeň + 1), zadáno: {1}",
    ),
    p(
        "degree {0} needs at least {1} control point(s), got {2}",
        "za stopnjo {0} je najmanjše število kontrolnih točk {1}, podano: {2}",
        "pro stupeň {0} je nejmenší počet řídicích bodů {1}, zadáno: {2}",
    ),
    p(
        "expected at least {0} control point(s), got {1}",
        "najmanjše število kontrolnih točk je {0}, podano: {1}",
        "nejmenší počet řídicích bodů je {0}, zadáno: {1}",
    ),
    p(
        "expected at least {0} parameter value(s), got {1}",
        "najmanjše število vrednosti parametra je {0}, podano: {1}",
        "nejmenší počet hodnot parametru je {0}, zadáno: {1}",
    ),
    p(
        "interval [{0}, {1}] is empty (expected a < b)",
        "interval [{0}, {1}] je prazen (pričakovano a < b)",
        "interval [{0}, {1}] je prázdný (očekává se a < b)",
    ),
    p(
        "parameter {0} is outside the domain [{1}, {2}]",
        "parameter {0} je zunaj definicijskega območja [{1}, {2}]",
        "parametr {0} leží mimo definiční obor [{1}, {2}]",
    ),
    p(
        "weight {0} is {1}; weights must be positive",
        "utež {0} je {1}; uteži morajo biti pozitivne",
        "váha {0} je {1}; váhy musí být kladné",
    ),
    p(
        "expected {0} weights (one per control point), found {1}",
        "pričakovano število uteži je {0} (ena na kontrolno točko), najdeno: {1}",
        "očekávaný počet vah je {0} (jedna na řídicí bod), nalezeno: {1}",
    ),
    p(
        "value {0} is not finite ({1})",
        "vrednost {0} ni končna ({1})",
        "hodnota {0} není konečná ({1})",
    ),
    p(
        "value {0} is not a finite double ({1}): the input's magnitudes are too large (or too close together) for double precision",
        "vrednost {0} ni končno število v dvojni natančnosti ({1}): velikosti vnosa so za dvojno natančnost prevelike (ali preblizu skupaj)",
        "hodnota {0} není konečné číslo ve dvojité přesnosti ({1}): velikosti vstupu jsou pro dvojitou přesnost příliš velké (nebo příliš blízko u sebe)",
    ),
    p(
        "derivative order {0} exceeds the degree {1}",
        "red odvoda {0} presega stopnjo {1}",
        "řád derivace {0} překračuje stupeň {1}",
    ),
    p(
        "nodes {0} and {1} are equal ({2})",
        "vozla {0} in {1} sta enaka ({2})",
        "uzly {0} a {1} jsou si rovny ({2})",
    ),
    p(
        "nodes must increase, but node {0} ({1}) is above node {2} ({3})",
        "vozli morajo naraščati, a vozel {0} ({1}) je večji od vozla {2} ({3})",
        "uzly musí růst, ale uzel {0} ({1}) je větší než uzel {2} ({3})",
    ),
    // Limits: "WHAT: REQUESTED exceeds the limit of LIMIT", and how the command line raises it.
    p("exceeds the limit of {0}", "presega mejo {0}", "překračuje mez {0}"),
    p(
        "(raise it with {0} or {1})",
        "(zvišate jo z {0} ali {1})",
        "(zvýšíte ji pomocí {0} nebo {1})",
    ),
    // The operation layer's own checks.
    p(
        "N = {0} is too small",
        "N = {0} je premajhen",
        "N = {0} je příliš malé",
    ),
    p("order k = {0}", "red k = {0}", "řád k = {0}"),
    p(
        "given together with the degree",
        "podan skupaj s stopnjo",
        "zadán spolu se stupněm",
    ),
    p(
        "i = {0} exceeds the degree {1}",
        "i = {0} presega stopnjo {1}",
        "i = {0} překračuje stupeň {1}",
    ),
    p(
        "lies outside [{0}, {1}]; the curve is extrapolated there",
        "leži zunaj [{0}, {1}]; tam je krivulja ekstrapolirana",
        "leží mimo [{0}, {1}]; křivka je tam extrapolována",
    ),
    p(
        "lies outside [{0}, {1}]; the polynomials are extrapolated there",
        "leži zunaj [{0}, {1}]; tam so polinomi ekstrapolirani",
        "leží mimo [{0}, {1}]; polynomy jsou tam extrapolovány",
    ),
    // Boundary curves of a Coons patch that do not meet.
    p(
        "boundary curves do not meet at the corners ({0})",
        "robne krivulje se ne stikajo v ogliščih ({0})",
        "hraniční křivky se nestýkají v rozích ({0})",
    ),
    p(
        "at {0} {1} and {2} differ by {3} (allowed {4})",
        "pri {0} {1} in {2}: razlika {3} (dovoljeno {4})",
        "v {0} {1} a {2}: rozdíl {3} (povoleno {4})",
    ),
    p(
        "relative tolerance {0}",
        "relativna toleranca {0}",
        "relativní tolerance {0}",
    ),
    p(
        "absolute tolerance {0}",
        "absolutna toleranca {0}",
        "absolutní tolerance {0}",
    ),
    p("exact equality", "točna enakost", "přesná rovnost"),
    p(
        ops::coons::BOUNDARY_FORM,
        "štiri robne krivulje, ki se stikajo v ogliščih: c1(0)=d1(0), c1(1)=d2(0), c2(0)=d1(1), c2(1)=d2(1)",
        "čtyři hraniční křivky, které se stýkají v rozích: c1(0)=d1(0), c1(1)=d2(0), c2(0)=d1(1), c2(1)=d2(1)",
    ),
    // The literal reader's errors (cagd_octave), after their "column N: ".
    p(
        "`{0}` is not accepted",
        "`{0}` ni dovoljeno",
        "`{0}` není přípustné",
    ),
    p(
        "finite real values",
        "končne realne vrednosti",
        "konečné reálné hodnoty",
    ),
    p(
        "row {0} has {1} column(s), expected {2}",
        "vrstica {0} ima število stolpcev {1}, pričakovano: {2}",
        "řádek {0} má počet sloupců {1}, očekává se: {2}",
    ),
    p(
        "expected `{0}` to close the `{1}` opened at column {2}, found {3}",
        "pričakovan je `{0}`, ki zapre `{1}` iz stolpca {2}, najdeno: {3}",
        "očekává se `{0}`, které uzavře `{1}` ze sloupce {2}, nalezeno: {3}",
    ),
    p(
        "unknown variable `{0}`",
        "neznana spremenljivka `{0}`",
        "neznámá proměnná `{0}`",
    ),
    p(
        "unknown function `{0}`",
        "neznana funkcija `{0}`",
        "neznámá funkce `{0}`",
    ),
    p("division by zero", "deljenje z nič", "dělení nulou"),
    // The command line's note on how a matrix was read.
    p(
        "read as {0} points in {1}-D, one per column; --rows if each row is a point",
        "prebrano kot točke v {1}-D, ena na stolpec (število točk: {0}); --rows, če je vsaka vrstica točka",
        "přečteno jako body v {1}-D, jeden na sloupec (počet bodů: {0}); --rows, je-li každý řádek bodem",
    ),
    p(
        "read as {0} point in {1}-D, one per column; --rows if each row is a point",
        "prebrano kot točka v {1}-D, ena na stolpec (število točk: {0}); --rows, če je vsaka vrstica točka",
        "přečteno jako bod v {1}-D, jeden na sloupec (počet bodů: {0}); --rows, je-li každý řádek bodem",
    ),
    p(
        "read as {0} points in {1}-D, one per row (--rows); leave out --rows if each column is a point",
        "prebrano kot točke v {1}-D, ena na vrstico (--rows; število točk: {0}); brez --rows, če je vsak stolpec točka",
        "přečteno jako body v {1}-D, jeden na řádek (--rows; počet bodů: {0}); bez --rows, je-li každý sloupec bodem",
    ),
    // The page's own check of a view's points.
    p(
        "{0} numbers do not make points of {1} coordinates",
        "števil ({0}) ni mogoče razdeliti na točke s {1} koordinatami",
        "čísla ({0}) nelze rozdělit na body o {1} souřadnicích",
    ),
    // The forms after "expected".
    p(
        cagd_ops::knots::KNOTS_FORM,
        "n + p + 1 nepadajočih vozlov za n kontrolnih točk stopnje p (n ≥ p + 1), pri čemer u_(p+1) < u_(n+1)",
        "n + p + 1 neklesajících uzlů pro n řídicích bodů stupně p (n ≥ p + 1), přičemž u_(p+1) < u_(n+1)",
    ),
    p(
        cagd_ops::knots::BASIS_KNOTS_FORM,
        "n + p + 1 nepadajočih vozlov za n ≥ 1 baznih funkcij stopnje p, ne vseh enakih",
        "n + p + 1 neklesajících uzlů pro n ≥ 1 bázových funkcí stupně p, ne všech stejných",
    ),
    p(
        cagd_ops::knots::DOMAIN_FORM,
        "parametri v definicijskem območju [u_(p+1), u_(n+1)] vozliščnega vektorja",
        "parametry v definičním oboru [u_(p+1), u_(n+1)] uzlového vektoru",
    ),
    p(
        "parameters between the first and the last knot",
        "parametri med prvim in zadnjim vozlom",
        "parametry mezi prvním a posledním uzlem",
    ),
    p(
        "knots strictly inside the domain [u_(p+1), u_(n+1)], each at most p + 1 times in the result",
        "vozli strogo znotraj definicijskega območja [u_(p+1), u_(n+1)], vsak v rezultatu največ (p + 1)-krat",
        "uzly ostře uvnitř definičního oboru [u_(p+1), u_(n+1)], každý ve výsledku nejvýše (p + 1)-krát",
    ),
    p(
        "one positive weight per control point",
        "ena pozitivna utež na kontrolno točko",
        "jedna kladná váha na řídicí bod",
    ),
    p(
        cagd_cli::PARAMS_FORM,
        "število, seznam, npr. \"[0 0.25 0.5]\", ali razpon, npr. 0:0.1:1",
        "číslo, seznam, např. \"[0 0.25 0.5]\", nebo rozsah, např. 0:0.1:1",
    ),
    p(
        cagd_ops::params::PARAMS_FORM,
        "število, seznam, npr. [0 0.25 0.5], ali razpon, npr. 0:0.1:1",
        "číslo, seznam, např. [0 0.25 0.5], nebo rozsah, např. 0:0.1:1",
    ),
    p(
        cagd_cli::MATRIX_FORM,
        "matrika v zapisu Octave, npr. \"[0 0 0; 1 2 0]'\", številska besedilna datoteka ali datoteka CSV ali - za standardni vhod",
        "matice v zápisu Octave, např. \"[0 0 0; 1 2 0]'\", číselný textový soubor nebo soubor CSV, nebo - pro standardní vstup",
    ),
    p(
        ops::BEZIER_CONTROL_FORM,
        "kontrolne točke b_0..b_n, ena na stolpec",
        "řídicí body b_0..b_n, jeden na sloupec",
    ),
    p(
        ops::BSPLINE_CONTROL_FORM,
        "kontrolne točke P_0..P_(n−1), ena na stolpec",
        "řídicí body P_0..P_(n−1), jeden na sloupec",
    ),
    p(
        ops::LAGRANGE_NODES_FORM,
        "različni končni vozli, vsaj eden",
        "různé konečné uzly, alespoň jeden",
    ),
    p(
        ops::LAGRANGE_VALUES_FORM,
        "en stolpec vrednosti na vozel (d × (m+1))",
        "jeden sloupec hodnot na uzel (d × (m+1))",
    ),
    p(
        "a lower degree (fewer control points or nodes)",
        "nižja stopnja (manj kontrolnih točk ali vozlov)",
        "nižší stupeň (méně řídicích bodů nebo uzlů)",
    ),
    p(
        "an integer N with 2 ≤ N ≤ {0} (N equally spaced samples)",
        "celo število N, 2 ≤ N ≤ {0} (N enakomerno razporejenih vzorcev)",
        "celé číslo N, 2 ≤ N ≤ {0} (N rovnoměrně rozložených vzorků)",
    ),
    p(
        "an order k ≥ 1 (the degree p = k − 1)",
        "red k ≥ 1 (stopnja p = k − 1)",
        "řád k ≥ 1 (stupeň p = k − 1)",
    ),
    p(
        "the degree p or the order k = p + 1, not both",
        "stopnja p ali red k = p + 1, ne oboje",
        "stupeň p nebo řád k = p + 1, ne obojí",
    ),
    p(
        "at least {0} control points, one point of at least one coordinate per column",
        "najmanjše število kontrolnih točk {0}, v vsakem stolpcu ena točka z vsaj eno koordinato",
        "nejmenší počet řídicích bodů {0}, v každém sloupci jeden bod s alespoň jednou souřadnicí",
    ),
    p(
        "an index 0 ≤ i ≤ n",
        "indeks 0 ≤ i ≤ n",
        "index 0 ≤ i ≤ n",
    ),
    p(
        "control points given coordinate by coordinate, one point after the other",
        "kontrolne točke po koordinatah, točka za točko",
        "řídicí body po souřadnicích, bod za bodem",
    ),
    p(
        ops::hermite::VECTOR_FORM,
        "točka ali vektor (d vrednosti)",
        "bod nebo vektor (d hodnot)",
    ),
];
