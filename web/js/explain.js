// A short explanation beside each construction: what it is (in English, Slovenian and Czech),
// its formula, and the source it comes from (by the short names of docs/SOURCES.md: thesis,
// CAD notes, matrix-form notes, lecture notes; in Slovenian and Czech each source's own name
// with the short name beside it, "zaključna naloga (thesis) §4.1"). Keyed by the command
// line's subcommand; the views show the explanation of the subcommand they run.

import { lang, t } from "./i18n.js";

const E = {
  decasteljau: {
    formula: "b_i^r(t) = (1 − t) b_i^(r−1)(t) + t b_(i+1)^(r−1)(t),   b(t) = b_0^n(t)",
    source: {
      en: "thesis, algorithm 1 (Primer 2.4)",
      sl: "zaključna naloga (thesis), algoritem 1 (Primer 2.4)",
      cs: "závěrečná práce (thesis), algoritmus 1 (Primer 2.4)",
    },
    en: "A Bézier curve is evaluated by repeated linear interpolation: each level of the scheme interpolates neighbouring points of the level before at the ratio t; the last point lies on the curve.",
    sl: "Bézierovo krivuljo izračunamo s ponavljajočo se linearno interpolacijo: vsak nivo sheme interpolira sosednji točki prejšnjega nivoja v razmerju t; zadnja točka leži na krivulji.",
    cs: "Bézierova křivka se počítá opakovanou lineární interpolací: každá úroveň schématu interpoluje sousední body předchozí úrovně v poměru t; poslední bod leží na křivce.",
  },
  subdivide: {
    formula: "left: b_0^0(t), b_0^1(t), …, b_0^n(t)   right: b_0^n(t), b_1^(n−1)(t), …, b_n^0(t)",
    source: {
      en: "thesis §2.3 (subdivision)",
      sl: "zaključna naloga (thesis) §2.3 (delitev)",
      cs: "závěrečná práce (thesis) §2.3 (dělení)",
    },
    en: "Subdivision at t: the de Casteljau scheme at t holds the control points of both parts of the curve — its diagonal b_0^r for the part before t, its last row b_(n−r)^r for the part after t.",
    sl: "Delitev pri t: de Casteljaujeva shema pri t vsebuje kontrolne točke obeh delov krivulje — diagonalo b_0^r za del pred t in zadnjo vrstico b_(n−r)^r za del za t.",
    cs: "Dělení v t: de Casteljauovo schéma v t obsahuje řídicí body obou částí křivky — diagonálu b_0^r pro část před t a poslední řádek b_(n−r)^r pro část za t.",
  },
  elevate: {
    formula: "b_i^(1) = i/(n+1) · b_(i−1) + (1 − i/(n+1)) · b_i,   i = 0, …, n + 1",
    source: {
      en: "thesis §2.3 (degree elevation); CAD notes §1.1",
      sl: "zaključna naloga (thesis) §2.3 (višanje stopnje); izpiski CAD (CAD notes) §1.1",
      cs: "závěrečná práce (thesis) §2.3 (zvýšení stupně); poznámky CAD (CAD notes) §1.1",
    },
    en: "Degree elevation writes the same curve with one control point more; each new point lies on the old control polygon, and repeated elevation converges to the curve.",
    sl: "Višanje stopnje zapiše isto krivuljo z eno kontrolno točko več; vsaka nova točka leži na starem kontrolnem poligonu, ponavljanje pa konvergira h krivulji.",
    cs: "Zvýšení stupně zapíše tutéž křivku o jeden řídicí bod více; každý nový bod leží na starém řídicím polygonu a opakování konverguje ke křivce.",
  },
  "bezier-patch": {
    formula: "x(u, v) = Σ_i Σ_j b_ij B_i^m(u) B_j^n(v)",
    source: {
      en: "thesis §3 (algorithms 2–4, ploskevB)",
      sl: "zaključna naloga (thesis) §3 (algoritmi 2–4, ploskevB)",
      cs: "závěrečná práce (thesis) §3 (algoritmy 2–4, ploskevB)",
    },
    en: "A tensor-product Bézier patch: de Casteljau's algorithm in u on every row of the control net, then in v.",
    sl: "Tenzorska Bézierova ploskev: de Casteljaujev algoritem v smeri u na vsaki vrstici kontrolne mreže, nato v smeri v.",
    cs: "Tenzorová Bézierova plocha: de Casteljauův algoritmus ve směru u na každém řádku řídicí sítě, potom ve směru v.",
  },
  coons: {
    formula: "x = r_c + r_d − r_cd,   r_c = (1−v) c1(u) + v c2(u),   r_d = (1−u) d1(v) + u d2(v)",
    source: {
      en: "thesis §4.1 (algorithms 5–6, Primer 4.3); CAD notes §2.1",
      sl: "zaključna naloga (thesis) §4.1 (algoritma 5–6, Primer 4.3); izpiski CAD (CAD notes) §2.1",
      cs: "závěrečná práce (thesis) §4.1 (algoritmy 5–6, Primer 4.3); poznámky CAD (CAD notes) §2.1",
    },
    en: "The bilinearly blended Coons patch fills four boundary curves that meet at the corners: the two ruled surfaces between opposite curves, minus the bilinear surface of the corners.",
    sl: "Bilinearno zlepljena Coonsova ploskev zapolni štiri robne krivulje, ki se stikajo v ogliščih: vsota premonosnih ploskev med nasprotnima krivuljama, zmanjšana za bilinearno ploskev oglišč.",
    cs: "Bilineárně sešitá Coonsova plocha vyplní čtyři hraniční křivky, které se stýkají v rozích: součet přímkových ploch mezi protějšími křivkami minus bilineární plocha rohů.",
  },
  "coons-bicubic": {
    formula: "x = r_c + r_d − r_cd with the cubic Hermite blends F_0, F_1, G_0, G_1 and the twists x_uv",
    source: {
      en: "thesis §4.2–4.4",
      sl: "zaključna naloga (thesis) §4.2–4.4",
      cs: "závěrečná práce (thesis) §4.2–4.4",
    },
    en: "The partially and the fully bicubically blended Coons patch: Hermite blending functions also match the derivatives across the boundary; the twists at the corners must be compatible.",
    sl: "Delno in v celoti bikubično zlepljena Coonsova ploskev: Hermitove zlepitvene funkcije ujemajo tudi odvode prečno na rob; zasuki v ogliščih morajo biti združljivi.",
    cs: "Částečně a úplně bikubicky sešitá Coonsova plocha: Hermiteovy spojovací funkce zachovají i derivace napříč hranicí; zkruty v rozích musí být slučitelné.",
  },
  "discrete-coons": {
    formula: "b_ij = α · (corner points) + β · (boundary points),   α + β = 1/4   (α = −1/4, β = 1/2)",
    source: {
      en: "CAD notes §2.1",
      sl: "izpiski CAD (CAD notes) §2.1",
      cs: "poznámky CAD (CAD notes) §2.1",
    },
    en: "The discrete Coons patch computes the inner points of a control net from its boundary points with a 3 × 3 mask.",
    sl: "Diskretna Coonsova ploskev izračuna notranje točke kontrolne mreže iz robnih z masko 3 × 3.",
    cs: "Diskrétní Coonsova plocha dopočítá vnitřní body řídicí sítě z hraničních maskou 3 × 3.",
  },
  gordon: {
    formula: "g = g1 + g2 − g12,   g1 = Σ_i L_i(u) g(u_i, v),   g2 = Σ_j L_j(v) g(u, v_j),   g12 = Σ_i Σ_j L_i(u) L_j(v) g(u_i, v_j)",
    source: {
      en: "thesis §4.5 (algorithm 7)",
      sl: "zaključna naloga (thesis) §4.5 (algoritem 7)",
      cs: "závěrečná práce (thesis) §4.5 (algoritmus 7)",
    },
    en: "A Gordon surface interpolates a whole network of curves: Lagrange interpolation across the curves of each family, minus the tensor-product interpolation of their intersections.",
    sl: "Gordonova ploskev interpolira celo mrežo krivulj: Lagrangeva interpolacija čez krivulje vsake družine, zmanjšana za tenzorsko interpolacijo njihovih presečišč.",
    cs: "Gordonova plocha interpoluje celou síť křivek: Lagrangeova interpolace přes křivky každé rodiny minus tenzorová interpolace jejich průsečíků.",
  },
  lagrange: {
    formula: "L_i(t) = Π_(j≠i) (t − x_j)/(x_i − x_j),   p(t) = Σ_i P_i L_i(t)",
    source: {
      en: "lecture notes (Příklad 1); thesis §4.5",
      sl: "češki zapiski predavanj (lecture notes), Příklad 1; zaključna naloga (thesis) §4.5",
      cs: "skripta (lecture notes), Příklad 1; závěrečná práce (thesis) §4.5",
    },
    en: "Lagrange interpolation: the polynomial of the lowest degree through given values at the nodes.",
    sl: "Lagrangeva interpolacija: polinom najnižje stopnje skozi dane vrednosti v vozliščih.",
    cs: "Lagrangeova interpolace: polynom nejnižšího stupně procházející danými hodnotami v uzlech.",
  },
  bernstein: {
    formula: "B_i^n(t) = C(n, i) t^i (1 − t)^(n−i)",
    source: {
      en: "thesis §2.2; CAD notes §1.1",
      sl: "zaključna naloga (thesis) §2.2; izpiski CAD (CAD notes) §1.1",
      cs: "závěrečná práce (thesis) §2.2; poznámky CAD (CAD notes) §1.1",
    },
    en: "The Bernstein polynomials of degree n: non-negative on [0, 1] and summing to 1, the weights of the control points of a Bézier curve.",
    sl: "Bernsteinovi polinomi stopnje n: nenegativni na [0, 1] z vsoto 1, uteži kontrolnih točk Bézierove krivulje.",
    cs: "Bernsteinovy polynomy stupně n: nezáporné na [0, 1] se součtem 1, váhy řídicích bodů Bézierovy křivky.",
  },
  derivative: {
    formula: "b′(t) = n Σ_i Δb_i B_i^(n−1)(t),   Δb_i = b_(i+1) − b_i",
    source: {
      en: "thesis §2.4",
      sl: "zaključna naloga (thesis) §2.4",
      cs: "závěrečná práce (thesis) §2.4",
    },
    en: "The derivative of a Bézier curve is a Bézier curve of degree n − 1 whose control points are n times the differences of the control points.",
    sl: "Odvod Bézierove krivulje je Bézierova krivulja stopnje n − 1, katere kontrolne točke so n-kratniki razlik kontrolnih točk.",
    cs: "Derivace Bézierovy křivky je Bézierova křivka stupně n − 1, jejíž řídicí body jsou n-násobky diferencí řídicích bodů.",
  },
  spline: {
    formula: "x′_(k−1) + 4 x′_k + x′_(k+1) = 3 (x_(k+1) − x_(k−1)),   k = 1, …, m − 1",
    source: {
      en: "lecture notes (cubic splines, cases a, b, c)",
      sl: "češki zapiski predavanj (lecture notes), kubični zlepki, primeri a, b, c",
      cs: "skripta (lecture notes), kubické spline křivky, případy a, b, c",
    },
    en: "The interpolating cubic spline: C² cubic pieces through the points; the tangents solve a tridiagonal system whose first and last rows come from the end condition (clamped, natural or closed).",
    sl: "Interpolacijski kubični zlepek: kubični odseki razreda C² skozi točke; tangente so rešitev tridiagonalnega sistema, katerega prva in zadnja vrstica izhajata iz robnega pogoja (vpet, naraven ali sklenjen).",
    cs: "Interpolační kubický splajn: kubické segmenty třídy C² procházející body; tečné vektory řeší třídiagonální soustavu, jejíž první a poslední řádek plyne z okrajové podmínky (upnutý, přirozený nebo uzavřený).",
  },
  hermite: {
    formula: "x(t) = [x_0  x_1  x′_0  x′_1] · M_H · [t³  t²  t  1]ᵀ",
    source: {
      en: "lecture notes (Hermite/Ferguson cubics)",
      sl: "češki zapiski predavanj (lecture notes), Hermitove/Fergusonove kubike",
      cs: "skripta (lecture notes), Hermitovy/Fergusonovy kubiky",
    },
    en: "The Hermite (Ferguson) cubic through two points with given tangents there.",
    sl: "Hermitova (Fergusonova) kubika skozi dve točki z danima tangentama v njiju.",
    cs: "Hermiteova (Fergusonova) kubika procházející dvěma body s danými tečnými vektory.",
  },
  bspline: {
    formula: "x(t) = Σ_i P_i N_(i,p)(t);   de Boor: d_i^r = (1 − α_i^r) d_(i−1)^(r−1) + α_i^r d_i^(r−1)",
    source: {
      en: "CAD notes §1.2; lecture notes (B-spline curves)",
      sl: "izpiski CAD (CAD notes) §1.2; češki zapiski predavanj (lecture notes), B-zlepki",
      cs: "poznámky CAD (CAD notes) §1.2; skripta (lecture notes), B-spline křivky",
    },
    en: "A B-spline curve: the control points weighted by the basis functions of degree p over a knot vector, evaluated by de Boor's algorithm; the curve lives on [u_(p+1), u_(n+1)], whatever the knots.",
    sl: "B-zlepek: kontrolne točke, utežene z baznimi funkcijami stopnje p nad vozliščnim vektorjem, izračunan z de Boorovim algoritmom; krivulja je definirana na [u_(p+1), u_(n+1)], ne glede na vozle.",
    cs: "B-spline křivka: řídicí body vážené bázovými funkcemi stupně p nad uzlovým vektorem, počítaná de Boorovým algoritmem; křivka je definována na [u_(p+1), u_(n+1)], ať jsou uzly jakékoli.",
  },
  "insert-knot": {
    formula: "P′_i = (1 − α_i) P_(i−1) + α_i P_i,   α_i = (u − u_i)/(u_(i+p) − u_i),   k − p + 1 ≤ i ≤ k",
    source: {
      en: "CAD notes §1.2 (Boehm's algorithm)",
      sl: "izpiski CAD (CAD notes) §1.2 (Boehmov algoritem)",
      cs: "poznámky CAD (CAD notes) §1.2 (Boehmův algoritmus)",
    },
    en: "Knot insertion (Boehm): the knot u joins its span [u_k, u_(k+1)); p new control points on the old polygon replace p − 1 old ones, and the curve stays the same.",
    sl: "Vstavljanje vozla (Boehm): vozel u dodamo v njegov interval [u_k, u_(k+1)); p novih kontrolnih točk na starem poligonu nadomesti p − 1 starih, krivulja pa ostane enaka.",
    cs: "Vkládání uzlu (Boehm): uzel u přibude do svého intervalu [u_k, u_(k+1)); p nových řídicích bodů na starém polygonu nahradí p − 1 starých a křivka zůstane stejná.",
  },
  "bspline-basis": {
    formula: "N_(i,0) = [u_i ≤ t < u_(i+1)],   N_(i,j) = (t − u_i)/(u_(i+j) − u_i) N_(i,j−1) + (u_(i+j+1) − t)/(u_(i+j+1) − u_(i+1)) N_(i+1,j−1)",
    source: {
      en: "CAD notes §1.2 (Cox–de Boor); lecture notes",
      sl: "izpiski CAD (CAD notes) §1.2 (Cox–de Boor); češki zapiski predavanj (lecture notes)",
      cs: "poznámky CAD (CAD notes) §1.2 (Cox–de Boor); skripta (lecture notes)",
    },
    en: "The B-spline basis functions by the Cox–de Boor recursion: degree 0 are the indicator functions of the knot spans, and each degree blends two functions of the degree below; the triangle shows every level at t.",
    sl: "Bazne funkcije B-zlepkov po rekurziji Cox–de Boor: stopnja 0 so karakteristične funkcije vozliščnih intervalov, vsaka višja stopnja pa zlepi dve funkciji nižje; trikotnik kaže vse nivoje pri t.",
    cs: "Bázové funkce B-spline podle rekurze Cox–de Boor: stupeň 0 jsou charakteristické funkce uzlových intervalů a každý vyšší stupeň spojí dvě funkce nižšího; trojúhelník ukazuje všechny úrovně v t.",
  },
  nurbs: {
    formula: "x(t) = Σ_i w_i P_i N_(i,p)(t) / Σ_i w_i N_(i,p)(t)",
    source: {
      en: "CAD notes §1.3",
      sl: "izpiski CAD (CAD notes) §1.3",
      cs: "poznámky CAD (CAD notes) §1.3",
    },
    en: "A NURBS curve: a B-spline curve with a weight per control point (a B-spline in homogeneous coordinates, projected); conics are exact — weights 1, 1, 2 on the points (1, 0), (1, 1), (0, 1) give a quarter circle.",
    sl: "NURBS krivulja: B-zlepek z utežjo v vsaki kontrolni točki (projekcija B-zlepka v homogenih koordinatah); stožnice so točne — uteži 1, 1, 2 v točkah (1, 0), (1, 1), (0, 1) dajo četrtino krožnice.",
    cs: "Křivka NURBS: B-spline křivka s váhou u každého řídicího bodu (projekce B-spline v homogenních souřadnicích); kuželosečky jsou přesné — váhy 1, 1, 2 v bodech (1, 0), (1, 1), (0, 1) dají čtvrtkružnici.",
  },
  convert: {
    formula: "G_to = M_to⁻¹ · M_from · G_from",
    source: {
      en: "lecture notes (conversions); matrix-form notes",
      sl: "češki zapiski predavanj (lecture notes), pretvorbe; zapiski o matrični obliki (matrix-form notes)",
      cs: "skripta (lecture notes), konverze; poznámky o maticovém tvaru (matrix-form notes)",
    },
    en: "Conversion of a cubic between the Hermite, Bézier, uniform B-spline and power forms by their basis matrices.",
    sl: "Pretvorba kubike med Hermitovo, Bézierovo, enakomerno B-zlepkovno in potenčno obliko z matrikami baz.",
    cs: "Převod kubiky mezi Hermiteovým, Bézierovým, uniformním B-spline a mocninným tvarem pomocí bázových matic.",
  },
  continuity: {
    formula: "C¹: x′(1) = ¹x′(0);   G¹: x′(1) = k · ¹x′(0), k > 0",
    source: {
      en: "lecture notes (continuity at a joint)",
      sl: "češki zapiski predavanj (lecture notes), zveznost v stiku",
      cs: "skripta (lecture notes), spojitost ve spoji",
    },
    en: "The continuity at the joint of two Bézier curves: C⁰, C¹, C² and G¹, compared through their end derivatives.",
    sl: "Zveznost v stiku dveh Bézierovih krivulj: C⁰, C¹, C² in G¹, primerjani z odvodi v krajiščih.",
    cs: "Spojitost ve spoji dvou Bézierových křivek: C⁰, C¹, C² a G¹, porovnané pomocí derivací v koncových bodech.",
  },
  curvature: {
    formula: "κ = |x′ × x″| / |x′|³;   T = x′/|x′|,  B = x′ × x″ / |x′ × x″|,  N = B × T",
    source: {
      en: "thesis §2.4 (derivatives)",
      sl: "zaključna naloga (thesis) §2.4 (odvodi)",
      cs: "závěrečná práce (thesis) §2.4 (derivace)",
    },
    en: "The curvature and the Frenet frame of a Bézier, B-spline or NURBS curve at t, from its first two derivatives.",
    sl: "Ukrivljenost in Frenetov trieder Bézierove, B-zlepkovne ali NURBS krivulje pri t iz prvih dveh odvodov.",
    cs: "Křivost a Frenetův repér Bézierovy, B-spline nebo NURBS křivky v t z prvních dvou derivací.",
  },
  integrate: {
    formula: "∫₀¹ B_i^n(t) dt = 1/(n + 1),   ∫ b(t) dt = (1/(n + 1)) Σ_i b_i",
    source: {
      en: "thesis §2.2 (Bernstein polynomials); CAD notes §1.1",
      sl: "zaključna naloga (thesis) §2.2 (Bernsteinovi polinomi); izpiski CAD (CAD notes) §1.1",
      cs: "závěrečná práce (thesis) §2.2 (Bernsteinovy polynomy); poznámky CAD (CAD notes) §1.1",
    },
    en: "Integrals and antiderivatives of Bernstein polynomials, Bézier curves and B-splines, exact where rational.",
    sl: "Integrali in nedoločeni integrali Bernsteinovih polinomov, Bézierovih krivulj in B-zlepkov, točni, kjer so racionalni.",
    cs: "Integrály a primitivní funkce Bernsteinových polynomů, Bézierových křivek a B-spline, přesné, kde jsou racionální.",
  },
  ruled: {
    formula: "x(u, v) = (1 − v) c1(u) + v c2(u)",
    source: {
      en: "lecture notes (ruled surfaces); thesis §4.1",
      sl: "češki zapiski predavanj (lecture notes), premonosne ploskve; zaključna naloga (thesis) §4.1",
      cs: "skripta (lecture notes), přímkové plochy; závěrečná práce (thesis) §4.1",
    },
    en: "A ruled surface: straight lines between corresponding points of two curves.",
    sl: "Premonosna ploskev: daljice med istoležnimi točkami dveh krivulj.",
    cs: "Přímková plocha: úsečky mezi odpovídajícími body dvou křivek.",
  },
  ferguson: {
    formula: "x(u, v) = U · M_H · X_H · M_Hᵀ · Vᵀ",
    source: {
      en: "lecture notes (Hermite surfaces)",
      sl: "češki zapiski predavanj (lecture notes), Hermitove ploskve",
      cs: "skripta (lecture notes), Hermitovy plochy",
    },
    en: "The Ferguson (bicubic Hermite) patch from the corner points, their tangents and twists.",
    sl: "Fergusonova (bikubična Hermitova) ploskev iz oglišč, njihovih tangent in zasukov.",
    cs: "Fergusonova (bikubická Hermiteova) plocha z rohových bodů, jejich tečných vektorů a zkrutů.",
  },
  "bspline-surface": {
    formula: "x(u, v) = Σ_i Σ_j P_ij N_(i,p)(u) N_(j,q)(v)",
    source: {
      en: "lecture notes (B-spline surfaces); CAD notes §1.2",
      sl: "češki zapiski predavanj (lecture notes), B-zlepkovne ploskve; izpiski CAD (CAD notes) §1.2",
      cs: "skripta (lecture notes), B-spline plochy; poznámky CAD (CAD notes) §1.2",
    },
    en: "A tensor-product B-spline surface over two knot vectors.",
    sl: "Tenzorska B-zlepkovna ploskev nad dvema vozliščnima vektorjema.",
    cs: "Tenzorová B-spline plocha nad dvěma uzlovými vektory.",
  },
  "nurbs-surface": {
    formula: "x(u, v) = Σ Σ w_ij P_ij N_(i,p)(u) N_(j,q)(v) / Σ Σ w_ij N_(i,p)(u) N_(j,q)(v)",
    source: {
      en: "CAD notes §1.3",
      sl: "izpiski CAD (CAD notes) §1.3",
      cs: "poznámky CAD (CAD notes) §1.3",
    },
    en: "A tensor-product NURBS surface: a B-spline surface with a weight per control point.",
    sl: "Tenzorska NURBS ploskev: B-zlepkovna ploskev z utežjo v vsaki kontrolni točki.",
    cs: "Tenzorová plocha NURBS: B-spline plocha s váhou u každého řídicího bodu.",
  },
  circle: {
    formula: "arcs of angle θ ≤ 90° with weights 1, cos(θ/2), 1",
    source: {
      en: "CAD notes §1.3 (conics)",
      sl: "izpiski CAD (CAD notes) §1.3 (stožnice)",
      cs: "poznámky CAD (CAD notes) §1.3 (kuželosečky)",
    },
    en: "A whole circle as a NURBS curve of degree 2, exact.",
    sl: "Cela krožnica kot NURBS krivulja stopnje 2, točna.",
    cs: "Celá kružnice jako křivka NURBS stupně 2, přesná.",
  },
  arc: {
    formula: "arcs of angle θ ≤ 90° with weights 1, cos(θ/2), 1",
    source: {
      en: "CAD notes §1.3 (conics)",
      sl: "izpiski CAD (CAD notes) §1.3 (stožnice)",
      cs: "poznámky CAD (CAD notes) §1.3 (kuželosečky)",
    },
    en: "A circular arc as a NURBS curve of degree 2, exact.",
    sl: "Krožni lok kot NURBS krivulja stopnje 2, točen.",
    cs: "Kruhový oblouk jako křivka NURBS stupně 2, přesný.",
  },
  curve: {
    formula: "x(t) = [x(t); y(t); z(t)]",
    source: {
      en: "thesis (curves as Octave expressions, appendix C)",
      sl: "zaključna naloga (thesis), krivulje kot izrazi Octave, priloga C",
      cs: "závěrečná práce (thesis), křivky jako výrazy Octave, příloha C",
    },
    en: "Samples of a curve written as the thesis writes curves, e.g. [u; 0; u-u^2].",
    sl: "Vzorci krivulje, zapisane tako kot v diplomski nalogi, npr. [u; 0; u-u^2].",
    cs: "Vzorky křivky zapsané jako v diplomové práci, např. [u; 0; u-u^2].",
  },
  surface: {
    formula: "x(u, v) = [x(u, v); y(u, v); z(u, v)]",
    source: {
      en: "thesis (surfaces as Octave expressions)",
      sl: "zaključna naloga (thesis), ploskve kot izrazi Octave",
      cs: "závěrečná práce (thesis), plochy jako výrazy Octave",
    },
    en: "Samples of a surface written as an expression in u and v on a grid.",
    sl: "Vzorci ploskve, zapisane kot izraz v u in v, na mreži.",
    cs: "Vzorky plochy zapsané jako výraz v u a v na mřížce.",
  },
  script: {
    formula: "u = linspace(0, 1, N);  c1 = [u; zeros(1, N); u - u.^2];  …",
    source: {
      en: "thesis, appendices C and D (data scripts)",
      sl: "zaključna naloga (thesis), prilogi C in D (podatkovni skripti)",
      cs: "závěrečná práce (thesis), přílohy C a D (datové skripty)",
    },
    en: "Runs a thesis-style data script (assignments, for loops) and prints its variables.",
    sl: "Izvede podatkovni skript v slogu diplomske naloge (prireditve, zanke for) in izpiše njegove spremenljivke.",
    cs: "Spustí datový skript ve stylu diplomové práce (přiřazení, cykly for) a vypíše jeho proměnné.",
  },
  thesis: {
    formula: "Primer 2.4: b(1/2) = (7/2, 3/2, 3/4);   Primer 4.3: x(1/5, 1/2) = (1/5, 3/10, 19/50)",
    source: {
      en: "thesis (Primer 2.4, 3.2, 4.3; appendices C and D)",
      sl: "zaključna naloga (thesis), Primer 2.4, 3.2, 4.3; prilogi C in D",
      cs: "závěrečná práce (thesis), Primer 2.4, 3.2, 4.3; přílohy C a D",
    },
    en: "The thesis's worked examples and appendix runs, with their steps and pictures.",
    sl: "Rešeni primeri in zagoni iz dodatkov diplomske naloge, s koraki in slikami.",
    cs: "Řešené příklady a běhy z příloh diplomové práce, s kroky a obrázky.",
  },
  course: {
    formula: "M_C = (1/6) [−1 3 −3 1; 3 −6 3 0; −3 0 3 0; 1 4 1 0]  …",
    source: {
      en: "CAD notes; matrix-form notes; lecture notes",
      sl: "izpiski CAD (CAD notes); zapiski o matrični obliki (matrix-form notes); češki zapiski predavanj (lecture notes)",
      cs: "poznámky CAD (CAD notes); poznámky o maticovém tvaru (matrix-form notes); skripta (lecture notes)",
    },
    en: "The worked examples of the three sets of course notes, with their pictures.",
    sl: "Rešeni primeri vseh treh zapiskov predavanj, s slikami.",
    cs: "Řešené příklady všech tří sad poznámek z přednášek, s obrázky.",
  },
  serve: {
    formula: "cagd serve --port 8000",
    source: {
      en: "—",
      sl: "—",
      cs: "—",
    },
    en: "Serves this page on localhost (in the program only; the page itself is already served).",
    sl: "Ponudi to stran na localhost (samo v programu; stran je že ponujena).",
    cs: "Poskytne tuto stránku na localhost (jen v programu; stránka už je poskytnutá).",
  },
};

/** The explanation of subcommand `name` in the current language: {text, formula, source}. */
export function explanation(name) {
  const e = E[name];
  if (!e) return null;
  return { text: e[lang()] ?? e.en, formula: e.formula, source: e.source[lang()] ?? e.source.en };
}

/** Fills `box` (a <details>) with the explanation of `name`, or hides it. */
export function explainInto(box, name) {
  const e = explanation(name);
  box.hidden = !e;
  if (!e) return;
  box.replaceChildren();
  const summary = document.createElement("summary");
  summary.textContent = t("explanation");
  const p = document.createElement("p");
  p.textContent = e.text;
  const f = document.createElement("p");
  f.className = "formula";
  const code = document.createElement("code");
  code.textContent = e.formula;
  f.append(`${t("formula")}: `, code);
  const s = document.createElement("p");
  s.className = "source";
  s.textContent = `${t("source")}: ${e.source}`;
  box.append(summary, p, f, s);
  box.dataset.construction = name;
}

/** The subcommands with an explanation (for the tests). */
export const explained = Object.keys(E);

/** Every explanation's source in the three languages (for the tests). */
export const sources = Object.fromEntries(Object.entries(E).map(([name, e]) => [name, e.source]));
