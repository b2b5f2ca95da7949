% cagd_test_bad_input () -- the package's bad-input table, run in this one Octave process:
% every row must raise an Octave error with the expected identifier (cagd:<kind>), and where a
% text is given the message must contain it (the library's own text, which the command line
% prints after the argument name).  Afterwards the process must be alive and correct: the
% thesis's Primer 2.4, a NURBS circle and the default limits come out right.  Includes a
% deliberate Rust panic (cagd:internal), caught at the boundary.
function cagd_test_bad_input ()
  pkg load nurbs;
  P = [0 0 8 4; 0 2 2 0; 0 2 0 0];
  h = sqrt (2) / 2;
  crv = struct ("form", "B-NURBS", "dim", 4, "number", 3, ...
                "coefs", [1 h 0; 0 h 1; 0 0 0; 1 h 1], "knots", [0 0 0 1 1 1], "order", 3);
  srf = nrbtestsrf ();
  U = [0 0 0 1/2 1 1 1];
  N = 5; t = linspace (0, 1, N); o = ones (1, N); z = zeros (1, N);
  c1 = [t; z; t - t.^2]; c2 = [t; o; t]; d1 = [z; t.^2; t - t.^2]; d2 = [o; t; t];
  P1 = [0;0;0]; P2 = [1;0;0]; P3 = [0;1;0]; P4 = [1;1;1];
  x = [0 0.5 1];
  g_u = [[t; 0*o; t-t.^2] [t; 0.5*o; 0.5+t-t.^2] [t; o; 1+t-t.^2]];
  g_v = [[0*o; t; t] [0.5*o; t; 0.25+t] [o; t; t]];
  g_uv = [0 0 0 0 0.5 0.5 0 1 1; 0.5 0 0.25 0.5 0.5 0.75 0.5 1 1.25; 1 0 0 1 0.5 0.5 1 1 1];
  cu = {[0 0; 0 1; 0 1], [0.5 0.5; 0 1; 0.25 1.25], [1 1; 0 1; 0 1]};
  cv = {[0 0.5 1; 0 0 0; 0 0.5 0], [0 0.5 1; 0.5 0.5 0.5; 0.5 1 0.5], [0 0.5 1; 1 1 1; 1 1.5 1]};
  bc = {[0 0.5 1; 0 0 0; 0 0.5 0], [0 1; 1 1; 0 1], [0 0 0; 0 0 1; 0 0.5 0], [1 1; 0 1; 0 1]};

  T = {
    % wrong classes
    "int32 control points",     @() deCasteljau (int32 ([0 1]), 3),         "cagd:class", "kontrolneT: int32 is not accepted"
    "uint8 control points",     @() deCasteljau (uint8 ([0 1]), 3),         "cagd:class", "uint8 is not accepted"
    "single control points",    @() deCasteljau (single ([0 1]), 3),        "cagd:class", "single is not accepted"
    "logical control points",   @() deCasteljau (true (1, 2), 3),           "cagd:class", "logical is not accepted"
    "complex control points",   @() deCasteljau ([0 1i], 3),                "cagd:class", "complex double is not accepted"
    "sparse control points",    @() deCasteljau (sparse ([0 1]), 3),        "cagd:class", "sparse double is not accepted"
    "cell control points",      @() deCasteljau ({[0 1]}, 3),               "cagd:class", "a cell array is not accepted"
    "struct without fields",    @() deCasteljau (struct (), 3),             "cagd:class", "a struct without fields is not accepted"
    "function handle",          @() deCasteljau (@sin, 3),                  "cagd:class", "function_handle is not accepted"
    "text control points",      @() deCasteljau ("abc", 3),                 "cagd:class", "text (char) is not accepted"
    "int8 N",                   @() deCasteljau ([0 1], int8 (3)),          "cagd:class", "N: int8 is not accepted"
    "int16 corner",             @() krpaCoons (c1, c2, d1, d2, P1, P2, P3, int16 (P4)), "cagd:class", "P4: int16"
    "logical parameter",        @() cagd_bezier (P, true),                  "cagd:class", "logical"
    "complex nodes",            @() Lagrange ([0 1i], 1, 0.5),              "cagd:class", "complex"
    "cell instead of curves",   @() cagd_gordon ([0 1], cv, x, x, 0.5, 0.5), "cagd:class", "cu: double is not accepted"
    "NURBS: struct w/o fields", @() cagd_nrbeval (struct (), 0.5),          "cagd:struct", "has no field"
    "NURBS: missing coefs",     @() cagd_nrbeval (struct ("form", "B-NURBS"), 0.5), "cagd:struct", "has no field"
    "NURBS: struct array",      @() cagd_nrbeval ([crv crv], 0.5),          "cagd:struct", "struct array is not a NURBS structure"
    "NURBS: a matrix",          @() cagd_nrbeval (eye (4), 0.5),            "cagd:struct", "double is not a NURBS structure"
    "NURBS: wrong form",        @() cagd_nrbeval (setfield (crv, "form", "X"), 0.5), "cagd:struct", "not a recognised NURBS"
    % empty
    "no control points",        @() deCasteljau ([], 3),                    "cagd:empty", "kontrolneT: empty (0×0)"
    "empty net",                @() ploskevB (zeros (0, 3), 2),             "cagd:empty", "kontrolneT: empty (0×3)"
    "empty curve",              @() cagd_bezier (zeros (2, 0), 0.5),        "cagd:empty", "P: empty"
    "empty nodes",              @() krpaGordon (g_u, g_v, g_uv, [], x, N),  "cagd:empty", "x_u: empty"
    "empty knots (twin)",       @() cagd_bspeval (2, [0 1 2], [], 0.5),     "cagd:value", "k: degree 2 and 3 control points need 6 knots, not 0"
    % not finite
    "NaN control point",        @() deCasteljau ([0 NaN], 3),               "cagd:nonfinite", "kontrolneT: value 2 is not finite (NaN)"
    "Inf parameter",            @() cagd_bezier (P, Inf),                   "cagd:nonfinite", "t: value 1 is not finite (inf)"
    "NaN Lagrange parameter",   @() Lagrange ([0 1], 1, NaN),               "cagd:nonfinite", "not finite"
    "NaN B-spline parameter",   @() cagd_bspline (2, [0 1 2], [], NaN),     "cagd:nonfinite", "t: value 1 is not finite (NaN)"
    % finite arguments, results beyond the doubles: refused, never returned as Inf or NaN
    "Bezier at t = 5",          @() cagd_bezier ([1e308 -1e308], 5),        "cagd:overflow", "t: Bézier curve points: value 1 is not a finite double (-inf)"
    "Hermite to B-spline",      @() cagd_convert (ones (2, 4) * 1.7e308, "hermite", "bspline"), "cagd:overflow", "G: the geometry's Bézier points"
    "derivative of ±1.7e308",   @() cagd_bezier_derivative ([1.7e308 -1.7e308 1.7e308], 0.5), "cagd:overflow", "Bézier derivative control points"
    "weighted point w P",       @() cagd_nurbs (1, [1e300 0], [1e10 1], [0 0 1 1], 0.5), "cagd:overflow", "w: NURBS weights"
    "knots 5e-324 apart",       @() cagd_bspline (2, [0 1 2 3], [0 0 0 5e-324 1e-320 1e-320 1e-320], 1e-321), "cagd:overflow", "U: knot vector"
    "Coons of 1.7e308",         @() cagd_coons (1.7e308 * ones (3, 2), 1.7e308 * ones (3, 2), 1.7e308 * ones (3, 2), 1.7e308 * ones (3, 2), 0.5, 0.5), "cagd:overflow", "X: the result overflows the range of doubles"
    "Bernstein at 1e103",       @() cagd_bernstein (3, 1e103),              "cagd:overflow", "B: the result overflows"
    "Lagrange at 1e300",        @() Lagrange ([0 1 2], 1, 1e300),           "cagd:overflow", "Lagrange basis value"
    "vrednostCoons at 1e300",   @() vrednostCoons (1e300, 1e300, P1, P2, P1, P3, P1, P3, P2, P4), "cagd:overflow", "vrednostCoons: T: value 1 is not a finite double"
    "bilinearna at 1e308",      @() bilinearna ([0 0 0 1 0 0; 0 1 0 1 1 1], 1e308, 1e308, 3), "cagd:overflow", "bilinearna: L:"
    "krpaGordon of 1.7e308",    @() krpaGordon (1.7e308 * ones (3, 10), 1.7e308 * ones (3, 10), 1.7e308 * ones (2, 6), [0 1], [0 1], 5), "cagd:overflow", "krpaGordon: R:"
    "deCasteljau at the max",   @() deCasteljau (realmax * ones (1, 30), 7), "cagd:overflow", "Bézier curve points"
    % values
    "fractional N",             @() deCasteljau ([0 1], 2.5),               "cagd:value", "N: 2.5 is not a non-negative integer"
    "negative N",               @() deCasteljau ([0 1], -1),                "cagd:value", "N: -1 is not a non-negative integer"
    "basis index out of range", @() Lagrange ([0 1], 3, 0.5),               "cagd:value", "m: expected the index of a node, 1 ≤ m ≤ 2, got 3"
    "derivative above degree",  @() cagd_bezier_derivative (P, 0.5, 4),     "cagd:value", "derivative order 4 exceeds the degree 3"
    "unknown end condition",    @() cagd_spline ([0 1 0], 0.5, "periodic"), "cagd:value", "ends: 'periodic'"
    "unknown cubic form",       @() cagd_convert ([0 1 2 3], "bezier", "monomial"), "cagd:value", "to: 'monomial'"
    "exact: unparsable text",   @() cagd_bezier ("[0 1", 0.5, "exact"),     "cagd:value", "P:"
    "exact: division by zero",  @() cagd_bezier ([0 1], "1/0", "exact"),    "cagd:value", "t:"
    % shapes
    "columns not in threes",    @() tenzor ([0 1 2 3]),                     "cagd:shape", "divisible by 3"
    "short boundary curve",     @() krpaCoons (c1, c2, d1, d2(:, 1:4), P1, P2, P3, P4), "cagd:shape", "d2: expected 3×5, found 3×4"
    "corner of wrong size",     @() vrednostCoons (0.5, 0.5, P1, P1, P1, [0;0], P1, P1, P1, P1), "cagd:shape", "d2: expected a 3×1 column"
    "3-D control points",       @() deCasteljau (zeros (2, 2, 2), 3),       "cagd:shape", "an array of size 2×2×2"
    "vector for a scalar",      @() cagd_bezier_subdivide ([0 1], [0.2 0.4]), "cagd:shape", "t: an array of size 1×2"
    "NURBS coefs not 4 rows",   @() cagd_nrbeval (setfield (crv, "coefs", [1 0 0; 0 0 1; 1 1 1]), 0.5), "cagd:shape", "index 4 is out of bound 3"
    % domain, knots, weights, nodes
    "NURBS outside knots",      @() cagd_nrbeval (crv, 1.5),                "cagd:domain", "u: 1.5 is outside the knots [0, 1]"
    "span outside knots",       @() cagd_findspan (3, 2, -0.1, U),          "cagd:value", "u: a value is outside the knots"
    "B-spline outside domain",  @() cagd_bspline (2, [0 1 2], [], 2),       "cagd:domain", "outside the domain"
    "decreasing knots",         @() cagd_bspline (1, [0 1], [0 1 0 1], 0.5), "cagd:knots", "knot 3 (0) is below the knot before it (1)"
    "knot count",               @() cagd_bspline (2, [0 1 2], [0 0 0 1 1 1 1], 0.5), "cagd:knots", "expected 6 knots"
    "span beyond the knots",    @() cagd_findspan (3, 2, 0.5, [0 0 1 1]),   "cagd:shape", "index 5 is out of bound 4"
    "negative weight",          @() cagd_nurbs (2, [0 1 2], [1 -1 1], [], 0.5), "cagd:weights", "weight 2 is -1; weights must be positive"
    "zero weight in NURBS",     @() cagd_nurbs (2, [1 0 0; 0 0 1], [1 0 1], [], 0.5), "cagd:weights", "weights must be positive"
    "repeated nodes",           @() Lagrange ([1 1], 1, 0.5),               "cagd:nodes", "nodes 1 and 2 are equal (1)"
    "unsorted nodes",           @() krpaGordon (g_u, g_v, g_uv, [0 1 0.5], x, N), "cagd:nodes", "nodes must increase"
    % constructions
    "corners do not meet",      @() krpaCoons (c1, c2, d1, d2, P1, P2, [1;1;1], P4), "cagd:corners", "do not meet at the corners"
    "Coons corner (as the CLI)", @() cagd_coons ([0 0 0; 1 0 0]', [0 1 0; 1 1 1]', [0 0 0; 0 1 0]', [1 0 0; 1 1 2]', 0.5, 0.5), ...
                                "cagd:corners", "cagd_coons: c1/c2/d1/d2: boundary curves do not meet at the corners (relative tolerance 1e-10): at x(1,1) (P4) c2(1) and d2(1) differ by 1e0 (allowed 2e-10)"
    "network does not cross",   @() krpaGordon (g_u, g_v, g_uv + 0.25, x, x, N), "cagd:network", "curve network is not compatible"
    "Bezier network",           @() cagd_gordon (cu, {cv{1}, cv{2} + 1, cv{3}}, x, x, 0.5, 0.5), "cagd:network", "not compatible"
    % huge inputs: refused before anything is allocated
    "N = 1e12 samples",         @() deCasteljau ([0 1], 1e12),              "cagd:limit", "N: 1000000000000 exceeds the limit of 1000000 (raise it with cagd_limits (\"max_samples\", VALUE))"
    "grid of 1e10 points",      @() ploskevB ([0 0 0], 1e5),                "cagd:limit", "exceeds the limit of 10000000"
    "degree 2000",              @() deCasteljau (zeros (2, 2001), 3),       "cagd:limit", "kontrolneT (degree): 2000 exceeds the limit of 1000"
    "patch grid 25e6",          @() cagd_bezier_patch (ones (3, 2, 2), rand (1, 5000), rand (1, 5000)), "cagd:limit", "max_grid_points"
    "NURBS grid 16e6",          @() cagd_nrbeval (srf, {linspace(0, 1, 4000), linspace(0, 1, 4000)}), "cagd:limit", "16000000 exceeds the limit of 1000000"
    "exact work",               @() cagd_bezier (zeros (1, 1001), linspace (0, 1, 1e5), "exact"), "cagd:limit", "max_"
    "thesis work",              @() deCasteljau (zeros (1, 1001), 1e6),     "cagd:limit", "N: estimated operations: 1002001000000 exceeds the limit of 2000000000 (raise it with cagd_limits (\"max_work\", VALUE)); expected fewer points or a lower degree"
    "twin work",                @() cagd_bspeval (1000, zeros (1, 1001), [zeros(1, 1001) ones(1, 1001)], linspace (0, 1, 1e6)), "cagd:limit", "u: estimated operations:"
    % arguments
    "too few arguments",        @() deCasteljau ([0 1]),                    "cagd:nargin", "deCasteljau: called with 1 argument(s); expected 2"
    "too many arguments",       @() krpaCoons (1, 2, 3, 4, 5, 6, 7, 8, 9),  "cagd:nargin", "expected 8"
    "unknown limit",            @() cagd_limits ("samples", 10),            "cagd:value", "no limit 'samples'"
    % the boundary itself
    "a Rust panic",             @() __cagd__ ("__panic__"),                 "cagd:internal", "a deliberate panic, to test the boundary"
    "no such function",         @() __cagd__ ("no_such_function"),          "cagd:internal", "no package function"
  };
  failed = {};
  for k = 1:rows (T)
    [label, f, id, text] = T{k, :};
    try
      f ();
      failed{end+1} = sprintf ("%s: no error", label);
    catch err
      if ! strcmp (err.identifier, id)
        failed{end+1} = sprintf ("%s: identifier %s, expected %s (%s)", label, err.identifier, id, err.message);
      elseif isempty (strfind (err.message, text))
        failed{end+1} = sprintf ("%s: message '%s' lacks '%s'", label, err.message, text);
      end
    end
  end
  % A limit lowered for the session applies to the next calls, and the defaults come back.
  unwind_protect
    cagd_limits ("max_degree", 2);
    try
      cagd_bezier (P, 0.5);
      failed{end+1} = "max_degree 2: no error";
    catch err
      if ! strcmp (err.identifier, "cagd:limit")
        failed{end+1} = sprintf ("max_degree 2: %s", err.identifier);
      end
    end
  unwind_protect_cleanup
    cagd_limits ("default");
  end_unwind_protect
  % Alive and correct afterwards.
  alive = isequal (deCasteljau (P, 3)(:, 2), [3.5; 1.5; 0.75]) ...
          && max (abs (sqrt (sum (cagd_nrbeval (nrbcirc (1), linspace (0, 1, 9)).^2)) - 1)) < 1e-15 ...
          && cagd_limits ().max_degree == 1000 ...
          && isequal (cagd_bezier (P, 0.5, "exact"), {"7/2"; "3/2"; "3/4"});
  printf ("  %d bad inputs, each refused with its identifier in this process; %d mismatch(es)\n", ...
          rows (T) + 1, numel (failed));
  for k = 1:numel (failed)
    printf ("    %s\n", failed{k});
  end
  if ! alive
    failed{end+1} = "the process is not correct after the errors";
  end
  if ! isempty (failed)
    error ("bad input: %d failure(s)", numel (failed));
  end
  printf ("  afterwards: Primer 2.4, a NURBS circle, exact fractions and the default limits are right\n");
  printf ("bad input: OK, %d case(s)\n", rows (T) + 1);
end
