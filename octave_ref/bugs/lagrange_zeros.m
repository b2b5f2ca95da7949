% Bug: Lagrange starts the product at v = zeros(size(u)), so every factor multiplies zero and
% the basis polynomial is 0 everywhere -- even at its own node, where it must be 1.  Nodes of
% appendix D, x = [0 0.5 1].
bug_setup;
x = [0 0.5 1];
u = linspace(0, 1, 5);
for m = 1:3
    printf('Lagrange(x, %d, %s) = %s;  at its node x(%d) = %g: %g\n', m, mat2str(u), ...
           mat2str(Lagrange(x, m, u)), m, x(m), Lagrange(x, m, x(m)));
end;
