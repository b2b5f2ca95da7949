% surf.m -- stand-in for Octave's surf while the bug scripts run the original thesis code: it draws
% nothing and records the call (name and arguments) in the global cell CAGD_PLOTS, so that a
% script can print the data the original would have drawn.  Used only by octave_ref/bugs/.
function surf(varargin)
    global CAGD_PLOTS;
    CAGD_PLOTS{end+1} = [{'surf'}, varargin];
end
