% Case "lagrange_basis": the Lagrange basis of the fixed Lagrange.m (product form).
%
% Node sets: x1 = [0 0.5 1] (appendix D), x2 = 6 sorted uniform nodes in [0, 1], x3 = the 9
% Chebyshev-Lobatto points (1 - cos(pi*(0:8)/8))/2.  Parameters: t1 = linspace(0,1,21),
% t2 = [linspace(-0.1, 1.1, 61), x2] (extrapolation and the nodes themselves), t3 =
% linspace(0,1,101).
% Inputs:  x<k>, t<k>
% Outputs: L<k>   numel(x<k>) x numel(t<k>), L<k>(i, :) = Lagrange(x<k>, i, t<k>)
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
save_precision(17);

rand('seed', 45);
x1 = [0 0.5 1];
t1 = linspace(0,1,21);
x2 = sort(rand(1,6));
t2 = [linspace(-0.1, 1.1, 61), x2];
x3 = (1 - cos(pi*(0:8)/8))/2;
t3 = linspace(0,1,101);
names = {};
for k = 1:3
    x = eval(sprintf('x%d', k));
    t = eval(sprintf('t%d', k));
    L = zeros(numel(x), numel(t));
    for i = 1:numel(x)
        L(i,:) = Lagrange(x, i, t);
    end;
    eval(sprintf('L%d = L;', k));
    names(end+1:end+3) = {sprintf('x%d', k), sprintf('t%d', k), sprintf('L%d', k)};
end;
save('-text', fullfile(outdir, 'lagrange_basis.txt'), names{:});
