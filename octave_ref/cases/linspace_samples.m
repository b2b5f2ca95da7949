% Case "linspace_samples": Octave 7's linspace(a, b, n) for n = 0..200 on several intervals.
% Inputs:  lin_<key>_a, lin_<key>_b   the interval (scalars)
% Outputs: lin_<key>_n<n>             1 x n, linspace(a, b, n)
% Keys: a0_b1 = [0,1] (the thesis's sampling), am1_b1 = [-1,1] (symmetric: middle element set to
% exactly 0), a0p3_b7p1 = [0.3,7.1], a1_b0 = [1,0] (decreasing), am3p7_b1000 = [-3.7,1000].
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
save_precision(17);

intervals = {'a0_b1', 0, 1; 'am1_b1', -1, 1; 'a0p3_b7p1', 0.3, 7.1; 'a1_b0', 1, 0; ...
             'am3p7_b1000', -3.7, 1000};
names = {};
for r = 1:rows(intervals)
    key = intervals{r,1};
    a = intervals{r,2};
    b = intervals{r,3};
    eval(sprintf('lin_%s_a = a; lin_%s_b = b;', key, key));
    names(end+1:end+2) = {sprintf('lin_%s_a', key), sprintf('lin_%s_b', key)};
    for n = 0:200
        name = sprintf('lin_%s_n%d', key, n);
        eval(sprintf('%s = linspace(a, b, n);', name));
        names{end+1} = name;
    end;
end;
save('-text', fullfile(outdir, 'linspace_samples.txt'), names{:});
