% Bug: deCasteljau allocates T = zeros(3,N), so only 3-D curves fit.
% A plane segment (2 points in 2-D, 2x2, where rows and columns happen to agree) fails when
% the first point is stored into the 3-row T.
bug_setup;
P = [0 1; 0 2];                      % b0 = (0,0), b1 = (1,2)
deCasteljau(P, 4);
