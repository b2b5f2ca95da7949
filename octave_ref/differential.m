% differential(infile, outfile) -- the Octave side of the live differential test
% (crates/cagd-octave/tests/it/differential.rs): runs every case of infile through the FIXED thesis functions
% (octave_ref/fixed/ must be on the path) and saves every output into outfile.
%
% infile (written by the crate's text-format writer, read here with load):
%   count            the number of cases
%   c<k>_fn          the function of case k (a string): deCasteljau, ploskevB, bilinearna,
%                    tenzor, linspace, Lagrange, vrednostCoons, krpaCoons or krpaGordon
%   c<k>_<argument>  its arguments, named as in the function's signature (P, N, B, u, v, a, b,
%                    x, m, c1, c2, d1, d2, P1..P4, g_u, g_v, g_uv, x_u, x_v)
% outfile (save -text, save_precision(17)): c<k>_<output> for every output of case k, named as
%   in the fixed function (T, P, L, A, y, v, T/rc/rd/rcd, R/P).
% The last line printed is "differential: OK, <count> case(s)" when every case ran.
function differential(infile, outfile)
    S = load(infile);
    count = S.count;
    out = struct();
    for k = 1:count
        p = sprintf('c%d_', k);
        arg = @(name) S.([p name]);
        switch arg('fn')
            case 'deCasteljau'
                out.([p 'T']) = deCasteljau(arg('P'), arg('N'));
            case 'ploskevB'
                out.([p 'P']) = ploskevB(arg('B'), arg('N'));
            case 'bilinearna'
                out.([p 'L']) = bilinearna(arg('B'), arg('u'), arg('v'), arg('N'));
            case 'tenzor'
                out.([p 'A']) = tenzor(arg('B'));
            case 'linspace'
                out.([p 'y']) = linspace(arg('a'), arg('b'), arg('N'));
            case 'Lagrange'
                out.([p 'v']) = Lagrange(arg('x'), arg('m'), arg('u'));
            case 'vrednostCoons'
                [T, rc, rd, rcd] = vrednostCoons(arg('u'), arg('v'), arg('c1'), arg('c2'), ...
                    arg('d1'), arg('d2'), arg('P1'), arg('P2'), arg('P3'), arg('P4'));
                out.([p 'T']) = T;
                out.([p 'rc']) = rc;
                out.([p 'rd']) = rd;
                out.([p 'rcd']) = rcd;
            case 'krpaCoons'
                [R, P] = krpaCoons(arg('c1'), arg('c2'), arg('d1'), arg('d2'), ...
                    arg('P1'), arg('P2'), arg('P3'), arg('P4'));
                out.([p 'R']) = R;
                out.([p 'P']) = P;
            case 'krpaGordon'
                [R, P] = krpaGordon(arg('g_u'), arg('g_v'), arg('g_uv'), arg('x_u'), ...
                    arg('x_v'), arg('N'));
                out.([p 'R']) = R;
                out.([p 'P']) = P;
            otherwise
                error('differential: case %d: unknown function %s', k, arg('fn'));
        end;
    end;
    save_precision(17);
    save('-text', outfile, '-struct', 'out');
    printf('differential: OK, %d case(s)\n', count);
end;
