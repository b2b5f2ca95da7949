% krpaGordon_data.m -- AS PRINTED, bugs included (uses u and v without defining them; with a
% vector u, "u^2" is a matrix power and "[u;0;...]" a dimension mismatch).  A script.
%
% Source: Irena Čavdek, "Bézierove in Gordon-Coons krpe", zaključna naloga, UP FAMNIT, Koper 2014,
%         Priloga D (appendix D), "Vhod: primer zapisa podatkov za algoritem 7".
% Transcribed from the OCR'd thesis text: line numbers and LaTeX/OCR debris removed.
% Reconstructed characters:
%   lines 2, 3, 4, 9: "\ " (LaTeX spacing) between numbers read as one space.
%   line 5: "\mathbf{5} \ \mathbf{g11} = [0.5 \ 0.5 \ 0.75];" read as "g11 = [0.5 0.5 0.75];".
%   line 13: "u-u<sup>2</sup>" (HTML debris) read as "u-u^2".
% Spacing around "=" is kept as printed (some lines have it, some not).
% Everything else is exactly as printed.
g00 = [0 0 0];
g01 = [0.5 0 0.25];
g02=[1 0 0];
g10=[0 0.5 0.5];
g11 = [0.5 0.5 0.75];
g12=[1 0.5 0.5];
g20=[0 1 1];
g21=[0.5 1 1.25];
g22=[1 1 1];
g_uv = [g00 g10 g20; g01 g11 g21; g02 g12 g22];
c0=[u;0;u-u^2];
c1=[u;0.5;0.5+u-u^2];
c2=[u;1;1+u-u^2];
g_u=[c0 c1 c2];
d0=[0;v;v];
d1=[0.5;v;0.25+v];
d2=[1;v;v];
g_v=[d0 d1 d2];
x = [0 0.5 1];
