% Bug: deCasteljau, ploskevB, krpaCoons and krpaGordon only draw; they declare no output, so no
% caller can use the points they compute.  Asking for an output is an error before the body
% runs (each call below would fail for other reasons too, see the other scripts).
bug_setup;
P = [0 0 8 4; 0 2 2 0; 0 2 0 0];
B = [0 0 0 0 1 0; 1 0 0 1 1 1];
c = zeros(3, 5);
p = zeros(3, 1);
calls = {'T = deCasteljau(P, 5)', 'P = ploskevB(B, 5)', ...
         'R = krpaCoons(c, c, c, c, p, p, p, p)', 'R = krpaGordon(c, c, B, [0 1], 5)'};
for k = 1:numel(calls)
    try
        eval([calls{k} ';']);
        printf('%s: no error\n', calls{k});
    catch err
        printf('%s: error: %s\n', calls{k}, err.message);
    end;
end;
