% krpaCoons_data.m -- AS PRINTED, bugs included (uses N without defining it; assigns P3 twice and
% never P4).  A script, not a function.
%
% Source: Irena Čavdek, "Bézierove in Gordon-Coons krpe", zaključna naloga, UP FAMNIT, Koper 2014,
%         Priloga C (appendix C), "Vhod: primer zapisa krivulj za algoritem 5".
% Transcribed from the OCR'd thesis text: line numbers and LaTeX/OCR debris removed, indentation
% normalised.  Reconstructed characters:
%   line 2: "\mathbf{2} \mathbf{v} = \text{linspace}(0,1,\mathbf{N});" read as "v = linspace(0,1,N);"
%   line 24: the line number "\mathbf{24}" printed after the statement; dropped.
% Line 35 reads "P3 = [1;1;1];" in the thesis (the author surely meant P4); kept as printed.
% Everything else is exactly as printed.
u = linspace(0,1,N);
v = linspace(0,1,N);
% c1 = [u;0;u-u^2];
c1x = u;
c1y = zeros(1,N);
c1z = zeros(1,N);
for i = 1:N
    c1z(i) = u(i)-(u(i))^2;
end;
c1 = [c1x;c1y;c1z];
% c2 = [u,1,u];
c2x = u;
c2y = ones(1,N);
c2z = u;
c2 = [c2x;c2y;c2z];
% d1 = [0;v^2;v-v^2];
d1x = zeros(1,N);
d1y = zeros(1,N);
for i = 1:N
    d1y(i) = (v(i))^2;
end;
d1z = zeros(1,N);
for i = 1:N
    d1z(i) = v(i)-(v(i))^2;
end;
d1 = [d1x;d1y;d1z];
% d2 = [1;v;v];
d2x = ones(1,N);
d2y = v;
d2z = v;
d2 = [d2x; d2y; d2z];
P1 = [0;0;0];
P2 = [1;0;0];
P3 = [0;1;0];
P3 = [1;1;1];
