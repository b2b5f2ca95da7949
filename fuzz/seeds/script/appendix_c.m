% Data script of the thesis, appendix C ("primer zapisa krivulj za algoritem 5"), as printed,
% with two fixes: `N = 10;` added at the top (the printed script uses N without setting it),
% and the last line sets P4 (the printed script sets P3 twice and never P4).
N = 10;
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
P4 = [1;1;1];
