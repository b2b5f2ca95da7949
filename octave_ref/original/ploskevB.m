% ploskevB.m -- AS PRINTED, bugs included.  Do not fix here; see ../fixed/ploskevB.m.
%
% Source: Irena Čavdek, "Bézierove in Gordon-Coons krpe", zaključna naloga, UP FAMNIT, Koper 2014,
%         Priloga B (appendix B), Algoritem 2: ploskevB.
%         Vhod: kontrolne točke in parameter N, ki nam pove, kako na gosto računamo točke na krpi
%         Izhod: nariše Bézierovo krpo
% Transcribed from the OCR'd thesis text: line numbers and LaTeX/OCR debris removed, indentation
% normalised.  Reconstructed characters:
%   line 2: "\mathbf{2} \mathbf{m} = \text{size}(\text{kontrolneT})(1)-1;" read as
%           "m = size(kontrolneT)(1)-1;"
%   line 3: the line number "3" was OCR'd as "\mathbf{s}"; dropped.
% Everything else is exactly as printed.
function ploskevB(kontrolneT,N)
m = size(kontrolneT)(1)-1;
n = (size(kontrolneT)(2)/3)-1;
t = linspace(0,1,N);
for i = 1:N
    for j = 1:N
        u = t(i);
        v = t(j);
        P(i,j,:) = bilinearna(kontrolneT,u,v,N);
    end;
end;
surf(P(:,:,1), P(:,:,2), P(:,:,3));
end;
