% bilinearna.m -- AS PRINTED, bugs included.  Do not fix here; see ../fixed/bilinearna.m.
%
% Source: Irena Čavdek, "Bézierove in Gordon-Coons krpe", zaključna naloga, UP FAMNIT, Koper 2014,
%         Priloga B (appendix B), Algoritem 3: bilinearna.
%         Vhod: kontrolne točke, parametra u,v, pri katerih računamo točke na ploskvi in parameter
%               N, ki nam pove, kako na gosto računamo točke na ploskvi
%         Izhod: izračuna točke na Bézierovi krpi
% Transcribed from the OCR'd thesis text: line numbers and LaTeX/OCR debris removed, indentation
% normalised.  Reconstructed characters:
%   line 2: "\mathbf{2} \ \mathrm{T} = \mathrm{zeros}(\mathrm{N},\mathrm{N},3);" read as
%           "T = zeros(N,N,3);"
%   line 3: the line number "3" was OCR'd as "s"; dropped.
%   line 9: every "^*" (LaTeX superscript debris) read as "*", and "\ = \ " as " = "; the
%           spaces around "+" are kept as OCR'd.
% Everything else is exactly as printed.
function L = bilinearna(B,u,v,N)
T = zeros(N,N,3);
m = size(B)(1)-1;
n = (size(B)(2)/3)-1;
B1 = tenzor(B);
for k=1:m
    for i = 1:(m-k+1)
        for j = 1:(n-k+1)
            T(i,j,:) = (1-u)*(1-v)*B1(i,j,:) + u*(1-v)*B1(i+1,j,:) + (1-u)*v*B1(i,j+1,:) + u*v*B1(i+1,j+1,:);
        end;
    end;
    B1=T;
end;
L = T(1,1,:);
end;
