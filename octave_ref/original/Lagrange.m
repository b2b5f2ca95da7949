% Lagrange.m -- AS PRINTED, bugs included (v starts as zeros, so every product stays 0).
% See ../fixed/Lagrange.m.
%
% Source: Irena Čavdek, "Bézierove in Gordon-Coons krpe", zaključna naloga, UP FAMNIT, Koper 2014,
%         Priloga D (appendix D), Algoritem 8: Lagrangeev polinom.
%         Vhod: v vektor x so podane vrednosti polinoma, m je stopnja Lagrangeevega polinoma,
%               parameter u, pri katerem računamo vrednost polinoma
%         Izhod: vrednost Lagrangeevega polinoma
% (The description is itself inaccurate: x holds the interpolation nodes and m is the index of
% the basis polynomial, not its degree.)
% Transcribed from the OCR'd thesis text: line numbers removed, indentation normalised.  No
% character had to be reconstructed.  The listing is printed without a closing "end" for the
% function (legal in an Octave function file); it is kept that way.
function v = Lagrange(x,m,u)
n = length(x);
v = zeros(size(u));
for j = [1:m-1 m+1:n]
    v = (u-x(j))./(x(m)-x(j)).*v;
end;
