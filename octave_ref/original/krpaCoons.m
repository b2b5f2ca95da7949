% krpaCoons.m -- AS PRINTED, bugs included (N is never defined).  See ../fixed/krpaCoons.m.
%
% Source: Irena Čavdek, "Bézierove in Gordon-Coons krpe", zaključna naloga, UP FAMNIT, Koper 2014,
%         Priloga C (appendix C), Algoritem 5: Coonsova krpa.
%         Vhod: štiri mejne krivulje in njihova oglišča   Izhod: nariše Coonsovo krpo in mejne krivulje
% Transcribed from the OCR'd thesis text: line numbers and LaTeX/OCR debris removed, indentation
% normalised.  Reconstructed characters:
%   line 2: "\mathbf{2} \ \mathbf{u} = \text{linspace}(0,1,\mathbf{N});" read as "u = linspace(0,1,N);"
%   line 3: the line number "3" was OCR'd as "\mathbf{s}"; dropped.
%   line 10: every "^{*}" (LaTeX superscript debris) read as "*".
% Everything else is exactly as printed.
function krpaCoons(c1,c2,d1,d2,P1,P2,P3,P4)
u = linspace(0,1,N);
v = linspace(0,1,N);
R = zeros(N,N);
for i = 1:N
    k = 1;
    for j = 1:N
        rc = (1-v(j))*c1(:,i)+v(j)*c2(:,i);
        rd = (1-u(i))*d1(:,j)+u(i)*d2(:,j);
        rcd = (1-u(i))*(1-v(j))*P1 + u(i)*(1-v(j))*P2 + (1-u(i))*v(j)*P3 + u(i)*v(j)*P4;
        R(i,k:(k+2)) = rc+rd-rcd;
        k = k+3;
    end;
end;
P = tenzor(R);
surf(P(:,:,1),P(:,:,2),P(:,:,3));
hold on;
plot3(c1(1,:),c1(2,:),c1(3,:),'r','LineWidth',2.5)
hold on
plot3(c2(1,:),c2(2,:),c2(3,:),'r','LineWidth',2.5)
hold on
plot3(d1(1,:),d1(2,:),d1(3,:),'g','LineWidth',2.5)
hold on
plot3(d2(1,:),d2(2,:),d2(3,:),'g','LineWidth',2.5)
hold on
end;
