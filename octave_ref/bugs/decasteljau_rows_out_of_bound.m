% Bug: deCasteljau interpolates ROWS (coordinates) where the points are COLUMNS.
% With thesis Primer 2.4 (4 control points in 3-D, one per column, as the plotting code of the
% original reads them) the inner loop i = 1:(n-1) = 1:3 reaches row i+1 = 4 of a 3-row matrix.
bug_setup;
P = [0 0 8 4; 0 2 2 0; 0 2 0 0];   % Primer 2.4: b0 = (0,0,0), b1 = (0,2,2), b2 = (8,2,0), b3 = (4,0,0)
printf('size(P) = %dx%d (3 coordinates, 4 control points)\n', size(P));
deCasteljau(P, 5);
