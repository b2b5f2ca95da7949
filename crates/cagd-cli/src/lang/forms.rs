//! The command line's own words in Slovenian and Czech: the summary of every subcommand and
//! the label and hint of every argument, for the forms the web page builds from the clap
//! definitions ([`crate::schema`]).
//!
//! The English is clap's help, written once beside each argument; this table holds only its
//! translations, keyed by subcommand and argument id. An entry for [`EVERY`] subcommand (or
//! for several) stands for an argument whose English help is the same wherever it appears; a
//! test checks that, and that every argument of every subcommand has both languages, so a new
//! subcommand or argument without its translations fails. Option names (`--t`, `CONTROL`)
//! and the sources' symbols stay as they are; the vocabulary is the sources': the thesis and
//! the CAD notes in Slovenian (kontrolne točke, vozliščni vektor, utež), the lecture notes in
//! Czech (řídicí body, uzlový vektor, váha).

use super::Lang;

/// A label (a few words naming the argument) and a hint (its form, default and use).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Help {
    /// The label.
    pub label: &'static str,
    /// The hint.
    pub hint: &'static str,
}

/// The Slovenian and Czech words of one argument.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ArgWords {
    /// The subcommands the entry is for ([`EVERY`]: any subcommand with the argument).
    pub commands: &'static [&'static str],
    /// The argument's clap id.
    pub id: &'static str,
    /// Slovenian.
    pub sl: Help,
    /// Czech.
    pub cs: Help,
}

/// A text in Slovenian and Czech.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Translated {
    /// Slovenian.
    pub sl: &'static str,
    /// Czech.
    pub cs: &'static str,
}

/// The subcommands of an entry that stands for an argument everywhere it appears.
pub const EVERY: &[&str] = &[];

