% deCasteljau.m -- AS PRINTED, bugs included.  Do not fix here; see ../fixed/deCasteljau.m.
%
% Source: Irena Čavdek, "Bézierove in Gordon-Coons krpe", zaključna naloga, UP FAMNIT, Koper 2014,
%         Priloga A (appendix A), Algoritem 1: de Casteljauev algoritem.
%         Vhod: kontrolne točke in parameter N, ki nam pove, kako na gosto računamo točke na krivulji
%         Izhod: graf krivulje in njen kontrolni poligon
% Transcribed from the OCR'd thesis text: line numbers and LaTeX/OCR debris removed, indentation
% normalised.  Reconstructed characters:
%   line 2: "\mathbf{2} \ \mathbf{m} = \text{size}(\text{kontrolneT})(1);" read as "m = size(kontrolneT)(1);"
%   line 3: the line number "3" was OCR'd as "\mathbf{s}"; dropped.
%   line 5: printed as "s = \text{linspace}(0,1,N);" with the line number 5 missing; the variable
%           name "s" is confirmed by "t = s(k);" on line 7.
% Everything else is exactly as printed.
function deCasteljau(kontrolneT,N)
m = size(kontrolneT)(1);
n = size(kontrolneT)(2);
T = zeros(3,N);
s = linspace(0,1,N);
for k = 1:N
    t = s(k);
    for j = 1:m
        for i = 1:(n-1)
            kontrolneT(i,:) = (1-t)*kontrolneT(i,:)+t*kontrolneT(i+1,:);
        end;
    end;
    T(:,[k]) = kontrolneT(:,[1]);
end;
plot3(T(1,:),T(2,:),T(3,:));
hold on;
plot3(kontrolneT(1,:),kontrolneT(2,:),kontrolneT(3,:),'ro');
hold on;
plot3(kontrolneT(1,:),kontrolneT(2,:),kontrolneT(3,:),'r');
hold off;
end;
