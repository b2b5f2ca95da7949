% Bug: deCasteljau overwrites its argument kontrolneT in place.
% Every parameter t(k) after the first starts from the scheme left by t(k-1) instead of the
% control points, so the point drawn for the same t depends on N (here t = 0.5, which is
% t(2) for N = 3 and t(3) for N = 5); and the "control polygon" plotted at the end is that
% leftover scheme, not the control points.
bug_setup;
P = [1 0 2; 2 2 0; 3 0 3];          % 3 points in 3-D, so the original runs (see decasteljau_rows_for_points)
deCasteljau(P, 3);
drawn_N3 = [CAGD_PLOTS{1}{2}(2); CAGD_PLOTS{1}{3}(2); CAGD_PLOTS{1}{4}(2)];
polygon = [CAGD_PLOTS{2}{2}; CAGD_PLOTS{2}{3}; CAGD_PLOTS{2}{4}];
CAGD_PLOTS = {};
deCasteljau(P, 5);
drawn_N5 = [CAGD_PLOTS{1}{2}(3); CAGD_PLOTS{1}{3}(3); CAGD_PLOTS{1}{4}(3)];
printf('point drawn at t = 0.5 with N = 3: %s\n', mat2str(drawn_N3', 6));
printf('point drawn at t = 0.5 with N = 5: %s\n', mat2str(drawn_N5', 6));
printf('control points passed (columns):   %s\n', mat2str(P, 6));
printf('"control polygon" drawn (N = 3):   %s\n', mat2str(polygon, 6));