const fn arg(
    commands: &'static [&'static str],
    id: &'static str,
    sl: [&'static str; 2],
    cs: [&'static str; 2],
) -> ArgWords {
    ArgWords {
        commands,
        id,
        sl: Help {
            label: sl[0],
            hint: sl[1],
        },
        cs: Help {
            label: cs[0],
            hint: cs[1],
        },
    }
}

const fn about(
    command: &'static str,
    sl: &'static str,
    cs: &'static str,
) -> (&'static str, Translated) {
    (command, Translated { sl, cs })
}

/// The summary of every subcommand (clap's `about`), by name.
pub static SUMMARIES: &[(&str, Translated)] = &[
    about(
        "thesis",
        "Ponovi vse rešene primere in izračune iz prilog zaključne naloge, s koraki in slikami",
        "Zopakuje všechny řešené příklady a výpočty z příloh závěrečné práce, s kroky a obrázky",
    ),
    about(
        "course",
        "Ponovi rešene primere zapiskov predavanj (zapiski o matrični obliki, češki zapiski predavanj, izpiski CAD)",
        "Zopakuje řešené příklady studijních textů (poznámky o maticovém tvaru, skripta, poznámky CAD)",
    ),
    about(
        "decasteljau",
        "Točke Bézierove krivulje z de Casteljaujevim algoritmom (zaključna naloga, algoritem 1)",
        "Body Bézierovy křivky de Casteljauovým algoritmem (závěrečná práce, algoritmus 1)",
    ),
    about(
        "bezier-patch",
        "Točke Bézierove ploskve (zaključna naloga, algoritmi 2–4, ploskevB/bilinearna/tenzor)",
        "Body Bézierovy plochy (závěrečná práce, algoritmy 2–4, ploskevB/bilinearna/tenzor)",
    ),
    about(
        "coons",
        "Coonsova ploskev z bilinearnim ujemanjem x = r_c + r_d - r_cd (zaključna naloga 4.1, algoritma 5 in 6)",
        "Bilineárně sešitá Coonsova plocha x = r_c + r_d - r_cd (závěrečná práce 4.1, algoritmy 5 a 6)",
    ),
    about(
        "coons-bicubic",
        "Coonsova ploskev z bikubičnim ujemanjem, s prečnimi odvodi na robovih (zaključna naloga 4.3)",
        "Bikubicky sešitá Coonsova plocha s derivacemi napříč hranicí (závěrečná práce 4.3)",
    ),
    about(
        "discrete-coons",
        "Diskretna Coonsova ploskev: notranje kontrolne točke iz roba kontrolne mreže",
        "Diskrétní Coonsova plocha: vnitřní řídicí body z okraje řídicí sítě",
    ),
    about(
        "gordon",
        "Gordonova ploskev g = g1 + g2 - g12 mreže krivulj (zaključna naloga 4.5, algoritem 7)",
        "Gordonova plocha g = g1 + g2 - g12 sítě křivek (závěrečná práce 4.5, algoritmus 7)",
    ),
    about(
        "lagrange",
        "Lagrangeevi bazni polinomi ali polinom, ki interpolira vrednosti v vozlih",
        "Lagrangeovy bázové polynomy nebo polynom interpolující hodnoty v uzlech",
    ),
    about(
        "bernstein",
        "Vrednosti Bernsteinovih polinomov B_i^n(t)",
        "Hodnoty Bernsteinových polynomů B_i^n(t)",
    ),
    about(
        "derivative",
        "Kontrolne točke (in vrednosti) r-tega odvoda Bézierove krivulje",
        "Řídicí body (a hodnoty) r-té derivace Bézierovy křivky",
    ),
    about(
        "spline",
        "Interpolacijski kubični zlepek (češki zapiski predavanj): tangente v točkah in vzorci krivulje",
        "Interpolační kubický spline (skripta): tečné vektory v bodech a vzorky křivky",
    ),
    about(
        "hermite",
        "Hermitova (Fergusonova) kubika iz krajišč in tangent v krajiščih (češki zapiski predavanj)",
        "Hermitova (Fergusonova) kubika z krajních bodů a krajních tečných vektorů (skripta)",
    ),
    about(
        "bspline",
        "B-zlepek z de Boorovim algoritmom (izpiski CAD in češki zapiski predavanj)",
        "B-spline křivka de Boorovým algoritmem (poznámky CAD a skripta)",
    ),
    about(
        "nurbs",
        "Krivulja NURBS (izpiski CAD): racionalni B-zlepek z utežmi",
        "Křivka NURBS (poznámky CAD): racionální B-spline s vahami",
    ),
    about(
        "convert",
        "Pretvorba krivulje med Hermitovo, Bézierovo, B-zlepkovo, monomsko in algebrsko obliko",
        "Převod křivky mezi Hermitovým, Bézierovým, B-spline, monomiálním a algebraickým tvarem",
    ),
    about(
        "elevate",
        "Zvišanje stopnje Bézierove krivulje (ali odprtega B-zlepka), ne da bi se krivulja spremenila",
        "Zvýšení stupně Bézierovy křivky (nebo otevřené B-spline křivky), aniž se křivka změní",
    ),
    about(
        "subdivide",
        "Delitev Bézierove krivulje pri t na dve Bézierovi krivulji (de Casteljaujeva delitev)",
        "Rozdělení Bézierovy křivky v t na dvě Bézierovy křivky (de Casteljauovo dělení)",
    ),
    about(
        "insert-knot",
        "Vstavljanje vozlov v B-zlepek ali krivuljo NURBS (Boehmov algoritem)",
        "Vkládání uzlů do B-spline křivky nebo křivky NURBS (Boehmův algoritmus)",
    ),
    about(
        "bspline-basis",
        "Bazne funkcije B-zlepka N_i,p(u) vozliščnega vektorja (Cox–de Boor)",
        "Bázové funkce B-spline N_i,p(u) uzlového vektoru (Cox–de Boor)",
    ),
    about(
        "continuity",
        "Zveznost (C0, C1, G1, C2) v stiku dveh Bézierovih krivulj; prosta točka stika C1",
        "Spojitost (C0, C1, G1, C2) ve spoji dvou Bézierových křivek; volný bod spoje C1",
    ),
    about(
        "curvature",
        "Ukrivljenost κ = |x′ × x″| / |x′|³ in Frenetovo ogrodje Bézierove krivulje, B-zlepka ali krivulje NURBS",
        "Křivost κ = |x′ × x″| / |x′|³ a Frenetův repér Bézierovy, B-spline nebo NURBS křivky",
    ),
    about(
        "integrate",
        "Nedoločeni in določeni integral Bernsteinovih polinomov, Bézierovih krivulj ali B-zlepkov",
        "Primitivní funkce a určitý integrál Bernsteinových polynomů, Bézierových nebo B-spline křivek",
    ),
    about(
        "ruled",
        "Premonosna ploskev (1 − v)·¹x(u) + v·²x(u) med dvema krivuljama (češki zapiski predavanj)",
        "Přímková plocha (1 − v)·¹x(u) + v·²x(u) mezi dvěma křivkami (skripta)",
    ),
    about(
        "ferguson",
        "Hermitova bikubična (Fergusonova) ploskev iz oglišč, tangent in mešanih odvodov",
        "Hermitova bikubická (Fergusonova) plocha z rohových bodů, tečných vektorů a zkrutů",
    ),
    about(
        "bspline-surface",
        "Tenzorska B-zlepkovna ploskev (izpiski CAD, češki zapiski predavanj)",
        "Tenzorová B-spline plocha (poznámky CAD, skripta)",
    ),
    about(
        "nurbs-surface",
        "Tenzorska ploskev NURBS (izpiski CAD): uteži in homogene točke",
        "Tenzorová plocha NURBS (poznámky CAD): váhy a homogenní body",
    ),
    about(
        "circle",
        "Krožnica kot točna krivulja NURBS (nrbcirc iz octave-nurbs)",
        "Kružnice jako přesná křivka NURBS (nrbcirc z octave-nurbs)",
    ),
    about(
        "arc",
        "Krožni lok kot točna krivulja NURBS (nrbcirc iz octave-nurbs s koti)",
        "Kruhový oblouk jako přesná křivka NURBS (nrbcirc z octave-nurbs s úhly)",
    ),
    about(
        "curve",
        "Vzorci krivulje, podane z izrazom v njenem parametru, kot krivulje zapiše zaključna naloga",
        "Vzorky křivky zadané výrazem v jejím parametru, jak křivky zapisuje závěrečná práce",
    ),
    about(
        "surface",
        "Vzorci ploskve, podane z izrazom v u in v, na mreži",
        "Vzorky plochy zadané výrazem v u a v, na mřížce",
    ),
    about(
        "serve",
        "Ponudi spletno stran (vse konstrukcije, v brskalniku) na localhost",
        "Poskytne webovou stránku (všechny konstrukce, v prohlížeči) na localhost",
    ),
    about(
        "script",
        "Zažene podatkovni skript Octave v slogu zaključne naloge in izpiše spremenljivke, ki jih določi",
        "Spustí datový skript Octave ve stylu závěrečné práce a vypíše proměnné, které definuje",
    ),
];

/// The subcommands whose `--t` is a curve's parameters, as any curve's.
const CURVE_T: &[&str] = &[
    "decasteljau",
    "lagrange",
    "bernstein",
    "hermite",
    "bspline",
    "nurbs",
    "bspline-basis",
    "curvature",
    "circle",
    "arc",
    "curve",
];
/// The subcommands whose `--n` samples a surface's u and v.
const SURFACE_N: &[&str] = &[
    "bezier-patch",
    "coons",
    "coons-bicubic",
    "gordon",
    "ruled",
    "ferguson",
    "bspline-surface",
    "nurbs-surface",
    "surface",
];
/// The subcommands whose `--n` samples [0, 1] as the thesis's N.
const UNIT_N: &[&str] = &[
    "bernstein",
    "hermite",
    "curvature",
    "circle",
    "arc",
    "curve",
];
/// The B-spline subcommands whose `--degree` is the degree p (default 3).
const SPLINE_DEGREE: &[&str] = &["bspline", "nurbs", "insert-knot", "bspline-basis"];
/// The surfaces given by a net or by `--x`, `--y`, `--z`.
const SPLINE_SURFACES: &[&str] = &["bspline-surface", "nurbs-surface"];

/// The words of every argument of every subcommand, by subcommand and argument id (an entry
/// for several subcommands stands for one English help).
pub static ARGUMENTS: &[ArgWords] = &[
    // Shared by every subcommand that has them.
    arg(
        EVERY,
        "rows",
        [
            "Točke so vrstice vhodnih matrik",
            "kot jih pišejo zapiski predavanj (privzeto: stolpci, kot v zaključni nalogi)",
        ],
        [
            "Body jsou řádky vstupních matic",
            "jak je píší skripta a poznámky (výchozí: sloupce, jako v závěrečné práci)",
        ],
    ),
    arg(
        EVERY,
        "columns",
        [
            "Točke so stolpci vhodnih matrik",
            "kot jih piše zaključna naloga (privzeto, a izrecno: brez opombe o usmerjenosti)",
        ],
        [
            "Body jsou sloupce vstupních matic",
            "jak je píše závěrečná práce (výchozí, ale výslovně: bez poznámky o orientaci)",
        ],
    ),
    arg(
        EVERY,
        "steps",
        [
            "Izpiše tudi vmesne korake algoritma",
            "vmesni rezultati, npr. de Casteljaujeva shema, vsak z oznako v izbranem jeziku",
        ],
        [
            "Vypíše také mezikroky algoritmu",
            "mezivýsledky, např. de Casteljauovo schéma, každý s popiskem ve zvoleném jazyce",
        ],
    ),
    arg(
        EVERY,
        "script",
        [
            "Najprej se izvede podatkovni skript Octave FILE (prirejanja in zanke for, kot v prilogah zaključne naloge)",
            "njegove spremenljivke so na voljo v drugih argumentih; `N` dobi vrednost `--n`, če je podan",
        ],
        [
            "Nejprve se spustí datový skript Octave FILE (přiřazení a cykly for, jako v přílohách závěrečné práce)",
            "jeho proměnné lze použít v ostatních argumentech; `N` má hodnotu `--n`, je-li zadán",
        ],
    ),
    arg(
        EVERY,
        "format",
        [
            "Oblika izpisa",
            "text za branje; octave, csv in json za nadaljnjo obdelavo",
        ],
        [
            "Formát výstupu",
            "text ke čtení; octave, csv a json pro další zpracování",
        ],
    ),
    arg(
        EVERY,
        "exact",
        [
            "Računa v točni racionalni aritmetiki in izpiše ulomke, kot je 7/2 (decimalni vhodi se preberejo točno: 0.2 je 1/5)",
            "samo za racionalne konstrukcije in izraze",
        ],
        [
            "Počítá v přesné racionální aritmetice a vypisuje zlomky jako 7/2 (desetinné vstupy se čtou přesně: 0.2 je 1/5)",
            "jen pro racionální konstrukce a výrazy",
        ],
    ),
    arg(
        EVERY,
        "output",
        [
            "Zapiše rezultat v FILE (atomarno) namesto na standardni izhod (`-` je standardni izhod)",
            "obstoječa FILE mora biti navadna datoteka: FIFO, naprava ali mapa se zavrne, nikoli nadomesti",
        ],
        [
            "Zapíše výsledek do FILE (atomicky) místo na standardní výstup (`-` je standardní výstup)",
            "existující FILE musí být obyčejný soubor: FIFO, zařízení nebo složka se odmítne, nikdy nepřepíše",
        ],
    ),
    arg(
        EVERY,
        "digits",
        [
            "Število veljavnih mest v besedilni obliki (1 do 17; privzeto 15, kar skrije zaokrožitvene napake, kot je 0.30000000000000004)",
            "oblike octave, csv in json ohranijo vse bite",
        ],
        [
            "Počet platných číslic v textovém formátu (1 až 17; výchozí 15, což skryje zaokrouhlovací chyby jako 0.30000000000000004)",
            "formáty octave, csv a json zachovají všechny bity",
        ],
    ),
    arg(
        EVERY,
        "lang",
        [
            "Jezik oznak berljivih korakov",
            "en, sl (slovenščina, zaključna naloga in izpiski CAD) ali cs (češčina, češki zapiski predavanj); vsak element besedilne oblike dobi nad seboj vrstico `% oznaka`, elementi obdržijo svoja imena (druge oblike so v vseh jezikih enake); sprejme se tudi pred podukazom",
        ],
        [
            "Jazyk popisků čitelných kroků",
            "en, sl (slovinština, závěrečná práce a poznámky CAD) nebo cs (čeština, skripta); každá položka textového formátu dostane nad sebou řádek `% popisek`, položky si ponechají jména (ostatní formáty jsou ve všech jazycích stejné); lze zadat i před podpříkazem",
        ],
    ),
    arg(
        EVERY,
        "plot",
        [
            "Nariše rezultat v FILE.svg ali FILE.png",
            "obliko določi končnica; `-` zapiše SVG na standardni izhod, rezultat pa gre z -o drugam",
        ],
        [
            "Nakreslí výsledek do FILE.svg nebo FILE.png",
            "formát určí přípona; `-` zapíše SVG na standardní výstup a výsledek se pošle pomocí -o jinam",
        ],
    ),
    arg(
        EVERY,
        "mesh",
        [
            "Zapiše ploskev kot mrežo trikotnikov v FILE.stl (binarno), FILE.obj ali FILE.ply (ASCII)",
            "obliko določi končnica; `-` zapiše OBJ na standardni izhod, rezultat pa gre z -o drugam",
        ],
        [
            "Zapíše plochu jako trojúhelníkovou síť do FILE.stl (binárně), FILE.obj nebo FILE.ply (ASCII)",
            "formát určí přípona; `-` zapíše OBJ na standardní výstup a výsledek se pošle pomocí -o jinam",
        ],
    ),
    arg(
        EVERY,
        "list",
        [
            "Izpiše ploskev po eno točko v vrstici, `u v x y z`",
            "matrika z eno vrstico na točko mreže, u se spreminja najpočasneje, namesto mreže nu×nv×d",
        ],
        [
            "Vypíše plochu po jednom bodu na řádek, `u v x y z`",
            "matice s jedním řádkem na bod mřížky, u se mění nejpomaleji, místo mřížky nu×nv×d",
        ],
    ),
    arg(
        EVERY,
        "u",
        [
            "Parametri u",
            "število, seznam \"[0 0.5 1]\" ali razpon 0:0.1:1 (privzeto: --n vzorcev)",
        ],
        [
            "Parametry u",
            "číslo, seznam \"[0 0.5 1]\" nebo rozsah 0:0.1:1 (výchozí: --n vzorků)",
        ],
    ),
    arg(
        EVERY,
        "v",
        [
            "Parametri v",
            "število, seznam ali razpon (privzeto: --n vzorcev)",
        ],
        [
            "Parametry v",
            "číslo, seznam nebo rozsah (výchozí: --n vzorků)",
        ],
    ),
    arg(
        EVERY,
        "c1",
        [
            "Robna krivulja c1 = x(u,0)",
            "izraz v u, npr. \"[u;0;u-u^2]\", Bézierove kontrolne točke ali bezier(P), bspline(P, U), nurbs(P, W, U)",
        ],
        [
            "Hraniční křivka c1 = x(u,0)",
            "výraz v u, např. \"[u;0;u-u^2]\", Bézierovy řídicí body nebo bezier(P), bspline(P, U), nurbs(P, W, U)",
        ],
    ),
    arg(
        EVERY,
        "c2",
        [
            "Robna krivulja c2 = x(u,1)",
            "v spremenljivki u, oblika kot pri --c1",
        ],
        [
            "Hraniční křivka c2 = x(u,1)",
            "v proměnné u, tvar jako u --c1",
        ],
    ),
    arg(
        EVERY,
        "d1",
        [
            "Robna krivulja d1 = x(0,v)",
            "v spremenljivki v, oblika kot pri --c1",
        ],
        [
            "Hraniční křivka d1 = x(0,v)",
            "v proměnné v, tvar jako u --c1",
        ],
    ),
    arg(
        EVERY,
        "d2",
        [
            "Robna krivulja d2 = x(1,v)",
            "v spremenljivki v, oblika kot pri --c1",
        ],
        [
            "Hraniční křivka d2 = x(1,v)",
            "v proměnné v, tvar jako u --c1",
        ],
    ),
    arg(
        EVERY,
        "samples",
        [
            "Krivulje, podane s podatki, so vzorci krivulje",
            "matrika iz --script ali podatkovna datoteka: en stolpec na vrednost parametra (u ali v iz skripta, sicer linspace(0,1,N)), ne Bézierove kontrolne točke",
        ],
        [
            "Křivky zadané daty jsou vzorky křivky",
            "matice z --script nebo datový soubor: jeden sloupec na hodnotu parametru (u nebo v ze skriptu, jinak linspace(0,1,N)), ne Bézierovy řídicí body",
        ],
    ),
    // The thesis and the course.
    arg(
        &["thesis"],
        "out",
        ["Mapa za slike in mreže trikotnikov", "če mape ni, se ustvari"],
        ["Složka pro obrázky a trojúhelníkové sítě", "pokud složka neexistuje, vytvoří se"],
    ),
    arg(
        &["course"],
        "out",
        ["Mapa za slike", "če mape ni, se ustvari"],
        ["Složka pro obrázky", "pokud složka neexistuje, vytvoří se"],
    ),
    // Bézier curves.
    arg(
        &["decasteljau"],
        "control",
        [
            "Kontrolne točke b_0..b_n",
            "matrika v zapisu Octave, podatkovna datoteka (FILE ali FILE.txt:NAME za datoteko Octave save -text) ali - za standardni vhod; ena točka na stolpec",
        ],
        [
            "Řídicí body b_0..b_n",
            "matice v zápisu Octave, datový soubor (FILE nebo FILE.txt:NAME pro soubor Octave save -text) nebo - pro standardní vstup; jeden bod na sloupec",
        ],
    ),
    arg(
        CURVE_T,
        "t",
        [
            "Parametri krivulje",
            "število, seznam \"[0 0.25 0.5]\" ali razpon 0:0.1:1",
        ],
        [
            "Parametry křivky",
            "číslo, seznam \"[0 0.25 0.5]\" nebo rozsah 0:0.1:1",
        ],
    ),
    arg(
        &["decasteljau"],
        "interval",
        [
            "Parametrski interval [a, b] krivulje (zaključna naloga §2.3.2)",
            "npr. --interval 2,5: uteži vsakega koraka sta (b − t)/(b − a) in (t − a)/(b − a); --n vzorči [a, b]",
        ],
        [
            "Parametrický interval [a, b] křivky (závěrečná práce §2.3.2)",
            "např. --interval 2,5: váhy každého kroku jsou (b − t)/(b − a) a (t − a)/(b − a); --n vzorkuje [a, b]",
        ],
    ),
    arg(
        &["decasteljau"],
        "n",
        [
            "Vzorči v linspace(0,1,N), kot N v zaključni nalogi",
            "preslikano na --interval, če je podan",
        ],
        [
            "Vzorkuje v linspace(0,1,N), jako N v závěrečné práci",
            "zobrazeno na --interval, je-li zadán",
        ],
    ),
    arg(
        UNIT_N,
        "n",
        ["Vzorči v linspace(0,1,N)", "kot N v zaključni nalogi"],
        ["Vzorkuje v linspace(0,1,N)", "jako N v závěrečné práci"],
    ),
    arg(
        SURFACE_N,
        "n",
        ["Vzorči u in v v linspace(0,1,N)", "kot N v zaključni nalogi"],
        ["Vzorkuje u a v v linspace(0,1,N)", "jako N v závěrečné práci"],
    ),
    // Bézier patches.
    arg(
        &["bezier-patch"],
        "net",
        [
            "Kontrolna mreža",
            "stisnjena (m+1)×3(n+1) kot vhod ploskevB (vrstica i = [b_i0 b_i1 … b_in], x y z vsake točke drug ob drugem) ali datoteka Octave save -text s tabelo (m+1)×(n+1)×3 (FILE ali FILE.txt:NAME)",
        ],
        [
            "Řídicí síť",
            "zhuštěná (m+1)×3(n+1) jako vstup ploskevB (řádek i = [b_i0 b_i1 … b_in], x y z každého bodu vedle sebe) nebo soubor Octave save -text s polem (m+1)×(n+1)×3 (FILE nebo FILE.txt:NAME)",
        ],
    ),
    arg(
        &["bezier-patch"],
        "x",
        [
            "Namesto NET: koordinate x kontrolnih točk",
            "matrika (m+1)×(n+1), element (i, j) pripada b_ij (i v smeri u); X_B iz čeških zapiskov predavanj z x(u,v) = vᵀM_BᵀX_BM_Bu ima vrstice v smeri v: podajte njeno transponiranko",
        ],
        [
            "Místo NET: souřadnice x řídicích bodů",
            "matice (m+1)×(n+1), prvek (i, j) patří b_ij (i ve směru u); X_B ze skript s x(u,v) = vᵀM_BᵀX_BM_Bu má řádky ve směru v: zadejte její transpozici",
        ],
    ),
    arg(
        &["bezier-patch"],
        "y",
        ["Koordinate y", "skupaj z --x, oblika kot pri --x"],
        ["Souřadnice y", "spolu s --x, tvar jako u --x"],
    ),
    arg(
        &["bezier-patch"],
        "z",
        ["Koordinate z", "skupaj z --x in --y, oblika kot pri --x"],
        ["Souřadnice z", "spolu s --x a --y, tvar jako u --x"],
    ),
    arg(
        &["bezier-patch"],
        "du",
        [
            "Odvaja R-krat v smeri u",
            "ploskev parcialnega odvoda (zaključna naloga, Trditev 3.3), njena mreža se izpiše kot `net`",
        ],
        [
            "Derivuje R-krát ve směru u",
            "plocha parciální derivace (závěrečná práce, Trditev 3.3), její síť se vypíše jako `net`",
        ],
    ),
    arg(
        &["bezier-patch"],
        "dv",
        [
            "Odvaja S-krat v smeri v",
            "--du 1 --dv 1 da mešani odvod x_uv (twist)",
        ],
        [
            "Derivuje S-krát ve směru v",
            "--du 1 --dv 1 dává zkrut x_uv",
        ],
    ),
    // Coons patches.
    arg(
        &["coons"],
        "blend",
        [
            "Funkciji ujemanja v u in v (zaključna naloga (4.4))",
            "linear (1 − t, t), bilinearna ploskev (privzeto); hermite (H0³, H3³), delno bikubična ploskev iz §4.2; ali f1 kot izraz v t (f2 = 1 − f1) ali par \"[f1; f2]\"; veljati mora f1(0) = 1, f1(1) = 0 in f1 + f2 = 1 (preverjeno pri t = k/32)",
        ],
        [
            "Spojovací funkce v u a v (závěrečná práce (4.4))",
            "linear (1 − t, t), bilineární plocha (výchozí); hermite (H0³, H3³), částečně bikubická plocha z §4.2; nebo f1 jako výraz v t (f2 = 1 − f1), nebo dvojice \"[f1; f2]\"; musí platit f1(0) = 1, f1(1) = 0 a f1 + f2 = 1 (kontrolováno v t = k/32)",
        ],
    ),
    arg(
        &["coons-bicubic"],
        "c1v",
        [
            "Prečni odvod x_v(u,0) čez c1",
            "izraz v u, Bézierove kontrolne točke ali bezier(P), bspline(P, U), nurbs(P, W, U)",
        ],
        [
            "Derivace x_v(u,0) napříč c1",
            "výraz v u, Bézierovy řídicí body nebo bezier(P), bspline(P, U), nurbs(P, W, U)",
        ],
    ),
    arg(
        &["coons-bicubic"],
        "c2v",
        [
            "Prečni odvod x_v(u,1) čez c2",
            "v spremenljivki u, oblika kot pri --c1v",
        ],
        ["Derivace x_v(u,1) napříč c2", "v proměnné u, tvar jako u --c1v"],
    ),
    arg(
        &["coons-bicubic"],
        "d1u",
        [
            "Prečni odvod x_u(0,v) čez d1",
            "v spremenljivki v, oblika kot pri --c1v",
        ],
        ["Derivace x_u(0,v) napříč d1", "v proměnné v, tvar jako u --c1v"],
    ),
    arg(
        &["coons-bicubic"],
        "d2u",
        [
            "Prečni odvod x_u(1,v) čez d2",
            "v spremenljivki v, oblika kot pri --c1v",
        ],
        ["Derivace x_u(1,v) napříč d2", "v proměnné v, tvar jako u --c1v"],
    ),
    arg(
        &["coons-bicubic"],
        "twist",
        [
            "Mešani odvodi x_uv v ogliščih (twist)",
            "zero: vsi štirje nič; gregory: Gregoryjev kvadrat iz odvodov prečnih krivulj; given: podani z --twists",
        ],
        [
            "Zkruty x_uv v rozích",
            "zero: všechny čtyři nulové; gregory: Gregoryho čtverec z derivací příčných křivek; given: zadané pomocí --twists",
        ],
    ),
    arg(
        &["coons-bicubic"],
        "twists",
        [
            "Mešani odvodi v ogliščih P1..P4 (z --twist given)",
            "P1..P4 = (0,0),(1,0),(0,1),(1,1) kot stolpci matrike d×4",
        ],
        [
            "Zkruty v rozích P1..P4 (s --twist given)",
            "P1..P4 = (0,0),(1,0),(0,1),(1,1) jako sloupce matice d×4",
        ],
    ),
    arg(
        &["discrete-coons"],
        "net",
        [
            "Bézierova kontrolna mreža",
            "stisnjena (m+1)×3(n+1), kot jo sprejme ploskevB, ali datoteka Octave s tabelo (m+1)×(n+1)×3; uporabijo se le robne vrstice in stolpci",
        ],
        [
            "Bézierova řídicí síť",
            "zhuštěná (m+1)×3(n+1), jak ji přijímá ploskevB, nebo soubor Octave s polem (m+1)×(n+1)×3; použijí se jen okrajové řádky a sloupce",
        ],
    ),
    arg(
        &["discrete-coons"],
        "mask",
        [
            "Afina maska P_ij = α·(4 diagonalni sosedi) + β·(4 robni sosedi) za vsako notranjo točko namesto formule diskretne Coonsove ploskve",
            "α + β mora biti 1/4; α = −1/4, β = 1/2 je maska, ki jo da princip permanence (izpiski CAD (7)–(8)): spet diskretna Coonsova ploskev; α = 0, β = 1/4 je diskretna Laplaceova maska (vsaka točka je povprečje svojih 4 robnih sosedov); npr. --mask=-0.25,0.5",
        ],
        [
            "Afinní maska P_ij = α·(4 diagonální sousedé) + β·(4 hranoví sousedé) pro každý vnitřní bod místo vzorce diskrétní Coonsovy plochy",
            "α + β musí být 1/4; α = −1/4, β = 1/2 je maska, kterou dává princip permanence (poznámky CAD (7)–(8)): opět diskrétní Coonsova plocha; α = 0, β = 1/4 je diskrétní Laplaceova maska (každý bod je průměrem svých 4 hranových sousedů); např. --mask=-0.25,0.5",
        ],
    ),
    // Gordon surfaces.
    arg(
        &["gordon"],
        "u_curves",
        [
            "Krivulja g(u_i, v) mreže, v spremenljivki v",
            "ponovite, po eno za vsak vozel u, po vrsti; izraz, npr. \"[0.5; v; 0.25+v]\", Bézierove kontrolne točke ali bezier(P), bspline(P, U), nurbs(P, W, U)",
        ],
        [
            "Křivka g(u_i, v) sítě, v proměnné v",
            "opakujte, jednu pro každý uzel u, v pořadí; výraz, např. \"[0.5; v; 0.25+v]\", Bézierovy řídicí body nebo bezier(P), bspline(P, U), nurbs(P, W, U)",
        ],
    ),
    arg(
        &["gordon"],
        "v_curves",
        [
            "Krivulja g(u, v_j) mreže, v spremenljivki u",
            "ponovite, po eno za vsak vozel v, po vrsti; oblika kot pri --u-curve",
        ],
        [
            "Křivka g(u, v_j) sítě, v proměnné u",
            "opakujte, jednu pro každý uzel v, v pořadí; tvar jako u --u-curve",
        ],
    ),
    arg(
        &["gordon"],
        "u_nodes",
        [
            "Vozli u_i",
            "privzeto: enakomerno razporejeni na [0, 1] ali x iz skripta",
        ],
        [
            "Uzly u_i",
            "výchozí: rovnoměrně rozložené na [0, 1] nebo x ze skriptu",
        ],
    ),
    arg(
        &["gordon"],
        "v_nodes",
        [
            "Vozli v_j",
            "privzeto: enakomerno razporejeni na [0, 1] ali x iz skripta",
        ],
        [
            "Uzly v_j",
            "výchozí: rovnoměrně rozložené na [0, 1] nebo x ze skriptu",
        ],
    ),
    // Lagrange interpolation and Bernstein polynomials.
    arg(
        &["lagrange"],
        "nodes",
        ["Vozli x_0..x_m", "seznam, npr. \"[0 0.5 1]\", ali razpon"],
        ["Uzly x_0..x_m", "seznam, např. \"[0 0.5 1]\", nebo rozsah"],
    ),
    arg(
        &["lagrange"],
        "points",
        [
            "Vrednosti v vozlih",
            "en stolpec na vozel (matrika d×(m+1) ali 1×(m+1) za števila): tedaj se izpišejo vrednosti interpolacijskega polinoma, brez njih pa bazni polinomi L_0..L_m",
        ],
        [
            "Hodnoty v uzlech",
            "jeden sloupec na uzel (matice d×(m+1) nebo 1×(m+1) pro čísla): pak se vypíší hodnoty interpolačního polynomu, bez nich bázové polynomy L_0..L_m",
        ],
    ),
    arg(
        &["lagrange"],
        "coefficients",
        [
            "Izpiše tudi koeficiente v monomski bazi",
            "najprej najvišja potenca, kot polyfit v Octave: `coefficients`, vrstica i za L_i (matrika G iz čeških zapiskov predavanj), z --points pa `polynomial`, koeficienti interpolacijskega polinoma (A = X G iz čeških zapiskov predavanj)",
        ],
        [
            "Vypíše také koeficienty v monomiální bázi",
            "nejvyšší mocnina první, jako polyfit v Octave: `coefficients`, řádek i pro L_i (matice G ze skript), a s --points `polynomial`, koeficienty interpolačního polynomu (A = X G ze skript)",
        ],
    ),
    arg(
        &["lagrange"],
        "linear",
        [
            "Odsekoma linearna interpolacija --points namesto polinoma",
            "\"lineární interpolace\" iz čeških zapiskov predavanj; vozli morajo naraščati, krajna odseka se podaljšata",
        ],
        [
            "Po částech lineární interpolace --points místo polynomu",
            "\"lineární interpolace\" ze skript; uzly musí růst, krajní úseky se prodlouží",
        ],
    ),
    arg(
        &["lagrange"],
        "n",
        [
            "Vzorči [najmanjši vozel, največji vozel]",
            "v N enakomerno razporejenih parametrih",
        ],
        [
            "Vzorkuje [nejmenší uzel, největší uzel]",
            "v N rovnoměrně rozložených parametrech",
        ],
    ),
    arg(
        &["bernstein"],
        "degree",
        ["Stopnja n", "bazni polinomi B_0^n..B_n^n"],
        ["Stupeň n", "bázové polynomy B_0^n..B_n^n"],
    ),
    arg(
        &["bernstein"],
        "i",
        ["Samo B_i^n", "privzeto: vsi B_0^n..B_n^n"],
        ["Jen B_i^n", "výchozí: všechny B_0^n..B_n^n"],
    ),
    // Derivatives.
    arg(
        &["derivative"],
        "control",
        ["Kontrolne točke krivulje (stolpci)", "kot pri decasteljau"],
        ["Řídicí body křivky (sloupce)", "jako u decasteljau"],
    ),
    arg(
        &["derivative"],
        "order",
        ["Red odvoda r", "r-ti odvod"],
        ["Řád derivace r", "r-tá derivace"],
    ),
    arg(
        &["derivative"],
        "spline_order",
        [
            "Zavrnjeno: --order je v vseh ukazih red B-zlepka (stopnja + 1)",
            "red odvoda je -r",
        ],
        [
            "Odmítnuto: --order je ve všech příkazech řád B-spline (stupeň + 1)",
            "řád derivace je -r",
        ],
    ),
    arg(
        &["derivative"],
        "t",
        [
            "Tudi vrednosti odvoda pri teh parametrih",
            "število, seznam ali razpon",
        ],
        [
            "Také hodnoty derivace v těchto parametrech",
            "číslo, seznam nebo rozsah",
        ],
    ),
    // Splines and Hermite cubics.
    arg(
        &["spline"],
        "points",
        ["Točke za interpolacijo", "ena na stolpec"],
        ["Body k interpolaci", "jeden na sloupec"],
    ),
    arg(
        &["spline"],
        "end",
        [
            "Robni pogoj",
            "privzeto: clamped (vpeti konci), če je podana tangenta, sicer natural (naravni)",
        ],
        [
            "Okrajová podmínka",
            "výchozí: clamped (vetknuté konce), je-li zadán tečný vektor, jinak natural (přirozená)",
        ],
    ),
    arg(
        &["spline"],
        "start_tangent",
        ["Tangenta v prvi točki", "pri vpetih koncih (clamped)"],
        ["Tečný vektor v prvním bodě", "pro vetknuté konce (clamped)"],
    ),
    arg(
        &["spline"],
        "end_tangent",
        ["Tangenta v zadnji točki", "pri vpetih koncih (clamped)"],
        ["Tečný vektor v posledním bodě", "pro vetknuté konce (clamped)"],
    ),
    arg(
        &["spline"],
        "params",
        [
            "Parametri točk",
            "uniform (t_k = k, češki zapiski predavanj), chord (tetivni), centripetal (centripetalni) ali seznam naraščajočih vrednosti (ena na točko, ena več za zaprt zlepek)",
        ],
        [
            "Parametry bodů",
            "uniform (t_k = k, skripta), chord (tětivové), centripetal (centripetální) nebo seznam rostoucích hodnot (jedna na bod, o jednu více pro uzavřený spline)",
        ],
    ),
    arg(
        &["spline"],
        "t",
        [
            "Parametri krivulje",
            "pri enakomernih parametrih je odsek k na [k, k+1]; zaprt zlepek je periodičen, zato je vsaka vrednost na krivulji",
        ],
        [
            "Parametry křivky",
            "při uniformních parametrech běží segment k přes [k, k+1]; uzavřený spline je periodický, takže každá hodnota leží na křivce",
        ],
    ),
    arg(
        &["hermite"],
        "p0",
        ["Začetna točka x(0)", "točka z d koordinatami"],
        ["Počáteční bod x(0)", "bod o d souřadnicích"],
    ),
    arg(
        &["hermite"],
        "p1",
        ["Končna točka x(1)", "točka z d koordinatami"],
        ["Koncový bod x(1)", "bod o d souřadnicích"],
    ),
    arg(
        &["hermite"],
        "t0",
        ["Začetna tangenta x'(0)", "vektor z d koordinatami"],
        ["Počáteční tečný vektor x'(0)", "vektor o d souřadnicích"],
    ),
    arg(
        &["hermite"],
        "t1",
        ["Končna tangenta x'(1)", "vektor z d koordinatami"],
        ["Koncový tečný vektor x'(1)", "vektor o d souřadnicích"],
    ),
    // B-splines and NURBS.
    arg(
        &["bspline", "nurbs"],
        "control",
        ["Kontrolne točke", "ena na stolpec"],
        ["Řídicí body", "jeden na sloupec"],
    ),
    arg(
        SPLINE_DEGREE,
        "degree",
        ["Stopnja p", "privzeto 3"],
        ["Stupeň p", "výchozí 3"],
    ),
    arg(
        &["bspline"],
        "order",
        [
            "Red k = p + 1 namesto stopnje",
            "češki zapiski predavanj štejejo B-zlepke po redu",
        ],
        [
            "Řád k = p + 1 místo stupně",
            "skripta počítají B-spline křivky podle řádu",
        ],
    ),
    arg(
        &["bspline", "nurbs", "insert-knot"],
        "knots",
        [
            "Vozliščni vektor",
            "n + p + 1 nepadajočih vrednosti za n kontrolnih točk; privzeto odprt (clamped) enakomeren na [0, 1]",
        ],
        [
            "Uzlový vektor",
            "n + p + 1 neklesajících hodnot pro n řídicích bodů; výchozí otevřený (clamped) uniformní na [0, 1]",
        ],
    ),
    arg(
        &["bspline", "nurbs"],
        "n",
        [
            "Vzorči definicijsko območje vozlov [u_(p+1), u_(n+1)] (ne [0, 1])",
            "v N enakomerno razporejenih parametrih",
        ],
        [
            "Vzorkuje definiční obor uzlů [u_(p+1), u_(n+1)] (ne [0, 1])",
            "v N rovnoměrně rozložených parametrech",
        ],
    ),
    arg(
        &["nurbs"],
        "weights",
        ["Uteži", "ena na kontrolno točko, pozitivne"],
        ["Váhy", "jedna na řídicí bod, kladné"],
    ),
    arg(
        &["nurbs"],
        "order",
        [
            "Red k = p + 1 namesto stopnje",
            "red, kot ga štejejo češki zapiski predavanj",
        ],
        ["Řád k = p + 1 místo stupně", "řád, jak ho počítají skripta"],
    ),
    arg(
        &["convert"],
        "geometry",
        [
            "Geometrijska matrika krivulje",
            "en vektor na stolpec (vrstice z --rows)",
        ],
        [
            "Geometrická matice křivky",
            "jeden vektor na sloupec (řádky s --rows)",
        ],
    ),
    arg(
        &["convert"],
        "from",
        [
            "Oblika, v kateri je GEOMETRY",
            "hermite, bezier, bspline, monomial ali algebraic",
        ],
        [
            "Tvar, v němž je GEOMETRY",
            "hermite, bezier, bspline, monomial nebo algebraic",
        ],
    ),
    arg(
        &["convert"],
        "to",
        [
            "Ciljna oblika",
            "hermite, bezier, bspline, monomial ali algebraic",
        ],
        [
            "Cílový tvar",
            "hermite, bezier, bspline, monomial nebo algebraic",
        ],
    ),
    // Degree elevation, subdivision, knot insertion.
    arg(
        &["elevate", "insert-knot"],
        "control",
        ["Kontrolne točke", "ena na stolpec (vrstice z --rows)"],
        ["Řídicí body", "jeden na sloupec (řádky s --rows)"],
    ),
    arg(
        &["elevate"],
        "by",
        ["Zviša stopnjo za R", "privzeto 1 ali do --degree"],
        ["Zvýší stupeň o R", "výchozí 1 nebo až na --degree"],
    ),
    arg(
        &["elevate"],
        "degree",
        [
            "Stopnja P po zvišanju",
            "ciljna stopnja, kot pravi \"zvišaj na stopnjo P\"; z --by mora biti enaka prejšnji stopnji plus R",
        ],
        [
            "Stupeň P po zvýšení",
            "cílový stupeň, jak říká \"zvyš na stupeň P\"; s --by se musí rovnat původnímu stupni plus R",
        ],
    ),
    arg(
        &["elevate"],
        "order",
        [
            "Red K = P + 1 po zvišanju",
            "češki zapiski predavanj štejejo po redu",
        ],
        ["Řád K = P + 1 po zvýšení", "skripta počítají podle řádu"],
    ),
    arg(
        &["elevate"],
        "knots",
        [
            "Odprt (clamped) B-zlepek s tem vozliščnim vektorjem namesto Bézierove krivulje",
            "njegova stopnja je numel(knots) − n − 1 za n kontrolnih točk",
        ],
        [
            "Otevřená (clamped) B-spline křivka s tímto uzlovým vektorem místo Bézierovy křivky",
            "její stupeň je numel(knots) − n − 1 pro n řídicích bodů",
        ],
    ),
    arg(
        &["subdivide"],
        "control",
        ["Kontrolne točke b_0..b_n", "ena na stolpec (vrstice z --rows)"],
        ["Řídicí body b_0..b_n", "jeden na sloupec (řádky s --rows)"],
    ),
    arg(
        &["subdivide"],
        "t",
        [
            "Kje deliti",
            "en parameter znotraj intervala (privzeto njegova sredina)",
        ],
        [
            "Kde dělit",
            "jeden parametr uvnitř intervalu (výchozí jeho střed)",
        ],
    ),
    arg(
        &["subdivide"],
        "interval",
        ["Parametrski interval [a, b] krivulje", "privzeto 0,1"],
        ["Parametrický interval [a, b] křivky", "výchozí 0,1"],
    ),
    arg(
        &["insert-knot"],
        "insert",
        [
            "Vozli za vstavljanje",
            "v poljubnem vrstnem redu, ponovitve so dovoljene, vsak strogo znotraj definicijskega območja",
        ],
        [
            "Uzly k vložení",
            "v libovolném pořadí, opakování jsou povolena, každý ostře uvnitř definičního oboru",
        ],
    ),
    arg(
        &["insert-knot"],
        "order",
        [
            "Red k = p + 1 namesto stopnje",
            "češki zapiski predavanj štejejo po redu",
        ],
        ["Řád k = p + 1 místo stupně", "skripta počítají podle řádu"],
    ),
    arg(
        &["insert-knot"],
        "weights",
        ["Uteži krivulje NURBS", "ena na kontrolno točko (pozitivne)"],
        ["Váhy křivky NURBS", "jedna na řídicí bod (kladné)"],
    ),
    arg(
        &["bspline-basis"],
        "knots",
        [
            "Vozliščni vektor u_1 ≤ … ≤ u_(n+p+1)",
            "n + p + 1 nepadajočih vrednosti za n baznih funkcij stopnje p",
        ],
        [
            "Uzlový vektor u_1 ≤ … ≤ u_(n+p+1)",
            "n + p + 1 neklesajících hodnot pro n bázových funkcí stupně p",
        ],
    ),
    arg(
        &["bspline-basis"],
        "order",
        [
            "Red k = p + 1 namesto stopnje",
            "češki zapiski predavanj štejejo po redu: N_i,k",
        ],
        [
            "Řád k = p + 1 místo stupně",
            "skripta počítají podle řádu: N_i,k",
        ],
    ),
    arg(
        &["bspline-basis"],
        "n",
        [
            "Vzorči ves razpon vozlov [u_1, u_(n+p+1)]",
            "v N enakomerno razporejenih parametrih",
        ],
        [
            "Vzorkuje celý rozsah uzlů [u_1, u_(n+p+1)]",
            "v N rovnoměrně rozložených parametrech",
        ],
    ),
    // Continuity and curvature.
    arg(
        &["continuity"],
        "first",
        [
            "Kontrolne točke prve krivulje x(u)",
            "konča se pri u = 1 (stolpci; vrstice z --rows)",
        ],
        [
            "Řídicí body první křivky x(u)",
            "končí v u = 1 (sloupce; řádky s --rows)",
        ],
    ),
    arg(
        &["continuity"],
        "second",
        ["Kontrolne točke druge krivulje ¹x(v)", "začne se pri v = 0"],
        ["Řídicí body druhé křivky ¹x(v)", "začíná ve v = 0"],
    ),
    arg(
        &["continuity"],
        "free_point",
        [
            "Predzadnja kontrolna točka FIRST je neznana in izpuščena iz FIRST",
            "izpiše premico točk, pri katerih je stik gladek (primer iz čeških zapiskov predavanj)",
        ],
        [
            "Předposlední řídicí bod FIRST je neznámý a ve FIRST vynechaný",
            "vypíše přímku bodů, pro které je spoj hladký (příklad ze skript)",
        ],
    ),
    arg(
        &["continuity"],
        "k",
        [
            "Faktor k v x'(1) = k·¹x'(0) (z --free-point)",
            "za izpisano točko; privzeto 1, točka za C1",
        ],
        [
            "Koeficient k v x'(1) = k·¹x'(0) (s --free-point)",
            "pro vypsaný bod; výchozí 1, bod pro C1",
        ],
    ),
    arg(
        &["curvature"],
        "curve",
        [
            "Krivulja",
            "kontrolne točke Bézierove krivulje ali bezier(P), bspline(P, U), nurbs(P, W, U)",
        ],
        [
            "Křivka",
            "řídicí body Bézierovy křivky nebo bezier(P), bspline(P, U), nurbs(P, W, U)",
        ],
    ),
    // Integrals.
    arg(
        &["integrate"],
        "control",
        [
            "Kontrolne točke Bézierove krivulje (ali z --knots/--degree/--order B-zlepka)",
            "ena na stolpec (vrstice z --rows); izpustite jih z --bernstein",
        ],
        [
            "Řídicí body Bézierovy křivky (nebo s --knots/--degree/--order B-spline křivky)",
            "jeden na sloupec (řádky s --rows); s --bernstein je vynechte",
        ],
    ),
    arg(
        &["integrate"],
        "bernstein",
        [
            "Integrira Bernsteinove polinome B_i^N stopnje N namesto krivulje",
            "brez kontrolnih točk",
        ],
        [
            "Integruje Bernsteinovy polynomy B_i^N stupně N místo křivky",
            "bez řídicích bodů",
        ],
    ),
    arg(
        &["integrate"],
        "i",
        ["Samo B_i^N (z --bernstein)", "sicer vsi B_0^N..B_N^N"],
        ["Jen B_i^N (s --bernstein)", "jinak všechny B_0^N..B_N^N"],
    ),
    arg(
        &["integrate"],
        "degree",
        [
            "B-zlepek stopnje P",
            "z --knots, privzeto odprt (clamped) enakomeren vozliščni vektor na [0, 1]",
        ],
        [
            "B-spline křivka stupně P",
            "s --knots, výchozí otevřený (clamped) uniformní uzlový vektor na [0, 1]",
        ],
    ),
    arg(
        &["integrate"],
        "order",
        [
            "B-zlepek reda K = P + 1",
            "red, kot ga štejejo češki zapiski predavanj",
        ],
        ["B-spline křivka řádu K = P + 1", "řád, jak ho počítají skripta"],
    ),
    arg(
        &["integrate"],
        "knots",
        [
            "Vozliščni vektor B-zlepka",
            "n + p + 1 nepadajočih vrednosti za n kontrolnih točk (z --degree ali --order; privzeto kubičen)",
        ],
        [
            "Uzlový vektor B-spline křivky",
            "n + p + 1 neklesajících hodnot pro n řídicích bodů (s --degree nebo --order; výchozí kubická)",
        ],
    ),
    arg(
        &["integrate"],
        "interval",
        ["Parametrski interval [a, b] Bézierove krivulje", "privzeto 0,1"],
        ["Parametrický interval [a, b] Bézierovy křivky", "výchozí 0,1"],
    ),
    arg(
        &["integrate"],
        "t",
        [
            "Tudi vrednosti nedoločenega integrala pri teh parametrih",
            "∫ od začetka definicijskega območja",
        ],
        [
            "Také hodnoty primitivní funkce v těchto parametrech",
            "∫ od začátku definičního oboru",
        ],
    ),
    // Surfaces of the lecture notes.
    arg(
        &["ruled"],
        "first",
        [
            "Krivulja ¹x(u) pri v = 0",
            "izraz v u, npr. \"[u;0;u-u^2]\", Bézierove kontrolne točke (stolpci) ali bezier(P), bspline(P, U), nurbs(P, W, U)",
        ],
        [
            "Křivka ¹x(u) ve v = 0",
            "výraz v u, např. \"[u;0;u-u^2]\", Bézierovy řídicí body (sloupce) nebo bezier(P), bspline(P, U), nurbs(P, W, U)",
        ],
    ),
    arg(
        &["ruled"],
        "second",
        ["Krivulja ²x(u) pri v = 1", "oblika kot pri --first"],
        ["Křivka ²x(u) ve v = 1", "tvar jako u --first"],
    ),
    arg(
        &["ferguson"],
        "points",
        [
            "Oglišča x(0,0), x(1,0), x(0,1), x(1,1)",
            "kot stolpci matrike d×4",
        ],
        [
            "Rohové body x(0,0), x(1,0), x(0,1), x(1,1)",
            "jako sloupce matice d×4",
        ],
    ),
    arg(
        &["ferguson"],
        "du",
        ["Tangente ∂x/∂u v ogliščih", "v istem vrstnem redu (d×4)"],
        ["Tečné vektory ∂x/∂u v rozích", "ve stejném pořadí (d×4)"],
    ),
    arg(
        &["ferguson"],
        "dv",
        ["Tangente ∂x/∂v v ogliščih", "v istem vrstnem redu (d×4)"],
        ["Tečné vektory ∂x/∂v v rozích", "ve stejném pořadí (d×4)"],
    ),
    arg(
        &["ferguson"],
        "twists",
        [
            "Mešani odvodi ∂²x/∂u∂v v ogliščih",
            "d×4; privzeto nič, F-ploskev iz čeških zapiskov predavanj",
        ],
        [
            "Zkruty ∂²x/∂u∂v v rozích",
            "d×4; výchozí nulové, F-plocha ze skript",
        ],
    ),
    arg(
        SPLINE_SURFACES,
        "net",
        [
            "Kontrolna mreža",
            "stisnjena (m+1)×3(n+1), kot jo sprejme ploskevB (vrstica i = [P_i0 P_i1 … P_in], x y z drug ob drugem), datoteka Octave s tabelo (m+1)×(n+1)×3 ali datoteka Octave save -text s strukturo nrbmak iz octave-nurbs (FILE ali FILE:NAME)",
        ],
        [
            "Řídicí síť",
            "zhuštěná (m+1)×3(n+1), jak ji přijímá ploskevB (řádek i = [P_i0 P_i1 … P_in], x y z vedle sebe), soubor Octave s polem (m+1)×(n+1)×3 nebo soubor Octave save -text se strukturou nrbmak z octave-nurbs (FILE nebo FILE:NAME)",
        ],
    ),
    arg(
        SPLINE_SURFACES,
        "x",
        [
            "Namesto NET: koordinate x kontrolnih točk",
            "matrika (m+1)×(n+1), element (i, j) pripada P_ij (i v smeri u; X_S iz čeških zapiskov predavanj ima vrstice v smeri v: podajte njeno transponiranko)",
        ],
        [
            "Místo NET: souřadnice x řídicích bodů",
            "matice (m+1)×(n+1), prvek (i, j) patří P_ij (i ve směru u; X_S ze skript má řádky ve směru v: zadejte její transpozici)",
        ],
    ),
    arg(
        SPLINE_SURFACES,
        "y",
        ["Koordinate y", "skupaj z --x"],
        ["Souřadnice y", "spolu s --x"],
    ),
    arg(
        SPLINE_SURFACES,
        "z",
        ["Koordinate z", "skupaj z --x in --y"],
        ["Souřadnice z", "spolu s --x a --y"],
    ),
    arg(
        SPLINE_SURFACES,
        "degree",
        [
            "Stopnji",
            "P za obe smeri ali P,Q (privzeto 3, kubična, ali red strukture − 1)",
        ],
        [
            "Stupně",
            "P pro oba směry nebo P,Q (výchozí 3, kubická, nebo řád struktury − 1)",
        ],
    ),
    arg(
        SPLINE_SURFACES,
        "order",
        ["Reda K = P + 1 namesto stopenj", "K ali K,L"],
        ["Řády K = P + 1 místo stupňů", "K nebo K,L"],
    ),
    arg(
        EVERY,
        "uknots",
        [
            "Vozliščni vektor v smeri u (vrstice mreže)",
            "n + p + 1 nepadajočih vrednosti za n kontrolnih točk v smeri u in stopnjo p v smeri u; privzeto odprt (clamped) enakomeren na [0, 1]",
        ],
        [
            "Uzlový vektor ve směru u (řádky sítě)",
            "n + p + 1 neklesajících hodnot pro n řídicích bodů ve směru u a stupeň p ve směru u; výchozí otevřený (clamped) uniformní na [0, 1]",
        ],
    ),
    arg(
        EVERY,
        "vknots",
        [
            "Vozliščni vektor v smeri v (stolpci mreže)",
            "n + q + 1 nepadajočih vrednosti za n kontrolnih točk v smeri v in stopnjo q v smeri v; privzeto odprt (clamped) enakomeren na [0, 1]",
        ],
        [
            "Uzlový vektor ve směru v (sloupce sítě)",
            "n + q + 1 neklesajících hodnot pro n řídicích bodů ve směru v a stupeň q ve směru v; výchozí otevřený (clamped) uniformní na [0, 1]",
        ],
    ),
    arg(
        &["nurbs-surface"],
        "weights",
        [
            "Uteži",
            "matrika (m+1)×(n+1) pozitivnih števil, ena na kontrolno točko (s strukturo nrbmak niso potrebne, ker jih vsebuje)",
        ],
        [
            "Váhy",
            "matice (m+1)×(n+1) kladných čísel, jedna na řídicí bod (se strukturou nrbmak nejsou potřeba, protože je obsahuje)",
        ],
    ),
    // Circles and expressions.
    arg(
        EVERY,
        "radius",
        ["Polmer r > 0", "pozitivno število"],
        ["Poloměr r > 0", "kladné číslo"],
    ),
    arg(
        EVERY,
        "center",
        [
            "Središče",
            "2 ali 3 koordinate (krožnica leži v ravnini z = z središča)",
        ],
        [
            "Střed",
            "2 nebo 3 souřadnice (kružnice leží v rovině z = z středu)",
        ],
    ),
    arg(
        &["arc"],
        "start",
        [
            "Začetni kot v radianih (v pozitivni smeri od osi x)",
            "dovoljeni so izrazi, kot je pi/4",
        ],
        [
            "Počáteční úhel v radiánech (proti směru hodinových ručiček od osy x)",
            "povoleny jsou výrazy jako pi/4",
        ],
    ),
    arg(
        &["arc"],
        "end",
        ["Končni kot v radianih", "največ en poln obrat od začetnega"],
        ["Koncový úhel v radiánech", "nejvýše jedna celá otáčka od počátečního"],
    ),
    arg(
        &["curve"],
        "expr",
        [
            "Krivulja",
            "izraz v enem parametru t, u ali v, npr. \"[u; 0; u-u^2]\"",
        ],
        [
            "Křivka",
            "výraz v jednom parametru t, u nebo v, např. \"[u; 0; u-u^2]\"",
        ],
    ),
    arg(
        &["surface"],
        "expr",
        ["Ploskev", "izraz v u in v, npr. \"[u; v; u.*v]\""],
        ["Plocha", "výraz v u a v, např. \"[u; v; u.*v]\""],
    ),
    // The page and scripts.
    arg(
        EVERY,
        "port",
        ["Vrata na 127.0.0.1", "0 izbere prosta vrata; naslov se izpiše"],
        ["Port na 127.0.0.1", "0 vybere volný port; adresa se vypíše"],
    ),
    arg(
        EVERY,
        "dir",
        [
            "Mapa zgrajene strani",
            "privzeto: web/dist v trenutni mapi, sicer v mapi nad programom cagd, kot v kopiji repozitorija",
        ],
        [
            "Složka sestavené stránky",
            "výchozí: web/dist v aktuální složce, jinak ve složce nad programem cagd, jako v klonu repozitáře",
        ],
    ),
    arg(
        EVERY,
        "file",
        ["Podatkovni skript Octave", "ali - za standardni vhod"],
        ["Datový skript Octave", "nebo - pro standardní vstup"],
    ),
    arg(
        &["script"],
        "n",
        [
            "Pred zagonom nastavi N",
            "uporabljajo ga skripti zaključne naloge, npr. u = linspace(0,1,N)",
        ],
        [
            "Před spuštěním nastaví N",
            "používají ho skripty závěrečné práce, např. u = linspace(0,1,N)",
        ],
    ),
];

impl Help {
    /// The label and the hint as one text (`LABEL. HINT`).
    pub fn text(&self) -> String {
        format!("{}. {}", self.label, self.hint)
    }
}

impl ArgWords {
    /// The words in `lang` (none for English, which is clap's).
    pub fn get(&self, lang: Lang) -> Option<Help> {
        match lang {
            Lang::En => None,
            Lang::Sl => Some(self.sl),
            Lang::Cs => Some(self.cs),
        }
    }
}

impl Translated {
    /// The text in `lang` (none for English, which is clap's).
    pub fn get(&self, lang: Lang) -> Option<&'static str> {
        match lang {
            Lang::En => None,
            Lang::Sl => Some(self.sl),
            Lang::Cs => Some(self.cs),
        }
    }
}

