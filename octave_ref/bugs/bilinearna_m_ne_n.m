% Bug: bilinearna is wrong for m ~= n.  It runs k = 1:m bilinear steps over i = 1:(m-k+1),
% j = 1:(n-k+1): for m < n it stops with a row of n-m+1 points and returns the first; for
% m > n the steps after the n-th find no j and change nothing; for m = 0 no step runs and it
% returns the zeros its work array started with.  Each net below is compared with the Bezier
% patch sum_i sum_j b_ij B_i^m(u) B_j^n(v) at (u, v) = (0.5, 0.25).  m = n is right.
bug_setup;
u = 0.5;
v = 0.25;
nets = {[1 0 0 2 1 0; 0 1 3 1 2 4], ...                  % (m, n) = (1, 1)
        [1 0 0 2 1 0 4 0 1; 0 1 3 1 2 4 2 2 0], ...      % (1, 2)
        [1 0 0 2 1 0; 0 1 3 1 2 4; 3 3 1 0 0 2], ...     % (2, 1)
        [1 2 3 4 5 6 7 8 9], ...                         % (0, 2)
        [1 2 3; 4 5 6; 7 8 9]};                          % (2, 0)
for k = 1:numel(nets)
    B = nets{k};
    m = rows(B) - 1;
    n = columns(B)/3 - 1;
    A = tenzor(B);
    exact = zeros(1, 3);
    for i = 0:m
        for j = 0:n
            w = nchoosek(m, i) * u^i * (1-u)^(m-i) * nchoosek(n, j) * v^j * (1-v)^(n-j);
            exact = exact + w * reshape(A(i+1, j+1, :), 1, 3);
        end;
    end;
    L = bilinearna(B, u, v, 5);
    printf('(m, n) = (%d, %d): bilinearna %-24s Bezier %-24s %s\n', m, n, ...
           mat2str(reshape(L, 1, 3), 6), mat2str(exact, 6), ...
           {'WRONG', 'same'}{1 + (max(abs(reshape(L, 1, 3) - exact)) < 1e-12)});
end;
