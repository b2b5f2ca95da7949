% krpaGordon.m -- AS PRINTED, bugs included.  See ../fixed/krpaGordon.m.
%
% Source: Irena Čavdek, "Bézierove in Gordon-Coons krpe", zaključna naloga, UP FAMNIT, Koper 2014,
%         Priloga D (appendix D), Algoritem 7: Gordonova krpa.
%         Vhod: krivulje, presečišča krivulj, vektor x in parameter N, ki nam pove, kako na gosto
%               računamo točke na krpi
%         Izhod: nariše Gordonovo krpo
% Transcribed from the OCR'd thesis text: line numbers and LaTeX/OCR debris removed, indentation
% normalised.  Reconstructed characters:
%   line 13: "g_{-}u(:,l)" (LaTeX subscript debris) read as "g_u(:,l)".
% Line 11 "g1 = g2 = g12 = 0;" is a chained assignment, which Octave accepts; kept as printed.
% Everything else is exactly as printed.
function krpaGordon(g_u,g_v,g_uv,x,N)
t = linspace(0,1,N);
R = zeros(N,N);
for i = 1:N
    u = t(i);
    k = 1;
    for j = 1:N
        v = t(j);
        m = size(g_u)(2);
        n = size(g_v)(2);
        g1 = g2 = g12 = 0;
        for l = 1:m
            g1 = g_u(:,l)*Lagrange(x,l,v)+g1;
            g2 = g_v(:,l) * Lagrange(x,l,u) + g2;
            c = 0;
            for s = 1:n
                g12 = g_uv(l,s+c:s+c+2) *Lagrange(x,l,u)*Lagrange(x,s,v)+g12;
                c = c+2;
            end;
        end;
        R(i,k:(k+2)) = g1+g2-g12;
        k = k+3;
    end;
end;
P=tenzor(R);
surf(P(:,:,1),P(:,:,2),P(:,:,3));
end;
