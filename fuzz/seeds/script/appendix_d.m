% Data script of the thesis, appendix D ("primer zapisa podatkov za algoritem 7"), as printed,
% preceded by the definitions it needs (N, u, v). With u and v sampled vectors, `u^2` and the
% constant rows in `[u;0;u-u^2]` are errors in Octave; the reader evaluates them element-wise
% and repeats the constants along the row, as the author meant, with a warning each.
N = 10;
u = linspace(0,1,N);
v = linspace(0,1,N);
g00 = [0 0 0];
g01=[0.5 0 0.25];
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
