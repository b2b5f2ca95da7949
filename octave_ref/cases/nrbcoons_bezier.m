% Case "nrbcoons_bezier": bilinearly blended Coons patches of Bezier boundary curves built by
% octave-nurbs (nrbmak with clamped knots [0...0 1...1], nrbcoons) and evaluated with nrbeval.
%
% For each case r = 1, 2: corners Q = [P1 P2 P3 P4] = x(0,0), x(1,0), x(0,1), x(1,1) uniform in
% [-3, 3]^3 and Bezier boundary curves with random inner control points (uniform in [-3, 3]^3):
%   c1 = x(u,0) from P1 to P2, c2 = x(u,1) from P3 to P4    (nrbcoons's ucrv1, ucrv2)
%   d1 = x(0,v) from P1 to P3, d2 = x(1,v) from P2 to P4    (nrbcoons's vcrv1, vcrv2)
% of degrees r = 1: (3, 3, 3, 3); r = 2: (3, 2, 4, 1).
% Inputs:  r<r>_c1, r<r>_c2, r<r>_d1, r<r>_d2   3 x (p+1), the control points (one per column)
%          r<r>_tu  1 x 11, linspace(0,1,11)      r<r>_tv  1 x 7, linspace(0,1,7)
% Outputs: r<r>_P   11 x 7 x 3, P(i,j,:) = x(tu(i), tv(j)): nrbeval(nrbcoons(...), {tu, tv})
%          permuted from octave-nurbs's 3 x nu x nv to the crate's grid layout
pkg load nurbs
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
save_precision(17);

rand('seed', 46);
degrees = [3 3 3 3; 3 2 4 1];
names = {};
for r = 1:rows(degrees)
    Q = 6*rand(3,4) - 3;
    p = degrees(r,:);
    ends = {[1 2], [3 4], [1 3], [2 4]};
    ctrl = cell(1,4);
    crv = cell(1,4);
    for k = 1:4
        inner = 6*rand(3, p(k)-1) - 3;
        ctrl{k} = [Q(:,ends{k}(1)) inner Q(:,ends{k}(2))];
        crv{k} = nrbmak(ctrl{k}, [zeros(1,p(k)+1) ones(1,p(k)+1)]);
    end;
    srf = nrbcoons(crv{1}, crv{2}, crv{3}, crv{4});
    tu = linspace(0,1,11);
    tv = linspace(0,1,7);
    P = permute(nrbeval(srf, {tu, tv}), [2 3 1]);
    key = sprintf('r%d', r);
    c1 = ctrl{1}; c2 = ctrl{2}; d1 = ctrl{3}; d2 = ctrl{4};
    vars = {'c1', 'c2', 'd1', 'd2', 'tu', 'tv', 'P'};
    for k = 1:numel(vars)
        eval(sprintf('%s_%s = %s;', key, vars{k}, vars{k}));
        names{end+1} = sprintf('%s_%s', key, vars{k});
    end;
end;
save('-text', fullfile(outdir, 'nrbcoons_bezier.txt'), names{:});
