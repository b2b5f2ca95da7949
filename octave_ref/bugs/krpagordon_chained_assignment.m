% Not portable: krpaGordon line 11 "g1 = g2 = g12 = 0;" is a chained assignment.  GNU Octave
% accepts it (an assignment is an expression whose value is the assigned value); MATLAB does
% not (parse error), so the printed code runs only in Octave.  The statement as printed:
bug_setup;
g1 = g2 = g12 = 0;
printf('g1 = %g, g2 = %g, g12 = %g\n', g1, g2, g12);
