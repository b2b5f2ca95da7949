% run_cases(refdir, outdir) -- run every octave_ref/cases/*.m in this one Octave process.
%
% Called by regenerate.sh.  Puts refdir/fixed on the path, sets CAGD_REF_OUT = outdir, and runs
% each case script (sorted by name) in a workspace of its own, so no variable leaks from one case
% into the next.  Case "<name>.m" must write exactly "<outdir>/<name>.txt"; a case that fails or
% does not write its file is reported.  The last line printed is "run_cases: OK, <k> case(s)"
% only when every case succeeded -- regenerate.sh checks for that line rather than trusting the
% exit status (Octave 7 may print "error: ignoring const execution_exception& while preparing
% to exit" and its exit status is not a reliable signal).
function run_cases(refdir, outdir)
    addpath(fullfile(refdir, 'fixed'));
    setenv('CAGD_REF_OUT', outdir);
    files = dir(fullfile(refdir, 'cases', '*.m'));
    names = sort({files.name});
    failed = 0;
    for k = 1:numel(names)
        [~, casename] = fileparts(names{k});
        out = fullfile(outdir, [casename '.txt']);
        if exist(out, 'file')
            delete(out);
        end;
        try
            run_one(fullfile(refdir, 'cases', names{k}));
            if !exist(out, 'file')
                error('case script did not write %s', out);
            end;
            printf('wrote %s\n', out);
        catch err
            failed = failed + 1;
            printf('FAILED %s: %s\n', casename, err.message);
        end;
    end;
    if failed == 0
        printf('run_cases: OK, %d case(s)\n', numel(names));
    else
        printf('run_cases: %d of %d case(s) FAILED\n', failed, numel(names));
    end;
end;

% The script runs in this function's workspace, which is thrown away when it returns.
% source() does not change directory, so a case script never shadows a function it calls.
function run_one(path)
    source(path);
end;
