% hold.m -- stand-in for Octave's hold while the bug scripts run the original thesis code: does
% nothing (there is no figure).  Used only by octave_ref/bugs/.
function hold(varargin)
end
