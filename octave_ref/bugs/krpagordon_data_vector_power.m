% Bug: appendix D's data script writes u^2, a matrix power; with u a vector of samples, as
% krpaGordon needs its curves (u = linspace(0,1,N)), it fails.  Even with the elementwise
% power the lines would not work: [u;0;...] stacks a 1xN row on a scalar.
bug_setup;
u = linspace(0, 1, 5);
v = u;
try
    c0 = [u;0;u-u.^2];
catch err
    printf('with .^ instead: error: %s\n', err.message);
end;
krpaGordon_data;