/// The summary of subcommand `command` in `lang` (none in English: clap's `about`).
///
/// ```
/// use cagd_cli::lang::{forms, Lang};
/// assert_eq!(forms::summary("bspline-basis", Lang::Cs),
///     Some("Bázové funkce B-spline N_i,p(u) uzlového vektoru (Cox–de Boor)"));
/// assert_eq!(forms::summary("bspline-basis", Lang::En), None);
/// ```
pub fn summary(command: &str, lang: Lang) -> Option<&'static str> {
    SUMMARIES
        .iter()
        .find(|(name, _)| *name == command)
        .and_then(|(_, words)| words.get(lang))
}

/// The entry for argument `id` of subcommand `command`: the subcommand's own, else the one
/// for [`EVERY`] subcommand.
pub fn entry(command: &str, id: &str) -> Option<&'static ArgWords> {
    let of = |own: bool| {
        ARGUMENTS.iter().find(|a| {
            a.id == id && (a.commands.is_empty() != own) && (!own || a.commands.contains(&command))
        })
    };
    of(true).or_else(|| of(false))
}

/// The label and hint of argument `id` of subcommand `command` in `lang` (none in English:
/// clap's help).
///
/// ```
/// use cagd_cli::lang::{forms, Lang};
/// let t = forms::argument("decasteljau", "t", Lang::Sl).unwrap();
/// assert_eq!(t.label, "Parametri krivulje");
/// let knots = forms::argument("bspline", "knots", Lang::Cs).unwrap();
/// assert_eq!(knots.label, "Uzlový vektor");
/// assert_eq!(forms::argument("decasteljau", "t", Lang::En), None);
/// ```
pub fn argument(command: &str, id: &str, lang: Lang) -> Option<Help> {
    entry(command, id).and_then(|a| a.get(lang))
}

#[cfg(test)]
mod tests {
    use super::*;

    // That every argument of every subcommand has its words, and each entry stands for one
    // English help, is tested beside the clap definitions' reader (crate::schema).

    #[test]
    fn the_labels_keep_the_sources_words() {
        assert_eq!(
            argument("bspline", "knots", Lang::Sl).unwrap().label,
            "Vozliščni vektor"
        );
        assert_eq!(
            argument("decasteljau", "control", Lang::Cs).unwrap().label,
            "Řídicí body b_0..b_n"
        );
        assert_eq!(
            argument("nurbs", "weights", Lang::Sl).unwrap().label,
            "Uteži"
        );
        assert_eq!(
            argument("nurbs", "weights", Lang::Cs).unwrap().label,
            "Váhy"
        );
        assert!(summary("coons", Lang::Sl)
            .unwrap()
            .starts_with("Coonsova ploskev"));
        assert!(summary("coons", Lang::Cs)
            .unwrap()
            .contains("Coonsova plocha"));
    }
}
