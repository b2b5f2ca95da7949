% Bug: deCasteljau interpolates ROWS (coordinates) where the points are COLUMNS.
% With as many control points as coordinates (3 points in 3-D) the original runs to the end,
% but the curve it draws is not the Bezier curve of the points: each step mixes the x, y and z
% rows instead of neighbouring points, and the point stored is column 1 of the result, a
% combination of the coordinates of b0 alone.
bug_setup;
P = [1 0 2; 2 2 0; 3 0 3];          % b0 = (1,2,3), b1 = (0,2,0), b2 = (2,0,3), as columns
N = 5;
deCasteljau(P, N);
T = CAGD_PLOTS{1}(2:4);              % plot3(T(1,:), T(2,:), T(3,:)): the curve it drew
t = linspace(0, 1, N);
B = [(1-t).^2; 2*t.*(1-t); t.^2];    % Bernstein basis of degree 2
C = P * B;                           % the Bezier curve of the columns of P
printf('t          = %s\n', mat2str(t));
printf('drawn x    = %s\n', mat2str(T{1}, 6));
printf('drawn y    = %s\n', mat2str(T{2}, 6));
printf('drawn z    = %s\n', mat2str(T{3}, 6));
printf('Bezier x   = %s\n', mat2str(C(1,:), 6));
printf('Bezier y   = %s\n', mat2str(C(2,:), 6));
printf('Bezier z   = %s\n', mat2str(C(3,:), 6));
printf('max |drawn - Bezier| = %g\n', max(abs([T{1}; T{2}; T{3}] - C)(:)));
